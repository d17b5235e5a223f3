//! Points: their size (glPointSize, GL_POINT_SIZE_MIN/MAX and distance attenuation) and
//! their setup into point jobs (aliased, smooth or covering samples), in llvmpipe's y-down
//! window space.
use super::clip::ClipVertex;
use super::geometry::Geometry;
use crate::framebuffer::Rect;
use crate::gl::float::fused_multiply_add;
use crate::gl::limits::MAX_POINT_SIZE;
use crate::setup::jobs::line::LineVertex;
use crate::setup::jobs::point::{PointJob, Sprite, SpriteCoord};
use crate::setup::jobs::smooth::{SmoothJob, SmoothPoint};
use crate::setup::multisample::SampleQuad;
use crate::setup::plane::point_varyings;
use crate::setup::point::point_rect;
use crate::setup::triangle::to_fixed;
use crate::setup::{Primitive as RasterPrimitive, Scene};
use crate::vertex::attribute::Attribute;

/// The size points are drawn with without distance attenuation: glPointSize `size` clamped to
/// GL_POINT_SIZE_MIN/MAX (the minimum winning when they cross, as in Mesa) and to the
/// implementation's range.
pub fn point_size(size: f32, min: f32, max: f32) -> f32 {
    clamp_point_size(size, min, max)
}

/// `size` clamped to [min, max] (min winning when they cross; NaN gives min) and to the
/// implementation's range.
fn clamp_point_size(size: f32, min: f32, max: f32) -> f32 {
    let size = if size.is_nan() || size < min {
        min
    } else if size > max {
        max
    } else {
        size
    };
    size.min(MAX_POINT_SIZE)
}

/// Point parameters' distance attenuation (GL 1.4, GL 2.1 §3.4): the derived size
/// `size · 1/√(a + b·d + c·d²)` clamped to GL_POINT_SIZE_MIN/MAX. As Mesa's fixed-function
/// vertex program, d is |z| of the eye coordinates (the spec's distance to the eye,
/// approximated along the view axis; the same on the view axis) and the square root is of
/// the absolute value. Without multisampling the derived size is the point's width (the
/// fade threshold applies to multisampled points only).
#[derive(Clone, Copy, Debug)]
pub struct PointAttenuation {
    pub size: f32,
    pub coefficients: [f32; 3],
    pub min: f32,
    pub max: f32,
}

impl PointAttenuation {
    pub fn size_at(&self, eye: [f32; 4]) -> f32 {
        let d = eye[2].abs();
        let [a, b, c] = self.coefficients;
        let factor = fused_multiply_add(fused_multiply_add(d, c, b), d, a);
        clamp_point_size(self.size / factor.abs().sqrt(), self.min, self.max)
    }
}

/// GL_POINT_SPRITE's state for a draw (GL 2.0 §3.3): what replaces each of the draw's
/// varyings on a sprite (`None`: the vertex's value) and where t = 0 is.
#[derive(Clone, Debug, PartialEq)]
pub struct PointSprites {
    pub replaced: Vec<Option<SpriteCoord>>,
    /// GL_POINT_SPRITE_COORD_ORIGIN is GL_LOWER_LEFT (t = 0 at the bottom).
    pub lower_left: bool,
}

impl PointSprites {
    /// The sprite state of a draw with `varyings`, where `coord_replace(unit)` is that
    /// unit's GL_COORD_REPLACE.
    pub fn new(varyings: &[Attribute], coord_replace: impl Fn(usize) -> bool, lower_left: bool) -> PointSprites {
        let replaced = varyings
            .iter()
            .map(|v| {
                // A fragment shader's gl_PointCoord: s and t whatever GL_COORD_REPLACE says.
                if let Some(component) = v.point_coordinate() {
                    return Some([SpriteCoord::S, SpriteCoord::T][component & 1]);
                }
                let (_, component) = v.texture_coordinate().filter(|&(unit, _)| coord_replace(unit))?;
                Some([SpriteCoord::S, SpriteCoord::T, SpriteCoord::R, SpriteCoord::Q][component])
            })
            .collect();
        PointSprites { replaced, lower_left }
    }
}

impl Geometry {
    /// The width of the point of vertex `v`: its program's gl_PointSize
    /// (GL_VERTEX_PROGRAM_POINT_SIZE, clamped as glPointSize's), else glPointSize's, attenuated
    /// by the eye distance when GL_POINT_DISTANCE_ATTENUATION says so.
    pub fn point_size_of<const N: usize>(&self, v: &ClipVertex<N>) -> f32 {
        if let Some(limits) = self.program_point_size {
            return clamp_point_size(v.point_size, limits[0], limits[1]);
        }
        self.point_attenuation.map_or(self.point_size, |a| a.size_at(v.eye))
    }
}

/// Emits a point whose vertex is inside the view volume.
pub fn emit_point<const N: usize>(scene: &mut Scene, state: u32, g: &Geometry, v: &ClipVertex<N>) {
    let w = g.viewport.window_down(v, true);
    emit_window_point(scene, state, g, &w, g.point_size_of(v));
}

pub fn emit_window_point<const N: usize>(scene: &mut Scene, state: u32, g: &Geometry, w: &LineVertex<N>, size: f32) {
    // llvmpipe interpolates point colors perspective-correctly too: (c/w)·w.
    let color = if w.inv_w == 1.0 { w.color } else { w.color.map(|c| c * w.inv_w * (1.0 / w.inv_w)) };
    let varyings = point_varyings(g.varyings.iter().map(|v| v.of_line(w)));
    if let Some(sprites) = &g.sprite {
        // A sprite is the square of its unrounded size (at least one pixel, as llvmpipe's
        // quad points), whatever GL_POINT_SMOOTH says (GL 2.0 §3.3).
        let side = size.max(1.0);
        let Some(square) = SampleQuad::point([w.x, g.height as f32 - w.y_down], side) else { return };
        let (x0, y0, x1, y1) = square.pixel_box();
        let rect = Rect { x0, y0, x1, y1 };
        let fixed_side = to_fixed(side).max(256);
        let mut sprite =
            Sprite::new([w.x, w.y_down], w.inv_w, fixed_side, &sprites.replaced, sprites.lower_left, g.height);
        let sample_square = if g.per_sample {
            Some(Box::new(square))
        } else {
            sprite.square = Some(square);
            None
        };
        let job = PointJob { rect, z: w.z, color, varyings, sample_square, sprite: Some(Box::new(sprite)) };
        scene.add(state, rect, RasterPrimitive::Point(job));
        return;
    }
    if g.per_sample {
        // The square of the unrounded size, as llvmpipe draws it on a multisampled target
        // (sizes below 1 draw as 1 there, as for aliased points); GL_POINT_SMOOTH changes
        // nothing there (measured on Mesa 22.3; GL 2.1 §3.3.3 would make it a circle).
        if let Some(square) = SampleQuad::point([w.x, g.height as f32 - w.y_down], size.max(1.0)) {
            let (x0, y0, x1, y1) = square.pixel_box();
            let rect = Rect { x0, y0, x1, y1 };
            let sample_square = Some(Box::new(square));
            scene.add(
                state,
                rect,
                RasterPrimitive::Point(PointJob { rect, z: w.z, color, varyings, sample_square, sprite: None }),
            );
        }
        return;
    }
    if g.smooth_points {
        if let Some(job) = SmoothPoint::new(w, size, g.height, color, varyings) {
            let job = SmoothJob::Point(Box::new(job));
            scene.add(state, job.bounds(), RasterPrimitive::Smooth(job));
        }
        return;
    }
    let rect = point_rect(w.x, w.y_down, size, g.height);
    let point = PointJob { rect, z: w.z, color, varyings, sample_square: None, sprite: None };
    scene.add(state, rect, RasterPrimitive::Point(point));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_size_clamps_like_mesa() {
        assert_eq!(point_size(10.0, 2.0, 4.0), 4.0);
        assert_eq!(point_size(1.0, 2.0, 4.0), 2.0);
        // Crossed limits: the minimum wins below it, the maximum above.
        assert_eq!(point_size(1.0, 6.0, 4.0), 6.0);
        assert_eq!(point_size(9.0, 6.0, 4.0), 4.0);
        assert_eq!(point_size(300.0, 0.0, MAX_POINT_SIZE), MAX_POINT_SIZE);
    }
}
