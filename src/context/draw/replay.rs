//! Test support for the draw path: a context drawing into a small RGBA8 drawable, vertices
//! with default attributes, reading pixels back, and the probe-script replay language of
//! `tools/gl-probe.c`, which lets a test run the same script as Mesa and compare the output.
use crate::context::Context;
use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, Drawable, FramebufferConfig};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::gl::CompareFunc;
use crate::vertex::Vertex;
use std::sync::{Arc, Mutex};

pub(crate) fn context(w: usize, h: usize) -> (Context, Arc<Mutex<Drawable>>) {
    let visual = FramebufferConfig::single_buffered(
        ColorFormat::Unorm8 { alpha: true },
        DepthStencilFormat::Packed24 { depth: true, stencil: true },
        0,
    );
    let (mut ctx, d) = Context::with_test_drawable(visual, w, h);
    // glOrtho(0, w, 0, h, -1, 1): object coordinates are window coordinates.
    ctx.matrix_mode(GL_PROJECTION);
    ctx.ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
    (ctx, d)
}

/// A vertex at (x, y, z) of `color` with default attributes (shared by the context's
/// draw tests).
pub(crate) fn vertex(x: f32, y: f32, z: f32, color: [f32; 4]) -> Vertex {
    Vertex {
        position: [x, y, z, 1.0],
        color,
        secondary_color: [0.0; 4],
        normal: [0.0, 0.0, 1.0],
        tex_coords: [[0.0; 4]; 4],
        fog_coord: 0.0,
        edge_flag: true,
        generic: crate::vertex::generic::CURRENT,
    }
}

pub(crate) fn pixels(ctx: &mut Context, d: &Arc<Mutex<Drawable>>) -> Vec<[u8; 4]> {
    ctx.flush_rendering();
    let guard = d.lock().unwrap();
    let fb = &guard.framebuffer;
    let mut out = Vec::new();
    for y in 0..fb.height() as i32 {
        let mut row = Vec::new();
        fb.color(ColorSlot::FrontLeft).unwrap().read_row_f32(y, 0, fb.width() as i32, &mut row);
        out.extend(row.iter().map(|c| c.map(|x| (x * 255.0).round() as u8)));
    }
    out
}

/// Replays a probe script: the command language of `tools/gl-probe.c`, which runs the
/// same script on Mesa (size, clear, viewport, ortho, frustum, linewidth, pointsize, pointminmax, stipple,
/// pstipple, enable, disable, shade, provoking, polymode, cullface, frontface,
/// depthfunc, offset, begin, color, edge, v, end, lit, dump, depth; one command per line
/// or separated by `;`), printing the same lines, so that a script's output on Mesa and
/// on tessera can be diffed. `lit` lists the pixels that differ from the clear color.
pub(crate) fn replay(script: &str) -> String {
    let mut out = String::new();
    let mut ctx_drawable: Option<(Context, Arc<Mutex<Drawable>>)> = None;
    let mut size = (0usize, 0usize);
    let mut clear = [0.0f32; 4];
    let mut mode = 0;
    let mut vertices = Vec::new();
    let mut color = [1.0f32; 4];
    let mut edge = true;
    let name = |n: &str| -> GLenum {
        match n {
            "points" => GL_POINTS,
            "lines" => GL_LINES,
            "line_strip" => GL_LINE_STRIP,
            "line_loop" => GL_LINE_LOOP,
            "triangles" => GL_TRIANGLES,
            "triangle_strip" => GL_TRIANGLE_STRIP,
            "triangle_fan" => GL_TRIANGLE_FAN,
            "quads" => GL_QUADS,
            "quad_strip" => GL_QUAD_STRIP,
            "polygon" => GL_POLYGON,
            "point" => GL_POINT,
            "line" => GL_LINE,
            "fill" => GL_FILL,
            "front" => GL_FRONT,
            "back" => GL_BACK,
            "front_and_back" => GL_FRONT_AND_BACK,
            "flat" => GL_FLAT,
            "smooth" => GL_SMOOTH,
            "cw" => GL_CW,
            "ccw" => GL_CCW,
            "first" => GL_FIRST_VERTEX_CONVENTION,
            "last" => GL_LAST_VERTEX_CONVENTION,
            _ => panic!("unknown name {n}"),
        }
    };
    for line in script.split(['\n', ';']) {
        let words: Vec<&str> = line.split_whitespace().collect();
        let Some(&cmd) = words.first() else { continue };
        if cmd.starts_with('#') {
            continue;
        }
        let f = |i: usize| words[i].parse::<f64>().unwrap();
        if cmd == "size" {
            size = (words[1].parse().unwrap(), words[2].parse().unwrap());
            ctx_drawable = Some(context(size.0, size.1));
            continue;
        }
        let (ctx, d) = ctx_drawable.as_mut().expect("size first");
        let st = &mut ctx.state;
        match cmd {
            "clear" => {
                clear = [f(1) as f32, f(2) as f32, f(3) as f32, f(4) as f32];
                st.color.clear_color = clear;
                st.depth.clear = 1.0;
                ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            }
            "cleardepth" => {
                st.depth.clear = f(1);
                ctx.clear(GL_DEPTH_BUFFER_BIT);
            }
            "ortho" | "frustum" => {
                let (l, r, b, t, n, fa) = (f(1), f(2), f(3), f(4), f(5), f(6));
                ctx.matrix_mode(GL_PROJECTION);
                ctx.load_identity();
                if cmd == "ortho" {
                    ctx.ortho(l, r, b, t, n, fa);
                } else {
                    ctx.frustum(l, r, b, t, n, fa);
                }
            }
            "viewport" => st.viewport.rect = [1, 2, 3, 4].map(|i| words[i].parse().unwrap()),
            "scissorbox" => st.scissor.rect = [1, 2, 3, 4].map(|i| words[i].parse().unwrap()),
            "linewidth" => st.line_point.line_width = f(1) as f32,
            "pointsize" => st.line_point.point_size = f(1) as f32,
            "pointminmax" => {
                st.line_point.point_size_min = f(1) as f32;
                st.line_point.point_size_max = f(2) as f32;
            }
            "stipple" => {
                st.line_point.line_stipple_factor = words[1].parse().unwrap();
                st.line_point.line_stipple_pattern = u16::from_str_radix(words[2], 16).unwrap();
            }
            "pstipple" => {
                for i in 0..32 {
                    st.polygon_stipple[i] = u32::from_str_radix(words[1 + i], 16).unwrap();
                }
            }
            "enable" | "disable" => {
                let on = cmd == "enable";
                match words[1] {
                    "line_stipple" => st.line_point.line_stipple = on,
                    "polygon_stipple" => st.polygon.stipple = on,
                    "depth_test" => st.depth.test = on,
                    "cull_face" => st.polygon.cull_face = on,
                    "offset_fill" => st.polygon.offset_fill = on,
                    "offset_line" => st.polygon.offset_line = on,
                    "offset_point" => st.polygon.offset_point = on,
                    "scissor" => st.scissor.test = on,
                    w => panic!("unknown capability {w}"),
                }
            }
            "shade" => st.lighting.shade_model = name(words[1]),
            "provoking" => st.lighting.provoking_vertex = name(words[1]),
            "polymode" => {
                let m = name(words[2]);
                match name(words[1]) {
                    GL_FRONT => st.polygon.mode_front = m,
                    GL_BACK => st.polygon.mode_back = m,
                    _ => {
                        st.polygon.mode_front = m;
                        st.polygon.mode_back = m;
                    }
                }
            }
            "cullface" => st.polygon.cull_face_mode = name(words[1]),
            "frontface" => st.polygon.front_face = name(words[1]),
            "depthfunc" => {
                st.depth.func = match words[1] {
                    "less" => CompareFunc::Less,
                    "lequal" => CompareFunc::LessEqual,
                    "equal" => CompareFunc::Equal,
                    "always" => CompareFunc::Always,
                    w => panic!("unknown depth func {w}"),
                }
            }
            "offset" => {
                st.polygon.offset_factor = f(1) as f32;
                st.polygon.offset_units = f(2) as f32;
            }
            "begin" => {
                mode = name(words[1]);
                vertices.clear();
            }
            "color" => color = [f(1) as f32, f(2) as f32, f(3) as f32, f(4) as f32],
            "edge" => edge = words[1] != "0",
            "v" => {
                let p = [
                    f(1) as f32,
                    f(2) as f32,
                    words.get(3).map_or(0.0, |_| f(3) as f32),
                    words.get(4).map_or(1.0, |_| f(4) as f32),
                ];
                let mut v = vertex(p[0], p[1], p[2], color);
                v.position[3] = p[3];
                v.edge_flag = edge;
                vertices.push(v);
            }
            "end" => ctx.draw_vertices(mode, &vertices),
            "lit" | "dump" => {
                let px = pixels(ctx, d);
                let cc = clear.map(|c| (c * 255.0 + 0.5) as u8);
                out.push_str(&format!("{}:", words[1]));
                for (i, p) in px.iter().enumerate() {
                    if *p != cc {
                        let (x, y) = (i % size.0, i / size.0);
                        if cmd == "lit" {
                            out.push_str(&format!(" {x},{y}"));
                        } else {
                            out.push_str(&format!(" {x},{y}={:02x}{:02x}{:02x}{:02x}", p[0], p[1], p[2], p[3]));
                        }
                    }
                }
                out.push('\n');
            }
            "depth" => {
                ctx.flush_rendering();
                let guard = d.lock().unwrap();
                let fb = &guard.framebuffer;
                out.push_str(&format!("{}:", words[1]));
                for y in 0..fb.height() as i32 {
                    let mut row = Vec::new();
                    fb.depth_stencil().read_depth_row(y, 0, fb.width() as i32, &mut row);
                    for (x, z) in row.iter().enumerate() {
                        if *z != 0x00ff_ffff {
                            out.push_str(&format!(" {x},{y}={z:06x}"));
                        }
                    }
                }
                out.push('\n');
            }
            w => panic!("unknown command {w}"),
        }
    }
    out
}
