//! Points inside one tile: an aliased point is a square of pixels with one depth and one
//! color, so every row of it is a constant span.
use super::{span_mask, write_span_colors, Band, DrawState, Scratch};
use crate::fragment::{depth_test, MAX_SPAN};
use crate::framebuffer::Rect;

/// A set-up point: its pixels, its window z and its color.
#[derive(Clone, Debug)]
pub struct PointJob {
    pub rect: Rect,
    pub z: f32,
    pub color: [f32; 4],
}

impl PointJob {
    pub fn bounds(&self) -> Rect {
        self.rect
    }

    /// Renders the part of the point inside `area` (within the band) into `band`.
    pub fn render(&self, state: &DrawState, area: Rect, band: &mut Band<'_>, scratch: &mut Scratch) {
        let area = area.intersect(self.rect);
        if area.is_empty() {
            return;
        }
        let fragment = &state.fragment;
        for y in area.y0..area.y1 {
            let mut x0 = area.x0;
            while x0 < area.x1 {
                let x1 = (x0 + MAX_SPAN as i32).min(area.x1);
                let n = (x1 - x0) as usize;
                let row_start = (y - band.y0) as usize * band.width + x0 as usize;
                let mut live = span_mask(n);
                if let Some(test) = &fragment.depth {
                    scratch.z.clear();
                    scratch.z.resize(n, self.z);
                    live = depth_test(test, &mut band.depth, row_start, &scratch.z, live);
                }
                if live != 0 {
                    scratch.colors.clear();
                    scratch.colors.resize(n, self.color);
                    write_span_colors(fragment, band, row_start, &scratch.colors, live);
                }
                x0 = x1;
            }
        }
    }
}
