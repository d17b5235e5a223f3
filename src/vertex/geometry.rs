//! The per-draw constants of the geometry stage: the typed snapshot of the GL state that
//! `context` takes at a draw and every later step of vertex processing reads (viewport,
//! clip planes, shading, culling, polygon modes and offsets, line and point parameters,
//! varyings).
//!
//! A snapshot of plain values rather than a view of the context's state: it is built once
//! per draw (a few dozen words) and keeps this room free of `context`'s types.
use super::attribute::Attribute;
use super::clip::{ClipPlanes, ClipVertex};
use super::point::PointAttenuation;
use super::viewport::Viewport;
use crate::framebuffer::format::DepthEncoding;
use crate::gl::types::GLenum;
use crate::setup::accuracy::Accuracy;

/// Per-draw constants of the geometry stage.
pub struct Geometry {
    pub viewport: Viewport,
    pub planes: ClipPlanes,
    /// The view volume without guard band: lines are clipped to it, points outside it
    /// are discarded.
    pub line_planes: ClipPlanes,
    /// GL_FIRST_VERTEX_CONVENTION: the first vertex of a primitive provokes (else the last).
    pub first_vertex: bool,
    pub flat: bool,
    /// Two-sided lighting: back-facing polygons take the back colors.
    pub two_side: bool,
    pub cull: Option<GLenum>,
    pub front_ccw: bool,
    pub offset: Option<(f32, f32)>,
    /// How the depth buffer stores depth: its resolution scales polygon offset units (per
    /// primitive on a float buffer, by the exponent of its largest depth).
    pub depth: DepthEncoding,
    /// Framebuffer height (for llvmpipe's y-down window space).
    pub height: i32,
    pub line_width: f32,
    pub point_size: f32,
    /// GL_POINT_DISTANCE_ATTENUATION's coefficients with GL_POINT_SIZE_MIN/MAX, when they
    /// attenuate (not (1, 0, 0)); `point_size` is used unchanged otherwise.
    pub point_attenuation: Option<PointAttenuation>,
    /// GL_VERTEX_PROGRAM_POINT_SIZE with a GLSL vertex program: points take their vertex's
    /// gl_PointSize, clamped to these GL_POINT_SIZE_MIN and MAX.
    pub program_point_size: Option<[f32; 2]>,
    /// glPolygonMode of front and back faces.
    pub mode_front: GLenum,
    pub mode_back: GLenum,
    /// The depth offsets of polygons drawn as lines and as points: (factor, units × 2r),
    /// r the depth buffer's resolution, as Mesa's offset stage applies them.
    pub offset_line: Option<(f32, f32)>,
    pub offset_point: Option<(f32, f32)>,
    /// GL_POLYGON_OFFSET_CLAMP (EXT_polygon_offset_clamp): the bound of every offset.
    pub offset_clamp: f32,
    /// The attributes interpolated over filled polygons for the stages this draw enables
    /// (none when only color is needed).
    pub varyings: Vec<Attribute>,
    /// How filled triangles interpolate.
    pub accuracy: Accuracy,
    /// GL_LINE_SMOOTH, GL_POINT_SMOOTH and GL_POLYGON_SMOOTH: the draw's lines, points or
    /// filled polygons are set up as smooth jobs (coverage in alpha) instead of aliased ones.
    pub smooth_lines: bool,
    pub smooth_points: bool,
    /// GL_POINT_SPRITE: points are sprites (`super::point::PointSprites`).
    pub sprite: Option<super::point::PointSprites>,
    pub smooth_polygons: bool,
    /// Lines and points cover samples (a multisampled target with GL_MULTISAMPLE on; set by
    /// the context from the draw state).
    pub per_sample: bool,
}

impl Geometry {
    /// Whether any vertex lies outside the view volume (not only the guard band) or an
    /// enabled user clip plane: where Mesa's draw module takes its pipeline path.
    pub fn leaves_view_volume<const N: usize>(&self, vertices: &[ClipVertex<N>]) -> bool {
        vertices.iter().any(|v| self.line_planes.outcode(v) != 0)
    }
}
