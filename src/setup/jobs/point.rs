//! Aliased points: the job a set-up point becomes, and how it renders inside one tile. An
//! aliased point is a square of pixels with one depth and one color, so every row of it is
//! a constant span handed to the fragment pipeline. On a multisampled target with
//! GL_MULTISAMPLE on, a point covers the samples of its unrounded square instead
//! ([`SampleQuad::point`], llvmpipe's shape there).
use crate::fragment::multisample::SampleMasks;
use crate::fragment::pipeline::{shade_span, shade_span_samples, DrawState, Scratch, Span};
use crate::fragment::{span_mask, MAX_SPAN};
use crate::framebuffer::band::Band;
use crate::framebuffer::Rect;
use crate::raster::walk::walk_sample_spans;
use crate::setup::multisample::{sample_offsets, SampleQuad};
use crate::setup::plane::PointVaryings;

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
                    |_, _, out| out.iter_mut().zip(&self.varyings).for_each(|(o, &v)| *o = v),
                );
            },
        );
    }

    /// Renders the part of the point inside `area` (within the band) into `band`.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.rect);
        if area.is_empty() {
            return;
        }
        for y in area.y0..area.y1 {
            let mut x0 = area.x0;
            while x0 < area.x1 {
                let x1 = (x0 + MAX_SPAN as i32).min(area.x1);
                let n = (x1 - x0) as usize;
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
                    |_, _, out| out.iter_mut().zip(&self.varyings).for_each(|(o, &v)| *o = v),
                );
                x0 = x1;
            }
        }
    }
}
