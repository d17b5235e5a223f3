//! Clipping in homogeneous clip space, and the vertex record that flows through it.
//!
//! A primitive is clipped only when it must be: against the near and far planes (unless
//! depth clamping is on), against enabled user clip planes, and against a guard band far
//! outside the viewport that keeps window coordinates inside the rasterizer's fixed-point
//! range. Everything that merely leaves the viewport is left to the rasterizer, which
//! discards outside pixels for free, so shared edges of visible geometry are never cut and
//! stay watertight.
//!
//! New vertices interpolate every attribute linearly in clip space, always from the outside
//! vertex towards the inside one, so an edge shared by two primitives is cut at exactly
//! the same point whichever primitive it belongs to.
//!
//! The record is generic over its number of varying slots (see [`ClipVertex`]): a
//! fixed-function draw's records carry its four texture units, a GLSL draw's all sixteen
//! slots, and clipping interpolates whatever the record holds.

use crate::gl::limits::MAX_TEXTURE_UNITS;
use crate::glsl::varyings::VARYING_SLOTS;

/// A vertex after transformation: clip coordinates, eye coordinates (for user clip planes
/// and fog) and the attributes the rasterizer interpolates.
///
/// `N` is the number of varying slots the record carries: all of them
/// ([`VARYING_SLOTS`], the default) after a GLSL vertex program, only the texture units'
/// ([`FIXED_SLOTS`]) after fixed-function processing, which writes no other. Every step
/// from here to the primitive jobs is generic over it (monomorphised for the two counts),
/// so a fixed-function draw copies 172-byte records through transformation, clipping and
/// setup instead of 364-byte ones, most of them zeros: the sixteen slots made the small
/// triangles benchmark 14 % more instructions, most of them `memcpy`s of records. A slot
/// beyond a record's `N` reads as zero, the value a full record would hold there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex<const N: usize = VARYING_SLOTS> {
    pub clip: [f32; 4],
    pub eye: [f32; 4],
    pub color: [f32; 4],
    pub secondary_color: [f32; 4],
    /// The back-face primary and secondary colors (two-sided lighting; else unused).
    pub back_colors: [[f32; 4]; 2],
    /// The varying slots: fixed-function texture coordinates in the first
    /// `gl::limits::MAX_TEXTURE_UNITS`, a GLSL program's `gl_TexCoord` and varyings in any
    /// ([`crate::glsl::varyings`]).
    pub tex_coords: [[f32; 4]; N],
    pub fog_coord: f32,
    /// gl_PointSize of a GLSL vertex program (read with GL_VERTEX_PROGRAM_POINT_SIZE; 0 from
    /// fixed-function processing, which never sets it).
    pub point_size: f32,
    /// Whether the edge from this vertex to the next one of its polygon is a boundary edge.
    pub edge_flag: bool,
}

/// The varying slots of a fixed-function vertex: its texture units' coordinates.
pub const FIXED_SLOTS: usize = MAX_TEXTURE_UNITS;

/// A vertex of fixed-function processing (see [`ClipVertex`]'s `N`).
pub type FixedClipVertex = ClipVertex<FIXED_SLOTS>;

impl<const N: usize> ClipVertex<N> {
    /// The record with all [`VARYING_SLOTS`] slots, the ones beyond `N` zero (for the
    /// callers that keep vertices of either kind, selection and feedback).
    pub fn widen(&self) -> ClipVertex {
        let mut tex_coords = [[0.0; 4]; VARYING_SLOTS];
        let n = N.min(VARYING_SLOTS);
        tex_coords[..n].copy_from_slice(&self.tex_coords[..n]);
        ClipVertex {
            clip: self.clip,
            eye: self.eye,
            color: self.color,
            secondary_color: self.secondary_color,
            back_colors: self.back_colors,
            tex_coords,
            fog_coord: self.fog_coord,
            point_size: self.point_size,
            edge_flag: self.edge_flag,
        }
    }

    /// `self + t · (other − self)` for every interpolated quantity.
    fn lerp(&self, other: &Self, t: f32) -> Self {
        let mix = |a: f32, b: f32| a + t * (b - a);
        let mix4 = |a: [f32; 4], b: [f32; 4]| [mix(a[0], b[0]), mix(a[1], b[1]), mix(a[2], b[2]), mix(a[3], b[3])];
        let mut tex_coords = self.tex_coords;
        for (out, (a, b)) in tex_coords.iter_mut().zip(self.tex_coords.iter().zip(&other.tex_coords)) {
            *out = mix4(*a, *b);
        }
        Self {
            clip: mix4(self.clip, other.clip),
            eye: mix4(self.eye, other.eye),
            color: mix4(self.color, other.color),
            secondary_color: mix4(self.secondary_color, other.secondary_color),
            back_colors: [0, 1].map(|k| mix4(self.back_colors[k], other.back_colors[k])),
            tex_coords,
            fog_coord: mix(self.fog_coord, other.fog_coord),
            point_size: mix(self.point_size, other.point_size),
            edge_flag: self.edge_flag,
        }
    }
}

/// The planes a primitive is clipped against, as signed distance functions: a point is
/// inside a plane when its distance is ≥ 0.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipPlanes {
    /// Guard band half-extent in normalized device coordinates (|x/w|, |y/w| ≤ this).
    pub guard_x: f32,
    pub guard_y: f32,
    /// Clip against the near and far planes (off with GL_DEPTH_CLAMP).
    pub clip_z: bool,
    /// The near plane is z = 0 (GL_ZERO_TO_ONE, ARB_clip_control) instead of z = −w.
    pub zero_to_one: bool,
    /// Enabled user clip planes, in eye coordinates.
    pub user: Vec<[f32; 4]>,
}

/// Number of fixed planes: x±, y±, z± and w > 0.
const FIXED_PLANES: usize = 7;

impl ClipPlanes {
    pub fn count(&self) -> usize {
        FIXED_PLANES + self.user.len()
    }

    /// Signed distance of `v` to plane `i`. Planes are numbered (and polygons clipped
    /// against them) in Mesa's order, right, left, top, bottom, near, far: the order
    /// decides the last bits of vertices cut by several planes.
    #[inline]
    pub fn distance<const N: usize>(&self, i: usize, v: &ClipVertex<N>) -> f32 {
        let [x, y, z, w] = v.clip;
        match i {
            0 => self.guard_x * w - x,
            1 => self.guard_x * w + x,
            2 => self.guard_y * w - y,
            3 => self.guard_y * w + y,
            4 => {
                if !self.clip_z {
                    0.0
                } else if self.zero_to_one {
                    z
                } else {
                    w + z
                }
            }
            5 => {
                if self.clip_z {
                    w - z
                } else {
                    0.0
                }
            }
            // w must stay positive for the divide; a tiny positive bound keeps 1/w finite.
            6 => w - W_EPSILON,
            _ => {
                let p = self.user[i - FIXED_PLANES];
                let e = v.eye;
                p[0] * e[0] + p[1] * e[1] + p[2] * e[2] + p[3] * e[3]
            }
        }
    }

    /// Bit set of the planes `v` is outside of (NaN counts as outside).
    ///
    /// The fixed planes' distances are written out (the same expressions as
    /// [`ClipPlanes::distance`], so the same bits) and tested without branches.
    #[inline]
    pub fn outcode<const N: usize>(&self, v: &ClipVertex<N>) -> u32 {
        let mut code = match (self.clip_z, self.zero_to_one) {
            (false, _) => self.fixed_code(v, |_, _| (0.0, 0.0)),
            (true, true) => self.fixed_code(v, |z, w| (z, w - z)),
            (true, false) => self.fixed_code(v, |z, w| (w + z, w - z)),
        };
        for i in FIXED_PLANES..self.count() {
            code |= outside(self.distance(i, v)) << i;
        }
        code
    }

    /// [`ClipPlanes::outcode`] of every vertex of `vertices`, in order: this runs for every
    /// vertex of every draw, so the near and far planes' form is chosen once, outside a
    /// loop of plain comparisons, and the user planes have a pass of their own when enabled.
    pub fn outcodes<const N: usize>(&self, vertices: &[ClipVertex<N>]) -> Vec<u32> {
        let mut codes: Vec<u32> = match (self.clip_z, self.zero_to_one) {
            (false, _) => vertices.iter().map(|v| self.fixed_code(v, |_, _| (0.0, 0.0))).collect(),
            (true, true) => vertices.iter().map(|v| self.fixed_code(v, |z, w| (z, w - z))).collect(),
            (true, false) => vertices.iter().map(|v| self.fixed_code(v, |z, w| (w + z, w - z))).collect(),
        };
        if !self.user.is_empty() {
            for (code, v) in codes.iter_mut().zip(vertices) {
                for i in FIXED_PLANES..self.count() {
                    *code |= outside(self.distance(i, v)) << i;
                }
            }
        }
        codes
    }

    /// The bits of the fixed planes, the near and far distances given by `near_far(z, w)`.
    #[inline(always)]
    fn fixed_code<const N: usize>(&self, v: &ClipVertex<N>, near_far: impl Fn(f32, f32) -> (f32, f32)) -> u32 {
        let [x, y, z, w] = v.clip;
        let (near, far) = near_far(z, w);
        outside(self.guard_x * w - x)
            | outside(self.guard_x * w + x) << 1
            | outside(self.guard_y * w - y) << 2
            | outside(self.guard_y * w + y) << 3
            | outside(near) << 4
            | outside(far) << 5
            | outside(w - W_EPSILON) << 6
    }

    /// Clips the convex polygon `poly` against every plane in `mask`, in place.
    /// `scratch` is reused storage. The result may be empty.
    pub fn clip_polygon<const N: usize>(
        &self,
        poly: &mut Vec<ClipVertex<N>>,
        scratch: &mut Vec<ClipVertex<N>>,
        mask: u32,
    ) {
        for plane in 0..self.count() {
            if mask & (1 << plane) == 0 || poly.is_empty() {
                continue;
            }
            scratch.clear();
            let n = poly.len();
            for i in 0..n {
                let cur = &poly[i];
                let next = &poly[(i + 1) % n];
                let d_cur = self.distance(plane, cur);
                let d_next = self.distance(plane, next);
                let cur_in = d_cur >= 0.0;
                let next_in = d_next >= 0.0;
                if cur_in {
                    scratch.push(*cur);
                }
                if cur_in != next_in {
                    // Interpolate from the outside vertex towards the inside one.
                    let (out, inside, d_out, d_in) =
                        if cur_in { (next, cur, d_next, d_cur) } else { (cur, next, d_cur, d_next) };
                    let t = d_out / (d_out - d_in);
                    let mut v = out.lerp(inside, t);
                    // The edge leaving the clip plane keeps the flag of the edge it cuts; the
                    // new edge along the plane is not a boundary of the original polygon.
                    v.edge_flag = if cur_in { false } else { cur.edge_flag };
                    scratch.push(v);
                }
            }
            std::mem::swap(poly, scratch);
        }
    }

    /// Clips the segment `a`–`b` plane by plane, exactly as a polygon edge is clipped;
    /// `None` when nothing remains.
    pub fn clip_line<const N: usize>(
        &self,
        a: &ClipVertex<N>,
        b: &ClipVertex<N>,
        mask: u32,
    ) -> Option<(ClipVertex<N>, ClipVertex<N>)> {
        let (mut a, mut b) = (*a, *b);
        for plane in 0..self.count() {
            if mask & (1 << plane) == 0 {
                continue;
            }
            let da = self.distance(plane, &a);
            let db = self.distance(plane, &b);
            match (da >= 0.0, db >= 0.0) {
                (true, true) => {}
                (false, false) => return None,
                (false, true) => a = a.lerp(&b, da / (da - db)),
                (true, false) => b = b.lerp(&a, db / (db - da)),
            }
        }
        Some((a, b))
    }
}

/// 1 when a vertex at signed distance `d` is outside its plane: not `d ≥ 0`, so NaN is
/// outside too, in one comparison.
#[inline(always)]
#[allow(clippy::neg_cmp_op_on_partial_ord)] // `!(d >= 0)` is the point: NaN is outside
fn outside(d: f32) -> u32 {
    (!(d >= 0.0)) as u32
}

/// Smallest w a clipped vertex may have.
pub const W_EPSILON: f32 = 1e-30;

#[cfg(test)]
mod tests {
    use super::*;

    fn vertex(x: f32, y: f32, z: f32, w: f32) -> ClipVertex {
        ClipVertex {
            clip: [x, y, z, w],
            eye: [x, y, z, w],
            color: [x, y, z, 1.0],
            secondary_color: [0.0; 4],
            back_colors: [[0.0; 4]; 2],
            tex_coords: [[0.0; 4]; VARYING_SLOTS],
            fog_coord: 0.0,
            point_size: 0.0,
            edge_flag: true,
        }
    }

    fn planes() -> ClipPlanes {
        ClipPlanes { guard_x: 1.0, guard_y: 1.0, clip_z: true, zero_to_one: false, user: Vec::new() }
    }

    #[test]
    fn a_triangle_crossing_the_near_plane_is_cut_there() {
        let p = planes();
        let tri = [vertex(0.0, 0.0, -2.0, 1.0), vertex(0.5, 0.0, 0.0, 1.0), vertex(0.0, 0.5, 0.0, 1.0)];
        let mask = tri.iter().fold(0, |m, v| m | p.outcode(v));
        assert_eq!(mask, 1 << 4);
        let mut poly = tri.to_vec();
        p.clip_polygon(&mut poly, &mut Vec::new(), mask);
        assert_eq!(poly.len(), 4);
        for v in &poly {
            assert!(v.clip[2] >= -v.clip[3] - 1e-6);
        }
    }

    /// GL_ZERO_TO_ONE (ARB_clip_control): the near plane is z_c = 0, so a vertex with
    /// −w ≤ z < 0 is outside, and the cut lands exactly on z = 0.
    #[test]
    fn zero_to_one_clips_at_z_zero() {
        let p = ClipPlanes { zero_to_one: true, ..planes() };
        assert_eq!(p.outcode(&vertex(0.0, 0.0, -0.5, 1.0)), 1 << 4);
        assert_eq!(planes().outcode(&vertex(0.0, 0.0, -0.5, 1.0)), 0);
        assert_eq!(p.outcode(&vertex(0.0, 0.0, 0.0, 1.0)), 0);
        assert_eq!(p.outcode(&vertex(0.0, 0.0, 1.5, 1.0)), 1 << 5);
        let (a, b) = p.clip_line(&vertex(0.0, 0.0, -1.0, 1.0), &vertex(0.0, 0.0, 1.0, 1.0), 1 << 4).unwrap();
        assert_eq!((a.clip[2], b.clip[2]), (0.0, 1.0));
    }

    #[test]
    fn shared_edges_are_cut_at_the_same_point_in_either_direction() {
        let p = planes();
        let a = vertex(-3.0, 0.2, 0.0, 1.0);
        let b = vertex(0.7, -0.4, 0.3, 1.0);
        let mask = p.outcode(&a) | p.outcode(&b);
        let (x0, y0) = p.clip_line(&a, &b, mask).unwrap();
        let (y1, x1) = p.clip_line(&b, &a, mask).unwrap();
        assert_eq!(x0, x1);
        assert_eq!(y0, y1);
        let mut poly1 = vec![a, b, vertex(0.0, 0.9, 0.0, 1.0)];
        let mut poly2 = vec![b, a, vertex(0.0, -0.9, 0.0, 1.0)];
        p.clip_polygon(&mut poly1, &mut Vec::new(), mask);
        p.clip_polygon(&mut poly2, &mut Vec::new(), mask);
        let on_plane = |v: &&ClipVertex| (v.clip[0] + 1.0).abs() < 1e-5;
        let cut1: Vec<_> = poly1.iter().filter(on_plane).map(|v| v.clip).collect();
        let cut2: Vec<_> = poly2.iter().filter(on_plane).map(|v| v.clip).collect();
        assert!(cut1.iter().any(|c| cut2.contains(c)), "{cut1:?} {cut2:?}");
    }

    #[test]
    fn vertices_behind_the_eye_are_removed() {
        let p = planes();
        let mut poly = vec![vertex(0.0, 0.0, 0.0, 1.0), vertex(1.0, 0.0, 0.0, -1.0), vertex(0.0, 1.0, 0.0, -1.0)];
        let mask = poly.iter().fold(0, |m, v| m | p.outcode(v));
        p.clip_polygon(&mut poly, &mut Vec::new(), mask);
        assert!(poly.iter().all(|v| v.clip[3] > 0.0));
    }

    /// Every varying slot, the last ones too, is interpolated at the cut (a GLSL vertex's
    /// record), and a fixed-function record clips to the same values in the slots it has,
    /// its wider copy's others staying zero.
    #[test]
    fn clipping_interpolates_every_varying_slot() {
        let p = planes();
        let mut tri = [vertex(0.0, 0.0, -3.0, 1.0), vertex(0.5, 0.0, 0.0, 1.0), vertex(0.0, 0.5, 0.0, 1.0)];
        for (k, v) in tri.iter_mut().enumerate() {
            for (slot, t) in v.tex_coords.iter_mut().enumerate() {
                *t = [0, 1, 2, 3].map(|c| (slot * 10 + c) as f32 + 100.0 * k as f32);
            }
        }
        let mask = tri.iter().fold(0, |m, v| m | p.outcode(v));
        let mut poly = tri.to_vec();
        p.clip_polygon(&mut poly, &mut Vec::new(), mask);
        assert_eq!(poly.len(), 4);
        // The cuts: from vertex 0 (z = −3) towards 1 and towards 2 (z = 0), at t = 2/3.
        let cuts: Vec<&ClipVertex> = poly.iter().filter(|v| !tri.contains(v)).collect();
        assert_eq!(cuts.len(), 2);
        for cut in &cuts {
            let t = 2.0 / 3.0;
            let to = if cut.clip[0] > 0.0 { 1 } else { 2 };
            for slot in [0, 3, 4, 9, VARYING_SLOTS - 1] {
                for c in 0..4 {
                    let (a, b) = (tri[0].tex_coords[slot][c], tri[to].tex_coords[slot][c]);
                    let want = a + t * (b - a);
                    assert!((cut.tex_coords[slot][c] - want).abs() < 1e-3, "slot {slot}: {cut:?}");
                }
            }
        }
        let mut fixed: Vec<FixedClipVertex> = tri
            .iter()
            .map(|v| {
                let mut tex_coords = [[0.0; 4]; FIXED_SLOTS];
                tex_coords.copy_from_slice(&v.tex_coords[..FIXED_SLOTS]);
                FixedClipVertex {
                    clip: v.clip,
                    eye: v.eye,
                    color: v.color,
                    secondary_color: v.secondary_color,
                    back_colors: v.back_colors,
                    tex_coords,
                    fog_coord: v.fog_coord,
                    point_size: v.point_size,
                    edge_flag: v.edge_flag,
                }
            })
            .collect();
        p.clip_polygon(&mut fixed, &mut Vec::new(), mask);
        assert_eq!(fixed.len(), poly.len());
        for (f, full) in fixed.iter().zip(&poly) {
            let wide = f.widen();
            assert_eq!(wide.tex_coords[..FIXED_SLOTS], full.tex_coords[..FIXED_SLOTS]);
            assert!(wide.tex_coords[FIXED_SLOTS..].iter().all(|t| *t == [0.0; 4]));
            assert_eq!((wide.clip, wide.color, wide.edge_flag), (full.clip, full.color, full.edge_flag));
        }
    }

    #[test]
    fn nan_is_outside() {
        assert_ne!(planes().outcode(&vertex(f32::NAN, 0.0, 0.0, 1.0)), 0);
    }
}
