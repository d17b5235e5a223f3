//! The typed GL state, grouped as glPushAttrib groups it.
//!
//! Each struct is one attribute group (or the part of it that exists so far), so that
//! glPushAttrib saves a group by cloning its struct. Defaults are the GL 2.1 initial values.
//! Enums are stored as the `GLenum` the API received only after validation; where the value
//! set is small and closed, a Rust enum is used instead.
use crate::gl::enums::*;
use crate::gl::limits::*;
use crate::gl::types::GLenum;
use crate::gl::CompareFunc;
/// The lighting state lives with the lighting it parameterises; the context stores it.
pub use crate::vertex::lighting::{Light, LightingState, Material};

/// GL_COLOR_BUFFER_BIT: alpha test, blending, dithering, logic op, draw buffers, clear color
/// and color masks.
#[derive(Clone, Debug, PartialEq)]
pub struct ColorBufferState {
    pub alpha_test: bool,
    pub alpha_func: CompareFunc,
    pub alpha_ref: f32,
    /// GL_BLEND per draw buffer (glEnablei); glEnable sets all.
    pub blend: [bool; MAX_DRAW_BUFFERS],
    pub blend_src_rgb: [GLenum; MAX_DRAW_BUFFERS],
    pub blend_dst_rgb: [GLenum; MAX_DRAW_BUFFERS],
    pub blend_src_alpha: [GLenum; MAX_DRAW_BUFFERS],
    pub blend_dst_alpha: [GLenum; MAX_DRAW_BUFFERS],
    pub blend_equation_rgb: [GLenum; MAX_DRAW_BUFFERS],
    pub blend_equation_alpha: [GLenum; MAX_DRAW_BUFFERS],
    pub blend_color: [f32; 4],
    pub dither: bool,
    pub color_logic_op: bool,
    pub index_logic_op: bool,
    pub logic_op: GLenum,
    /// The draw buffer of each fragment output (GL_DRAW_BUFFERi), GL_NONE when unused.
    pub draw_buffers: [GLenum; MAX_DRAW_BUFFERS],
    pub clear_color: [f32; 4],
    pub clear_index: f32,
    pub index_mask: u32,
    pub color_mask: [[bool; 4]; MAX_DRAW_BUFFERS],
    pub clamp_fragment_color: GLenum,
    pub clamp_read_color: GLenum,
}

impl ColorBufferState {
    /// Initial state for a framebuffer whose default draw buffer is `draw_buffer`.
    pub fn new(draw_buffer: GLenum) -> Self {
        let mut draw_buffers = [GL_NONE; MAX_DRAW_BUFFERS];
        draw_buffers[0] = draw_buffer;
        ColorBufferState {
            alpha_test: false,
            alpha_func: CompareFunc::Always,
            alpha_ref: 0.0,
            blend: [false; MAX_DRAW_BUFFERS],
            blend_src_rgb: [GL_ONE; MAX_DRAW_BUFFERS],
            blend_dst_rgb: [GL_ZERO; MAX_DRAW_BUFFERS],
            blend_src_alpha: [GL_ONE; MAX_DRAW_BUFFERS],
            blend_dst_alpha: [GL_ZERO; MAX_DRAW_BUFFERS],
            blend_equation_rgb: [GL_FUNC_ADD; MAX_DRAW_BUFFERS],
            blend_equation_alpha: [GL_FUNC_ADD; MAX_DRAW_BUFFERS],
            blend_color: [0.0; 4],
            dither: true,
            color_logic_op: false,
            index_logic_op: false,
            logic_op: GL_COPY,
            draw_buffers,
            clear_color: [0.0; 4],
            clear_index: 0.0,
            index_mask: !0,
            color_mask: [[true; 4]; MAX_DRAW_BUFFERS],
            clamp_fragment_color: GL_FIXED_ONLY,
            clamp_read_color: GL_FIXED_ONLY,
        }
    }
}

/// GL_DEPTH_BUFFER_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthState {
    pub test: bool,
    pub func: CompareFunc,
    pub write_mask: bool,
    pub clear: f64,
}

impl Default for DepthState {
    fn default() -> Self {
        DepthState { test: false, func: CompareFunc::Less, write_mask: true, clear: 1.0 }
    }
}

/// One face's stencil state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StencilFace {
    pub func: CompareFunc,
    pub reference: i32,
    pub value_mask: u32,
    pub fail: GLenum,
    pub depth_fail: GLenum,
    pub depth_pass: GLenum,
    pub write_mask: u32,
}

impl Default for StencilFace {
    fn default() -> Self {
        StencilFace {
            func: CompareFunc::Always,
            reference: 0,
            value_mask: !0,
            fail: GL_KEEP,
            depth_fail: GL_KEEP,
            depth_pass: GL_KEEP,
            write_mask: !0,
        }
    }
}

/// GL_STENCIL_BUFFER_BIT.
///
/// As in Mesa, there are three faces: `front`, `back` (what glStencil*Separate(GL_BACK) and
/// GL_STENCIL_BACK_* address) and `ext_back`, the back face of EXT_stencil_two_side, which
/// the non-separate calls set while GL_ACTIVE_STENCIL_FACE_EXT is GL_BACK and which back
/// faces use while GL_STENCIL_TEST_TWO_SIDE_EXT is enabled.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct StencilState {
    pub test: bool,
    /// GL_STENCIL_TEST_TWO_SIDE_EXT.
    pub two_side: bool,
    /// GL_ACTIVE_STENCIL_FACE_EXT is GL_BACK (true) or GL_FRONT (false).
    pub active_face_back: bool,
    pub front: StencilFace,
    pub back: StencilFace,
    pub ext_back: StencilFace,
    pub clear: i32,
}

impl StencilState {
    /// The face that back-facing primitives are tested against.
    pub fn back_face_in_use(&self) -> &StencilFace {
        if self.two_side {
            &self.ext_back
        } else {
            &self.back
        }
    }

    /// The face GL_STENCIL_FUNC & co. report: the EXT back face when it is active.
    pub fn active_face(&self) -> &StencilFace {
        if self.active_face_back {
            &self.ext_back
        } else {
            &self.front
        }
    }
}

/// GL_SCISSOR_BIT.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ScissorState {
    pub test: bool,
    /// x, y, width, height.
    pub rect: [i32; 4],
}

impl ScissorState {
    /// `bounds` cut by the scissor box when the scissor test is on: the rectangle clears,
    /// accumulation operations, blits and fragments are confined to.
    pub fn clip(&self, bounds: crate::framebuffer::Rect) -> crate::framebuffer::Rect {
        if self.test {
            let [x, y, w, h] = self.rect;
            bounds.intersect(crate::framebuffer::Rect::from_xywh(x, y, w, h))
        } else {
            bounds
        }
    }
}

/// GL_VIEWPORT_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewportState {
    /// x, y, width, height.
    pub rect: [i32; 4],
    pub depth_range: [f64; 2],
}

impl Default for ViewportState {
    fn default() -> Self {
        ViewportState { rect: [0; 4], depth_range: [0.0, 1.0] }
    }
}

/// GL_ACCUM_BUFFER_BIT.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct AccumState {
    pub clear: [f32; 4],
}

/// GL_HINT_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct HintState {
    pub perspective_correction: GLenum,
    pub point_smooth: GLenum,
    pub line_smooth: GLenum,
    pub polygon_smooth: GLenum,
    pub fog: GLenum,
    pub generate_mipmap: GLenum,
    pub texture_compression: GLenum,
    pub fragment_shader_derivative: GLenum,
}

impl Default for HintState {
    fn default() -> Self {
        HintState {
            perspective_correction: GL_DONT_CARE,
            point_smooth: GL_DONT_CARE,
            line_smooth: GL_DONT_CARE,
            polygon_smooth: GL_DONT_CARE,
            fog: GL_DONT_CARE,
            generate_mipmap: GL_DONT_CARE,
            texture_compression: GL_DONT_CARE,
            fragment_shader_derivative: GL_DONT_CARE,
        }
    }
}

/// GL_FOG_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct FogState {
    pub enabled: bool,
    pub color_sum: bool,
    /// GL_FOG_MODE: GL_LINEAR, GL_EXP or GL_EXP2.
    pub mode: GLenum,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub index: f32,
    /// GL_FOG_COLOR as given; clamped where fragment colors are (see `get.rs`).
    pub color: [f32; 4],
    /// GL_FOG_COORD_SRC: GL_FOG_COORD or GL_FRAGMENT_DEPTH.
    pub coord_src: GLenum,
    /// GL_FOG_DISTANCE_MODE_NV: GL_EYE_RADIAL_NV, GL_EYE_PLANE or GL_EYE_PLANE_ABSOLUTE_NV.
    pub distance_mode: GLenum,
}

impl Default for FogState {
    fn default() -> Self {
        FogState {
            enabled: false,
            color_sum: false,
            mode: GL_EXP,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            index: 0.0,
            color: [0.0; 4],
            coord_src: GL_FRAGMENT_DEPTH,
            distance_mode: GL_EYE_PLANE_ABSOLUTE_NV,
        }
    }
}

/// GL_TRANSFORM_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct TransformState {
    pub clip_planes: [bool; MAX_CLIP_PLANES],
    /// glClipPlane equations, in eye coordinates (transformed by the inverse modelview
    /// at specification).
    pub clip_plane_equations: [[f64; 4]; MAX_CLIP_PLANES],
    pub normalize: bool,
    pub rescale_normal: bool,
    pub depth_clamp: bool,
    /// glClipControl (ARB_clip_control): GL_LOWER_LEFT or GL_UPPER_LEFT, and
    /// GL_NEGATIVE_ONE_TO_ONE or GL_ZERO_TO_ONE.
    pub clip_origin: GLenum,
    pub clip_depth_mode: GLenum,
    /// glMatrixMode: GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE or GL_COLOR.
    pub matrix_mode: GLenum,
}

impl Default for TransformState {
    fn default() -> Self {
        TransformState {
            clip_planes: [false; MAX_CLIP_PLANES],
            clip_plane_equations: [[0.0; 4]; MAX_CLIP_PLANES],
            normalize: false,
            rescale_normal: false,
            depth_clamp: false,
            clip_origin: GL_LOWER_LEFT,
            clip_depth_mode: GL_NEGATIVE_ONE_TO_ONE,
            matrix_mode: GL_MODELVIEW,
        }
    }
}

/// GL_POLYGON_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonState {
    pub cull_face: bool,
    pub smooth: bool,
    pub stipple: bool,
    pub offset_fill: bool,
    pub offset_line: bool,
    pub offset_point: bool,
    /// glCullFace: GL_FRONT, GL_BACK or GL_FRONT_AND_BACK.
    pub cull_face_mode: GLenum,
    /// glFrontFace: GL_CCW or GL_CW.
    pub front_face: GLenum,
    /// glPolygonMode of front and back faces: GL_POINT, GL_LINE or GL_FILL.
    pub mode_front: GLenum,
    pub mode_back: GLenum,
    /// glPolygonOffset (and GL_POLYGON_OFFSET_CLAMP, 0 = no clamp).
    pub offset_factor: f32,
    pub offset_units: f32,
    pub offset_clamp: f32,
}

impl Default for PolygonState {
    fn default() -> Self {
        PolygonState {
            cull_face: false,
            smooth: false,
            stipple: false,
            offset_fill: false,
            offset_line: false,
            offset_point: false,
            cull_face_mode: GL_BACK,
            front_face: GL_CCW,
            mode_front: GL_FILL,
            mode_back: GL_FILL,
            offset_factor: 0.0,
            offset_units: 0.0,
            offset_clamp: 0.0,
        }
    }
}

/// GL_LINE_BIT and GL_POINT_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct LinePointState {
    pub line_smooth: bool,
    pub line_stipple: bool,
    pub point_smooth: bool,
    pub point_sprite: bool,
    pub vertex_program_point_size: bool,
    pub vertex_program_two_side: bool,
    /// glLineWidth.
    pub line_width: f32,
    /// glLineStipple: repeat factor (clamped to [1, 256]) and pattern.
    pub line_stipple_factor: i32,
    pub line_stipple_pattern: u16,
    /// glPointSize.
    pub point_size: f32,
    /// glPointParameter: GL_POINT_SIZE_MIN/MAX, GL_POINT_FADE_THRESHOLD_SIZE,
    /// GL_POINT_DISTANCE_ATTENUATION, GL_POINT_SPRITE_COORD_ORIGIN.
    pub point_size_min: f32,
    pub point_size_max: f32,
    pub point_fade_threshold: f32,
    pub point_distance_attenuation: [f32; 3],
    pub point_sprite_coord_origin: GLenum,
}

impl Default for LinePointState {
    fn default() -> Self {
        LinePointState {
            line_smooth: false,
            line_stipple: false,
            point_smooth: false,
            point_sprite: false,
            vertex_program_point_size: false,
            vertex_program_two_side: false,
            line_width: 1.0,
            line_stipple_factor: 1,
            line_stipple_pattern: 0xffff,
            point_size: 1.0,
            point_size_min: 0.0,
            point_size_max: MAX_POINT_SIZE,
            point_fade_threshold: 1.0,
            point_distance_attenuation: [1.0, 0.0, 0.0],
            point_sprite_coord_origin: GL_UPPER_LEFT,
        }
    }
}

/// GL_MULTISAMPLE_BIT.
#[derive(Clone, Debug, PartialEq)]
pub struct MultisampleState {
    pub enabled: bool,
    pub alpha_to_coverage: bool,
    pub alpha_to_one: bool,
    pub coverage: bool,
    /// glSampleCoverage's value (clamped to [0, 1]) and invert flag.
    pub coverage_value: f32,
    pub coverage_invert: bool,
}

impl Default for MultisampleState {
    fn default() -> Self {
        MultisampleState {
            enabled: true,
            alpha_to_coverage: false,
            alpha_to_one: false,
            coverage: false,
            coverage_value: 1.0,
            coverage_invert: false,
        }
    }
}

/// Texture enables of one unit (GL_TEXTURE_BIT / GL_ENABLE_BIT).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct TextureUnitEnables {
    pub texture_1d: bool,
    pub texture_2d: bool,
    pub texture_3d: bool,
    pub texture_cube_map: bool,
    /// GL_TEXTURE_GEN_S, T, R, Q.
    pub gen: [bool; 4],
}

/// GL_TEXTURE_BIT: the active unit, and per unit the enables, the bindings, the texture
/// environment and texture coordinate generation (`context::texture_env`).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TextureState {
    pub active_unit: usize,
    /// Per texture coordinate set: units at and past GL_MAX_TEXTURE_UNITS only ever have
    /// their texgen enables set (their target enables are GL_INVALID_OPERATION).
    pub units: [TextureUnitEnables; MAX_TEXTURE_COORDS],
    /// Per texture coordinate set; past GL_MAX_TEXTURE_UNITS only the texgen state and the
    /// bindings are used (glTexEnv there is GL_INVALID_OPERATION).
    pub unit_state: [super::texture_env::TextureUnitState; MAX_TEXTURE_COORDS],
}

/// GL_EVAL_BIT: the enables GL_MAP1_* and GL_MAP2_* (in enum order) and GL_AUTO_NORMAL, and
/// the grids of glMapGrid (the maps themselves are `context::evaluators`).
#[derive(Clone, Debug, PartialEq)]
pub struct EvalState {
    pub map1: [bool; 9],
    pub map2: [bool; 9],
    pub auto_normal: bool,
    /// GL_MAP1_GRID_SEGMENTS and GL_MAP1_GRID_DOMAIN (u1, u2).
    pub grid1_segments: i32,
    pub grid1_domain: [f32; 2],
    /// GL_MAP2_GRID_SEGMENTS (nu, nv) and GL_MAP2_GRID_DOMAIN (u1, u2, v1, v2).
    pub grid2_segments: [i32; 2],
    pub grid2_domain: [f32; 4],
}

impl Default for EvalState {
    fn default() -> Self {
        EvalState {
            map1: [false; 9],
            map2: [false; 9],
            auto_normal: false,
            grid1_segments: 1,
            grid1_domain: [0.0, 1.0],
            grid2_segments: [1, 1],
            grid2_domain: [0.0, 1.0, 0.0, 1.0],
        }
    }
}

/// GL_PIXEL_MODE_BIT (the read buffer, so far).
#[derive(Clone, Debug, PartialEq)]
pub struct PixelModeState {
    pub read_buffer: GLenum,
    /// glPixelZoom's x and y factors.
    pub zoom: [f32; 2],
    /// glPixelTransfer's values.
    pub transfer: PixelTransfer,
    /// glPixelMap's ten tables, in the order of their enums (GL_PIXEL_MAP_I_TO_I ...
    /// GL_PIXEL_MAP_A_TO_A); each holds at least one entry.
    pub maps: [Vec<f32>; 10],
}

/// glPixelTransfer's state (part of GL_PIXEL_MODE_BIT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelTransfer {
    /// RGBA scale and bias.
    pub scale: [f32; 4],
    pub bias: [f32; 4],
    pub depth_scale: f32,
    pub depth_bias: f32,
    pub index_shift: i32,
    pub index_offset: i32,
    pub map_color: bool,
    pub map_stencil: bool,
}

impl Default for PixelTransfer {
    fn default() -> Self {
        PixelTransfer {
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            index_shift: 0,
            index_offset: 0,
            map_color: false,
            map_stencil: false,
        }
    }
}

/// One direction of glPixelStore (GL_PACK_* or GL_UNPACK_*): client state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelStoreModes {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    pub row_length: i32,
    pub image_height: i32,
    pub skip_rows: i32,
    pub skip_pixels: i32,
    pub skip_images: i32,
    pub alignment: i32,
}

impl Default for PixelStoreModes {
    fn default() -> Self {
        PixelStoreModes {
            swap_bytes: false,
            lsb_first: false,
            row_length: 0,
            image_height: 0,
            skip_rows: 0,
            skip_pixels: 0,
            skip_images: 0,
            alignment: 4,
        }
    }
}

/// GL_CLIENT_PIXEL_STORE_BIT.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PixelStoreState {
    pub pack: PixelStoreModes,
    pub unpack: PixelStoreModes,
    /// The buffers bound to GL_PIXEL_PACK_BUFFER and GL_PIXEL_UNPACK_BUFFER (0: none, the
    /// pointer arguments are client memory). Saved with this group, as Mesa saves them.
    pub pack_buffer: u32,
    pub unpack_buffer: u32,
}

/// GL_CURRENT_BIT: the current vertex attributes (what glColor, glNormal, ... set).
#[derive(Clone, Debug, PartialEq)]
pub struct CurrentState {
    pub color: [f32; 4],
    pub secondary_color: [f32; 4],
    pub normal: [f32; 3],
    pub tex_coords: [[f32; 4]; MAX_TEXTURE_UNITS],
    pub fog_coord: f32,
    pub edge_flag: bool,
    pub index: f32,
    /// The current raster position (glRasterPos, glWindowPos) and its attributes.
    pub raster: crate::context::raster_pos::RasterPos,
    /// The current generic attributes (glVertexAttrib); attribute 0 is the vertex itself and
    /// has none. Past them, the current texture coordinates of the sets past
    /// GL_MAX_TEXTURE_UNITS ([`crate::vertex::generic::tex_coord_slot`]): glMultiTexCoord
    /// sets those as glVertexAttrib sets a generic attribute.
    pub generic: crate::vertex::generic::GenericValues,
    /// The row of the open glBegin/glEnd's generic attribute rows that holds `generic`, once
    /// glVertexAttrib changed them there (see [`crate::vertex::generic`]); else
    /// [`crate::vertex::generic::CURRENT`].
    pub generic_row: u32,
}

impl CurrentState {
    /// The vertex a glVertex call at `position` makes: every other attribute is the current one.
    #[inline]
    pub fn vertex_at(&self, position: [f32; 4]) -> crate::vertex::Vertex {
        crate::vertex::Vertex {
            position,
            color: self.color,
            secondary_color: self.secondary_color,
            normal: self.normal,
            tex_coords: self.tex_coords,
            fog_coord: self.fog_coord,
            edge_flag: self.edge_flag,
            generic: self.generic_row,
        }
    }
}

impl Default for CurrentState {
    fn default() -> Self {
        CurrentState {
            color: [1.0; 4],
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            normal: [0.0, 0.0, 1.0],
            tex_coords: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS],
            fog_coord: 0.0,
            edge_flag: true,
            index: 1.0,
            raster: Default::default(),
            generic: [[0.0, 0.0, 0.0, 1.0]; crate::vertex::generic::SLOTS],
            generic_row: crate::vertex::generic::CURRENT,
        }
    }
}

/// All server-side state covered so far, one field per attribute group.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    pub current: CurrentState,
    /// GL_POLYGON_STIPPLE_BIT: 32 rows of 32 bits, row 0 at the bottom, bit 31 leftmost.
    pub polygon_stipple: [u32; 32],
    pub color: ColorBufferState,
    pub depth: DepthState,
    pub stencil: StencilState,
    pub scissor: ScissorState,
    pub viewport: ViewportState,
    pub accum: AccumState,
    pub hint: HintState,
    pub fog: FogState,
    pub lighting: LightingState,
    pub transform: TransformState,
    pub polygon: PolygonState,
    pub line_point: LinePointState,
    pub multisample: MultisampleState,
    pub texture: TextureState,
    pub eval: EvalState,
    pub pixel_mode: PixelModeState,
    /// GL_LIST_BIT: the offset glCallLists adds to every name (glListBase).
    pub list_base: u32,
}

impl State {
    /// Initial state for a framebuffer whose default draw and read buffer is `buffer`
    /// (GL_FRONT single-buffered, GL_BACK double-buffered).
    pub fn new(buffer: GLenum) -> Self {
        State {
            current: CurrentState::default(),
            polygon_stipple: [!0; 32],
            color: ColorBufferState::new(buffer),
            depth: DepthState::default(),
            stencil: StencilState::default(),
            scissor: ScissorState::default(),
            viewport: ViewportState::default(),
            accum: AccumState::default(),
            hint: HintState::default(),
            fog: FogState::default(),
            lighting: LightingState::default(),
            transform: TransformState::default(),
            polygon: PolygonState::default(),
            line_point: LinePointState::default(),
            multisample: MultisampleState::default(),
            texture: TextureState::default(),
            eval: EvalState::default(),
            pixel_mode: PixelModeState {
                read_buffer: buffer,
                zoom: [1.0, 1.0],
                transfer: PixelTransfer::default(),
                maps: std::array::from_fn(|_| vec![0.0]),
            },
            list_base: 0,
        }
    }
}

#[cfg(test)]
mod current_tests {
    use super::*;

    #[test]
    fn vertices_snapshot_every_current_attribute() {
        let mut current =
            CurrentState { color: [0.1, 0.2, 0.3, 0.4], edge_flag: false, fog_coord: 9.0, ..Default::default() };
        current.tex_coords[3] = [5.0, 6.0, 7.0, 8.0];
        let v = current.vertex_at([1.0, 2.0, 3.0, 4.0]);
        assert_eq!(v.position, [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(v.color, [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(v.secondary_color, [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(v.normal, [0.0, 0.0, 1.0]);
        assert_eq!(v.tex_coords[3], [5.0, 6.0, 7.0, 8.0]);
        assert_eq!(v.tex_coords[0], [0.0, 0.0, 0.0, 1.0]);
        assert_eq!((v.fog_coord, v.edge_flag), (9.0, false));
    }
}
