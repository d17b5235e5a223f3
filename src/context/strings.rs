//! glGetString: vendor, renderer, version and the extension list.
//!
//! The version is the highest GL version whose every required feature works, and the
//! extension list names only what works; both grow as the pipeline does. The strings are
//! static so the pointers handed to C stay valid for the life of the process.
use super::Context;
use crate::api::enums::*;
use crate::api::types::GLenum;

pub const VENDOR: &str = "tessera project\0";
pub const RENDERER: &str = concat!("tessera ", env!("CARGO_PKG_VERSION"), " (software rasterizer)\0");
/// GL_VERSION: 1.1 names the level the state machine targets until the rasterizer and
/// the rest of GL 1.x land (see the issues); it is never above what works.
pub const VERSION: &str = concat!("1.1 tessera ", env!("CARGO_PKG_VERSION"), "\0");
/// Extensions whose every entry point and enum works, each checked against the code (and
/// by the piglit tests named in tests/piglit/expected.txt). Left out although close:
/// GL_ARB_depth_clamp (piglit depth_clamp and depth-clamp-range fail: depth is not clamped
/// to the depth range), GL_EXT_draw_buffers2 (glGetBooleanIndexedvEXT/glGetIntegerIndexedvEXT do not exist),
/// GL_EXT_polygon_offset_clamp (the clamp is stored but the rasterizer does not apply it),
/// GL_EXT_packed_pixels/GL_EXT_bgra (glReadPixels accepts them, but glDrawPixels and
/// textures do not exist yet), GL_ARB_multitexture (no texturing yet).
pub const EXTENSIONS: &[&str] = &[
    "GL_ARB_draw_buffers",
    "GL_ARB_draw_buffers_blend",
    "GL_ARB_framebuffer_object",
    "GL_ARB_point_parameters",
    "GL_ARB_transpose_matrix",
    "GL_ARB_vertex_buffer_object",
    "GL_ATI_separate_stencil",
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
    "GL_EXT_point_parameters",
    "GL_EXT_provoking_vertex",
    "GL_EXT_secondary_color",
    "GL_EXT_stencil_two_side",
    "GL_EXT_stencil_wrap",
    "GL_EXT_vertex_array",
    "GL_NV_blend_square",
    "GL_NV_fog_distance",
];

/// Whether a context of GL version `major.minor` (compatibility profile) can be created.
pub fn supports_version(major: i32, minor: i32) -> bool {
    (major, minor) <= (1, 1) && major >= 1 && minor >= 0
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
            GL_EXTENSIONS => Some(extensions_string()),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }
}
