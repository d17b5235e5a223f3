//! Draw-state assembly: the fragment state, clip rectangles, polygon stipple, query counter
//! and multisample state a draw records into the scene, and the varyings (attributes beyond
//! color) that its enabled per-fragment stages read.
use super::super::Context;
use crate::fragment::pipeline::DrawState;
use crate::fragment::program::FragmentKey;
use crate::fragment::shading::{is_identity, Shading};
use crate::fragment::{DepthTest, FragmentState};
use crate::framebuffer::{ColorFormat, Rect};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::setup::accuracy::Accuracy;
use crate::setup::Scene;
use crate::vertex::attribute::Attribute;

impl Context {
    /// The attributes beyond color that the enabled per-fragment stages read: the secondary
    /// color for the color sum, the fog coordinate for fog, and the texture coordinates of
    /// every unit with a texture target enabled. Nothing else is interpolated.
    pub(in crate::context) fn varyings_needed(&self) -> Vec<Attribute> {
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
