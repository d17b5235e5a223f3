//! Hierarchical coverage of filled triangles: a tile walked 64 → 16 → 4 on the triangle's
//! exact integer edge functions, handing the fragment stage 4×4 blocks with a 16-bit
//! coverage mask (lane `i` is pixel `(x + (i & 3), y + (i >> 2))`).
//!
//! Each edge is `E(x, y) = c + a·x + b·y` over window pixel coordinates, covered where
//! `E ≥ 0` (the setup folds the pixel centre and the fill rule's bias into `c`, so the
//! coverage is bit for bit `TriangleSetup::covers`). Each level tests the 16 sub-blocks
//! of a block at once, as 16 lanes, on all three edges: a sub-block is skipped when an
//! edge's largest value over its pixels is negative, and known inside when every edge's
//! smallest value is non-negative, so the inside of a large triangle costs no edge work
//! below the level where it became inside. A 4×4 block that is neither evaluates its 16
//! pixels as lanes. A triangle whose pixels lie within the 16×16 pixels from its first
//! aligned 4×4 block starts there, one within 6 blocks or one block at its blocks' pixels
//! (small triangles pay for neither the upper levels nor a tile's loops). A lane mask's
//! signs are gathered by movemask (`simd::dispatch::sign_mask16`), at the caller's level.
//!
//! **Exact in 32-bit lanes.** The values are exact integers. An edge's `a` and `b` are
//! multiples of 256 (the setup's pixel-unit coefficients of 1/256-pixel coordinates);
//! with `2^s` the largest power of two dividing both, `E ≥ 0 ⇔ ⌊E/2^s⌋ ≥ 0` and
//! `⌊E/2^s⌋ = ⌊c/2^s⌋ + (a/2^s)·x + (b/2^s)·y` exactly ([`Reduced`]), which takes 8 bits
//! off. Then every value the walk of a tile computes is `B + o`: `B` the reduced edge at
//! the tile's (or a small area's first block's) corner, evaluated once in i64, and `o` a sum
//! of steps with `|o| ≤ 63·M`, `M = |a'| + |b'|` (a pixel is at most 63 columns and 63
//! rows from its tile's corner; the largest-value corner of a sub-block too). The walk
//! clamps `B` to `[−K, K]` with `K = 64·M + 1` before adding the steps: when `|B| ≤ K`
//! nothing changes; when `B > K` both the exact value and the computed one are at least
//! `K − 63·M ≥ 1`, and symmetrically below `−K`, so every sign, which is all the walk
//! reads, is the exact one. When every edge has `M ≤ 2²⁴` (edges shorter than about 65 000
//! pixels: `M` is 256 times the edge's extent in pixels), `K + 63·M < 2³¹` and the lanes
//! are i32; otherwise (triangles reaching towards the guard band) they are i64, with no
//! clamp needed: within the guard band every value at a framebuffer pixel is below 2⁶³
//! (`setup::triangle::GUARD_BAND`). The choice is made per triangle; both give the same
//! coverage.
//!
//! Blocks are clipped to the walked area (the tile ∩ scissor ∩ viewport, inside the
//! framebuffer), so a block at the framebuffer's right or top edge carries only its pixels
//! inside; polygon stipple is applied here as a mask. Everything here is `#[inline(always)]`
//! so that the caller's per-level copy (`crate::simd`) compiles the walk and the block
//! handler together, once per SIMD level. Multisampled triangles walk here too, on edges
//! widened to their outermost samples, each block then masked per sample
//! ([`super::samples`]). The span walkers ([`super::walk`]) remain for lines, points, smooth
//! primitives, pixel rectangles, multisampled draws with alpha-to-coverage or depth clamping,
//! and the exact accuracy mode.

use super::walk::stipple_mask;
use crate::framebuffer::Rect;
use crate::simd::dispatch::{edge_steps16, inside_mask16, sign_mask16};
use crate::simd::Supported;
use std::ops::{Add, BitOr};

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
}

/// The coverage mask of the 4×4 block at `(x, y)` cut to the rectangle `area`, without a
/// loop: the columns inside as 4 bits copied to each row's nibble, the rows inside as whole
/// nibbles.
#[inline(always)]
pub fn rect_mask(area: Rect, x: i32, y: i32) -> u16 {
    // Bits `lo..hi` of 4 (clamped), in steps of `unit` bits.
    let run = |lo: i32, hi: i32, unit: i32| {
        let (lo, hi) = (lo.clamp(0, 4), hi.clamp(0, 4));
        if hi > lo {
            (1u32 << (unit * hi)) - (1u32 << (unit * lo))
        } else {
            0
        }
    };
    let cols = run(area.x0 - x, area.x1 - x, 1);
    let rows = run(area.y0 - y, area.y1 - y, 4);
    ((cols * 0x1111) & rows) as u16
}

/// Walks the pixels of `area` covered by all three `edges`, calling `emit(x, y, mask)` for
/// every 4×4 block (at multiples of 4) with a covered pixel. `stipple` is the polygon
/// stipple pattern when enabled; `level` the SIMD level of the caller's copy (the lanes'
/// signs are gathered by movemask).
#[inline(always)]
pub fn walk_blocks(
    level: Supported,
    area: Rect,
    edges: &[PixelEdge; 3],
    stipple: Option<&[u32; 32]>,
    emit: impl FnMut(i32, i32, u16),
) {
    walk_blocks_filling(level, area, edges, stipple, emit, None::<fn(Rect)>);
}

/// [`walk_blocks`], but where `fill` is given and there is no stipple, the parts of `area`
/// the triangle covers whole (a tile, a 16×16 block or a 4×4 block all of whose pixels are
/// inside every edge, cut to `area`) go to `fill` as rectangles instead of to `emit` as
/// blocks: a primitive whose fragments all store one value (a constant fill) writes them
/// as rows, with no per-block work. Every covered pixel goes to exactly one of the two.
#[inline(always)]
pub fn walk_blocks_filling(
    level: Supported,
    area: Rect,
    edges: &[PixelEdge; 3],
    stipple: Option<&[u32; 32]>,
    emit: impl FnMut(i32, i32, u16),
    fill: Option<impl FnMut(Rect)>,
) {
    if area.is_empty() {
        return;
    }
    let fill = fill.filter(|_| stipple.is_none());
    let reduced = map3(*edges, |e| Reduced::new(&e));
    if reduced.iter().all(|e| e.a.unsigned_abs() + e.b.unsigned_abs() <= 1 << 24) {
        Walker::<i32, _, _>::new(level, area, reduced, stipple, emit, fill).run();
    } else {
        Walker::<i64, _, _>::new(level, area, reduced, stipple, emit, fill).run();
    }
}

/// An edge divided by the largest power of two dividing both `a` and `b` (see the module):
/// `⌊E/2^s⌋`, whose sign is `E`'s at every pixel.
#[derive(Clone, Copy, Debug)]
struct Reduced {
    c: i64,
    a: i64,
    b: i64,
}

impl Reduced {
    #[inline(always)]
    fn new(e: &PixelEdge) -> Self {
        // Both zero (a constant edge): any shift below 63 keeps the sign of c.
        let s = (e.a | e.b).trailing_zeros().min(62);
        Reduced { c: e.c >> s, a: e.a >> s, b: e.b >> s }
    }

    #[inline(always)]
    fn at(&self, x: i32, y: i32) -> i64 {
        self.c + self.a * x as i64 + self.b * y as i64
    }

    /// `M = |a| + |b|`: how much the edge changes from one pixel to the next, at most.
    #[inline(always)]
    fn steepness(&self) -> i64 {
        self.a.abs() + self.b.abs()
    }
}

/// The integer type of the walk's lanes: i32 when every value fits (see the module), i64
/// otherwise.
trait Lane: Copy + Default + Add<Output = Self> + BitOr<Output = Self> {
    /// `v` clamped to `[−k, k]` (i32), or `v` (i64, where nothing needs clamping).
    fn clamped(v: i64, k: i64) -> Self;
    /// `v`, which fits.
    fn exact(v: i64) -> Self;
    /// 1 when negative, else 0.
    fn sign(self) -> u16;
    /// `self · k` for a small `k` (which fits).
    fn times(self, k: i32) -> Self;
    /// `self · 2^n` (which fits).
    fn shl(self, n: u32) -> Self;
    /// The negative lanes of `v` as a mask (lane `i` as bit `i`).
    fn negatives(level: Supported, v: &Lanes<Self>) -> u16;
    /// An edge's steps `a·column + b·row` over the 16 lanes ([`steps`]).
    #[inline(always)]
    fn steps(_: Supported, a: Self, b: Self) -> Lanes<Self> {
        steps(a, b)
    }
    /// The lanes `i` (as bit `i`) inside all three edges: `base[k] + steps[k][i]` not
    /// negative for every `k`, the sign of the OR of the three.
    #[inline(always)]
    fn inside(level: Supported, base: [Self; 3], steps: &[Lanes<Self>; 3]) -> u16 {
        let [s0, s1, s2] = steps;
        !Self::negatives(level, &lanes(|j| (base[0] + s0[j]) | (base[1] + s1[j]) | (base[2] + s2[j])))
    }
}

impl Lane for i32 {
    #[inline(always)]
    fn clamped(v: i64, k: i64) -> Self {
        v.clamp(-k, k) as i32
    }
    #[inline(always)]
    fn exact(v: i64) -> Self {
        v as i32
    }
    #[inline(always)]
    fn sign(self) -> u16 {
        (self as u32 >> 31) as u16
    }
    #[inline(always)]
    fn times(self, k: i32) -> Self {
        self * k
    }
    #[inline(always)]
    fn shl(self, n: u32) -> Self {
        self << n
    }
    /// By movemask: LLVM compiles the plain loop of sign bits as 16 lane extractions.
    #[inline(always)]
    fn negatives(level: Supported, v: &Lanes<Self>) -> u16 {
        let mut words = [0u32; 16];
        for i in 0..16 {
            words[i] = v[i] as u32;
        }
        sign_mask16(level, &words)
    }
    /// In explicit vectors (`simd::dispatch::edge_steps16`): the plain loop became one
    /// scalar and one insert per lane.
    #[inline(always)]
    fn steps(level: Supported, a: Self, b: Self) -> Lanes<Self> {
        edge_steps16(level, a, b)
    }
    /// In explicit vectors (`simd::dispatch::inside_mask16`): the plain loop stayed 48 scalar
    /// adds and ORs.
    #[inline(always)]
    fn inside(level: Supported, base: [Self; 3], steps: &[Lanes<Self>; 3]) -> u16 {
        inside_mask16(level, base, steps)
    }
}

impl Lane for i64 {
    #[inline(always)]
    fn clamped(v: i64, _: i64) -> Self {
        v
    }
    #[inline(always)]
    fn exact(v: i64) -> Self {
        v
    }
    #[inline(always)]
    fn sign(self) -> u16 {
        (self as u64 >> 63) as u16
    }
    #[inline(always)]
    fn times(self, k: i32) -> Self {
        self * k as i64
    }
    #[inline(always)]
    fn shl(self, n: u32) -> Self {
        self << n
    }
    #[inline(always)]
    fn negatives(_: Supported, v: &Lanes<Self>) -> u16 {
        let mut bits = 0u16;
        for (i, x) in v.iter().enumerate() {
            bits |= x.sign() << i;
        }
        bits
    }
}

type Lanes<T> = [T; 16];

/// `f` on each of three edges' values, written out: `<[T; 3]>::map` and
/// `std::array::from_fn` can stay calls (out of the caller's per-level copy) in a large
/// function.
#[inline(always)]
fn map3<T: Copy, U>(a: [T; 3], f: impl Fn(T) -> U) -> [U; 3] {
    [f(a[0]), f(a[1]), f(a[2])]
}

/// `[f(0), f(1), f(2)]` (see [`map3`]).
#[inline(always)]
fn index3<U>(f: impl Fn(usize) -> U) -> [U; 3] {
    [f(0), f(1), f(2)]
}

/// The lanes `f(0) … f(15)` (a plain loop, which LLVM vectorises).
#[inline(always)]
fn lanes<T: Lane>(f: impl Fn(usize) -> T) -> Lanes<T> {
    let mut out = [T::default(); 16];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

/// The column and row of each lane of a 4×4 block.
const COLUMN: [i32; 16] = [0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3];
const ROW: [i32; 16] = [0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3];

/// An edge's steps `a·column + b·row` over the 16 lanes (from a 4×4 block's corner to its
/// pixels; with `a` and `b` scaled by a sub-block's side, from a block's corner to its
/// sub-blocks' corners). The walk takes them through [`Lane::steps`] (explicit vectors for
/// i32 lanes).
#[inline(always)]
fn steps<T: Lane>(a: T, b: T) -> Lanes<T> {
    lanes(|i| a.times(COLUMN[i]) + b.times(ROW[i]))
}

/// An edge's value at the pixel of a block of side `size` where it is largest (`hi`) and
/// smallest (`lo`), relative to the block's corner.
#[inline(always)]
fn extremes(e: &Reduced, size: i64) -> (i64, i64) {
    let s = size - 1;
    (s * (e.a.max(0) + e.b.max(0)), s * (e.a.min(0) + e.b.min(0)))
}

/// The sub-blocks (lanes) of a block that may hold covered pixels and those entirely
/// inside: `hi`/`lo` are the three edges' values at the block's corner plus their
/// largest/smallest over a sub-block, `ab` their steps from one sub-block to the next.
#[inline(always)]
fn sub_blocks<T: Lane>(level: Supported, hi: [T; 3], lo: [T; 3], ab: [(T, T); 3]) -> (u16, u16) {
    let s = map3(ab, |(a, b)| T::steps(level, a, b));
    (T::inside(level, hi, &s), T::inside(level, lo, &s))
}

/// Bit `i` of each nibble set for the lanes of that row (`0b0101` → rows 0 and 2 of a
/// block: `0x0f0f`).
const NIBBLES: [u16; 16] = {
    let mut t = [0u16; 16];
    let mut i = 0;
    while i < 16 {
        let mut r = 0;
        while r < 4 {
            if i & (1 << r) != 0 {
                t[i] |= 0xf << (4 * r);
            }
            r += 1;
        }
        i += 1;
    }
    t
};

/// The columns and rows of the non-empty `area` from `(x, y)` (fewer than 32 of each, from
/// the area's first aligned block) as bit runs: bit `i` of the first is column `x + i` inside
/// the area, of the second row `y + i`. Four bits are one block's columns (or rows), the
/// runs end with the area, so blocks past it have none.
#[inline(always)]
fn area_runs(area: Rect, x: i32, y: i32) -> (u32, u32) {
    let run = |lo: i32, hi: i32| (1u32 << hi) - (1u32 << lo);
    (run(area.x0 - x, area.x1 - x), run(area.y0 - y, area.y1 - y))
}

/// The 16 sub-blocks of side `size` of the block at `(x, y)` that meet `area`.
#[inline(always)]
fn area_mask(area: Rect, x: i32, y: i32, size: i32) -> u16 {
    let mut cols = 0u16;
    for c in 0..4 {
        let x0 = x + c * size;
        cols |= ((x0 < area.x1 && x0 + size > area.x0) as u16) << c;
    }
    let mut mask = 0u16;
    for r in 0..4 {
        let y0 = y + r * size;
        if y0 < area.y1 && y0 + size > area.y0 {
            mask |= cols << (4 * r);
        }
    }
    mask
}

struct Walker<'a, T, F, G> {
    level: Supported,
    area: Rect,
    edges: [Reduced; 3],
    /// The clamp of each edge's corner values (see the module).
    clamp: [i64; 3],
    stipple: Option<&'a [u32; 32]>,
    /// Where the walk starts: 3 when the area lies within one aligned 4×4 block, 2 when
    /// within at most 6 aligned blocks (3 by 2, 2 by 3) from its first, 1 when within the 16×16 pixels from
    /// its first aligned 4×4 block, 0 at the tiles.
    start: u8,
    /// Each edge's `a` and `b` as lanes.
    ab: [(T, T); 3],
    emit: F,
    /// Where whole covered rectangles go ([`walk_blocks_filling`]); never with a stipple.
    fill: Option<G>,
}

impl<'a, T: Lane, F: FnMut(i32, i32, u16), G: FnMut(Rect)> Walker<'a, T, F, G> {
    #[inline(always)]
    fn new(
        level: Supported,
        area: Rect,
        edges: [Reduced; 3],
        stipple: Option<&'a [u32; 32]>,
        emit: F,
        fill: Option<G>,
    ) -> Self {
        let (x4, y4) = (area.x0 & !3, area.y0 & !3);
        let start = if area.x1 - x4 <= 4 && area.y1 - y4 <= 4 {
            3
        } else if area.x1 - x4 <= 12 && area.y1 - y4 <= 12 && (area.x1 - x4 + 3) / 4 * ((area.y1 - y4 + 3) / 4) <= 6 {
            2
        } else if area.x1 - x4 <= 16 && area.y1 - y4 <= 16 {
            1
        } else {
            0
        };
        Walker {
            level,
            area,
            edges,
            clamp: map3(edges, |e| 64 * e.steepness() + 1),
            stipple,
            start,
            ab: map3(edges, |e| (T::exact(e.a), T::exact(e.b))),
            emit,
            fill,
        }
    }

    /// The edges' values at `(x, y)`, clamped: the base a tile's (or a small area's
    /// block's) steps are added to.
    #[inline(always)]
    fn corner(&self, x: i32, y: i32) -> [T; 3] {
        let [e0, e1, e2] = &self.edges;
        let [k0, k1, k2] = self.clamp;
        [T::clamped(e0.at(x, y), k0), T::clamped(e1.at(x, y), k1), T::clamped(e2.at(x, y), k2)]
    }

    /// The edges' steps scaled by `2^shift`.
    #[inline(always)]
    fn ab_shl(&self, shift: u32) -> [(T, T); 3] {
        map3(self.ab, |(a, b)| (a.shl(shift), b.shl(shift)))
    }

    /// `corner` plus each edge's largest (and smallest) value over a block of side `size`.
    #[inline(always)]
    fn extremes(&self, corner: &[T; 3], size: i64) -> ([T; 3], [T; 3]) {
        let ext = map3(self.edges, |e| extremes(&e, size));
        (index3(|k| corner[k] + T::exact(ext[k].0)), index3(|k| corner[k] + T::exact(ext[k].1)))
    }

    #[inline(always)]
    fn run(&mut self) {
        if self.start == 3 {
            return self.one_block();
        }
        if self.start == 2 {
            return self.few_blocks();
        }
        if self.start > 0 {
            return self.tile(0, 0);
        }
        let area = self.area;
        let mut ty = area.y0 & !63;
        while ty < area.y1 {
            let mut tx = area.x0 & !63;
            while tx < area.x1 {
                self.tile(tx, ty);
                tx += 64;
            }
            ty += 64;
        }
    }

    /// An area within one aligned 4×4 block (a small triangle's): that block's pixels
    /// tested at once, what [`Walker::block16`] does for it without the levels above.
    #[inline(always)]
    fn one_block(&mut self) {
        let area = self.area;
        let (x, y) = (area.x0 & !3, area.y0 & !3);
        let base = self.corner(x, y);
        let s = map3(self.ab, |(a, b)| T::steps(self.level, a, b));
        let mask = T::inside(self.level, base, &s) & rect_mask(area, x, y);
        self.emit_masked(x, y, mask);
    }

    /// An area within up to 6 aligned 4×4 blocks from its first (a small triangle's): each
    /// of its blocks tested at once as in [`Walker::one_block`]. For so few blocks the
    /// 16×16 level's bounds on each edge ([`Walker::block16`]) cost more than they save.
    /// The edges step from block to block by adds (the same exact integers as the corner
    /// plus multiples of the steps), and the area's cut of each block comes from its columns
    /// and rows as bit runs made once ([`area_runs`]), not from [`rect_mask`] per block.
    #[inline(always)]
    fn few_blocks(&mut self) {
        let area = self.area;
        let (x, y) = (area.x0 & !3, area.y0 & !3);
        let s = map3(self.ab, |(a, b)| T::steps(self.level, a, b));
        let ab4 = self.ab_shl(2);
        let (columns, rows) = area_runs(area, x, y);
        let mut row_base = self.corner(x, y);
        let mut by = y;
        let mut row_bits = rows;
        while row_bits != 0 {
            // The row's covered lines as whole nibbles.
            let row_mask = NIBBLES[(row_bits & 0xf) as usize];
            let mut base = row_base;
            let (mut bx, mut column_bits) = (x, columns);
            while column_bits != 0 {
                let mask = T::inside(self.level, base, &s) & row_mask & ((column_bits & 0xf) as u16 * 0x1111);
                self.emit_masked(bx, by, mask);
                base = index3(|k| base[k] + ab4[k].0);
                bx += 4;
                column_bits >>= 4;
            }
            row_base = index3(|k| row_base[k] + ab4[k].1);
            by += 4;
            row_bits >>= 4;
        }
    }

    /// Emits the block at `(x, y)` with the covered pixels `mask`, cut by the stipple.
    #[inline(always)]
    fn emit_masked(&mut self, x: i32, y: i32, mut mask: u16) {
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

    /// The 64×64 tile at `(x, y)`: its 16×16 blocks that may hold covered pixels (for a
    /// small area, the 16×16 pixels from its first 4×4 block, wherever the tile).
    #[inline(always)]
    fn tile(&mut self, x: i32, y: i32) {
        let area = self.area;
        let small = (area.x0 & !3, area.y0 & !3);
        let (visit, inside, corner) = if self.start > 0 {
            (1u16, 0, self.corner(small.0, small.1))
        } else {
            // The tile as a whole first (most tiles of a thin triangle's box miss it).
            let mut all_inside = true;
            for e in &self.edges {
                let v = e.at(x, y);
                let (hi, lo) = extremes(e, 64);
                if v + hi < 0 {
                    return;
                }
                all_inside &= v + lo >= 0;
            }
            if all_inside {
                if let Some(fill) = self.fill.as_mut() {
                    return fill(Rect::from_xywh(x, y, 64, 64).intersect(area));
                }
            }
            let mask = area_mask(area, x, y, 16);
            let corner = self.corner(x, y);
            if all_inside {
                (mask, mask, corner)
            } else {
                let (hi, lo) = self.extremes(&corner, 16);
                let (visit, inside) = sub_blocks(self.level, hi, lo, self.ab_shl(4));
                (visit & mask, inside & mask, corner)
            }
        };
        let ab16 = self.ab_shl(4);
        let mut bits = visit;
        while bits != 0 {
            let i = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            let (bx, by, corner) = if self.start > 0 {
                (small.0, small.1, corner)
            } else {
                let (c, r) = (COLUMN[i], ROW[i]);
                let corner = index3(|k| corner[k] + ab16[k].0.times(c) + ab16[k].1.times(r));
                (x + 16 * c, y + 16 * r, corner)
            };
            self.block16(bx, by, &corner, inside & (1 << i) != 0);
        }
    }

    /// The 16×16 pixels at `(x, y)` (`corner`: the edges there): their 4×4 blocks.
    #[inline(always)]
    fn block16(&mut self, x: i32, y: i32, corner: &[T; 3], inside: bool) {
        let area = self.area;
        if inside {
            if let Some(fill) = self.fill.as_mut() {
                return fill(Rect::from_xywh(x, y, 16, 16).intersect(area));
            }
        }
        let mask = area_mask(area, x, y, 4);
        let ab4 = self.ab_shl(2);
        let (visit, inside) = if inside {
            (mask, mask)
        } else {
            let (hi, lo) = self.extremes(corner, 4);
            let (visit, inside) = sub_blocks(self.level, hi, lo, ab4);
            (visit & mask, inside & mask)
        };
        let within = x >= area.x0 && y >= area.y0 && x + 16 <= area.x1 && y + 16 <= area.y1;
        let s = map3(self.ab, |(a, b)| T::steps(self.level, a, b));
        let mut bits = visit;
        while bits != 0 {
            let i = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            let (c, r) = (COLUMN[i], ROW[i]);
            let (bx, by) = (x + 4 * c, y + 4 * r);
            let mut mask = if inside & (1 << i) != 0 {
                if let Some(fill) = self.fill.as_mut() {
                    fill(Rect::from_xywh(bx, by, 4, 4).intersect(area));
                    continue;
                }
                0xffff
            } else {
                let base: [T; 3] = index3(|k| corner[k] + ab4[k].0.times(c) + ab4[k].1.times(r));
                T::inside(self.level, base, &s)
            };
            if !within && (bx < area.x0 || by < area.y0 || bx + 4 > area.x1 || by + 4 > area.y1) {
                mask &= rect_mask(area, bx, by);
            }
            self.emit_masked(bx, by, mask);
        }
    }
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

    /// The blocks `Walker<T>` emits for `area`.
    fn walked<T: Lane>(area: Rect, edges: &[PixelEdge; 3]) -> Vec<(i32, i32, u16)> {
        let mut seen = Vec::new();
        let emit = |x, y, m| seen.push((x, y, m));
        Walker::<T, _, fn(Rect)>::new(crate::simd::current(), area, edges.map(|e| Reduced::new(&e)), None, emit, None)
            .run();
        seen
    }

    #[test]
    fn inside_masks_are_the_scalar_signs_at_every_level() {
        // Random bases and steps with sums of every sign (zero included, which is inside),
        // at each SIMD level the machine has: the mask of the lanes inside all three edges.
        use crate::simd::{Level, Supported};
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = |range: i32| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * range as u64 + 1)) as i32 - range
        };
        for round in 0..2000 {
            let range = if round % 2 == 0 { 8 } else { 1 << 29 };
            let base = [next(range), next(range), next(range)];
            let steps: [Lanes<i32>; 3] = std::array::from_fn(|_| std::array::from_fn(|_| next(range)));
            let inside = |i: usize| (0..3).all(|k| base[k] + steps[k][i] >= 0);
            let expected = (0..16).fold(0u16, |m, i| m | (inside(i) as u16) << i);
            for &level in Level::ALL.iter().filter(|l| l.available()) {
                let level = Supported::new(level).expect("available");
                assert_eq!(<i32 as Lane>::inside(level, base, &steps), expected, "round {round}");
                assert_eq!(
                    <i64 as Lane>::inside(level, base.map(i64::from), &steps.map(|s| s.map(i64::from))),
                    expected
                );
            }
        }
    }

    #[test]
    fn edge_steps_are_the_products_at_every_level() {
        // `a·column + b·row` per lane, for steps of every sign and size the walk uses (up to
        // 2²⁴ · 3 · 64 in magnitude), at each SIMD level the machine has.
        use crate::simd::{Level, Supported};
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |range: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * range as u64 + 1)) as i64 - range
        };
        for round in 0..500 {
            let range = if round % 2 == 0 { 300 } else { 1 << 28 };
            let (a, b) = (next(range) as i32, next(range) as i32);
            let expected = steps::<i64>(a.into(), b.into()).map(|v| v as i32);
            for &level in Level::ALL.iter().filter(|l| l.available()) {
                let level = Supported::new(level).expect("available");
                assert_eq!(<i32 as Lane>::steps(level, a, b), expected, "{a} {b}");
                assert_eq!(<i64 as Lane>::steps(level, a.into(), b.into()).map(|v| v as i32), expected);
            }
        }
    }

    #[test]
    fn clamped_i32_lanes_give_the_coverage_of_exact_i64_lanes() {
        // Edges at the i32 limit (M = 2²⁴: an edge 65 536 pixels long) far from and
        // through the walked areas, where the clamp decides; both lane types must agree,
        // and not trivially (some blocks partly covered).
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |range: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * range as u64)) as i64 - range
        };
        let mut partial = 0;
        for round in 0..400 {
            let edges: [PixelEdge; 3] = std::array::from_fn(|_| {
                let a = next(1 << 15) * 256;
                let b = ((1 << 24) - a.abs() / 256) * 256 * if next(1) < 0 { -1 } else { 1 };
                // Through a point near the areas, or up to 2²⁰ pixels away.
                let reach = if round % 2 == 0 { 100 } else { 1 << 20 };
                let (px, py) = (next(reach) + 64, next(reach) + 64);
                PixelEdge { c: -(a * px + b * py) + next(1 << 20), a, b }
            });
            let x0 = 64 + next(60) as i32;
            let area = Rect::from_xywh(x0, 40 + next(30) as i32, 1 + next(50).unsigned_abs() as i32, 70);
            let narrow = walked::<i32>(area, &edges);
            assert_eq!(narrow, walked::<i64>(area, &edges), "round {round}");
            partial += narrow.iter().filter(|b| b.2 != 0xffff).count();
        }
        assert!(partial > 100);
    }

    #[test]
    fn areas_within_one_block_are_walked_exactly() {
        // Areas inside one aligned 4×4 block (the small-triangle path): every pixel of the
        // area emitted exactly when all three edges are non-negative there, with i32 and
        // i64 lanes, and the stipple cutting the mask.
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |range: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * range as u64)) as i64 - range
        };
        let mut pattern = [0u32; 32];
        pattern.iter_mut().enumerate().for_each(|(i, p)| *p = 0x5555_5555u32.rotate_left(i as u32));
        let mut covered = 0;
        for round in 0..2000 {
            let edges: [PixelEdge; 3] = std::array::from_fn(|_| {
                let (a, b) = (next(1 << 12) * 256, next(1 << 12) * 256);
                let (px, py) = (next(8) + 102, next(8) + 42);
                PixelEdge { c: -(a * px + b * py) + next(1 << 16), a, b }
            });
            let (x0, y0) = (100 + next(2).unsigned_abs() as i32, 40 + next(2).unsigned_abs() as i32);
            let area = Rect { x0, y0, x1: x0 + 1 + next(2).unsigned_abs().min(103 - x0 as u64) as i32, y1: y0 + 2 };
            let stipple = (round % 3 == 0).then_some(&pattern);
            let mut seen = Vec::new();
            walk_blocks(crate::simd::current(), area, &edges, stipple, |x, y, m| seen.push((x, y, m)));
            let mut expected = 0u16;
            for y in area.y0..area.y1 {
                for x in area.x0..area.x1 {
                    let inside = edges.iter().all(|e| e.c + e.a * x as i64 + e.b * y as i64 >= 0);
                    let stippled = stipple.is_none_or(|p| stipple_mask(p, x, y) & 1 != 0);
                    if inside && stippled {
                        expected |= 1 << ((x - 100) + 4 * (y - 40));
                    }
                }
            }
            covered += expected.count_ones();
            let expected = if expected == 0 { vec![] } else { vec![(100, 40, expected)] };
            assert_eq!(seen, expected, "round {round}");
            let reduced = edges.map(|e| Reduced::new(&e));
            let mut wide = Vec::new();
            let emit = |x, y, m| wide.push((x, y, m));
            Walker::<i64, _, fn(Rect)>::new(crate::simd::current(), area, reduced, stipple, emit, None).run();
            assert_eq!(wide, expected, "round {round}, i64 lanes");
        }
        assert!(covered > 200, "{covered}");
    }

    #[test]
    fn small_areas_are_walked_as_the_hierarchical_walk_walks_them() {
        // Small triangles at every sub-pixel position of their first vertex, both windings,
        // edges through pixel centres (the fill rule), walked over their box cut by a
        // scissor-like rectangle: the direct paths (one block, a few blocks) emit exactly
        // what the tile walk (64 → 16 → 4) emits, which the per-pixel test checks.
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = |range: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * range as u64)) as i64 - range
        };
        let level = crate::simd::current();
        let mut direct = 0;
        for sub in 0..256 {
            for round in 0..12 {
                let base = [(200 + next(8)) * 256 + sub, (70 + next(8)) * 256 + (sub * 7) % 256];
                let extent = if round % 3 == 0 { 3 } else { 11 };
                let mut v = [base, [0; 2], [0; 2]];
                for p in &mut v[1..] {
                    *p = [base[0] + next(extent * 256), base[1] + next(extent * 256)];
                    if round % 4 == 0 {
                        // On pixel centres: edges through centres.
                        *p = p.map(|c| (c & !255) + 128);
                    }
                }
                for w in [v, [v[0], v[2], v[1]]] {
                    // The setup's pixel edges (`TriangleSetup::pixel_edges`, a room above):
                    // counter-clockwise, centres at +128, bias 1 but on left and bottom edges.
                    let area2 = (w[1][0] - w[0][0]) * (w[2][1] - w[0][1]) - (w[2][0] - w[0][0]) * (w[1][1] - w[0][1]);
                    if area2 == 0 {
                        continue;
                    }
                    let w = if area2 < 0 { [w[0], w[2], w[1]] } else { w };
                    let edges: [PixelEdge; 3] = std::array::from_fn(|i| {
                        let (p, q) = (w[i], w[(i + 1) % 3]);
                        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
                        let (a, b, c) = (-dy, dx, dy * p[0] - dx * p[1]);
                        let bias = !(dy < 0 || (dy == 0 && dx > 0)) as i64;
                        PixelEdge { c: a * 128 + b * 128 + c - bias, a: a * 256, b: b * 256 }
                    });
                    let covers = |x: i32, y: i32| edges.iter().all(|e| e.c + e.a * x as i64 + e.b * y as i64 >= 0);
                    let lo = |k: usize| -((128 - w.iter().map(|p| p[k]).min().unwrap()) >> 8) as i32;
                    let hi = |k: usize| ((w.iter().map(|p| p[k]).max().unwrap() - 128) >> 8) as i32 + 1;
                    let bounds = Rect { x0: lo(0), y0: lo(1), x1: hi(0), y1: hi(1) };
                    if bounds.is_empty() {
                        continue;
                    }
                    let scissor = if round % 5 == 0 {
                        Rect::from_xywh(bounds.x0 + 1, bounds.y0, 3, 100)
                    } else {
                        Rect::from_xywh(0, 0, 1000, 1000)
                    };
                    let area = bounds.intersect(scissor);
                    if area.is_empty() {
                        continue;
                    }
                    let reduced = edges.map(|e| Reduced::new(&e));
                    let mut tiled = Vec::new();
                    let mut walker = Walker::<i32, _, fn(Rect)>::new(
                        level,
                        area,
                        reduced,
                        None,
                        |x, y, m| tiled.push((x, y, m)),
                        None,
                    );
                    direct += (walker.start >= 2) as usize;
                    walker.start = 0;
                    walker.run();
                    let mut seen = Vec::new();
                    walk_blocks(level, area, &edges, None, |x, y, m| seen.push((x, y, m)));
                    // The same blocks (a 16×16 boundary may order them differently).
                    let (mut sorted, mut tiled) = (seen.clone(), tiled);
                    sorted.sort_unstable();
                    tiled.sort_unstable();
                    assert_eq!(sorted, tiled, "{w:?} in {area:?}");
                    for y in area.y0..area.y1 {
                        for x in area.x0..area.x1 {
                            let (bx, by) = (x & !3, y & !3);
                            let bit = 1 << ((x - bx) + 4 * (y - by));
                            let emitted = seen.iter().any(|&(sx, sy, m)| (sx, sy) == (bx, by) && m & bit != 0);
                            assert_eq!(emitted, covers(x, y), "({x}, {y}) of {w:?}");
                        }
                    }
                }
            }
        }
        assert!(direct > 3000, "{direct}");
    }

    #[test]
    fn a_half_plane_is_walked_exactly_with_its_stipple() {
        // x ≥ 10: c + a·x with a = 1, c = −10.
        let e = PixelEdge { c: -10, a: 1, b: 0 };
        let always = PixelEdge { c: 0, a: 0, b: 0 };
        let mut pattern = [0u32; 32];
        pattern[1] = 0x8000_0000 >> 12; // column 12 of rows 1, 33, …
        let mut seen = Vec::new();
        walk_blocks(
            crate::simd::current(),
            Rect::from_xywh(0, 0, 16, 2),
            &[e, always, always],
            Some(&pattern),
            |x, y, m| seen.push((x, y, m)),
        );
        // Only pixel (12, 1): block (12, 0), lane 4.
        assert_eq!(seen, [(12, 0, 1 << 4)]);
        let mut count = 0;
        walk_blocks(crate::simd::current(), Rect::from_xywh(0, 0, 70, 3), &[e, always, always], None, |x, _, m| {
            assert!(x >= 8);
            count += m.count_ones();
        });
        assert_eq!(count, 60 * 3);
    }

    #[test]
    fn a_filling_walk_covers_each_covered_pixel_once() {
        // Large triangles over several tiles and a scissor-like area: the rectangles given
        // to `fill` and the blocks given to `emit` are disjoint and together exactly the
        // pixels the plain walk emits (which the other tests check pixel by pixel), and the
        // fill takes most of them (the inside is not walked block by block).
        let mut seed = 0x1234_5678_9abc_def1u64;
        let mut next = |range: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * range as u64)) as i64 - range
        };
        let (mut filled_total, mut covered_total) = (0, 0);
        for round in 0..200 {
            let p: [[i64; 2]; 3] = std::array::from_fn(|_| [next(160) + 100, next(160) + 100]);
            let cross = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
            // Counter-clockwise (E ≥ 0 inside), in 1/256 pixel units, through pixel centres.
            let p = if cross >= 0 { p } else { [p[0], p[2], p[1]] };
            let edges: [PixelEdge; 3] = std::array::from_fn(|k| {
                let (a0, a1) = (p[k], p[(k + 1) % 3]);
                let (a, b) = ((a0[1] - a1[1]) * 256, (a1[0] - a0[0]) * 256);
                PixelEdge { c: -(a * a0[0] + b * a0[1]) + a / 2 + b / 2 + next(64), a, b }
            });
            let mut at = |base: i64| (base + next(20)) as i32;
            let area = Rect { x0: at(20), y0: at(20), x1: at(200), y1: at(210) };
            let mut plain = vec![false; 256 * 256];
            walk_blocks(crate::simd::current(), area, &edges, None, |x, y, m| {
                for i in 0..16 {
                    if m & (1 << i) != 0 {
                        plain[(y + i / 4) as usize * 256 + (x + i % 4) as usize] = true;
                    }
                }
            });
            let seen = std::cell::RefCell::new(vec![0u8; 256 * 256]);
            let mut filled = 0;
            walk_blocks_filling(
                crate::simd::current(),
                area,
                &edges,
                None,
                |x, y, m| {
                    for i in 0..16 {
                        if m & (1 << i) != 0 {
                            seen.borrow_mut()[(y + i / 4) as usize * 256 + (x + i % 4) as usize] += 1;
                        }
                    }
                },
                Some(|r: Rect| {
                    assert!(!r.is_empty() && r.intersect(area) == r, "round {round}: {r:?}");
                    for y in r.y0..r.y1 {
                        for x in r.x0..r.x1 {
                            seen.borrow_mut()[y as usize * 256 + x as usize] += 1;
                            filled += 1;
                        }
                    }
                }),
            );
            let seen = seen.into_inner();
            assert!(seen.iter().zip(&plain).all(|(&n, &p)| n == u8::from(p)), "round {round}");
            filled_total += filled;
            covered_total += plain.iter().filter(|&&p| p).count();
        }
        assert!(filled_total * 2 > covered_total, "{filled_total} of {covered_total}");
    }
}
