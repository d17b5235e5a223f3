//! Aliased points: the job a set-up point becomes, and how it renders inside one tile. An
//! aliased point is a square of pixels with one depth and one color, so every row of it is
//! a constant span handed to the fragment pipeline. On a multisampled target with
//! GL_MULTISAMPLE on, a point covers the samples of its unrounded square instead
//! ([`SampleQuad::point`], llvmpipe's shape there), and so does a point sprite
//! (GL_POINT_SPRITE, GL 2.0 §3.3) at the pixel centres, with the texture coordinates
//! GL_COORD_REPLACE replaces varying over it ([`Sprite`]).
use crate::fragment::multisample::SampleMasks;
use crate::fragment::pipeline::{shade_span, shade_span_samples, DrawState, Scratch, Span};
use crate::fragment::{span_mask, MAX_SPAN};
use crate::framebuffer::band::Band;
use crate::framebuffer::Rect;
use crate::gl::float::fused_multiply_add;
use crate::raster::walk::walk_sample_spans;
use crate::setup::multisample::{sample_offsets, SampleQuad};
use crate::setup::plane::{PointVaryings, MAX_VARYINGS};

/// A set-up point: its pixels, its window z and its color.
#[derive(Clone, Debug)]
pub struct PointJob {
    pub rect: Rect,
    pub z: f32,
    pub color: [f32; 4],
    /// The varyings the draw needs (one value each over the whole point).
    pub varyings: PointVaryings,
    /// The square covered sample by sample, when rasterized per sample (`rect` is then its
    /// pixel box).
    pub sample_square: Option<Box<SampleQuad>>,
    /// The sprite coordinates, for a point sprite.
    pub sprite: Option<Box<Sprite>>,
}

/// What a sprite coordinate replaces a texture coordinate component with: s and t across the
/// square, r = 0 and q = 1 (GL 2.0 §3.3.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpriteCoord {
    S,
    T,
    R,
    Q,
}

/// The replaced varyings of a point sprite, as llvmpipe sets them up (`texcoord_coef`) and
/// interpolates them: the plane `a0 + dadx·x + dady·y` over its y-down pixel coordinates
/// (`x`, `y` the pixel, its centre at +½) with two fused multiply-adds, as the line planes
/// (the same bits on every machine: [`fused_multiply_add`]), premultiplied by the point's
/// 1/w and divided by it again per fragment, as every perspective attribute is.
#[derive(Clone, Debug)]
pub struct Sprite {
    /// The square, when the point is single-sampled (rasterized at the pixel centres).
    pub square: Option<SampleQuad>,
    /// Per varying: `Some([a0, dadx, dady])` when the sprite replaces it.
    pub planes: [Option<[f32; 3]>; MAX_VARYINGS],
    /// The point's 1/w, and the framebuffer height (GL rows to y-down rows).
    pub inv_w: f32,
    pub height: i32,
}

impl Sprite {
    /// The sprite's planes for a point at window `(x, y_down)` with 1/w `inv_w` and
    /// fixed-point side `fixed_side` (1/256 pixels, at least 256); `replaced[k]` says what
    /// replaces varying `k`; `lower_left`: GL_POINT_SPRITE_COORD_ORIGIN is GL_LOWER_LEFT.
    pub fn new(
        position: [f32; 2],
        inv_w: f32,
        fixed_side: i64,
        replaced: &[Option<SpriteCoord>],
        lower_left: bool,
        height: i32,
    ) -> Sprite {
        let step = 256.0 / fixed_side as f32;
        // llvmpipe's positions are shifted by half a pixel, so pixel x has its centre at x.
        let (x0, y0) = (position[0] - 0.5, position[1] - 0.5);
        let mut planes = [None; MAX_VARYINGS];
        for (plane, coord) in planes.iter_mut().zip(replaced) {
            let [a0, dadx, dady] = match coord {
                None => continue,
                // 0.5 − (dadx·x0 + dady·y0), the sum in single precision and the difference
                // in double (a C double constant), as llvmpipe writes it.
                Some(SpriteCoord::S) => [(0.5 - (step * x0 + 0.0 * y0) as f64) as f32, step, 0.0],
                Some(SpriteCoord::T) => {
                    let dady = if lower_left { -step } else { step };
                    [(0.5 - (0.0 * x0 + dady * y0) as f64) as f32, 0.0, dady]
                }
                Some(SpriteCoord::R) => [0.0; 3],
                Some(SpriteCoord::Q) => [1.0, 0.0, 0.0],
            };
            *plane = Some([a0 * inv_w, dadx * inv_w, dady * inv_w]);
        }
        Sprite { square: None, planes, inv_w, height }
    }

    /// The varyings at GL pixel `(x, y)`: the replaced ones from their planes, the others
    /// `constant`.
    #[inline]
    pub fn varyings_at(&self, x: i32, y: i32, constant: &PointVaryings, out: &mut [f32]) {
        let (fx, fy) = (x as f32, (self.height - 1 - y) as f32);
        let w = 1.0 / self.inv_w;
        for ((o, plane), &c) in out.iter_mut().zip(&self.planes).zip(constant) {
            *o = match plane {
                Some([a0, dadx, dady]) => fused_multiply_add(*dady, fy, fused_multiply_add(*dadx, fx, *a0)) * w,
                None => c,
            };
        }
    }
}

impl PointJob {
    pub fn bounds(&self) -> Rect {
        self.rect
    }

    /// Renders the part of the point inside `area` into a multisampled band, sample by
    /// sample (a point without a sample square draws nothing here).
    pub fn render_samples(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let Some(square) = &self.sample_square else { return };
        walk_sample_spans(
            area.intersect(self.rect),
            sample_offsets(band.samples),
            |y, o, x0, x1| square.row_span_at(y, o.x, o.y, x0, x1),
            |y, x0, x1, masks: SampleMasks| {
                let n = (x1 - x0) as usize;
                let span = Span { y, x0, n, row_start: band.sample_index(y, x0, 0), front_facing: true };
                shade_span_samples(
                    state,
                    band,
                    scratch,
                    span,
                    masks,
                    |_, _| self.z,
                    |_| Some(self.color),
                    |dx, dy, out| self.varyings_at(x0 + dx, y + dy, out),
                );
            },
        );
    }

    /// The varyings of the fragment at GL pixel `(x, y)` (a sprite's vary; the helper
    /// pixels of a quad outside the point take its planes' values there).
    #[inline]
    fn varyings_at(&self, x: i32, y: i32, out: &mut [f32]) {
        match &self.sprite {
            Some(sprite) => sprite.varyings_at(x, y, &self.varyings, out),
            None => out.iter_mut().zip(&self.varyings).for_each(|(o, &v)| *o = v),
        }
    }

    /// Renders the part of the point inside `area` (within the band) into `band`: its
    /// square's rows, or a single-sampled sprite's pixels whose centres its square covers.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.rect);
        let square = self.sprite.as_ref().and_then(|s| s.square.as_ref());
        let centre = sample_offsets(1)[0];
        for y in area.y0..area.y1 {
            let row = match square {
                Some(square) => square.row_span_at(y, centre.x, centre.y, area.x0, area.x1),
                None => Some((area.x0, area.x1)),
            };
            let Some((mut x0, x1)) = row else { continue };
            while x0 < x1 {
                let end = (x0 + MAX_SPAN as i32).min(x1);
                let n = (end - x0) as usize;
                let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                // Points are front-facing (GL 2.1 §4.1.5); so are the vertices of polygons in
                // GL_POINT mode, as in Mesa 22 (llvmpipe and softpipe), though §4.1.5 gives
                // them their polygon's facing.
                let span = Span { y, x0, n, row_start, front_facing: true };
                shade_span(
                    state,
                    band,
                    scratch,
                    span,
                    span_mask(n),
                    |_| self.z,
                    |_| Some(self.color),
                    |dx, dy, out| self.varyings_at(x0 + dx, y + dy, out),
                );
                x0 = end;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sprite coordinates of a 16-pixel sprite at (10.5, 20.5) (y-down) in a 64-row
    /// framebuffer: s and t are 0.5 + (centre offset)/16, t from the top (GL row 50 is
    /// y-down row 13) or from the bottom, r = 0, q = 1, and a perspective point (1/w = 0.25)
    /// gives the same values; unreplaced varyings keep the vertex's value.
    #[test]
    fn sprite_coordinates_cross_the_square() {
        use SpriteCoord::*;
        let replaced = [Some(S), Some(T), Some(R), Some(Q), None];
        let constant: PointVaryings = std::array::from_fn(|k| 10.0 + k as f32);
        for inv_w in [1.0, 0.25] {
            for lower_left in [false, true] {
                let sprite = Sprite::new([10.5, 20.5], inv_w, 16 * 256, &replaced, lower_left, 64);
                let mut out = [0.0; MAX_VARYINGS];
                // Pixel x = 3, y-down row 13 (GL row 50): centre offsets (−7, −7).
                sprite.varyings_at(3, 50, &constant, &mut out);
                let t = if lower_left { 1.0 - 1.0 / 16.0 } else { 1.0 / 16.0 };
                assert_eq!(out[..5], [1.0 / 16.0, t, 0.0, 1.0, 14.0], "inv_w {inv_w} lower_left {lower_left}");
                // One pixel right and one down.
                sprite.varyings_at(4, 49, &constant, &mut out);
                let t = if lower_left { 1.0 - 2.0 / 16.0 } else { 2.0 / 16.0 };
                assert_eq!(out[..2], [2.0 / 16.0, t]);
            }
        }
    }
}
