//! The instruction-set level the hot loops run at, and the one mechanism that compiles a
//! loop once per level from one source body and calls the copy the CPU can run.
//!
//! tessera is built for the x86-64 baseline (SSE2), so without help every loop is SSE2
//! code. [`per_level!`] wraps an expression (usually a block) in a closure marked
//! `#[inline(always)]` and hands it to one wrapper per level (`dispatch.rs`): a function
//! compiled with `#[target_feature(enable = "sse4.1")]`, one with `"avx2"`, and one for the
//! SSE2 baseline. The closure is inlined into each wrapper, so the block and everything the
//! compiler inlines into it are compiled three times, each with its level's instructions
//! (AVX2's 256-bit vectors and three-operand VEX forms, SSE4.1's `pminsd`/`pmulld`/
//! `roundps`/`blendvps`/`pmovzx`), and [`current`] picks the copy at run time. Functions the
//! block calls without inlining them stay SSE2 code (a `target_feature` is a property of a
//! compiled function, not inherited by its callees), so there are two ways to use it:
//! - around a driver whose hot loops are all inlined into it: the tile workers' per-band
//!   render (`raster::render_tiles`) is one block per level, so whatever the compiler
//!   inlines under it runs at the level;
//! - around a kernel called out of line: a thin function whose body is
//!   `per_level!(kernel_body(args))` with `kernel_body` `#[inline(always)]` and its loops
//!   written as plain loops (an iterator adaptor such as `Vec::extend` may stay a call out of
//!   the copy). Today: `fragment::write_colors` (conversion) and
//!   `setup::plane::Shading::span_colors` (color planes). A dispatch costs a call and a few loads per use (measured: 20–40
//!   instructions, +3–8 % on the benchmark's small and thin triangles, whose spans are a few
//!   pixels long), so a kernel should do a block's or a long span's work per call; the
//!   per-band copy costs nothing per span, which is where the 4×4 block kernels belong.
//!
//! **What each copy costs.** Every copy is code in both shipped libraries, which issue #18
//! holds to 5 MB each, so a body gets a level's copy only where it pays:
//! `dispatch::run_with_sse2_for_sse41`/`per_level!(sse2_for_sse41, ..)` compile no SSE4.1
//! copy and `dispatch::baseline` only SSE2's. The triangle walk and its block stages have
//! AVX2 and SSE2 copies (an SSE4.1 copy ran blends about 12 % fewer instructions on CPUs
//! with SSE4.1 and no AVX2, and cost 230 KB); the span path's writes
//! (`fragment::output::write_target`: lines, points, pixel rectangles, short spans) only
//! SSE2's (its AVX2 copy was 96 KB); texture sampling, fragment shading and the shader
//! executor all three.
//!
//! **Same bytes at every level.** The levels differ only in how many lanes an instruction
//! carries and in encodings, never in the value of an operation: IEEE 754 add, subtract,
//! multiply, divide, square root and conversions are correctly rounded single operations
//! whether one lane of an SSE2 register or eight of an AVX2 register computes them, and
//! integer arithmetic is exact. What could differ is kept out. No level enables `fma`
//! (every AVX2 CPU has it, but a fused multiply-add rounds once where `a * b + c` rounds
//! twice), and Rust never contracts `a * b + c` into a fused operation on its own (it gives
//! LLVM no fast-math or contraction flags), so AVX2 without FMA performs exactly the source's
//! two roundings, as SSE2 does. Where tessera means a fused operation (line planes and the
//! viewport, to match llvmpipe), it calls `gl::float::fused_multiply_add`, an exact fused
//! multiply-add built from plain IEEE operations, the same at every level. Without fast-math the
//! compiler does not reassociate float arithmetic either, so a vectorised loop computes each
//! element with the scalar loop's operations in the scalar loop's order. Rounding and floor
//! on hot paths are integer or bit formulations, not libm calls whose code could differ.
//! `tests/simd_levels.rs` renders the capi and example scenes at every level the CPU has
//! and compares the bytes.
//!
//! **Choosing the level.** Detected once per process (`is_x86_feature_detected!`): the best
//! of SSE2, SSE4.1 and AVX2 the CPU has. `TESSERA_SIMD=sse2|sse41|avx2` (any case) forces a
//! level; a level the CPU lacks falls back to the best one it has below, and an unknown value
//! is ignored (reported once on stderr). Off x86-64 there is one level, the portable code
//! the compiler generates for the target.
//!
//! This is a bottom room (only `gl` is below it, and it needs nothing of it): any room may
//! dispatch a loop. Unsafe code (calling a `target_feature` function) is confined to
//! `dispatch.rs`.
#![deny(unsafe_code)]

pub mod dispatch;

use std::sync::OnceLock;

/// An instruction-set level: what the hot loops are compiled for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Level {
    /// The x86-64 baseline: SSE2, 128-bit vectors.
    #[cfg(target_arch = "x86_64")]
    Sse2,
    /// SSE4.1 (with SSSE3 and SSE3): 32-bit integer min/max/multiply, float rounding,
    /// blends, zero-extending loads.
    #[cfg(target_arch = "x86_64")]
    Sse41,
    /// AVX2 (with AVX): 256-bit float and integer vectors. Not FMA.
    #[cfg(target_arch = "x86_64")]
    Avx2,
    /// Off x86-64: the code the compiler generates for the target.
    #[cfg(not(target_arch = "x86_64"))]
    Portable,
}

impl Level {
    /// Every level of this architecture, lowest first.
    #[cfg(target_arch = "x86_64")]
    pub const ALL: &'static [Level] = &[Level::Sse2, Level::Sse41, Level::Avx2];
    /// Every level of this architecture, lowest first.
    #[cfg(not(target_arch = "x86_64"))]
    pub const ALL: &'static [Level] = &[Level::Portable];

    /// The name `TESSERA_SIMD` uses for the level.
    pub fn name(self) -> &'static str {
        match self {
            #[cfg(target_arch = "x86_64")]
            Level::Sse2 => "sse2",
            #[cfg(target_arch = "x86_64")]
            Level::Sse41 => "sse41",
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => "avx2",
            #[cfg(not(target_arch = "x86_64"))]
            Level::Portable => "portable",
        }
    }

    /// Whether this CPU can run the level.
    pub fn available(self) -> bool {
        match self {
            #[cfg(target_arch = "x86_64")]
            Level::Sse2 => true,
            #[cfg(target_arch = "x86_64")]
            Level::Sse41 => std::arch::is_x86_feature_detected!("sse4.1"),
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => std::arch::is_x86_feature_detected!("avx2"),
            #[cfg(not(target_arch = "x86_64"))]
            Level::Portable => true,
        }
    }

    /// The best level this CPU has.
    pub fn best() -> Level {
        Level::ALL.iter().rev().copied().find(|l| l.available()).unwrap_or(Level::ALL[0])
    }

    /// The level a `TESSERA_SIMD` value names, any case (`sse4.1` and `sse4_1` are `sse41`);
    /// off x86-64 every x86 name is the portable level.
    pub fn parse(value: &str) -> Option<Level> {
        let name: String = value.trim().to_ascii_lowercase().chars().filter(|c| !matches!(c, '.' | '_')).collect();
        #[cfg(target_arch = "x86_64")]
        let level = match name.as_str() {
            "sse2" => Some(Level::Sse2),
            "sse41" => Some(Level::Sse41),
            "avx2" => Some(Level::Avx2),
            _ => None,
        };
        #[cfg(not(target_arch = "x86_64"))]
        let level = matches!(name.as_str(), "sse2" | "sse41" | "avx2" | "portable").then_some(Level::Portable);
        level
    }
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A level this CPU has: the only way to run code compiled for a level
/// ([`dispatch::run`]), so the `target_feature` calls there need no check of their own.
/// Made only by [`Supported::new`], which checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Supported(Level);

impl Supported {
    /// `level`, if this CPU has it.
    pub fn new(level: Level) -> Option<Supported> {
        level.available().then_some(Supported(level))
    }

    pub fn level(self) -> Level {
        self.0
    }
}

/// What a `TESSERA_SIMD` value selects on a CPU where `available` says which levels run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Choice {
    /// The level the hot loops run at.
    pub level: Level,
    /// The level the variable asked for, when it named one.
    pub requested: Option<Level>,
    /// The variable was set to something that names no level (ignored).
    pub unknown: bool,
}

/// The level for the value of `TESSERA_SIMD` (`None`: unset): the requested level if the CPU
/// has it, else the best level it has below the requested one; unset or unknown: the best
/// level it has.
pub fn choose(value: Option<&str>, available: impl Fn(Level) -> bool) -> Choice {
    let best_up_to = |top: Level| Level::ALL.iter().rev().copied().find(|&l| l <= top && available(l));
    let requested = value.filter(|v| !v.trim().is_empty()).map(Level::parse);
    let unknown = matches!(requested, Some(None));
    let requested = requested.flatten();
    let top = requested.unwrap_or(*Level::ALL.last().expect("a level"));
    Choice { level: best_up_to(top).unwrap_or(Level::ALL[0]), requested, unknown }
}

/// This process's level: `TESSERA_SIMD` and the CPU, decided once.
pub fn choice() -> Choice {
    static CHOICE: OnceLock<Choice> = OnceLock::new();
    *CHOICE.get_or_init(|| {
        let value = std::env::var("TESSERA_SIMD").ok();
        let choice = choose(value.as_deref(), Level::available);
        if choice.unknown {
            let names: Vec<&str> = Level::ALL.iter().map(|l| l.name()).collect();
            eprintln!(
                "tessera: unknown TESSERA_SIMD={:?} ({}); using {}",
                value.unwrap_or_default(),
                names.join(", "),
                choice.level
            );
        }
        choice
    })
}

/// The level the hot loops of this process run at.
pub fn level() -> Level {
    current().level()
}

/// The level the hot loops of this process run at, as the token [`dispatch::run`] takes.
#[inline]
pub fn current() -> Supported {
    static CURRENT: OnceLock<Supported> = OnceLock::new();
    *CURRENT.get_or_init(|| {
        let level = choice().level;
        Supported::new(level).expect("choose() picks only levels available() says the CPU has")
    })
}

/// The level and why, for diagnostics (`TESSERA_DEBUG=config`): `avx2 (TESSERA_SIMD=avx2)`,
/// `avx2 (detected; TESSERA_SIMD unset)`, `sse41 (TESSERA_SIMD=avx2 is not available on this
/// CPU)`, `avx2 (detected; TESSERA_SIMD names no level)`.
pub fn describe() -> String {
    let choice = choice();
    let why = match choice.requested {
        Some(r) if r == choice.level => format!("TESSERA_SIMD={r}"),
        Some(r) => format!("TESSERA_SIMD={r} is not available on this CPU"),
        None if choice.unknown => "detected; TESSERA_SIMD names no level".to_string(),
        None => "detected; TESSERA_SIMD unset".to_string(),
    };
    format!("{} ({why})", choice.level)
}

/// Evaluates an expression (usually a block) compiled once per SIMD level and runs the copy
/// for this process's [`level`]: the expression becomes an `#[inline(always)]` closure that
/// each level's `target_feature` wrapper inlines (`dispatch.rs`). `return`, `break` and `?`
/// inside it act on that closure, not on the enclosing function. The form
/// `per_level!(|level| body)` also names the copy's level (a [`Supported`], a constant in
/// each copy) for the lane helpers that take one ([`dispatch::sign_mask16`],
/// [`dispatch::load_block`]) and for [`dispatch::outlined`] calls. The form
/// `per_level!(sse2_for_sse41, |level| body)` compiles no SSE4.1 copy: that level runs
/// SSE2's ([`dispatch::run_with_sse2_for_sse41`]), for code whose SSE4.1 copy is not worth
/// its size.
///
/// ```
/// let mut a = [1.0f32; 64];
/// let b = [0.5f32; 64];
/// tessera::simd::per_level!({
///     for (x, y) in a.iter_mut().zip(&b) {
///         *x = *x * 3.0 + *y; // two roundings at every level: never fused
///     }
/// });
/// assert_eq!(a[0], 3.5);
/// ```
#[macro_export]
macro_rules! simd_per_level {
    (sse2_for_sse41, |$level:ident| $body:expr) => {
        $crate::simd::dispatch::run_with_sse2_for_sse41(
            $crate::simd::current(),
            #[inline(always)]
            |$level: $crate::simd::Supported| $body,
        )
    };
    (|$level:ident| $body:expr) => {
        $crate::simd::dispatch::run_with(
            $crate::simd::current(),
            #[inline(always)]
            |$level: $crate::simd::Supported| $body,
        )
    };
    ($body:expr) => {
        $crate::simd::dispatch::run(
            $crate::simd::current(),
            #[inline(always)]
            || $body,
        )
    };
}
pub use super::simd_per_level as per_level;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_names_are_none() {
        for &level in Level::ALL {
            assert_eq!(Level::parse(level.name()), Some(level));
            assert_eq!(Level::parse(&level.name().to_ascii_uppercase()), Some(level));
        }
        assert_eq!(Level::parse("avx512"), None);
        assert_eq!(Level::parse(""), None);
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    fn a_missing_level_falls_back_to_the_best_below_and_unknown_values_are_ignored() {
        use Level::*;
        let only_sse41 = |l: Level| l <= Sse41;
        let only_sse2 = |l: Level| l == Sse2;
        let all = |_: Level| true;
        assert_eq!(choose(None, all).level, Avx2);
        assert_eq!(choose(Some("sse2"), all).level, Sse2);
        assert_eq!(choose(Some("SSE4.1"), all).level, Sse41);
        assert_eq!(choose(Some("avx2"), only_sse41), Choice { level: Sse41, requested: Some(Avx2), unknown: false });
        assert_eq!(choose(Some("avx2"), only_sse2).level, Sse2);
        assert_eq!(choose(Some("sse41"), only_sse2).level, Sse2);
        assert_eq!(choose(None, only_sse41).level, Sse41);
        assert_eq!(choose(Some("neon"), only_sse41), Choice { level: Sse41, requested: None, unknown: true });
        assert_eq!(choose(Some(" "), all), Choice { level: Avx2, requested: None, unknown: false });
    }

    #[test]
    fn the_process_level_is_one_the_cpu_has() {
        assert!(level().available());
        assert_eq!(current(), current());
        assert!(Level::best() >= level() || choice().requested.is_some());
        assert!(Level::ALL[0].available());
    }

    #[test]
    fn sign_masks_are_the_lanes_sign_bits_at_every_level() {
        // Lane masks for every 16-bit mask, then words whose other bits vary (only bit 31
        // counts, whatever the rest).
        for level in Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            for bits in 0..=u16::MAX {
                let m: [u32; 16] = std::array::from_fn(|i| if bits & (1 << i) != 0 { !0 } else { 0 });
                let got = dispatch::run_with(level, |l| dispatch::sign_mask16(l, &m));
                assert_eq!(got, bits, "level {}", level.level());
                let words: [u32; 16] =
                    std::array::from_fn(|i| (m[i] & 0x8000_0000) | (i as u32 * 0x0101_0101 + bits as u32));
                assert_eq!(dispatch::sign_mask16(level, &words), bits, "level {}", level.level());
            }
        }
    }

    #[test]
    fn blocks_load_and_store_lane_by_lane_at_every_level() {
        // A 7-wide image of distinct words; the block at column 2 of rows 1..5.
        let image: Vec<u32> = (0..7 * 6).map(|i| 0x0101_0101 * i + 0x8000_0000 * (i % 3)).collect();
        let want: [u32; 16] = std::array::from_fn(|i| image[(1 + i / 4) * 7 + 2 + i % 4]);
        for level in Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            let got = dispatch::run_with(level, |l| dispatch::load_block(l, &image, 9, 7));
            assert_eq!(got, want, "level {}", level.level());
            let bytes: Vec<[u8; 4]> = image.iter().map(|w| w.to_le_bytes()).collect();
            let got = dispatch::load_block(level, &bytes, 9, 7);
            assert_eq!(got.map(u32::from_le_bytes), want, "level {}", level.level());
            // Stored back reversed into a copy: only the block's 16 words change.
            let mut copy = image.clone();
            let values: [u32; 16] = std::array::from_fn(|i| want[15 - i]);
            dispatch::run_with(level, |l| dispatch::store_block(l, &mut copy, 9, 7, &values));
            for (i, (&a, &b)) in copy.iter().zip(&image).enumerate() {
                let (y, x) = (i / 7, i % 7);
                if (1..5).contains(&y) && (2..6).contains(&x) {
                    assert_eq!(a, values[(y - 1) * 4 + x - 2], "level {} ({x}, {y})", level.level());
                } else {
                    assert_eq!(a, b, "level {} ({x}, {y})", level.level());
                }
            }
            // The last block that fits, and one row too far.
            assert_eq!(dispatch::load_block(level, &image, 3 + 7 * 2, 7)[15], image[41]);
            let beyond = std::panic::catch_unwind(|| dispatch::load_block(level, &image, 4 + 7 * 2, 7));
            assert!(beyond.is_err(), "level {}", level.level());
        }
    }

    #[test]
    fn unorm8_packing_saturates_every_channel_at_every_level() {
        // Values below, inside and above [0, 255] and i32::MIN (a NaN's conversion), each
        // channel reading them rotated so that every channel sees every value.
        let values = [i32::MIN, -70000, -256, -1, 0, 1, 127, 128, 254, 255, 256, 300, 32767, 32768, 70000, i32::MAX];
        let c: [[i32; 16]; 4] = std::array::from_fn(|k| std::array::from_fn(|i| values[(i + 5 * k) % 16]));
        let want: [u32; 16] =
            std::array::from_fn(|i| (0..4).fold(0, |w, k| w | (c[k][i].clamp(0, 255) as u32) << (8 * k)));
        for level in Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            assert_eq!(dispatch::run_with(level, |l| dispatch::pack_unorm8(l, &c)), want, "level {}", level.level());
        }
    }

    #[test]
    fn channel_lanes_blend_as_packed_words_at_every_level() {
        // `s·a + d·(1 − a)` (or `s + d·(1 − a)`) per byte with the span path's rounding
        // (`mul8`), the source clamped below to 0 as the packing does.
        let mul8 = |x: u32, y: u32| {
            let t = x * y + 128;
            (t + (t >> 8)) >> 8
        };
        let reference = |src_alpha: bool, c: &[[i32; 16]; 4], dst: &[u32; 16]| -> [u32; 16] {
            std::array::from_fn(|i| {
                let s = |k: usize| c[k][i].clamp(0, 255) as u32;
                (0..4).fold(0, |w, k| {
                    let d = (dst[i] >> (8 * k)) & 0xff;
                    let sf = if src_alpha { mul8(s(k), s(3)) } else { s(k) };
                    w | (sf + mul8(d, 255 - s(3))).min(255) << (8 * k)
                })
            })
        };
        // Channels and destinations that differ per lane and per channel (so that a lane or
        // channel taken from the wrong place shows), with out-of-range sources in some lanes.
        let mut seed = 0x2545_f491_u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        for round in 0..64 {
            let c: [[i32; 16]; 4] = std::array::from_fn(|_| {
                std::array::from_fn(|i| match (round + i) % 11 {
                    0 => i32::MIN,
                    1 => -((next() % 300) as i32),
                    _ => (next() % 256) as i32,
                })
            });
            let dst: [u32; 16] = std::array::from_fn(|_| next());
            for level in Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
                let got = dispatch::run_with(level, |l| dispatch::blend_channels_inv_src_alpha8::<true>(l, &c, &dst));
                assert_eq!(got, reference(true, &c, &dst), "SRC_ALPHA, level {}", level.level());
                let got = dispatch::run_with(level, |l| dispatch::blend_channels_inv_src_alpha8::<false>(l, &c, &dst));
                assert_eq!(got, reference(false, &c, &dst), "ONE, level {}", level.level());
            }
        }
    }

    #[test]
    fn outlined_copies_run_at_every_level() {
        for level in Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            let got = dispatch::run_with(level, |l| dispatch::outlined(l, |inner| (l, inner)));
            assert_eq!(got, (level, level));
        }
    }

    #[test]
    fn every_level_computes_the_same_bits() {
        // A loop the compiler vectorises differently per level (8 lanes at AVX2, 4 at SSE,
        // a scalar tail): products and sums that would change in the last bit if any level
        // fused a*b+c, and values chosen to round.
        let a: Vec<f32> = (0..1027).map(|i| 1.0 + i as f32 * 1.000_001e-3).collect();
        let b: Vec<f32> = (0..1027).map(|i| 0.1 + (i % 7) as f32 * 0.333_333_34).collect();
        let expected: Vec<u32> = a.iter().zip(&b).map(|(x, y)| (x * y + x - y / 3.0).to_bits()).collect();
        assert!(expected.iter().all(|&bits| f32::from_bits(bits).is_finite()));
        for level in Level::ALL.iter().filter_map(|&l| Supported::new(l)) {
            let got: Vec<u32> = dispatch::run(
                level,
                #[inline(always)]
                || a.iter().zip(&b).map(|(x, y)| (x * y + x - y / 3.0).to_bits()).collect(),
            );
            assert_eq!(got, expected, "level {}", level.level());
        }
        // The same expression fused rounds once and differs: the check above can fail.
        let fused = a.iter().zip(&b).filter(|(x, y)| x.mul_add(**y, **x) != *x * **y + **x);
        assert!(fused.count() > 0, "no input distinguishes a fused multiply-add");
    }
}
