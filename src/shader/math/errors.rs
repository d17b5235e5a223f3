//! The measured accuracy of [`super`]'s functions against double precision: one sweep per
//! function, shared by the tests (which assert the documented bounds) and by the table that
//! `tools/bench.sh` prints into BENCHMARKS.md (`examples/math_errors.rs`).
//!
//! Each sweep samples the function's range densely by bit pattern (every 97th or so f32), so
//! the figure is a measured maximum, not a proof; the bounds the tests assert sit a little
//! above it.

/// How an error is counted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// In units in the last place of the exact result rounded to f32.
    Ulp,
    /// In absolute terms.
    Absolute,
}

/// One function's measured error.
#[derive(Clone, Copy, Debug)]
pub struct Measured {
    pub function: &'static str,
    /// The inputs swept.
    pub range: &'static str,
    pub unit: Unit,
    /// The bound the tests assert.
    pub bound: f64,
    /// The largest error found.
    pub worst: f64,
    /// Where tessera evaluates it.
    pub used_by: &'static str,
}

/// The bound asserted for pow through llvmpipe's exp2 and log2 (see [`pow_worst`]).
pub const POW_ULPS: f64 = 256.0;

/// The distance in ulps between `a` and the f64 `exact` (in units of `exact`'s ulp as an
/// f32; below the normal range, the spacing of subnormals times 2²³).
pub fn ulps(a: f32, exact: f64) -> f64 {
    let ulp = if exact.abs() < f32::MIN_POSITIVE as f64 {
        f32::MIN_POSITIVE as f64 * f32::EPSILON as f64
    } else {
        let e = (exact.abs() as f32).to_bits() >> 23;
        f32::from_bits(e << 23) as f64 * f32::EPSILON as f64
    };
    (a as f64 - exact).abs() / ulp
}

/// Every `step`-th f32 bit pattern in `[lo, hi]` (positive floats order as their bits).
pub fn samples(lo: f32, hi: f32, step: u32) -> impl Iterator<Item = f32> {
    let (a, b) = (lo.to_bits(), hi.to_bits());
    (a..=b).step_by(step as usize).map(f32::from_bits)
}

/// llvmpipe's 2^x over ±[10⁻⁸, 127.9] with results above twice the smallest normal.
pub fn exp2_worst() -> f64 {
    samples(1e-8, 127.9, 97)
        .flat_map(|x| [x, -x])
        .filter(|&x| (x as f64).exp2() >= f32::MIN_POSITIVE as f64 * 2.0)
        .map(|x| ulps(super::exp2(x), (x as f64).exp2()))
        .fold(0.0, f64::max)
}

/// llvmpipe's log₂ over the positive normal floats, absolute in units of 2⁻²³ where
/// |log₂ x| < 1 (the result is tiny near 1; relative error means nothing there).
pub fn log2_worst() -> f64 {
    samples(f32::MIN_POSITIVE, f32::MAX, 101)
        .map(|x| {
            let exact = (x as f64).log2();
            if exact.abs() < 1.0 {
                (super::log2(x) as f64 - exact).abs() / f32::EPSILON as f64
            } else {
                ulps(super::log2(x), exact)
            }
        })
        .fold(0.0, f64::max)
}

/// pow(x, y) as the IR computes it, 2^(y·log₂ x) with llvmpipe's functions (fixed-function
/// specular and spotlight exponents, GLSL's `pow`): x over [2⁻⁸, 2⁸], y over exponents that
/// lighting uses (shininess up to 128) and fractional ones, results in the normal range.
/// The error grows with |y·log₂ x|, as any 2^(y·log₂ x) does: log2's absolute error and the
/// rounding of the product are multiplied by it (about 190 ulp at y = 128, results near
/// 2^±120; a few ulp for the exponents of everyday specular highlights).
pub fn pow_worst() -> f64 {
    let exponents = [0.5f32, 1.5, 2.0, 3.7, 10.0, 16.0, 64.0, 128.0, -1.0, -2.5];
    let mut worst = 0.0f64;
    for x in samples(1.0 / 256.0, 256.0, 4099) {
        for &y in &exponents {
            let exact = (x as f64).powf(y as f64);
            if !(f32::MIN_POSITIVE as f64 * 2.0..f32::MAX as f64 / 2.0).contains(&exact) {
                continue;
            }
            worst = worst.max(ulps(super::exp2(y * super::log2(x)), exact));
        }
    }
    worst
}

/// 2^x within an ulp or so, over ±[10⁻⁸, 127.9] (results below the normal range are 0).
pub fn exp2_precise_worst() -> f64 {
    samples(1e-8, 127.9, 97)
        .flat_map(|x| [x, -x])
        .filter(|&x| (x as f64).exp2() >= f32::MIN_POSITIVE as f64)
        .map(|x| ulps(super::exp2_precise(x), (x as f64).exp2()))
        .fold(0.0, f64::max)
}

/// log₂ x within an ulp, over every positive float from the smallest subnormal.
pub fn log2_precise_worst() -> f64 {
    samples(f32::from_bits(1), f32::MAX, 101)
        .map(|x| ulps(super::log2_precise(x), (x as f64).log2()))
        .fold(0.0, f64::max)
}

/// sin and cos, absolute, over ±[10⁻⁶, 10⁵].
pub fn sin_cos_worst() -> f64 {
    samples(1e-6, 1e5, 53)
        .flat_map(|x| [x, -x])
        .map(|x| {
            let xd = x as f64;
            (super::sin(x) as f64 - xd.sin()).abs().max((super::cos(x) as f64 - xd.cos()).abs())
        })
        .fold(0.0, f64::max)
}

/// eˣ against eˣ in f64, in ulps of the result, over [−104, 89] in steps of 2⁻¹² and every
/// 61st float of [−1, −0.5).
pub fn exp_worst() -> f64 {
    let grid = (-104 * 4096..=89 * 4096).map(|i| i as f32 / 4096.0 + 1.0e-4);
    let near_zero = (0..(1u32 << 23)).step_by(61).map(|m| -f32::from_bits(0x3f00_0000 | m));
    grid.chain(near_zero)
        .filter_map(|x| {
            let want = (x as f64).exp();
            let nearest = want as f32;
            if nearest.is_infinite() {
                return None;
            }
            let ulp = (f32::from_bits(nearest.to_bits() + 1) as f64 - nearest as f64)
                .max(f64::from_bits(0x36a0_0000_0000_0000));
            Some((super::exp(x) as f64 - want).abs() / ulp)
        })
        .fold(0.0, f64::max)
}

/// Every function's measured error, in the order of the module docs' table.
pub fn measure_all() -> Vec<Measured> {
    let lighting = "fixed-function lighting (specular, spotlights) and the IR's Exp2/Log2, every accuracy mode";
    vec![
        Measured {
            function: "exp2 (llvmpipe's polynomial)",
            range: "±[1e-8, 127.9], results ≥ 2⁻¹²⁵",
            unit: Unit::Ulp,
            bound: 3.5,
            worst: exp2_worst(),
            used_by: lighting,
        },
        Measured {
            function: "log2 (llvmpipe's polynomial)",
            range: "positive normal floats (absolute, in 2⁻²³, where log₂ x is within ±1)",
            unit: Unit::Ulp,
            bound: 2.0,
            worst: log2_worst(),
            used_by: lighting,
        },
        Measured {
            function: "pow = exp2(y·log2 x)",
            range: "x in [2⁻⁸, 2⁸], y in {±0.5…128}, normal results",
            unit: Unit::Ulp,
            bound: POW_ULPS,
            worst: pow_worst(),
            used_by: lighting,
        },
        Measured {
            function: "exp2_precise",
            range: "±[1e-8, 127.9], normal results",
            unit: Unit::Ulp,
            bound: 2.0,
            worst: exp2_precise_worst(),
            used_by: "none yet (kept for GLSL's exact mode)",
        },
        Measured {
            function: "log2_precise",
            range: "every positive float",
            unit: Unit::Ulp,
            bound: 1.0,
            worst: log2_precise_worst(),
            used_by: "none yet (kept for GLSL's exact mode)",
        },
        Measured {
            function: "sin, cos",
            range: "±[1e-6, 1e5]",
            unit: Unit::Absolute,
            bound: f64::from(f32::EPSILON),
            worst: sin_cos_worst(),
            used_by: "the IR's Sin/Cos (GLSL), every accuracy mode",
        },
        Measured {
            function: "exp (eˣ, fog)",
            range: "[−104, 89]",
            unit: Unit::Ulp,
            bound: 0.5 + 1e-6,
            worst: exp_worst(),
            used_by: "fog (GL_EXP, GL_EXP2), every accuracy mode",
        },
    ]
}

/// The table of [`measure_all`] in Markdown (for BENCHMARKS.md).
pub fn markdown_table(rows: &[Measured]) -> String {
    let mut out =
        String::from("| Function | Inputs | Tested bound | Measured maximum | Used in |\n|---|---|---:|---:|---|\n");
    for r in rows {
        let figure = |v: f64| match r.unit {
            Unit::Ulp => format!("{v:.2} ulp"),
            Unit::Absolute => format!("{v:.2e} absolute"),
        };
        out +=
            &format!("| {} | {} | {} | {} | {} |\n", r.function, r.range, figure(r.bound), figure(r.worst), r.used_by);
    }
    out
}
