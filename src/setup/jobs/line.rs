//! Aliased lines: the job a set-up line becomes (its edges and attribute planes), and how
//! it renders inside one tile: its row spans walked by `raster`, each handed with its
//! depth, colors and varyings to the same fragment pipeline as triangles.
//!
//! Attributes follow llvmpipe's line planes: they vary along the major axis only, linearly
//! in window space for z and perspective-correctly (planes of c/w and 1/w) for colors.
//!
//! On a multisampled target with GL_MULTISAMPLE on, a line covers the samples of its
//! rectangle instead ([`SampleQuad::line`], llvmpipe's shape there); its color and varyings
//! are still evaluated at pixel centres and its depth at each sample.
use crate::fragment::multisample::SampleMasks;
use crate::fragment::pipeline::{shade_span, shade_span_samples, DrawState, Scratch, Span};
use crate::fragment::span_mask;
use crate::framebuffer::band::Band;
use crate::framebuffer::Rect;
use crate::raster::walk::{walk_sample_spans, walk_spans};
use crate::setup::line::{LineGradient, LinePlane, LineSetup};
use crate::setup::multisample::{sample_offsets, sample_shifts, SampleQuad};
use crate::setup::plane::{Shading, Varyings};

/// How a line's color varies along it (planes over y-down pixel coordinates).
pub type LineShading = Shading<LinePlane>;

/// One endpoint of a line in window space (y down, as the line setup wants it), with the `N`
/// varying slots of its clip-space record (see `crate::vertex::clip::ClipVertex`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineVertex<const N: usize = { crate::glsl::varyings::VARYING_SLOTS }> {
    pub x: f32,
    pub y_down: f32,
    pub z: f32,
    pub inv_w: f32,
    pub color: [f32; 4],
    /// Read for the varyings a draw needs.
    pub secondary_color: [f32; 4],
    pub tex_coords: [[f32; 4]; N],
    pub fog_coord: f32,
}

/// A set-up line with everything its fragments need.
#[derive(Clone, Debug)]
pub struct LineJob {
    setup: LineSetup,
    z: LinePlane,
    shading: LineShading,
    /// Planes of a/w for the draw's varyings, and of 1/w (perspective-correct, as colors).
    varyings: Varyings<LinePlane>,
    /// The rectangle covered sample by sample, when rasterized per sample.
    sample_quad: Option<Box<SampleQuad>>,
}

impl LineJob {
    /// Sets up the line `a`–`b` of GL width `width` in a framebuffer `height` rows high;
    /// `flat` is the flat-shading color if flat shaded; `varyings` the values of the draw's
    /// varyings at `a` and `b`. `None` if it draws nothing.
    pub fn new<const N: usize>(
        a: &LineVertex<N>,
        b: &LineVertex<N>,
        width: f32,
        height: i32,
        flat: Option<[f32; 4]>,
        varyings: impl IntoIterator<Item = [f32; 2]>,
    ) -> Option<LineJob> {
        let setup = LineSetup::new([a.x, a.y_down], [b.x, b.y_down], width, height)?;
        let g = setup.gradient;
        Some(LineJob::with_planes(setup, g, a, b, flat, varyings))
    }

    /// As [`LineJob::new`] for a line covering the samples of `quad` (its rectangle) on a
    /// multisampled target with GL_MULTISAMPLE on, its attributes varying along the line
    /// (llvmpipe's planes for such rectangles).
    pub fn covering_samples<const N: usize>(
        a: &LineVertex<N>,
        b: &LineVertex<N>,
        height: i32,
        flat: Option<[f32; 4]>,
        varyings: impl IntoIterator<Item = [f32; 2]>,
        quad: SampleQuad,
    ) -> Option<LineJob> {
        let setup = LineSetup::new([a.x, a.y_down], [b.x, b.y_down], 1.0, height)?;
        let g = LineGradient::along([a.x, a.y_down], [b.x, b.y_down]);
        let mut job = LineJob::with_planes(setup, g, a, b, flat, varyings);
        job.sample_quad = Some(Box::new(quad));
        Some(job)
    }

    fn with_planes<const N: usize>(
        setup: LineSetup,
        g: LineGradient,
        a: &LineVertex<N>,
        b: &LineVertex<N>,
        flat: Option<[f32; 4]>,
        varyings: impl IntoIterator<Item = [f32; 2]>,
    ) -> LineJob {
        let z = g.plane(a.z, b.z);
        let shading = match flat {
            Some(color) => LineShading::Flat(color),
            None if a.color == b.color => LineShading::Flat(a.color),
            None if a.inv_w == b.inv_w => LineShading::Affine(std::array::from_fn(|c| g.plane(a.color[c], b.color[c]))),
            None => LineShading::Perspective {
                color_over_w: std::array::from_fn(|c| g.plane(a.color[c] * a.inv_w, b.color[c] * b.inv_w)),
                inv_w: g.plane(a.inv_w, b.inv_w),
            },
        };
        let over_w = varyings.into_iter().map(|v| g.plane(v[0] * a.inv_w, v[1] * b.inv_w));
        let varyings = Varyings::new(over_w, g.plane(a.inv_w, b.inv_w));
        LineJob { setup, z, shading, varyings, sample_quad: None }
    }

    pub fn setup(&self) -> &LineSetup {
        &self.setup
    }

    /// The pixel rectangle that may contain covered pixels (or samples).
    pub fn bounds(&self) -> Rect {
        match &self.sample_quad {
            Some(quad) => {
                let (x0, y0, x1, y1) = quad.pixel_box();
                Rect { x0, y0, x1, y1 }
            }
            None => self.setup.bounds,
        }
    }

    /// Whether the line is rasterized per sample ([`LineJob::render_samples`]).
    pub fn per_sample(&self) -> bool {
        self.sample_quad.is_some()
    }

    /// Renders the part of the line inside `area` into a multisampled band, sample by sample
    /// (a line without a sample rectangle draws nothing here).
    pub fn render_samples(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let Some(quad) = &self.sample_quad else { return };
        let offsets = sample_offsets(band.samples);
        let shifts = sample_shifts(offsets);
        walk_sample_spans(
            area.intersect(self.bounds()),
            offsets,
            |y, o, x0, x1| quad.row_span_at(y, o.x, o.y, x0, x1),
            |y, x0, x1, masks: SampleMasks| {
                let n = (x1 - x0) as usize;
                // llvmpipe evaluates these planes at the pixel's upper-right corner, half a
                // pixel right of and above its centre (measured on Mesa 22.3: a line from
                // x = 0 to 16 shaded from 1 to 0 gives pixel 0 the value 15/16).
                let (py, px0) = (self.setup.row_down(y) as f32 - 0.5, x0 as f32 + 0.5);
                let span = Span { y, x0, n, row_start: band.sample_index(y, x0, 0), front_facing: true };
                shade_span_samples(
                    state,
                    band,
                    scratch,
                    span,
                    masks,
                    // The planes are over y-down rows: a sample above the centre is at a smaller py.
                    |i, s| self.z.at(px0 + i as f32 + shifts[s][0], py - shifts[s][1]),
                    |colors| self.shading.span_colors(px0, py, n, colors),
                    |i, j, out| self.varyings.at(px0 + i as f32, py - j as f32, out),
                );
            },
        );
    }

    /// Renders the part of the line inside `area` (within the band) into `band`.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.bounds());
        if area.is_empty() {
            return;
        }
        walk_spans(
            area,
            |y, x0, x1| self.setup.row_span(y, x0, x1),
            |y, x0, x1| self.shade_span(state, band, y, x0, x1, scratch),
        );
    }

    fn shade_span(&self, state: &DrawState, band: &mut Band<'_>, y: i32, x0: i32, x1: i32, scratch: &mut Scratch) {
        let n = (x1 - x0) as usize;
        // Planes are over llvmpipe's y-down pixel coordinates.
        let py = self.setup.row_down(y) as f32;
        let px0 = x0 as f32;
        let row_start = (y - band.y0) as usize * band.width + x0 as usize;
        // Lines are front-facing (GL 2.1 §4.1.5); so are the edges of polygons in GL_LINE mode, as in
        // Mesa 22 (llvmpipe and softpipe), though §4.1.5 gives them their polygon's facing.
        let span = Span { y, x0, n, row_start, front_facing: true };
        shade_span(
            state,
            band,
            scratch,
            span,
            span_mask(n),
            |i| self.z.at(px0 + i as f32, py),
            |colors| self.shading.span_colors(px0, py, n, colors),
            // Planes are over y-down rows: a row above is one less.
            |i, j, out| self.varyings.at(px0 + i as f32, py - j as f32, out),
        );
    }
}
