//! Hierarchical coverage of filled triangles: a tile walked 64 → 16 → 4 on the triangle's
//! exact integer edge functions, handing the fragment stage 4×4 blocks with a 16-bit
//! coverage mask (lane `i` is pixel `(x + (i & 3), y + (i >> 2))`).
//!
//! Each edge is `E(x, y) = c + a·x + b·y` over window pixel coordinates, covered where
//! `E ≥ 0` (the setup folds the pixel centre and the fill rule's bias into `c`, so the
//! coverage is bit for bit `TriangleSetup::covers`). At each level a block is rejected when
//! an edge's largest value over its pixels is negative; an edge whose smallest value is
//! non-negative accepts the block and is not tested again below it, so the inside of a
//! large triangle costs no edge work at all. Only 4×4 blocks with a partial edge evaluate
//! that edge per lane. The values are exact in i64: within the guard band an edge function
//! at any pixel of a framebuffer is below 2⁶³ (`setup::triangle::GUARD_BAND`).
//!
//! Blocks are clipped to the walked area (the tile ∩ scissor ∩ viewport, inside the
//! framebuffer), so a block at the framebuffer's right or top edge carries only its pixels
//! inside; polygon stipple is applied here as a mask. The span walkers ([`super::walk`])
//! remain for lines, points, smooth primitives, pixel rectangles, multisampled targets and
//! the exact accuracy mode.

use super::walk::stipple_mask;
use crate::framebuffer::Rect;

/// One edge function over window pixels: `c + a·x + b·y`, covered where ≥ 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelEdge {
    pub c: i64,
    pub a: i64,
    pub b: i64,
}

impl PixelEdge {
    /// From `[c, a, b]` (`TriangleSetup::pixel_edges`).
    pub fn from_array(e: [i64; 3]) -> Self {
        PixelEdge { c: e[0], a: e[1], b: e[2] }
    }

    #[inline(always)]
    fn at(&self, x: i32, y: i32) -> i64 {
        self.c + self.a * x as i64 + self.b * y as i64
    }
}

/// The coverage mask of the 4×4 block at `(x, y)` cut to the rectangle `area`.
#[inline]
pub fn rect_mask(area: Rect, x: i32, y: i32) -> u16 {
    let mut cols = 0u16;
    for c in 0..4 {
        let px = x + c;
        cols |= ((px >= area.x0 && px < area.x1) as u16) << c;
    }
    let mut mask = 0u16;
    for r in 0..4 {
        let py = y + r;
        if py >= area.y0 && py < area.y1 {
            mask |= cols << (4 * r);
        }
    }
    mask
}

/// Walks the pixels of `area` covered by all three `edges`, calling `emit(x, y, mask)` for
/// every 4×4 block (at multiples of 4) with a covered pixel. `stipple` is the polygon
/// stipple pattern when enabled.
#[inline]
pub fn walk_blocks(area: Rect, edges: &[PixelEdge; 3], stipple: Option<&[u32; 32]>, emit: impl FnMut(i32, i32, u16)) {
    if area.is_empty() {
        return;
    }
    let mut walker = Walker { area, edges, stipple, emit };
    // A small area (a small triangle's box) starts at the smallest aligned block holding it.
    let within = |size: i32| {
        let m = !(size - 1);
        (area.x0 & m) == ((area.x1 - 1) & m) && (area.y0 & m) == ((area.y1 - 1) & m)
    };
    for size in [4, 16] {
        if within(size) {
            let m = !(size - 1);
            return walker.level(size, area.x0 & m, area.y0 & m, 0b111);
        }
    }
    let mut ty = area.y0 & !63;
    while ty < area.y1 {
        let mut tx = area.x0 & !63;
        while tx < area.x1 {
            walker.level(64, tx, ty, 0b111);
            tx += 64;
        }
        ty += 64;
    }
}

struct Walker<'a, F> {
    area: Rect,
    edges: &'a [PixelEdge; 3],
    stipple: Option<&'a [u32; 32]>,
    emit: F,
}

impl<F: FnMut(i32, i32, u16)> Walker<'_, F> {
    /// The block of side `size` at `(x, y)`, with the edges of `partial` (bit k: edge k) not
    /// yet known to accept it.
    #[inline]
    fn level(&mut self, size: i32, x: i32, y: i32, mut partial: u8) {
        let s = (size - 1) as i64;
        for (k, e) in self.edges.iter().enumerate() {
            if partial & (1 << k) == 0 {
                continue;
            }
            let v = e.at(x, y);
            let hi = v + (e.a.max(0) + e.b.max(0)) * s;
            if hi < 0 {
                return;
            }
            let lo = v + (e.a.min(0) + e.b.min(0)) * s;
            if lo >= 0 {
                partial &= !(1 << k);
            }
        }
        if size == 4 {
            return self.block(x, y, partial);
        }
        let sub = size / 4;
        let area = self.area;
        for j in 0..4 {
            let sy = y + j * sub;
            if sy >= area.y1 || sy + sub <= area.y0 {
                continue;
            }
            for i in 0..4 {
                let sx = x + i * sub;
                if sx >= area.x1 || sx + sub <= area.x0 {
                    continue;
                }
                if sub == 4 {
                    self.level4(sx, sy, partial);
                } else {
                    self.level(sub, sx, sy, partial);
                }
            }
        }
    }

    #[inline(never)]
    fn level4(&mut self, x: i32, y: i32, partial: u8) {
        self.level(4, x, y, partial)
    }

    /// A 4×4 block: its lanes tested on the partial edges, cut to the area and the stipple.
    #[inline(always)]
    fn block(&mut self, x: i32, y: i32, partial: u8) {
        let mut mask = 0xffffu16;
        for (k, e) in self.edges.iter().enumerate() {
            if partial & (1 << k) != 0 {
                mask &= lane_mask(e, x, y);
            }
        }
        let area = self.area;
        if x < area.x0 || y < area.y0 || x + 4 > area.x1 || y + 4 > area.y1 {
            mask &= rect_mask(area, x, y);
        }
        if let Some(pattern) = self.stipple {
            let mut bits = 0u16;
            for r in 0..4 {
                bits |= ((stipple_mask(pattern, x, y + r) & 0xf) as u16) << (4 * r);
            }
            mask &= bits;
        }
        if mask != 0 {
            (self.emit)(x, y, mask);
        }
    }
}

/// The lanes of the 4×4 block at `(x, y)` inside edge `e`: each lane's value as the
/// block corner's plus a column and a row step (adds only), its sign bit packed.
#[inline(always)]
fn lane_mask(e: &PixelEdge, x: i32, y: i32) -> u16 {
    let v = e.at(x, y);
    let cols = [v, v + e.a, v + 2 * e.a, v + 3 * e.a];
    let rows = [0, e.b, 2 * e.b, 3 * e.b];
    let mut outside = 0u16;
    for (r, &row) in rows.iter().enumerate() {
        let mut bits = 0u16;
        for (c, &col) in cols.iter().enumerate() {
            bits |= (((col + row) as u64 >> 63) as u16) << c;
        }
        outside |= bits << (4 * r);
    }
    !outside
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rect_mask_cuts_columns_and_rows() {
        let area = Rect { x0: 5, y0: 2, x1: 7, y1: 3 };
        // Block at (4, 0): columns 5 and 6 (lanes 1, 2) of row 2 (lanes 8..12).
        assert_eq!(rect_mask(area, 4, 0), 0b0110 << 8);
        assert_eq!(rect_mask(area, 8, 0), 0);
    }

    #[test]
    fn a_half_plane_is_walked_exactly_with_its_stipple() {
        // x ≥ 10: c + a·x with a = 1, c = −10.
        let e = PixelEdge { c: -10, a: 1, b: 0 };
        let always = PixelEdge { c: 0, a: 0, b: 0 };
        let mut pattern = [0u32; 32];
        pattern[1] = 0x8000_0000 >> 12; // column 12 of rows 1, 33, …
        let mut seen = Vec::new();
        walk_blocks(Rect::from_xywh(0, 0, 16, 2), &[e, always, always], Some(&pattern), |x, y, m| seen.push((x, y, m)));
        // Only pixel (12, 1): block (12, 0), lane 4.
        assert_eq!(seen, [(12, 0, 1 << 4)]);
        let mut count = 0;
        walk_blocks(Rect::from_xywh(0, 0, 70, 3), &[e, always, always], None, |x, _, m| {
            assert!(x >= 8);
            count += m.count_ones();
        });
        assert_eq!(count, 60 * 3);
    }
}
