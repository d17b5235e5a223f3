//! Lines inside one tile: the row spans of a set-up line, its attribute planes evaluated at
//! pixel centres, then the same fragment operations as triangles.
//!
//! Attributes follow llvmpipe's line planes: they vary along the major axis only, linearly
//! in window space for z and perspective-correctly (planes of c/w and 1/w) for colors.
use super::interpolate::{Interpolant, Shading, Varyings};
use super::{shade_span, span_mask, walk_spans, Band, DrawState, Scratch, Span};
use crate::framebuffer::Rect;
use crate::setup::line::{LinePlane, LineSetup};

impl Interpolant for LinePlane {
    #[inline]
    fn at(&self, px: f32, py: f32) -> f32 {
        LinePlane::at(self, px, py)
    }
}

/// How a line's color varies along it (planes over y-down pixel coordinates).
pub type LineShading = Shading<LinePlane>;

/// One endpoint of a line in window space (y down, as the line setup wants it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineVertex {
    pub x: f32,
    pub y_down: f32,
    pub z: f32,
    pub inv_w: f32,
    pub color: [f32; 4],
    /// Read for the varyings a draw needs.
    pub secondary_color: [f32; 4],
    pub tex_coords: [[f32; 4]; crate::context::state::MAX_TEXTURE_UNITS],
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
}

impl LineJob {
    /// Sets up the line `a`–`b` of GL width `width` in a framebuffer `height` rows high;
    /// `flat` is the flat-shading color if flat shaded; `varyings` the values of the draw's
    /// varyings at `a` and `b`. `None` if it draws nothing.
    pub fn new(
        a: &LineVertex,
        b: &LineVertex,
        width: f32,
        height: i32,
        flat: Option<[f32; 4]>,
        varyings: &[[f32; 2]],
    ) -> Option<LineJob> {
        let setup = LineSetup::new([a.x, a.y_down], [b.x, b.y_down], width, height)?;
        let g = setup.gradient;
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
        let over_w = varyings.iter().map(|v| g.plane(v[0] * a.inv_w, v[1] * b.inv_w)).collect();
        let varyings = Varyings::new(over_w, g.plane(a.inv_w, b.inv_w));
        Some(LineJob { setup, z, shading, varyings })
    }

    pub fn setup(&self) -> &LineSetup {
        &self.setup
    }

    /// The pixel rectangle that may contain covered pixels.
    pub fn bounds(&self) -> Rect {
        self.setup.bounds
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
