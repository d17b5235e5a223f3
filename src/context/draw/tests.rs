//! Tests of the draw path through the context: fragment state per draw buffer, coverage,
//! depth, clipping, thread-count independence, and lines, points and polygon modes replayed
//! against Mesa's output (see [`super::replay`]).
use super::replay::{context, pixels, replay, vertex};
use crate::context::Context;
use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, Drawable, FramebufferConfig};
use crate::gl::enums::*;
use crate::gl::CompareFunc;
use crate::setup::{Primitive as RasterPrimitive, Scene};
use crate::vertex::Vertex;
use std::sync::{Arc, Mutex};

const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];

fn slot_pixel(ctx: &mut Context, d: &Arc<Mutex<Drawable>>, slot: ColorSlot, x: i32, y: i32) -> [u8; 4] {
    ctx.flush_rendering();
    let mut row = Vec::new();
    d.lock().unwrap().framebuffer.color(slot).unwrap().read_row_f32(y, x, x + 1, &mut row);
    row[0].map(|c| (c * 255.0).round() as u8)
}

fn square(ctx: &mut Context, x0: f32, y0: f32, x1: f32, y1: f32, color: [f32; 4]) {
    let v = |x, y| vertex(x, y, 0.0, color);
    ctx.draw_vertices(GL_QUADS, &[v(x0, y0), v(x1, y0), v(x1, y1), v(x0, y1)]);
}

#[test]
fn each_draw_buffer_blends_with_its_own_state() {
    let visual = FramebufferConfig {
        aux_buffers: 2,
        ..FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0)
    };
    let (mut ctx, d) = Context::with_test_drawable(visual, 4, 4);
    ctx.matrix_mode(GL_PROJECTION);
    ctx.ortho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
    ctx.draw_buffers(&[GL_FRONT_LEFT, GL_AUX0, GL_AUX0 + 1]);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
    ctx.clear_color([0.5; 4]);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    // Buffer 0 adds, buffer 1 modulates (glBlendFunci), buffer 2 does not blend.
    ctx.set_capability_indexed(GL_BLEND, 0, true);
    ctx.set_capability_indexed(GL_BLEND, 1, true);
    ctx.blend_func(Some(0), GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    ctx.blend_func(Some(1), GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_SRC_COLOR);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
    let mut scene = Scene::new(4, 4);
    let state = ctx.draw_state(&mut scene, 4, 4, ColorFormat::Unorm8 { alpha: true }, 0, 0);
    assert!(state.fragment.blend[0].is_some() && state.fragment.blend[1].is_some());
    assert_eq!(state.fragment.blend[2], None, "a buffer with blending off has no blend stage");
    square(&mut ctx, 0.0, 0.0, 4.0, 4.0, [0.25, 0.5, 0.75, 0.5]);
    // The source is (64, 128, 191, 128) in 8 bits, the destination 128.
    assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::FrontLeft, 1, 1), [192, 255, 255, 255]);
    assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(0), 1, 1), [32, 64, 96, 64]);
    assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(1), 1, 1), [64, 128, 191, 128]);
    // The logic op replaces blending on every buffer.
    ctx.set_capability(GL_COLOR_LOGIC_OP, true);
    ctx.logic_op(GL_XOR);
    square(&mut ctx, 0.0, 0.0, 4.0, 4.0, [1.0, 0.0, 1.0, 0.0]);
    assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::FrontLeft, 1, 1), [63, 255, 0, 255]);
    assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(0), 1, 1), [223, 64, 159, 64]);
    assert_eq!(slot_pixel(&mut ctx, &d, ColorSlot::Aux(1), 1, 1), [191, 128, 64, 128]);
}

#[test]
fn disabled_stages_are_absent_from_the_compiled_state() {
    let (mut ctx, _d) = context(4, 4);
    let mut scene = Scene::new(4, 4);
    let compile = |ctx: &Context, scene: &mut Scene, format, stencil_bits| {
        ctx.draw_state(scene, 4, 4, format, 24, stencil_bits).fragment
    };
    let rgba8 = ColorFormat::Unorm8 { alpha: true };
    let f = compile(&ctx, &mut scene, rgba8, 8);
    assert_eq!((f.alpha, f.stencil, f.logic_op, f.dither), (None, None, None, false));
    assert!(f.blend.iter().all(|b| b.is_none()));
    // GL_DITHER is on by default but only RGB565 targets dither.
    assert!(compile(&ctx, &mut scene, ColorFormat::Rgb565, 8).dither);
    ctx.set_capability(GL_STENCIL_TEST, true);
    ctx.set_capability(GL_ALPHA_TEST, true);
    ctx.set_capability(GL_BLEND, true);
    ctx.set_capability(GL_COLOR_LOGIC_OP, true);
    let f = compile(&ctx, &mut scene, rgba8, 8);
    assert!(f.alpha.is_some() && f.stencil.is_some() && f.logic_op.is_some());
    assert!(f.blend.iter().all(|b| b.is_none()), "the logic op replaces blending");
    assert_eq!(compile(&ctx, &mut scene, rgba8, 0).stencil, None, "no stencil bits, no stencil test");
    // Float buffers blend: the logic op does not apply to them.
    let f = compile(&ctx, &mut scene, ColorFormat::Float32 { alpha: true }, 8);
    assert!(f.logic_op.is_none() && f.blend.iter().all(|b| b.is_some()));
}

#[test]
fn a_triangle_covers_exactly_the_centres_inside_it() {
    let (mut ctx, d) = context(8, 8);
    ctx.draw_vertices(
        GL_TRIANGLES,
        &[vertex(0.5, 0.5, 0.0, RED), vertex(4.5, 0.5, 0.0, RED), vertex(4.5, 4.5, 0.0, RED)],
    );
    let px = pixels(&mut ctx, &d);
    let lit: Vec<(usize, usize)> = (0..64).filter(|i| px[*i][0] == 255).map(|i| (i % 8, i / 8)).collect();
    // Mesa 22 llvmpipe: rows y0: x0..3, y1: x1..3, y2: x2..3, y3: x3.
    assert_eq!(lit, vec![(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2), (3, 2), (3, 3)]);
}

#[test]
fn depth_test_keeps_the_nearer_surface_in_any_order() {
    for order in [0, 1] {
        let (mut ctx, d) = context(16, 16);
        ctx.state.depth.test = true;
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        let quad = |z: f32, c: [f32; 4]| {
            [vertex(0.0, 0.0, z, c), vertex(16.0, 0.0, z, c), vertex(16.0, 16.0, z, c), vertex(0.0, 16.0, z, c)]
        };
        // glOrtho maps z = 0.5 nearer than z = -0.5 (eye z is negated).
        let (near, far) = (quad(0.5, GREEN), quad(-0.5, RED));
        let draws = if order == 0 { [near, far] } else { [far, near] };
        for q in &draws {
            ctx.draw_vertices(GL_QUADS, q);
        }
        assert!(pixels(&mut ctx, &d).iter().all(|p| *p == [0, 255, 0, 255]), "order {order}");
    }
}

#[test]
fn equal_depth_passes_on_redrawn_geometry() {
    let (mut ctx, d) = context(32, 32);
    ctx.state.depth.test = true;
    ctx.clear(GL_DEPTH_BUFFER_BIT);
    let tri = |c| [vertex(1.3, 2.1, -0.31, c), vertex(30.2, 5.7, 0.77, c), vertex(11.9, 29.4, 0.12, c)];
    ctx.draw_vertices(GL_TRIANGLES, &tri(RED));
    ctx.state.depth.func = CompareFunc::Equal;
    ctx.draw_vertices(GL_TRIANGLES, &tri(GREEN));
    let px = pixels(&mut ctx, &d);
    assert!(px.iter().any(|p| p[1] == 255));
    assert!(px.iter().all(|p| p[0] == 0), "every redrawn pixel passes GL_EQUAL");
}

#[test]
fn geometry_behind_the_eye_is_clipped_not_wrapped() {
    let (mut ctx, d) = context(16, 16);
    ctx.matrix_mode(GL_PROJECTION);
    ctx.load_identity();
    ctx.frustum(-0.5, 0.5, -0.5, 0.5, 0.5, 10.0);
    // A triangle from in front of the camera to behind it (eye z > 0).
    ctx.draw_vertices(
        GL_TRIANGLES,
        &[vertex(-1.0, -1.0, -2.0, RED), vertex(1.0, -1.0, -2.0, RED), vertex(0.0, -1.0, 3.0, RED)],
    );
    let px = pixels(&mut ctx, &d);
    let lit = px.iter().filter(|p| p[0] == 255).count();
    assert!(lit > 0 && lit < 16 * 16 / 2, "{lit} pixels");
    // Only the lower half of the view can see a floor below the eye.
    assert!(px[8 * 16..].iter().all(|p| p[0] == 0));
}

#[test]
fn results_are_identical_for_any_thread_count() {
    let render = |threads: usize| {
        let (mut ctx, d) = context(200, 150);
        ctx.state.depth.test = true;
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        let mut seed = 12345u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            (seed >> 8) as f32 / (1 << 24) as f32
        };
        let mut vertices = Vec::new();
        for _ in 0..300 {
            let c = [rnd(), rnd(), rnd(), 1.0];
            vertices.push(vertex(rnd() * 220.0 - 10.0, rnd() * 170.0 - 10.0, rnd() * 2.0 - 1.0, c));
        }
        ctx.draw_vertices(GL_TRIANGLES, &vertices);
        let scene = ctx.scene.take().unwrap();
        scene.execute_on(&mut d.lock().unwrap().framebuffer, threads);
        pixels(&mut ctx, &d)
    };
    let one = render(1);
    for threads in [2, 4, 7] {
        assert!(one == render(threads), "{threads} threads differ");
    }
}

#[test]
fn a_draw_split_between_threads_draws_the_bytes_of_small_draws() {
    // 2400 overlapping triangles in one draw (split between two threads when there are two)
    // and in draws of one triangle each (never split): the same bytes, with the depth test
    // and without it (where large triangles drop the tiles they cover).
    let mut seed = 777u32;
    let mut rnd = || {
        seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
        (seed >> 8) as f32 / (1 << 24) as f32
    };
    let mut vertices = Vec::new();
    for i in 0..2400 {
        let size = if i % 97 == 0 { 400.0 } else { 12.0 };
        let (x, y) = (rnd() * 220.0 - 10.0, rnd() * 170.0 - 10.0);
        for _ in 0..3 {
            let c = [rnd(), rnd(), rnd(), 1.0];
            vertices.push(vertex(x + (rnd() - 0.5) * size, y + (rnd() - 0.5) * size, rnd() * 2.0 - 1.0, c));
        }
    }
    let geometry = |ctx: &mut Context| ctx.geometry(24, 150);
    for depth in [false, true] {
        let render = |whole: bool| {
            let (mut ctx, d) = context(200, 150);
            ctx.state.depth.test = depth;
            ctx.clear(GL_DEPTH_BUFFER_BIT);
            if whole {
                assert_eq!(
                    super::split_point(GL_TRIANGLES, &geometry(&mut ctx), vertices.len(), super::SPLIT_MIN_THREADS),
                    Some((3150, 3150))
                );
                ctx.draw_vertices(GL_TRIANGLES, &vertices);
            } else {
                vertices.chunks(3).for_each(|t| ctx.draw_vertices(GL_TRIANGLES, t));
            }
            pixels(&mut ctx, &d)
        };
        let split = render(true);
        assert!(split.iter().any(|p| p[0] != 0));
        assert!(split == render(false), "depth test {depth}: the split draw differs");
    }
}

#[test]
fn a_strip_split_between_threads_draws_the_bytes_of_short_strips() {
    // Triangle and quad strips zigzagging over each other (each overlapping the ones before,
    // depth-tested and flat-shaded or not, so order, winding parity and provoking vertices
    // show), drawn whole (split in half between two threads when there are two) and as
    // strips of four vertices starting at every even vertex (never split): the same bytes.
    let mut seed = 99u32;
    let mut rnd = || {
        seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
        (seed >> 8) as f32 / (1 << 24) as f32
    };
    let mut vertices = Vec::new();
    for i in 0..1538 {
        let x = (i / 2) as f32 * 1.3 % 190.0 + rnd() * 3.0;
        let y = if i % 2 == 0 { 20.0 + rnd() * 40.0 } else { 80.0 + rnd() * 60.0 };
        vertices.push(vertex(x, y, rnd() * 2.0 - 1.0, [rnd(), rnd(), rnd(), 1.0]));
    }
    let geometry = |ctx: &mut Context| ctx.geometry(24, 150);
    for mode in [GL_TRIANGLE_STRIP, GL_QUAD_STRIP] {
        for (depth, flat) in [(false, false), (true, false), (true, true)] {
            let render = |whole: bool| {
                let (mut ctx, d) = context(200, 150);
                ctx.state.depth.test = depth;
                if flat {
                    ctx.shade_model(GL_FLAT);
                }
                ctx.clear(GL_DEPTH_BUFFER_BIT);
                if whole {
                    assert_eq!(
                        super::split_point(mode, &geometry(&mut ctx), vertices.len(), super::SPLIT_MIN_THREADS),
                        Some((770, 768))
                    );
                    assert_eq!(super::split_point(mode, &geometry(&mut ctx), vertices.len(), 2), None);
                    ctx.draw_vertices(mode, &vertices);
                } else {
                    for start in (0..vertices.len() - 2).step_by(2) {
                        ctx.draw_vertices(mode, &vertices[start..(start + 4).min(vertices.len())]);
                    }
                }
                pixels(&mut ctx, &d)
            };
            let split = render(true);
            assert!(split.iter().any(|p| p[0] != 0));
            assert!(split == render(false), "mode {mode:#x}, depth test {depth}, flat {flat}: the split strip differs");
        }
    }
}

/// Small overlapping triangles drawn in long draws (a tile's consecutive triangles render
/// as runs through one batch of blocks: `setup::jobs::triangle::TriangleJob::render_run`)
/// and one triangle per scene (never a run): the same bytes and occlusion counts. The
/// triangles overlap in the same blocks, so the order of a run's fragments shows through
/// blending and the depth test; they alternate in winding, and the two faces' stencil tests
/// differ, so a triangle rendered with its neighbour's facing shows; the draws alternate
/// between two blend functions and two colour masks, so runs must end at a state change;
/// a run reaches past a batch's 32 blocks; some triangles are flat, some larger than a
/// hierarchical z region (never in a run with the depth test).
#[test]
fn runs_of_small_triangles_draw_the_bytes_of_one_triangle_at_a_time() {
    let mut seed = 4242u32;
    let mut rnd = || {
        seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
        (seed >> 8) as f32 / (1 << 24) as f32
    };
    let mut triangles = Vec::new();
    for i in 0..900 {
        let size = if i % 61 == 0 { 40.0 } else { 7.0 };
        let (x, y) = (rnd() * 150.0 - 5.0, rnd() * 80.0 - 5.0);
        let flat = i % 7 == 0;
        let c = [rnd(), rnd(), rnd(), rnd()];
        let mut t: Vec<_> = (0..3)
            .map(|_| {
                let c = if flat { c } else { [rnd(), rnd(), rnd(), rnd()] };
                vertex(x + rnd() * size, y + rnd() * size, rnd() * 2.0 - 1.0, c)
            })
            .collect();
        // Counter-clockwise and clockwise in turn, whatever the random points gave.
        let [p, q, r] = [&t[0].position, &t[1].position, &t[2].position];
        let ccw = (q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]) > 0.0;
        if ccw != (i % 2 == 0) {
            t.swap(1, 2);
        }
        triangles.push(t);
    }
    for (depth, stencil) in [(false, false), (true, false), (true, true), (false, true)] {
        let render = |one_at_a_time: bool| {
            let (mut ctx, d) = context(160, 90);
            ctx.state.depth.test = depth;
            ctx.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            if stencil {
                ctx.set_capability(GL_STENCIL_TEST, true);
                ctx.stencil_func_separate(GL_FRONT, GL_GEQUAL, 1, !0);
                ctx.stencil_func_separate(GL_BACK, GL_NOTEQUAL, 2, !0);
                ctx.stencil_op_separate(GL_FRONT, GL_KEEP, GL_INCR, GL_INCR);
                ctx.stencil_op_separate(GL_BACK, GL_INCR, GL_KEEP, GL_DECR);
            }
            let query = ctx.gen_queries(1).unwrap()[0];
            ctx.begin_query(GL_SAMPLES_PASSED, query);
            for (k, draw) in triangles.chunks(150).enumerate() {
                ctx.set_capability(GL_BLEND, k % 3 != 2);
                let (src, dst) = if k % 2 == 0 { (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) } else { (GL_ONE, GL_ONE) };
                ctx.blend_func(None, src, dst, src, dst);
                ctx.color_mask(None, [true, k % 4 != 3, true, true]);
                for t in draw {
                    if one_at_a_time {
                        ctx.draw_vertices(GL_TRIANGLES, t);
                        ctx.flush_rendering();
                    }
                }
                if !one_at_a_time {
                    ctx.draw_vertices(GL_TRIANGLES, &draw.concat());
                }
            }
            ctx.end_query(GL_SAMPLES_PASSED);
            assert_eq!(ctx.take_error(), GL_NO_ERROR);
            let passed = ctx.get_query_object(query, GL_QUERY_RESULT).unwrap();
            (pixels(&mut ctx, &d), passed)
        };
        let (runs, passed) = render(false);
        let (alone, alone_passed) = render(true);
        assert!(runs.iter().any(|p| p[0] != 0) && passed > 0);
        assert!(runs == alone, "depth {depth}, stencil {stencil}: the runs' pixels differ");
        assert_eq!(passed, alone_passed, "depth {depth}, stencil {stencil}: samples passed");
    }
}

/// Horizontal, vertical, diagonal, shallow and steep lines; pixel-centre, integer and
/// fractional endpoints; both directions of one steep segment (its centre tie goes
/// differently each way).
#[test]
fn width_1_lines_follow_the_diamond_exit_rule_as_llvmpipe() {
    let script = "
        size 16 16; color 1 1 1 1; clear 0 0 0 0; begin lines; v 1.5 1.5; v 6.5 1.5; v 6.5 3.5
        v 1.5 3.5; v 8 1; v 14 1; v 1.5 5.5; v 1.5 10.5; v 3.5 10.5; v 3.5 5.5; end; lit axis_aligned
        clear 0 0 0 0; begin lines; v 1.5 1.5; v 6.5 6.5; v 12.5 1.5; v 7.5 6.5; v 1.25 8.75
        v 14.75 11.25; v 14.75 13.25; v 1.25 15.75; end; lit diagonal_and_shallow; clear 0 0 0 0
        begin lines; v 2.2 0.7; v 4.9 14.3; v 13.8 14.6; v 10.1 1.2; v 7.5 2.5; v 8.5 4.5; end
        lit steep_fractional; clear 0 0 0 0; begin lines; v 10.5 2.5; v 9.5 12.5; v 9.5 12.5; v 10.5 2.5
        end; lit both_directions_of_a_tie";
    let mesa = concat!(
        "axis_aligned: 8,0 9,0 10,0 11,0 12,0 13,0 1,1 2,1 3,1 4,1 5,1 2,3 3,3 4,3 5,3 6,3 1,5 \
         1,6 3,6 1,7 3,7 1,8 3,8 1,9 3,9 3,10\n",
        "diagonal_and_shallow: 1,1 12,1 2,2 11,2 3,3 10,3 4,4 9,4 5,5 8,5 1,8 2,8 3,9 4,9 5,9 6,9 \
         7,9 8,10 9,10 10,10 11,10 12,10 13,11 14,11 11,13 12,13 13,13 14,13 5,14 6,14 7,14 8,14 \
         9,14 10,14 1,15 2,15 3,15 4,15\n",
        "steep_fractional: 2,1 10,1 2,2 7,2 10,2 2,3 7,3 10,3 2,4 11,4 3,5 11,5 3,6 11,6 3,7 11,7 \
         3,8 12,8 3,9 12,9 4,10 12,10 4,11 12,11 4,12 13,12 4,13 13,13 13,14\n",
        "both_directions_of_a_tie: 10,2 10,3 10,4 10,5 10,6 9,7 10,7 9,8 9,9 9,10 9,11 9,12\n",
    );
    assert_eq!(replay(script), mesa);
}

/// Each segment draws its start pixel and not its end pixel.
#[test]
fn strips_and_loops_draw_shared_vertices_once() {
    let script = "
        size 16 16; color 1 1 1 1; clear 0 0 0 0; begin line_strip; v 1.5 1.5; v 8.5 1.5; v 8.5 8.5
        v 1.7 14.2; end; lit strip; clear 0 0 0 0; begin line_loop; v 2.5 2.5; v 12.5 3.5; v 7.5 12.5
        end; lit loop";
    let mesa = concat!(
        "strip: 1,1 2,1 3,1 4,1 5,1 6,1 7,1 8,1 8,2 8,3 8,4 8,5 8,6 8,7 8,8 7,9 6,10 4,11 5,11 \
         3,12 2,13\n",
        "loop: 2,2 3,2 4,2 5,2 6,2 7,2 2,3 8,3 9,3 10,3 11,3 12,3 3,4 11,4 3,5 11,5 4,6 10,6 4,7 \
         10,7 5,8 9,8 5,9 9,9 6,10 8,10 6,11 8,11 7,12\n",
    );
    assert_eq!(replay(script), mesa);
}

/// x-major lines get round(width) rows per column, y-major lines round(width) columns per
/// row; 2.5 rounds up.
#[test]
fn wide_lines_are_widened_across_their_minor_axis() {
    let script = "
        size 16 16; color 1 1 1 1; clear 0 0 0 0; linewidth 2; begin lines; v 1.5 2.5; v 12.5 4.5
        v 13.5 6.5; v 11.5 14.5; end; lit width2; clear 0 0 0 0; linewidth 2.5; begin lines; v 1.25 3.3
        v 14.75 8.6; end; lit width2_5_is_3; clear 0 0 0 0; linewidth 4; begin lines; v 7.4 1.2
        v 8.6 13.9; end; lit width4_ymajor";
    let mesa = concat!(
        "width2: 1,2 2,2 3,2 4,2 5,2 6,2 1,3 2,3 3,3 4,3 5,3 6,3 7,3 8,3 9,3 10,3 11,3 7,4 8,4 \
         9,4 10,4 11,4 12,6 13,6 12,7 13,7 12,8 13,8 12,9 13,9 11,10 12,10 11,11 12,11 11,12 \
         12,12 11,13 12,13\n",
        "width2_5_is_3: 1,2 2,2 1,3 2,3 3,3 4,3 5,3 1,4 2,4 3,4 4,4 5,4 6,4 7,4 3,5 4,5 5,5 6,5 \
         7,5 8,5 9,5 10,5 6,6 7,6 8,6 9,6 10,6 11,6 12,6 8,7 9,7 10,7 11,7 12,7 13,7 11,8 12,8 \
         13,8 13,9\n",
        "width4_ymajor: 5,1 6,1 7,1 8,1 6,2 7,2 8,2 9,2 6,3 7,3 8,3 9,3 6,4 7,4 8,4 9,4 6,5 7,5 \
         8,5 9,5 6,6 7,6 8,6 9,6 6,7 7,7 8,7 9,7 6,8 7,8 8,8 9,8 6,9 7,9 8,9 9,9 6,10 7,10 8,10 \
         9,10 6,11 7,11 8,11 9,11 6,12 7,12 8,12 9,12 7,13 8,13 9,13 10,13\n",
    );
    assert_eq!(replay(script), mesa);
}

/// GL_LINES restarts the pattern for every segment; strips and loops continue it, by whole
/// pixel steps per segment (Mesa 22); the factor repeats each bit.
#[test]
fn line_stipple_restarts_per_segment_of_gl_lines_only() {
    let script = "
        size 24 8; color 1 1 1 1; enable line_stipple; stipple 1 0f0f; clear 0 0 0 0; begin lines
        v 0.5 1.5; v 10.5 1.5; v 0.5 3.5; v 20.5 3.5; end; lit lines_restart; clear 0 0 0 0
        begin line_strip; v 0.5 1.5; v 6.25 1.5; v 20.5 1.5; end; lit strip_continues_by_whole_steps
        clear 0 0 0 0; stipple 3 00ff; begin line_loop; v 1.5 1.5; v 20.5 1.5; v 20.5 6.5; v 1.5 6.5
        end; lit loop_factor3";
    let mesa = concat!(
        "lines_restart: 0,1 1,1 2,1 3,1 8,1 9,1 0,3 1,3 2,3 3,3 8,3 9,3 10,3 11,3 16,3 17,3 18,3 \
         19,3\n",
        "strip_continues_by_whole_steps: 0,1 1,1 2,1 3,1 8,1 9,1 10,1 11,1 16,1 17,1 18,1 19,1\n",
        "loop_factor3: 1,1 2,1 3,1 4,1 5,1 6,1 7,1 8,1 9,1 10,1 11,1 12,1 13,1 14,1 15,1 16,1 \
         17,1 18,1 19,1 20,1 20,2 20,3 20,4 20,5\n",
    );
    assert_eq!(replay(script), mesa);
}

/// Odd sizes centre on the pixel containing the point, even sizes on the nearest corner;
/// sizes round at halves down and clamp to GL_POINT_SIZE_MIN/MAX; a point whose centre is
/// outside the view volume is discarded, a wide one inside it draws past the viewport.
#[test]
fn points_cover_squares_of_their_rounded_size() {
    let script = "
        size 24 24; color 1 1 1 1; clear 0 0 0 0; pointsize 1; begin points; v 2.5 2.5; v 4.0 2.0
        v 6.99 2.01; end; pointsize 2; begin points; v 2.5 6.5; v 6.2 6.7; end; pointsize 3
        begin points; v 12.5 6.5; v 17.0 6.0; end; pointsize 2.5; begin points; v 4.5 12.5; end
        pointsize 1.5; begin points; v 10.5 12.5; end; lit sizes; clear 0 0 0 0; pointsize 10
        pointminmax 2 4; begin points; v 5.5 5.5; end; pointsize 1; begin points; v 15.5 15.5; end
        pointminmax 0 255; lit clamped_to_min_max; clear 0 0 0 0; viewport 4 4 16 16
        ortho 0 16 0 16 -1 1; pointsize 5; begin points; v 0.5 0.5; v -0.5 8.5; v 15.9 15.9; end
        lit centre_in_view_decides";
    let mesa = concat!(
        "sizes: 2,2 4,2 6,2 11,5 12,5 13,5 16,5 17,5 18,5 2,6 3,6 5,6 6,6 11,6 12,6 13,6 16,6 \
         17,6 18,6 2,7 3,7 5,7 6,7 11,7 12,7 13,7 16,7 17,7 18,7 4,12 5,12 10,12 4,13 5,13\n",
        "clamped_to_min_max: 4,4 5,4 6,4 7,4 4,5 5,5 6,5 7,5 4,6 5,6 6,6 7,6 4,7 5,7 6,7 7,7 \
         15,15 16,15 15,16 16,16\n",
        "centre_in_view_decides: 2,2 3,2 4,2 5,2 6,2 2,3 3,3 4,3 5,3 6,3 2,4 3,4 4,4 5,4 6,4 2,5 \
         3,5 4,5 5,5 6,5 2,6 3,6 4,6 5,6 6,6 17,17 18,17 19,17 20,17 21,17 17,18 18,18 19,18 \
         20,18 21,18 17,19 18,19 19,19 20,19 21,19 17,20 18,20 19,20 20,20 21,20 17,21 18,21 \
         19,21 20,21 21,21\n",
    );
    assert_eq!(replay(script), mesa);
}

/// Smooth color and window z along a line; flat color from the last or the first vertex.
#[test]
fn lines_interpolate_color_and_depth_and_flat_shade_from_the_provoking_vertex() {
    let script = "
        size 16 8; enable depth_test; clear 0 0 0 0; begin lines; color 1 0 0 1; v 1.5 1.5 -0.5
        color 0 0 1 1; v 14.5 5.5 0.5; end; dump smooth; depth smooth_z; shade flat; clear 0 0 0 0
        begin line_strip; color 1 0 0 1; v 1.5 1.5; color 0 1 0 1; v 8.5 1.5; color 0 0 1 1; v 8.5 6.5
        end; dump flat_last; provoking first; clear 0 0 0 0; begin line_strip; color 1 0 0 1; v 1.5 1.5
        color 0 1 0 1; v 8.5 1.5; color 0 0 1 1; v 8.5 6.5; end; dump flat_first";
    let mesa = concat!(
        "smooth: 1,1=ff0000ff 2,1=eb0014ff 3,2=d80027ff 4,2=c4003bff 5,2=b1004eff 6,3=9d0062ff \
         7,3=890076ff 8,3=760089ff 9,3=62009dff 10,4=4e00b1ff 11,4=3b00c4ff 12,4=2700d8ff \
         13,5=1400ebff\n",
        "smooth_z: 1,1=bfffff 2,1=b62762 3,2=ac4ec4 4,2=a27627 5,2=989d89 6,3=8ec4eb 7,3=84ec4e \
         8,3=7b13b0 9,3=713b13 10,4=676276 11,4=5d89d8 12,4=53b13a 13,5=49d89c\n",
        "flat_last: 1,1=00ff00ff 2,1=00ff00ff 3,1=00ff00ff 4,1=00ff00ff 5,1=00ff00ff 6,1=00ff00ff \
         7,1=00ff00ff 8,1=0000ffff 8,2=0000ffff 8,3=0000ffff 8,4=0000ffff 8,5=0000ffff\n",
        "flat_first: 1,1=ff0000ff 2,1=ff0000ff 3,1=ff0000ff 4,1=ff0000ff 5,1=ff0000ff \
         6,1=ff0000ff 7,1=ff0000ff 8,1=00ff00ff 8,2=00ff00ff 8,3=00ff00ff 8,4=00ff00ff \
         8,5=00ff00ff\n",
    );
    assert_eq!(replay(script), mesa);
}

/// Only boundary edges (no quad diagonal, glEdgeFlag honoured), per-face modes and culling,
/// and clipped polygons: edges made by clipping are not drawn, vertices made by it are.
#[test]
fn polygon_modes_draw_polygon_edges_and_vertices() {
    let script = "
        size 16 16; color 1 1 1 1; polymode front_and_back line; clear 0 0 0 0; begin quads; v 2.5 2.5
        v 12.5 2.5; v 12.5 12.5; v 2.5 12.5; end; lit quad_outline_no_diagonal; clear 0 0 0 0
        begin polygon; v 2.3 1.7; edge 0; v 13.2 3.1; edge 1; v 11.6 13.4; v 3.1 10.2; end
        lit polygon_edge_flag; polymode front point; polymode back line; clear 0 0 0 0; begin triangles
        v 2.5 2.5; v 7.5 2.5; v 2.5 7.5; v 9.5 9.5; v 9.5 14.5; v 14.5 9.5; end
        lit front_points_back_lines; enable cull_face; cullface front; clear 0 0 0 0; begin triangles
        v 2.5 2.5; v 7.5 2.5; v 2.5 7.5; v 9.5 9.5; v 9.5 14.5; v 14.5 9.5; end; lit front_culled
        disable cull_face; polymode front_and_back line; clear 0 0 0 0; begin triangles; v -6.5 4.5
        v 12.5 6.5; v 4.5 14.5; end; lit clip_edges_not_drawn; polymode front_and_back point
        clear 0 0 0 0; begin triangles; v -6.5 4.5; v 12.5 6.5; v 4.5 14.5; end
        lit clip_vertices_are_points";
    let mesa = concat!(
        "quad_outline_no_diagonal: 2,2 3,2 4,2 5,2 6,2 7,2 8,2 9,2 10,2 11,2 12,2 2,3 12,3 2,4 \
         12,4 2,5 12,5 2,6 12,6 2,7 12,7 2,8 12,8 2,9 12,9 2,10 12,10 2,11 12,11 2,12 3,12 4,12 \
         5,12 6,12 7,12 8,12 9,12 10,12 11,12 12,12\n",
        "polygon_edge_flag: 2,1 3,1 4,1 2,2 5,2 6,2 7,2 8,2 9,2 10,2 11,2 2,3 12,3 2,4 2,5 2,6 \
         2,7 2,8 3,9 3,10 4,10 5,11 6,11 7,11 8,12 9,12 10,12 11,13\n",
        "front_points_back_lines: 2,2 7,2 2,7 9,9 10,9 11,9 12,9 13,9 14,9 9,10 13,10 9,11 12,11 \
         9,12 11,12 9,13 10,13 9,14\n",
        "front_culled: 9,9 10,9 11,9 12,9 13,9 14,9 9,10 13,10 9,11 12,11 9,12 11,12 9,13 10,13 \
         9,14\n",
        "clip_edges_not_drawn: 0,5 1,5 2,5 3,5 4,5 5,5 6,5 7,5 8,6 9,6 10,6 11,6 12,6 11,7 10,8 \
         9,9 0,10 8,10 1,11 7,11 2,12 6,12 3,13 5,13 4,14\n",
        "clip_vertices_are_points: 0,5 12,6 4,14\n",
    );
    assert_eq!(replay(script), mesa);
}
/// GL_POLYGON_OFFSET_LINE with factor 1 and units 2, against no offset.
#[test]
fn polygon_offset_line_moves_outline_depth() {
    let script = "
        size 16 16; color 1 1 1 1; enable depth_test; depthfunc always; polymode front_and_back line
        enable offset_line; offset 1 2; clear 0 0 0 0; begin triangles; v 2.5 2.5 0.2; v 13.5 3.5 -0.3
        v 6.5 13.5 0.4; end; depth offset_line; disable offset_line; clear 0 0 0 0; begin triangles
        v 2.5 2.5 0.2; v 13.5 3.5 -0.3; v 6.5 13.5 0.4; end; depth no_offset";
    let mesa = concat!(
        "offset_line: 2,2=6ca2ce 3,2=727442 4,2=7845b6 5,2=7e172a 6,2=83e89f 7,2=89ba13 \
         2,3=6a4f06 8,3=8f8b87 9,3=955cfc 10,3=9b2e70 11,3=a0ffe4 12,3=a6d159 13,3=aca2cd \
         3,4=67fb3e 12,4=a3ad0b 3,5=65a776 12,5=9ab748 3,6=6353ae 11,6=91c185 4,7=60ffe6 \
         10,7=88cbc3 4,8=5eac1d 10,8=7fd601 5,9=5c5855 9,9=76e03e 5,10=5a048d 8,10=6dea7c \
         5,11=57b0c5 7,11=64f4ba 6,12=555cfd 7,12=5bfef7 6,13=530934\n",
        "no_offset: 2,2=666666 3,2=6c37da 4,2=72094e 5,2=77dac3 6,2=7dac38 7,2=837dab 2,3=64129e \
         8,3=894f1f 9,3=8f2094 10,3=94f208 11,3=9ac37c 12,3=a094f1 13,3=a66665 3,4=61bed6 \
         12,4=9d70a3 3,5=5f6b0e 12,5=947ae0 3,6=5d1746 11,6=8b851d 4,7=5ac37d 10,7=828f5b \
         4,8=586fb5 10,8=799999 5,9=561bed 9,9=70a3d6 5,10=53c824 8,10=67ae14 5,11=51745c \
         7,11=5eb852 6,12=4f2094 7,12=55c28f 6,13=4ccccc\n",
    );
    assert_eq!(replay(script), mesa);
}

/// Row y % 32 from the bottom, bit 31 − x % 32; outlines are not stippled.
#[test]
fn polygon_stipple_is_anchored_at_the_window_origin() {
    let script = "
        size 40 37; color 1 1 1 1; clear 0 0 0 0
        pstipple 80000001 00000000 00000000 80000001 00000000 0000ffff 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000 00000000 80000001 00000000
        enable polygon_stipple; begin triangles; v 1.3 2.7; v 39 5; v 20 36; end; lit filled
        polymode front_and_back line; clear 0 0 0 0; begin triangles; v 1.3 2.7; v 39 5; v 20 36; end
        lit outline_not_stippled";
    let mesa = concat!(
        "filled: 16,5 17,5 18,5 19,5 20,5 21,5 22,5 23,5 24,5 25,5 26,5 27,5 28,5 29,5 30,5 31,5 \
         31,6 32,6 31,9 32,9 31,12 32,12 31,15 32,15\n",
        "outline_not_stippled: 1,2 2,2 3,2 4,2 5,2 1,3 6,3 7,3 8,3 9,3 10,3 11,3 12,3 13,3 14,3 \
         15,3 16,3 17,3 18,3 19,3 20,3 21,3 22,3 2,4 23,4 24,4 25,4 26,4 27,4 28,4 29,4 30,4 31,4 \
         32,4 33,4 34,4 35,4 36,4 37,4 38,4 2,5 38,5 3,6 38,6 3,7 37,7 4,8 36,8 5,9 36,9 5,10 \
         35,10 6,11 35,11 6,12 34,12 7,13 33,13 7,14 33,14 8,15 32,15 9,16 31,16 9,17 31,17 10,18 \
         30,18 10,19 30,19 11,20 29,20 11,21 28,21 12,22 28,22 12,23 27,23 13,24 27,24 14,25 \
         26,25 14,26 25,26 15,27 25,27 15,28 24,28 16,29 23,29 16,30 23,30 17,31 22,31 18,32 \
         22,32 18,33 21,33 19,34 20,34 19,35 20,35\n",
    );
    assert_eq!(replay(script), mesa);
}

/// A quad in GL_LINE mode is stippled as one strip of four edges, in Mesa's edge order.
#[test]
fn outline_edges_continue_the_line_stipple() {
    let script = "
        size 16 16; color 1 1 1 1; polymode front_and_back line; enable line_stipple; stipple 1 3333
        clear 0 0 0 0; begin quads; v 1.5 1.5; v 14.5 1.5; v 14.5 14.5; v 1.5 14.5; end
        lit quad_edges_continue_the_pattern";
    let mesa = "quad_edges_continue_the_pattern: 1,1 4,1 5,1 8,1 9,1 12,1 13,1 1,2 14,3 14,4 1,5 1,6 \
         14,7 14,8 1,9 1,10 14,11 14,12 1,13 1,14 4,14 5,14 8,14 9,14 12,14 13,14\n";
    assert_eq!(replay(script), mesa);
}

#[test]
fn lines_points_and_outlines_are_identical_for_any_thread_count() {
    let render = |threads: usize| {
        let (mut ctx, d) = context(300, 200);
        ctx.state.depth.test = true;
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        let mut seed = 777u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            (seed >> 8) as f32 / (1 << 24) as f32
        };
        let mut vertices = Vec::new();
        for _ in 0..120 {
            let c = [rnd(), rnd(), rnd(), 1.0];
            vertices.push(vertex(rnd() * 340.0 - 20.0, rnd() * 240.0 - 20.0, rnd() * 2.0 - 1.0, c));
        }
        ctx.state.line_point.line_width = 3.0;
        ctx.draw_vertices(GL_LINE_STRIP, &vertices);
        ctx.state.line_point.line_stipple = true;
        ctx.state.line_point.line_stipple_pattern = 0x3f3f;
        ctx.state.line_point.line_width = 1.0;
        ctx.draw_vertices(GL_LINES, &vertices);
        ctx.state.line_point.point_size = 9.0;
        ctx.draw_vertices(GL_POINTS, &vertices);
        ctx.state.polygon.mode_front = GL_LINE;
        ctx.state.polygon.mode_back = GL_POINT;
        ctx.draw_vertices(GL_TRIANGLES, &vertices);
        let scene = ctx.scene.take().unwrap();
        scene.execute_on(&mut d.lock().unwrap().framebuffer, threads);
        pixels(&mut ctx, &d)
    };
    let one = render(1);
    assert!(one.iter().filter(|p| p[3] != 0).count() > 5000);
    for threads in [2, 4, 7] {
        assert!(one == render(threads), "{threads} threads differ");
    }
}
/// Long connected primitives are delivered in parts (glBegin/glEnd and array draws) and
/// the scene is rendered when over budget; the pixels are those of the primitive drawn
/// whole: strip order, fans' and polygons' first vertex, provoking vertices, a polygon's
/// outline and the line stipple all continue across parts.
#[test]
fn long_primitives_in_parts_draw_the_same_pixels_as_whole() {
    use crate::context::vertex_input::test_support::{floats, FakeMemory};
    use crate::context::vertex_input::BATCH_VERTICES;
    let count = 2 * BATCH_VERTICES + 7;
    let spiral: Vec<Vertex> = (0..count)
        .map(|i| {
            let t = i as f32 / count as f32;
            let angle = t * 9.0 * std::f32::consts::TAU;
            let r = 6.0 + 38.0 * t + if i % 2 == 1 { 4.0 } else { 0.0 };
            let color = [t, 1.0 - t, if i % 7 < 3 { 1.0 } else { 0.2 }, 1.0];
            vertex(48.0 + r * angle.cos(), 48.0 + r * angle.sin(), 0.0, color)
        })
        .collect();
    let mut memory = FakeMemory::default();
    let positions: Vec<f32> = spiral.iter().flat_map(|v| v.position).collect();
    let colors: Vec<f32> = spiral.iter().flat_map(|v| v.color).collect();
    let positions = memory.add(0x1000_0000, floats(&positions));
    let colors = memory.add(0x2000_0000, floats(&colors));
    let modes = [GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUAD_STRIP, GL_POLYGON];
    for mode in modes {
        for (flat, first_vertex, outline) in [(false, false, false), (true, false, true), (true, true, false)] {
            let setup = |ctx: &mut Context| {
                ctx.shade_model(if flat { GL_FLAT } else { GL_SMOOTH });
                ctx.provoking_vertex(if first_vertex { GL_FIRST_VERTEX_CONVENTION } else { GL_LAST_VERTEX_CONVENTION });
                ctx.polygon_mode(GL_FRONT_AND_BACK, if outline { GL_LINE } else { GL_FILL });
                ctx.line_stipple(1, 0x0f3b);
                ctx.set_capability(GL_LINE_STIPPLE, true);
            };
            let (mut whole, d) = context(96, 96);
            setup(&mut whole);
            whole.draw_vertices(mode, &spiral);
            let expected = pixels(&mut whole, &d);
            let (mut ctx, d) = context(96, 96);
            setup(&mut ctx);
            ctx.begin(mode);
            for v in &spiral {
                ctx.set_color(v.color);
                ctx.vertex(v.position);
            }
            ctx.end();
            assert!(ctx.vertex_input.delivered.len() >= 3, "mode {mode:#x}: delivered in parts");
            assert!(pixels(&mut ctx, &d) == expected, "mode {mode:#x} flat {flat} outline {outline}: glBegin");
            let (mut ctx, d) = context(96, 96);
            setup(&mut ctx);
            ctx.vertex_pointer(4, GL_FLOAT, 0, positions);
            ctx.color_pointer(4, GL_FLOAT, 0, colors);
            ctx.enable_client_state(GL_VERTEX_ARRAY, true);
            ctx.enable_client_state(GL_COLOR_ARRAY, true);
            ctx.draw_arrays(mode, 0, count as i32, &memory);
            assert!(ctx.vertex_input.delivered.len() >= 3, "mode {mode:#x}: delivered in parts");
            assert!(pixels(&mut ctx, &d) == expected, "mode {mode:#x} flat {flat} outline {outline}: arrays");
            assert_eq!(ctx.take_error(), GL_NO_ERROR);
        }
    }
}

#[test]
fn a_scene_over_its_budget_is_rendered_at_the_next_draw() {
    let (mut ctx, d) = context(64, 64);
    let per_square = 2 * std::mem::size_of::<(u32, RasterPrimitive)>() + 2 * 4;
    let squares = Scene::BUDGET_BYTES / per_square + 2;
    for i in 0..squares {
        let c = (i % 256) as f32 / 255.0;
        square(&mut ctx, 0.0, 0.0, 64.0, 64.0, [c, 1.0 - c, 0.5, 1.0]);
        let recorded = ctx.scene.as_ref().map_or(0, |s| s.recorded_bytes());
        assert!(recorded <= Scene::BUDGET_BYTES, "square {i}: {recorded} bytes recorded");
    }
    let last = ((squares - 1) % 256) as f32 / 255.0;
    let expected = [(last * 255.0).round() as u8, ((1.0 - last) * 255.0).round() as u8, 128, 255];
    assert!(pixels(&mut ctx, &d).iter().all(|&p| p == expected));
}

/// A long triangle strip of small triangles (zig-zag rows over a 64 × 64 window, each
/// triangle half of a 1 × 2 pixel cell and covering one pixel centre, so that the scene
/// records every one: a triangle covering no centre is not recorded), drawn in
/// immediate mode, from a client array, and from a display list that captured that array
/// draw: the scene is rendered whenever it passes its budget, so what it records never
/// exceeds the budget by more than one part of a draw. (Before display-list draws were cut
/// into parts again at replay, the list's strip was drawn as one part: 300 000 vertices
/// made a scene of about 170 MB.)
#[test]
fn long_draws_keep_the_scene_within_its_budget() {
    use super::PEAK_SCENE_BYTES;
    use crate::context::vertex_input::test_support::{floats, FakeMemory};
    use crate::context::vertex_input::BATCH_VERTICES;
    const N: usize = 300_000;
    let position = |i: usize| {
        let (column, row) = ((i / 2) % 60, (i / 2) / 60);
        [0.75 + column as f32, ((row % 30) * 2 + (i & 1) * 2) as f32 + 0.25]
    };
    let (mut ctx, _d) = Context::with_test_drawable(
        FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0),
        64,
        64,
    );
    ctx.matrix_mode(GL_PROJECTION);
    ctx.ortho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    // One part of a strip: its triangles, one bin entry each (the window is one tile).
    let part = (BATCH_VERTICES + 2) * (std::mem::size_of::<(u32, RasterPrimitive)>() + std::mem::size_of::<u32>());
    let bound = Scene::BUDGET_BYTES + part;
    let mut memory = FakeMemory::default();
    let xy: Vec<f32> = (0..N).flat_map(position).collect();
    memory.add(0x1000, floats(&xy));
    ctx.vertex_pointer(2, GL_FLOAT, 0, 0x1000);
    ctx.enable_client_state(GL_VERTEX_ARRAY, true);
    type Draw<'a> = (&'a str, &'a dyn Fn(&mut Context));
    let draws: [Draw; 3] = [
        ("immediate mode", &|ctx| {
            ctx.begin(GL_TRIANGLE_STRIP);
            for i in 0..N {
                let [x, y] = position(i);
                ctx.vertex([x, y, 0.0, 1.0]);
            }
            ctx.end();
        }),
        ("client array", &|ctx| ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, N as i32, &memory)),
        ("display list", &|ctx| {
            ctx.new_list(1, GL_COMPILE);
            ctx.draw_or_compile(|ctx| ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, N as i32, &memory));
            ctx.end_list();
            ctx.vertex_input.delivered.clear();
            PEAK_SCENE_BYTES.with(|p| p.set(0));
            ctx.call_list(1);
        }),
    ];
    for (how, draw) in draws {
        ctx.flush_rendering();
        ctx.vertex_input.delivered.clear();
        PEAK_SCENE_BYTES.with(|p| p.set(0));
        draw(&mut ctx);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let peak = PEAK_SCENE_BYTES.with(|p| p.get());
        assert!(peak > Scene::BUDGET_BYTES / 2, "{how}: the draw must be long enough to fill a scene");
        assert!(peak <= bound, "{how}: the scene recorded {peak} bytes, over {bound}");
        let delivered = &ctx.vertex_input.delivered;
        assert!(delivered.iter().all(|(_, v)| v.len() <= BATCH_VERTICES + 2), "{how}: a part too long");
        assert_eq!(delivered.iter().map(|(_, v)| v.len() - 2).sum::<usize>(), N - 2, "{how}: every triangle once");
    }
}

/// Records the long draw of the overlap tests (a segment and 101 triangles, blended in
/// order, depth tested after a depth clear) into a 96 × 96 window, with the overlap on or
/// off, before `present` (which may give the drawable a presenter), and runs `finish` after;
/// the bytes the scene left pending after the draw, and what `finish` returns.
fn long_overlap_draw<R>(
    overlap: bool,
    present: impl FnOnce(&Arc<Mutex<Drawable>>),
    finish: impl FnOnce(&mut Context, &Arc<Mutex<Drawable>>) -> R,
) -> (usize, R) {
    use super::{OVERLAP_ENABLED, OVERLAP_SEGMENT_VERTICES};
    use crate::context::vertex_input::test_support::{floats, FakeMemory};
    let triangles = OVERLAP_SEGMENT_VERTICES + 101;
    let mut seed = 12345u32;
    let mut random = move || {
        seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    };
    let (mut xyz, mut rgba) = (Vec::new(), Vec::new());
    for _ in 0..triangles {
        let (x, y, z) = (random() * 90.0, random() * 90.0, random() * 2.0 - 1.0);
        let color = [random(), random(), random(), 0.5];
        for _ in 0..3 {
            xyz.extend([x + random() * 8.0, y + random() * 8.0, z]);
            rgba.extend(color);
        }
    }
    let mut memory = FakeMemory::default();
    let positions = memory.add(0x1000_0000, floats(&xyz));
    let colors = memory.add(0x2000_0000, floats(&rgba));
    OVERLAP_ENABLED.with(|on| on.set(overlap));
    let (mut ctx, d) = Context::with_test_drawable(
        FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::Packed24 { depth: true, stencil: false },
            0,
        ),
        96,
        96,
    );
    present(&d);
    ctx.matrix_mode(GL_PROJECTION);
    ctx.ortho(0.0, 96.0, 0.0, 96.0, -1.0, 1.0);
    ctx.clear_color([0.2, 0.3, 0.4, 1.0]);
    ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ctx.set_capability(GL_DEPTH_TEST, true);
    ctx.depth_func(GL_LEQUAL);
    ctx.set_capability(GL_BLEND, true);
    ctx.blend_func(None, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    ctx.vertex_pointer(3, GL_FLOAT, 0, positions);
    ctx.color_pointer(4, GL_FLOAT, 0, colors);
    ctx.enable_client_state(GL_VERTEX_ARRAY, true);
    ctx.enable_client_state(GL_COLOR_ARRAY, true);
    ctx.draw_arrays(GL_TRIANGLES, 0, 3 * triangles as i32, &memory);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
    let pending = ctx.scene.as_ref().map_or(0, |s| s.recorded_bytes());
    let result = finish(&mut ctx, &d);
    OVERLAP_ENABLED.with(|on| on.set(true));
    (pending, result)
}

/// A long array draw of independent triangles into the window is recorded in segments, each
/// while the segment before it renders on another thread
/// (`Context::record_in_segments`): the pixels (blended in order, depth tested after a
/// depth clear) are those of the draw recorded whole, and the scene left pending holds only
/// the draw's last segment (without the overlap it holds every triangle).
#[test]
fn a_long_draw_records_each_segment_while_the_one_before_renders_with_the_same_pixels() {
    let read = |ctx: &mut Context, d: &Arc<Mutex<Drawable>>| pixels(ctx, d);
    let (whole_pending, whole) = long_overlap_draw(false, |_| {}, read);
    let (overlapped_pending, overlapped) = long_overlap_draw(true, |_| {}, read);
    assert!(whole.iter().filter(|p| p[0] != 51).count() > 96 * 96 / 2, "the triangles cover the window");
    assert!(overlapped_pending * 3 < whole_pending, "{overlapped_pending} bytes pending of {whole_pending}");
    assert!(overlapped == whole, "the overlapped draw's pixels differ");
}

/// Into a window presented in memory it lends (an OSMesa caller's RGBA8 buffer), the
/// segments of an overlapped draw render in place there, as a presenting flush point does:
/// glFinish then leaves the same image in that memory as the draw recorded whole, and
/// neither copies the framebuffer's own pixels into it (the segments rendered into those
/// would leave the last flush a copy of the whole image).
#[test]
fn an_overlapped_draw_renders_its_segments_in_place_into_lent_memory() {
    use crate::framebuffer::external::CallerBuffer;
    use crate::framebuffer::{Framebuffer, Present};
    use std::sync::atomic::{AtomicUsize, Ordering};
    /// Test memory (RGBA8 rows bottom-up) lent for rendering in place; `copies` counts
    /// the presentations that copy the own pixels into it.
    struct Lending {
        buffer: CallerBuffer,
        copies: Arc<AtomicUsize>,
    }
    impl Present for Lending {
        fn present(&mut self, framebuffer: &Framebuffer) {
            self.copies.fetch_add(1, Ordering::SeqCst);
            let pixels = framebuffer.width() * framebuffer.height();
            let own = framebuffer.color(ColorSlot::FrontLeft).map(|b| b.pixels());
            if let (Some(crate::framebuffer::surface::ColorPixels::Unorm8(own)), Some(memory)) =
                (own, self.buffer.unorm8_pixels_mut(pixels))
            {
                memory.copy_from_slice(&own[..pixels]);
            }
        }
        fn only_when_drawn(&self) -> bool {
            true
        }
        fn lends(&self, _: &Framebuffer) -> bool {
            true
        }
        fn lend(&mut self, _: &Framebuffer) -> Option<CallerBuffer> {
            Some(std::mem::replace(&mut self.buffer, CallerBuffer::empty()))
        }
        fn give_back(&mut self, memory: CallerBuffer) {
            self.buffer = memory;
        }
        fn memory(&self) -> Option<usize> {
            Some(self.buffer.as_ptr() as usize)
        }
    }
    let draw = |overlap: bool| {
        let mut memory = vec![0u8; 96 * 96 * 4];
        let copies = Arc::new(AtomicUsize::new(0));
        let buffer = CallerBuffer::of_test_vec(&mut memory);
        let lending = Lending { buffer, copies: copies.clone() };
        let present = |d: &Arc<Mutex<Drawable>>| d.lock().unwrap().set_presenter(Some(Box::new(lending)));
        let (_, ()) = long_overlap_draw(overlap, present, |ctx, d| {
            ctx.finish();
            // The memory is the test's again (the presenter is dropped with the drawable).
            d.lock().unwrap().set_presenter(None);
        });
        (memory, copies.load(Ordering::SeqCst))
    };
    let (whole, whole_copies) = draw(false);
    let (overlapped, overlapped_copies) = draw(true);
    assert!(whole.chunks(4).filter(|p| p[0] != 51).count() > 96 * 96 / 2, "the triangles cover the window");
    assert_eq!((whole_copies, overlapped_copies), (0, 0), "presentations that copied the image");
    assert!(overlapped == whole, "the overlapped draw's pixels differ");
}
