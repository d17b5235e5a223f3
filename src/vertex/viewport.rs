//! The viewport transform: clip coordinates to window coordinates (glViewport,
//! glDepthRange), in GL's y-up window space for filled polygons and in llvmpipe's y-down
//! window space for lines and points. This is the only place that maps to window space.
use super::clip::ClipVertex;
use crate::gl::float::fused_multiply_add;
use crate::setup::jobs::line::LineVertex;
use crate::setup::jobs::triangle::WindowVertex;
use crate::setup::triangle::GUARD_BAND;

/// The viewport transform: window = ndc · scale + offset (x, y, z).
#[derive(Clone, Copy, Debug)]
pub struct Viewport {
    scale: [f32; 3],
    offset: [f32; 3],
    /// The y translation of llvmpipe's y-down window space (framebuffer height − offset y),
    /// where lines and points are set up: `y_down = ndc_y · −scale_y + offset_down`.
    offset_down: f32,
}

impl Viewport {
    /// The viewport transform of glViewport's `rect` (x, y, width, height) for a framebuffer
    /// `height` rows high. `depth` is the (scale, offset) of window z, which glDepthRange and
    /// glClipControl's depth mode decide; `y_sign` is −1 under GL_UPPER_LEFT (glClipControl
    /// mirrors y), else 1.
    pub fn new(rect: [i32; 4], depth: (f64, f64), y_sign: f32, height: usize) -> Viewport {
        let [x, y, w, h] = rect;
        let half = [w as f32 * 0.5, h as f32 * 0.5];
        let centre = [x as f32 + half[0], y as f32 + half[1]];
        Viewport {
            scale: [half[0], half[1] * y_sign, depth.0 as f32],
            offset: [centre[0], centre[1], depth.1 as f32],
            offset_down: height as f32 - centre[1],
        }
    }

    /// The guard band in NDC (x, y): as far out as keeps window coordinates within
    /// [`GUARD_BAND`].
    pub fn guard_band(&self) -> (f32, f32) {
        let guard = |c: f32, h: f32| if h > 0.0 { ((GUARD_BAND * 0.5 - c.abs()) / h).max(1.0) } else { 1.0 };
        (guard(self.offset[0], self.scale[0].abs()), guard(self.offset[1], self.scale[1].abs()))
    }

    /// Window coordinates of a clip-space vertex (w > 0), as llvmpipe computes them:
    /// the reciprocal of w first, then a multiply and the scale/offset, in single precision.
    #[inline]
    pub fn window<const N: usize>(&self, v: &ClipVertex<N>) -> WindowVertex<N> {
        let inv_w = 1.0 / v.clip[3];
        let ndc = [v.clip[0] * inv_w, v.clip[1] * inv_w, v.clip[2] * inv_w];
        WindowVertex {
            x: ndc[0] * self.scale[0] + self.offset[0],
            y: ndc[1] * self.scale[1] + self.offset[1],
            z: ndc[2] * self.scale[2] + self.offset[2],
            inv_w,
            color: v.color,
            secondary_color: v.secondary_color,
            tex_coords: v.tex_coords,
            fog_coord: v.fog_coord,
        }
    }

    /// Window coordinates of a line or point vertex in llvmpipe's y-down window space.
    /// Vertices straight from the vertex stage get the multiply-add llvmpipe's generated
    /// code fuses (`fused`); vertices made by clipping get its C clipper's separate
    /// multiply and add. Endpoint pixels depend on the last bit of these coordinates.
    #[inline]
    pub fn window_down<const N: usize>(&self, v: &ClipVertex<N>, fused: bool) -> LineVertex<N> {
        let inv_w = 1.0 / v.clip[3];
        let ndc = [v.clip[0] * inv_w, v.clip[1] * inv_w, v.clip[2] * inv_w];
        let map = |n: f32, scale: f32, offset: f32| {
            if fused {
                fused_multiply_add(n, scale, offset)
            } else {
                n * scale + offset
            }
        };
        LineVertex {
            x: map(ndc[0], self.scale[0], self.offset[0]),
            y_down: map(ndc[1], -self.scale[1], self.offset_down),
            z: map(ndc[2], self.scale[2], self.offset[2]),
            inv_w,
            color: v.color,
            secondary_color: v.secondary_color,
            tex_coords: v.tex_coords,
            fog_coord: v.fog_coord,
        }
    }
}
