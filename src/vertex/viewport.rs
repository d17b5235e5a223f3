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
        let WindowVertex { x, y, z, inv_w, color, secondary_color, fog_coord, .. } = self.window_without_slots(v);
        WindowVertex { x, y, z, inv_w, color, secondary_color, tex_coords: v.tex_coords, fog_coord }
    }

    /// [`Viewport::window`] without the varying slots, for a filled triangle no varying of
    /// which reads a texture coordinate: the slots are never read, and copying them into
    /// each corner was a fifth of making a small triangle's corners.
    #[inline]
    pub fn window_without_slots<const N: usize>(&self, v: &ClipVertex<N>) -> WindowVertex<0> {
        let inv_w = 1.0 / v.clip[3];
        let ndc = [v.clip[0] * inv_w, v.clip[1] * inv_w, v.clip[2] * inv_w];
        WindowVertex {
            x: ndc[0] * self.scale[0] + self.offset[0],
            y: ndc[1] * self.scale[1] + self.offset[1],
            z: ndc[2] * self.scale[2] + self.offset[2],
            inv_w,
            color: v.color,
            secondary_color: v.secondary_color,
            tex_coords: [],
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vertex::clip::FixedClipVertex;

    /// A filled triangle's corners without their slots keep every other value of the full
    /// corners, bit for bit (the images of draws without textures must not change).
    #[test]
    fn corners_without_slots_keep_every_other_value() {
        let viewport = Viewport::new([3, -7, 250, 190], (0.5, 0.25), 1.0, 300);
        let v = FixedClipVertex {
            clip: [0.3, -1.7, 0.9, 1.9],
            eye: [0.0; 4],
            color: [0.1, 0.2, 0.3, 0.4],
            secondary_color: [0.5, 0.6, 0.7, 0.8],
            back_colors: [[0.0; 4]; 2],
            tex_coords: [[9.0; 4]; 4],
            fog_coord: 0.75,
            point_size: 0.0,
            edge_flag: true,
        };
        let (full, bare) = (viewport.window(&v), viewport.window_without_slots(&v));
        let bits = |w: [f32; 4]| w.map(f32::to_bits);
        assert_eq!(bits([full.x, full.y, full.z, full.inv_w]), bits([bare.x, bare.y, bare.z, bare.inv_w]));
        assert_eq!(bits(full.color), bits(bare.color));
        assert_eq!(bits(full.secondary_color), bits(bare.secondary_color));
        assert_eq!(full.fog_coord.to_bits(), bare.fog_coord.to_bits());
        assert_eq!(full.tex_coords, [[9.0; 4]; 4]);
    }
}
