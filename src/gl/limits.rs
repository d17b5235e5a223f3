//! The implementation limits GL reports through glGet (`GL_MAX_*`), shared by every room.

/// The most draw buffers a fragment can be written to at once (GL_MAX_DRAW_BUFFERS).
pub const MAX_DRAW_BUFFERS: usize = 8;
/// Depth of the attribute stacks (GL_MAX_ATTRIB_STACK_DEPTH and the client one).
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;
/// User clip planes (GL_MAX_CLIP_PLANES).
pub const MAX_CLIP_PLANES: usize = 6;
/// Fixed-function lights (GL_MAX_LIGHTS).
pub const MAX_LIGHTS: usize = 8;
/// Texture units with fixed-function state (GL_MAX_TEXTURE_UNITS).
pub const MAX_TEXTURE_UNITS: usize = 4;
/// Texture coordinate sets (GL_MAX_TEXTURE_COORDS, GL 2.0 section 2.7): current values,
/// arrays, texture matrices and texgen state exist for these; the first
/// [`MAX_TEXTURE_UNITS`] also have fixed-function texturing.
pub const MAX_TEXTURE_COORDS: usize = 8;
/// Texture image units a fragment shader's samplers may name (GL_MAX_TEXTURE_IMAGE_UNITS,
/// and GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS: vertex shaders have none). Each has texture
/// bindings and the parameters of its textures; the first [`MAX_TEXTURE_UNITS`] also have
/// fixed-function texturing (enables, environment).
pub const MAX_TEXTURE_IMAGE_UNITS: usize = 8;
/// The units glActiveTexture selects: the larger of [`MAX_TEXTURE_COORDS`] and
/// [`MAX_TEXTURE_IMAGE_UNITS`] (GL 2.0 section 2.7). The per-unit state (texture bindings,
/// coordinate state, texture matrices) is kept for each of them.
pub const MAX_ACTIVE_TEXTURE_UNITS: usize =
    if MAX_TEXTURE_COORDS > MAX_TEXTURE_IMAGE_UNITS { MAX_TEXTURE_COORDS } else { MAX_TEXTURE_IMAGE_UNITS };
// The per-unit state arrays are sized by MAX_TEXTURE_COORDS: every image unit must be a
// coordinate set too.
const _: () = assert!(MAX_TEXTURE_IMAGE_UNITS <= MAX_TEXTURE_COORDS);
/// GL_MAX_VERTEX_ATTRIBS: generic vertex attributes (GL 2.0), as Mesa's 16.
pub const MAX_VERTEX_ATTRIBS: usize = 16;
/// Largest point size and line width (GL_POINT_SIZE_RANGE / GL_LINE_WIDTH_RANGE maximum).
pub const MAX_POINT_SIZE: f32 = 255.0;
pub const MAX_LINE_WIDTH: f32 = 255.0;
/// Depths of the matrix stacks (GL_MAX_MODELVIEW/PROJECTION/TEXTURE_STACK_DEPTH; GL
/// requires at least 32, 2 and 2).
pub const MAX_MODELVIEW_STACK_DEPTH: usize = 32;
pub const MAX_PROJECTION_STACK_DEPTH: usize = 32;
pub const MAX_TEXTURE_STACK_DEPTH: usize = 10;
pub const MAX_COLOR_STACK_DEPTH: usize = 10;
/// Largest viewport and renderbuffer side (GL_MAX_VIEWPORT_DIMS, OSMESA_MAX_WIDTH).
pub const MAX_VIEWPORT_DIM: i32 = 16384;
