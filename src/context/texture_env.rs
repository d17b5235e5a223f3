//! Per-unit texturing state and its compilation: glTexEnv*, glTexGen* and their queries, what
//! the texture coordinates of each vertex need (texgen, the texture matrix), and the per-draw
//! [`Texturing`] the fragment stage runs: for each enabled unit with a complete texture, a
//! sampler chosen once per draw and its compiled environment. An untextured draw compiles
//! to `None` and its spans do no texture work at all.
//!
//! Eye planes are transformed by the inverse modelview at specification (GL 2.1 §2.11.4),
//! as Mesa does. The per-vertex work (texgen, the texture matrix) is
//! [`crate::vertex::texgen`]'s; this module compiles what it reads per draw.
use super::texture::{Level, TextureObject, MAX_TEXTURE_LOD_BIAS};
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::MAX_TEXTURE_UNITS;
use crate::gl::types::GLenum;
use crate::gl::CompareFunc;
use crate::texture::env::{Combine, CombineFn, EnvMode, Operand, Source, TexEnv};
use crate::texture::sampler::{DepthMode, Dim, Filter, Sampler, Wrap};
use crate::texture::{BaseFormat, TextureStage, Texturing};
use crate::vertex::texgen::{Gen, TexCoordUnit};
use glam::Mat4;

/// GL_TEXTURE_ENV state of one unit.
#[derive(Clone, Debug, PartialEq)]
pub struct TexEnvState {
    pub mode: GLenum,
    pub color: [f32; 4],
    pub combine_rgb: GLenum,
    pub combine_alpha: GLenum,
    pub source_rgb: [GLenum; 3],
    pub source_alpha: [GLenum; 3],
    pub operand_rgb: [GLenum; 3],
    pub operand_alpha: [GLenum; 3],
    pub rgb_scale: f32,
    pub alpha_scale: f32,
    /// GL_TEXTURE_FILTER_CONTROL's GL_TEXTURE_LOD_BIAS.
    pub lod_bias: f32,
    /// GL_POINT_SPRITE's GL_COORD_REPLACE (kept for queries).
    pub coord_replace: bool,
}

impl Default for TexEnvState {
    fn default() -> Self {
        TexEnvState {
            mode: GL_MODULATE,
            color: [0.0; 4],
            combine_rgb: GL_MODULATE,
            combine_alpha: GL_MODULATE,
            source_rgb: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            source_alpha: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            operand_rgb: [GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA],
            operand_alpha: [GL_SRC_ALPHA; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
            lod_bias: 0.0,
            coord_replace: false,
        }
    }
}

/// glTexGen state of one coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenState {
    pub mode: GLenum,
    pub object_plane: [f64; 4],
    pub eye_plane: [f64; 4],
}

/// The texturing state of one unit (GL_TEXTURE_BIT), beside its enables.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureUnitState {
    /// The object bound to each target of [`TARGETS`] (0: the default object).
    pub bindings: [u32; 4],
    pub env: TexEnvState,
    /// S, T, R, Q.
    pub gen: [TexGenState; 4],
}

impl Default for TextureUnitState {
    fn default() -> Self {
        let plane = |i: usize| {
            let mut p = [0.0; 4];
            if i < 2 {
                p[i] = 1.0;
            }
            TexGenState { mode: GL_EYE_LINEAR, object_plane: p, eye_plane: p }
        };
        TextureUnitState { bindings: [0; 4], env: TexEnvState::default(), gen: std::array::from_fn(plane) }
    }
}
fn combine_fn(e: GLenum) -> Option<CombineFn> {
    Some(match e {
        GL_REPLACE => CombineFn::Replace,
        GL_MODULATE => CombineFn::Modulate,
        GL_ADD => CombineFn::Add,
        GL_ADD_SIGNED => CombineFn::AddSigned,
        GL_INTERPOLATE => CombineFn::Interpolate,
        GL_SUBTRACT => CombineFn::Subtract,
        GL_DOT3_RGB => CombineFn::Dot3Rgb,
        GL_DOT3_RGBA => CombineFn::Dot3Rgba,
        _ => return None,
    })
}

fn combine_source(e: GLenum) -> Option<Source> {
    Some(match e {
        GL_TEXTURE => Source::Texture,
        GL_CONSTANT => Source::Constant,
        GL_PRIMARY_COLOR => Source::PrimaryColor,
        GL_PREVIOUS => Source::Previous,
        t if (GL_TEXTURE0..GL_TEXTURE0 + MAX_TEXTURE_UNITS as GLenum).contains(&t) => {
            Source::TextureUnit((t - GL_TEXTURE0) as usize)
        }
        _ => return None,
    })
}

fn operand(e: GLenum) -> Operand {
    Operand {
        alpha: matches!(e, GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA),
        invert: matches!(e, GL_ONE_MINUS_SRC_COLOR | GL_ONE_MINUS_SRC_ALPHA),
    }
}

fn wrap(e: GLenum) -> Wrap {
    match e {
        GL_CLAMP => Wrap::Clamp,
        GL_CLAMP_TO_EDGE => Wrap::ClampToEdge,
        GL_CLAMP_TO_BORDER => Wrap::ClampToBorder,
        GL_MIRRORED_REPEAT => Wrap::MirroredRepeat,
        _ => Wrap::Repeat,
    }
}

impl Context {
    /// Whether glTexEnv / glGetTexEnv of (`target`, `pname`) may address the active unit
    /// (else GL_INVALID_OPERATION, before any enum check, as in Mesa): the environment and
    /// the level-of-detail bias exist on the fixed-function units (GL_MAX_TEXTURE_UNITS; the
    /// image units past them have bindings and texture parameters only, their bias 0),
    /// GL_COORD_REPLACE on every texture coordinate set (GL 2.0 sections 3.3.1 and 3.8.13).
    /// Mesa accepts the environment on all of its 192 combined image units.
    fn check_env_unit(&mut self, target: GLenum, pname: GLenum) -> bool {
        let coordinate_state = (target, pname) == (GL_POINT_SPRITE, GL_COORD_REPLACE);
        if self.state.texture.active_unit >= MAX_TEXTURE_UNITS && !coordinate_state {
            self.error(GL_INVALID_OPERATION);
            return false;
        }
        true
    }

    fn active_env(&mut self) -> &mut TexEnvState {
        let unit = self.state.texture.active_unit;
        &mut self.state.texture.unit_state[unit].env
    }

    /// glTexEnv{if}[v]. `int_form`: the values came from an integer form (the color is then
    /// normalized).
    pub fn tex_env(&mut self, target: GLenum, pname: GLenum, values: &[f32], int_form: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !self.check_env_unit(target, pname) {
            return;
        }
        let v = values.first().copied().unwrap_or(0.0);
        let e = v as i32 as GLenum;
        let result = match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => match e {
                GL_MODULATE | GL_DECAL | GL_BLEND | GL_REPLACE | GL_ADD | GL_COMBINE => {
                    self.active_env().mode = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => {
                if values.len() < 4 {
                    Err(GL_INVALID_ENUM)
                } else {
                    let c: [f32; 4] = std::array::from_fn(|i| {
                        let x = values[i];
                        let f = if int_form { (x as f64 / 2147483647.0) as f32 } else { x };
                        f.clamp(0.0, 1.0)
                    });
                    self.active_env().color = c;
                    Ok(())
                }
            }
            (GL_TEXTURE_ENV, GL_COMBINE_RGB | GL_COMBINE_ALPHA) => match combine_fn(e) {
                Some(CombineFn::Dot3Rgb | CombineFn::Dot3Rgba) if pname == GL_COMBINE_ALPHA => Err(GL_INVALID_ENUM),
                Some(_) => {
                    let env = self.active_env();
                    if pname == GL_COMBINE_RGB {
                        env.combine_rgb = e;
                    } else {
                        env.combine_alpha = e;
                    }
                    Ok(())
                }
                None => Err(GL_INVALID_ENUM),
            },
            (GL_TEXTURE_ENV, GL_SOURCE0_RGB..=GL_SOURCE2_RGB | GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA) => {
                match combine_source(e) {
                    Some(_) => {
                        let env = self.active_env();
                        if pname <= GL_SOURCE2_RGB {
                            env.source_rgb[(pname - GL_SOURCE0_RGB) as usize] = e;
                        } else {
                            env.source_alpha[(pname - GL_SOURCE0_ALPHA) as usize] = e;
                        }
                        Ok(())
                    }
                    None => Err(GL_INVALID_ENUM),
                }
            }
            (GL_TEXTURE_ENV, GL_OPERAND0_RGB..=GL_OPERAND2_RGB) => match e {
                GL_SRC_COLOR | GL_ONE_MINUS_SRC_COLOR | GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA => {
                    self.active_env().operand_rgb[(pname - GL_OPERAND0_RGB) as usize] = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            (GL_TEXTURE_ENV, GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA) => match e {
                GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA => {
                    self.active_env().operand_alpha[(pname - GL_OPERAND0_ALPHA) as usize] = e;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            (GL_TEXTURE_ENV, GL_RGB_SCALE | GL_ALPHA_SCALE) => {
                if v == 1.0 || v == 2.0 || v == 4.0 {
                    let env = self.active_env();
                    if pname == GL_RGB_SCALE {
                        env.rgb_scale = v;
                    } else {
                        env.alpha_scale = v;
                    }
                    Ok(())
                } else {
                    Err(GL_INVALID_VALUE)
                }
            }
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => {
                self.active_env().lod_bias = v;
                Ok(())
            }
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => match e {
                0 | 1 => {
                    self.active_env().coord_replace = e == 1;
                    Ok(())
                }
                _ => Err(GL_INVALID_ENUM),
            },
            _ => Err(GL_INVALID_ENUM),
        };
        if let Err(err) = result {
            self.error(err);
        }
    }

    /// glGetTexEnv{if}v: the values, and whether the value is a color (normalized as an integer).
    pub fn get_tex_env(&mut self, target: GLenum, pname: GLenum) -> Option<(Vec<f32>, bool)> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if !self.check_env_unit(target, pname) {
            return None;
        }
        let env = self.state.texture.unit_state[self.state.texture.active_unit].env.clone();
        let e = |x: GLenum| Some((vec![x as f32], false));
        let r = match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => e(env.mode),
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => Some((env.color.to_vec(), true)),
            (GL_TEXTURE_ENV, GL_COMBINE_RGB) => e(env.combine_rgb),
            (GL_TEXTURE_ENV, GL_COMBINE_ALPHA) => e(env.combine_alpha),
            (GL_TEXTURE_ENV, GL_SOURCE0_RGB..=GL_SOURCE2_RGB) => e(env.source_rgb[(pname - GL_SOURCE0_RGB) as usize]),
            (GL_TEXTURE_ENV, GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA) => {
                e(env.source_alpha[(pname - GL_SOURCE0_ALPHA) as usize])
            }
            (GL_TEXTURE_ENV, GL_OPERAND0_RGB..=GL_OPERAND2_RGB) => {
                e(env.operand_rgb[(pname - GL_OPERAND0_RGB) as usize])
            }
            (GL_TEXTURE_ENV, GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA) => {
                e(env.operand_alpha[(pname - GL_OPERAND0_ALPHA) as usize])
            }
            (GL_TEXTURE_ENV, GL_RGB_SCALE) => Some((vec![env.rgb_scale], false)),
            (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => Some((vec![env.alpha_scale], false)),
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => Some((vec![env.lod_bias], false)),
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => e(env.coord_replace as GLenum),
            _ => None,
        };
        if r.is_none() {
            self.error(GL_INVALID_ENUM);
        }
        r
    }

    /// glTexGen{ifd}[v]. `vector`: from a vector form (planes need one).
    pub fn tex_gen(&mut self, coord: GLenum, pname: GLenum, values: &[f64], vector: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(c) = (GL_S..=GL_Q).contains(&coord).then(|| (coord - GL_S) as usize) else {
            return self.error(GL_INVALID_ENUM);
        };
        let unit = self.state.texture.active_unit;
        match pname {
            GL_TEXTURE_GEN_MODE => {
                let mode = values.first().copied().unwrap_or(0.0) as i32 as GLenum;
                let ok = match mode {
                    GL_OBJECT_LINEAR | GL_EYE_LINEAR => true,
                    GL_SPHERE_MAP => c < 2,
                    GL_NORMAL_MAP | GL_REFLECTION_MAP => c < 3,
                    _ => false,
                };
                if !ok {
                    return self.error(GL_INVALID_ENUM);
                }
                self.state.texture.unit_state[unit].gen[c].mode = mode;
            }
            GL_OBJECT_PLANE | GL_EYE_PLANE if vector && values.len() >= 4 => {
                let p: [f64; 4] = std::array::from_fn(|i| values[i]);
                if pname == GL_OBJECT_PLANE {
                    self.state.texture.unit_state[unit].gen[c].object_plane = p;
                } else {
                    self.matrices.validate();
                    let inv = self.matrices.modelview_inverse().to_cols_array();
                    // p_eye = p · M⁻¹ (a row vector), in single precision as Mesa.
                    let e = crate::context::matrix::transform_row_vector(p.map(|x| x as f32), &inv);
                    self.state.texture.unit_state[unit].gen[c].eye_plane = e.map(f64::from);
                }
            }
            _ => self.error(GL_INVALID_ENUM),
        }
    }

    /// glGetTexGen{ifd}v.
    pub fn get_tex_gen(&mut self, coord: GLenum, pname: GLenum) -> Option<Vec<f64>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let Some(c) = (GL_S..=GL_Q).contains(&coord).then(|| (coord - GL_S) as usize) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        let g = self.state.texture.unit_state[self.state.texture.active_unit].gen[c];
        match pname {
            GL_TEXTURE_GEN_MODE => Some(vec![g.mode as f64]),
            GL_OBJECT_PLANE => Some(g.object_plane.to_vec()),
            GL_EYE_PLANE => Some(g.eye_plane.to_vec()),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// The units with a texture target enabled: (unit, target index of the enabled target
    /// of highest priority: cube map, 3D, 2D, 1D).
    pub(super) fn enabled_texture_units(&self) -> Vec<(usize, usize)> {
        let mut units = Vec::new();
        for (unit, e) in self.state.texture.units.iter().enumerate().take(MAX_TEXTURE_UNITS) {
            let t = if e.texture_cube_map {
                3
            } else if e.texture_3d {
                2
            } else if e.texture_2d {
                1
            } else if e.texture_1d {
                0
            } else {
                continue;
            };
            units.push((unit, t));
        }
        units
    }

    /// What texgen ([`crate::vertex::texgen`]) needs per enabled unit, decided once per draw.
    /// With a GLSL fragment shader, the units whose coordinates it reads (`gl_TexCoord[i]`
    /// among the texture units).
    pub(super) fn tex_coord_units(&self) -> Vec<TexCoordUnit> {
        if self.fragment_shader().is_some() {
            let mut units: Vec<usize> = (self.varyings_needed().iter())
                .filter_map(|a| a.texture_coordinate().map(|(unit, _)| unit))
                .filter(|&unit| unit < MAX_TEXTURE_UNITS)
                .collect();
            units.sort_unstable();
            units.dedup();
            return self.tex_coord_units_of(units.into_iter());
        }
        self.tex_coord_units_of(self.enabled_texture_units().into_iter().map(|(unit, _)| unit))
    }

    /// The lookup stage of a GLSL program's sampler `index` reading texture unit `unit`'s
    /// binding for target index `t` (1D, 2D, 3D, cube map): that texture's parameters and the
    /// unit's level-of-detail bias, whatever the unit's enables; `None` when the unit does
    /// not exist or its texture is incomplete (the lookups then read (0, 0, 0, 1)).
    pub(super) fn shader_texture_stage(&self, index: usize, unit: usize, t: usize) -> Option<TextureStage> {
        let st = self.state.texture.unit_state.get(unit)?;
        let textures = self.textures.lock();
        let obj = textures.get(st.bindings[t], t)?;
        let sampler = compile_sampler(obj, t, st.env.lod_bias)?;
        let env = compile_env(&st.env, sampler.base);
        Some(TextureStage::new(index, sampler, env, 0))
    }

    /// The texture coordinate work of the given units (every unit for the raster position,
    /// whose coordinates are queryable whether or not a texture is enabled).
    pub(super) fn tex_coord_units_of(&self, units: impl Iterator<Item = usize>) -> Vec<TexCoordUnit> {
        units
            .map(|unit| {
                let st = &self.state.texture.unit_state[unit];
                let enables = self.state.texture.units[unit].gen;
                let gen: [Option<Gen>; 4] = std::array::from_fn(|c| {
                    let g = &st.gen[c];
                    enables[c].then(|| match g.mode {
                        GL_OBJECT_LINEAR => Gen::Object(g.object_plane.map(|x| x as f32)),
                        GL_EYE_LINEAR => Gen::Eye(g.eye_plane.map(|x| x as f32)),
                        GL_SPHERE_MAP => Gen::Sphere,
                        GL_REFLECTION_MAP => Gen::Reflection,
                        _ => Gen::Normal,
                    })
                });
                let needs_normal = gen.iter().any(|g| matches!(g, Some(Gen::Sphere | Gen::Reflection | Gen::Normal)));
                let m = self.matrices.texture(unit);
                TexCoordUnit { unit, gen, needs_normal, matrix: (m != Mat4::IDENTITY).then_some(m) }
            })
            .collect()
    }

    /// The texturing of a draw: `None` when no unit has a texture target enabled.
    /// `first_slot` is the index of the first texture coordinate among the draw's varyings;
    /// each enabled unit has four from there, in unit order.
    pub(super) fn compile_texturing(&self, first_slot: usize, fb_height: i32) -> Option<Texturing> {
        let enabled = self.enabled_texture_units();
        if enabled.is_empty() {
            return None;
        }
        let mut stages = Vec::new();
        let textures = self.textures.lock();
        for (k, &(unit, t)) in enabled.iter().enumerate() {
            let st = &self.state.texture.unit_state[unit];
            let Some(obj) = textures.get(st.bindings[t], t) else { continue };
            let Some(sampler) = compile_sampler(obj, t, st.env.lod_bias) else { continue };
            let base = match (sampler.base, sampler.depth_mode) {
                (BaseFormat::Depth, DepthMode::Luminance) => BaseFormat::Luminance,
                (BaseFormat::Depth, DepthMode::Intensity) => BaseFormat::Intensity,
                (BaseFormat::Depth, DepthMode::Alpha) => BaseFormat::Alpha,
                (b, _) => b,
            };
            let env = compile_env(&st.env, base);
            stages.push(TextureStage::new(unit, sampler, env, first_slot + 4 * k));
        }
        Some(Texturing { stages, fb_height })
    }
}

fn compile_env(env: &TexEnvState, base: BaseFormat) -> TexEnv {
    let mode = match env.mode {
        GL_REPLACE => EnvMode::Replace,
        GL_DECAL => EnvMode::Decal,
        GL_BLEND => EnvMode::Blend,
        GL_ADD => EnvMode::Add,
        GL_COMBINE => EnvMode::Combine(Combine {
            rgb: combine_fn(env.combine_rgb).unwrap_or(CombineFn::Modulate),
            alpha: combine_fn(env.combine_alpha).unwrap_or(CombineFn::Modulate),
            src_rgb: env.source_rgb.map(|s| combine_source(s).unwrap_or(Source::Previous)),
            op_rgb: env.operand_rgb.map(operand),
            src_alpha: env.source_alpha.map(|s| combine_source(s).unwrap_or(Source::Previous)),
            op_alpha: env.operand_alpha.map(operand),
            scale_rgb: env.rgb_scale,
            scale_alpha: env.alpha_scale,
        }),
        _ => EnvMode::Modulate,
    };
    TexEnv { mode, base, color: env.color }
}

/// The sampler of a texture object bound to target index `t`, or `None` when the texture is
/// not complete (GL 2.1 §3.8.10: texturing is then disabled for the unit).
fn compile_sampler(obj: &TextureObject, t: usize, unit_bias: f32) -> Option<Sampler> {
    let p = &obj.params;
    let mip = match p.min_filter {
        GL_NEAREST_MIPMAP_NEAREST | GL_LINEAR_MIPMAP_NEAREST => Some(Filter::Nearest),
        GL_NEAREST_MIPMAP_LINEAR | GL_LINEAR_MIPMAP_LINEAR => Some(Filter::Linear),
        _ => None,
    };
    let min = match p.min_filter {
        GL_LINEAR | GL_LINEAR_MIPMAP_NEAREST | GL_LINEAR_MIPMAP_LINEAR => Filter::Linear,
        _ => Filter::Nearest,
    };
    let base_level = p.base_level.max(0) as usize;
    let faces = if t == 3 { 6 } else { 1 };
    let mut all = Vec::new();
    let base0: &Level = obj.level(0, base_level)?;
    let (w, h, d) = (base0.width, base0.height, base0.depth);
    if t == 3 && w != h {
        return None;
    }
    // The last level of a complete chain: p = ⌊log₂ max size⌋ + base, capped by max_level.
    let largest = w.max(h).max(d);
    let chain = usize::BITS as usize - 1 - largest.leading_zeros() as usize;
    let last = if mip.is_some() { (base_level + chain).min(p.max_level.max(0) as usize) } else { base_level };
    if last < base_level {
        return None;
    }
    for face in 0..faces {
        let mut levels = Vec::new();
        for (k, level) in (base_level..=last).enumerate() {
            let l = obj.level(face, level)?;
            let expect = |s: usize| crate::texture::level_size(s, k);
            let dims_ok = l.width == expect(w)
                && (t == 0 || l.height == expect(h))
                && (t != 2 || l.depth == expect(d))
                && l.info.base == base0.info.base
                && l.border == base0.border
                && l.internal_format == base0.internal_format;
            if !dims_ok {
                return None;
            }
            levels.push(l.image.clone()?);
        }
        all.push(levels);
    }
    let depth = base0.info.base == BaseFormat::Depth;
    let compare =
        (depth && p.compare_mode == GL_COMPARE_R_TO_TEXTURE).then(|| CompareFunc::from_gl(p.compare_func)).flatten();
    let depth_mode = match p.depth_mode {
        GL_INTENSITY => DepthMode::Intensity,
        GL_ALPHA => DepthMode::Alpha,
        _ => DepthMode::Luminance,
    };
    let bias = (p.lod_bias + unit_bias).clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS);
    let border = if depth { p.border_color } else { base0.info.base.texture_color(p.border_color) };
    let dim = [Dim::D1, Dim::D2, Dim::D3, Dim::Cube][t];
    Some(Sampler {
        dim,
        faces: all,
        wrap: p.wrap.map(wrap),
        mag: if p.mag_filter == GL_LINEAR { Filter::Linear } else { Filter::Nearest },
        min,
        mip,
        border,
        lod_bias: bias,
        shader_bias: 0.0,
        min_lod: p.min_lod,
        max_lod: p.max_lod,
        compare,
        depth_mode,
        base: base0.info.base,
    })
}
