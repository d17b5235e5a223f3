//! Hierarchical z: per band, an upper bound of the stored depth of each 16×16 region, so
//! that a triangle drawn with GL_LESS or GL_LEQUAL skips the regions where its nearest
//! fragment cannot pass before any block of them is walked (`setup::jobs::triangle`).
//!
//! The summary lives in the band (`Band::hiz`), so it exists only while one scene renders:
//! it starts unknown (bound `u32::MAX`, loose) and is read from the depth buffer the first
//! time a region is asked about, which makes it exact whatever wrote the buffer between
//! scenes (blits, glDrawPixels, texture uploads into a depth attachment, the caller).
//! Inside a scene, every job that may write depth tells the band (`Band::hiz_written`):
//! a depth test that only lets nearer or equal values through (LESS, LEQUAL, EQUAL,
//! NEVER) keeps every bound valid, only looser; anything else (GREATER, ALWAYS, pixel
//! rectangles) forgets the bounds it may have raised. Clears set them exactly.
//!
//! A rejected region is one where every fragment fails the depth test: the bound `B` is
//! at least every stored value, the fragment depths at least `F` (the plane's minimum over
//! the region's pixel centres, lowered by more than the single-precision evaluation's
//! error, then encoded as the depth test encodes, which is monotonic), so `F ≥ B` (LESS)
//! or `F > B` (LEQUAL) means no fragment passes. The caller rejects only when failing
//! changes nothing (no stencil operation on failure, no shader depth), so the bytes are
//! those of testing every fragment; an occlusion query counts no passing fragment either
//! way.

use super::band::{Band, DepthBand};
use super::surface::depth_clear_value;
use super::Rect;

/// The side of a region, in pixels (regions are aligned to multiples of it in the band).
pub const REGION: i32 = 16;

/// The summary of one band ([`crate::framebuffer::band::Band::hiz`]); empty until first used.
#[derive(Default, Debug)]
pub struct HiZ {
    /// Regions per row of regions (0: not set up).
    columns: usize,
    /// Per region (row-major from the band's first row): at least the stored depth (its
    /// bits as the depth test compares them, stencil excluded) of each of its pixels.
    bound: Vec<u32>,
    /// Per region: whether the bound may exceed the largest stored depth (a scan of the
    /// region makes it exact).
    loose: Vec<bool>,
    /// Per region: a depth the stored ones are thought to be at least (0: unknown), which
    /// only decides whether a loose region is worth a scan: a primitive whose nearest
    /// fragment is no farther than it likely passes somewhere. Never used to reject.
    floor: Vec<u32>,
    /// The area of the last primitive [`Band::hiz_rejected`] tested and its lowest encoded
    /// depth per region (4 × 4, as its bits), for its own depth write that follows.
    last: Option<(Rect, [u32; 16])>,
}

/// A depth test that hierarchical z can reject regions for: GL_LESS or GL_LEQUAL.
#[derive(Clone, Copy, Debug)]
pub struct DepthReject {
    /// GL_LEQUAL (equal depths pass) rather than GL_LESS.
    pub equal_passes: bool,
    /// GL_DEPTH_CLAMP's range, applied to fragment depths before the test.
    pub clamp: Option<[f32; 2]>,
}

/// A linear depth over window space: `a0 + dadx·(x − anchor.x) + dady·(y − anchor.y)` at
/// pixel centres, evaluated in single precision by the caller's lanes.
#[derive(Clone, Copy, Debug)]
pub struct DepthPlane {
    pub a0: f32,
    pub dadx: f32,
    pub dady: f32,
    pub anchor: [f32; 2],
}

impl DepthPlane {
    /// A depth no fragment at a pixel centre of `rect` falls below when the plane is
    /// evaluated in single precision (`None` when the plane is not finite).
    pub fn lowest(&self, rect: Rect) -> Option<f32> {
        let (a0, dadx, dady) = (self.a0 as f64, self.dadx as f64, self.dady as f64);
        let dx = [rect.x0 as f64 + 0.5 - self.anchor[0] as f64, rect.x1 as f64 - 0.5 - self.anchor[0] as f64];
        let dy = [rect.y0 as f64 + 0.5 - self.anchor[1] as f64, rect.y1 as f64 - 0.5 - self.anchor[1] as f64];
        let low = a0 + (dadx * dx[0]).min(dadx * dx[1]) + (dady * dy[0]).min(dady * dy[1]);
        // The lanes' f32 arithmetic (offsets, two products, two sums) errs by at most about
        // 4·2⁻²⁴ of the magnitudes involved; 1e-6 of them is four times that.
        let magnitude =
            a0.abs() + dadx.abs() * dx[0].abs().max(dx[1].abs()) + dady.abs() * dy[0].abs().max(dy[1].abs());
        let low = low - 1e-6 * magnitude - 1e-30;
        (low.is_finite() && magnitude < 1e30).then_some(low as f32)
    }
}

impl HiZ {
    /// The regions of a band `width` × `rows`, all unknown.
    fn set_up(&mut self, width: usize, rows: usize) {
        let r = REGION as usize;
        self.columns = width.div_ceil(r);
        let count = self.columns * rows.div_ceil(r);
        self.bound = vec![u32::MAX; count];
        self.loose = vec![true; count];
        self.floor = vec![0; count];
    }
}

/// The largest stored depth of `rect` (band-relative rows) of `depth`, as the depth test
/// compares it; `u32::MAX` for a band without depth.
fn scan(depth: &DepthBand<'_>, width: usize, rect: Rect) -> u32 {
    match depth {
        DepthBand::None => u32::MAX,
        DepthBand::Depth16(px) => scan_rows(px, width, rect, i32::from) as u32,
        DepthBand::Packed24(px) => scan_rows(px, width, rect, |v| (v & 0x00ff_ffff) as i32) as u32,
        // Halved so that the baseline's signed lane maximum applies (SSE2 has no unsigned
        // one); the bound rounds back up: at least every value, at most one step above.
        DepthBand::Depth32(px, _) | DepthBand::Float32(px, _) => {
            ((scan_rows(px, width, rect, |v| (v >> 1) as i32) as u32) << 1) | 1
        }
    }
}

/// The largest `key` of the pixels of `rect` (band-relative rows) of `px`: a whole region's
/// rows as 16 lanes of running maxima (a few vector instructions a row), others one by one.
#[inline(always)]
fn scan_rows<T: Copy>(px: &[T], width: usize, rect: Rect, key: impl Fn(T) -> i32) -> i32 {
    let (x0, x1) = (rect.x0 as usize, rect.x1 as usize);
    let rows = rect.y0 as usize..rect.y1 as usize;
    let mut lanes = [0i32; REGION as usize];
    if x1 - x0 == REGION as usize {
        for y in rows {
            let row: &[T; REGION as usize] = px[y * width + x0..][..REGION as usize].try_into().expect("16 pixels");
            for (m, &v) in lanes.iter_mut().zip(row) {
                *m = (*m).max(key(v));
            }
        }
    } else {
        for y in rows {
            for &v in &px[y * width + x0..y * width + x1] {
                lanes[0] = lanes[0].max(key(v));
            }
        }
    }
    lanes.into_iter().fold(0, i32::max)
}

impl Band<'_> {
    /// Whether this band keeps a summary (single-sampled with depth bits), setting it up
    /// on first use.
    fn hiz_ready(&mut self) -> bool {
        if self.samples != 1 || self.depth_format.depth_bits() == 0 || matches!(self.depth, DepthBand::None) {
            return false;
        }
        if self.hiz.columns == 0 {
            self.hiz.set_up(self.width, self.rows);
        }
        true
    }

    /// The band's pixels of region `(rx, ry)` (window coordinates).
    fn region_rect(&self, rx: usize, ry: usize) -> Rect {
        let r = REGION;
        let region = Rect::from_xywh(rx as i32 * r, self.y0 + ry as i32 * r, r, r);
        region.intersect(Rect::from_xywh(0, self.y0, self.width as i32, self.rows as i32))
    }

    /// The regions `rect` (window coordinates, clipped to the band) touches: columns and
    /// rows of regions, half-open.
    fn regions_of(&self, rect: Rect) -> Option<([usize; 2], [usize; 2])> {
        let rect = rect.intersect(Rect::from_xywh(0, self.y0, self.width as i32, self.rows as i32));
        if rect.is_empty() {
            return None;
        }
        let r = REGION;
        let columns = [(rect.x0 / r) as usize, (rect.x1 + r - 1) as usize / r as usize];
        let rows = [((rect.y0 - self.y0) / r) as usize, (rect.y1 - self.y0 + r - 1) as usize / r as usize];
        Some((columns, rows))
    }

    /// `rect` was cleared to depth `depth` (`whole`: a whole-buffer clear, whose encoding
    /// may differ, see `surface::depth_clear_value`).
    pub fn hiz_cleared(&mut self, rect: Rect, depth: f64, whole: bool) {
        if !self.hiz_ready() {
            return;
        }
        let Some((columns, rows)) = self.regions_of(rect) else { return };
        let value = depth_clear_value(self.depth_format, whole, depth);
        for ry in rows[0]..rows[1] {
            for rx in columns[0]..columns[1] {
                let region = self.region_rect(rx, ry);
                let i = ry * self.hiz.columns + rx;
                if region.intersect(rect) == region {
                    self.hiz.bound[i] = value;
                    self.hiz.loose[i] = false;
                    self.hiz.floor[i] = value;
                } else {
                    self.hiz.bound[i] = self.hiz.bound[i].max(value);
                    self.hiz.loose[i] = true;
                    self.hiz.floor[i] = self.hiz.floor[i].min(value);
                }
            }
        }
    }

    /// A job may have written depth inside `rect`: only nearer or equal values
    /// (`only_nearer`: its depth test is LESS, LEQUAL, EQUAL or NEVER), or any.
    pub fn hiz_written(&mut self, rect: Rect, only_nearer: bool) {
        if self.hiz.columns == 0 {
            return; // Nothing known yet: nothing to forget.
        }
        let Some((columns, rows)) = self.regions_of(rect) else { return };
        // The writer's own nearest depths, when it was the primitive tested last.
        let lows = self.hiz.last.take().filter(|(area, _)| *area == rect && only_nearer).map(|(_, lows)| lows);
        for ry in rows[0]..rows[1] {
            for rx in columns[0]..columns[1] {
                let i = ry * self.hiz.columns + rx;
                self.hiz.loose[i] = true;
                if !only_nearer {
                    self.hiz.bound[i] = u32::MAX;
                }
                let k = 4 * (ry - rows[0]) + rx - columns[0];
                self.hiz.floor[i] = match lows {
                    Some(lows) if k < 16 => self.hiz.floor[i].min(lows[k]),
                    _ => 0,
                };
            }
        }
    }

    /// [`Band::hiz_written`] for each of `rects` in order, all inside `area` (a run of small
    /// triangles in a tile, `setup::scene`): the first as that call, then, the writer's own
    /// depths no longer known (the first call took them), each region the others touch
    /// marked once, not once per triangle (most touch the regions the ones before them did).
    pub fn hiz_written_within(&mut self, area: Rect, rects: impl IntoIterator<Item = Rect>, only_nearer: bool) {
        let mut rects = rects.into_iter();
        let Some(first) = rects.next() else { return };
        self.hiz_written(first, only_nearer);
        if self.hiz.columns == 0 {
            return;
        }
        let Some((columns, rows)) = self.regions_of(area) else { return };
        if columns[1] - columns[0] > 8 || rows[1] - rows[0] > 8 {
            return rects.for_each(|r| self.hiz_written(r, only_nearer));
        }
        // The regions touched, bit `8·row + column` from the area's first region.
        let mut touched = 0u64;
        for rect in rects {
            let Some(([c0, c1], [r0, r1])) = self.regions_of(rect) else { continue };
            let row_bits = (1u64 << (c1 - columns[0])) - (1u64 << (c0 - columns[0]));
            for ry in r0..r1 {
                touched |= row_bits << (8 * (ry - rows[0]));
            }
        }
        while touched != 0 {
            let bit = touched.trailing_zeros() as usize;
            touched &= touched - 1;
            let i = (rows[0] + bit / 8) * self.hiz.columns + columns[0] + bit % 8;
            self.hiz.loose[i] = true;
            if !only_nearer {
                self.hiz.bound[i] = u32::MAX;
            }
            self.hiz.floor[i] = 0;
        }
    }

    /// Whether no fragment of a primitive whose depth is at least `low` (an encoded depth,
    /// see the module) over `part` (inside region `(rx, ry)`) can pass `test`. A loose
    /// bound is made exact first when `part` is the whole region (a primitive covering
    /// less would pay a scan for few fragments).
    fn hiz_rejects(&mut self, rx: usize, ry: usize, part: Rect, low: u32, test: DepthReject) -> bool {
        let fails = |bound: u32| if test.equal_passes { low > bound } else { low >= bound };
        let i = ry * self.hiz.columns + rx;
        if fails(self.hiz.bound[i]) {
            return true;
        }
        let region = self.region_rect(rx, ry);
        if !self.hiz.loose[i] || part != region || low <= self.hiz.floor[i] {
            return false;
        }
        let local = Rect { y0: region.y0 - self.y0, y1: region.y1 - self.y0, ..region };
        self.hiz.bound[i] = scan(&self.depth, self.width, local);
        self.hiz.loose[i] = false;
        fails(self.hiz.bound[i])
    }

    /// The regions of `area` (inside the band, at most 4 × 4 regions) where no fragment
    /// of a primitive of depth `plane` drawn with `test` passes: bit `4·row + column`
    /// counted from `area`'s first region ([`visible_parts`] walks the rest).
    pub fn hiz_rejected(&mut self, area: Rect, plane: &DepthPlane, test: DepthReject) -> u16 {
        self.hiz.last = None;
        let Some((columns, rows)) = self.regions_of(area).filter(|_| self.hiz_ready()) else {
            return 0;
        };
        if columns[1] - columns[0] > 4 || rows[1] - rows[0] > 4 {
            return 0;
        }
        let encoding = self.depth_format.depth_encoding();
        let mut rejected = 0u16;
        let mut lows = [0u32; 16];
        for ry in rows[0]..rows[1] {
            for rx in columns[0]..columns[1] {
                let part = self.region_rect(rx, ry).intersect(area);
                let Some(mut low) = plane.lowest(part) else { return 0 };
                if let Some([lo, hi]) = test.clamp {
                    low = low.clamp(lo, hi);
                }
                let (low, k) = (encoding.encode_fragment(low), 4 * (ry - rows[0]) + rx - columns[0]);
                lows[k] = low;
                if self.hiz_rejects(rx, ry, part, low, test) {
                    rejected |= 1 << k;
                }
            }
        }
        self.hiz.last = Some((area, lows));
        rejected
    }
}

/// The parts of `area` outside the `rejected` regions ([`Band::hiz_rejected`] of that area):
/// `area` itself when none is, else per row of regions the runs of the others, cut to
/// `area`. (Bands start at multiples of [`REGION`] rows, so regions are aligned in window
/// coordinates too.) Returned as a list rather than handed to a callback so that the caller
/// walks them from one call site: a walk called from two sites was compiled as a separate
/// function without the caller's SIMD level (and with a third copy of the colour stage).
#[inline(always)]
pub fn visible_parts(area: Rect, rejected: u16) -> Parts {
    let mut parts = Parts { rects: [Rect::default(); MAX_PARTS], len: 0 };
    if rejected == 0 {
        parts.rects[0] = area;
        parts.len = 1;
        return parts;
    }
    let (rx0, ry0) = (area.x0.div_euclid(REGION), area.y0.div_euclid(REGION));
    let (rx1, ry1) = ((area.x1 + REGION - 1).div_euclid(REGION), (area.y1 + REGION - 1).div_euclid(REGION));
    let is_rejected = |rx: i32, ry: i32| rejected & (1 << (4 * (ry - ry0) + rx - rx0)) != 0;
    for ry in ry0..ry1 {
        let mut rx = rx0;
        while rx < rx1 {
            if is_rejected(rx, ry) {
                rx += 1;
                continue;
            }
            let start = rx;
            while rx < rx1 && !is_rejected(rx, ry) {
                rx += 1;
            }
            let run = Rect { x0: start * REGION, x1: rx * REGION, y0: ry * REGION, y1: (ry + 1) * REGION };
            parts.rects[parts.len] = run.intersect(area);
            parts.len += 1;
        }
    }
    parts
}

/// The most parts [`visible_parts`] hands out: an area of at most 4 × 4 regions (the `u16`
/// of rejected regions) has at most two runs per row of regions.
const MAX_PARTS: usize = 8;

/// The rectangles of [`visible_parts`].
#[derive(Clone, Copy, Debug)]
pub struct Parts {
    rects: [Rect; MAX_PARTS],
    len: usize,
}

impl Parts {
    pub fn as_slice(&self) -> &[Rect] {
        &self.rects[..self.len]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::DepthStencilFormat;

    fn band(depth: &mut [u32], width: usize, rows: usize) -> Band<'_> {
        Band {
            y0: 64,
            rows,
            width,
            samples: 1,
            colors: Vec::new(),
            depth: DepthBand::Packed24(depth),
            depth_format: DepthStencilFormat::Packed24 { depth: true, stencil: true },
            hiz: HiZ::default(),
        }
    }

    /// The rectangles `hiz_rejected` and `visible_parts` hands out for a flat plane at `z` over `area`.
    fn visible(band: &mut Band<'_>, area: Rect, z: f32, equal_passes: bool) -> Vec<Rect> {
        let plane = DepthPlane { a0: z, dadx: 0.0, dady: 0.0, anchor: [0.0, 0.0] };
        let rejected = band.hiz_rejected(area, &plane, DepthReject { equal_passes, clamp: None });
        visible_parts(area, rejected).as_slice().to_vec()
    }

    const HALF: u32 = 0x80_0000; // 0.5 in 24 bits (0.5 · (2²⁴ − 1) rounded to even)

    #[test]
    fn regions_are_rejected_only_where_every_stored_depth_is_nearer() {
        let (width, rows) = (40, 20); // partial regions at the right and top edges
        let mut depth = vec![0xff00_0000 | HALF; width * rows];
        // One pixel of region (1, 0) holds the far plane: that region must stay visible.
        depth[5 * width + 20] = 0xff00_0000 | 0xff_ffff;
        let mut band = band(&mut depth, width, rows);
        let area = Rect { x0: 0, y0: 64, x1: 40, y1: 84 };
        assert_eq!(fragment_depth(0.5), HALF, "the test's encoding");
        // LESS a little farther than the stored depths fails everywhere but region (1, 0).
        assert_eq!(visible(&mut band, area, 0.501, false), vec![Rect { x0: 16, y0: 64, x1: 32, y1: 80 }]);
        // At exactly the stored depth nothing is rejected: the plane's evaluation error is
        // allowed for (rejecting there is not needed for the bytes to be right).
        assert_eq!(visible(&mut band, area, 0.5, false), vec![area]);
        assert_eq!(visible(&mut band, area, 0.5, true), vec![area]);
        // Nearer fragments: nothing rejected.
        assert_eq!(visible(&mut band, area, 0.49, false), vec![area]);
        // A part of the area only: the same regions, cut to it.
        let part = Rect { x0: 10, y0: 70, x1: 30, y1: 84 };
        assert_eq!(visible(&mut band, part, 0.501, false), vec![Rect { x0: 16, y0: 70, x1: 30, y1: 80 }]);
    }

    fn fragment_depth(z: f32) -> u32 {
        DepthStencilFormat::Packed24 { depth: true, stencil: true }.depth_encoding().encode_fragment(z)
    }

    #[test]
    fn writes_and_clears_keep_the_bounds_above_the_stored_depths() {
        let (width, rows) = (32, 16);
        let mut depth = vec![HALF; width * rows];
        let mut band = band(&mut depth, width, rows);
        let area = Rect { x0: 0, y0: 64, x1: 32, y1: 80 };
        assert_eq!(visible(&mut band, area, 0.75, false), vec![], "all stored depths are nearer");
        // A write that may raise depths (GL_ALWAYS) in region 1: it must be looked at again.
        if let DepthBand::Packed24(px) = &mut band.depth {
            px[3 * width + 17] = 0xff_ffff;
        }
        band.hiz_written(Rect { x0: 17, y0: 67, x1: 18, y1: 68 }, false);
        assert_eq!(visible(&mut band, area, 0.75, false), vec![Rect { x0: 16, y0: 64, x1: 32, y1: 80 }]);
        // A clear of part of region 0 to the far plane keeps it visible; of all of it, too.
        band.hiz_cleared(Rect { x0: 0, y0: 64, x1: 4, y1: 66 }, 1.0, false);
        if let DepthBand::Packed24(px) = &mut band.depth {
            px[0] = 0xff_ffff;
        }
        assert_eq!(visible(&mut band, area, 0.75, false), vec![area]);
        band.hiz_cleared(Rect { x0: 0, y0: 64, x1: 32, y1: 80 }, 0.25, true);
        if let DepthBand::Packed24(px) = &mut band.depth {
            px.fill(0x40_0000);
        }
        assert_eq!(visible(&mut band, area, 0.75, false), vec![]);
        assert_eq!(visible(&mut band, area, 0.2, false), vec![area]);
    }

    #[test]
    fn the_lowest_depth_is_below_every_lane_value() {
        let plane = DepthPlane { a0: 0.3, dadx: 1.0 / 3000.0, dady: -1.0 / 7000.0, anchor: [100.25, 3.75] };
        let rect = Rect { x0: 96, y0: 0, x1: 112, y1: 16 };
        let low = plane.lowest(rect).unwrap();
        for y in rect.y0..rect.y1 {
            for x in rect.x0..rect.x1 {
                let (dx, dy) = (x as f32 + 0.5 - plane.anchor[0], y as f32 + 0.5 - plane.anchor[1]);
                let z = plane.a0 + plane.dadx * dx + plane.dady * dy;
                assert!(low <= z, "{low} > {z} at ({x}, {y})");
            }
        }
        // … and close to the true minimum (the corner (96.5, 15.5)).
        let corner = 0.3 + (96.5 - 100.25) / 3000.0 - (15.5 - 3.75) / 7000.0;
        assert!((low as f64 - corner).abs() < 1e-5);
        let infinite = DepthPlane { a0: f32::INFINITY, ..plane };
        assert_eq!(infinite.lowest(rect), None);
    }

    #[test]
    fn written_within_an_area_marks_what_each_write_would() {
        // Two bands, one told of each rectangle in turn, the other of all of them at once;
        // both first made exact (not loose, floors known) by a clear, then the first
        // rectangle tested (its own depths kept for its write).
        let (width, rows) = (80, 64);
        let area = Rect { x0: 8, y0: 70, x1: 72, y1: 128 };
        let rects = [
            Rect { x0: 8, y0: 70, x1: 12, y1: 75 },
            Rect { x0: 13, y0: 74, x1: 20, y1: 79 },
            Rect { x0: 30, y0: 96, x1: 34, y1: 101 },
            Rect { x0: 31, y0: 95, x1: 50, y1: 98 },
            Rect { x0: 60, y0: 120, x1: 72, y1: 128 },
        ];
        for only_nearer in [true, false] {
            let (mut one, mut all) = (vec![0xff00_0000 | HALF; width * rows], vec![0xff00_0000 | HALF; width * rows]);
            let (mut each, mut within) = (band(&mut one, width, rows), band(&mut all, width, rows));
            for b in [&mut each, &mut within] {
                let plane = DepthPlane { a0: 0.25, dadx: 0.0, dady: 0.0, anchor: [0.0, 0.0] };
                b.hiz_cleared(Rect { x0: 0, y0: 64, x1: 80, y1: 128 }, 0.5, false);
                b.hiz_rejected(rects[0], &plane, DepthReject { equal_passes: false, clamp: None });
            }
            for r in rects {
                each.hiz_written(r, only_nearer);
            }
            within.hiz_written_within(area, rects, only_nearer);
            assert_eq!(each.hiz.loose, within.hiz.loose);
            assert_eq!(each.hiz.bound, within.hiz.bound);
            assert_eq!(each.hiz.floor, within.hiz.floor);
            // Something was marked (the test can fail): the regions of the rectangles only.
            assert!(within.hiz.loose.iter().any(|&l| l) && !within.hiz.loose.iter().all(|&l| l));
        }
    }
}
