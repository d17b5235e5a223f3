//! Draws with a GLSL vertex shader (and fixed-function fragment processing): the generic
//! attributes reach the shader through every vertex source (current values, arrays of
//! every kind, glVertexAttrib between glBegin and glEnd, attribute 0 as the position), and
//! the outputs land where the rest of the pipeline reads them.
use super::test_support::FakeMemory;
use crate::context::draw::replay::{context, pixels};
use crate::context::shader_objects::UniformForm;
use crate::context::Context;
use crate::gl::enums::*;
use crate::vertex::generic::CURRENT;

/// An 8×8 context (glOrtho(0, 8, 0, 8)) using the vertex shader `source`, "color" bound to
/// generic attribute 1 and "size" to 2.
fn with_shader(source: &str) -> (Context, std::sync::Arc<std::sync::Mutex<crate::framebuffer::Drawable>>) {
    let (mut ctx, d) = context(8, 8);
    let shader = ctx.create_shader(GL_VERTEX_SHADER);
    ctx.shader_source(shader, Ok(vec![source.as_bytes().to_vec()]));
    ctx.compile_shader(shader);
    let program = ctx.create_program();
    ctx.attach_shader(program, shader);
    ctx.bind_attrib_location(program, 1, b"color");
    ctx.bind_attrib_location(program, 2, b"size");
    ctx.link_program(program);
    assert_eq!(ctx.get_program(program, GL_LINK_STATUS), Some(1), "{source}");
    ctx.use_program(program);
    ctx.shade_model(GL_FLAT);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
    (ctx, d)
}

/// Maps object coordinates 0..8 onto the window, the colour from generic attribute 1.
const GENERIC_COLOR: &str = "attribute vec4 color;\n\
    void main() { gl_Position = vec4(gl_Vertex.xy / 4.0 - 1.0, 0.0, 1.0); gl_FrontColor = color; }";

fn bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_ne_bytes()).collect()
}

/// The lower-right and upper-left triangles of the window, as a triangle list.
const HALVES: [f32; 12] = [0.0, 0.0, 8.0, 0.0, 8.0, 8.0, 0.0, 0.0, 8.0, 8.0, 0.0, 8.0];

fn pixel(p: &[[u8; 4]], x: usize, y: usize) -> [u8; 4] {
    p[y * 8 + x]
}

#[test]
fn generic_attributes_from_current_values_and_arrays() {
    let (mut ctx, d) = with_shader(GENERIC_COLOR);
    let mut memory = FakeMemory::default();
    let positions = memory.add(0x1000, bytes(&HALVES));
    ctx.vertex_pointer(2, GL_FLOAT, 0, positions);
    ctx.enable_client_state(GL_VERTEX_ARRAY, true);
    // The current value, for every vertex.
    ctx.vertex_attrib(1, [0.0, 1.0, 0.0, 1.0]);
    ctx.draw_arrays(GL_TRIANGLES, 0, 6, &memory);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [0, 255, 0, 255]);
    assert_eq!(pixel(&p, 1, 6), [0, 255, 0, 255]);
    // A float array: flat shading takes each triangle's last vertex.
    let colors: Vec<f32> = [[1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0]]
        .iter()
        .flat_map(|c| std::iter::repeat_n(*c, 3).flatten())
        .collect();
    let address = memory.add(0x2000, bytes(&colors));
    ctx.vertex_attrib_pointer(1, 4, GL_FLOAT, false, 0, address);
    ctx.enable_vertex_attrib_array(1, true);
    ctx.draw_arrays(GL_TRIANGLES, 0, 6, &memory);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [255, 0, 0, 255]);
    assert_eq!(pixel(&p, 1, 6), [0, 0, 255, 255]);
    // Normalized unsigned bytes, three components (alpha 1), through glDrawElements.
    let address = memory.add(0x3000, vec![0, 0, 0, 255, 255, 0, 0, 0, 0, 51, 102, 153]);
    let indices = memory.add(0x4000, vec![0, 1, 2, 0, 2, 3]);
    let quad = memory.add(0x5000, bytes(&[0.0, 0.0, 8.0, 0.0, 8.0, 8.0, 0.0, 8.0]));
    ctx.vertex_pointer(2, GL_FLOAT, 0, quad);
    ctx.vertex_attrib_pointer(1, 3, GL_UNSIGNED_BYTE, true, 3, address);
    ctx.draw_elements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, indices, &memory);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [0, 0, 0, 255], "vertex 2");
    assert_eq!(pixel(&p, 1, 6), [51, 102, 153, 255], "vertex 3");
    // Not normalized: the integers themselves.
    let address = memory.add(0x6000, vec![0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1]);
    ctx.vertex_attrib_pointer(1, 3, GL_UNSIGNED_BYTE, false, 3, address);
    ctx.draw_elements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, indices, &memory);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [255, 0, 255, 255]);
    assert_eq!(pixel(&p, 1, 6), [0, 0, 255, 255]);
    // The rows of an array draw do not outlive it.
    assert!(ctx.vertex_input.generic_rows.rows.is_empty());
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
}

#[test]
fn generic_attributes_between_begin_and_end_keep_each_vertex_its_values() {
    let (mut ctx, d) = with_shader(GENERIC_COLOR);
    ctx.vertex_attrib(1, [1.0, 0.0, 0.0, 1.0]);
    ctx.begin(GL_TRIANGLES);
    ctx.vertex([0.0, 0.0, 0.0, 1.0]);
    ctx.vertex([8.0, 0.0, 0.0, 1.0]);
    // The vertices made so far keep red; the first triangle's last vertex takes it.
    ctx.vertex_attrib(1, [0.0, 1.0, 0.0, 1.0]);
    ctx.vertex_attrib(1, [0.0, 0.0, 1.0, 1.0]);
    ctx.vertex_attrib(1, [1.0, 1.0, 0.0, 1.0]);
    assert_eq!(ctx.vertex_input.vertices[0].generic, ctx.vertex_input.vertices[1].generic);
    ctx.vertex([8.0, 8.0, 0.0, 1.0]);
    ctx.vertex([0.0, 0.0, 0.0, 1.0]);
    ctx.vertex_attrib(1, [0.0, 1.0, 1.0, 1.0]);
    ctx.vertex([8.0, 8.0, 0.0, 1.0]);
    // Generic attribute 0 is a glVertex, made with the current values.
    ctx.vertex_attrib(1, [1.0, 0.0, 1.0, 1.0]);
    ctx.vertex_attrib(0, [0.0, 8.0, 0.0, 1.0]);
    let rows: Vec<u32> = ctx.vertex_input.vertices.iter().map(|v| v.generic).collect();
    assert!(rows.iter().all(|&r| r != CURRENT));
    ctx.end();
    assert_eq!(ctx.state.current.generic_row, CURRENT, "glEnd forgets the rows");
    assert!(ctx.vertex_input.generic_rows.rows.is_empty());
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [255, 255, 0, 255]);
    assert_eq!(pixel(&p, 1, 6), [255, 0, 255, 255]);
    // Smooth: each vertex its own value.
    ctx.shade_model(GL_SMOOTH);
    ctx.begin(GL_TRIANGLES);
    ctx.vertex_attrib(1, [1.0, 0.0, 0.0, 1.0]);
    ctx.vertex([0.0, 0.0, 0.0, 1.0]);
    ctx.vertex_attrib(1, [0.0, 1.0, 0.0, 1.0]);
    ctx.vertex([16.0, 0.0, 0.0, 1.0]);
    ctx.vertex_attrib(1, [0.0, 0.0, 1.0, 1.0]);
    ctx.vertex([0.0, 16.0, 0.0, 1.0]);
    ctx.end();
    let p = pixels(&mut ctx, &d);
    let corner = pixel(&p, 0, 0);
    assert!(corner[0] > 230 && corner[1] < 20 && corner[2] < 20, "{corner:?}");
    let right = pixel(&p, 7, 0);
    assert!(right[1] > 100 && right[0] > 100 && right[2] < 20, "{right:?}");
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
}

#[test]
fn attribute_zero_is_the_position_in_arrays_and_user_attributes() {
    let (mut ctx, d) = with_shader(
        "attribute vec2 where;\n\
         void main() { gl_Position = vec4(where.yx / 4.0 - 1.0, 0.0, 1.0); gl_FrontColor = vec4(1.0); }",
    );
    // "where" is not bound: link gave it a location; bind it to 0 and relink.
    let program = ctx.program_in_use.name();
    ctx.bind_attrib_location(program, 0, b"where");
    ctx.link_program(program);
    let mut memory = FakeMemory::default();
    // Only the lower-right triangle; swapped by the shader into the upper-left one.
    let address = memory.add(0x1000, bytes(&HALVES[..6]));
    ctx.vertex_attrib_pointer(0, 2, GL_FLOAT, false, 0, address);
    ctx.enable_vertex_attrib_array(0, true);
    ctx.draw_arrays(GL_TRIANGLES, 0, 3, &memory);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 1, 6), [255; 4]);
    assert_eq!(pixel(&p, 6, 1), [0, 0, 0, 0]);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
}

#[test]
fn colour_outputs_two_sided_clamped_and_unwritten() {
    let (mut ctx, d) = with_shader(
        "uniform vec4 front;\n\
         void main() { gl_Position = vec4(gl_Vertex.xy / 4.0 - 1.0, 0.0, 1.0);\n\
         gl_FrontColor = front; gl_BackColor = vec4(0.0, 0.0, 1.0, 1.0); }",
    );
    let location = ctx.uniform_location(ctx.program_in_use.name(), "front");
    let value = [2.0f32, -1.0, 0.5, 1.0].map(f32::to_bits);
    ctx.set_uniform(location, 1, UniformForm::Float(4), &value);
    // Counter-clockwise lower-right half, clockwise upper-left half.
    let draw = |ctx: &mut Context| {
        ctx.begin(GL_TRIANGLES);
        for [x, y] in [[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 0.0], [8.0, 8.0], [0.0, 8.0]] {
            ctx.vertex([x, y, 0.0, 1.0]);
        }
        ctx.end();
    };
    // The second triangle wound clockwise.
    let draw_cw = |ctx: &mut Context| {
        ctx.begin(GL_TRIANGLES);
        for [x, y] in [[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 0.0], [0.0, 8.0], [8.0, 8.0]] {
            ctx.vertex([x, y, 0.0, 1.0]);
        }
        ctx.end();
    };
    draw(&mut ctx);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [255, 0, 128, 255], "clamped front colour");
    draw_cw(&mut ctx);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 1, 6), [255, 0, 128, 255], "one-sided: the front colour on back faces");
    ctx.set_capability(GL_VERTEX_PROGRAM_TWO_SIDE, true);
    draw_cw(&mut ctx);
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [255, 0, 128, 255]);
    assert_eq!(pixel(&p, 1, 6), [0, 0, 255, 255], "two-sided: gl_BackColor");
    ctx.set_capability(GL_VERTEX_PROGRAM_TWO_SIDE, false);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
}

#[test]
fn point_size_and_clip_vertex_outputs() {
    let (mut ctx, d) = with_shader(
        "attribute float size;\n\
         void main() { gl_Position = vec4(gl_Vertex.xy / 4.0 - 1.0, 0.0, 1.0);\n\
         gl_FrontColor = vec4(1.0); gl_PointSize = size; gl_ClipVertex = vec4(gl_Vertex.x, 0.0, 0.0, 1.0); }",
    );
    let count = |p: &[[u8; 4]]| p.iter().filter(|c| c[0] == 255).count();
    ctx.vertex_attrib(2, [4.0, 0.0, 0.0, 1.0]);
    ctx.begin(GL_POINTS);
    ctx.vertex([4.0, 4.0, 0.0, 1.0]);
    ctx.end();
    assert_eq!(count(&pixels(&mut ctx, &d)), 1, "glPointSize without GL_VERTEX_PROGRAM_POINT_SIZE");
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.set_capability(GL_VERTEX_PROGRAM_POINT_SIZE, true);
    ctx.begin(GL_POINTS);
    ctx.vertex([4.0, 4.0, 0.0, 1.0]);
    ctx.end();
    assert_eq!(count(&pixels(&mut ctx, &d)), 16, "gl_PointSize 4");
    ctx.clear(GL_COLOR_BUFFER_BIT);
    // x ≤ 3 in the clip vertex's coordinates.
    ctx.clip_plane(GL_CLIP_PLANE0, [-1.0, 0.0, 0.0, 3.0]);
    ctx.set_capability(GL_CLIP_PLANE0, true);
    ctx.begin(GL_QUADS);
    for [x, y] in [[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]] {
        ctx.vertex([x, y, 0.0, 1.0]);
    }
    ctx.end();
    let p = pixels(&mut ctx, &d);
    assert_eq!(count(&p), 24, "three columns");
    assert_eq!(pixel(&p, 2, 5), [255; 4]);
    assert_eq!(pixel(&p, 3, 5)[0], 0);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
}

#[test]
fn array_element_sets_generic_attributes_before_its_vertex() {
    let (mut ctx, d) = with_shader(GENERIC_COLOR);
    let mut memory = FakeMemory::default();
    let positions = memory.add(0x1000, bytes(&HALVES));
    let colors = memory.add(0x2000, vec![255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 0, 0, 255, 255, 255, 0, 255]);
    ctx.vertex_pointer(2, GL_FLOAT, 0, positions);
    ctx.enable_client_state(GL_VERTEX_ARRAY, true);
    ctx.vertex_attrib_pointer(1, 3, GL_UNSIGNED_BYTE, true, 0, colors);
    ctx.enable_vertex_attrib_array(1, true);
    ctx.begin(GL_TRIANGLES);
    for i in 0..6 {
        ctx.array_element(i, &memory);
    }
    ctx.end();
    let p = pixels(&mut ctx, &d);
    assert_eq!(pixel(&p, 6, 1), [0, 0, 255, 255]);
    assert_eq!(pixel(&p, 1, 6), [255, 0, 255, 255]);
    // The last element's values stay current.
    assert_eq!(ctx.state.current.generic[1], [1.0, 0.0, 1.0, 1.0]);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
}
