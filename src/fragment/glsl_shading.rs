//! GLSL fragment shading: a linked program's fragment stage run in a draw in place of the
//! fixed-function fragment program (texturing, the texture environments, the colour sum and
//! fog; GL 2.1 §3.11), over a 4×4 block ([`GlslShading::run_block`]) or a span
//! ([`GlslShading::run_span`]), with the quads of [`super::shading`] (llvmpipe's, for
//! derivatives and implicit levels of detail).
//!
//! The context wires the program once per draw state ([`GlslShading`]'s lists): what each
//! input slot reads ([`ShaderInput`]: the primary colour, a varying the draw interpolates,
//! `gl_FragCoord`, `gl_FrontFacing`), where each output slot goes ([`ShaderOutput`]: a draw
//! buffer's colour, the fragment depth), the uniform words, and each sampler's texture
//! (a [`Texturing`] whose stage `i` is the program's sampler `i`, IR `Sample.unit` `i`).
//! Two inputs come through varyings the draw interpolates like any other: `gl_FragCoord.w`
//! is 1 over the clip w ([`ShaderInput::Reciprocal`] of `Attribute::CLIP_W`, perspective-
//! correct, so 1/w interpolated linearly in the window), and `gl_PointCoord` is a point
//! sprite's s and t (`Attribute::point_coord`, which a sprite replaces as GL_COORD_REPLACE
//! replaces a texture coordinate).
//!
//! Unlike the fixed-function program, a shader may drop fragments (`discard`) and replace
//! their depth (`gl_FragDepth`): then the pipeline runs it before the alpha, stencil and
//! depth tests ([`GlslShading::late_tests`]), and both runs return the fragments that
//! survive and leave the depths to test in their `depth` lanes.
//!
//! `gl_FragColor` (and `gl_FragData[0]` alone) reaches every draw buffer; a shader that
//! writes `gl_FragData[n]` for n > 0 gives each draw buffer its own colour: the span run
//! keeps those colours in the scratch ([`GlslShading::target_colors`]), and such a draw
//! takes the span path (the block path has one colour per fragment).
//!
//! Every lane of a quad with a live lane runs when the program takes derivatives (helper
//! lanes: their own pixel's inputs); on a span, a helper lane in the other row of the quad
//! takes the primary colour and depth of the span's pixel in its column (the span path has
//! no other row's colours), so `dFdy` of those is 0 there.
//!
//! Known differences from GL: `gl_PointCoord` is (0, 0) on points without GL_POINT_SPRITE;
//! a lookup's explicit level is ignored (only vertex shaders have one).

use super::block::{F32s, LANES};
use super::shading::{quads, StageTextures};
use crate::shader::exec::{Io, Word};
use crate::shader::fast::{Compiled, Registers, Specialization};
use crate::shader::ir::{Inst, Lod, Program, Stmt};
use crate::texture::Texturing;
use std::fmt::Debug;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// The next [`GlslShading::id`] (0: a fresh scratch has prepared none).
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// Where an input word of a shader comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderInput {
    /// Channel 0..4 of the primary (interpolated or flat) colour: `gl_Color`.
    Primary(u8),
    /// A varying of the draw (index into the draw's varying list).
    Varying(u16),
    /// `gl_FragCoord`'s component: window x + ½, y + ½, the depth (w comes as
    /// [`ShaderInput::Reciprocal`]).
    FragCoord(u8),
    /// 1 over a varying of the draw: `gl_FragCoord.w`, 1 over the interpolated clip w.
    Reciprocal(u16),
    /// `gl_FrontFacing` (a bool: 1 or 0).
    FrontFacing,
    /// Anything the draw does not supply (`gl_PointCoord`, a varying beyond the vertex
    /// record's slots): 0.
    Zero,
}

/// Where an output word of a shader goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderOutput {
    /// Channel `channel` of the colour of draw buffer `buffer` (`gl_FragColor` is buffer 0
    /// and reaches every target; `gl_FragData[n]` is buffer n).
    Color { buffer: u8, channel: u8 },
    /// `gl_FragDepth`.
    Depth,
    /// Not used by the pipeline.
    Unused,
}

/// A linked program's compiled fragment stage, as the context holds it.
pub trait ShaderCode: Send + Sync + Debug {
    fn compiled(&self) -> &Compiled;
}

/// A draw's GLSL fragment shading: the program and everything it reads.
#[derive(Debug)]
pub struct GlslShading {
    code: Arc<dyn ShaderCode>,
    inputs: Vec<ShaderInput>,
    outputs: Vec<ShaderOutput>,
    uniforms: Vec<u32>,
    /// How many varyings the draw interpolates for the program.
    varyings: usize,
    /// Stage `i` samples for the program's sampler `i` (a sampler whose texture is
    /// incomplete has no stage: its lookups read (0, 0, 0, 1)).
    textures: Texturing,
    discards: bool,
    writes_depth: bool,
    derivatives: bool,
    /// 1 + the highest n > 0 of the `gl_FragData[n]` written (0: one colour, broadcast).
    data_buffers: usize,
    /// Bit n: the shader writes `gl_FragData[n]`.
    data_written: u32,
    /// The draw buffer index of each of the band's colour targets (when `data_buffers`).
    target_buffers: Vec<u8>,
    /// Which shading a scratch's registers were prepared for (its uniform values).
    id: u64,
    /// The program specialised on `uniforms` ([`Compiled::specialize`]).
    specialized: Arc<Specialization>,
}

impl PartialEq for GlslShading {
    /// Two draws shade alike if they run the very same program on the same values.
    fn eq(&self, other: &Self) -> bool {
        std::ptr::addr_eq(Arc::as_ptr(&self.code), Arc::as_ptr(&other.code))
            && self.inputs == other.inputs
            && self.outputs == other.outputs
            && self.uniforms == other.uniforms
            && self.textures == other.textures
            && self.target_buffers == other.target_buffers
    }
}

/// What a program's body may do, found by one walk of its statements.
#[derive(Default)]
struct Traits {
    discards: bool,
    derivatives: bool,
}

fn walk(body: &[Stmt], traits: &mut Traits) {
    for stmt in body {
        match stmt {
            Stmt::Discard => traits.discards = true,
            Stmt::Inst(Inst::Derivative { .. }) => traits.derivatives = true,
            Stmt::Inst(Inst::Sample { lod: Lod::Implicit | Lod::Bias(_), .. }) => traits.derivatives = true,
            Stmt::If { then, otherwise, .. } => {
                walk(then, traits);
                walk(otherwise, traits);
            }
            Stmt::Loop { body } => walk(body, traits),
            _ => {}
        }
    }
}

impl GlslShading {
    /// The shading of `program` (the IR the code was compiled from) with its slots wired as
    /// `inputs` and `outputs`, its uniform words `uniforms`, `varyings` interpolated
    /// varyings and its samplers' `textures`.
    pub fn new(
        code: Arc<dyn ShaderCode>,
        program: &Program,
        inputs: Vec<ShaderInput>,
        outputs: Vec<ShaderOutput>,
        uniforms: Vec<u32>,
        varyings: usize,
        textures: Texturing,
    ) -> GlslShading {
        let mut traits = Traits::default();
        walk(&program.body, &mut traits);
        let data_buffers = outputs
            .iter()
            .filter_map(|o| match *o {
                ShaderOutput::Color { buffer, .. } if buffer > 0 => Some(buffer as usize + 1),
                _ => None,
            })
            .max()
            .unwrap_or(0);
        let data_written = outputs.iter().fold(0u32, |bits, o| match *o {
            ShaderOutput::Color { buffer, .. } => bits | 1u32.checked_shl(buffer.into()).unwrap_or(0),
            _ => bits,
        });
        let specialized = code.compiled().specialize(&uniforms);
        GlslShading {
            specialized,
            code,
            data_buffers,
            data_written,
            target_buffers: Vec::new(),
            writes_depth: outputs.contains(&ShaderOutput::Depth),
            inputs,
            outputs,
            uniforms,
            varyings,
            textures,
            discards: traits.discards,
            derivatives: traits.derivatives,
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
        }
    }

    /// Whether the alpha, stencil and depth tests must wait for the shader: it may discard,
    /// or it writes the depth.
    pub fn late_tests(&self) -> bool {
        self.discards || self.writes_depth
    }

    /// The shading with the band's colour target `i` being draw buffer `buffers[i]` (where
    /// `gl_FragData[n]` goes).
    pub fn with_target_buffers(mut self, buffers: Vec<u8>) -> GlslShading {
        self.target_buffers = buffers;
        self
    }

    /// Whether the shader writes `gl_FragData[n]` for some n > 0: then each draw buffer has
    /// its own colour ([`GlslShading::target_colors`]), and the draw takes the span path.
    #[inline]
    pub fn writes_data(&self) -> bool {
        self.data_buffers > 0
    }

    /// The colours of the span shaded last for the band's colour target `index`: its draw
    /// buffer's `gl_FragData[n]`, or `colors` (buffer 0's) for buffer 0 and any buffer the
    /// shader does not write.
    #[inline]
    pub fn target_colors<'a>(&self, scratch: &'a GlslScratch, index: usize, colors: &'a [[f32; 4]]) -> &'a [[f32; 4]] {
        match self.target_buffers.get(index).copied().unwrap_or(0) {
            0 => colors,
            b if self.data_written & 1u32.checked_shl(b.into()).unwrap_or(0) == 0 => colors,
            b => scratch.span_data.get(b as usize - 1).map_or(colors, |c| &c[..colors.len().min(c.len())]),
        }
    }

    /// Whether the shader writes `gl_FragDepth` (then the depths of the runs are its).
    pub fn writes_depth(&self) -> bool {
        self.writes_depth
    }

    /// Shades the lanes `live` of the 4×4 block at window `(x, y)` (lane `i` the pixel
    /// `(x + (i & 3), y + (i >> 2))`) of a primitive facing `front_facing`; returns the
    /// lanes that did not discard. `inputs(y0, colors, z, varyings)` gives the primary
    /// colours, depths and varyings of the 16 lanes of the block at `(x, y0)` (`y0` is `y`,
    /// or `y − 1` and `y + 3` for the quads, see [`super::shading`]). `colors` and `depth`
    /// receive the shaded colour and depth of the surviving lanes.
    #[allow(clippy::too_many_arguments)]
    pub fn run_block(
        &self,
        scratch: &mut GlslScratch,
        x: i32,
        y: i32,
        live: u16,
        front_facing: bool,
        colors: &mut [F32s; 4],
        depth: &mut F32s,
        inputs: impl Fn(i32, &mut [F32s; 4], &mut F32s, &mut [F32s]),
    ) -> u16 {
        if live == 0 {
            return 0;
        }
        scratch.prepare(self);
        let aligned = !self.derivatives || (self.textures.fb_height - y) & 1 == 0;
        let px: F32s = std::array::from_fn(|i| (x + (i & 3) as i32) as f32 + 0.5);
        if aligned {
            // One pass over the block itself: its inputs and results in `colors` and `depth`
            // directly (the shifted passes' copies below were five `memcpy` calls a block).
            inputs(y, colors, depth, &mut scratch.varyings[..self.varyings]);
            let py: F32s = std::array::from_fn(|i| (y + (i >> 2) as i32) as f32 + 0.5);
            return self.run(scratch, live, front_facing, &px, &py, colors, depth) & live;
        }
        // The block straddles llvmpipe's quads: the rows above and below, shifted.
        let mut survivors = 0;
        for (dy, lanes) in [(-1, live << 4), (3, live >> 12)] {
            if lanes == 0 {
                continue;
            }
            let y0 = y + dy;
            let mut primary = [[0.0; LANES]; 4];
            let mut z = [0.0; LANES];
            inputs(y0, &mut primary, &mut z, &mut scratch.varyings[..self.varyings]);
            let py: F32s = std::array::from_fn(|i| (y0 + (i >> 2) as i32) as f32 + 0.5);
            let kept = self.run(scratch, lanes, front_facing, &px, &py, &mut primary, &mut z);
            // Back to the block's lanes: the shifted block's lane j is the block's j − 4·dy.
            let (from, to, count) = if dy < 0 { (4, 0, 12) } else { (0, 12, 4) };
            for (c, p) in colors.iter_mut().zip(&primary) {
                c[to..to + count].copy_from_slice(&p[from..from + count]);
            }
            depth[to..to + count].copy_from_slice(&z[from..from + count]);
            let bits = ((1u32 << count) - 1) as u16;
            survivors |= ((kept >> from) & bits) << to;
        }
        survivors & live
    }

    /// Shades the fragments `live` of the span at window row `y`, columns `x0 ..
    /// x0 + colors.len()`, of a primitive facing `front_facing`; returns the fragments that
    /// did not discard. `colors` and `depth` hold the primary colours and depths and
    /// receive the shaded ones; `varyings_at(dx, dy, out)` evaluates the draw's varyings at
    /// the pixel `dx` columns right of the span's first and `dy` rows above it.
    #[allow(clippy::too_many_arguments)]
    pub fn run_span(
        &self,
        scratch: &mut GlslScratch,
        x0: i32,
        y: i32,
        live: u64,
        front_facing: bool,
        colors: &mut [[f32; 4]],
        depth: &mut [f32],
        varyings_at: impl Fn(i32, i32, &mut [f32]),
    ) -> u64 {
        let n = colors.len().min(64).min(depth.len());
        let mut rest = live & super::span_mask(n);
        let mut survivors = 0u64;
        if rest == 0 {
            return 0;
        }
        scratch.prepare(self);
        for data in &mut scratch.span_data {
            data.clear();
            data.resize(n, [0.0; 4]);
        }
        // As the fixed-function span run: lane rows 0 and 2 are the lower row of
        // llvmpipe's quads holding row `y`, the span is lane row `row` (and `row + 2`).
        let low = if (self.textures.fb_height - y) & 1 == 0 { y } else { y - 1 };
        let row = (y - low) as usize;
        let mut pixel = vec![0.0; self.varyings];
        while rest != 0 {
            let left = (x0 + rest.trailing_zeros() as i32) & !7;
            let lane_of = |d: i32| 4 * (2 * (d >> 2) as usize + row) + (d & 3) as usize;
            let mut lanes = 0u16;
            for d in 0..8 {
                let i = left + d - x0;
                if (0..n as i32).contains(&i) && rest & (1u64 << i) != 0 {
                    lanes |= 1 << lane_of(d);
                }
            }
            for d in 0..8 {
                let i = left + d - x0;
                if (0..64).contains(&i) {
                    rest &= !(1u64 << i);
                }
            }
            let evaluated = if self.derivatives { quads(lanes) } else { lanes };
            let mut primary = [[0.0; LANES]; 4];
            let mut z = [0.0; LANES];
            let (mut px, mut py) = ([0.0; LANES], [0.0; LANES]);
            for v in &mut scratch.varyings[..self.varyings] {
                *v = [0.0; LANES];
            }
            for lane in 0..LANES {
                let (lane_row, col) = (lane >> 2, (lane & 3) as i32);
                let dx = left + col + 4 * (lane_row >> 1) as i32 - x0;
                let dy = low + (lane_row & 1) as i32 - y;
                px[lane] = (x0 + dx) as f32 + 0.5;
                py[lane] = (y + dy) as f32 + 0.5;
                if evaluated & (1 << lane) == 0 {
                    continue;
                }
                if (0..n as i32).contains(&dx) {
                    for (k, p) in primary.iter_mut().enumerate() {
                        p[lane] = colors[dx as usize][k];
                    }
                    z[lane] = depth[dx as usize];
                }
                varyings_at(dx, dy, &mut pixel);
                for (v, value) in scratch.varyings.iter_mut().zip(&pixel) {
                    v[lane] = *value;
                }
            }
            let kept = self.run(scratch, lanes, front_facing, &px, &py, &mut primary, &mut z);
            for d in 0..8 {
                let i = left + d - x0;
                let lane = lane_of(d);
                if kept & (1 << lane) != 0 {
                    for (data, lanes) in scratch.span_data.iter_mut().zip(&scratch.data) {
                        data[i as usize] = std::array::from_fn(|k| lanes[k][lane]);
                    }
                    colors[i as usize] = std::array::from_fn(|k| primary[k][lane]);
                    depth[i as usize] = z[lane];
                    survivors |= 1 << i;
                }
            }
        }
        survivors
    }

    /// Runs the program on the lanes `live` of a block whose row pairs are llvmpipe's quads
    /// (or that takes no derivatives), at window pixels `px`, `py` (centres): the
    /// varyings in `scratch`, `colors` and `z` the primary colours and depths, replaced by
    /// the program's. Returns the lanes of `live` that did not discard.
    #[allow(clippy::too_many_arguments)]
    fn run(
        &self,
        scratch: &mut GlslScratch,
        live: u16,
        front_facing: bool,
        px: &F32s,
        py: &F32s,
        colors: &mut [F32s; 4],
        z: &mut F32s,
    ) -> u16 {
        let GlslScratch { registers, inputs, varyings, outputs, prepared, data, .. } = scratch;
        let compiled = self.code.compiled();
        if *prepared != self.id {
            compiled.prepare_specialized(&self.specialized, registers);
            *prepared = self.id;
        }
        for (word, source) in inputs.iter_mut().zip(&self.inputs) {
            *word = match *source {
                ShaderInput::Primary(k) => bits(&colors[k as usize & 3]),
                ShaderInput::Varying(v) => bits(&varyings[v as usize]),
                ShaderInput::FragCoord(0) => bits(px),
                ShaderInput::FragCoord(1) => bits(py),
                ShaderInput::FragCoord(2) => bits(z),
                ShaderInput::FragCoord(_) => [1f32.to_bits(); LANES],
                ShaderInput::Reciprocal(v) => bits(&varyings[v as usize].map(|w| 1.0 / w)),
                ShaderInput::FrontFacing => [u32::from(front_facing); LANES],
                ShaderInput::Zero => [0; LANES],
            };
        }
        let running = if self.derivatives { quads(live) } else { live };
        let textures = StageTextures { texturing: Some(&self.textures), used: !0 };
        let mut io = Io { inputs, uniforms: &self.uniforms, outputs, textures: &textures };
        let kept = compiled.run_specialized(&self.specialized, registers, &mut io, running) & live;
        for (out, target) in outputs.iter().zip(&self.outputs) {
            match *target {
                ShaderOutput::Color { buffer: 0, channel } => colors[channel as usize & 3] = floats(out),
                ShaderOutput::Color { buffer, channel } => {
                    data[buffer as usize - 1][channel as usize & 3] = floats(out)
                }
                ShaderOutput::Depth => {
                    // GL 2.1 §3.11.2: the shader's depth is clamped to [0, 1].
                    *z = floats(out);
                    for d in z.iter_mut() {
                        *d = if *d > 0.0 { d.min(1.0) } else { 0.0 };
                    }
                }
                _ => {}
            }
        }
        kept
    }
}

// Plain loops, not `array::map`: without LTO those stayed calls, ten per run (a tenth of
// phong's instructions).

/// The bit patterns of 16 f32 lanes.
#[inline(always)]
fn bits(lanes: &F32s) -> Word {
    let mut out = [0; LANES];
    for (o, v) in out.iter_mut().zip(lanes) {
        *o = v.to_bits();
    }
    out
}

/// The f32 lanes of 16 bit patterns.
#[inline(always)]
fn floats(word: &Word) -> F32s {
    let mut out = [0.0; LANES];
    for (o, w) in out.iter_mut().zip(word) {
        *o = f32::from_bits(*w);
    }
    out
}

/// A worker's storage for runs of GLSL fragment programs, reused from block to block.
#[derive(Default)]
pub struct GlslScratch {
    registers: Registers,
    inputs: Vec<Word>,
    varyings: Vec<F32s>,
    outputs: Vec<Word>,
    /// The [`GlslShading::id`] whose uniform values `registers` hold (0: none).
    prepared: u64,
    /// `gl_FragData[n + 1]`'s lanes of a run.
    data: Vec<[F32s; 4]>,
    /// `gl_FragData[n + 1]` of the span shaded last, per pixel.
    span_data: Vec<Vec<[f32; 4]>>,
}

impl GlslScratch {
    /// Room for `shading`'s program.
    fn prepare(&mut self, shading: &GlslShading) {
        self.inputs.resize(shading.inputs.len(), [0; LANES]);
        self.outputs.resize(shading.outputs.len(), [0; LANES]);
        if self.varyings.len() < shading.varyings {
            self.varyings.resize(shading.varyings, [0.0; LANES]);
        }
        let extra = shading.data_buffers.saturating_sub(1);
        self.data.resize(extra, [[0.0; LANES]; 4]);
        self.span_data.resize_with(extra, Vec::new);
    }
}

#[cfg(test)]
mod tests;
