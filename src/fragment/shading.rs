//! Fragment shading: a draw's fragment program ([`super::program`], looked up in the share
//! group's cache once per draw state) run over 16 lanes by the shading executor
//! ([`crate::shader::fast`]), for a 4×4 block ([`Shading::run_block`]) or a span
//! ([`Shading::run_span`]): one path for texturing, the texture environments, the colour sum
//! and fog, whatever the primitive. A draw whose program would pass the colour through (no
//! unit, no colour sum, no fog) has none, and its colours are not touched.
//!
//! Texture lookups go to the texture room through [`StageTextures`], the executor's
//! [`Textures`] over a draw's units: [`crate::texture::TextureStage::sample_lanes`], the
//! coordinates divided by q (0 when q is 0) and llvmpipe's level of detail per 2×2 quad.
//!
//! **Quads.** The executor's lanes are row-major, and a lookup's quads are the lane row pairs
//! (0, 1) and (2, 3). llvmpipe's quads pair its y-down rows, so they are the block's row
//! pairs when `fb_height − y` is even; otherwise they straddle the block's edges, and a
//! program whose lookups need derivatives runs on the block one row below (rows 0..3 of the
//! block as its rows 1..4) and the block three rows above (row 3 as its row 0), whose row
//! pairs are llvmpipe's quads. Running the program on those shifted blocks, rather than
//! asking the sampler for other pixels' coordinates, is what a program computing its
//! coordinates (GLSL) needs too. A span runs as 16-lane groups of 8 columns of its row and
//! the row it shares quads with (lane rows 0 and 1 the left 4 columns, 2 and 3 the right 4).
//! Every lane of a quad with a live lane runs (helper lanes: their own pixel's varyings),
//! only the live lanes' colours are kept.

use super::block::{lanes, F32s, LANES};
use super::program::{CompiledFragment, FragmentInput, FragmentKey};
use super::FragmentState;
use crate::shader::exec::{Io, LodLanes, SampleRequest, Textures, Word};
use crate::shader::fast::{lane_mask, Bound, Registers};
use crate::shader::lower::R;
use crate::simd::Supported;
use crate::texture::Texturing;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// The next [`Shading::id`] (0 is no shading: a fresh scratch has prepared none).
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// The most varyings a fixed-function fragment program reads: the secondary colour, the
/// fog coordinate and every unit's s, t, r, q.
const MAX_VARYINGS: usize = 4 + 4 * super::program::MAX_UNITS;

/// A draw's fragment shading: its compiled program and the values it reads.
#[derive(Debug)]
pub struct Shading {
    pub program: Arc<CompiledFragment>,
    /// The uniform words (environment colours, fog parameters) of the draw.
    uniforms: Vec<u32>,
    /// Runs of consecutive varyings the program reads: (first, count).
    varying_runs: Vec<(usize, usize)>,
    /// One more than the highest varying the program reads.
    varyings: usize,
    /// Whether a lookup depends on derivatives (then quads matter).
    derivatives: bool,
    /// Framebuffer height: llvmpipe's quads pair its y-down rows.
    fb_height: i32,
    /// With the program's bound form: the primary colour channels its registers take
    /// (register, channel), the varyings (register, varying), and the output registers
    /// the colour channels take (channel, register), less a channel the program passes
    /// through unchanged.
    bound_primary: Vec<(R, usize)>,
    bound_varyings: Vec<(R, usize)>,
    bound_outputs: Vec<(usize, R)>,
    /// Which shading a scratch's registers were prepared for (its uniform values).
    id: u64,
    /// The program's arithmetic written out, when the program is linear fog alone
    /// ([`LinearFog`]): blocks then skip the executor.
    linear_fog: Option<LinearFog>,
}

impl PartialEq for Shading {
    /// Two draws shade alike if they run the very same program on the same values.
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.program, &other.program)
            && self.uniforms == other.uniforms
            && self.fb_height == other.fb_height
    }
}

/// Whether `key`'s program passes the primary colour through unchanged (then a draw has no
/// [`Shading`]).
pub fn is_identity(key: &FragmentKey) -> bool {
    key.stages.is_empty() && key.color_sum.is_none() && key.fog.is_none()
}

impl Shading {
    /// The shading of `state` (its texturing, colour sum and fog) by `program`, the program
    /// of `FragmentKey::of(state)`.
    pub fn new(program: Arc<CompiledFragment>, state: &FragmentState) -> Shading {
        let stages = state.texturing.as_ref().map_or(&[][..], |t| &t.stages[..]);
        let envs: Vec<_> = stages.iter().map(|s| &s.env).collect();
        let uniforms = program.fixed.uniform_values(&envs, state.fog.as_ref());
        let mut read: Vec<usize> = program
            .fixed
            .inputs
            .iter()
            .filter_map(|i| match *i {
                FragmentInput::Varying(v) => Some(v as usize),
                FragmentInput::Primary(_) => None,
            })
            .collect();
        read.sort_unstable();
        read.dedup();
        let mut varying_runs: Vec<(usize, usize)> = Vec::new();
        for v in &read {
            match varying_runs.last_mut() {
                Some((first, count)) if *first + *count == *v => *count += 1,
                _ => varying_runs.push((*v, 1)),
            }
        }
        let (mut bound_primary, mut bound_varyings, mut bound_outputs) = (Vec::new(), Vec::new(), Vec::new());
        if let Some(bound) = &program.bound {
            let input = |slot: usize| bound.input_register(slot);
            let primary_register = |k: usize| {
                let slot = program.fixed.inputs.iter().position(|i| *i == FragmentInput::Primary(k as u8));
                slot.and_then(input)
            };
            for k in 0..4 {
                let Some(r) = bound.output_register(k) else { continue };
                if primary_register(k) != Some(r) {
                    bound_outputs.push((k, r));
                }
            }
            for (slot, source) in program.fixed.inputs.iter().enumerate() {
                let Some(r) = input(slot) else { continue };
                match *source {
                    FragmentInput::Primary(k) => {
                        // A channel passed through unchanged and read by nothing else
                        // stays where it is.
                        if bound.reads_register(r) || bound_outputs.iter().any(|&(_, o)| o == r) {
                            bound_primary.push((r, k as usize & 3));
                        }
                    }
                    FragmentInput::Varying(v) => bound_varyings.push((r, v as usize)),
                }
            }
        }
        Shading {
            uniforms,
            bound_primary,
            bound_varyings,
            bound_outputs,
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            linear_fog: LinearFog::of(&FragmentKey::of(state), state.fog.as_ref()),
            varying_runs,
            varyings: read.last().map_or(0, |v| v + 1),
            derivatives: stages.iter().any(|s| s.needs_derivatives()),
            fb_height: state.texturing.as_ref().map_or(0, |t| t.fb_height),
            program,
        }
    }

    /// The program written out when it is linear fog alone ([`LinearFog`]).
    pub fn linear_fog(&self) -> Option<&LinearFog> {
        self.linear_fog.as_ref()
    }

    /// Shades the lanes `live` of the 4×4 block at window `(x, y)` (lane `i` the pixel
    /// `(x + (i & 3), y + (i >> 2))`): `colors[channel][lane]` holds the primary colours and
    /// receives the program's colour in the live lanes (the other lanes' colours are left
    /// unspecified: the pipeline does not read them). `varying_lanes(y0, first, out)`
    /// gives varyings `first .. first + out.len()` of the 16 lanes of the block at
    /// `(x, y0)` (`y0` is `y`, or `y − 1` and `y + 3`, see the module). Inlined into the
    /// block pipeline's per-SIMD-level body, whose level `level` is.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn run_block(
        &self,
        level: Supported,
        scratch: &mut ShadingScratch,
        texturing: Option<&Texturing>,
        y: i32,
        live: u16,
        colors: &mut [F32s; 4],
        varying_lanes: impl Fn(i32, usize, &mut [F32s]),
    ) {
        if live == 0 {
            return;
        }
        if let Some(fog) = &self.linear_fog {
            // No lookups, so no quads: the block's own varyings, as the program's pass.
            let mut coordinate = [[0.0; LANES]];
            varying_lanes(y, 0, &mut coordinate);
            fog.apply(level, &coordinate[0], colors);
            return;
        }
        let textures = StageTextures { texturing, used: !0 };
        scratch.prepare(self);
        // The passes: the block itself, or (see the module) the block one row below, whose
        // rows 1..4 are the block's rows 0..3, and the block three rows above, whose row 0
        // is the block's row 3. One call site each for the varyings and the program, so
        // that both are inlined into the caller's SIMD level.
        let aligned = !self.derivatives || (self.fb_height - y) & 1 == 0;
        let passes: [(i32, u16); 2] = if aligned { [(0, live), (0, 0)] } else { [(-1, live << 4), (3, live >> 12)] };
        for (dy, lanes) in passes {
            if lanes == 0 {
                continue;
            }
            let mut shifted = [[0.0; LANES]; 4];
            let target = match dy {
                0 => &mut *colors,
                -1 => {
                    for (s, c) in shifted.iter_mut().zip(colors.iter()) {
                        s[4..].copy_from_slice(&c[..12]);
                    }
                    &mut shifted
                }
                _ => {
                    for (s, c) in shifted.iter_mut().zip(colors.iter()) {
                        s[..4].copy_from_slice(&c[12..]);
                    }
                    &mut shifted
                }
            };
            for &(first, count) in &self.varying_runs {
                varying_lanes(y + dy, first, &mut scratch.varyings[first..first + count]);
            }
            self.run(scratch, &textures, lanes, target);
            match dy {
                0 => {}
                -1 => {
                    for (s, c) in shifted.iter().zip(colors.iter_mut()) {
                        c[..12].copy_from_slice(&s[4..]);
                    }
                }
                _ => {
                    for (s, c) in shifted.iter().zip(colors.iter_mut()) {
                        c[12..].copy_from_slice(&s[..4]);
                    }
                }
            }
        }
    }

    /// Shades the fragments `live` of the span at window row `y`, columns `x0 ..
    /// x0 + colors.len()`: `colors` holds the primary colours and receives the program's.
    /// `varyings_at(dx, dy, out)` evaluates the draw's varyings at the pixel `dx` columns
    /// right of the span's first and `dy` rows above it (a live fragment's own at `dy = 0`;
    /// its quad's neighbours for the derivatives).
    // The span's place and its inputs, as the span pipeline hands them over.
    #[allow(clippy::too_many_arguments)]
    pub fn run_span(
        &self,
        scratch: &mut ShadingScratch,
        texturing: Option<&Texturing>,
        x0: i32,
        y: i32,
        live: u64,
        colors: &mut [[f32; 4]],
        varyings_at: impl Fn(i32, i32, &mut [f32]),
    ) {
        let n = colors.len().min(64);
        let mut rest = live & super::span_mask(n);
        if rest == 0 {
            return;
        }
        let textures = StageTextures { texturing, used: !0 };
        scratch.prepare(self);
        // The window row of lane rows 0 and 2: the lower row of llvmpipe's quads holding
        // row `y` (see the module); the span is lane row `row` (and `row + 2`).
        let low = if (self.fb_height - y) & 1 == 0 { y } else { y - 1 };
        let row = (y - low) as usize;
        let mut pixel = [0.0; MAX_VARYINGS];
        let pixel = &mut pixel[..self.varyings];
        while rest != 0 {
            // The 8 columns from a multiple of 8 holding the first fragment left.
            let left = (x0 + rest.trailing_zeros() as i32) & !7;
            let mut lanes = 0u16;
            let mut block = [[0.0; LANES]; 4];
            let lane_of = |d: i32| 4 * (2 * (d >> 2) as usize + row) + (d & 3) as usize;
            for d in 0..8 {
                let i = left + d - x0;
                if (0..n as i32).contains(&i) && rest & (1u64 << i) != 0 {
                    let lane = lane_of(d);
                    lanes |= 1 << lane;
                    for (k, channel) in block.iter_mut().enumerate() {
                        channel[lane] = colors[i as usize][k];
                    }
                }
            }
            for d in 0..8 {
                let i = left + d - x0;
                if (0..64).contains(&i) {
                    rest &= !(1u64 << i);
                }
            }
            let evaluated = if self.derivatives { quads(lanes) } else { lanes };
            for v in &mut scratch.varyings[..self.varyings] {
                *v = [0.0; LANES];
            }
            for lane in (0..LANES).filter(|l| evaluated & (1 << l) != 0) {
                let (lane_row, col) = (lane >> 2, (lane & 3) as i32);
                let dx = left + col + 4 * (lane_row >> 1) as i32 - x0;
                let dy = low + (lane_row & 1) as i32 - y;
                varyings_at(dx, dy, pixel);
                for &(first, count) in &self.varying_runs {
                    for (v, value) in scratch.varyings[first..first + count].iter_mut().zip(&pixel[first..]) {
                        v[lane] = *value;
                    }
                }
            }
            self.run(scratch, &textures, lanes, &mut block);
            for d in 0..8 {
                let i = left + d - x0;
                let lane = lane_of(d);
                if lanes & (1 << lane) != 0 {
                    colors[i as usize] = std::array::from_fn(|k| block[k][lane]);
                }
            }
        }
    }

    /// Runs the program on the lanes of a block whose row pairs are llvmpipe's quads (or
    /// whose lookups need no derivatives): the varyings in `scratch`, `colors` the primary
    /// colours, replaced by the program's in the lanes `live`. Plain lane loops (no
    /// per-lane branch), so that they vectorise in the caller's SIMD level.
    ///
    /// One copy per SIMD level, called from the block and span paths' own copies (inlined
    /// into each, it made the libraries a few hundred kB larger); SSE4.1 runs SSE2's (the
    /// block walk that calls it has no SSE4.1 copy either), whose third copy was 22 KB of
    /// each library (issue #18's 5 MB limit).
    fn run(&self, scratch: &mut ShadingScratch, textures: &StageTextures<'_>, live: u16, colors: &mut [F32s; 4]) {
        crate::simd::per_level!(sse2_for_sse41, |_level| self.run_body(scratch, textures, live, colors))
    }

    #[inline(always)]
    fn run_body(&self, scratch: &mut ShadingScratch, textures: &StageTextures<'_>, live: u16, colors: &mut [F32s; 4]) {
        if let Some(bound) = &self.program.bound {
            self.run_bound(bound, scratch, textures, live, colors);
            return;
        }
        scratch.prepared = 0;
        let ShadingScratch { registers, inputs, varyings, outputs, .. } = scratch;
        for (word, source) in inputs.iter_mut().zip(&self.program.fixed.inputs) {
            let lanes = match *source {
                FragmentInput::Primary(k) => &colors[k as usize & 3],
                FragmentInput::Varying(v) => &varyings[v as usize],
            };
            *word = bits(lanes);
        }
        let running = if self.derivatives { quads(live) } else { live };
        let mut io = Io { inputs, uniforms: &self.uniforms, outputs, textures };
        self.program.compiled.run(registers, &mut io, running);
        let keep = lane_mask(live);
        for (channel, out) in colors.iter_mut().zip(outputs.iter()) {
            for i in 0..LANES {
                channel[i] = f32::from_bits((out[i] & keep[i]) | (channel[i].to_bits() & !keep[i]));
            }
        }
    }
}

impl Shading {
    /// [`Shading::run`] with the program's bound form: the uniform values computed once per
    /// scratch and draw, the inputs written straight into their registers and the colours
    /// read straight from the output registers.
    #[inline(always)]
    fn run_bound(
        &self,
        bound: &Bound,
        scratch: &mut ShadingScratch,
        textures: &StageTextures<'_>,
        live: u16,
        colors: &mut [F32s; 4],
    ) {
        let ShadingScratch { registers, varyings, prepared, .. } = scratch;
        if *prepared != self.id {
            bound.prepare(registers, &self.uniforms);
            *prepared = self.id;
        }
        for &(r, k) in &self.bound_primary {
            *registers.word(r) = bits(&colors[k & 3]);
        }
        for &(r, v) in &self.bound_varyings {
            *registers.word(r) = bits(&varyings[v]);
        }
        let running = if self.derivatives { quads(live) } else { live };
        let textures = StageTextures { texturing: textures.texturing, used: live };
        let mut io = Io { inputs: &[], uniforms: &self.uniforms, outputs: &mut [], textures: &textures };
        bound.run_inline(registers, &mut io, running);
        // Every lane: the pipeline uses only the live lanes' colours (the others' are
        // whatever the registers hold). The word is read whole into a local first: the
        // colours reach here through the caller's closure, so LLVM cannot tell them apart
        // from the register file, and a lane-by-lane copy between the two stayed 16
        // scalar loads and stores per channel (a third of the run of a fog program).
        for &(k, r) in &self.bound_outputs {
            let out: Word = *registers.word(r);
            colors[k & 3] = floats(&out);
        }
    }
}

/// A fixed-function program that is GL_LINEAR fog and nothing else (no texture unit, no
/// colour sum), written out on lanes: the operations of the generated program
/// (`program::Gen::fog_factor`, `shader::build::Gen::clamp01`, the blend of three channels)
/// in its order and single-precision roundings, so the same bits, without the executor's
/// register moves: fog_blend's fog cost 589 instructions a block over blend_fill's with the
/// executor and 281 with this, the fog coordinate's evaluation included (callgrind, LTO).
/// The alpha and the lanes outside the block's live ones are the program's too (it reads
/// the alpha through).
#[derive(Clone, Copy, Debug)]
pub struct LinearFog {
    end: f32,
    /// How the factor divides by `end − start` (LINEAR's divisor); `None` when start = end
    /// (Mesa's `c − end`).
    span: Option<Divisor>,
    color: [f32; 3],
}

/// LINEAR fog's divisor `end − start`: a power of two (fog_blend's 0 to 1, a span of 1) as
/// the product by its reciprocal, which is exact, so `x · (1 / s)` rounds the very value
/// `x / s` does and gives the same bits; any other as the division. A division of 16 lanes
/// is four (SSE) or two (AVX2) `divps`, each several cycles of a busy divider, where a
/// product is one cycle's issue.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Divisor {
    Reciprocal(f32),
    Divide(f32),
}

impl Divisor {
    fn of(span: f32) -> Self {
        let reciprocal = 1.0 / span;
        // A product of two f32 is exact in f64: it is 1 only when `reciprocal` is `1 / span`
        // exactly, that is when `span` is a power of two whose reciprocal is a float.
        let exact = reciprocal.is_finite() && reciprocal != 0.0 && f64::from(reciprocal) * f64::from(span) == 1.0;
        if exact {
            Divisor::Reciprocal(reciprocal)
        } else {
            Divisor::Divide(span)
        }
    }
}

impl LinearFog {
    /// The written-out form of `key`'s program, when it is linear fog alone.
    fn of(key: &FragmentKey, fog: Option<&super::fog::Fog>) -> Option<LinearFog> {
        use super::program::FogKey;
        if !key.stages.is_empty() || key.color_sum.is_some() {
            return None;
        }
        let fog = fog?;
        let span = match key.fog? {
            FogKey::Linear => Some(Divisor::of(fog.end - fog.start)),
            FogKey::LinearDegenerate => None,
            FogKey::Exp | FogKey::Exp2 => return None,
        };
        Some(LinearFog { end: fog.end, span, color: [fog.color[0], fog.color[1], fog.color[2]] })
    }

    /// Fogs `colors` by the fog coordinates `c` (varying 0 of the program), every lane, in
    /// the copy for `level` (the caller's, a constant there): one out-of-line copy per level,
    /// called directly, rather than one inlined at each of the block paths' call sites (13 KB
    /// more per library) or one baseline copy for every level (fog_blend 13 % slower).
    #[inline(always)]
    fn apply(&self, level: Supported, c: &F32s, colors: &mut [F32s; 4]) {
        // A non-generic function's closure: one copy per level whatever the caller.
        crate::simd::dispatch::outlined(
            level,
            #[inline(always)]
            |_| self.apply_body(c, colors),
        )
    }

    /// Fogs `colors` by the fog coordinates `c` in the caller's copy (the block colour
    /// stage's fast path inlines it into its per-level loop: no call, and the lanes stay in
    /// registers).
    #[inline(always)]
    pub fn apply_body(&self, c: &F32s, colors: &mut [F32s; 4]) {
        // clamp01: `0 < x ? (1 < x ? 1 : x) : 0` (NaN gives 0), as two selects, which
        // vectorise (max and min); the nested form stayed a scalar division and two
        // branches per lane (262 instructions a block at SSE2).
        let clamp01 = |x: f32| {
            let v = if 0.0 < x { x } else { 0.0 };
            if v < 1.0 {
                v
            } else {
                1.0
            }
        };
        // Index loops over whole lanes (`block::lanes`), which LLVM vectorises whole; zipped
        // iterators came out as vectors of 8, 4, 2 and single lanes.
        let factor: F32s = match self.span {
            Some(Divisor::Reciprocal(scale)) => lanes(|i| clamp01((self.end - c[i]) * scale)),
            Some(Divisor::Divide(span)) => lanes(|i| clamp01((self.end - c[i]) / span)),
            None => lanes(|i| clamp01(c[i] - self.end)),
        };
        for (channel, fog) in colors[..3].iter_mut().zip(self.color) {
            let x = *channel;
            *channel = lanes(|i| factor[i] * x[i] + (1.0 - factor[i]) * fog);
        }
    }
}

/// The bit patterns of 16 f32 lanes, as one 64-byte move (a loop storing lane by lane into
/// the input word stayed 32 scalar moves).
#[inline(always)]
fn bits(lanes: &F32s) -> Word {
    let mut word = [0u32; LANES];
    for (w, x) in word.iter_mut().zip(lanes) {
        *w = x.to_bits();
    }
    word
}

/// The f32 lanes of 16 bit patterns ([`bits`]'s inverse).
#[inline(always)]
fn floats(word: &Word) -> F32s {
    let mut lanes = [0f32; LANES];
    for (x, w) in lanes.iter_mut().zip(word) {
        *x = f32::from_bits(*w);
    }
    lanes
}

/// The lanes of the 2×2 quads (lane row pairs (0, 1) and (2, 3), column pairs (0, 1) and
/// (2, 3)) holding a lane of `live`.
#[inline(always)]
pub fn quads(live: u16) -> u16 {
    let columns = live | ((live >> 1) & 0x5555) | ((live & 0x5555) << 1);
    columns | ((columns >> 4) & 0x0f0f) | ((columns & 0x0f0f) << 4)
}

/// A worker's storage for runs of fragment programs, reused from block to block.
#[derive(Default)]
pub struct ShadingScratch {
    registers: Registers,
    inputs: Vec<Word>,
    varyings: Vec<F32s>,
    outputs: Vec<Word>,
    /// The [`Shading::id`] whose uniform values `registers` hold (0: none).
    prepared: u64,
}

impl ShadingScratch {
    /// Room for `shading`'s program.
    #[inline(always)]
    fn prepare(&mut self, shading: &Shading) {
        let inputs = shading.program.fixed.inputs.len();
        if self.inputs.len() != inputs || self.varyings.len() < shading.varyings || self.outputs.len() != 4 {
            self.grow(inputs, shading.varyings);
        }
    }

    #[cold]
    fn grow(&mut self, inputs: usize, varyings: usize) {
        self.inputs.resize(inputs, [0; LANES]);
        if self.varyings.len() < varyings {
            self.varyings.resize(varyings, [0.0; LANES]);
        }
        self.outputs.resize(4, [0; LANES]);
    }
}

/// The executor's texture lookups over a draw's units: the fixed-function lookup (s, t, r
/// divided by q, implicit level of detail) through each unit's block lookup.
pub struct StageTextures<'a> {
    pub texturing: Option<&'a Texturing>,
    /// The lanes whose texels are used: a fixed-function program reads a texel only in its
    /// own lane (no derivative of it, no lookup at it), so the lanes that only help a quad's
    /// level of detail need none.
    pub used: u16,
}

impl Textures for StageTextures<'_> {
    fn sample(&self, r: &SampleRequest<'_>, out: &mut [Word; 4]) {
        let Some(stage) = self.texturing.and_then(|t| t.stages.iter().find(|s| s.unit == r.unit as usize)) else {
            // No such unit: the default texel (0, 0, 0, 1).
            *out = [[0; LANES], [0; LANES], [0; LANES], [1f32.to_bits(); LANES]];
            return;
        };
        let live = r.lanes & self.used;
        // The sampler reads (s, t, r, q): a GLSL lookup of fewer than three coordinates
        // has its q right after them, and a shadow lookup its depth reference apart.
        let moved;
        let coords = if (r.projective && r.n < 3) || r.compare.is_some() {
            let mut c = *r.coords;
            if r.projective && r.n < 3 {
                c[3] = r.coords[r.n as usize];
                c[r.n as usize..3].fill([0; LANES]);
            }
            if let Some(reference) = r.compare {
                c[2] = *reference;
            }
            moved = c;
            &moved
        } else {
            r.coords
        };
        match r.lod {
            LodLanes::Bias(bias) => stage.sample_lanes_biased(coords, r.projective, bias, live, out),
            // Only vertex programs give an explicit level; fragment stages take the implicit.
            LodLanes::Implicit | LodLanes::Explicit(_) => stage.sample_lanes(coords, r.projective, live, out),
        }
    }

    fn fetch(&self, _: u8, _: u8, _: &[Word; 3], _: &Word, _: u16, out: &mut [Word; 4]) {
        // Fixed-function programs do not fetch texels by index (GLSL's texelFetch will).
        *out = [[0; LANES]; 4];
    }

    fn size(&self, _: u8, _: &Word, _: u16, out: &mut [Word; 3]) {
        // Nor ask sizes (GLSL's textureSize will).
        *out = [[0; LANES]; 3];
    }
}

#[cfg(test)]
mod tests;
