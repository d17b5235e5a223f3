//! Exact coverage tests of the whole draw path (transform, clip, setup, binning, bands):
//! meshes of many triangles sharing edges must cover every pixel exactly once, at many
//! sub-pixel offsets, across tile boundaries and after clipping.
use super::Context;
use crate::framebuffer::surface::ColorPixels;
use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, FramebufferConfig};
use crate::gl::enums::*;
use crate::setup::triangle::TriangleSetup;
use crate::vertex::Vertex;

fn vertex(x: f32, y: f32, color: [f32; 4]) -> Vertex {
    Vertex {
        position: [x, y, 0.0, 1.0],
        color,
        secondary_color: [0.0; 4],
        normal: [0.0, 0.0, 1.0],
        tex_coords: [[0.0; 4]; 4],
        fog_coord: 0.0,
        edge_flag: true,
        generic: crate::vertex::generic::CURRENT,
    }
}

/// A color that encodes `id` exactly in 8-bit channels (never black).
fn id_color(id: usize) -> [f32; 4] {
    let id = id + 1;
    [(id & 255) as f32 / 255.0, ((id >> 8) & 255) as f32 / 255.0, ((id >> 16) & 255) as f32 / 255.0, 1.0]
}

/// Renders flat-colored triangles (window coordinates) and checks every pixel against the
/// unique triangle whose exact coverage test claims it.
fn check_mesh(width: usize, height: usize, triangles: &[[[f32; 2]; 3]]) {
    let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0);
    let (mut ctx, drawable) = Context::with_test_drawable(visual, width, height);
    ctx.matrix_mode(GL_PROJECTION);
    ctx.ortho(0.0, width as f64, 0.0, height as f64, -1.0, 1.0);
    ctx.state.lighting.shade_model = GL_FLAT;
    let vertices: Vec<Vertex> =
        triangles.iter().enumerate().flat_map(|(id, t)| t.map(|p| vertex(p[0], p[1], id_color(id)))).collect();
    ctx.draw_vertices(GL_TRIANGLES, &vertices);
    ctx.flush_rendering();
    let setups: Vec<Option<TriangleSetup>> = triangles.iter().map(|t| TriangleSetup::new(*t)).collect();
    let guard = drawable.lock().unwrap();
    let ColorPixels::Unorm8(px) = guard.framebuffer.color(ColorSlot::FrontLeft).unwrap().pixels() else {
        unreachable!()
    };
    for y in 0..height as i32 {
        for x in 0..width as i32 {
            let owners: Vec<usize> =
                (0..triangles.len()).filter(|&i| setups[i].as_ref().is_some_and(|s| s.covers(x, y))).collect();
            assert!(owners.len() <= 1, "pixel ({x},{y}) covered by {owners:?}");
            let expected = owners.first().map_or([0, 0, 0, 0], |&id| id_color(id).map(|c| (c * 255.0).round() as u8));
            assert_eq!(px[y as usize * width + x as usize], expected, "pixel ({x},{y})");
        }
    }
}

/// A grid of `n` × `n` cells, each split into two triangles, jittered and offset.
fn grid(n: usize, size: f32, offset: [f32; 2], jitter: f32) -> Vec<[[f32; 2]; 3]> {
    let mut seed = 0x2545_f491u32;
    let mut points = vec![[0.0f32; 2]; (n + 1) * (n + 1)];
    for j in 0..=n {
        for i in 0..=n {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            let r = |s: u32| (s % 1000) as f32 / 1000.0 - 0.5;
            let inner = i > 0 && i < n && j > 0 && j < n;
            let (jx, jy) = if inner { (r(seed) * jitter, r(seed >> 10) * jitter) } else { (0.0, 0.0) };
            points[j * (n + 1) + i] = [offset[0] + i as f32 * size + jx, offset[1] + j as f32 * size + jy];
        }
    }
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let p = |a: usize, b: usize| points[(j + b) * (n + 1) + i + a];
            tris.push([p(0, 0), p(1, 0), p(1, 1)]);
            tris.push([p(0, 0), p(1, 1), p(0, 1)]);
        }
    }
    tris
}

#[test]
fn jittered_grids_cover_every_pixel_exactly_once() {
    for (k, offset) in [[0.0, 0.0], [0.25, 0.75], [0.5, 0.5], [0.123, 0.877], [-3.3, -2.9]].iter().enumerate() {
        // 30 × 30 cells of 4.4 px (1800 triangles) over 140 × 140 pixels: crosses tile
        // boundaries at 64 and 128, and (for the last offset) the window edge.
        let tris = grid(30, 4.4, *offset, if k % 2 == 0 { 2.0 } else { 0.0 });
        check_mesh(140, 140, &tris);
    }
}

#[test]
fn fans_with_many_thin_triangles_cover_their_disc_exactly_once() {
    let centre = [70.3, 66.7];
    let n = 500;
    let ring: Vec<[f32; 2]> = (0..n)
        .map(|i| {
            let a = i as f32 / n as f32 * std::f32::consts::TAU;
            [centre[0] + 60.0 * a.cos(), centre[1] + 60.0 * a.sin()]
        })
        .collect();
    let tris: Vec<_> = (0..n).map(|i| [centre, ring[i], ring[(i + 1) % n]]).collect();
    check_mesh(140, 140, &tris);
}

#[test]
fn only_enabled_stages_ask_for_varyings() {
    let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0);
    let (mut ctx, _) = Context::with_test_drawable(visual, 4, 4);
    assert!(ctx.varyings_needed().is_empty());
    ctx.set_capability(GL_FOG, true);
    ctx.set_capability(GL_TEXTURE_2D, true);
    assert_eq!(ctx.varyings_needed().len(), 1 + 4);
    ctx.set_capability(GL_COLOR_SUM, true);
    assert_eq!(ctx.varyings_needed().len(), 3 + 1 + 4);
}
