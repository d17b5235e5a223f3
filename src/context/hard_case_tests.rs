//! The hard-case suite: numerically hard inputs with analytic expectations, run through the
//! whole draw path (transform, clipping, setup, binning, fragment operations) in every
//! accuracy mode.
//!
//! Coverage is the same in every mode (the modes change attribute interpolation only), so
//! coverage, depth and stencil expectations are exact in all of them; where a case checks
//! interpolated colors, the fast mode's bound is stated at the check.
//!
//! Most cases count how often each pixel is hit with additive blending of 1/255 into an
//! RGBA8 buffer, so a count above one (overlap) is as visible as a hole.
use super::Context;
use crate::framebuffer::surface::{ColorPixels, DepthStencilPixels};
use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, Drawable, FramebufferConfig};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::setup::accuracy::Accuracy;
use crate::vertex::Vertex;
use std::sync::{Arc, Mutex};

const RGBA8: ColorFormat = ColorFormat::Unorm8 { alpha: true };
const FLOAT: ColorFormat = ColorFormat::Float32 { alpha: true };
const DEPTH24: DepthStencilFormat = DepthStencilFormat::Packed24 { depth: true, stencil: true };

fn vertex(position: [f32; 4], color: [f32; 4]) -> Vertex {
    Vertex {
        position,
        color,
        secondary_color: [0.0; 4],
        normal: [0.0, 0.0, 1.0],
        tex_coords: [[0.0; 4]; 4],
        fog_coord: 0.0,
        edge_flag: true,
        generic: crate::vertex::generic::CURRENT,
    }
}

/// A context on a fresh drawable, identity matrices (positions are clip coordinates).
struct Harness {
    ctx: Context,
    drawable: Arc<Mutex<Drawable>>,
    width: usize,
    height: usize,
}

impl Harness {
    fn new(color: ColorFormat, depth: DepthStencilFormat, width: usize, height: usize, accuracy: Accuracy) -> Self {
        let visual = FramebufferConfig::single_buffered(color, depth, 0);
        let (mut ctx, drawable) = Context::with_test_drawable(visual, width, height);
        ctx.accuracy = accuracy;
        ctx.set_capability(GL_DITHER, false);
        Harness { ctx, drawable, width, height }
    }

    /// A harness whose draws add 1/255 to every pixel they hit (RGBA8, cleared to 0).
    fn counting(width: usize, height: usize, accuracy: Accuracy) -> Self {
        let mut h = Harness::new(RGBA8, DEPTH24, width, height, accuracy);
        h.ctx.set_capability(GL_BLEND, true);
        h.ctx.blend_func(None, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
        h
    }

    /// Ortho projection mapping object (x, y) to window pixels.
    fn window_coordinates(&mut self) {
        self.ctx.matrix_mode(GL_PROJECTION);
        self.ctx.ortho(0.0, self.width as f64, 0.0, self.height as f64, -1.0, 1.0);
        self.ctx.matrix_mode(GL_MODELVIEW);
    }

    fn draw(&mut self, mode: GLenum, vertices: &[Vertex]) {
        self.ctx.draw_vertices(mode, vertices);
    }

    /// Triangles (window or clip coordinates as set up), each vertex with `color`.
    fn triangles(&mut self, triangles: &[[[f32; 4]; 3]], color: [f32; 4]) {
        let v: Vec<Vertex> = triangles.iter().flat_map(|t| t.map(|p| vertex(p, color))).collect();
        self.draw(GL_TRIANGLES, &v);
    }

    /// Every pixel as f32 RGBA, row 0 at the bottom.
    fn colors(&mut self) -> Vec<[f32; 4]> {
        self.ctx.flush_rendering();
        let guard = self.drawable.lock().unwrap();
        let buffer = guard.framebuffer.color(ColorSlot::FrontLeft).unwrap();
        let mut all = Vec::new();
        let mut row = Vec::new();
        for y in 0..self.height as i32 {
            row.clear();
            buffer.read_row_f32(y, 0, self.width as i32, &mut row);
            all.extend_from_slice(&row);
        }
        all
    }

    fn rgba8(&mut self) -> Vec<[u8; 4]> {
        self.ctx.flush_rendering();
        let guard = self.drawable.lock().unwrap();
        match guard.framebuffer.color(ColorSlot::FrontLeft).unwrap().pixels() {
            ColorPixels::Unorm8(p) => p.clone(),
            _ => panic!("not an RGBA8 buffer"),
        }
    }

    /// The hit count of every pixel of a counting harness.
    fn counts(&mut self) -> Vec<u8> {
        self.rgba8().iter().map(|p| p[0]).collect()
    }

    /// Depth values as stored (16, 24 or 32 bits).
    fn depths(&mut self) -> Vec<u32> {
        self.ctx.flush_rendering();
        let guard = self.drawable.lock().unwrap();
        match guard.framebuffer.depth_stencil().pixels() {
            DepthStencilPixels::Depth16(d) => d.iter().map(|&v| v as u32).collect(),
            DepthStencilPixels::Packed24(d) => d.iter().map(|&v| v & 0xff_ffff).collect(),
            DepthStencilPixels::Depth32(d, _) => d.clone(),
            DepthStencilPixels::None => panic!("no depth buffer"),
        }
    }

    fn stencils(&mut self) -> Vec<u8> {
        self.ctx.flush_rendering();
        let guard = self.drawable.lock().unwrap();
        match guard.framebuffer.depth_stencil().pixels() {
            DepthStencilPixels::Packed24(d) => d.iter().map(|&v| (v >> 24) as u8).collect(),
            DepthStencilPixels::Depth32(_, Some(s)) => s.clone(),
            _ => panic!("no stencil buffer"),
        }
    }

    /// The clip-space position whose window position is the centre of pixel (x, y)
    /// (full-window viewport).
    fn ndc_of_centre(&self, x: usize, y: usize) -> [f64; 2] {
        [(x as f64 + 0.5) / self.width as f64 * 2.0 - 1.0, (y as f64 + 0.5) / self.height as f64 * 2.0 - 1.0]
    }
}

fn full_quad(z: f32, color: [f32; 4]) -> Vec<Vertex> {
    [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].iter().map(|p| vertex([p[0], p[1], z, 1.0], color)).collect()
}

/// Whether the clip-space triangle `t` (x, y, z, w per vertex) covers the point of NDC
/// `(nx, ny)` after clipping to the view volume: some point of the triangle with w > 0 and
/// −w ≤ z ≤ w projects there. Solves (x, y, w)ᵢ·λ = (nx, ny, 1) in f64 (the weights are the
/// homogeneous barycentrics); `None` when the triangle is degenerate in (x, y, w).
fn clip_covers(t: &[[f64; 4]; 3], nx: f64, ny: f64) -> Option<bool> {
    let m = |i: usize| [t[i][0], t[i][1], t[i][3]];
    let (a, b, c) = (m(0), m(1), m(2));
    let det3 = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    };
    let d = det3(a, b, c);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let p = [nx, ny, 1.0];
    let l = [det3(p, b, c) / d, det3(a, p, c) / d, det3(a, b, p) / d];
    if l.iter().any(|&x| x < 0.0) {
        return Some(false);
    }
    let z: f64 = (0..3).map(|i| l[i] * t[i][2]).sum();
    Some((-1.0..=1.0).contains(&z))
}

/// Checks a counting render of clip-space triangle `t` against [`clip_covers`]: a pixel whose
/// centre and the four points ±`margin` pixels around it agree must be hit exactly when
/// covered; pixels within the margin of an edge may go either way but are hit at most once.
fn assert_clip_coverage(h: &mut Harness, t: [[f32; 4]; 3], margin: f64, what: &str) {
    let counts = h.counts();
    let t64 = t.map(|v| v.map(|c| c as f64));
    let (w, hh) = (h.width, h.height);
    let mut checked = 0;
    for y in 0..hh {
        for x in 0..w {
            let n = counts[y * w + x];
            assert!(n <= 1, "{what}: pixel ({x},{y}) hit {n} times");
            let [nx, ny] = h.ndc_of_centre(x, y);
            let (dx, dy) = (2.0 * margin / w as f64, 2.0 * margin / hh as f64);
            let probes = [(0.0, 0.0), (dx, 0.0), (-dx, 0.0), (0.0, dy), (0.0, -dy)];
            let results: Vec<Option<bool>> =
                probes.iter().map(|(ox, oy)| clip_covers(&t64, nx + ox, ny + oy)).collect();
            let Some(Some(expected)) = results.first().copied() else {
                continue;
            };
            if results.iter().all(|r| *r == Some(expected)) {
                checked += 1;
                assert_eq!(n == 1, expected, "{what}: pixel ({x},{y}) hit {n} times, covered: {expected}");
            }
        }
    }
    assert!(checked > w * hh / 2, "{what}: only {checked} pixels away from edges");
}

// ---------------------------------------------------------------------------------------
// Clipping at the near plane and the eye plane (w = 0), w < 0, tiny w.

#[test]
fn triangles_crossing_the_eye_plane_have_no_holes_and_no_wrong_side_pixels() {
    let near_zero_ws = [1e-30f32, 0.0, -1e-30, 1e-7, -1e-7, -0.5, -1.0, 0.25];
    for accuracy in Accuracy::ALL {
        for &w in &near_zero_ws {
            // Two ordinary vertices and one near (or behind) the eye, pointing up-right: its
            // part with w > 0 reaches towards infinity along that direction. The apex's z
            // puts it in front of, on, or behind the near plane too.
            for apex_z in [0.0f32, 0.6, -0.6] {
                let base = [[-0.6, -0.7, -0.3, 1.0], [0.5, -0.4, 0.4, 1.0]];
                let apex = [0.3, 0.5, apex_z, w];
                for rotation in 0..3 {
                    let mut t = [base[0], base[1], apex];
                    t.rotate_left(rotation);
                    let mut h = Harness::counting(48, 40, accuracy);
                    h.triangles(&[t], [1.0 / 255.0; 4]);
                    let what = format!("{accuracy:?} w={w} z={apex_z} rotation {rotation}");
                    assert_clip_coverage(&mut h, t, 0.05, &what);
                }
            }
        }
    }
}

#[test]
fn vertices_behind_the_eye_and_at_infinity_give_finite_colors_and_depths() {
    // Float color buffer (unclamped): a NaN or infinity from the clipper or the perspective
    // divide would survive into the buffer. Colors must stay within the vertices' range.
    let cases: [[[f32; 4]; 3]; 5] = [
        [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.0, 1.0], [0.3, 0.5, 0.2, 0.0]],
        [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.0, 1.0], [0.3, 0.5, 0.0, 1e-30]],
        [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.5, -1.0], [0.3, 0.5, 0.0, -1e-30]],
        [[-0.5, -0.5, -0.9, 1.0], [0.5, -0.5, 0.3, 0.0], [0.3, 0.5, 0.0, 0.0]],
        [[-0.5, -0.5, 2.0, 1.0], [0.5, -0.5, -3.0, 1.0], [0.3, 0.5, 0.0, -1e-7]],
    ];
    let colors = [[1.0, 0.0, 0.25, 1.0], [0.0, 1.0, 0.5, 0.5], [0.5, 0.5, 1.0, 0.0]];
    for accuracy in Accuracy::ALL {
        for (k, t) in cases.iter().enumerate() {
            let mut h = Harness::new(FLOAT, DEPTH24, 32, 32, accuracy);
            h.ctx.set_capability(GL_DEPTH_TEST, true);
            h.ctx.depth_func(GL_ALWAYS);
            h.ctx.clear_color([-7.0; 4]);
            h.ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            let v: Vec<Vertex> = (0..3).map(|i| vertex(t[i], colors[i])).collect();
            h.draw(GL_TRIANGLES, &v);
            for (i, c) in h.colors().iter().enumerate() {
                if *c == [-7.0; 4] {
                    continue;
                }
                for (ch, &value) in c.iter().enumerate() {
                    let (lo, hi) = (
                        colors.iter().map(|c| c[ch]).fold(1.0f32, f32::min),
                        colors.iter().map(|c| c[ch]).fold(0.0f32, f32::max),
                    );
                    assert!(
                        value.is_finite() && value >= lo - 1e-4 && value <= hi + 1e-4,
                        "{accuracy:?} case {k}: pixel {i} channel {ch} = {value}"
                    );
                }
            }
            assert!(h.depths().iter().all(|&d| d <= 0xff_ffff));
        }
    }
}

// ---------------------------------------------------------------------------------------
// Huge and tiny coordinates, the largest viewport, the guard band.

#[test]
fn huge_coordinates_cover_exactly_what_they_should() {
    for accuracy in Accuracy::ALL {
        for &big in &[1e5f32, 1e7, 3e7] {
            // A quad far larger than the window: every pixel exactly once.
            let mut h = Harness::counting(40, 36, accuracy);
            let q = [[-big, -big, 0.0, 1.0], [big, -big, 0.0, 1.0], [big, big, 0.0, 1.0], [-big, big, 0.0, 1.0]];
            h.triangles(&[[q[0], q[1], q[2]], [q[0], q[2], q[3]]], [1.0 / 255.0; 4]);
            assert!(h.counts().iter().all(|&n| n == 1), "{accuracy:?} quad ±{big}");
            // A huge triangle whose edge crosses the window: a half-plane.
            for t in [
                [[-big, -big * 0.9, 0.0, 1.0], [big, -big * 1.1 + 0.37, 0.0, 1.0], [0.2, big, 0.0, 1.0]],
                [[-big, 0.1, 0.0, 1.0], [big * 0.5, -big, 0.0, 1.0], [big, big, 0.0, 1.0]],
            ] {
                let mut h = Harness::counting(40, 36, accuracy);
                h.triangles(&[t], [1.0 / 255.0; 4]);
                assert_clip_coverage(&mut h, t, 0.05, &format!("{accuracy:?} huge triangle {big}"));
            }
        }
    }
}

#[test]
fn tiny_coordinates_scaled_up_cover_like_their_scaled_copy() {
    // Object coordinates of 1e-7 scaled by 1e7 (and 1e7 scaled by 1e-7) cover exactly the
    // pixels of the same triangle given directly, away from its edges.
    let t = [[-0.71, -0.52, 0.0, 1.0], [0.66, -0.3, 0.0, 1.0], [0.1, 0.77, 0.0, 1.0]];
    for accuracy in Accuracy::ALL {
        for scale in [1e-7f32, 1e7] {
            let mut h = Harness::counting(40, 40, accuracy);
            h.ctx.scale(1.0 / scale, 1.0 / scale, 1.0);
            let scaled = t.map(|v| [v[0] * scale, v[1] * scale, 0.0, 1.0]);
            h.triangles(&[scaled], [1.0 / 255.0; 4]);
            assert_clip_coverage(&mut h, t, 0.02, &format!("{accuracy:?} scaled by {scale}"));
        }
    }
}

#[test]
fn the_largest_viewport_maps_exactly() {
    let max = crate::gl::limits::MAX_VIEWPORT_DIM;
    for accuracy in Accuracy::ALL {
        let mut h = Harness::counting(64, 48, accuracy);
        // The window is the lower-left corner of a viewport of the largest size.
        h.ctx.viewport(0, 0, max, max);
        // Window coordinates (px, py) are NDC (2px/max − 1, 2py/max − 1), exact in f32.
        let ndc = |p: f32| 2.0 * p / max as f32 - 1.0;
        let tri = [[3.25f32, 2.5], [60.75, 10.0], [20.0, 45.5]];
        let t = tri.map(|p| [ndc(p[0]), ndc(p[1]), 0.0, 1.0]);
        h.triangles(&[t], [1.0 / 255.0; 4]);
        let counts = h.counts();
        let expected = exact_coverage(&tri.map(|p| [p[0] as f64, p[1] as f64]), 64, 48);
        assert_eq!(counts, expected, "{accuracy:?}");
    }
}

#[test]
fn guard_band_boundaries_are_exact() {
    // Vertices exactly at, just inside and just outside the guard band (2^22 pixels from the
    // window origin): the covered pixels of the window are the analytic half-planes.
    let guard = crate::setup::triangle::GUARD_BAND as f64;
    let size = 32usize;
    // NDC of window coordinate g for a `size`-pixel viewport at the origin.
    let ndc = |g: f64| (2.0 * g / size as f64 - 1.0) as f32;
    for accuracy in Accuracy::ALL {
        for offset in [-1.0, -1.0 / 256.0, 0.0, 1.0 / 256.0, 1.0, 4096.0] {
            let g = guard + offset;
            for t in [
                [[ndc(-g), ndc(3.0), 0.0, 1.0], [ndc(g), ndc(20.0), 0.0, 1.0], [ndc(5.0), ndc(g), 0.0, 1.0]],
                [[ndc(-g), ndc(-g), 0.0, 1.0], [ndc(g), ndc(-g), 0.0, 1.0], [ndc(16.3), ndc(17.7), 0.0, 1.0]],
            ] {
                let mut h = Harness::counting(size, size, accuracy);
                h.triangles(&[t], [1.0 / 255.0; 4]);
                assert_clip_coverage(&mut h, t, 0.05, &format!("{accuracy:?} guard band {offset:+}"));
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Slivers and needles: coverage equals the exact count of centres inside.

/// Exact coverage of a window-space triangle whose coordinates are multiples of 1/256:
/// edge functions in i128 over 1/512-pixel units (centres at odd multiples of 256), the
/// fill rule as GL's y-up left/bottom edges. Independent of `setup::triangle`.
fn exact_coverage(t: &[[f64; 2]; 3], width: usize, height: usize) -> Vec<u8> {
    let fixed = |v: f64| {
        let f = v * 512.0;
        assert_eq!(f, f.round(), "not on the 1/256 grid");
        f as i128
    };
    let mut p: Vec<[i128; 2]> = t.iter().map(|v| [fixed(v[0]), fixed(v[1])]).collect();
    let area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    let mut out = vec![0u8; width * height];
    if area == 0 {
        return out;
    }
    if area < 0 {
        p.swap(1, 2);
    }
    for y in 0..height {
        for x in 0..width {
            let c = [x as i128 * 512 + 256, y as i128 * 512 + 256];
            let inside = (0..3).all(|i| {
                let (a, b) = (p[i], p[(i + 1) % 3]);
                let e = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let owns_centres = dy < 0 || (dy == 0 && dx > 0);
                e > 0 || (e == 0 && owns_centres)
            });
            out[y * width + x] = inside as u8;
        }
    }
    out
}

#[test]
fn slivers_and_needles_cover_exactly_the_centres_inside() {
    let q = |v: f64| (v * 256.0).round() / 256.0;
    let mut seed = 0x1234_5678u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (w, h) = (96usize, 64usize);
    let mut cases: Vec<[[f64; 2]; 3]> = Vec::new();
    for _ in 0..150 {
        // Needles of 1000:1 aspect (length ~60, width ~0.06) and slivers below one pixel.
        let (x0, y0) = (q(2.0 + next() * 90.0), q(2.0 + next() * 60.0));
        let angle = next() * std::f64::consts::TAU;
        let len = 20.0 + next() * 60.0;
        let (dx, dy) = (angle.cos() * len, angle.sin() * len);
        let width = len / 1000.0;
        cases.push([
            [x0, y0],
            [q(x0 + dx), q(y0 + dy)],
            [q(x0 + dx - angle.sin() * width), q(y0 + dy + angle.cos() * width)],
        ]);
        let s = next() * 0.9;
        cases.push([[x0, y0], [q(x0 + s), q(y0 + 0.3 * s)], [q(x0 + 0.2 * s), q(y0 + s)]]);
        // Slivers through pixel centres.
        let (cx, cy) = ((x0.floor() + 0.5).min(94.5), (y0.floor() + 0.5).min(62.5));
        cases.push([[cx, cy], [q(cx + len.min(40.0)), cy], [q(cx + 3.0), q(cy + 1.0 / 256.0)]]);
        cases.push([[cx, cy], [q(cx + len.min(40.0)), cy], [q(cx + 3.0), q(cy - 0.75)]]);
        cases.push([[cx, cy], [cx, q(cy + len.min(30.0))], [q(cx - 1.0 / 256.0), q(cy + 2.0)]]);
        cases.push([[cx, cy], [cx, q(cy + len.min(30.0))], [q(cx + 0.6), q(cy + 2.0)]]);
    }
    for accuracy in Accuracy::ALL {
        for (k, t) in cases.iter().enumerate() {
            let mut hs = Harness::counting(w, h, accuracy);
            hs.window_coordinates();
            hs.triangles(&[t.map(|p| [p[0] as f32, p[1] as f32, 0.0, 1.0])], [1.0 / 255.0; 4]);
            assert_eq!(hs.counts(), exact_coverage(t, w, h), "{accuracy:?} case {k}: {t:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Watertightness of large meshes, at many sub-pixel offsets and rotations.

/// A rotated, offset grid of `n`×`n` cells (2n² triangles) with jittered inner points.
fn rotated_grid(n: usize, size: f32, centre: [f32; 2], angle: f32, jitter: f32, seed: u32) -> Vec<[[f32; 4]; 3]> {
    let mut seed = seed | 1;
    let (s, c) = angle.sin_cos();
    let half = n as f32 * size / 2.0;
    let mut points = vec![[0.0f32; 2]; (n + 1) * (n + 1)];
    for j in 0..=n {
        for i in 0..=n {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            let r = |s: u32| (s % 1000) as f32 / 1000.0 - 0.5;
            let inner = i > 0 && i < n && j > 0 && j < n;
            let (jx, jy) = if inner { (r(seed) * jitter, r(seed >> 10) * jitter) } else { (0.0, 0.0) };
            let (x, y) = (i as f32 * size - half + jx, j as f32 * size - half + jy);
            points[j * (n + 1) + i] = [centre[0] + c * x - s * y, centre[1] + s * x + c * y];
        }
    }
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let p = |a: usize, b: usize| {
                let q = points[(j + b) * (n + 1) + i + a];
                [q[0], q[1], 0.0, 1.0]
            };
            tris.push([p(0, 0), p(1, 0), p(1, 1)]);
            tris.push([p(0, 0), p(1, 1), p(0, 1)]);
        }
    }
    tris
}

#[test]
fn ten_thousand_triangle_grids_are_watertight_at_any_offset_and_rotation() {
    // 72 × 72 cells (10 368 triangles) of 1.3 px, rotated and offset by sub-pixel amounts,
    // in a window larger than the grid: every pixel hit at most once, every pixel whose
    // centre lies inside the grid's square (0.75 px from its border) exactly once.
    let (n, size) = (72usize, 1.3f32);
    // Odd configurations are not jittered; the first two put grid lines through pixel
    // centres (horizontal and vertical edges exercise the fill rule's tie cases).
    let configs = [
        (0.3f32, [64.37f32, 63.91f32]),
        (0.0, [64.0, 64.0]),
        (1.1, [63.5, 64.5]),
        (std::f32::consts::FRAC_PI_2, [64.0, 64.0]),
        (2.6, [64.123, 64.877]),
        (0.7, [64.25, 64.75]),
    ];
    for accuracy in Accuracy::ALL {
        for (k, &(angle, centre)) in configs.iter().enumerate() {
            // Jitter of ±0.15 px keeps every triangle of the 1.3 px cells counter-clockwise.
            let tris = rotated_grid(n, size, centre, angle, if k % 2 == 0 { 0.3 } else { 0.0 }, 77 + k as u32);
            let mut h = Harness::counting(128, 128, accuracy);
            h.window_coordinates();
            h.triangles(&tris, [1.0 / 255.0; 4]);
            let counts = h.counts();
            let half = n as f32 * size / 2.0;
            let (s, c) = angle.sin_cos();
            for y in 0..128 {
                for x in 0..128 {
                    let hits = counts[y * 128 + x];
                    assert!(hits <= 1, "{accuracy:?} config {k}: ({x},{y}) hit {hits} times");
                    let (dx, dy) = (x as f32 + 0.5 - centre[0], y as f32 + 0.5 - centre[1]);
                    let (u, v) = (c * dx + s * dy, -s * dx + c * dy);
                    if u.abs() < half - 0.75 && v.abs() < half - 0.75 {
                        assert_eq!(hits, 1, "{accuracy:?} config {k}: hole at ({x},{y})");
                    }
                }
            }
        }
    }
}

#[test]
fn ten_thousand_triangle_fans_are_watertight() {
    let n = 10_000;
    for accuracy in Accuracy::ALL {
        for (k, centre) in [[50.0f32, 50.0], [50.37, 49.61], [49.5, 50.5]].iter().enumerate() {
            let ring: Vec<[f32; 4]> = (0..n)
                .map(|i| {
                    let a = (i as f64 / n as f64 * std::f64::consts::TAU + k as f64 * 0.1) as f32;
                    [centre[0] + 45.0 * a.cos(), centre[1] + 45.0 * a.sin(), 0.0, 1.0]
                })
                .collect();
            let c = [centre[0], centre[1], 0.0, 1.0];
            let tris: Vec<_> = (0..n).map(|i| [c, ring[i], ring[(i + 1) % n]]).collect();
            let mut h = Harness::counting(100, 100, accuracy);
            h.window_coordinates();
            h.triangles(&tris, [1.0 / 255.0; 4]);
            let counts = h.counts();
            for y in 0..100 {
                for x in 0..100 {
                    let hits = counts[y * 100 + x];
                    let r = ((x as f32 + 0.5 - centre[0]).powi(2) + (y as f32 + 0.5 - centre[1]).powi(2)).sqrt();
                    assert!(hits <= 1, "{accuracy:?} fan {k}: ({x},{y}) hit {hits} times");
                    if r < 44.5 {
                        assert_eq!(hits, 1, "{accuracy:?} fan {k}: hole at ({x},{y})");
                    }
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Invariance.

#[test]
fn coverage_is_invariant_under_vertex_rotation_reversal_and_integer_translation() {
    let tris = rotated_grid(12, 3.7, [30.3, 29.8], 0.4, 1.5, 5);
    for accuracy in Accuracy::ALL {
        let render = |order: [usize; 3], shift: [f32; 2]| {
            let mut h = Harness::counting(80, 80, accuracy);
            h.window_coordinates();
            let moved: Vec<_> =
                tris.iter().map(|t| order.map(|i| [t[i][0] + shift[0], t[i][1] + shift[1], 0.0, 1.0])).collect();
            h.triangles(&moved, [1.0 / 255.0; 4]);
            h.counts()
        };
        let base = render([0, 1, 2], [0.0, 0.0]);
        for order in [[1, 2, 0], [2, 0, 1], [0, 2, 1], [2, 1, 0]] {
            assert_eq!(render(order, [0.0, 0.0]), base, "{accuracy:?} order {order:?}");
        }
        for shift in [[7.0f32, 3.0f32], [-5.0, 13.0], [17.0, -2.0]] {
            let moved = render([0, 1, 2], shift);
            for y in 0..80i32 {
                for x in 0..80i32 {
                    let (sx, sy) = (x - shift[0] as i32, y - shift[1] as i32);
                    let original =
                        if (0..80).contains(&sx) && (0..80).contains(&sy) { base[(sy * 80 + sx) as usize] } else { 0 };
                    // Pixels shifted in from outside the window were clipped in `base`.
                    if (0..80).contains(&sx) && (0..80).contains(&sy) {
                        assert_eq!(moved[(y * 80 + x) as usize], original, "{accuracy:?} shift {shift:?} ({x},{y})");
                    }
                }
            }
        }
    }
}

#[test]
fn multipass_with_equal_depth_hits_every_pixel_again() {
    // Perspective geometry drawn once with GL_LESS, then again with GL_EQUAL under different
    // state (color, smooth vs flat, blending, alpha test passing, fog): GL's invariance rules
    // give the same depths, so the second pass reaches every pixel the first one drew.
    let mut tris = rotated_grid(10, 0.17, [0.0, 0.0], 0.3, 0.05, 9);
    for (k, t) in tris.iter_mut().enumerate() {
        for (i, v) in t.iter_mut().enumerate() {
            let w = 1.0 + 0.8 * ((k + i) % 3) as f32 + v[0];
            *v = [v[0] * w, v[1] * w, (0.3 * v[1] - 0.2) * w, w];
        }
    }
    for accuracy in Accuracy::ALL {
        for depth in [DepthStencilFormat::Depth16, DEPTH24, DepthStencilFormat::Depth32 { stencil: false }] {
            let mut h = Harness::new(RGBA8, depth, 64, 64, accuracy);
            h.ctx.set_capability(GL_DEPTH_TEST, true);
            h.ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            let first: Vec<Vertex> = tris
                .iter()
                .enumerate()
                .flat_map(|(k, t)| t.map(|p| vertex(p, [(k % 7) as f32 / 7.0, 0.5, 1.0, 1.0])))
                .collect();
            h.draw(GL_TRIANGLES, &first);
            let drawn: Vec<bool> = h.rgba8().iter().map(|p| p[3] != 0).collect();
            assert!(drawn.iter().filter(|&&d| d).count() > 1000);
            h.ctx.depth_func(GL_EQUAL);
            h.ctx.shade_model(GL_FLAT);
            h.ctx.set_capability(GL_ALPHA_TEST, true);
            h.ctx.alpha_func(GL_GREATER, 0.0);
            h.ctx.set_capability(GL_FOG, true);
            h.ctx.set_capability(GL_BLEND, true);
            h.ctx.blend_func(None, GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
            h.ctx.clear_color([0.0; 4]);
            h.ctx.clear(GL_COLOR_BUFFER_BIT);
            let second: Vec<Vertex> = tris.iter().flat_map(|t| t.map(|p| vertex(p, [1.0, 0.0, 0.0, 1.0]))).collect();
            h.ctx.fog(GL_FOG_COLOR, [1.0, 0.0, 0.0, 1.0]);
            h.draw(GL_TRIANGLES, &second);
            let again = h.rgba8();
            for (i, d) in drawn.iter().enumerate() {
                assert_eq!(*d, again[i][3] == 255, "{accuracy:?} {depth:?}: pixel {i} missed by the GL_EQUAL pass");
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Depth extremes.

fn depth_max(format: DepthStencilFormat) -> u32 {
    match format {
        DepthStencilFormat::Depth16 => 0xffff,
        DepthStencilFormat::Packed24 { .. } => 0xff_ffff,
        _ => 0xffff_ffff,
    }
}

const DEPTH_FORMATS: [DepthStencilFormat; 3] =
    [DepthStencilFormat::Depth16, DEPTH24, DepthStencilFormat::Depth32 { stencil: false }];

#[test]
fn depth_ranges_and_the_near_and_far_planes_give_exact_extremes() {
    for accuracy in Accuracy::ALL {
        for format in DEPTH_FORMATS {
            let max = depth_max(format);
            // (range, z_ndc of the quad, expected stored depth)
            let cases = [
                ((0.0, 1.0), -1.0f32, 0u32),
                ((0.0, 1.0), 1.0, max),
                ((1.0, 1.0), -0.3, max),
                ((0.0, 0.0), 0.6, 0),
                ((1.0, 0.0), -1.0, max),
                ((1.0, 0.0), 1.0, 0),
            ];
            for ((near, far), z, expected) in cases {
                let mut h = Harness::new(RGBA8, format, 16, 16, accuracy);
                h.ctx.set_capability(GL_DEPTH_TEST, true);
                h.ctx.depth_func(GL_ALWAYS);
                h.ctx.clear_depth(0.5);
                h.ctx.clear(GL_DEPTH_BUFFER_BIT);
                h.ctx.depth_range(near, far);
                h.draw(GL_QUADS, &full_quad(z, [1.0; 4]));
                let depths = h.depths();
                assert!(
                    depths.iter().all(|&d| d == expected),
                    "{accuracy:?} {format:?} range ({near},{far}) z {z}: {:#x} expected {expected:#x}",
                    depths[0]
                );
            }
            // Reversed range over a slanted quad: depth falls from left to right.
            let mut h = Harness::new(RGBA8, format, 16, 4, accuracy);
            h.ctx.set_capability(GL_DEPTH_TEST, true);
            h.ctx.depth_func(GL_ALWAYS);
            h.ctx.depth_range(1.0, 0.0);
            let v: Vec<Vertex> = [[-1.0, -1.0, -1.0], [1.0, -1.0, 1.0], [1.0, 1.0, 1.0], [-1.0, 1.0, -1.0]]
                .iter()
                .map(|p| vertex([p[0], p[1], p[2], 1.0], [1.0; 4]))
                .collect();
            h.draw(GL_QUADS, &v);
            let depths = h.depths();
            for x in 0..16 {
                let expected = 1.0 - (x as f64 + 0.5) / 16.0;
                let got = depths[x] as f64 / max as f64;
                assert!((got - expected).abs() < 1e-4, "{accuracy:?} {format:?} x {x}: {got} vs {expected}");
                assert!(x == 0 || depths[x] < depths[x - 1]);
            }
        }
    }
}

#[test]
fn clear_depth_one_half_equals_geometry_at_one_half() {
    for accuracy in Accuracy::ALL {
        for format in DEPTH_FORMATS {
            let mut h2 = Harness::new(RGBA8, format, 16, 16, accuracy);
            h2.ctx.set_capability(GL_DEPTH_TEST, true);
            h2.ctx.depth_func(GL_EQUAL);
            h2.ctx.clear_depth(0.5);
            h2.ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            // z_ndc 0 → window z 0.5 everywhere, also with perspective (w ≠ 1).
            let v: Vec<Vertex> = [[-1.0, -1.0, 1.0], [1.0, -1.0, 2.0], [1.0, 1.0, 3.0], [-1.0, 1.0, 1.5]]
                .iter()
                .map(|p| vertex([p[0] * p[2], p[1] * p[2], 0.0, p[2]], [1.0; 4]))
                .collect();
            h2.draw(GL_QUADS, &v);
            assert!(h2.rgba8().iter().all(|p| *p == [255; 4]), "{accuracy:?} {format:?}");
        }
    }
}

#[test]
fn polygon_offset_at_large_slopes_stays_in_range_and_above_the_surface() {
    for accuracy in Accuracy::ALL {
        for format in DEPTH_FORMATS {
            let max = depth_max(format) as f64;
            // A quad almost edge-on: window z rises by 0.05 per pixel along x.
            let slanted = |h: &mut Harness| {
                let v: Vec<Vertex> = [[-1.0, -1.0, -0.9], [1.0, -1.0, 0.7], [1.0, 1.0, 0.7], [-1.0, 1.0, -0.9]]
                    .iter()
                    .map(|p| vertex([p[0], p[1], p[2], 1.0], [1.0; 4]))
                    .collect();
                h.draw(GL_QUADS, &v);
            };
            let render = |factor: f32, units: f32| {
                let mut h = Harness::new(RGBA8, format, 16, 8, accuracy);
                h.ctx.set_capability(GL_DEPTH_TEST, true);
                h.ctx.depth_func(GL_ALWAYS);
                if factor != 0.0 || units != 0.0 {
                    h.ctx.set_capability(GL_POLYGON_OFFSET_FILL, true);
                    h.ctx.polygon_offset(factor, units, 0.0);
                }
                slanted(&mut h);
                h.depths()
            };
            let plain = render(0.0, 0.0);
            let slope = 1.6 / 2.0 / 16.0; // window z per pixel
            for factor in [1.0f32, 4.0, 40.0, -40.0] {
                let offset = render(factor, 0.0);
                for i in 0..plain.len() {
                    let expected = (plain[i] as f64 / max + factor as f64 * slope).clamp(0.0, 1.0);
                    let got = offset[i] as f64 / max;
                    assert!(
                        (got - expected).abs() < 2e-3,
                        "{accuracy:?} {format:?} factor {factor} pixel {i}: {got} vs {expected}"
                    );
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Color extremes.

#[test]
fn blending_at_zero_and_one_is_exact_and_sums_saturate() {
    for accuracy in Accuracy::ALL {
        for format in [RGBA8, ColorFormat::Rgb565, ColorFormat::Unorm16 { alpha: true }, FLOAT] {
            let bits = format.channel_bits();
            let quantise = |v: f32, b: u32| {
                if format == FLOAT {
                    v
                } else {
                    let m = ((1u64 << b) - 1) as f32;
                    (v.clamp(0.0, 1.0) * m).round() / m
                }
            };
            let dst = [0.2f32, 0.4, 0.6, 0.8];
            // Multiples of 1/255 (and of 1/31, 1/63 nearly): no rounding ties.
            let src_rgb = [230.0f32 / 255.0, 25.0 / 255.0, 180.0 / 255.0];
            for (alpha, expected) in [(1.0f32, src_rgb), (0.0, [dst[0], dst[1], dst[2]])] {
                let mut h = Harness::new(format, DepthStencilFormat::None, 8, 8, accuracy);
                h.ctx.clear_color(dst);
                h.ctx.clear(GL_COLOR_BUFFER_BIT);
                h.ctx.set_capability(GL_BLEND, true);
                h.ctx.blend_func(None, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                h.draw(GL_QUADS, &full_quad(0.0, [src_rgb[0], src_rgb[1], src_rgb[2], alpha]));
                let colors = h.colors();
                for c in 0..3 {
                    let want = quantise(expected[c], bits[c]);
                    assert!(
                        colors.iter().all(|p| (p[c] - want).abs() < 1e-6),
                        "{accuracy:?} {format:?} alpha {alpha} channel {c}: {} vs {want}",
                        colors[0][c]
                    );
                }
            }
            // ONE + ONE: 0.8 + 0.8 saturates at 1 on fixed point; float keeps 1.6.
            let mut h = Harness::new(format, DepthStencilFormat::None, 8, 8, accuracy);
            h.ctx.clear_color([0.8; 4]);
            h.ctx.clear(GL_COLOR_BUFFER_BIT);
            h.ctx.set_capability(GL_BLEND, true);
            h.ctx.blend_func(None, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
            h.draw(GL_QUADS, &full_quad(0.0, [0.8; 4]));
            let want = if format == FLOAT { 2.0 * quantise(0.8, 32) } else { 1.0 };
            assert!(
                h.colors().iter().all(|p| (p[0] - want).abs() < 1e-6),
                "{accuracy:?} {format:?} saturating sum {} vs {want}",
                h.colors()[0][0]
            );
        }
    }
}

#[test]
fn src_alpha_saturate_uses_min_of_source_alpha_and_one_minus_destination_alpha() {
    for accuracy in Accuracy::ALL {
        for (src_a, dst_a) in [(0.5f32, 0.25f32), (0.9, 0.6), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
            let mut h = Harness::new(RGBA8, DepthStencilFormat::None, 4, 4, accuracy);
            h.ctx.clear_color([0.0, 0.0, 0.0, dst_a]);
            h.ctx.clear(GL_COLOR_BUFFER_BIT);
            h.ctx.set_capability(GL_BLEND, true);
            h.ctx.blend_func(None, GL_SRC_ALPHA_SATURATE, GL_ZERO, GL_SRC_ALPHA_SATURATE, GL_ZERO);
            let src = [0.8f32, 0.4, 1.0, src_a];
            h.draw(GL_QUADS, &full_quad(0.0, src));
            // The destination alpha is what the buffer holds (8 bits), the source exact.
            let da = (dst_a * 255.0).round() / 255.0;
            let sa = (src_a * 255.0).round() / 255.0;
            let f = sa.min(1.0 - da);
            let px = h.rgba8()[0];
            for c in 0..3 {
                let want = src[c] * f * 255.0;
                assert!(
                    (px[c] as f32 - want).abs() <= 0.5 + 1e-3,
                    "{accuracy:?} ({src_a},{dst_a}) channel {c}: {px:?} vs {want}"
                );
            }
            // The alpha factor of SRC_ALPHA_SATURATE is one.
            assert_eq!(px[3], (src_a * 255.0).round() as u8, "{accuracy:?} alpha");
        }
    }
}

#[test]
fn float_buffers_keep_values_outside_zero_one_unless_clamped() {
    for accuracy in Accuracy::ALL {
        for (clamp, clamped) in [(GL_FALSE as GLenum, false), (GL_TRUE as GLenum, true), (GL_FIXED_ONLY, false)] {
            let mut h = Harness::new(FLOAT, DepthStencilFormat::None, 4, 4, accuracy);
            h.ctx.clamp_color(GL_CLAMP_VERTEX_COLOR, GL_FALSE as GLenum);
            h.ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, clamp);
            let color = [2.5f32, -1.25, 0.5, 3.0];
            h.draw(GL_QUADS, &full_quad(0.0, color));
            let want = if clamped { color.map(|c| c.clamp(0.0, 1.0)) } else { color };
            assert!(h.colors().iter().all(|p| *p == want), "{accuracy:?} clamp {clamp:#x}: {:?}", h.colors()[0]);
            // Blending with unclamped values: ONE, ONE adds them.
            h.ctx.set_capability(GL_BLEND, true);
            h.ctx.blend_func(None, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
            h.draw(GL_QUADS, &full_quad(0.0, color));
            // Clamping applies to fragment colors, not to the blend result of a float buffer.
            let twice = want.map(|c| 2.0 * c);
            let got = h.colors()[5];
            assert_eq!(got, twice, "{accuracy:?} clamp {clamp:#x}: blended");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Stencil at its limits with partial write masks.

#[test]
fn stencil_wraps_and_saturates_at_0_and_255_under_partial_masks() {
    for accuracy in Accuracy::ALL {
        for (clear, op, mask, expected) in [
            (255u8, GL_INCR, 0xffu32, 255u8),
            (255, GL_INCR_WRAP, 0xff, 0),
            (0, GL_DECR, 0xff, 0),
            (0, GL_DECR_WRAP, 0xff, 255),
            // Masked: new = (op(old) & mask) | (old & !mask).
            (255, GL_INCR_WRAP, 0x0f, 0xf0),
            (0, GL_DECR_WRAP, 0xf0, 0xf0),
            (0x7f, GL_INCR, 0x80, 0xff),
            (0x80, GL_DECR, 0x7f, 0xff),
            (0xfe, GL_INCR_WRAP, 0x01, 0xff),
            (0x0f, GL_INVERT, 0x3c, 0x33),
            (0xa5, GL_ZERO, 0x0f, 0xa0),
            (0x00, GL_REPLACE, 0x81, 0x81),
        ] {
            let mut h = Harness::new(RGBA8, DEPTH24, 8, 8, accuracy);
            h.ctx.clear_stencil(clear as i32);
            h.ctx.clear(GL_STENCIL_BUFFER_BIT);
            h.ctx.set_capability(GL_STENCIL_TEST, true);
            h.ctx.stencil_func(GL_ALWAYS, 0xff, 0xff);
            h.ctx.stencil_op(GL_KEEP, GL_KEEP, op);
            h.ctx.stencil_mask(GL_FRONT_AND_BACK, mask);
            h.draw(GL_QUADS, &full_quad(0.0, [1.0; 4]));
            let s = h.stencils();
            assert!(
                s.iter().all(|&v| v == expected),
                "{accuracy:?} clear {clear:#x} op {op:#x} mask {mask:#x}: {:#x} expected {expected:#x}",
                s[0]
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// NaN and infinities.

#[test]
fn nan_and_infinity_in_inputs_leave_buffers_finite() {
    let nan = f32::NAN;
    let inf = f32::INFINITY;
    let bad_positions: [[[f32; 4]; 3]; 6] = [
        [[nan, 0.0, 0.0, 1.0], [0.5, -0.5, 0.0, 1.0], [0.0, 0.5, 0.0, 1.0]],
        [[-0.5, -0.5, 0.0, 1.0], [inf, -0.5, 0.0, 1.0], [0.0, 0.5, 0.0, 1.0]],
        [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.0, 1.0], [0.0, 0.5, 0.0, nan]],
        [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, -inf, 1.0], [0.0, 0.5, 0.0, inf]],
        [[-inf, -inf, 0.0, 1.0], [inf, -inf, 0.0, 1.0], [0.0, inf, 0.0, 1.0]],
        [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.0, 1.0], [0.0, 0.5, nan, 1.0]],
    ];
    let good = [[-0.5, -0.5, 0.0, 1.0], [0.5, -0.5, 0.3, 1.0], [0.0, 0.5, -0.2, 1.0]];
    let bad_colors = [[nan, 0.5, 0.5, 1.0], [inf, -inf, 0.5, nan], [0.5, 0.5, 0.5, inf]];
    for accuracy in Accuracy::ALL {
        let mut h = Harness::new(FLOAT, DEPTH24, 24, 24, accuracy);
        h.ctx.set_capability(GL_DEPTH_TEST, true);
        h.ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_TRUE as GLenum);
        h.ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let check = |h: &mut Harness, what: &str| {
            for c in h.colors() {
                assert!(c.iter().all(|v| v.is_finite() && (0.0..=1.0).contains(v)), "{accuracy:?} {what}: {c:?}");
            }
            assert!(h.depths().iter().all(|&d| d <= 0xff_ffff));
        };
        for (k, t) in bad_positions.iter().enumerate() {
            for mode in [GL_TRIANGLES, GL_LINE_LOOP, GL_POINTS] {
                let v: Vec<Vertex> = t.iter().map(|p| vertex(*p, [0.5; 4])).collect();
                h.draw(mode, &v);
                check(&mut h, &format!("position case {k} mode {mode:#x}"));
            }
        }
        for (k, color) in bad_colors.iter().enumerate() {
            let v: Vec<Vertex> = (0..3).map(|i| vertex(good[i], if i == 1 { *color } else { [0.2; 4] })).collect();
            for mode in [GL_TRIANGLES, GL_LINE_LOOP, GL_POINTS] {
                h.draw(mode, &v);
                check(&mut h, &format!("color case {k} mode {mode:#x}"));
            }
        }
        // Matrices, depth range, fog parameters.
        let v: Vec<Vertex> = (0..3).map(|i| vertex(good[i], [0.3; 4])).collect();
        for m in [[nan; 16], [inf; 16], {
            let mut m = [0.0f32; 16];
            m[0] = 1.0;
            m[5] = inf;
            m[10] = 1.0;
            m[15] = 1.0;
            m
        }] {
            h.ctx.load_matrix(&m);
            h.draw(GL_TRIANGLES, &v);
            check(&mut h, "matrix");
        }
        h.ctx.load_identity();
        h.ctx.depth_range(f64::NAN, f64::INFINITY);
        h.draw(GL_TRIANGLES, &v);
        check(&mut h, "depth range");
        h.ctx.depth_range(0.0, 1.0);
        h.ctx.set_capability(GL_FOG, true);
        for (pname, value) in [
            (GL_FOG_START, nan),
            (GL_FOG_END, inf),
            (GL_FOG_START, 0.5),
            (GL_FOG_END, 0.5),
            (GL_FOG_DENSITY, inf),
            (GL_FOG_DENSITY, nan),
        ] {
            for mode in [GL_LINEAR, GL_EXP, GL_EXP2] {
                h.ctx.fog(GL_FOG_MODE, [mode as f32, 0.0, 0.0, 0.0]);
                h.ctx.fog(pname, [value, 0.0, 0.0, 0.0]);
                h.ctx.fog(GL_FOG_COLOR, [nan, inf, -inf, 0.5]);
                h.draw(GL_TRIANGLES, &v);
                check(&mut h, &format!("fog {pname:#x} = {value} mode {mode:#x}"));
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The accuracy modes' stated bounds.

#[test]
fn accuracy_modes_stay_within_their_stated_bounds() {
    // A full-window quad whose left edge lies at w = 1 and right edge at w = r, red going
    // from 0 (left) to 1 (right), into a float buffer. Perspective-correct red at window
    // fraction s is s / (s + r(1 − s)); the fast mode interpolates linearly (red = s), whose
    // worst error over s is (√r − 1)/(√r + 1) (at s = 1/(1 + √r)). Conformant is within f32
    // rounding of exact.
    for r in [1.0f32, 2.0, 4.0, 16.0] {
        let render = |accuracy| {
            let mut h = Harness::new(FLOAT, DepthStencilFormat::None, 64, 4, accuracy);
            let v: Vec<Vertex> = [[-1.0f32, -1.0, 1.0], [1.0, -1.0, r], [1.0, 1.0, r], [-1.0, 1.0, 1.0]]
                .iter()
                .map(|p| {
                    let red = if p[0] > 0.0 { 1.0 } else { 0.0 };
                    vertex([p[0] * p[2], p[1] * p[2], 0.0, p[2]], [red, 0.5, 0.5, 1.0])
                })
                .collect();
            h.draw(GL_QUADS, &v);
            h.colors()
        };
        let exact = render(Accuracy::Exact);
        for (x, pixel) in exact.iter().enumerate().take(64) {
            let s = (x as f64 + 0.5) / 64.0;
            let analytic = s / (s + r as f64 * (1.0 - s));
            assert!((pixel[0] as f64 - analytic).abs() < 1e-6, "exact r {r} x {x}: {} vs {analytic}", pixel[0]);
        }
        let max_diff =
            |a: &[[f32; 4]]| a.iter().zip(&exact).map(|(p, q)| (p[0] - q[0]).abs() as f64).fold(0.0, f64::max);
        let conformant = max_diff(&render(Accuracy::Conformant));
        assert!(conformant < 1e-5, "conformant r {r}: {conformant}");
        let bound = (r.sqrt() as f64 - 1.0) / (r.sqrt() as f64 + 1.0);
        let fast = max_diff(&render(Accuracy::Fast));
        assert!(fast <= bound + 1e-5, "fast r {r}: {fast} above {bound}");
        // The bound is tight: the fast mode is affine, not secretly perspective-correct.
        assert!(fast >= 0.9 * bound, "fast r {r}: {fast} far below {bound}");
    }
}
