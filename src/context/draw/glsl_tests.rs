//! Tests of GLSL fragment shaders in draws: the inputs a shader reads (the colours,
//! `gl_TexCoord`, `gl_FragCoord`, `gl_FrontFacing`), the varyings the draw interpolates for
//! it, uniforms and sampler units, and its outputs (colour, `discard`, `gl_FragDepth`), on
//! the block path (filled triangles) and the span path (lines, points, pixel rectangles).
use crate::context::draw::replay::{context, pixels, vertex};
use crate::context::shader_objects::UniformForm;
use crate::context::texture::ImageArgs;
use crate::context::Context;
use crate::gl::enums::*;
use crate::vertex::attribute::Attribute;
use crate::vertex::Vertex;

/// Compiles, links and uses a program of the one fragment shader `source`.
fn use_fragment_shader(ctx: &mut Context, source: &str) -> u32 {
    let shader = ctx.create_shader(GL_FRAGMENT_SHADER);
    ctx.shader_source(shader, Ok(vec![source.as_bytes().to_vec()]));
    ctx.compile_shader(shader);
    let program = ctx.create_program();
    ctx.attach_shader(program, shader);
    ctx.link_program(program);
    ctx.use_program(program);
    assert_eq!(ctx.take_error(), GL_NO_ERROR, "{source}");
    assert!(ctx.fragment_shader().is_some(), "{source}");
    program
}

/// A w×h rectangle from the origin of colour `color`, every vertex with texture
/// coordinates `tex` on unit 1.
fn rectangle(ctx: &mut Context, w: f32, h: f32, color: [f32; 4], tex: [f32; 4]) {
    let v = |x, y| {
        let mut v: Vertex = vertex(x, y, 0.0, color);
        v.tex_coords[1] = tex;
        v
    };
    ctx.draw_vertices(GL_QUADS, &[v(0.0, 0.0), v(w, 0.0), v(w, h), v(0.0, h)]);
}

fn at(p: &[[u8; 4]], w: usize, x: usize, y: usize) -> [u8; 4] {
    p[y * w + x]
}

#[test]
fn a_shader_reads_the_colour_tex_coords_frag_coord_and_facing() {
    let (mut ctx, d) = context(8, 8);
    // Fixed-function texturing on unit 0 (no texture: it would change nothing anyway) and
    // fog are replaced by the shader.
    ctx.set_capability(GL_TEXTURE_2D, true);
    ctx.set_capability(GL_FOG, true);
    use_fragment_shader(
        &mut ctx,
        "void main() { gl_FragColor = vec4(gl_Color.g, gl_TexCoord[1].y, \
         gl_FragCoord.x / 8.0, gl_FrontFacing ? 1.0 : 0.25); }",
    );
    rectangle(&mut ctx, 8.0, 8.0, [0.0, 0.25, 0.0, 1.0], [0.0, 0.25, 0.0, 1.0]);
    let p = pixels(&mut ctx, &d);
    // x = 3: (3.5 / 8) · 255 = 111.56.
    assert_eq!(at(&p, 8, 3, 2), [64, 64, 112, 255]);
    assert_eq!(at(&p, 8, 7, 7), [64, 64, 239, 255]);
    // The same rectangle wound clockwise faces back.
    let v = |x, y| vertex(x, y, 0.0, [0.0; 4]);
    ctx.draw_vertices(GL_TRIANGLES, &[v(0.0, 0.0), v(0.0, 8.0), v(8.0, 0.0)]);
    let p = pixels(&mut ctx, &d);
    assert_eq!(at(&p, 8, 1, 1), [0, 0, 48, 64]);
}

#[test]
fn the_draw_interpolates_exactly_the_varyings_the_shader_reads() {
    let (mut ctx, _d) = context(4, 4);
    ctx.set_capability(GL_FOG, true);
    ctx.set_capability(GL_TEXTURE_2D, true);
    use_fragment_shader(
        &mut ctx,
        "varying float unplaced; void main() { gl_FragColor = vec4(gl_SecondaryColor.a, \
         gl_TexCoord[2].y, gl_Color.r + unplaced, gl_FragCoord.z); }",
    );
    // Neither fog nor unit 0's enabled texture: the shader's own reads. (A user varying
    // without a vertex shader is placed in the first component no gl_TexCoord names: slot 0
    // component 0; its value is undefined, GL 2.1 §2.15.)
    let needed = ctx.varyings_needed();
    assert_eq!(needed.len(), 3, "{needed:?}");
    for a in [Attribute::secondary_color(3), Attribute::tex_coord(2, 1), Attribute::tex_coord(0, 0)] {
        assert!(needed.contains(&a), "{a:?} in {needed:?}");
    }
}

#[test]
fn a_sampler_uniform_names_the_unit_whose_texture_it_reads() {
    let (mut ctx, d) = context(4, 4);
    // A 2×1 texture on unit 1 (its texturing not enabled), NEAREST.
    ctx.active_texture(GL_TEXTURE1);
    let tex = ctx.gen_textures(1).unwrap()[0];
    ctx.bind_texture(GL_TEXTURE_2D, tex);
    let args = ImageArgs {
        target: GL_TEXTURE_2D,
        level: 0,
        internal_format: GL_RGBA as i32,
        width: 2,
        height: 1,
        depth: 1,
        border: 0,
    };
    let texels: [u8; 8] = [255, 0, 0, 255, 0, 0, 255, 128];
    ctx.tex_image(2, args, GL_RGBA, GL_UNSIGNED_BYTE, |_| Ok(Some(&texels[..])));
    ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &[GL_NEAREST as f32], true);
    ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &[GL_NEAREST as f32], true);
    ctx.active_texture(GL_TEXTURE0);
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
    let program = use_fragment_shader(
        &mut ctx,
        "uniform sampler2D s; uniform vec4 add; \
         void main() { gl_FragColor = texture2D(s, vec2(gl_FragCoord.x / 4.0, 0.5)) + add; }",
    );
    let s = ctx.uniform_location(program, "s");
    ctx.set_uniform(s, 1, UniformForm::Int(1), &[1]);
    let add = ctx.uniform_location(program, "add");
    ctx.set_uniform(add, 1, UniformForm::Float(4), &[0.0f32, 0.25, 0.0, 0.0].map(f32::to_bits));
    assert_eq!(ctx.take_error(), GL_NO_ERROR);
    rectangle(&mut ctx, 4.0, 4.0, [0.0; 4], [0.0; 4]);
    let p = pixels(&mut ctx, &d);
    assert_eq!(at(&p, 4, 0, 0), [255, 64, 0, 255]);
    assert_eq!(at(&p, 4, 3, 3), [0, 64, 255, 128]);
    // Unit 2 has no complete texture: (0, 0, 0, 1).
    ctx.set_uniform(s, 1, UniformForm::Int(1), &[2]);
    rectangle(&mut ctx, 4.0, 4.0, [0.0; 4], [0.0; 4]);
    let p = pixels(&mut ctx, &d);
    assert_eq!(at(&p, 4, 1, 1), [0, 64, 0, 255]);
}

#[test]
fn discard_drops_fragments_and_frag_depth_is_tested() {
    let (mut ctx, d) = context(8, 8);
    ctx.set_capability(GL_DEPTH_TEST, true);
    ctx.clear_color([0.0; 4]);
    // Columns 0 and 1 discard; the others take depth x / 8: columns 2 and 3 (0.25, 0.375
    // at their centres: below 0.5) pass, 4.. fail.
    let program = use_fragment_shader(
        &mut ctx,
        "void main() { if (gl_FragCoord.x < 2.0) discard; \
         gl_FragDepth = gl_FragCoord.x / 8.0 - 1.0 / 16.0; gl_FragColor = vec4(1.0); }",
    );
    for draw in 0..2 {
        // Stored depth 0.5 everywhere (z = 0 under glOrtho(.., -1, 1)), drawn without the
        // shader.
        ctx.use_program(0);
        ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        rectangle(&mut ctx, 8.0, 8.0, [0.0, 0.0, 1.0, 1.0], [0.0; 4]);
        ctx.use_program(program);
        if draw == 1 {
            // The span path: one-pixel-high lines of the same fragments, at depth 1.
            for y in 0..8 {
                let v = |x| vertex(x, y as f32 + 0.5, -1.0, [0.0; 4]);
                ctx.draw_vertices(GL_LINES, &[v(0.0), v(8.0)]);
            }
        } else {
            let v = |x, y| vertex(x, y, -1.0, [0.0; 4]);
            ctx.draw_vertices(GL_QUADS, &[v(0.0, 0.0), v(8.0, 0.0), v(8.0, 8.0), v(0.0, 8.0)]);
        }
        let p = pixels(&mut ctx, &d);
        let blue = [0, 0, 255, 255];
        for y in 0..8 {
            assert_eq!(at(&p, 8, 1, y), blue, "draw {draw}: discarded");
            assert_eq!(at(&p, 8, 2, y), [255; 4], "draw {draw}: depth 0.25 passes");
            assert_eq!(at(&p, 8, 4, y), blue, "draw {draw}: depth 0.5 fails");
        }
    }
}

#[test]
fn derivatives_are_taken_over_quads_on_blocks_and_spans() {
    let (mut ctx, d) = context(8, 8);
    use_fragment_shader(
        &mut ctx,
        "void main() { float q = gl_FragCoord.x * gl_FragCoord.x; \
         gl_FragColor = vec4(dFdx(q) / 16.0, dFdy(gl_FragCoord.y) / 2.0, 0.0, 1.0); }",
    );
    rectangle(&mut ctx, 8.0, 8.0, [0.0; 4], [0.0; 4]);
    let p = pixels(&mut ctx, &d);
    // Quads pair columns (0, 1), (2, 3)…: dFdx(x²) = (x₁² − x₀²) = 2 for the first quad
    // (0.5², 1.5²), 6 for the second, 14 for the fourth.
    let expect = |x: usize| ((2.0 * (x & !1) as f32 + 2.0) / 16.0 * 255.0).round() as u8;
    for x in 0..8 {
        assert_eq!(at(&p, 8, x, 3), [expect(x), 128, 0, 255], "column {x}");
    }
    // A line is a span: the same derivatives (its helper lanes are the pixels around it).
    ctx.clear(GL_COLOR_BUFFER_BIT);
    let v = |x| vertex(x, 2.5, 0.0, [0.0; 4]);
    ctx.draw_vertices(GL_LINES, &[v(0.0), v(8.0)]);
    let p = pixels(&mut ctx, &d);
    for x in 0..8 {
        assert_eq!(at(&p, 8, x, 2), [expect(x), 128, 0, 255], "line column {x}");
    }
}
