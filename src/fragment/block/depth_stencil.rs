//! The stencil and depth tests of a block as one lane kernel per depth/stencil storage
//! format, chosen once per draw state ([`DepthStencilKernel`]), and the comparison helpers
//! the alpha, stencil and depth tests share.
//!
//! - Comparisons (alpha, depth, stencil) are GL's three-bit encoding: bit 0 passes when the
//!   fragment is less, bit 1 when equal, bit 2 when greater (`GL_NEVER` 0 … `GL_ALWAYS` 7).
//! - Depth: every [`DepthBand`] format, stored values as u32 lanes, the fragment depth
//!   encoded as the span path's `DepthEncoding::encode_fragment`; the stencil test, its
//!   operations (two-sided, one monomorphised function per `StencilOp`) and the depth write
//!   in GL's order (`super::super::stencil`).

use super::{lanes, load, map_lanes, store, BlockAt, F32s, U32s, LANES};
use crate::fragment::stencil::{StencilFace, StencilOp};
use crate::fragment::FragmentState;
use crate::framebuffer::band::DepthBand;
use crate::framebuffer::format::DepthEncoding;
use crate::framebuffer::DepthStencilFormat;
use crate::gl::CompareFunc;

/// GL's comparison bits of `func` (see the module).
pub fn compare_bits(func: CompareFunc) -> u8 {
    match func {
        CompareFunc::Never => 0,
        CompareFunc::Less => 1,
        CompareFunc::Equal => 2,
        CompareFunc::LessEqual => 3,
        CompareFunc::Greater => 4,
        CompareFunc::NotEqual => 5,
        CompareFunc::GreaterEqual => 6,
        CompareFunc::Always => 7,
    }
}

/// The lanes where `fragment func stored` holds, branch-free: each relation as an
/// all-ones lane mask, the function's three bits as all-ones or zero words, then the lane
/// masks packed into bits.
#[inline(always)]
pub fn compare_lanes(func: u8, fragment: &U32s, stored: &U32s) -> u16 {
    let bit = |b: u8| if func & b != 0 { !0u32 } else { 0 };
    let (lt, eq, gt) = (bit(1), bit(2), bit(4));
    let ok = lanes(|i| {
        let (f, s) = (fragment[i], stored[i]);
        let all = |c: bool| if c { !0u32 } else { 0 };
        (all(f < s) & lt) | (all(f == s) & eq) | (all(f > s) & gt)
    });
    pack_mask(&ok)
}

/// [`compare_lanes`] for values below 2³¹ (unorm depth up to 24 bits, float depth bits,
/// stencil and alpha): signed comparisons, which SSE2 has, one plain comparison loop per
/// function (the function is the draw's: the branch goes the same way every block).
#[inline(always)]
pub fn compare_lanes_small(func: u8, fragment: &U32s, stored: &U32s) -> u16 {
    let f = map_lanes(fragment, |v| v as i32);
    let s = map_lanes(stored, |v| v as i32);
    let mask = |c: &dyn Fn(i32, i32) -> bool| pack_mask(&lanes(|i| if c(f[i], s[i]) { !0u32 } else { 0 }));
    match func {
        0 => 0,
        1 => mask(&|a, b| a < b),
        2 => mask(&|a, b| a == b),
        3 => mask(&|a, b| a <= b),
        4 => mask(&|a, b| a > b),
        5 => mask(&|a, b| a != b),
        6 => mask(&|a, b| a >= b),
        _ => 0xffff,
    }
}

/// Lane masks (all-ones or zero words) packed into one bit per lane.
#[inline(always)]
fn pack_mask(m: &U32s) -> u16 {
    let mut bits = 0u16;
    for (i, &v) in m.iter().enumerate() {
        bits |= ((v >> 31) as u16) << i;
    }
    bits
}

/// The lanes of `mask` as all-ones / zero words, for selects.
#[inline(always)]
fn select_u32(mask: u16, new: &U32s, old: &U32s) -> U32s {
    lanes(|i| if mask & (1 << i) != 0 { new[i] } else { old[i] })
}

// ---------------------------------------------------------------------------------------
// Stencil and depth.

/// One stencil operation on the lanes of `which`, through the write mask.
type StencilOpFn = fn(values: &mut U32s, reference: u32, which: u16, write_mask: u32);

#[inline(always)]
fn stencil_op<const OP: u8>(values: &mut U32s, reference: u32, which: u16, write_mask: u32) {
    for (i, v) in values.iter_mut().enumerate() {
        let new = match OP {
            1 => 0,
            2 => reference,
            3 => (*v + 1).min(255),
            4 => v.saturating_sub(1),
            5 => (*v + 1) & 255,
            6 => v.wrapping_sub(1) & 255,
            7 => !*v & 255,
            _ => *v,
        };
        let new = (*v & !write_mask) | (new & write_mask);
        if which & (1 << i) != 0 {
            *v = new;
        }
    }
}

fn stencil_op_fn(op: StencilOp) -> Option<StencilOpFn> {
    Some(match op {
        StencilOp::Keep => return None,
        StencilOp::Zero => stencil_op::<1>,
        StencilOp::Replace => stencil_op::<2>,
        StencilOp::Incr => stencil_op::<3>,
        StencilOp::Decr => stencil_op::<4>,
        StencilOp::IncrWrap => stencil_op::<5>,
        StencilOp::DecrWrap => stencil_op::<6>,
        StencilOp::Invert => stencil_op::<7>,
    })
}

/// One face of the stencil state on lanes; an operation that changes nothing (KEEP, or an
/// empty write mask) is absent.
#[derive(Clone, Copy)]
struct FaceKernel {
    func: u8,
    reference: u32,
    value_mask: u32,
    write_mask: u32,
    sfail: Option<StencilOpFn>,
    zfail: Option<StencilOpFn>,
    zpass: Option<StencilOpFn>,
}

impl FaceKernel {
    fn new(face: &StencilFace) -> Self {
        let op = |op| if face.write_mask == 0 { None } else { stencil_op_fn(op) };
        FaceKernel {
            func: compare_bits(face.func),
            reference: face.reference as u32,
            value_mask: face.value_mask as u32,
            write_mask: face.write_mask as u32,
            sfail: op(face.sfail),
            zfail: op(face.zfail),
            zpass: op(face.zpass),
        }
    }

    /// Whether any operation can change stored values.
    fn writes(&self) -> bool {
        self.sfail.is_some() || self.zfail.is_some() || self.zpass.is_some()
    }

    #[inline(always)]
    fn apply(op: Option<StencilOpFn>, values: &mut U32s, reference: u32, which: u16, write_mask: u32) {
        if let Some(f) = op {
            if which != 0 {
                f(values, reference, which, write_mask);
            }
        }
    }
}

/// The compiled depth and stencil state.
pub struct DepthStencilParams {
    /// Comparison bits and depth write.
    depth: Option<(u8, bool)>,
    clamp: Option<[f32; 2]>,
    /// Front and back faces.
    stencil: Option<[FaceKernel; 2]>,
    /// Whether the stencil values can change (else they are not stored back).
    stencil_writes: bool,
}

type DepthStencilFn = fn(&DepthStencilParams, &mut DepthBand<'_>, &BlockAt, &F32s, u16, bool) -> u16;

/// The stencil and depth tests of a draw on one depth/stencil format.
pub struct DepthStencilKernel {
    run: DepthStencilFn,
    params: DepthStencilParams,
}

const D16: u8 = 0;
const PACKED24: u8 = 1;
const D32: u8 = 2;
const F32: u8 = 3;

impl DepthStencilKernel {
    /// `None` when the draw has neither test (or the framebuffer no depth/stencil layer).
    pub fn new(fragment: &FragmentState, format: DepthStencilFormat) -> Option<Self> {
        let stencil = fragment.stencil.filter(|_| format.stencil_bits() > 0);
        if fragment.depth.is_none() && stencil.is_none() {
            return None;
        }
        let run: DepthStencilFn = match format {
            DepthStencilFormat::None => return None,
            DepthStencilFormat::Depth16 => depth_stencil::<D16>,
            DepthStencilFormat::Packed24 { .. } => depth_stencil::<PACKED24>,
            DepthStencilFormat::Depth32 { .. } => depth_stencil::<D32>,
            DepthStencilFormat::Float32 { .. } => depth_stencil::<F32>,
        };
        let faces = stencil.map(|s| [FaceKernel::new(&s.front), FaceKernel::new(&s.back)]);
        let params = DepthStencilParams {
            depth: fragment.depth.map(|d| (compare_bits(d.func), d.write)),
            clamp: fragment.depth_clamp,
            stencil_writes: faces.is_some_and(|f| f[0].writes() || f[1].writes()),
            stencil: faces,
        };
        Some(DepthStencilKernel { run, params })
    }

    /// Runs the tests on the lanes of `live`; `z()` gives the fragments' window depth (read
    /// only when the depth test is on). Returns the lanes that pass.
    #[inline]
    pub fn run(
        &self,
        band: &mut DepthBand<'_>,
        at: &BlockAt,
        live: u16,
        front_facing: bool,
        z: impl FnOnce() -> F32s,
    ) -> u16 {
        let mut lanes = [0f32; LANES];
        if self.params.depth.is_some() {
            lanes = z();
            if let Some([lo, hi]) = self.params.clamp {
                for z in &mut lanes {
                    *z = z.clamp(lo, hi);
                }
            }
        }
        (self.run)(&self.params, band, at, &lanes, live, front_facing)
    }
}

/// `DepthEncoding::encode_fragment` on lanes, branch-free: the clamp as selects (NaN and
/// −0 give 0), then for unorm the same single-precision product rounded to nearest even
/// through f64 (`format::round_half_even`), for float the clamped value's bits.
#[inline(always)]
fn encode_depth(encoding: DepthEncoding, z: &F32s) -> U32s {
    let clamped = lanes(|i| {
        let v = z[i];
        let v = if v > 0.0 { v } else { 0.0 };
        if v < 1.0 {
            v
        } else {
            1.0
        }
    });
    match encoding {
        DepthEncoding::Unorm(bits) if bits <= 24 => {
            // Below 2²³ adding 2²³ in single precision rounds to nearest even; from 2²³ on
            // every f32 is an integer already: the f64 rounding's result, without f64.
            const MAGIC: f32 = (1u32 << 23) as f32;
            let max = crate::framebuffer::format::unorm_max(bits) as f32;
            // The integer read from the bits: below 2²³ those of `p + 2²³` minus 2²³'s; from
            // 2²³ to 2²⁴ (exponent 23) the mantissa plus the implicit bit.
            lanes(|i| {
                let p = clamped[i] * max;
                let small = (p + MAGIC).to_bits().wrapping_sub(MAGIC.to_bits());
                let large = (p.to_bits() & 0x007f_ffff) | 0x0080_0000;
                if p < MAGIC {
                    small
                } else {
                    large
                }
            })
        }
        DepthEncoding::Unorm(bits) => {
            const MAGIC: f64 = (1u64 << 52) as f64;
            let max = crate::framebuffer::format::unorm_max(bits) as f32;
            lanes(|i| (((clamped[i] * max) as f64 + MAGIC) - MAGIC) as u32)
        }
        DepthEncoding::Float => map_lanes(&clamped, f32::to_bits),
    }
}

/// The stencil test, the depth test and the stencil operations on one format (see
/// [`crate::fragment::stencil_depth_test`], whose order this is).
fn depth_stencil<const FMT: u8>(
    p: &DepthStencilParams,
    band: &mut DepthBand<'_>,
    at: &BlockAt,
    z: &F32s,
    live: u16,
    front_facing: bool,
) -> u16 {
    crate::simd::per_level!({
        let encoding = match FMT {
            D16 => DepthEncoding::Unorm(16),
            PACKED24 => DepthEncoding::Unorm(24),
            D32 => DepthEncoding::Unorm(32),
            _ => DepthEncoding::Float,
        };
        // Stored depth and stencil as lanes.
        let (stored, mut stencil): (U32s, U32s) = match band {
            DepthBand::Depth16(px) if FMT == D16 => (map_lanes(&load(px, at), |v| v as u32), [0; LANES]),
            DepthBand::Packed24(px) if FMT == PACKED24 => {
                let words = load(px, at);
                (map_lanes(&words, |w| w & 0x00ff_ffff), map_lanes(&words, |w| w >> 24))
            }
            DepthBand::Depth32(px, s) | DepthBand::Float32(px, s) if FMT == D32 || FMT == F32 => {
                let stencil = match (s, p.stencil.is_some()) {
                    (Some(s), true) => map_lanes(&load(s, at), |v| v as u32),
                    _ => [0; LANES],
                };
                (load(px, at), stencil)
            }
            _ => return live,
        };
        let face = p.stencil.map(|f| f[usize::from(!front_facing)]);
        let mut passing = live;
        if let Some(face) = &face {
            let reference = [face.reference & face.value_mask; LANES];
            let masked = map_lanes(&stencil, |v| v & face.value_mask);
            passing = compare_lanes_small(face.func, &reference, &masked) & live;
            FaceKernel::apply(face.sfail, &mut stencil, face.reference, live & !passing, face.write_mask);
        }
        let mut depth_out = None;
        if let Some((func, write)) = p.depth {
            let fragment = encode_depth(encoding, z);
            let depth_pass = if FMT == D32 {
                compare_lanes(func, &fragment, &stored)
            } else {
                compare_lanes_small(func, &fragment, &stored)
            } & passing;
            if write && depth_pass != 0 {
                depth_out = Some(select_u32(depth_pass, &fragment, &stored));
            }
            if let Some(face) = &face {
                FaceKernel::apply(face.zfail, &mut stencil, face.reference, passing & !depth_pass, face.write_mask);
            }
            passing = depth_pass;
        }
        if let Some(face) = &face {
            FaceKernel::apply(face.zpass, &mut stencil, face.reference, passing, face.write_mask);
        }
        let stencil_out = p.stencil_writes;
        if depth_out.is_none() && !stencil_out {
            return passing;
        }
        let depth = depth_out.unwrap_or(stored);
        match band {
            DepthBand::Depth16(px) => store(px, at, &map_lanes(&depth, |v| v as u16), live),
            DepthBand::Packed24(px) => {
                // `stencil` holds the stored high bytes even without a stencil test.
                let words: U32s = lanes(|i| depth[i] | stencil[i] << 24);
                store(px, at, &words, live);
            }
            DepthBand::Depth32(px, s) | DepthBand::Float32(px, s) => {
                if depth_out.is_some() {
                    store(px, at, &depth, live);
                }
                if let (Some(s), true) = (s, stencil_out) {
                    store(s, at, &map_lanes(&stencil, |v| v as u8), live);
                }
            }
            DepthBand::None => {}
        }
        passing
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compare_bits_follow_every_function() {
        let f: U32s = std::array::from_fn(|i| (i % 3) as u32);
        let s = [1u32; LANES];
        for func in [
            CompareFunc::Never,
            CompareFunc::Less,
            CompareFunc::Equal,
            CompareFunc::LessEqual,
            CompareFunc::Greater,
            CompareFunc::NotEqual,
            CompareFunc::GreaterEqual,
            CompareFunc::Always,
        ] {
            let want = (0..LANES).filter(|&i| crate::fragment::passes(func, f[i], s[i])).fold(0u16, |m, i| m | 1 << i);
            assert_eq!(compare_lanes(compare_bits(func), &f, &s), want, "{func:?}");
        }
    }

    #[test]
    fn stencil_ops_wrap_and_saturate_through_the_write_mask() {
        let mut v: U32s = [0; LANES];
        v[1] = 255;
        stencil_op_fn(StencilOp::DecrWrap).unwrap()(&mut v, 0, 0b01, 0xff);
        stencil_op_fn(StencilOp::Incr).unwrap()(&mut v, 0, 0b10, 0xff);
        assert_eq!(v[..2], [255, 255]);
        stencil_op_fn(StencilOp::IncrWrap).unwrap()(&mut v, 0, 0b11, 0x0f);
        assert_eq!(v[..2], [0xf0, 0xf0]);
        stencil_op_fn(StencilOp::Replace).unwrap()(&mut v, 0x3c, 0b01, 0xff);
        stencil_op_fn(StencilOp::Invert).unwrap()(&mut v, 0, 0b10, 0xff);
        assert_eq!(v[..3], [0x3c, 0x0f, 0]);
        assert!(stencil_op_fn(StencilOp::Keep).is_none());
    }
}
