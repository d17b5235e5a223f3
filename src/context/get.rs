//! glGetBooleanv/Integerv/Floatv/Doublev: one table from pname to typed values, and one
//! conversion layer from typed values to the four result types.
//!
//! [`Context::state_values`] answers a pname with the values as the state holds them, each
//! tagged with its kind ([`Value`]); the `to_*` methods of [`Value`] are the only place where
//! a value changes type, following section 6.1.2 of the GL 2.1 specification and Mesa 22's
//! arithmetic where the specification leaves it open (measured on llvmpipe):
//! - boolean → number is 0 or 1; number → boolean is "not zero" (NaN is true);
//! - float → integer rounds to nearest, halves away from zero (`lroundf`);
//! - a normalized float (colors, alpha reference, depth range, clear depth) → integer maps
//!   [-1, 1] onto [-2³¹+1, 2³¹−1] by truncating `x · 2147483647` computed in double precision:
//!   `glClearColor(0.5, 0.1, …)` reads back 1073741823, 214748367;
//! - an unsigned state value (stencil masks) → integer saturates at 2³¹−1.
//!
//! Deliberate deviations from Mesa 22, where its answer is an accident of C on x86:
//! a normalized value outside [-1, 1] (an unclamped clear color on a float buffer) saturates
//! to the integer range instead of becoming −2³¹, NaN becomes 0 instead of −2³¹, and a float
//! beyond the integer range saturates instead of wrapping. The depth range is reported as the
//! double it is kept in (Mesa 22 keeps it as a float: glDepthRange(0.1, …) reads back
//! 0.10000000149011612 there, 0.1 here).
//!
//! Matrices are not normalized values, so as integers they round like any float (GL 2.1
//! 6.1.2); Mesa 22 maps them like colors (0.5 reads back as 1073741823). GL_TRANSPOSE_TEXTURE_MATRIX
//! is the active unit's, as GL_TEXTURE_MATRIX is (Mesa 22 answers it from unit 0).
//!
//! Colors that fragment clamping applies to (clear color, blend color, alpha reference) are
//! stored as given and clamped here when the clamp is in effect: CLAMP_FRAGMENT_COLOR TRUE, or
//! FIXED_ONLY with a fixed-point color buffer. (Mesa 22 also clamps for OSMesa float buffers
//! under FIXED_ONLY, because its window-system framebuffer never records that it is float,
//! although its clears there are unclamped; tessera answers by the buffer's real format.)
use super::capabilities;
use super::matrix::{transpose, MatrixStacks, StackId};
use super::raster_state::{LINE_WIDTH_GRANULARITY, LINE_WIDTH_RANGE, POINT_SIZE_GRANULARITY, POINT_SIZE_RANGE};
use super::state::StencilFace;
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::{
    MAX_ATTRIB_STACK_DEPTH, MAX_CLIP_PLANES, MAX_LIGHTS, MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS, MAX_VIEWPORT_DIM,
};
use crate::gl::types::*;

/// The implementation limits GLSL programs see, which glGet reports.
const GLSL_LIMITS: crate::glsl::Limits = crate::glsl::Limits::TESSERA;

/// Bits of subpixel precision of the rasterizer (GL_SUBPIXEL_BITS).
pub const SUBPIXEL_BITS: i32 = 8;

/// One state value as GL stores it; the kind decides how it converts to each result type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    Bool(bool),
    Int(i32),
    /// Unsigned state (stencil masks): as an integer it saturates at `i32::MAX`.
    Uint(u32),
    Enum(GLenum),
    /// A float that is not normalized: as an integer it is rounded.
    Float(f32),
    /// A normalized float (colors, alpha reference): as an integer [-1, 1] spans the range.
    NormFloat(f32),
    /// A normalized double (depth range, clear depth).
    NormDouble(f64),
}

/// `x · (2³¹ − 1)` truncated toward zero, as Mesa's `FLOAT_TO_INT`; saturating, NaN → 0.
fn normalized_to_int(x: f64) -> GLint {
    (x * 2147483647.0) as GLint
}

impl Value {
    pub fn to_boolean(self) -> GLboolean {
        let on = match self {
            Value::Bool(b) => b,
            Value::Int(i) => i != 0,
            Value::Uint(u) => u != 0,
            Value::Enum(e) => e != 0,
            Value::Float(f) | Value::NormFloat(f) => f != 0.0,
            Value::NormDouble(d) => d != 0.0,
        };
        if on {
            GL_TRUE
        } else {
            GL_FALSE
        }
    }

    pub fn to_integer(self) -> GLint {
        match self {
            Value::Bool(b) => b as GLint,
            Value::Int(i) => i,
            Value::Uint(u) => u.min(i32::MAX as u32) as GLint,
            Value::Enum(e) => e as GLint,
            // f32::round rounds halves away from zero, as lroundf; `as` saturates.
            Value::Float(f) => f.round() as GLint,
            Value::NormFloat(f) => normalized_to_int(f as f64),
            Value::NormDouble(d) => normalized_to_int(d),
        }
    }

    pub fn to_float(self) -> GLfloat {
        match self {
            Value::Bool(b) => b as u8 as GLfloat,
            Value::Int(i) => i as GLfloat,
            Value::Uint(u) => u as GLfloat,
            Value::Enum(e) => e as GLfloat,
            Value::Float(f) | Value::NormFloat(f) => f,
            Value::NormDouble(d) => d as GLfloat,
        }
    }

    pub fn to_double(self) -> GLdouble {
        match self {
            Value::Bool(b) => b as u8 as GLdouble,
            Value::Int(i) => i as GLdouble,
            Value::Uint(u) => u as GLdouble,
            Value::Enum(e) => e as GLdouble,
            Value::Float(f) | Value::NormFloat(f) => f as GLdouble,
            Value::NormDouble(d) => d,
        }
    }
}

/// The clear index as Mesa 22 reports it: kept as a GLuint made by C's truncating cast (on
/// x86-64 through a 64-bit integer, so 5e9 wraps to 705032704) and returned as a signed int.
/// Color-index rendering does not exist, so the value only matters to glGet.
fn clear_index_value(index: f32) -> i32 {
    if index.is_nan() || index.abs() >= 9.2e18 {
        0
    } else {
        index as i64 as u32 as i32
    }
}

fn bools<const N: usize>(values: [bool; N]) -> Vec<Value> {
    values.map(Value::Bool).to_vec()
}

fn ints<const N: usize>(values: [i32; N]) -> Vec<Value> {
    values.map(Value::Int).to_vec()
}

fn norm_floats<const N: usize>(values: [f32; N]) -> Vec<Value> {
    values.map(Value::NormFloat).to_vec()
}

fn floats<const N: usize>(values: [f32; N]) -> Vec<Value> {
    values.map(Value::Float).to_vec()
}

fn one(value: Value) -> Vec<Value> {
    vec![value]
}

impl Context {
    /// Whether fragment colors (and so the clear color, blend color and alpha reference as
    /// queried) are clamped to [0, 1] for the current draw framebuffer.
    pub fn fragment_clamping(&self) -> bool {
        match self.state.color.clamp_fragment_color {
            GL_FIXED_ONLY => !self.draw_config().color.is_float(),
            clamp => clamp != GL_FALSE as GLenum,
        }
    }

    /// Every value of `pname` as state holds it; `None` when `pname` is not a GL 2.1 query
    /// (or an extension query tessera implements).
    pub fn state_values(&mut self, pname: GLenum) -> Option<Vec<Value>> {
        use Value::*;
        if let Some(on) = capabilities::flag(&mut self.state, pname) {
            return Some(one(Bool(*on)));
        }
        if let Some(values) = self.vertex_input_values(pname) {
            return Some(values);
        }
        if let Some(values) = self.list_values(pname) {
            return Some(values);
        }
        if let Some(values) = self.raster_pos_values(pname) {
            return Some(values);
        }
        if let Some(values) = self.selection_values(pname) {
            return Some(values);
        }
        if let Some(values) = self.pixel_transfer_values(pname) {
            return Some(values);
        }
        if let Some(values) = self.pixel_map_values(pname) {
            return Some(values);
        }
        if let Some(values) = self.evaluator_values(pname) {
            return Some(values);
        }
        let clamp = self.fragment_clamping();
        let clamped = |c: f32| if clamp { c.clamp(0.0, 1.0) } else { c };
        let (s, fb) = (&self.state, &self.draw_config());
        let [red, green, blue, alpha] = fb.color.channel_bits().map(|b| b as i32);
        let accum = fb.accum_bits as i32;
        let stencil_max = (1i32 << fb.depth_stencil.stencil_bits()) - 1;
        // GL_STENCIL_* answer the active face (the EXT back face when it is active, as in
        // Mesa); GL_STENCIL_BACK_* always the GL 2.0 back face.
        let face: &StencilFace = s.stencil.active_face();
        let back = &s.stencil.back;
        let (pack, unpack) = (&self.pixel_store.pack, &self.pixel_store.unpack);
        let texture_stack = StackId::Texture(s.texture.active_unit);
        // Matrices are not normalized: as integers they round (Mesa 22 maps them like colors).
        let matrix = |stack| floats(self.matrix_elements(stack));
        let transposed = |stack| floats(transpose(&self.matrix_elements(stack)));
        let depth = |stack| one(Int(self.matrices.depth(stack) as i32));
        let max_depth = |stack| one(Int(MatrixStacks::max_depth(stack) as i32));
        let (lp, polygon) = (&s.line_point, &s.polygon);
        Some(match pname {
            // Framebuffer properties.
            GL_RED_BITS => one(Int(red)),
            GL_GREEN_BITS => one(Int(green)),
            GL_BLUE_BITS => one(Int(blue)),
            GL_ALPHA_BITS => one(Int(alpha)),
            GL_DEPTH_BITS => one(Int(fb.depth_stencil.depth_bits() as i32)),
            GL_STENCIL_BITS => one(Int(fb.depth_stencil.stencil_bits() as i32)),
            GL_ACCUM_RED_BITS | GL_ACCUM_GREEN_BITS | GL_ACCUM_BLUE_BITS | GL_ACCUM_ALPHA_BITS => one(Int(accum)),
            GL_AUX_BUFFERS => one(Int(fb.aux_buffers as i32)),
            GL_DOUBLEBUFFER => one(Bool(fb.double_buffered)),
            GL_STEREO => one(Bool(fb.stereo)),
            GL_RGBA_MODE => one(Bool(true)),
            GL_INDEX_MODE => one(Bool(false)),
            GL_SAMPLE_BUFFERS => one(Int(i32::from(self.framebuffer_samples() > 1))),
            GL_SAMPLES => one(Int(match self.framebuffer_samples() {
                1 => 0,
                n => n as i32,
            })),
            GL_SAMPLE_COVERAGE_VALUE => one(Float(s.multisample.coverage_value)),
            GL_SAMPLE_COVERAGE_INVERT => one(Bool(s.multisample.coverage_invert)),

            // Implementation limits.
            GL_MAX_VIEWPORT_DIMS => ints([MAX_VIEWPORT_DIM, MAX_VIEWPORT_DIM]),
            GL_MAX_ATTRIB_STACK_DEPTH | GL_MAX_CLIENT_ATTRIB_STACK_DEPTH => one(Int(MAX_ATTRIB_STACK_DEPTH as i32)),
            GL_MAX_DRAW_BUFFERS => one(Int(GLSL_LIMITS.max_draw_buffers)),
            // Framebuffer objects (`framebuffer_object`).
            GL_DRAW_FRAMEBUFFER_BINDING => one(Int(self.fbo.draw as i32)),
            GL_READ_FRAMEBUFFER_BINDING => one(Int(self.fbo.read as i32)),
            GL_RENDERBUFFER_BINDING => one(Int(self.fbo.renderbuffer as i32)),
            GL_CURRENT_PROGRAM => one(Int(self.program_in_use.name() as i32)),
            // GLSL's limits: what the shaders' built-in constants say (`glsl::Limits`).
            GL_MAX_VERTEX_ATTRIBS => one(Int(GLSL_LIMITS.max_vertex_attribs)),
            GL_MAX_VARYING_FLOATS => one(Int(GLSL_LIMITS.max_varying_floats)),
            GL_MAX_VERTEX_UNIFORM_COMPONENTS => one(Int(GLSL_LIMITS.max_vertex_uniform_components)),
            GL_MAX_FRAGMENT_UNIFORM_COMPONENTS => one(Int(GLSL_LIMITS.max_fragment_uniform_components)),
            GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS => one(Int(GLSL_LIMITS.max_vertex_texture_image_units)),
            GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS => one(Int(GLSL_LIMITS.max_combined_texture_image_units)),
            GL_MAX_TEXTURE_IMAGE_UNITS => one(Int(GLSL_LIMITS.max_texture_image_units)),
            GL_MAX_COLOR_ATTACHMENTS => one(Int(super::framebuffer_object::MAX_COLOR_ATTACHMENTS as i32)),
            GL_MAX_RENDERBUFFER_SIZE => one(Int(super::framebuffer_object::MAX_RENDERBUFFER_SIZE)),
            GL_MAX_SAMPLES => one(Int(super::framebuffer_object::MAX_SAMPLES)),
            GL_MAX_CLIP_PLANES => one(Int(MAX_CLIP_PLANES as i32)),
            GL_MAX_LIGHTS => one(Int(MAX_LIGHTS as i32)),
            GL_MAX_TEXTURE_UNITS => one(Int(MAX_TEXTURE_UNITS as i32)),
            // Textures (`texture`).
            GL_MAX_TEXTURE_SIZE => one(Int(super::texture::MAX_TEXTURE_SIZE as i32)),
            GL_MAX_3D_TEXTURE_SIZE => one(Int(super::texture::MAX_3D_TEXTURE_SIZE as i32)),
            GL_MAX_CUBE_MAP_TEXTURE_SIZE => one(Int(super::texture::MAX_CUBE_MAP_TEXTURE_SIZE as i32)),
            GL_MAX_TEXTURE_LOD_BIAS => one(Float(super::texture::MAX_TEXTURE_LOD_BIAS)),
            GL_NUM_COMPRESSED_TEXTURE_FORMATS => one(Int(0)),
            // The texture coordinate sets (GL 2.0 section 2.7), as many as GLSL's
            // gl_MaxTextureCoords says (`glsl::Limits::TESSERA`); the first
            // GL_MAX_TEXTURE_UNITS have fixed-function texturing.
            GL_MAX_TEXTURE_COORDS => one(Int(MAX_TEXTURE_COORDS as i32)),
            GL_COMPRESSED_TEXTURE_FORMATS => Vec::new(),
            GL_TEXTURE_BINDING_1D | GL_TEXTURE_BINDING_2D | GL_TEXTURE_BINDING_3D | GL_TEXTURE_BINDING_CUBE_MAP => {
                let t = match pname {
                    GL_TEXTURE_BINDING_1D => 0,
                    GL_TEXTURE_BINDING_2D => 1,
                    GL_TEXTURE_BINDING_3D => 2,
                    _ => 3,
                };
                one(Int(s.texture.unit_state[s.texture.active_unit].bindings[t] as i32))
            }
            GL_SUBPIXEL_BITS => one(Int(SUBPIXEL_BITS)),
            GL_ATTRIB_STACK_DEPTH => one(Int(self.attrib_stack.len() as i32)),
            GL_CLIENT_ATTRIB_STACK_DEPTH => one(Int(self.client_attrib_stack.len() as i32)),

            // Color buffer (GL_COLOR_BUFFER_BIT).
            GL_DRAW_BUFFER => one(Enum(s.color.draw_buffers[0])),
            GL_DRAW_BUFFER0..=GL_DRAW_BUFFER7 => one(Enum(s.color.draw_buffers[(pname - GL_DRAW_BUFFER0) as usize])),
            GL_COLOR_CLEAR_VALUE => norm_floats(s.color.clear_color.map(clamped)),
            GL_INDEX_CLEAR_VALUE => one(Int(clear_index_value(s.color.clear_index))),
            GL_COLOR_WRITEMASK => bools(s.color.color_mask[0]),
            GL_INDEX_WRITEMASK => one(Int(s.color.index_mask as i32)),
            GL_ALPHA_TEST_FUNC => one(Enum(s.color.alpha_func.to_gl())),
            GL_ALPHA_TEST_REF => one(NormFloat(clamped(s.color.alpha_ref))),
            GL_BLEND_SRC | GL_BLEND_SRC_RGB => one(Enum(s.color.blend_src_rgb[0])),
            GL_BLEND_DST | GL_BLEND_DST_RGB => one(Enum(s.color.blend_dst_rgb[0])),
            GL_BLEND_SRC_ALPHA => one(Enum(s.color.blend_src_alpha[0])),
            GL_BLEND_DST_ALPHA => one(Enum(s.color.blend_dst_alpha[0])),
            // GL_BLEND_EQUATION has the same value.
            GL_BLEND_EQUATION_RGB => one(Enum(s.color.blend_equation_rgb[0])),
            GL_BLEND_EQUATION_ALPHA => one(Enum(s.color.blend_equation_alpha[0])),
            GL_BLEND_COLOR => norm_floats(s.color.blend_color.map(clamped)),
            GL_LOGIC_OP_MODE => one(Enum(s.color.logic_op)),
            GL_CLAMP_FRAGMENT_COLOR => one(Enum(s.color.clamp_fragment_color)),
            GL_CLAMP_READ_COLOR => one(Enum(s.color.clamp_read_color)),

            // Fog (GL_FOG_BIT). GL_FOG_COORD_SRC has the value of GL_FOG_COORDINATE_SOURCE.
            GL_FOG_MODE => one(Enum(s.fog.mode)),
            GL_FOG_DENSITY => one(Float(s.fog.density)),
            GL_FOG_START => one(Float(s.fog.start)),
            GL_FOG_END => one(Float(s.fog.end)),
            GL_FOG_INDEX => one(Float(s.fog.index)),
            GL_FOG_COLOR => norm_floats(s.fog.color.map(clamped)),
            GL_FOG_COORD_SRC => one(Enum(s.fog.coord_src)),
            GL_FOG_DISTANCE_MODE_NV => one(Enum(s.fog.distance_mode)),

            // Depth, stencil, accumulation buffers.
            GL_DEPTH_FUNC => one(Enum(s.depth.func.to_gl())),
            GL_DEPTH_WRITEMASK => one(Bool(s.depth.write_mask)),
            GL_DEPTH_CLEAR_VALUE => one(NormDouble(s.depth.clear)),
            GL_STENCIL_FUNC => one(Enum(face.func.to_gl())),
            GL_STENCIL_REF => one(Int(face.reference.clamp(0, stencil_max))),
            GL_STENCIL_VALUE_MASK => one(Uint(face.value_mask)),
            GL_STENCIL_FAIL => one(Enum(face.fail)),
            GL_STENCIL_PASS_DEPTH_FAIL => one(Enum(face.depth_fail)),
            GL_STENCIL_PASS_DEPTH_PASS => one(Enum(face.depth_pass)),
            GL_STENCIL_WRITEMASK => one(Uint(face.write_mask)),
            GL_STENCIL_BACK_FUNC => one(Enum(back.func.to_gl())),
            GL_STENCIL_BACK_REF => one(Int(back.reference.clamp(0, stencil_max))),
            GL_STENCIL_BACK_VALUE_MASK => one(Uint(back.value_mask)),
            GL_STENCIL_BACK_FAIL => one(Enum(back.fail)),
            GL_STENCIL_BACK_PASS_DEPTH_FAIL => one(Enum(back.depth_fail)),
            GL_STENCIL_BACK_PASS_DEPTH_PASS => one(Enum(back.depth_pass)),
            GL_STENCIL_BACK_WRITEMASK => one(Uint(back.write_mask)),
            GL_ACTIVE_STENCIL_FACE_EXT => one(Enum(if s.stencil.active_face_back { GL_BACK } else { GL_FRONT })),
            GL_STENCIL_CLEAR_VALUE => one(Int(s.stencil.clear)),
            GL_ACCUM_CLEAR_VALUE => norm_floats(s.accum.clear),

            // Viewport, scissor, transformation, lighting.
            GL_VIEWPORT => ints(s.viewport.rect),
            GL_DEPTH_RANGE => vec![NormDouble(s.viewport.depth_range[0]), NormDouble(s.viewport.depth_range[1])],
            GL_SCISSOR_BOX => ints(s.scissor.rect),
            GL_CLAMP_VERTEX_COLOR => one(Enum(s.lighting.clamp_vertex_color)),
            GL_SHADE_MODEL => one(Enum(s.lighting.shade_model)),
            GL_PROVOKING_VERTEX => one(Enum(s.lighting.provoking_vertex)),
            GL_LIGHT_MODEL_AMBIENT => norm_floats(s.lighting.model_ambient),
            GL_LIGHT_MODEL_LOCAL_VIEWER => one(Bool(s.lighting.local_viewer)),
            GL_LIGHT_MODEL_TWO_SIDE => one(Bool(s.lighting.two_side)),
            GL_LIGHT_MODEL_COLOR_CONTROL => one(Enum(s.lighting.color_control)),
            GL_COLOR_MATERIAL_FACE => one(Enum(s.lighting.color_material_face)),
            GL_COLOR_MATERIAL_PARAMETER => one(Enum(s.lighting.color_material_mode)),

            // Matrices.
            GL_MATRIX_MODE => one(Enum(s.transform.matrix_mode)),
            GL_CLIP_ORIGIN => one(Enum(s.transform.clip_origin)),
            GL_CLIP_DEPTH_MODE => one(Enum(s.transform.clip_depth_mode)),
            GL_MODELVIEW_MATRIX => matrix(StackId::Modelview),
            GL_PROJECTION_MATRIX => matrix(StackId::Projection),
            GL_TEXTURE_MATRIX => matrix(texture_stack),
            GL_COLOR_MATRIX => matrix(StackId::Color),
            GL_TRANSPOSE_MODELVIEW_MATRIX => transposed(StackId::Modelview),
            GL_TRANSPOSE_PROJECTION_MATRIX => transposed(StackId::Projection),
            GL_TRANSPOSE_TEXTURE_MATRIX => transposed(texture_stack),
            GL_TRANSPOSE_COLOR_MATRIX => transposed(StackId::Color),
            GL_MODELVIEW_STACK_DEPTH => depth(StackId::Modelview),
            GL_PROJECTION_STACK_DEPTH => depth(StackId::Projection),
            GL_TEXTURE_STACK_DEPTH => depth(texture_stack),
            GL_COLOR_MATRIX_STACK_DEPTH => depth(StackId::Color),
            GL_MAX_MODELVIEW_STACK_DEPTH => max_depth(StackId::Modelview),
            GL_MAX_PROJECTION_STACK_DEPTH => max_depth(StackId::Projection),
            GL_MAX_TEXTURE_STACK_DEPTH => max_depth(texture_stack),
            GL_MAX_COLOR_MATRIX_STACK_DEPTH => max_depth(StackId::Color),

            // Polygons, lines and points.
            GL_FRONT_FACE => one(Enum(polygon.front_face)),
            GL_CULL_FACE_MODE => one(Enum(polygon.cull_face_mode)),
            GL_POLYGON_MODE => vec![Enum(polygon.mode_front), Enum(polygon.mode_back)],
            GL_POLYGON_OFFSET_FACTOR => one(Float(polygon.offset_factor)),
            GL_POLYGON_OFFSET_UNITS => one(Float(polygon.offset_units)),
            GL_POLYGON_OFFSET_CLAMP => one(Float(polygon.offset_clamp)),
            GL_LINE_WIDTH => one(Float(lp.line_width)),
            // Also GL_SMOOTH_LINE_WIDTH_RANGE and GL_SMOOTH_LINE_WIDTH_GRANULARITY.
            GL_LINE_WIDTH_RANGE | GL_ALIASED_LINE_WIDTH_RANGE => floats(LINE_WIDTH_RANGE),
            GL_LINE_WIDTH_GRANULARITY => one(Float(LINE_WIDTH_GRANULARITY)),
            GL_LINE_STIPPLE_PATTERN => one(Int(lp.line_stipple_pattern as i32)),
            GL_LINE_STIPPLE_REPEAT => one(Int(lp.line_stipple_factor)),
            GL_POINT_SIZE => one(Float(lp.point_size)),
            // Also GL_SMOOTH_POINT_SIZE_RANGE and GL_SMOOTH_POINT_SIZE_GRANULARITY.
            GL_POINT_SIZE_RANGE | GL_ALIASED_POINT_SIZE_RANGE => floats(POINT_SIZE_RANGE),
            GL_POINT_SIZE_GRANULARITY => one(Float(POINT_SIZE_GRANULARITY)),
            GL_POINT_SIZE_MIN => one(Float(lp.point_size_min)),
            GL_POINT_SIZE_MAX => one(Float(lp.point_size_max)),
            GL_POINT_FADE_THRESHOLD_SIZE => one(Float(lp.point_fade_threshold)),
            GL_POINT_DISTANCE_ATTENUATION => floats(lp.point_distance_attenuation),
            GL_POINT_SPRITE_COORD_ORIGIN => one(Enum(lp.point_sprite_coord_origin)),

            // Hints.
            GL_PERSPECTIVE_CORRECTION_HINT => one(Enum(s.hint.perspective_correction)),
            GL_POINT_SMOOTH_HINT => one(Enum(s.hint.point_smooth)),
            GL_LINE_SMOOTH_HINT => one(Enum(s.hint.line_smooth)),
            GL_POLYGON_SMOOTH_HINT => one(Enum(s.hint.polygon_smooth)),
            GL_FOG_HINT => one(Enum(s.hint.fog)),
            GL_GENERATE_MIPMAP_HINT => one(Enum(s.hint.generate_mipmap)),
            GL_TEXTURE_COMPRESSION_HINT => one(Enum(s.hint.texture_compression)),
            GL_FRAGMENT_SHADER_DERIVATIVE_HINT => one(Enum(s.hint.fragment_shader_derivative)),

            // Texturing, pixel modes.
            GL_ACTIVE_TEXTURE => one(Enum(GL_TEXTURE0 + s.texture.active_unit as GLenum)),
            GL_READ_BUFFER => one(Enum(s.pixel_mode.read_buffer)),

            // Pixel storage (client state).
            GL_PACK_SWAP_BYTES => one(Bool(pack.swap_bytes)),
            GL_PACK_LSB_FIRST => one(Bool(pack.lsb_first)),
            GL_PACK_ROW_LENGTH => one(Int(pack.row_length)),
            GL_PACK_IMAGE_HEIGHT => one(Int(pack.image_height)),
            GL_PACK_SKIP_ROWS => one(Int(pack.skip_rows)),
            GL_PACK_SKIP_PIXELS => one(Int(pack.skip_pixels)),
            GL_PACK_SKIP_IMAGES => one(Int(pack.skip_images)),
            GL_PACK_ALIGNMENT => one(Int(pack.alignment)),
            GL_UNPACK_SWAP_BYTES => one(Bool(unpack.swap_bytes)),
            GL_UNPACK_LSB_FIRST => one(Bool(unpack.lsb_first)),
            GL_UNPACK_ROW_LENGTH => one(Int(unpack.row_length)),
            GL_UNPACK_IMAGE_HEIGHT => one(Int(unpack.image_height)),
            GL_UNPACK_SKIP_ROWS => one(Int(unpack.skip_rows)),
            GL_UNPACK_SKIP_PIXELS => one(Int(unpack.skip_pixels)),
            GL_UNPACK_SKIP_IMAGES => one(Int(unpack.skip_images)),
            GL_UNPACK_ALIGNMENT => one(Int(unpack.alignment)),
            _ => return None,
        })
    }

    /// The values of a glGet* query, with its errors: GL_INVALID_OPERATION between
    /// glBegin/glEnd, GL_INVALID_ENUM for an unknown pname.
    fn query(&mut self, pname: GLenum) -> Option<Vec<Value>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if capabilities::is_missing_unit_enable(&self.state, pname) {
            self.error(GL_INVALID_OPERATION);
            return None;
        }
        let values = self.state_values(pname);
        if values.is_none() {
            self.error(GL_INVALID_ENUM);
        }
        values
    }

    /// glGetBooleanv.
    pub fn get_booleans(&mut self, pname: GLenum) -> Option<Vec<GLboolean>> {
        Some(self.query(pname)?.into_iter().map(Value::to_boolean).collect())
    }

    /// glGetIntegerv.
    pub fn get_integers(&mut self, pname: GLenum) -> Option<Vec<GLint>> {
        Some(self.query(pname)?.into_iter().map(Value::to_integer).collect())
    }

    /// glGetFloatv.
    pub fn get_floats(&mut self, pname: GLenum) -> Option<Vec<GLfloat>> {
        Some(self.query(pname)?.into_iter().map(Value::to_float).collect())
    }

    /// glGetDoublev.
    pub fn get_doubles(&mut self, pname: GLenum) -> Option<Vec<GLdouble>> {
        Some(self.query(pname)?.into_iter().map(Value::to_double).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
    use crate::gl::CompareFunc;

    fn context(color: ColorFormat) -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        Context::new(ContextConfig { visual: FramebufferConfig::single_buffered(color, depth_stencil, 16) })
    }

    fn rgba8() -> Context {
        context(ColorFormat::Unorm8 { alpha: true })
    }

    #[test]
    fn normalized_values_map_onto_the_integer_range_by_truncation() {
        // Measured on Mesa 22: glClearColor(0.5, 0.1, -1, 2) reads back these integers.
        assert_eq!(Value::NormFloat(0.5).to_integer(), 1073741823);
        assert_eq!(Value::NormFloat(0.1).to_integer(), 214748367);
        assert_eq!(Value::NormFloat(1.0).to_integer(), 2147483647);
        assert_eq!(Value::NormFloat(-1.0).to_integer(), -2147483647);
        assert_eq!(Value::NormFloat(0.25).to_integer(), 536870911);
        assert_eq!(Value::NormFloat(-0.5).to_integer(), -1073741823);
        assert_eq!(Value::NormFloat(0.0).to_integer(), 0);
        // Out of range and NaN: saturation and 0 (Mesa 22 gives -2^31 for all three).
        assert_eq!(Value::NormFloat(2.0).to_integer(), i32::MAX);
        assert_eq!(Value::NormFloat(-3.0).to_integer(), i32::MIN);
        assert_eq!(Value::NormFloat(f32::NAN).to_integer(), 0);
        // Doubles keep their precision: 0.3 is not 0.3f.
        assert_eq!(Value::NormDouble(0.3).to_integer(), 644245094);
        assert_eq!(Value::NormDouble(0.3f32 as f64).to_integer(), 644245119);
        assert_eq!(Value::NormDouble(0.3).to_float(), 0.3f32);
        assert_eq!(Value::NormDouble(0.3).to_double(), 0.3);
        assert_eq!(Value::NormFloat(0.1).to_double(), 0.10000000149011612);
    }

    #[test]
    fn floats_round_half_away_from_zero_as_integers() {
        assert_eq!(Value::Float(2.5).to_integer(), 3);
        assert_eq!(Value::Float(-2.5).to_integer(), -3);
        assert_eq!(Value::Float(2.4999998).to_integer(), 2);
        assert_eq!(Value::Float(0.49999997).to_integer(), 0);
        assert_eq!(Value::Float(-0.4).to_integer(), 0);
        assert_eq!(Value::Float(1e10).to_integer(), i32::MAX);
        assert_eq!(Value::Float(-1e10).to_integer(), i32::MIN);
        assert_eq!(Value::Float(16384.0).to_double(), 16384.0);
    }

    #[test]
    fn booleans_and_numbers_convert_both_ways() {
        for v in [Value::Bool(true), Value::Int(-1), Value::Uint(1), Value::Enum(GL_FIXED_ONLY), Value::Float(f32::NAN)]
        {
            assert_eq!(v.to_boolean(), GL_TRUE, "{v:?}");
        }
        for v in [Value::Bool(false), Value::Int(0), Value::Uint(0), Value::Float(-0.0), Value::NormDouble(0.0)] {
            assert_eq!(v.to_boolean(), GL_FALSE, "{v:?}");
        }
        assert_eq!(Value::NormFloat(1e-30).to_boolean(), GL_TRUE);
        assert_eq!(Value::Bool(true).to_integer(), 1);
        assert_eq!(Value::Bool(true).to_float(), 1.0);
        assert_eq!(Value::Bool(false).to_double(), 0.0);
        assert_eq!(Value::Enum(GL_FIXED_ONLY).to_integer(), 35101);
        assert_eq!(Value::Enum(GL_FIXED_ONLY).to_float(), 35101.0);
        assert_eq!(Value::Int(-7).to_float(), -7.0);
        assert_eq!(Value::Int(i32::MAX).to_float(), 2147483648.0);
        assert_eq!(Value::Int(-1).to_double(), -1.0);
    }

    #[test]
    fn unsigned_values_saturate_as_integers_only() {
        // Measured on Mesa 22 after glStencilMaskSeparate(GL_BACK, 0x80000001).
        let mask = Value::Uint(0x8000_0001);
        assert_eq!(mask.to_integer(), 2147483647);
        assert_eq!(mask.to_float(), 2147483648.0);
        assert_eq!(mask.to_double(), 2147483649.0);
        assert_eq!(Value::Uint(255).to_integer(), 255);
        assert_eq!(Value::Uint(u32::MAX).to_double(), 4294967295.0);
    }

    #[test]
    fn clear_index_is_mesa_s_truncated_unsigned() {
        assert_eq!(clear_index_value(3.7), 3);
        assert_eq!(clear_index_value(-2.5), -2);
        assert_eq!(clear_index_value(5e9), 705032704);
        assert_eq!(clear_index_value(f32::NAN), 0);
        assert_eq!(clear_index_value(1e30), 0);
    }

    #[test]
    fn clear_color_is_clamped_for_fixed_point_buffers_only() {
        let mut ctx = rgba8();
        ctx.clear_color([0.5, 0.1, -1.0, 2.0]);
        assert_eq!(ctx.get_integers(GL_COLOR_CLEAR_VALUE), Some(vec![1073741823, 214748367, 0, 2147483647]));
        assert_eq!(ctx.get_floats(GL_COLOR_CLEAR_VALUE), Some(vec![0.5, 0.1, 0.0, 1.0]));
        assert_eq!(ctx.get_booleans(GL_COLOR_CLEAR_VALUE), Some(vec![GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE]));
        ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE as GLenum);
        assert_eq!(ctx.get_floats(GL_COLOR_CLEAR_VALUE), Some(vec![0.5, 0.1, -1.0, 2.0]));
        assert_eq!(ctx.get_doubles(GL_COLOR_CLEAR_VALUE), Some(vec![0.5, 0.1f32 as f64, -1.0, 2.0]));

        let mut float = context(ColorFormat::Float32 { alpha: true });
        float.clear_color([0.5, 0.1, -1.0, 2.0]);
        assert_eq!(float.get_floats(GL_COLOR_CLEAR_VALUE), Some(vec![0.5, 0.1, -1.0, 2.0]));
        float.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_TRUE as GLenum);
        assert_eq!(float.get_floats(GL_COLOR_CLEAR_VALUE), Some(vec![0.5, 0.1, 0.0, 1.0]));
        assert_eq!(float.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn blend_color_and_alpha_reference_clamp_like_the_clear_color() {
        let mut ctx = rgba8();
        ctx.state.color.blend_color = [0.5, -1.0, 2.0, 0.25];
        ctx.state.color.alpha_ref = 2.0;
        assert_eq!(ctx.get_integers(GL_BLEND_COLOR), Some(vec![1073741823, 0, 2147483647, 536870911]));
        assert_eq!(ctx.get_floats(GL_ALPHA_TEST_REF), Some(vec![1.0]));
        ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE as GLenum);
        assert_eq!(ctx.get_floats(GL_BLEND_COLOR), Some(vec![0.5, -1.0, 2.0, 0.25]));
        assert_eq!(ctx.get_doubles(GL_ALPHA_TEST_REF), Some(vec![2.0]));
    }

    #[test]
    fn stencil_queries_follow_the_active_face_and_clamp_the_reference() {
        let mut ctx = rgba8();
        ctx.state.stencil.front.func = CompareFunc::Less;
        ctx.state.stencil.front.reference = 300;
        ctx.state.stencil.back.func = CompareFunc::Equal;
        ctx.state.stencil.back.reference = -3;
        ctx.state.stencil.back.fail = GL_INCR_WRAP;
        ctx.state.stencil.ext_back = ctx.state.stencil.back;
        ctx.state.stencil.ext_back.func = CompareFunc::Greater;
        assert_eq!(ctx.get_integers(GL_STENCIL_FUNC), Some(vec![GL_LESS as i32]));
        assert_eq!(ctx.get_integers(GL_STENCIL_REF), Some(vec![255]));
        assert_eq!(ctx.get_integers(GL_STENCIL_BACK_REF), Some(vec![0]));
        assert_eq!(ctx.get_integers(GL_STENCIL_VALUE_MASK), Some(vec![i32::MAX]));
        assert_eq!(ctx.get_doubles(GL_STENCIL_WRITEMASK), Some(vec![4294967295.0]));
        assert_eq!(ctx.get_integers(GL_ACTIVE_STENCIL_FACE_EXT), Some(vec![GL_FRONT as i32]));
        ctx.state.stencil.active_face_back = true;
        assert_eq!(ctx.get_integers(GL_ACTIVE_STENCIL_FACE_EXT), Some(vec![GL_BACK as i32]));
        assert_eq!(ctx.get_integers(GL_STENCIL_FUNC), Some(vec![GL_GREATER as i32]));
        assert_eq!(ctx.get_integers(GL_STENCIL_BACK_FUNC), Some(vec![GL_EQUAL as i32]));
        assert_eq!(ctx.get_integers(GL_STENCIL_FAIL), Some(vec![GL_INCR_WRAP as i32]));
        assert_eq!(ctx.get_integers(GL_STENCIL_BACK_FAIL), Some(vec![GL_INCR_WRAP as i32]));
    }

    #[test]
    fn every_capability_reads_back_its_enable() {
        let mut ctx = rgba8();
        for &cap in capabilities::CAPABILITIES {
            let initial = matches!(cap, GL_DITHER | GL_MULTISAMPLE);
            assert_eq!(ctx.get_integers(cap), Some(vec![initial as i32]), "{cap:#x}");
            ctx.set_capability(cap, !initial);
            assert_eq!(ctx.get_booleans(cap), Some(vec![(!initial) as GLboolean]), "{cap:#x}");
        }
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn texture_queries_follow_the_active_unit() {
        let mut ctx = rgba8();
        ctx.state.texture.active_unit = 2;
        ctx.set_capability(GL_TEXTURE_2D, true);
        assert_eq!(ctx.get_integers(GL_ACTIVE_TEXTURE), Some(vec![GL_TEXTURE0 as i32 + 2]));
        assert_eq!(ctx.get_integers(GL_TEXTURE_2D), Some(vec![1]));
        ctx.state.texture.active_unit = 1;
        assert_eq!(ctx.get_integers(GL_TEXTURE_2D), Some(vec![0]));
    }

    #[test]
    fn image_units_past_the_fixed_function_units_have_bindings_only() {
        let mut ctx = rgba8();
        assert_eq!(ctx.get_integers(GL_MAX_TEXTURE_IMAGE_UNITS), Some(vec![8]));
        assert_eq!(ctx.get_integers(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS), Some(vec![8]));
        assert_eq!(ctx.get_integers(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS), Some(vec![0]));
        let names = ctx.gen_textures(2).unwrap();
        ctx.active_texture(GL_TEXTURE7);
        ctx.bind_texture(GL_TEXTURE_2D, names[0]);
        ctx.active_texture(GL_TEXTURE5);
        ctx.bind_texture(GL_TEXTURE_2D, names[1]);
        ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &[GL_NEAREST as f32], true);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_integers(GL_TEXTURE_BINDING_2D), Some(vec![names[1] as i32]));
        ctx.active_texture(GL_TEXTURE7);
        assert_eq!(ctx.get_integers(GL_TEXTURE_BINDING_2D), Some(vec![names[0] as i32]));
        // Fixed-function enables stop at GL_MAX_TEXTURE_UNITS.
        assert_eq!(ctx.is_enabled(GL_TEXTURE_2D), GL_FALSE);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.active_texture(GL_TEXTURE8);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn framebuffer_limits_and_buffers() {
        let mut ctx = context(ColorFormat::Rgb565);
        let int = |ctx: &mut Context, pname| ctx.get_integers(pname).unwrap();
        assert_eq!(int(&mut ctx, GL_RED_BITS), [5]);
        assert_eq!(int(&mut ctx, GL_GREEN_BITS), [6]);
        assert_eq!(int(&mut ctx, GL_ALPHA_BITS), [0]);
        assert_eq!(int(&mut ctx, GL_DEPTH_BITS), [24]);
        assert_eq!(int(&mut ctx, GL_STENCIL_BITS), [8]);
        assert_eq!(int(&mut ctx, GL_ACCUM_ALPHA_BITS), [16]);
        assert_eq!(int(&mut ctx, GL_MAX_VIEWPORT_DIMS), [16384, 16384]);
        assert_eq!(int(&mut ctx, GL_MAX_CLIP_PLANES), [6]);
        assert_eq!(int(&mut ctx, GL_MAX_TEXTURE_UNITS), [4]);
        assert_eq!(int(&mut ctx, GL_DRAW_BUFFER), [GL_FRONT as i32]);
        assert_eq!(int(&mut ctx, GL_DRAW_BUFFER7), [GL_NONE as i32]);
        ctx.draw_buffer(GL_FRONT_LEFT);
        assert_eq!(int(&mut ctx, GL_DRAW_BUFFER0), [GL_FRONT_LEFT as i32]);
        ctx.push_attrib(0);
        ctx.push_client_attrib(0);
        ctx.push_client_attrib(0);
        assert_eq!(int(&mut ctx, GL_ATTRIB_STACK_DEPTH), [1]);
        assert_eq!(int(&mut ctx, GL_CLIENT_ATTRIB_STACK_DEPTH), [2]);
        ctx.pixel_store.unpack.alignment = 2;
        ctx.pixel_store.pack.swap_bytes = true;
        assert_eq!(int(&mut ctx, GL_UNPACK_ALIGNMENT), [2]);
        assert_eq!(int(&mut ctx, GL_PACK_ALIGNMENT), [4]);
        assert_eq!(ctx.get_booleans(GL_PACK_SWAP_BYTES), Some(vec![GL_TRUE]));
        ctx.viewport(1, 2, 3, 4);
        ctx.depth_range(0.1, 0.7);
        assert_eq!(ctx.get_doubles(GL_VIEWPORT), Some(vec![1.0, 2.0, 3.0, 4.0]));
        assert_eq!(ctx.get_doubles(GL_DEPTH_RANGE), Some(vec![0.1, 0.7]));
        assert_eq!(int(&mut ctx, GL_DEPTH_RANGE), [214748364, 1503238552]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn unknown_pnames_are_invalid_enum_and_return_nothing() {
        let mut ctx = rgba8();
        for pname in [0, GL_RGBA, 0xdead, GL_DRAW_BUFFER8, GL_MAJOR_VERSION, GL_TEXTURE_2D + 1] {
            assert_eq!(ctx.get_booleans(pname), None);
            assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
            assert_eq!(ctx.get_doubles(pname), None);
            assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        }
    }

    #[test]
    fn queries_between_begin_and_end_are_invalid_operation() {
        let mut ctx = rgba8();
        ctx.inside_begin_end = true;
        assert_eq!(ctx.get_integers(GL_DEPTH_FUNC), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_floats(0xdead), None);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
    }
}
