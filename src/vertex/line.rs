//! Lines: clipping to the view volume as Mesa's clipper does, the line stipple (dashes in
//! window space), and their setup into line jobs (aliased, smooth or covering samples), in
//! llvmpipe's y-down window space.
use super::clip::ClipVertex;
use super::geometry::Geometry;
use crate::setup::jobs::line::{LineJob, LineVertex};
use crate::setup::jobs::smooth::{SmoothJob, SmoothLine};
use crate::setup::multisample::SampleQuad;
use crate::setup::plane::MAX_VARYINGS;
use crate::setup::{Primitive as RasterPrimitive, Scene};

/// The line stipple of a draw: GL's repeat factor and pattern, and the running counter
/// (in pixel steps along the lines' major axes).
#[derive(Clone, Copy, Debug)]
pub struct LineStipple {
    pub factor: i32,
    pub pattern: u16,
    pub counter: i32,
}

/// Clips a line to the view volume the way Mesa's clipper does (both ends moved from the
/// original endpoints, by the largest cut of any plane), maps it to window space and emits
/// it. `outcodes` are against `g.line_planes`.
pub fn emit_clip_line<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    ends: [&ClipVertex<N>; 2],
    outcodes: [u32; 2],
    flat: Option<[f32; 4]>,
    stipple: Option<&mut LineStipple>,
) {
    let [a, b] = ends;
    if outcodes[0] & outcodes[1] != 0 {
        return;
    }
    let (wa, wb) = if outcodes[0] | outcodes[1] == 0 {
        (g.viewport.window_down(a, true), g.viewport.window_down(b, true))
    } else {
        let planes = &g.line_planes;
        let (mut t0, mut t1) = (0.0f32, 0.0f32);
        let mut mask = outcodes[0] | outcodes[1];
        while mask != 0 {
            let plane = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let (da, db) = (planes.distance(plane, a), planes.distance(plane, b));
            if !da.is_finite() || !db.is_finite() {
                return;
            }
            if db < 0.0 {
                t1 = t1.max(db / (db - da));
            }
            if da < 0.0 {
                t0 = t0.max(da / (da - db));
            }
            if t0 + t1 >= 1.0 {
                return;
            }
        }
        let wa = if outcodes[0] != 0 {
            g.viewport.window_down(&lerp_clip(a, b, t0), false)
        } else {
            g.viewport.window_down(a, true)
        };
        let wb = if outcodes[1] != 0 {
            g.viewport.window_down(&lerp_clip(b, a, t1), false)
        } else {
            g.viewport.window_down(b, true)
        };
        (wa, wb)
    };
    emit_window_line(scene, state, g, wa, wb, flat, stipple);
}

/// `from + t · (to − from)` for the clip position and attributes of a clipped line end.
pub fn lerp_clip<const N: usize>(from: &ClipVertex<N>, to: &ClipVertex<N>, t: f32) -> ClipVertex<N> {
    let mix = |a: [f32; 4], b: [f32; 4]| std::array::from_fn(|i| a[i] + t * (b[i] - a[i]));
    ClipVertex {
        clip: mix(from.clip, to.clip),
        color: mix(from.color, to.color),
        secondary_color: mix(from.secondary_color, to.secondary_color),
        tex_coords: std::array::from_fn(|u| mix(from.tex_coords[u], to.tex_coords[u])),
        fog_coord: from.fog_coord + t * (to.fog_coord - from.fog_coord),
        ..*from
    }
}

/// Emits a window-space line, cut into its stippled dashes when stippled.
pub fn emit_window_line<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    a: LineVertex<N>,
    b: LineVertex<N>,
    flat: Option<[f32; 4]>,
    stipple: Option<&mut LineStipple>,
) {
    let Some(stipple) = stipple else {
        emit_line_job(scene, state, g, &a, &b, flat);
        return;
    };
    // llvmpipe's stipple: the line is cut into dashes, one pixel step along the major axis
    // per stipple bit, each dash drawn as a line of its own.
    // Smooth lines count their stipple along their true (Euclidean) length, as Mesa's
    // draw module does for them.
    let (dx, dy) = ((a.x - b.x).abs(), (a.y_down - b.y_down).abs());
    let length = if g.smooth_lines { (dx * dx + dy * dy).sqrt() } else { dx.max(dy) };
    let steps = if length.is_finite() { crate::gl::float::ceil_to_i32(length) } else { 0 };
    let base = stipple.counter;
    let bit = |i: i32| stipple.pattern >> (((base + i) / stipple.factor) & 15) & 1 != 0;
    let mut dash_start = None;
    for i in 0..steps {
        match (dash_start, bit(i)) {
            (None, true) => dash_start = Some(i),
            (Some(start), false) => {
                emit_dash(scene, state, g, &a, &b, start as f32 / length, i as f32 / length, flat);
                dash_start = None;
            }
            _ => {}
        }
    }
    if let Some(start) = dash_start {
        if (start as f32) < length {
            emit_dash(scene, state, g, &a, &b, start as f32 / length, 1.0, flat);
        }
    }
    // The counter advances by whole steps: a strip's next segment continues where this
    // one's last (partial) step ended, as in Mesa 22.
    stipple.counter = stipple.counter.wrapping_add(steps);
}

/// Emits the part of `a`–`b` between parameters `t0` and `t1`, every attribute
/// interpolated linearly in window space as llvmpipe's stipple stage does.
#[allow(clippy::too_many_arguments)]
pub fn emit_dash<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    a: &LineVertex<N>,
    b: &LineVertex<N>,
    t0: f32,
    t1: f32,
    flat: Option<[f32; 4]>,
) {
    let at = |t: f32| {
        let mix = |p: f32, q: f32| p + t * (q - p);
        LineVertex {
            x: mix(a.x, b.x),
            y_down: mix(a.y_down, b.y_down),
            z: mix(a.z, b.z),
            inv_w: mix(a.inv_w, b.inv_w),
            color: std::array::from_fn(|i| mix(a.color[i], b.color[i])),
            secondary_color: std::array::from_fn(|i| mix(a.secondary_color[i], b.secondary_color[i])),
            tex_coords: std::array::from_fn(|u| std::array::from_fn(|i| mix(a.tex_coords[u][i], b.tex_coords[u][i]))),
            fog_coord: mix(a.fog_coord, b.fog_coord),
        }
    };
    let start = if t0 > 0.0 { at(t0) } else { *a };
    let end = if t1 < 1.0 { at(t1) } else { *b };
    emit_line_job(scene, state, g, &start, &end, flat);
}

pub fn emit_line_job<const N: usize>(
    scene: &mut Scene,
    state: u32,
    g: &Geometry,
    a: &LineVertex<N>,
    b: &LineVertex<N>,
    flat: Option<[f32; 4]>,
) {
    // Each varying's values at the ends, read as the job's planes are made: setting up a
    // line allocates, fills and zeroes no table of them.
    let varyings = g.varyings.iter().take(MAX_VARYINGS).map(|v| [v.of_line(a), v.of_line(b)]);
    if g.smooth_lines {
        if let Some(job) = SmoothLine::new(a, b, g.line_width, g.height, flat, varyings) {
            let job = SmoothJob::Line(Box::new(job));
            scene.add(state, job.bounds(), RasterPrimitive::Smooth(job));
        }
        return;
    }
    if g.per_sample {
        // The rectangle of the unrounded width, as llvmpipe draws it on a multisampled target
        // (widths below 1 draw as 1 there, Mesa's minimum line width).
        let up = |v: &LineVertex<N>| [v.x, g.height as f32 - v.y_down];
        let quad = SampleQuad::line(up(a), up(b), g.line_width.max(1.0));
        if let Some(job) = quad.and_then(|quad| LineJob::covering_samples(a, b, g.height, flat, varyings, quad)) {
            scene.add(state, job.bounds(), RasterPrimitive::Line(job));
        }
        return;
    }
    if let Some(job) = LineJob::new(a, b, g.line_width, g.height, flat, varyings) {
        let (bounds, setup) = (job.bounds(), job.setup().clone());
        scene.add_narrow(state, bounds, RasterPrimitive::Line(job), |y0, y1| setup.columns(y0, y1));
    }
}
