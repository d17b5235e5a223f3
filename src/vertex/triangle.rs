//! Filled triangles: the colors of their facing (two-sided lighting, flat shading), culling,
//! polygon offset and their setup into triangle jobs (aliased or smooth).
use super::clip::ClipVertex;
use super::cull::{area2, culls, faces_front};
use super::geometry::Geometry;
use super::offset::{clamp_offset, polygon_offset};
use crate::setup::jobs::smooth::{SmoothJob, SmoothTriangle};
use crate::setup::jobs::triangle::{TriangleJob, WindowVertex};
use crate::setup::plane::MAX_VARYINGS;
use crate::setup::triangle::TriangleSetup;
use crate::setup::{Primitive as RasterPrimitive, Scene};

/// The colors of a flat-shaded primitive: its provoking vertex's front primary and
/// secondary colors, and its back ones.
#[derive(Clone, Copy, Debug)]
pub struct FlatColors {
    pub front: [[f32; 4]; 2],
    pub back: [[f32; 4]; 2],
}

impl FlatColors {
    pub fn of<const N: usize>(v: &ClipVertex<N>) -> Self {
        FlatColors { front: [v.color, v.secondary_color], back: v.back_colors }
    }
}

/// Emits a filled triangle with the colors of its facing: the back colors `back` of its
/// corners when it faces back under two-sided lighting, and the provoking vertex's colors
/// (primary and secondary) under flat shading.
pub fn emit_shaded_triangle<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    w: &[WindowVertex<N>; 3],
    back: [[[f32; 4]; 2]; 3],
    flat: Option<FlatColors>,
) {
    emit_shaded_triangle_with(scene, state, g, w, None, || back, flat)
}

/// A triangle's corners snapped to fixed point by the caller ([`TriangleSetup::snapped`]:
/// `None` outside the guard band), for callers that snap each vertex of a strip once; or
/// `None`, snapped where the triangle is set up.
pub type Snapped = Option<[Option<[i64; 2]>; 3]>;

/// [`emit_shaded_triangle`] with the back colors fetched by `back` only when the triangle
/// uses them (copying them for every triangle of a draw without two-sided lighting cost
/// a small triangle's setup more than its culling).
#[inline(always)]
pub fn emit_shaded_triangle_with<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    w: &[WindowVertex<N>; 3],
    snapped: Snapped,
    back: impl FnOnce() -> [[[f32; 4]; 2]; 3],
    flat: Option<FlatColors>,
) {
    let use_back = g.two_side && !faces_front(g.front_ccw, area2(w));
    let flat = flat.map(|f| if use_back { f.back } else { f.front });
    if !use_back && flat.is_none() {
        // The corners as they are (no copy).
        return emit_triangle(scene, state, g, w, snapped, None);
    }
    let mut w = *w;
    if use_back {
        for (c, b) in w.iter_mut().zip(back()) {
            (c.color, c.secondary_color) = (b[0], b[1]);
        }
    }
    if let Some([_, secondary]) = flat {
        for c in &mut w {
            c.secondary_color = secondary;
        }
    }
    emit_triangle(scene, state, g, &w, snapped, flat.map(|f| f[0]));
}

/// Culls, offsets, sets up and bins one window-space triangle.
pub fn emit_triangle<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    w: &[WindowVertex<N>; 3],
    snapped: Snapped,
    flat: Option<[f32; 4]>,
) {
    let area2 = area2(w);
    if !area2.is_finite() {
        return;
    }
    let front = faces_front(g.front_ccw, area2);
    if culls(g.cull, front) {
        return;
    }
    let count = g.varyings.len().min(MAX_VARYINGS);
    // Varying k's values at the corners, read from the vertices where the job is made:
    // no table of all of them is filled (and zeroed) per triangle.
    let varying = |k: usize| {
        let a = g.varyings[k];
        [a.of(&w[0]), a.of(&w[1]), a.of(&w[2])]
    };
    if g.smooth_polygons {
        let values = (0..count).map(varying);
        if let Some(job) = SmoothTriangle::new(*w, flat, depth_offset(g, w), values, front) {
            let job = SmoothJob::Triangle(Box::new(job));
            scene.add(state, job.bounds(), RasterPrimitive::Smooth(job));
        }
        return;
    }
    // The edges first: a triangle that covers no pixel (most of a mesh finer than the
    // pixels) is dropped before its planes are made.
    let setup = match snapped {
        Some([Some(a), Some(b), Some(c)]) => TriangleSetup::from_snapped([a, b, c]),
        Some(_) => None,
        None => TriangleSetup::new(w.map(|p| [p.x, p.y])),
    };
    let Some(setup) = setup else { return };
    scene.add_triangle(state, setup, |setup| {
        let offset = depth_offset(g, w);
        let mut job = TriangleJob::with_setup_by(setup, g.accuracy, w, flat, offset, count, varying);
        job.front_facing = front;
        job
    });
}

/// A triangle's polygon offset (0 without one).
#[inline(always)]
fn depth_offset<const N: usize>(g: &Geometry, w: &[WindowVertex<N>; 3]) -> f32 {
    g.offset.map_or(0.0, |(factor, units)| clamp_offset(polygon_offset(w, factor, units, g.depth), g.offset_clamp))
}
