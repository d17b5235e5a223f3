//! The fragment pipeline: from a covered span to the framebuffer write.
//!
//! [`pipeline`] is the driver, GL's stage order written once for single-sampled and
//! multisampled targets ([`multisample`] supplies the per-sample coverage and the
//! multisample operations). A draw's state is compiled into a [`FragmentState`] once;
//! disabled operations are absent from it rather than tested per pixel. The stages:
//! fragment shading (texturing, the texture environments, the color sum and fog: the
//! draw's fragment program, [`shading`]; or the program in use's GLSL fragment shader,
//! [`glsl_shading`]), the alpha test ([`alpha`]), the stencil and depth
//! tests with the stencil operations ([`stencil_depth_test`]), then per color target blending ([`blend`]) or the logic op ([`logic_op`]), dither
//! ([`dither`]) and the masked write ([`output`]).
//!
//! Filled triangles on single-sampled targets run the same stages on 4×4 blocks of
//! 16 lanes instead ([`block`]), with kernels compiled once per draw state.
//!
//! This room imports no room above it: jobs (`setup`) and tile workers (`raster`) hand it
//! spans with closures for their depth, colors and varyings.
#![deny(unsafe_code)]

pub mod alpha;
pub mod blend;
pub mod block;
pub mod describe;
pub mod dither;
pub mod fog;
pub mod glsl_shading;
pub mod logic_op;
pub mod multisample;
pub mod output;
pub mod pipeline;
pub mod program;
pub mod shading;
pub mod stencil;

use crate::framebuffer::band::{ColorBand, DepthBand};
use crate::framebuffer::format::float_to_unorm;
use crate::gl::CompareFunc;
use blend::Blend;
use logic_op::LogicOp;
use stencil::StencilFace;

/// Longest span the fragment stage processes at once (one tile row).
pub const MAX_SPAN: usize = 64;

/// The live-fragment mask of a whole `n`-pixel span (bit i: pixel i), n ≤ 64. Here, in
/// the lowest room that builds such masks, so that fragment, raster and setup share one.
#[inline]
pub fn span_mask(n: usize) -> u64 {
    if n >= 64 {
        !0
    } else {
        (1u64 << n) - 1
    }
}

/// The depth test of a draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DepthTest {
    pub func: CompareFunc,
    pub write: bool,
}

/// What a draw does to each fragment, compiled from the GL state at draw time.
#[derive(Clone, Debug, PartialEq)]
pub struct FragmentState {
    /// `None` when the depth test is disabled or there is no depth buffer.
    pub depth: Option<DepthTest>,
    /// GL_DEPTH_CLAMP (ARB_depth_clamp): fragment depths are clamped to [min, max] of the
    /// depth range before the depth test; `None` when disabled.
    pub depth_clamp: Option<[f32; 2]>,
    /// For each color target of the scene (same order as the band's colors): the channel
    /// write mask, or `None` when this draw does not write that target.
    pub color_masks: Vec<Option<[bool; 4]>>,
    /// Clamp colors written to float buffers to [0, 1].
    pub clamp_float: bool,
    /// `None` when GL_ALPHA_TEST is disabled.
    pub alpha: Option<AlphaTest>,
    /// `None` when GL_STENCIL_TEST is disabled or there are no stencil bits.
    pub stencil: Option<StencilTest>,
    /// For each color target (as `color_masks`): its draw buffer's blend state, `None` when
    /// blending is disabled for it or the logic op replaces it.
    pub blend: Vec<Option<Blend>>,
    /// GL_BLEND_COLOR, as given (the blend functions clamp it where GL says so).
    pub blend_color: [f32; 4],
    /// GL_COLOR_LOGIC_OP's operation when enabled (it replaces blending).
    pub logic_op: Option<LogicOp>,
    /// GL_DITHER on an RGB565 framebuffer (the only format tessera dithers).
    pub dither: bool,
    /// GL_COLOR_SUM with lighting off: the secondary color (varyings 0..3) is added to RGB.
    pub color_sum: bool,
    /// GL_FOG when enabled: the fog coordinate is varying 3 with the color sum, else 0.
    pub fog: Option<fog::Fog>,
    /// The enabled texture units (their coordinates follow the color sum and fog varyings);
    /// `None` for an untextured draw.
    pub texturing: Option<std::sync::Arc<crate::texture::Texturing>>,
    /// The fragment program of the texturing, colour sum and fog above, with its values
    /// ([`shading`]); `None` when it would pass the colour through.
    pub shading: Option<std::sync::Arc<shading::Shading>>,
    /// The program in use's GLSL fragment stage with its values ([`glsl_shading`]): it
    /// replaces `shading` (then `None`), texturing, the colour sum and fog.
    pub glsl: Option<std::sync::Arc<glsl_shading::GlslShading>>,
}

impl FragmentState {
    /// A state with only the given depth test and color masks (every other stage off).
    pub fn plain(depth: Option<DepthTest>, color_masks: Vec<Option<[bool; 4]>>, clamp_float: bool) -> Self {
        let blend = vec![None; color_masks.len()];
        FragmentState {
            depth,
            depth_clamp: None,
            color_masks,
            clamp_float,
            alpha: None,
            stencil: None,
            blend,
            blend_color: [0.0; 4],
            logic_op: None,
            dither: false,
            color_sum: false,
            fog: None,
            texturing: None,
            shading: None,
            glsl: None,
        }
    }

    /// Whether the draw's GLSL shader must run before the alpha, stencil and depth tests
    /// (it may discard or writes the depth).
    #[inline]
    pub fn late_tests(&self) -> bool {
        self.glsl.as_ref().is_some_and(|g| g.late_tests())
    }

    /// Whether target `index` needs more than a plain masked write (blend, logic op, dither).
    #[inline]
    pub fn target_has_ops(&self, index: usize) -> bool {
        self.dither || self.logic_op.is_some() || self.blend.get(index).is_some_and(|b| b.is_some())
    }

    /// The operations of target `index`, written with channel mask `mask`.
    pub fn target_ops(&self, index: usize, mask: [bool; 4]) -> output::TargetOps<'_> {
        output::TargetOps {
            blend: self.blend.get(index).and_then(|b| b.as_ref()),
            logic_op: self.logic_op,
            dither: self.dither,
            blend_color: self.blend_color,
            mask,
            clamp_float: self.clamp_float,
        }
    }
}

/// The alpha test of a draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlphaTest {
    pub func: CompareFunc,
    pub reference: f32,
    /// Compare in 8 bits (the color targets are 8-bit unorm), see [`alpha`].
    pub unorm8: bool,
}

impl AlphaTest {
    /// The fragments of `live` whose alpha passes.
    pub fn test(&self, colors: &[[f32; 4]], live: u64) -> u64 {
        let n = colors.len().min(MAX_SPAN);
        if self.unorm8 {
            let mut alphas = [0u8; MAX_SPAN];
            for (a, c) in alphas.iter_mut().zip(&colors[..n]) {
                *a = float_to_unorm(c[3], 8) as u8;
            }
            alpha::alpha_test_unorm8(self.func, alpha::reference_unorm8(self.reference), &alphas[..n], live)
        } else {
            let mut alphas = [0f32; MAX_SPAN];
            for (a, c) in alphas.iter_mut().zip(&colors[..n]) {
                *a = c[3];
            }
            alpha::alpha_test_f32(self.func, self.reference, &alphas[..n], live)
        }
    }

    /// Whether a fragment of alpha `a` passes (one test for a whole flat span).
    pub fn passes_one(&self, a: f32) -> bool {
        self.test(&[[0.0, 0.0, 0.0, a]], 1) != 0
    }
}

/// The stencil state of a draw: the face front-facing primitives use and the one
/// back-facing polygons use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilTest {
    pub front: StencilFace,
    pub back: StencilFace,
}

/// The stencil test, the depth test and the stencil operations on the fragments of `live`
/// (the `n` pixels from `row_start`), in GL order: fragments failing the stencil test take
/// `sfail`; the survivors are depth-tested (depth written only where both pass) and take
/// `zfail` or `zpass`. Without `stencil` this is the depth test alone. Returns the survivors.
pub fn stencil_depth_test(
    stencil: Option<&StencilFace>,
    depth: Option<&DepthTest>,
    band: &mut DepthBand<'_>,
    row_start: usize,
    n: usize,
    z: &[f32],
    live: u64,
) -> u64 {
    let Some(face) = stencil else {
        return match depth {
            Some(test) => depth_test(test, band, row_start, z, live),
            None => live,
        };
    };
    let mut values = [0u8; MAX_SPAN];
    let values = &mut values[..n];
    match band {
        DepthBand::Packed24(px) => stencil::load_packed(&px[row_start..row_start + n], values),
        DepthBand::Depth32(_, Some(s)) | DepthBand::Float32(_, Some(s)) => {
            values.copy_from_slice(&s[row_start..row_start + n])
        }
        // No stencil bits: the context compiles no stencil test then.
        _ => return live,
    }
    let pass = stencil::stencil_and_depth(face, values, live, |m| match depth {
        Some(test) => depth_test(test, band, row_start, z, m),
        None => m,
    });
    match band {
        DepthBand::Packed24(px) => stencil::store_packed(values, &mut px[row_start..row_start + n]),
        DepthBand::Depth32(_, Some(s)) | DepthBand::Float32(_, Some(s)) => {
            s[row_start..row_start + n].copy_from_slice(values)
        }
        _ => {}
    }
    pass
}

/// Whether `fragment func stored` holds; shared by the depth, stencil and alpha tests.
#[inline]
pub(crate) fn passes(func: CompareFunc, fragment: u32, stored: u32) -> bool {
    match func {
        CompareFunc::Never => false,
        CompareFunc::Less => fragment < stored,
        CompareFunc::Equal => fragment == stored,
        CompareFunc::LessEqual => fragment <= stored,
        CompareFunc::Greater => fragment > stored,
        CompareFunc::NotEqual => fragment != stored,
        CompareFunc::GreaterEqual => fragment >= stored,
        CompareFunc::Always => true,
    }
}

/// Depth-tests the fragments of `live` (bit i: pixel `offset + i` of the row) against the
/// row of `depth` starting at `offset`, updating stored depth where the test passes and
/// writing is enabled. `z` holds window-space depths. Returns the fragments that pass.
pub fn depth_test(test: &DepthTest, depth: &mut DepthBand<'_>, row_start: usize, z: &[f32], live: u64) -> u64 {
    use crate::framebuffer::format::DepthEncoding::{Float, Unorm};
    // One loop per comparison function and format, so that the comparison is not chosen
    // again at every pixel.
    macro_rules! run_with {
        ($px:expr, $encoding:expr, $read:expr, $write:expr, $cmp:expr) => {{
            let mut pass = 0u64;
            let cells = &mut $px[row_start..row_start + z.len()];
            for (i, (&zf, cell)) in z.iter().zip(cells.iter_mut()).enumerate() {
                if live & (1 << i) == 0 {
                    continue;
                }
                let frag = $encoding.encode_fragment(zf);
                #[allow(clippy::redundant_closure_call)]
                let stored = ($read)(*cell);
                #[allow(clippy::redundant_closure_call)]
                if ($cmp)(frag, stored) {
                    pass |= 1 << i;
                    if test.write {
                        ($write)(cell, frag);
                    }
                }
            }
            pass
        }};
    }
    macro_rules! run {
        ($px:expr, $bits:expr, $read:expr, $write:expr) => {
            match test.func {
                CompareFunc::Never => 0,
                CompareFunc::Less => run_with!($px, $bits, $read, $write, |f: u32, s: u32| f < s),
                CompareFunc::Equal => run_with!($px, $bits, $read, $write, |f: u32, s: u32| f == s),
                CompareFunc::LessEqual => run_with!($px, $bits, $read, $write, |f: u32, s: u32| f <= s),
                CompareFunc::Greater => run_with!($px, $bits, $read, $write, |f: u32, s: u32| f > s),
                CompareFunc::NotEqual => run_with!($px, $bits, $read, $write, |f: u32, s: u32| f != s),
                CompareFunc::GreaterEqual => run_with!($px, $bits, $read, $write, |f: u32, s: u32| f >= s),
                CompareFunc::Always => run_with!($px, $bits, $read, $write, |_: u32, _: u32| true),
            }
        };
    }
    match depth {
        DepthBand::None => live,
        DepthBand::Depth16(px) => run!(px, Unorm(16), |v: u16| v as u32, |c: &mut u16, f: u32| *c = f as u16),
        DepthBand::Packed24(px) => {
            run!(px, Unorm(24), |v: u32| v & 0x00ff_ffff, |c: &mut u32, f: u32| *c = (*c & 0xff00_0000) | f)
        }
        DepthBand::Depth32(px, _) => run!(px, Unorm(32), |v: u32| v, |c: &mut u32, f: u32| *c = f),
        // Float bit patterns of values in [0, 1] compare as the values: same integer test.
        DepthBand::Float32(px, _) => run!(px, Float, |v: u32| v, |c: &mut u32, f: u32| *c = f),
    }
}

/// Writes `colors[i]` for every bit of `live` to the row of `target` starting at
/// `row_start`, converting to the buffer's format and honouring the channel `mask`.
pub fn write_colors(
    target: &mut ColorBand<'_>,
    row_start: usize,
    colors: &[[f32; 4]],
    live: u64,
    mask: [bool; 4],
    clamp_float: bool,
) {
    // One copy per SIMD level (`crate::simd`): the body's conversion loops run with the CPU's
    // instructions.
    crate::simd::per_level!({
        let all = mask.iter().all(|&m| m);
        let lanes = colors.iter().enumerate().filter(|(i, _)| live & (1 << i) != 0);
        match target {
            ColorBand::Unorm8(px) if all && live == span_mask(colors.len()) => {
                // Every fragment written, every channel: a plain loop the compiler can unroll.
                let cells = &mut px[row_start..row_start + colors.len()];
                for (cell, c) in cells.iter_mut().zip(colors) {
                    *cell = c.map(|x| float_to_unorm(x, 8) as u8);
                }
            }
            ColorBand::Unorm8(px) => {
                for (i, c) in lanes {
                    let v = c.map(|x| float_to_unorm(x, 8) as u8);
                    let cell = &mut px[row_start + i];
                    if all {
                        *cell = v;
                    } else {
                        (0..4).filter(|&k| mask[k]).for_each(|k| cell[k] = v[k]);
                    }
                }
            }
            ColorBand::Unorm16(px) => {
                for (i, c) in lanes {
                    let v = c.map(|x| float_to_unorm(x, 16) as u16);
                    let cell = &mut px[row_start + i];
                    (0..4).filter(|&k| mask[k]).for_each(|k| cell[k] = v[k]);
                }
            }
            ColorBand::Float32(px) => {
                for (i, c) in lanes {
                    let v = if clamp_float { c.map(|x| if x > 0.0 { x.min(1.0) } else { 0.0 }) } else { *c };
                    let cell = &mut px[row_start + i];
                    (0..4).filter(|&k| mask[k]).for_each(|k| cell[k] = v[k]);
                }
            }
            ColorBand::Rgb565(px) => {
                // 5/6-bit stores take the top bits of the 8-bit conversion, as llvmpipe's do.
                let keep: u16 = (if mask[0] { 0 } else { 0xf800 })
                    | (if mask[1] { 0 } else { 0x07e0 })
                    | (if mask[2] { 0 } else { 0x001f });
                for (i, c) in lanes {
                    let [r, g, b, _] = c.map(|x| float_to_unorm(x, 8));
                    let v = ((r >> 3) << 11 | (g >> 2) << 5 | (b >> 3)) as u16;
                    let cell = &mut px[row_start + i];
                    *cell = (*cell & keep) | (v & !keep);
                }
            }
        }
    })
}

/// Writes one color to every fragment of `live` in the `n` pixels from `row_start`: the flat
/// shaded case, converted once per span instead of once per pixel.
pub fn write_uniform_color(
    target: &mut ColorBand<'_>,
    row_start: usize,
    n: usize,
    color: [f32; 4],
    live: u64,
    mask: [bool; 4],
    clamp_float: bool,
) {
    let all_live = live == span_mask(n);
    if let (ColorBand::Unorm8(px), [true, true, true, true]) = (&mut *target, mask) {
        let v = color.map(|x| float_to_unorm(x, 8) as u8);
        if all_live {
            px[row_start..row_start + n].fill(v);
        } else {
            let mut bits = live;
            while bits != 0 {
                let i = bits.trailing_zeros() as usize;
                px[row_start + i] = v;
                bits &= bits - 1;
            }
        }
        return;
    }
    let colors = [color; MAX_SPAN];
    write_colors(target, row_start, &colors[..n], live, mask, clamp_float);
}

#[cfg(test)]
mod tests {
    use super::stencil::StencilOp as O;
    use super::*;
    use crate::framebuffer::format::fragment_depth_to_fixed;

    const FACE: StencilFace = StencilFace {
        func: CompareFunc::Equal,
        reference: 3,
        value_mask: 0xff,
        write_mask: 0xff,
        sfail: O::Zero,
        zfail: O::Incr,
        zpass: O::Invert,
    };

    #[test]
    fn stencil_then_depth_on_packed_and_separate_storage() {
        // Pixels: stencil fails; stencil passes, depth fails; both pass.
        let depth = DepthTest { func: CompareFunc::Less, write: true };
        let z = [0.25f32, 0.75, 0.25];
        let mut packed = [0x0100_0000 | 0x80_0000u32, 0x0380_0000, 0x0380_0000];
        let pass =
            stencil_depth_test(Some(&FACE), Some(&depth), &mut DepthBand::Packed24(&mut packed), 0, 3, &z, 0b111);
        assert_eq!(pass, 0b100);
        let q = fragment_depth_to_fixed(0.25, 24);
        assert_eq!(packed, [0x0080_0000, 0x0480_0000, 0xfc00_0000 | q]);
        let mut depth32 = [0x8000_0000u32; 3];
        let mut stencil = [1u8, 3, 3];
        let band = &mut DepthBand::Depth32(&mut depth32, Some(&mut stencil));
        assert_eq!(stencil_depth_test(Some(&FACE), Some(&depth), band, 0, 3, &z, 0b111), 0b100);
        assert_eq!(stencil, [0, 4, 0xfc]);
        assert_eq!(depth32, [0x8000_0000, 0x8000_0000, fragment_depth_to_fixed(0.25, 32)]);
        // Without a depth test every stencil survivor takes zpass.
        let mut stencil = [1u8, 3, 3];
        let band = &mut DepthBand::Depth32(&mut depth32, Some(&mut stencil));
        assert_eq!(stencil_depth_test(Some(&FACE), None, band, 0, 3, &z, 0b011), 0b010);
        assert_eq!(stencil, [0, 0xfc, 3]);
    }
}
