//! glEnable, glDisable, glIsEnabled and their indexed forms: which capability enum names
//! which boolean of the typed state.
//!
//! One table ([`flag`]) maps a capability to its field, so enable, disable, query and the
//! GL_ENABLE_BIT attribute group can never disagree about the set of capabilities.
use super::state::State;
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::{MAX_DRAW_BUFFERS, MAX_TEXTURE_UNITS};
use crate::gl::types::{GLboolean, GLenum};

/// Every capability accepted by glEnable (GL 2.1 compatibility profile plus the
/// extensions tessera exposes), in the order GL_ENABLE_BIT saves them.
pub const CAPABILITIES: &[GLenum] = &[
    GL_ALPHA_TEST,
    GL_AUTO_NORMAL,
    GL_BLEND,
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
    GL_COLOR_LOGIC_OP,
    GL_COLOR_MATERIAL,
    GL_COLOR_SUM,
    GL_CULL_FACE,
    GL_DEPTH_CLAMP,
    GL_DEPTH_TEST,
    GL_DITHER,
    GL_FOG,
    GL_INDEX_LOGIC_OP,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    GL_LIGHTING,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_MAP1_COLOR_4,
    GL_MAP1_INDEX,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP2_COLOR_4,
    GL_MAP2_INDEX,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_MULTISAMPLE,
    GL_NORMALIZE,
    GL_POINT_SMOOTH,
    GL_POINT_SPRITE,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_RESCALE_NORMAL,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_COVERAGE,
    GL_SCISSOR_TEST,
    GL_STENCIL_TEST,
    GL_STENCIL_TEST_TWO_SIDE_EXT,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
    GL_VERTEX_PROGRAM_POINT_SIZE,
    GL_VERTEX_PROGRAM_TWO_SIDE,
];

/// Whether `cap` is a texture target enable while the active unit is a texture coordinate
/// set without fixed-function texturing (GL_MAX_TEXTURE_UNITS <= unit <
/// GL_MAX_TEXTURE_COORDS): glEnable, glDisable, glIsEnabled and glGet of it are then
/// GL_INVALID_OPERATION (GL 2.0 section 3.8.15; Mesa's check too, though its llvmpipe has 8
/// fixed-function units). Texgen enables are coordinate state and exist on every set.
pub fn is_missing_unit_enable(state: &State, cap: GLenum) -> bool {
    matches!(cap, GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP)
        && state.texture.active_unit >= MAX_TEXTURE_UNITS
}

/// The boolean a capability names, or `None` for an enum that is not a capability.
/// Texture enables are those of the active texture unit.
pub fn flag(state: &mut State, cap: GLenum) -> Option<&mut bool> {
    let unit = state.texture.active_unit;
    Some(match cap {
        GL_ALPHA_TEST => &mut state.color.alpha_test,
        GL_AUTO_NORMAL => &mut state.eval.auto_normal,
        GL_BLEND => &mut state.color.blend[0],
        GL_CLIP_PLANE0..=GL_CLIP_PLANE5 => &mut state.transform.clip_planes[(cap - GL_CLIP_PLANE0) as usize],
        GL_COLOR_LOGIC_OP => &mut state.color.color_logic_op,
        GL_COLOR_MATERIAL => &mut state.lighting.color_material,
        GL_COLOR_SUM => &mut state.fog.color_sum,
        GL_CULL_FACE => &mut state.polygon.cull_face,
        GL_DEPTH_CLAMP => &mut state.transform.depth_clamp,
        GL_DEPTH_TEST => &mut state.depth.test,
        GL_DITHER => &mut state.color.dither,
        GL_FOG => &mut state.fog.enabled,
        GL_INDEX_LOGIC_OP => &mut state.color.index_logic_op,
        GL_LIGHT0..=GL_LIGHT7 => &mut state.lighting.lights[(cap - GL_LIGHT0) as usize],
        GL_LIGHTING => &mut state.lighting.enabled,
        GL_LINE_SMOOTH => &mut state.line_point.line_smooth,
        GL_LINE_STIPPLE => &mut state.line_point.line_stipple,
        GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => &mut state.eval.map1[(cap - GL_MAP1_COLOR_4) as usize],
        GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => &mut state.eval.map2[(cap - GL_MAP2_COLOR_4) as usize],
        GL_MULTISAMPLE => &mut state.multisample.enabled,
        GL_NORMALIZE => &mut state.transform.normalize,
        GL_POINT_SMOOTH => &mut state.line_point.point_smooth,
        GL_POINT_SPRITE => &mut state.line_point.point_sprite,
        GL_POLYGON_OFFSET_FILL => &mut state.polygon.offset_fill,
        GL_POLYGON_OFFSET_LINE => &mut state.polygon.offset_line,
        GL_POLYGON_OFFSET_POINT => &mut state.polygon.offset_point,
        GL_POLYGON_SMOOTH => &mut state.polygon.smooth,
        GL_POLYGON_STIPPLE => &mut state.polygon.stipple,
        GL_RESCALE_NORMAL => &mut state.transform.rescale_normal,
        GL_SAMPLE_ALPHA_TO_COVERAGE => &mut state.multisample.alpha_to_coverage,
        GL_SAMPLE_ALPHA_TO_ONE => &mut state.multisample.alpha_to_one,
        GL_SAMPLE_COVERAGE => &mut state.multisample.coverage,
        GL_SCISSOR_TEST => &mut state.scissor.test,
        GL_STENCIL_TEST => &mut state.stencil.test,
        GL_STENCIL_TEST_TWO_SIDE_EXT => &mut state.stencil.two_side,
        GL_TEXTURE_1D => &mut state.texture.units[unit].texture_1d,
        GL_TEXTURE_2D => &mut state.texture.units[unit].texture_2d,
        GL_TEXTURE_3D => &mut state.texture.units[unit].texture_3d,
        GL_TEXTURE_CUBE_MAP => &mut state.texture.units[unit].texture_cube_map,
        GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q => &mut state.texture.units[unit].gen[(cap - GL_TEXTURE_GEN_S) as usize],
        GL_VERTEX_PROGRAM_POINT_SIZE => &mut state.line_point.vertex_program_point_size,
        GL_VERTEX_PROGRAM_TWO_SIDE => &mut state.line_point.vertex_program_two_side,
        _ => return None,
    })
}

impl Context {
    /// glEnable / glDisable.
    pub fn set_capability(&mut self, cap: GLenum, on: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        if cap == GL_BLEND {
            // glEnable(GL_BLEND) enables blending for every draw buffer.
            self.state.color.blend = [on; MAX_DRAW_BUFFERS];
            return;
        }
        if let Some(enabled) = self.client_array_enable(cap) {
            // Client arrays: as glEnableClientState (Mesa accepts them here too).
            *enabled = on;
            return;
        }
        if is_missing_unit_enable(&self.state, cap) {
            return self.error(GL_INVALID_OPERATION);
        }
        match flag(&mut self.state, cap) {
            Some(f) => *f = on,
            None => self.error(GL_INVALID_ENUM),
        }
        if cap == GL_COLOR_MATERIAL {
            // Enabling starts tracking the current color at once.
            self.update_color_material();
        }
    }

    /// glIsEnabled.
    pub fn is_enabled(&mut self, cap: GLenum) -> GLboolean {
        if !self.check_outside_begin_end() {
            return GL_FALSE;
        }
        if let Some(enabled) = self.client_array_enable(cap) {
            return *enabled as GLboolean;
        }
        if is_missing_unit_enable(&self.state, cap) {
            self.error(GL_INVALID_OPERATION);
            return GL_FALSE;
        }
        match flag(&mut self.state, cap) {
            Some(f) => *f as GLboolean,
            None => {
                self.error(GL_INVALID_ENUM);
                GL_FALSE
            }
        }
    }

    /// glEnablei / glDisablei: only GL_BLEND is indexed in this GL.
    pub fn set_capability_indexed(&mut self, cap: GLenum, index: u32, on: bool) {
        if !self.check_outside_begin_end() {
            return;
        }
        if cap != GL_BLEND {
            return self.error(GL_INVALID_ENUM);
        }
        match self.state.color.blend.get_mut(index as usize) {
            Some(f) => *f = on,
            None => self.error(GL_INVALID_VALUE),
        }
    }

    /// glIsEnabledi.
    pub fn is_enabled_indexed(&mut self, cap: GLenum, index: u32) -> GLboolean {
        if !self.check_outside_begin_end() {
            return GL_FALSE;
        }
        if cap != GL_BLEND {
            self.error(GL_INVALID_ENUM);
            return GL_FALSE;
        }
        match self.state.color.blend.get(index as usize) {
            Some(&f) => f as GLboolean,
            None => {
                self.error(GL_INVALID_VALUE);
                GL_FALSE
            }
        }
    }

    /// Snapshot of every capability (for GL_ENABLE_BIT).
    pub fn capability_snapshot(&mut self) -> Vec<(GLenum, bool)> {
        CAPABILITIES.iter().filter_map(|&cap| flag(&mut self.state, cap).map(|f| (cap, *f))).collect()
    }
}
