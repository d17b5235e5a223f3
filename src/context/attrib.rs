//! glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib.
//!
//! A pushed entry holds a clone of each group struct of [`State`] that the mask names; popping
//! writes back exactly the state of those groups, as the tables of chapter 6 of the GL 2.1
//! specification assign it. Most groups are one struct of [`State`] and come back whole.
//! Three need care: GL_LINE_BIT and GL_POINT_BIT share [`LinePointState`] (which also holds
//! enables that belong to GL_ENABLE_BIT only), and GL_ENABLE_BIT gathers the enables of every
//! group, including the texture enables of every unit and the blend enable of every draw
//! buffer, while leaving the rest of those groups alone.
//!
//! Groups whose state does not exist yet (current, list, polygon stipple pattern, ...) are
//! accepted and save nothing. Unknown mask bits are ignored, and an empty mask still pushes
//! an entry, as in Mesa.
//!
//! Deliberate differences from Mesa 22, which restores less than the specification asks:
//! GL_ENABLE_BIT restores GL_LIGHTi (Mesa's enable group has no light loop), GL_ENABLE_BIT and
//! GL_FOG_BIT restore GL_COLOR_SUM (fog/enable in table 6.11), and GL_HINT_BIT restores
//! GL_GENERATE_MIPMAP_HINT and GL_FRAGMENT_SHADER_DERIVATIVE_HINT.
use super::capabilities::{self, CAPABILITIES};
use super::state::*;
use super::Context;
use crate::api::enums::*;
use crate::api::types::GLenum;

/// GL_ENABLE_BIT: every capability's flag.
#[derive(Clone, Debug, PartialEq)]
struct Enables {
    /// The flags of the capabilities that are neither per texture unit nor per draw buffer,
    /// in [`CAPABILITIES`] order.
    flags: Vec<bool>,
    /// GL_BLEND of every draw buffer.
    blend: [bool; MAX_DRAW_BUFFERS],
    /// The texture and texture-coordinate generation enables of every unit.
    texture_units: [TextureUnitEnables; MAX_TEXTURE_UNITS],
}

/// Capabilities that are not one flag of the context: GL_BLEND has one flag per draw buffer,
/// the texture enables one set per texture unit.
fn is_per_buffer_or_unit(cap: GLenum) -> bool {
    matches!(
        cap,
        GL_BLEND | GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP | GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q
    )
}

/// The single-flag capabilities, in [`CAPABILITIES`] order.
fn single_flag_capabilities() -> impl Iterator<Item = GLenum> {
    CAPABILITIES.iter().copied().filter(|&cap| !is_per_buffer_or_unit(cap))
}

impl Enables {
    fn save(state: &mut State) -> Enables {
        let flags = single_flag_capabilities().map(|cap| capabilities::flag(state, cap).is_some_and(|f| *f)).collect();
        Enables { flags, blend: state.color.blend, texture_units: state.texture.units }
    }

    fn restore(&self, state: &mut State) {
        for (cap, &on) in single_flag_capabilities().zip(&self.flags) {
            if let Some(flag) = capabilities::flag(state, cap) {
                *flag = on;
            }
        }
        state.color.blend = self.blend;
        state.texture.units = self.texture_units;
    }
}

/// One glPushAttrib entry: a clone of each group the mask named.
#[derive(Clone, Debug, Default)]
pub struct SavedAttribs {
    color: Option<ColorBufferState>,
    depth: Option<DepthState>,
    stencil: Option<StencilState>,
    scissor: Option<ScissorState>,
    viewport: Option<ViewportState>,
    accum: Option<AccumState>,
    hint: Option<HintState>,
    fog: Option<FogState>,
    lighting: Option<LightingState>,
    transform: Option<TransformState>,
    polygon: Option<PolygonState>,
    /// GL_LINE_BIT and GL_POINT_BIT: the shared struct, of which each restores its fields.
    line: Option<LinePointState>,
    point: Option<LinePointState>,
    multisample: Option<MultisampleState>,
    texture: Option<TextureState>,
    eval: Option<EvalState>,
    pixel_mode: Option<PixelModeState>,
    enable: Option<Enables>,
}

/// Clones `group` when `mask` names `bit`.
fn saved<T: Clone>(mask: u32, bit: u32, group: &T) -> Option<T> {
    (mask & bit != 0).then(|| group.clone())
}

impl SavedAttribs {
    fn save(state: &mut State, mask: u32) -> SavedAttribs {
        SavedAttribs {
            color: saved(mask, GL_COLOR_BUFFER_BIT, &state.color),
            depth: saved(mask, GL_DEPTH_BUFFER_BIT, &state.depth),
            stencil: saved(mask, GL_STENCIL_BUFFER_BIT, &state.stencil),
            scissor: saved(mask, GL_SCISSOR_BIT, &state.scissor),
            viewport: saved(mask, GL_VIEWPORT_BIT, &state.viewport),
            accum: saved(mask, GL_ACCUM_BUFFER_BIT, &state.accum),
            hint: saved(mask, GL_HINT_BIT, &state.hint),
            fog: saved(mask, GL_FOG_BIT, &state.fog),
            lighting: saved(mask, GL_LIGHTING_BIT, &state.lighting),
            transform: saved(mask, GL_TRANSFORM_BIT, &state.transform),
            polygon: saved(mask, GL_POLYGON_BIT, &state.polygon),
            line: saved(mask, GL_LINE_BIT, &state.line_point),
            point: saved(mask, GL_POINT_BIT, &state.line_point),
            multisample: saved(mask, GL_MULTISAMPLE_BIT, &state.multisample),
            texture: saved(mask, GL_TEXTURE_BIT, &state.texture),
            eval: saved(mask, GL_EVAL_BIT, &state.eval),
            pixel_mode: saved(mask, GL_PIXEL_MODE_BIT, &state.pixel_mode),
            enable: (mask & GL_ENABLE_BIT != 0).then(|| Enables::save(state)),
        }
    }

    /// Writes the saved groups back. Where groups overlap (GL_ENABLE_BIT with any other) both
    /// hold the same values, saved at the same time, so the order does not matter.
    fn restore(self, state: &mut State) {
        if let Some(enable) = self.enable {
            enable.restore(state);
        }
        if let Some(line) = self.line {
            state.line_point.line_smooth = line.line_smooth;
            state.line_point.line_stipple = line.line_stipple;
        }
        if let Some(point) = self.point {
            state.line_point.point_smooth = point.point_smooth;
            state.line_point.point_sprite = point.point_sprite;
        }
        restore(&mut state.color, self.color);
        restore(&mut state.depth, self.depth);
        restore(&mut state.stencil, self.stencil);
        restore(&mut state.scissor, self.scissor);
        restore(&mut state.viewport, self.viewport);
        restore(&mut state.accum, self.accum);
        restore(&mut state.hint, self.hint);
        restore(&mut state.fog, self.fog);
        restore(&mut state.lighting, self.lighting);
        restore(&mut state.transform, self.transform);
        restore(&mut state.polygon, self.polygon);
        restore(&mut state.multisample, self.multisample);
        restore(&mut state.texture, self.texture);
        restore(&mut state.eval, self.eval);
        restore(&mut state.pixel_mode, self.pixel_mode);
    }
}

fn restore<T>(group: &mut T, saved: Option<T>) {
    if let Some(saved) = saved {
        *group = saved;
    }
}

/// One glPushClientAttrib entry. GL_CLIENT_VERTEX_ARRAY_BIT is accepted; vertex array state
/// does not exist yet, so it saves nothing.
#[derive(Clone, Debug, Default)]
pub struct SavedClientAttribs {
    pixel_store: Option<PixelStoreState>,
}

impl Context {
    /// glPushAttrib.
    pub fn push_attrib(&mut self, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if self.attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.error(GL_STACK_OVERFLOW);
        }
        let saved = SavedAttribs::save(&mut self.state, mask);
        self.attrib_stack.push(saved);
    }

    /// glPopAttrib.
    pub fn pop_attrib(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        match self.attrib_stack.pop() {
            Some(saved) => saved.restore(&mut self.state),
            None => self.error(GL_STACK_UNDERFLOW),
        }
    }

    /// glPushClientAttrib. Client state commands are not checked against glBegin/glEnd (the
    /// specification lists no error for them there, and Mesa checks none).
    pub fn push_client_attrib(&mut self, mask: u32) {
        if self.client_attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.error(GL_STACK_OVERFLOW);
        }
        let pixel_store = saved(mask, GL_CLIENT_PIXEL_STORE_BIT, &self.pixel_store);
        self.client_attrib_stack.push(SavedClientAttribs { pixel_store });
    }

    /// glPopClientAttrib.
    pub fn pop_client_attrib(&mut self) {
        match self.client_attrib_stack.pop() {
            Some(saved) => restore(&mut self.pixel_store, saved.pixel_store),
            None => self.error(GL_STACK_UNDERFLOW),
        }
    }
}
