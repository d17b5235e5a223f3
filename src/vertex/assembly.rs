//! Primitive assembly: which vertices of a draw form which points, lines and triangles,
//! which vertex provokes the flat-shaded color, and which polygon edges are boundary edges.
//!
//! Quads, quad strips and polygons become triangles here; the edges a decomposition adds
//! inside a polygon are marked as not being boundary edges, so GL_LINE polygon mode draws
//! only the polygon's outline (and the edge flags of glEdgeFlag are honoured).
use crate::gl::enums::*;
use crate::gl::types::GLenum;

/// A primitive as indices into the draw's vertex array.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    Point(u32),
    /// Endpoints and the provoking vertex.
    Line {
        v: [u32; 2],
        provoking: u32,
    },
    /// Vertices in the order that defines facing, the provoking vertex, and for each edge
    /// (v0→v1, v1→v2, v2→v0) whether it is a boundary edge of the original polygon
    /// (before edge flags, which the caller applies per vertex).
    Triangle {
        v: [u32; 3],
        provoking: u32,
        boundary: [bool; 3],
    },
}

/// Which part of a long connected primitive (strip, fan, loop, polygon) a delivery is.
/// Vertex input delivers such a primitive in bounded parts ([`continued_vertices`] says
/// which vertices each part repeats from the one before), so the geometry stage needs to
/// know where the primitive's outline starts and ends, and carries the line stipple across
/// parts. A draw delivered whole is [`DrawPart::WHOLE`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DrawPart {
    /// The part begins the primitive (a polygon's first edge is an outline edge; the line
    /// stipple starts at 0).
    pub first: bool,
    /// The part ends the primitive (a polygon's closing edge is an outline edge).
    pub last: bool,
}

impl DrawPart {
    pub const WHOLE: DrawPart = DrawPart { first: true, last: true };
}

/// The vertices of a connected primitive that the next part repeats when a part of `count`
/// vertices is delivered: the last one of a line strip (and line loop, whose parts are
/// drawn as line strips and which also keeps its first vertex for the closing segment),
/// the last two of triangle and quad strips (`count` even keeps the odd/even order of
/// strip triangles), the first and the last of fans and polygons (every triangle shares the
/// first vertex). `None` for the modes whose primitives share no vertices.
pub fn continued_vertices(mode: GLenum, count: usize) -> Option<ContinuedVertices> {
    match mode {
        GL_LINE_STRIP => Some(ContinuedVertices { first: false, tail: 1 }),
        GL_LINE_LOOP | GL_TRIANGLE_FAN | GL_POLYGON => Some(ContinuedVertices { first: true, tail: 1 }),
        GL_TRIANGLE_STRIP | GL_QUAD_STRIP if count.is_multiple_of(2) => {
            Some(ContinuedVertices { first: false, tail: 2 })
        }
        _ => None,
    }
}

/// What the next part of a connected primitive repeats ([`continued_vertices`]): the
/// primitive's first vertex when `first`, then the last `tail` vertices of the part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContinuedVertices {
    pub first: bool,
    pub tail: usize,
}

/// How quads become triangles. Mesa's draw module splits a quad v0 v1 v2 v3 along v0–v2
/// when it emits vertices directly, but along v1–v3 (so that the provoking v3 ends both
/// triangles) when the draw goes through its pipeline stages, as it does when any vertex
/// lies outside the view volume (measured: GL_QUADS only; quad strips and polygons keep
/// v0–v2 either way). The split decides which triangle's colors a pixel of a
/// non-planar-colored quad gets, so tessera follows the same rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuadSplit {
    /// Diagonal v0–v2.
    FirstDiagonal,
    /// Diagonal v1–v3 (last-vertex convention through the clipping pipeline).
    SecondDiagonal,
}

/// Calls `emit` for every primitive of `mode` over `count` vertices, in GL order.
/// `first_vertex_convention` selects GL_FIRST_VERTEX_CONVENTION for the provoking vertex.
pub fn assemble(
    mode: GLenum,
    count: u32,
    first_vertex_convention: bool,
    split: QuadSplit,
    mut emit: impl FnMut(Primitive),
) {
    let tri = |v: [u32; 3], last: u32, first: u32| Primitive::Triangle {
        v,
        provoking: if first_vertex_convention { first } else { last },
        boundary: [true; 3],
    };
    let line = |a: u32, b: u32, provoking_last: u32| Primitive::Line {
        v: [a, b],
        provoking: if first_vertex_convention { a } else { provoking_last },
    };
    match mode {
        GL_POINTS => (0..count).for_each(|i| emit(Primitive::Point(i))),
        GL_LINES => (0..count / 2).for_each(|i| emit(line(2 * i, 2 * i + 1, 2 * i + 1))),
        GL_LINE_STRIP => (1..count.max(1)).for_each(|i| emit(line(i - 1, i, i))),
        GL_LINE_LOOP if count >= 2 => {
            (1..count).for_each(|i| emit(line(i - 1, i, i)));
            // The closing segment is provoked by the first vertex (GL 2.1 table 2.12).
            emit(Primitive::Line { v: [count - 1, 0], provoking: if first_vertex_convention { count - 1 } else { 0 } });
        }
        GL_TRIANGLES => (0..count / 3).for_each(|i| emit(tri([3 * i, 3 * i + 1, 3 * i + 2], 3 * i + 2, 3 * i))),
        GL_TRIANGLE_STRIP => {
            for i in 0..count.saturating_sub(2) {
                // Odd triangles swap their first two vertices to keep a consistent facing.
                let v = if i % 2 == 0 { [i, i + 1, i + 2] } else { [i + 1, i, i + 2] };
                emit(tri(v, i + 2, i));
            }
        }
        GL_TRIANGLE_FAN => {
            for i in 1..count.saturating_sub(1) {
                emit(tri([0, i, i + 1], i + 1, i));
            }
        }
        GL_QUADS => {
            for q in 0..count / 4 {
                let b = 4 * q;
                // Quads do not follow the provoking-vertex convention (Mesa reports
                // GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION false): the last vertex.
                let provoking = b + 3;
                quad(&mut emit, [b, b + 1, b + 2, b + 3], provoking, split);
            }
        }
        GL_QUAD_STRIP => {
            for q in 0..(count.saturating_sub(2)) / 2 {
                let b = 2 * q;
                // Quads do not follow the provoking-vertex convention (Mesa reports
                // GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION false): the last vertex.
                let provoking = b + 3;
                quad(&mut emit, [b, b + 1, b + 3, b + 2], provoking, split);
            }
        }
        GL_POLYGON => {
            // A polygon is flat shaded with its first vertex under either convention.
            for i in 1..count.saturating_sub(1) {
                let last = i + 2 == count;
                emit(Primitive::Triangle { v: [0, i, i + 1], provoking: 0, boundary: [i == 1, true, last] });
            }
        }
        _ => {}
    }
}

/// A quad v0 v1 v2 v3 (in polygon order) as two triangles split as `split` says.
fn quad(emit: &mut impl FnMut(Primitive), v: [u32; 4], provoking: u32, split: QuadSplit) {
    match split {
        QuadSplit::FirstDiagonal => {
            emit(Primitive::Triangle { v: [v[0], v[1], v[2]], provoking, boundary: [true, true, false] });
            emit(Primitive::Triangle { v: [v[0], v[2], v[3]], provoking, boundary: [false, true, true] });
        }
        QuadSplit::SecondDiagonal => {
            emit(Primitive::Triangle { v: [v[0], v[1], v[3]], provoking, boundary: [true, false, true] });
            emit(Primitive::Triangle { v: [v[1], v[2], v[3]], provoking, boundary: [true, true, false] });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collect(mode: GLenum, count: u32, first: bool) -> Vec<Primitive> {
        let mut out = Vec::new();
        assemble(mode, count, first, QuadSplit::FirstDiagonal, |p| out.push(p));
        out
    }

    #[test]
    fn counts_follow_the_spec_and_drop_incomplete_primitives() {
        assert_eq!(collect(GL_POINTS, 5, false).len(), 5);
        assert_eq!(collect(GL_LINES, 5, false).len(), 2);
        assert_eq!(collect(GL_LINE_STRIP, 1, false).len(), 0);
        assert_eq!(collect(GL_LINE_LOOP, 4, false).len(), 4);
        assert_eq!(collect(GL_TRIANGLES, 8, false).len(), 2);
        assert_eq!(collect(GL_TRIANGLE_STRIP, 6, false).len(), 4);
        assert_eq!(collect(GL_TRIANGLE_FAN, 6, false).len(), 4);
        assert_eq!(collect(GL_QUADS, 11, false).len(), 4);
        assert_eq!(collect(GL_QUAD_STRIP, 7, false).len(), 4);
        assert_eq!(collect(GL_POLYGON, 5, false).len(), 3);
        assert_eq!(collect(GL_POLYGON, 2, false).len(), 0);
    }

    #[test]
    fn provoking_vertices_follow_table_2_12() {
        let strip = collect(GL_TRIANGLE_STRIP, 4, false);
        assert_eq!(strip[1], Primitive::Triangle { v: [2, 1, 3], provoking: 3, boundary: [true; 3] });
        let loop_ = collect(GL_LINE_LOOP, 3, false);
        assert_eq!(loop_[2], Primitive::Line { v: [2, 0], provoking: 0 });
        let quads = collect(GL_QUAD_STRIP, 4, false);
        assert!(matches!(quads[0], Primitive::Triangle { provoking: 3, .. }));
        let polygon = collect(GL_POLYGON, 4, false);
        assert!(polygon.iter().all(|p| matches!(p, Primitive::Triangle { provoking: 0, .. })));
        let first = collect(GL_TRIANGLES, 3, true);
        assert!(matches!(first[0], Primitive::Triangle { provoking: 0, .. }));
    }

    #[test]
    fn quads_through_the_clipping_pipeline_split_along_the_other_diagonal() {
        let mut out = Vec::new();
        assemble(GL_QUADS, 4, false, QuadSplit::SecondDiagonal, |p| out.push(p));
        assert_eq!(out[0], Primitive::Triangle { v: [0, 1, 3], provoking: 3, boundary: [true, false, true] });
        assert_eq!(out[1], Primitive::Triangle { v: [1, 2, 3], provoking: 3, boundary: [true, true, false] });
    }

    #[test]
    fn polygon_decomposition_marks_only_the_outline() {
        let polygon = collect(GL_POLYGON, 5, false);
        let outline: usize = polygon
            .iter()
            .map(|p| match p {
                Primitive::Triangle { boundary, .. } => boundary.iter().filter(|&&b| b).count(),
                _ => 0,
            })
            .sum();
        assert_eq!(outline, 5);
    }
}
