//! The primitive pipeline of a draw: its clip-space vertices assembled into points, lines
//! and triangles (or, in the point and line polygon modes, outlines), each clipped only when
//! it must be, and handed to the step that sets it up and bins it into the scene.
use super::assembly::{assemble, DrawPart, Primitive, QuadSplit};
use super::clip::ClipVertex;
use super::geometry::Geometry;
use super::line::{emit_clip_line, LineStipple};
use super::outline::{decompose_outlines, Outline};
use super::point::emit_point;
use super::triangle::{emit_shaded_triangle, emit_shaded_triangle_with, FlatColors};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::setup::jobs::triangle::WindowVertex;
use crate::setup::triangle::TriangleSetup;
use crate::setup::Scene;

/// A vertex of a filled primitive in window space (for a draw that interpolates no varying
/// slot), with its coordinates snapped to fixed point for triangle setup.
#[derive(Clone, Copy)]
struct Corner {
    w: WindowVertex<0>,
    snapped: Option<[i64; 2]>,
}

/// The corner of a vertex outside the clip planes (its triangles are clipped, so it is
/// never read).
const OUTSIDE: WindowVertex<0> = WindowVertex {
    x: 0.0,
    y: 0.0,
    z: 0.0,
    inv_w: 0.0,
    color: [0.0; 4],
    secondary_color: [0.0; 4],
    tex_coords: [],
    fog_coord: 0.0,
};

/// Draws `clip_vertices` as primitives of `mode` into `scene` under the draw state
/// `state_index`, with the per-draw constants `geometry`. `part` is the part of a long
/// connected primitive these vertices are (see [`DrawPart`]); `stipple` is GL_LINE_STIPPLE's
/// state where the part starts, and the state where it ends is returned.
#[allow(clippy::too_many_arguments)]
pub fn draw<const N: usize>(
    scene: &mut Scene,
    state_index: u32,
    geometry: &Geometry,
    mode: GLenum,
    clip_vertices: &[ClipVertex<N>],
    part: DrawPart,
    mut stipple: Option<LineStipple>,
) -> Option<LineStipple> {
    let first_vertex = geometry.first_vertex;
    let mut poly = Vec::new();
    let mut scratch = Vec::new();
    let polygons = (GL_TRIANGLES..=GL_POLYGON).contains(&mode);
    let outlines = polygons && (geometry.mode_front != GL_FILL || geometry.mode_back != GL_FILL);
    // Filled polygons are clipped to the guard band; points, lines and outlines to the
    // view volume.
    let planes = if polygons && !outlines { &geometry.planes } else { &geometry.line_planes };
    let outcodes = planes.outcodes(clip_vertices);
    if outlines {
        let mut outline = Outline { scene, state: state_index, g: geometry, stipple };
        decompose_outlines(mode, clip_vertices.len() as u32, first_vertex, part, |t| {
            let v = t.v.map(|i| &clip_vertices[i as usize]);
            let codes = t.v.map(|i| outcodes[i as usize]);
            outline.triangle(v, codes, t, &mut poly, &mut scratch);
        });
        return outline.stipple;
    }
    // No varying reads a texture slot (a draw without textures): filled triangles' window
    // vertices leave the slots out.
    let slots_unread = geometry.varyings.iter().all(|a| a.texture_coordinate().is_none());
    // Vertices shared by several triangles (strips, fans, quads, polygons) are mapped to
    // window space and snapped once, not once per triangle: the lit mesh's quad strips set
    // up each vertex three times otherwise. Independent triangles map theirs in place, and
    // points and lines have no triangles (a table for them made glVertex3f's points a fifth slower).
    let corners: Option<Vec<Corner>> = (slots_unread && polygons && mode != GL_TRIANGLES).then(|| {
        let viewport = &geometry.viewport;
        let corner = |(v, &code): (&ClipVertex<N>, &u32)| {
            // A vertex outside the planes is only ever clipped: its corner is never read.
            let w = if code == 0 { viewport.window_without_slots(v) } else { OUTSIDE };
            Corner { snapped: TriangleSetup::snapped([w.x, w.y]), w }
        };
        clip_vertices.iter().zip(&outcodes).map(corner).collect()
    });
    let split = if !first_vertex && mode == GL_QUADS && geometry.leaves_view_volume(clip_vertices) {
        QuadSplit::SecondDiagonal
    } else {
        QuadSplit::FirstDiagonal
    };
    assemble(mode, clip_vertices.len() as u32, first_vertex, split, |primitive| match primitive {
        Primitive::Point(i) => {
            let i = i as usize;
            if outcodes[i] == 0 {
                emit_point(scene, state_index, geometry, &clip_vertices[i]);
            }
        }
        Primitive::Line { v: [a, b], provoking } => {
            if mode == GL_LINES {
                // Every independent segment restarts the pattern (GL 2.1 §3.4.2).
                if let Some(s) = stipple.as_mut() {
                    s.counter = 0;
                }
            }
            let provoking = &clip_vertices[provoking as usize];
            let flat_color = geometry.flat.then_some(provoking.color);
            let (a, b) = (a as usize, b as usize);
            let codes = [outcodes[a], outcodes[b]];
            if geometry.flat {
                // Flat shading covers the secondary color too (the lit specular term).
                let secondary_color = provoking.secondary_color;
                let ea = ClipVertex { secondary_color, ..clip_vertices[a] };
                let eb = ClipVertex { secondary_color, ..clip_vertices[b] };
                emit_clip_line(scene, state_index, geometry, [&ea, &eb], codes, flat_color, stipple.as_mut());
            } else {
                let ends = [&clip_vertices[a], &clip_vertices[b]];
                emit_clip_line(scene, state_index, geometry, ends, codes, flat_color, stipple.as_mut());
            }
        }
        Primitive::Triangle { v, provoking, .. } => {
            let [a, b, c] = v.map(|i| i as usize);
            let (oa, ob, oc) = (outcodes[a], outcodes[b], outcodes[c]);
            if oa & ob & oc != 0 {
                return;
            }
            let flat = geometry.flat.then(|| FlatColors::of(&clip_vertices[provoking as usize]));
            if oa | ob | oc == 0 {
                let (va, vb, vc) = (&clip_vertices[a], &clip_vertices[b], &clip_vertices[c]);
                let viewport = &geometry.viewport;
                let back = || [va.back_colors, vb.back_colors, vc.back_colors];
                if let Some(corners) = &corners {
                    let (ca, cb, cc) = (&corners[a], &corners[b], &corners[c]);
                    let snapped = Some([ca.snapped, cb.snapped, cc.snapped]);
                    emit_shaded_triangle_with(scene, state_index, geometry, &[ca.w, cb.w, cc.w], snapped, back, flat);
                } else if slots_unread {
                    let window = |v| viewport.window_without_slots(v);
                    let w = [window(va), window(vb), window(vc)];
                    emit_shaded_triangle_with(scene, state_index, geometry, &w, None, back, flat);
                } else {
                    let w = [viewport.window(va), viewport.window(vb), viewport.window(vc)];
                    emit_shaded_triangle_with(scene, state_index, geometry, &w, None, back, flat);
                }
            } else {
                poly.clear();
                poly.extend([clip_vertices[a], clip_vertices[b], clip_vertices[c]]);
                geometry.planes.clip_polygon(&mut poly, &mut scratch, oa | ob | oc);
                if poly.len() < 3 {
                    return;
                }
                // A fan around the first vertex, each vertex mapped to window space once.
                let window = |v: &ClipVertex<N>| geometry.viewport.window(v);
                let (w0, mut previous) = (window(&poly[0]), window(&poly[1]));
                for i in 1..poly.len() - 1 {
                    let next = window(&poly[i + 1]);
                    let back = [poly[0].back_colors, poly[i].back_colors, poly[i + 1].back_colors];
                    emit_shaded_triangle(scene, state_index, geometry, &[w0, previous, next], back, flat);
                    previous = next;
                }
            }
        }
    });
    stipple
}
