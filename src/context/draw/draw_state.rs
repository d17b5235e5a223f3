//! Draw-state assembly: the fragment state, clip rectangles, polygon stipple, query counter
//! and multisample state a draw records into the scene, and the varyings (attributes beyond
//! color) that its enabled per-fragment stages read.
//!
//! With a GLSL program whose fragment stage is a shader in use, that shader replaces the
//! fixed-function fragment program ([`crate::fragment::glsl_shading`]): its inputs, outputs,
//! uniform words and samplers are wired here once per draw state ([`ShaderWiring`]), and
//! the varyings are exactly the ones it reads.
use super::super::shader_objects::{sampler_target, Executable, StageProgram};
use super::super::Context;
use crate::fragment::glsl_shading::{GlslShading, ShaderCode, ShaderInput, ShaderOutput};
use crate::fragment::pipeline::DrawState;
use crate::fragment::program::FragmentKey;
use crate::fragment::shading::{is_identity, Shading};
use crate::fragment::{DepthTest, FragmentState};
use crate::framebuffer::{ColorFormat, Rect};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::setup::accuracy::Accuracy;
use crate::setup::jobs::triangle::WindowVertex;
use crate::setup::Scene;
use crate::shader::fast::Compiled;
use crate::texture::Texturing;
use crate::vertex::attribute::Attribute;
use std::sync::Arc;

impl Context {
    /// The attributes beyond color that the enabled per-fragment stages read: the secondary
    /// color for the color sum, the fog coordinate for fog, and the texture coordinates of
    /// every unit with a texture target enabled. Nothing else is interpolated.
    pub(in crate::context) fn varyings_needed(&self) -> Vec<Attribute> {
        if let Some((executable, stage)) = self.fragment_shader() {
            return ShaderWiring::inputs(executable, stage).varyings;
        }
        let mut needed = Vec::new();
        if self.color_sum_active() {
            needed.extend((0..3).map(Attribute::secondary_color));
        }
        if self.state.fog.enabled {
            needed.push(Attribute::FOG_COORD);
        }
        for (unit, _) in self.enabled_texture_units() {
            needed.extend((0..4).map(|c| Attribute::tex_coord(unit, c)));
        }
        needed
    }

    /// Whether the color sum adds the secondary color: GL_COLOR_SUM without lighting; with
    /// lighting, GL_SEPARATE_SPECULAR_COLOR (the secondary color is then the specular term;
    /// under GL_SINGLE_COLOR it is zero and adding it changes nothing).
    pub(in crate::context) fn color_sum_active(&self) -> bool {
        if self.state.lighting.enabled {
            self.state.lighting.color_control == GL_SEPARATE_SPECULAR_COLOR
        } else {
            self.state.fog.color_sum
        }
    }

    /// The fragment state and clip rectangle of a draw.
    pub(in crate::context) fn draw_state(
        &self,
        scene: &mut Scene,
        width: usize,
        height: usize,
        color_format: ColorFormat,
        depth_bits: u32,
        stencil_bits: u32,
    ) -> DrawState {
        let float_color = color_format.is_float();
        let depth = (self.state.depth.test && depth_bits > 0)
            .then_some(DepthTest { func: self.state.depth.func, write: self.state.depth.write_mask });
        let mut color_masks = vec![None; scene.target_count()];
        let mut buffer_of = vec![None; scene.target_count()];
        for (slot, index) in self.draw_targets() {
            let target = scene.target_index(slot);
            if color_masks.len() <= target {
                color_masks.resize(target + 1, None);
                buffer_of.resize(target + 1, None);
            }
            color_masks[target] = Some(self.write_mask(slot, index));
            buffer_of[target] = Some(index);
        }
        let clamp_float = match self.state.color.clamp_fragment_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let clip = self.clip_rect(Rect::from_xywh(0, 0, width as i32, height as i32));
        let [vx, vy, vw, vh] = self.state.viewport.rect;
        let fill_clip = clip.intersect(Rect::from_xywh(vx, vy, vw, vh));
        let polygon_stipple = self.state.polygon.stipple.then_some(self.state.polygon_stipple);
        let mut fragment = FragmentState::plain(depth, color_masks, clamp_float);
        if self.state.transform.depth_clamp {
            // ARB_depth_clamp: near/far clipping is off (`geometry`), and fragment depths
            // are clamped to the depth range instead.
            let [near, far] = self.state.viewport.depth_range.map(|d| d as f32);
            fragment.depth_clamp = Some([near.min(far), near.max(far)]);
        }
        self.compile_fragment_ops(&mut fragment, &buffer_of, color_format, stencil_bits);
        if self.accuracy == Accuracy::Fast {
            fragment.dither = false;
        }
        if let Some((executable, stage)) = self.fragment_shader() {
            // The shader replaces texturing, the colour sum and fog.
            fragment.color_sum = false;
            fragment.fog = None;
            let buffers = buffer_of.iter().map(|b| b.unwrap_or(0) as u8).collect();
            let shading = self.glsl_shading(executable, stage, height as i32).with_target_buffers(buffers);
            fragment.glsl = Some(Arc::new(shading));
            let samples_passed = self.queries.active_counter();
            let multisample = self.multisample_state(self.framebuffer_samples());
            return DrawState { fragment, clip, fill_clip, polygon_stipple, samples_passed, multisample };
        }
        // Texture coordinates follow the secondary color and the fog coordinate among the
        // varyings (`varyings_needed`).
        let first_slot = 3 * usize::from(self.color_sum_active()) + usize::from(self.state.fog.enabled);
        fragment.texturing = self.compile_texturing(first_slot, height as i32).map(std::sync::Arc::new);
        // The fragment program of texturing, colour sum and fog, from the share group's
        // cache (once per draw state; none when it would pass the colour through).
        let key = FragmentKey::of(&fragment);
        if !is_identity(&key) {
            let program = self.programs.lock().fragment(&key);
            fragment.shading = Some(std::sync::Arc::new(Shading::new(program, &fragment)));
        }
        let samples_passed = self.queries.active_counter();
        let multisample = self.multisample_state(self.framebuffer_samples());
        DrawState { fragment, clip, fill_clip, polygon_stipple, samples_passed, multisample }
    }
}

/// How many varying slots the vertex records carry (the length of their texture coordinate
/// array, whatever it grows to).
fn record_slots() -> usize {
    fn length<const N: usize>(_: fn(&WindowVertex) -> &[[f32; 4]; N]) -> usize {
        N
    }
    length(|v: &WindowVertex| &v.tex_coords)
}

impl ShaderCode for StageProgram {
    fn compiled(&self) -> &Compiled {
        &self.compiled
    }
}

/// What a fragment shader's input slots read, and the varyings the draw interpolates for
/// them.
pub(in crate::context) struct ShaderWiring {
    pub inputs: Vec<ShaderInput>,
    pub varyings: Vec<Attribute>,
}

impl ShaderWiring {
    /// The wiring of `stage`'s inputs: `gl_Color` the primary colour, `gl_SecondaryColor`
    /// the secondary colour, `gl_FogFragCoord` the fog coordinate, `gl_TexCoord[i]` and user
    /// varyings their vertex-record slot component (`executable.varyings`), `gl_FragCoord`
    /// and `gl_FrontFacing` the fragment's own; anything else (`gl_PointCoord`, a slot the
    /// records lack) reads 0.
    pub fn inputs(executable: &Executable, stage: &StageProgram) -> ShaderWiring {
        let slots = record_slots();
        let mut varyings: Vec<Attribute> = Vec::new();
        let mut varying = |a: Attribute| {
            let index = varyings.iter().position(|&v| v == a).unwrap_or_else(|| {
                varyings.push(a);
                varyings.len() - 1
            });
            ShaderInput::Varying(index as u16)
        };
        let inputs = stage
            .lowered
            .inputs
            .iter()
            .map(|w| match w.name.as_str() {
                "gl_Color" => ShaderInput::Primary(w.index as u8),
                "gl_SecondaryColor" => varying(Attribute::secondary_color(w.index as usize & 3)),
                "gl_FogFragCoord" => varying(Attribute::FOG_COORD),
                // w: 1 over the clip w, interpolated as a varying (perspective-correctly).
                "gl_FragCoord" if w.index == 3 => match varying(Attribute::CLIP_W) {
                    ShaderInput::Varying(v) => ShaderInput::Reciprocal(v),
                    other => other,
                },
                "gl_FragCoord" => ShaderInput::FragCoord(w.index as u8),
                "gl_FrontFacing" => ShaderInput::FrontFacing,
                "gl_PointCoord" => varying(Attribute::point_coord(w.index as usize & 1)),
                name => match executable.varyings.index_of(name, w.index).map(usize::from) {
                    Some(k) if k / 4 < slots => varying(Attribute::tex_coord(k / 4, k % 4)),
                    _ => ShaderInput::Zero,
                },
            })
            .collect();
        ShaderWiring { inputs, varyings }
    }
}

/// Where a fragment shader's output word goes.
fn shader_output(name: &str, index: u32) -> ShaderOutput {
    let channel = (index & 3) as u8;
    match name {
        "gl_FragColor" => ShaderOutput::Color { buffer: 0, channel },
        "gl_FragDepth" => ShaderOutput::Depth,
        _ => match name.strip_prefix("gl_FragData[").and_then(|n| n.strip_suffix(']')?.parse::<u8>().ok()) {
            Some(buffer) => ShaderOutput::Color { buffer, channel },
            None => ShaderOutput::Unused,
        },
    }
}

impl Context {
    /// The program in use and its fragment stage, when that is a shader.
    pub(in crate::context) fn fragment_shader(&self) -> Option<(&Arc<Executable>, &Arc<StageProgram>)> {
        let executable = self.program_in_use.executable()?;
        Some((executable, executable.fragment_program.as_ref()?))
    }

    /// The GLSL fragment shading of a draw on a framebuffer `fb_height` rows high: the
    /// program's wiring, its uniform words (user uniforms from the program's values,
    /// built-in state, 0 where it has none: [`Context::stage_uniforms`]) and each
    /// sampler's texture: the texture its unit has bound for the sampler's target, with
    /// that texture's parameters, whatever the unit's enables (none when incomplete).
    fn glsl_shading(&self, executable: &Executable, stage: &Arc<StageProgram>, fb_height: i32) -> GlslShading {
        let lowered = &stage.lowered;
        let values = self.program_in_use.uniform_values().unwrap_or_default();
        let user_word = |name: &str, index: u32| -> u32 {
            let Some((_, first)) = executable.interface.element(name) else { return 0 };
            values.get(first + index as usize).copied().unwrap_or(0)
        };
        let uniforms = self.stage_uniforms(stage);
        let stages = lowered
            .samplers
            .iter()
            .enumerate()
            .filter_map(|(i, s)| {
                let unit = user_word(&s.name, 0) as i32;
                self.shader_texture_stage(i, usize::try_from(unit).ok()?, sampler_target(s.kind))
            })
            .collect();
        let wiring = ShaderWiring::inputs(executable, stage);
        let outputs = lowered.outputs.iter().map(|w| shader_output(&w.name, w.index)).collect();
        let code: Arc<dyn ShaderCode> = stage.clone();
        GlslShading::new(
            code,
            &lowered.program,
            wiring.inputs,
            outputs,
            uniforms,
            wiring.varyings.len(),
            Texturing { stages, fb_height },
        )
    }
}

#[cfg(test)]
#[path = "glsl_tests.rs"]
mod glsl_tests;
