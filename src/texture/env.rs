//! Texture environments (GL 2.1 §3.8.13): how a unit combines its texture color with the
//! color from the previous unit (the primary color for the first), compiled per draw into
//! [`TexEnv`], the state the fixed-function fragment program (`crate::fragment::program`)
//! is generated from; the program is what runs. [`TexEnv::apply`] is the tests' reference.
//!
//! The classic modes follow tables 3.22 and 3.23 by base format; GL_COMBINE follows tables
//! 3.24 and 3.25 with every source of ARB_texture_env_crossbar. Colors are floats; every
//! unit's result is clamped to [0, 1], as the specification says.
use super::BaseFormat;

/// GL_TEXTURE_ENV_MODE.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EnvMode {
    Replace,
    Modulate,
    Decal,
    Blend,
    Add,
    Combine(Combine),
}

/// A GL_COMBINE_RGB or GL_COMBINE_ALPHA function.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineFn {
    Replace,
    Modulate,
    Add,
    AddSigned,
    Interpolate,
    Subtract,
    Dot3Rgb,
    Dot3Rgba,
}

/// Where an argument of GL_COMBINE comes from (GL_SOURCEn_RGB/ALPHA).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Source {
    /// This unit's texture.
    Texture,
    /// The texture of unit n (ARB_texture_env_crossbar).
    TextureUnit(usize),
    Constant,
    PrimaryColor,
    Previous,
}

/// GL_OPERANDn_RGB/ALPHA: which part of the source, and whether inverted.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Operand {
    /// Read alpha (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) rather than the color.
    pub alpha: bool,
    /// ONE_MINUS_…
    pub invert: bool,
}

/// A compiled GL_COMBINE environment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combine {
    pub rgb: CombineFn,
    pub alpha: CombineFn,
    pub src_rgb: [Source; 3],
    pub op_rgb: [Operand; 3],
    pub src_alpha: [Source; 3],
    pub op_alpha: [Operand; 3],
    pub scale_rgb: f32,
    pub scale_alpha: f32,
}

/// One unit's compiled environment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexEnv {
    pub mode: EnvMode,
    /// The base format of the unit's texture (for depth textures: of its depth mode).
    pub base: BaseFormat,
    /// GL_TEXTURE_ENV_COLOR.
    pub color: [f32; 4],
}

#[cfg(test)]
fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
}

/// **The test reference only** (not compiled into the library): the per-fragment
/// arithmetic of the environments, written out directly from the tables, which the
/// generated fragment program (`crate::fragment::program`, the one path the pipeline runs)
/// must reproduce bit for bit; its tests run both on random states. A second, independent
/// writing of the same operations catches a generator that reorders or drops one, which an
/// f64 evaluation within a tolerance would not.
#[cfg(test)]
impl TexEnv {
    /// The unit's output color from the previous unit's `previous`, the fragment's `primary`
    /// color and the texture colors of every unit (`texels[unit]`, this one's at `unit`).
    pub fn apply(&self, unit: usize, previous: [f32; 4], primary: [f32; 4], texels: &[[f32; 4]]) -> [f32; 4] {
        let t = texels[unit];
        let (cf, cc) = (previous, self.color);
        let has_color = !matches!(self.base, BaseFormat::Alpha);
        let has_alpha = matches!(
            self.base,
            BaseFormat::Alpha | BaseFormat::LuminanceAlpha | BaseFormat::Intensity | BaseFormat::Rgba
        );
        let rgb = |f: &dyn Fn(usize) -> f32| -> [f32; 3] { [f(0), f(1), f(2)] };
        let (c, a): ([f32; 3], f32) = match self.mode {
            EnvMode::Replace => {
                (if has_color { rgb(&|k| t[k]) } else { rgb(&|k| cf[k]) }, if has_alpha { t[3] } else { cf[3] })
            }
            EnvMode::Modulate => (
                if has_color { rgb(&|k| cf[k] * t[k]) } else { rgb(&|k| cf[k]) },
                if has_alpha { cf[3] * t[3] } else { cf[3] },
            ),
            EnvMode::Decal => match self.base {
                BaseFormat::Rgb => (rgb(&|k| t[k]), cf[3]),
                BaseFormat::Rgba => (rgb(&|k| cf[k] * (1.0 - t[3]) + t[k] * t[3]), cf[3]),
                // Undefined for other formats: the fragment passes unchanged.
                _ => (rgb(&|k| cf[k]), cf[3]),
            },
            EnvMode::Blend => (
                if has_color { rgb(&|k| cf[k] * (1.0 - t[k]) + cc[k] * t[k]) } else { rgb(&|k| cf[k]) },
                match self.base {
                    BaseFormat::Intensity => cf[3] * (1.0 - t[3]) + cc[3] * t[3],
                    _ if has_alpha => cf[3] * t[3],
                    _ => cf[3],
                },
            ),
            EnvMode::Add => (
                if has_color { rgb(&|k| cf[k] + t[k]) } else { rgb(&|k| cf[k]) },
                match self.base {
                    BaseFormat::Intensity => cf[3] + t[3],
                    _ if has_alpha => cf[3] * t[3],
                    _ => cf[3],
                },
            ),
            EnvMode::Combine(comb) => return combine(&comb, unit, previous, primary, cc, texels),
        };
        [clamp01(c[0]), clamp01(c[1]), clamp01(c[2]), clamp01(a)]
    }
}

/// The color of a combine source (test reference).
#[cfg(test)]
fn source(
    s: Source,
    unit: usize,
    previous: [f32; 4],
    primary: [f32; 4],
    constant: [f32; 4],
    texels: &[[f32; 4]],
) -> [f32; 4] {
    match s {
        Source::Texture => texels[unit],
        Source::TextureUnit(n) => texels.get(n).copied().unwrap_or([0.0, 0.0, 0.0, 1.0]),
        Source::Constant => constant,
        Source::PrimaryColor => primary,
        Source::Previous => previous,
    }
}

/// GL_COMBINE (test reference).
#[cfg(test)]
fn combine(
    comb: &Combine,
    unit: usize,
    previous: [f32; 4],
    primary: [f32; 4],
    constant: [f32; 4],
    texels: &[[f32; 4]],
) -> [f32; 4] {
    let arg_rgb = |i: usize| -> [f32; 3] {
        let c = source(comb.src_rgb[i], unit, previous, primary, constant, texels);
        let op = comb.op_rgb[i];
        let v = if op.alpha { [c[3]; 3] } else { [c[0], c[1], c[2]] };
        if op.invert {
            v.map(|x| 1.0 - x)
        } else {
            v
        }
    };
    let arg_alpha = |i: usize| -> f32 {
        let c = source(comb.src_alpha[i], unit, previous, primary, constant, texels);
        let v = c[3];
        if comb.op_alpha[i].invert {
            1.0 - v
        } else {
            v
        }
    };
    let args_needed = |f: CombineFn| match f {
        CombineFn::Replace => 1,
        CombineFn::Interpolate => 3,
        _ => 2,
    };
    let n = args_needed(comb.rgb);
    let a: Vec<[f32; 3]> = (0..n).map(arg_rgb).collect();
    let rgb: [f32; 3] = match comb.rgb {
        CombineFn::Replace => a[0],
        CombineFn::Modulate => std::array::from_fn(|k| a[0][k] * a[1][k]),
        CombineFn::Add => std::array::from_fn(|k| a[0][k] + a[1][k]),
        CombineFn::AddSigned => std::array::from_fn(|k| a[0][k] + a[1][k] - 0.5),
        CombineFn::Interpolate => std::array::from_fn(|k| a[0][k] * a[2][k] + a[1][k] * (1.0 - a[2][k])),
        CombineFn::Subtract => std::array::from_fn(|k| a[0][k] - a[1][k]),
        CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => {
            let d = 4.0 * ((0..3).map(|k| (a[0][k] - 0.5) * (a[1][k] - 0.5)).sum::<f32>());
            [d; 3]
        }
    };
    if comb.rgb == CombineFn::Dot3Rgba {
        // The dot product goes to alpha too, scaled by GL_ALPHA_SCALE (as Mesa does).
        let d = rgb[0];
        return [
            clamp01(d * comb.scale_rgb),
            clamp01(d * comb.scale_rgb),
            clamp01(d * comb.scale_rgb),
            clamp01(d * comb.scale_alpha),
        ];
    }
    let rgb = rgb.map(|x| clamp01(x * comb.scale_rgb));
    let m = args_needed(comb.alpha);
    let b: Vec<f32> = (0..m).map(arg_alpha).collect();
    let alpha = match comb.alpha {
        CombineFn::Replace => b[0],
        CombineFn::Modulate => b[0] * b[1],
        CombineFn::Add => b[0] + b[1],
        CombineFn::AddSigned => b[0] + b[1] - 0.5,
        CombineFn::Interpolate => b[0] * b[2] + b[1] * (1.0 - b[2]),
        CombineFn::Subtract => b[0] - b[1],
        // Not valid for alpha (the context refuses them).
        CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => b[0],
    };
    [rgb[0], rgb[1], rgb[2], clamp01(alpha * comb.scale_alpha)]
}

#[cfg(test)]
mod tests {
    use super::*;

    const COLOR: Operand = Operand { alpha: false, invert: false };
    const ALPHA: Operand = Operand { alpha: true, invert: false };

    fn env(mode: EnvMode, base: BaseFormat) -> TexEnv {
        TexEnv { mode, base, color: [0.0, 0.5, 1.0, 0.25] }
    }

    #[test]
    fn classic_modes_by_base_format() {
        let prev = [0.5, 0.5, 0.5, 0.5];
        let tex = [[1.0, 0.25, 0.0, 0.5]];
        let apply = |mode, base| env(mode, base).apply(0, prev, prev, &tex);
        assert_eq!(apply(EnvMode::Replace, BaseFormat::Rgb), [1.0, 0.25, 0.0, 0.5]);
        assert_eq!(apply(EnvMode::Modulate, BaseFormat::Rgba), [0.5, 0.125, 0.0, 0.25]);
        assert_eq!(apply(EnvMode::Modulate, BaseFormat::Alpha), [0.5, 0.5, 0.5, 0.25]);
        assert_eq!(apply(EnvMode::Decal, BaseFormat::Rgba), [0.75, 0.375, 0.25, 0.5]);
        assert_eq!(apply(EnvMode::Blend, BaseFormat::Rgb), [0.0, 0.5, 0.5, 0.5]);
        assert_eq!(apply(EnvMode::Add, BaseFormat::Rgba), [1.0, 0.75, 0.5, 0.25]);
        // Intensity: BLEND and ADD treat alpha as another intensity channel.
        let tex_i = [[0.5; 4]];
        assert_eq!(env(EnvMode::Blend, BaseFormat::Intensity).apply(0, prev, prev, &tex_i)[3], 0.375);
        assert_eq!(env(EnvMode::Add, BaseFormat::Intensity).apply(0, prev, prev, &tex_i)[3], 1.0);
    }

    #[test]
    fn combine_functions() {
        let base = Combine {
            rgb: CombineFn::Modulate,
            alpha: CombineFn::Replace,
            src_rgb: [Source::Texture, Source::Previous, Source::Constant],
            op_rgb: [COLOR; 3],
            src_alpha: [Source::PrimaryColor, Source::Previous, Source::Constant],
            op_alpha: [ALPHA; 3],
            scale_rgb: 1.0,
            scale_alpha: 1.0,
        };
        let prev = [0.5, 0.25, 1.0, 0.5];
        let primary = [1.0, 1.0, 1.0, 0.75];
        let tex = [[1.0, 0.5, 0.0, 1.0], [0.25, 0.25, 0.25, 0.25]];
        let run = |c: Combine| env(EnvMode::Combine(c), BaseFormat::Rgba).apply(0, prev, primary, &tex);
        assert_eq!(run(base), [0.5, 0.125, 0.0, 0.75]);
        assert_eq!(run(Combine { rgb: CombineFn::AddSigned, scale_rgb: 2.0, ..base }), [1.0, 0.5, 1.0, 0.75]);
        assert_eq!(run(Combine { rgb: CombineFn::Subtract, ..base }), [0.5, 0.25, 0.0, 0.75]);
        // Interpolate texture and previous by the constant (0, 0.5, 1).
        assert_eq!(run(Combine { rgb: CombineFn::Interpolate, ..base }), [0.5, 0.375, 0.0, 0.75]);
        // Crossbar: unit 1's texture, inverted.
        let cross = Combine {
            rgb: CombineFn::Replace,
            src_rgb: [Source::TextureUnit(1); 3],
            op_rgb: [Operand { alpha: false, invert: true }; 3],
            ..base
        };
        assert_eq!(run(cross), [0.75, 0.75, 0.75, 0.75]);
        // DOT3: 4 · ((1−.5)(.5−.5) + (.5−.5)(.25−.5) + (0−.5)(1−.5)) = −1 → 0; with
        // arguments swapped to unit 1 and previous: 4 · (−.25·0 − .25·−.25 − .25·.5) = −0.25 → 0.
        let dot = Combine {
            rgb: CombineFn::Dot3Rgba,
            src_rgb: [Source::Texture, Source::Constant, Source::Constant],
            ..base
        };
        assert_eq!(run(dot), [0.0; 4]);
        let dot =
            Combine { rgb: CombineFn::Dot3Rgb, src_rgb: [Source::Texture, Source::Texture, Source::Constant], ..base };
        // 4 · (.25 + 0 + .25) = 2 → 1; alpha from the alpha function.
        assert_eq!(run(dot), [1.0, 1.0, 1.0, 0.75]);
    }
}
