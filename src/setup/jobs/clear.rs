//! Clears recorded in the scene: glClear becomes a bin entry of every tile it touches, and
//! each tile's worker clears its own pixels when it renders that tile, in submission order
//! with the draws around it. No whole-buffer pass runs before the scene, a tile that a
//! later opaque triangle covers drops the color clear with its other earlier work (see
//! `Scene::add`), and the pages of a fresh buffer are first touched by the worker that
//! owns them.
//!
//! A clear is recorded as up to two jobs: one for the color buffers and one for depth and
//! stencil, so that dropping a tile's color work keeps its depth/stencil clear.

use crate::framebuffer::band::Band;
use crate::framebuffer::surface::{clear_color_band, clear_depth_band};
use crate::framebuffer::{ColorSlot, Rect};

/// One color buffer a clear writes: its slot, the clear color as set (fixed-point buffers
/// clamp it when the clear runs) and the channels written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColorClear {
    pub slot: ColorSlot,
    pub color: [f32; 4],
    pub mask: [bool; 4],
}

/// A clear of the pixels of `rect`.
#[derive(Clone, Debug, PartialEq)]
pub struct ClearJob {
    pub rect: Rect,
    /// Whether `rect` is the whole framebuffer (the encoding of a whole-buffer clear can
    /// differ from that of a partial one: `framebuffer::surface::clear_color_band`).
    pub whole: bool,
    pub colors: Vec<ColorClear>,
    /// The depth value, when depth is cleared.
    pub depth: Option<f64>,
    /// The stencil value and write mask, when stencil is cleared.
    pub stencil: Option<(u8, u8)>,
}

impl ClearJob {
    /// Whether this job clears only depth and stencil (kept when a tile's color work is
    /// dropped).
    pub fn depth_stencil_only(&self) -> bool {
        self.colors.is_empty()
    }

    /// Clears the part of `rect` inside `area` (within the band).
    pub fn render(&self, area: Rect, band: &mut Band<'_>) {
        let area = area.intersect(self.rect);
        if area.is_empty() {
            return;
        }
        let (width, y0) = (band.width, band.y0);
        for target in &mut band.colors {
            for c in self.colors.iter().filter(|c| c.slot == target.slot) {
                let whole = self.whole && c.mask.iter().all(|&m| m);
                // ARB_color_buffer_float: fragment color clamping does not apply to clears;
                // only fixed-point buffers clamp the clear color (as Mesa).
                let color = if target.format.is_float() { c.color } else { c.color.map(|v| v.clamp(0.0, 1.0)) };
                clear_color_band(&mut target.pixels, target.format, width, y0, area, color, c.mask, whole);
            }
        }
        if self.depth.is_some() || self.stencil.is_some() {
            let format = band.depth_format;
            clear_depth_band(&mut band.depth, format, width, y0, area, self.depth, self.stencil, self.whole);
            if let Some(depth) = self.depth {
                band.hiz_cleared(area, depth, self.whole);
            }
        }
    }
}
