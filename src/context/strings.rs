//! glGetString: vendor, renderer, version and the extension list.
//!
//! The version is the highest GL version whose every required feature works, and the
//! extension list names only what works; both grow as the pipeline does. The strings are
//! static so the pointers handed to C stay valid for the life of the process.
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;

pub const VENDOR: &str = "tessera project\0";
pub const RENDERER: &str = concat!("tessera ", env!("CARGO_PKG_VERSION"), " (software rasterizer)\0");
/// GL_VERSION: 2.1, the highest version whose every feature works (the audit below).
/// Fixed-function texturing has 4 units (GL_MAX_TEXTURE_UNITS) beside the 8 texture
/// coordinate sets shaders see (GL_MAX_TEXTURE_COORDS, gl_MaxTextureCoords) and the 8
/// texture image units fragment shaders sample (GL_MAX_TEXTURE_IMAGE_UNITS), as GL 2.0
/// sections 2.7 and 3.11.2 allow.
pub const VERSION: &str = concat!("2.1 tessera ", env!("CARGO_PKG_VERSION"), "\0");

/// GL_SHADING_LANGUAGE_VERSION: GLSL 1.20, GL 2.1's (1.10 shaders too, by `#version`).
pub const SHADING_LANGUAGE_VERSION: &str = "1.20\0";

// The version audit: each feature of the GL 1.2–2.1 core feature lists (GL 2.1 spec,
// appendices C–H) checked against the code and its tests. GL 1.0/1.1 are complete now that
// evaluators and smoothing exist.
//
// | Version | Feature                                          | Status | Where / checked by |
// |---------|--------------------------------------------------|--------|--------------------|
// | 1.2     | 3D textures (glTexImage3D, wrap R)               | works  | context/texture.rs; capi texture_formats, texture_sampling |
// | 1.2     | BGRA and packed pixel formats                    | works  | pixel/; capi readpixels_pack, texture_formats, pixel_rects |
// | 1.2     | GL_RESCALE_NORMAL                                | works  | vertex/lighting.rs; capi lighting_* |
// | 1.2     | Separate specular color                          | works  | capi lighting_render |
// | 1.2     | Texture LOD (MIN/MAX_LOD, BASE/MAX_LEVEL)        | works  | texture/sampler.rs; capi texture_sampling |
// | 1.2     | GL_CLAMP_TO_EDGE                                 | works  | texture/sampler.rs |
// | 1.2     | glDrawRangeElements                              | works  | capi draw_arrays |
// | 1.2     | Imaging subset                                   | optional, absent (no GL_ARB_imaging) | |
// | 1.3     | Compressed texture entry points                  | works, no formats (GL_NUM_COMPRESSED_TEXTURE_FORMATS = 0) | api/gl_texture.rs |
// | 1.3     | Cube map textures                                | works  | capi texture_texgen_shadow |
// | 1.3     | Multisample state (GL_MULTISAMPLE, SAMPLE_*)     | works (2/4/8 samples: multisampled GLX configs and renderbuffers) | context/multisample.rs; capi msaa_resolve, glx multisample.c |
// | 1.3     | Multitexture (4 units; 8 coordinate sets, GL 2.0) | works  | capi texture_env, texture_coord_sets |
// | 1.3     | Env modes ADD, COMBINE, DOT3                     | works  | texture/env.rs; capi texture_env, piglit gl-1.3-texture-env |
// | 1.3     | GL_CLAMP_TO_BORDER                               | works  | texture/sampler.rs |
// | 1.3     | Transpose matrices                               | works  | capi transform_matrices |
// | 1.4     | Automatic mipmaps (GL_GENERATE_MIPMAP)           | works  | context/texture.rs |
// | 1.4     | Blend squaring (NV_blend_square)                 | works  | piglit blendsquare |
// | 1.4     | Depth textures and shadows (compare mode)        | works  | capi texture_texgen_shadow |
// | 1.4     | Fog coordinate                                   | works  | piglit ext_fog_coord-modes |
// | 1.4     | glMultiDrawArrays/Elements                       | works  | capi draw_arrays |
// | 1.4     | Point parameters (size min/max, attenuation)     | works  | vertex/point.rs; capi point_attenuation (fade threshold: multisample only) |
// | 1.4     | Secondary color                                  | works  | capi lighting_*, fragment_ops_fog |
// | 1.4     | glBlendFuncSeparate                              | works  | capi fragment_ops_blend |
// | 1.4     | Stencil wrap                                     | works  | piglit stencil-wrap |
// | 1.4     | Texture env crossbar                             | works  | capi texture_env |
// | 1.4     | Texture LOD bias                                 | works  | texture/sampler.rs |
// | 1.4     | GL_MIRRORED_REPEAT                               | works  | texture/sampler.rs |
// | 1.4     | glWindowPos                                      | works  | capi pixel_rects |
// | 1.5     | Buffer objects                                   | works  | capi vertex_buffers |
// | 1.5     | Occlusion queries                                | works  | capi occlusion_queries |
// | 1.5     | Shadow functions (all 8 compare funcs)           | works  | context/texture.rs |
// | 2.0     | GLSL 1.10: shader and program objects, compile, link, validate, deferred deletion, info logs | works | context/shader_objects.rs, glsl/; capi shader_objects, glsl_*; piglit GLSL 1.10 (tests/piglit/glsl-expected.txt) |
// | 2.0     | Uniforms and their reflection, generic attributes (attribute 0 aliases glVertex) | works | context/shader_objects.rs, vertex_input/; capi shader_uniforms, vertex_attributes, glsl_draw_validation |
// | 2.0     | Multiple render targets (glDrawBuffers, gl_FragData) | works | capi glsl_fragment_lookups; piglit arb_draw_buffers (gl2x-expected.txt) |
// | 2.0     | Non-power-of-two textures                        | works  | see GL_ARB_texture_non_power_of_two below |
// | 2.0     | Point sprites                                    | works  | see GL_ARB_point_sprite below |
// | 2.0     | Separate stencil (glStencil*Separate)            | works  | capi fragment_ops_alpha_stencil |
// | 2.0     | glBlendEquationSeparate                          | works  | capi fragment_ops_blend |
// | 2.0     | Two-sided colour and point size from vertex shaders (GL_VERTEX_PROGRAM_TWO_SIDE, _POINT_SIZE) | works | capi glsl_vertex |
// | 2.0     | Texture coordinate sets (GL_MAX_TEXTURE_COORDS 8, the shaders' gl_MaxTextureCoords) beside 4 fixed-function units | works | capi texture_coord_sets |
// | 2.0     | Texture image units for fragment shaders (GL_MAX_TEXTURE_IMAGE_UNITS 8, combined 8; none for vertex shaders) | works | capi glsl_eight_samplers; piglit gl-2.0-texture-units |
// | 2.1     | GLSL 1.20 (arrays, implicit conversions, non-square matrices, invariant, centroid) | works | glsl/; piglit GLSL 1.20 |
// | 2.1     | Non-square uniform matrices (glUniformMatrix2x3fv ...) | works | capi shader_uniforms |
// | 2.1     | Pixel buffer objects                             | works  | see GL_ARB_pixel_buffer_object below |
// | 2.1     | sRGB textures                                    | works  | see GL_EXT_texture_sRGB below |
//
// Beyond GL 1.5, extensions checked the same way:
//
// | Extension            | Feature                                      | Status | Where / checked by |
// |----------------------|----------------------------------------------|--------|--------------------|
// | GL_ARB_clip_control  | glClipControl, GL_CLIP_ORIGIN/DEPTH_MODE queries, GL_TRANSFORM_BIT | works | context/transform.rs; capi clip_control |
// |                      | GL_ZERO_TO_ONE clipping and depth mapping (draws, glRasterPos) | works | vertex/clip.rs, context/draw.rs, raster_pos.rs; capi clip_control (reversed-Z scene) |
// |                      | GL_UPPER_LEFT: y mirrored, facing mirrored    | works | context/draw.rs; capi clip_control (culling) |
// | GL_ARB_depth_buffer_float | GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8 renderbuffers (float depth, clamped to [0, 1]) | works | framebuffer/format.rs DepthEncoding; capi depth_buffer_float |
// |                      | the same as depth textures (sampling, compare, glGetTexImage, glCopyTexImage, render to texture) | works | context/texture.rs; capi depth_buffer_float |
// |                      | glReadPixels/glDrawPixels/glTexImage of depth as GL_FLOAT (exact), clears, GL_DEPTH_BITS 32, component type GL_FLOAT | works | pixel/depth.rs; capi depth_buffer_float |
// |                      | polygon offset r = 2^(e − 23) of the largest depth | works | context/draw.rs float_depth_resolution; capi depth_buffer_float |
// |                      | glBlitFramebuffer float ↔ fixed depth: GL_INVALID_OPERATION (formats differ, as Mesa) | works | capi depth_buffer_float |
// |                      | GL_FLOAT_32_UNSIGNED_INT_24_8_REV pixel type  | see below | |
// | GL_ARB_point_sprite (GL 2.0) | GL_POINT_SPRITE: squares of the unrounded size whatever GL_POINT_SMOOTH says, GL_COORD_REPLACE per unit (s, t across the square, r = 0, q = 1), GL_POINT_SPRITE_COORD_ORIGIN; llvmpipe's coordinate planes | works | setup/jobs/point.rs Sprite; capi point_sprites |
// | GL_EXT_texture_sRGB (GL 2.1) | GL_SRGB*, GL_SLUMINANCE*, the generic GL_COMPRESSED_S* (stored uncompressed); texels decoded with llvmpipe's curve before filtering, fixed function and GLSL; glGetTexImage of the stored values; colour attachments (writes not encoded) | works | texture/mod.rs srgb_to_linear, texture/sampler.rs; capi texture_srgb |
// | GL_ARB_pixel_buffer_object | pack and unpack buffer targets (GL 2.1): glReadPixels, glGetTexImage, glGetPolygonStipple, glGetPixelMap into a buffer; glTexImage*, glTexSubImage*, glDrawPixels, glBitmap, glPolygonStipple, glPixelMap from one (also while compiling a list); range, alignment and mapping errors | works | context/pixel_buffers.rs; capi pixel_buffer_objects |
// | GL_ARB_texture_non_power_of_two (GL 2.0) | any size for 1D, 2D, 3D and cube map textures (and their borders): every wrap mode, filter and mipmap chain (⌊size / 2^level⌋, down to 1), glGenerateMipmap and GL_GENERATE_MIPMAP, render to texture | works | texture/sampler.rs; capi texture_sampling (npot_1d_3d_cube); piglit texwrap … npot, tex-npot, tex3d-npot, fbo-npot |
//
// Outside these lists but needed by every version: GL 1.0's evaluators (capi evaluators),
// polygon/line/point smoothing (capi smooth_primitives), and color-index pixel data in RGBA
// mode (glTexImage of GL_COLOR_INDEX, capi texture_color_index; glDrawPixels of
// GL_COLOR_INDEX, capi pixel_color_index).

/// Extensions whose every entry point and enum works, each checked against the code (and
/// by the piglit tests named in tests/piglit/expected.txt). Left out although close:
/// GL_EXT_draw_buffers2 (glGetBooleanIndexedvEXT/glGetIntegerIndexedvEXT do not exist),
/// GL_MESA_window_pos
/// (glWindowPos4*MESA do not exist), GL_EXT_texture_object and GL_EXT_copy_texture (their
/// EXT entry points do not exist), GL_EXT_texture_env_dot3 (its enums differ from the ARB
/// ones tessera implements), GL_EXT_abgr (GL_ABGR_EXT is not a pixel format here).
pub const EXTENSIONS: &[&str] = &[
    "GL_ARB_clip_control",
    "GL_ARB_depth_buffer_float",
    "GL_ARB_depth_clamp",
    "GL_ARB_depth_texture",
    "GL_ARB_draw_buffers",
    "GL_ARB_draw_buffers_blend",
    "GL_ARB_multisample",
    "GL_ARB_multitexture",
    "GL_ARB_occlusion_query",
    "GL_ARB_framebuffer_object",
    "GL_ARB_pixel_buffer_object",
    "GL_ARB_point_parameters",
    "GL_ARB_point_sprite",
    "GL_ARB_shadow",
    "GL_ARB_texture_border_clamp",
    "GL_ARB_texture_compression",
    "GL_ARB_texture_cube_map",
    "GL_ARB_texture_env_add",
    "GL_ARB_texture_env_combine",
    "GL_ARB_texture_env_crossbar",
    "GL_ARB_texture_env_dot3",
    "GL_ARB_texture_mirrored_repeat",
    "GL_ARB_texture_non_power_of_two",
    "GL_ARB_transpose_matrix",
    "GL_ARB_vertex_buffer_object",
    "GL_ARB_window_pos",
    "GL_ATI_separate_stencil",
    "GL_EXT_bgra",
    "GL_EXT_blend_color",
    "GL_EXT_blend_equation_separate",
    "GL_EXT_blend_func_separate",
    "GL_EXT_blend_logic_op",
    "GL_EXT_blend_minmax",
    "GL_EXT_blend_subtract",
    "GL_EXT_draw_range_elements",
    "GL_EXT_framebuffer_blit",
    "GL_EXT_framebuffer_object",
    "GL_EXT_fog_coord",
    "GL_EXT_multi_draw_arrays",
    "GL_EXT_packed_depth_stencil",
    "GL_EXT_packed_pixels",
    "GL_EXT_pixel_buffer_object",
    "GL_EXT_point_parameters",
    "GL_EXT_polygon_offset_clamp",
    "GL_EXT_provoking_vertex",
    "GL_EXT_rescale_normal",
    "GL_EXT_secondary_color",
    "GL_EXT_separate_specular_color",
    "GL_EXT_shadow_funcs",
    "GL_EXT_stencil_two_side",
    "GL_EXT_stencil_wrap",
    "GL_EXT_texture3D",
    "GL_EXT_texture_edge_clamp",
    "GL_EXT_texture_env_add",
    "GL_EXT_texture_env_combine",
    "GL_EXT_texture_lod_bias",
    "GL_EXT_texture_sRGB",
    "GL_EXT_vertex_array",
    "GL_NV_blend_square",
    "GL_NV_fog_distance",
    "GL_SGIS_generate_mipmap",
    "GL_SGIS_texture_edge_clamp",
    "GL_SGIS_texture_lod",
];

/// The GL version tessera provides, `(major, minor)`: the leading number of [`VERSION`], so
/// that the string, the context-creation checks and the refusal notices cannot disagree.
pub const PROVIDED_VERSION: (i32, i32) = {
    let b = VERSION.as_bytes();
    let (mut i, mut major, mut minor) = (0, 0, 0);
    while b[i].is_ascii_digit() {
        major = major * 10 + (b[i] - b'0') as i32;
        i += 1;
    }
    i += 1; // the '.'
    while b[i].is_ascii_digit() {
        minor = minor * 10 + (b[i] - b'0') as i32;
        i += 1;
    }
    (major, minor)
};

/// Whether a context of GL version `major.minor` (compatibility profile) can be created.
pub fn supports_version(major: i32, minor: i32) -> bool {
    (major, minor) <= PROVIDED_VERSION && major >= 1 && minor >= 0
}

/// What tessera provides, for messages: e.g. "OpenGL 2.1 (compatibility)".
pub fn provided_description() -> String {
    let (major, minor) = PROVIDED_VERSION;
    format!("OpenGL {major}.{minor} (compatibility)")
}

fn extensions_string() -> &'static str {
    static JOINED: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    JOINED.get_or_init(|| {
        let mut s = EXTENSIONS.join(" ");
        s.push('\0');
        s
    })
}

impl Context {
    /// glGetString: a NUL-terminated static string, or `None` (GL_INVALID_ENUM).
    pub fn get_string(&mut self, name: GLenum) -> Option<&'static str> {
        if !self.check_outside_begin_end() {
            return None;
        }
        match name {
            GL_VENDOR => Some(VENDOR),
            GL_RENDERER => Some(RENDERER),
            GL_VERSION => Some(VERSION),
            GL_SHADING_LANGUAGE_VERSION => Some(SHADING_LANGUAGE_VERSION),
            GL_EXTENSIONS => Some(extensions_string()),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn provided_version_is_the_version_string_number() {
        let (major, minor) = PROVIDED_VERSION;
        assert!(VERSION.starts_with(&format!("{major}.{minor} ")));
        assert!(supports_version(major, minor) && supports_version(1, 0));
        assert!(!supports_version(major, minor + 1) && !supports_version(major + 1, 0));
        assert!(!supports_version(0, 9) && !supports_version(1, -1));
        assert_eq!(provided_description(), format!("OpenGL {major}.{minor} (compatibility)"));
    }
}
