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
//! Groups whose state does not exist yet (list, ...) are accepted and save nothing. Unknown
//! mask bits are ignored, and an empty mask still pushes
//! an entry, as in Mesa.
//!
//! Deliberate differences from Mesa 22, which restores less than the specification asks:
//! GL_ENABLE_BIT restores GL_LIGHTi (Mesa's enable group has no light loop), GL_ENABLE_BIT and
//! GL_FOG_BIT restore GL_COLOR_SUM (fog/enable in table 6.11), and GL_HINT_BIT restores
//! GL_GENERATE_MIPMAP_HINT and GL_FRAGMENT_SHADER_DERIVATIVE_HINT, and GL_LIGHTING_BIT restores
//! GL_PROVOKING_VERTEX (ARB_provoking_vertex puts it in the lighting group; Mesa 22 leaves it).
//! GL_STENCIL_BUFFER_BIT restores the EXT_stencil_two_side back face (Mesa 22 restores its
//! front and back faces only), and GL_FOG_BIT restores GL_FOG_COORD_SRC (table 6.11) and
//! GL_FOG_DISTANCE_MODE_NV (NV_fog_distance puts it in the fog group); Mesa 22 leaves both.
use super::capabilities::{self, CAPABILITIES};
use super::state::*;
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::*;
use crate::gl::types::GLenum;

/// GL_ENABLE_BIT: every capability's flag.
#[derive(Clone, Debug, PartialEq)]
struct Enables {
    /// The flags of the capabilities that are neither per texture unit nor per draw buffer,
    /// in [`CAPABILITIES`] order.
    flags: Vec<bool>,
    /// GL_BLEND of every draw buffer.
    blend: [bool; MAX_DRAW_BUFFERS],
    /// The texture and texture-coordinate generation enables of every unit.
    texture_units: [TextureUnitEnables; MAX_TEXTURE_COORDS],
}

/// Capabilities that are not one flag of the context: GL_BLEND has one flag per draw buffer,
/// the texture enables one set per texture unit.
fn is_per_buffer_or_unit(cap: GLenum) -> bool {
    matches!(
        cap,
        GL_BLEND | GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP | GL_TEXTURE_GEN_S
            ..=GL_TEXTURE_GEN_Q
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
    current: Option<CurrentState>,
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
    polygon_stipple: Option<[u32; 32]>,
    enable: Option<Enables>,
    /// GL_TEXTURE_BIT: the parameters of the texture objects bound to every target of every
    /// unit (GL 2.1 table 6.20 puts texture object state in the texture group).
    texture_objects: Vec<(u32, usize, super::texture::TexParams)>,
    list_base: Option<u32>,
}

/// Clones `group` when `mask` names `bit`.
fn saved<T: Clone>(mask: u32, bit: u32, group: &T) -> Option<T> {
    (mask & bit != 0).then(|| group.clone())
}

impl SavedAttribs {
    fn save(state: &mut State, mask: u32) -> SavedAttribs {
        SavedAttribs {
            current: saved(mask, GL_CURRENT_BIT, &state.current),
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
            polygon_stipple: saved(mask, GL_POLYGON_STIPPLE_BIT, &state.polygon_stipple),
            enable: (mask & GL_ENABLE_BIT != 0).then(|| Enables::save(state)),
            texture_objects: Vec::new(),
            list_base: saved(mask, GL_LIST_BIT, &state.list_base),
        }
    }

    /// Writes the saved groups back. Where groups overlap (GL_ENABLE_BIT with any other) both
    /// hold the same values, saved at the same time, so the order does not matter.
    fn restore(self, state: &mut State) {
        if let Some(enable) = self.enable {
            enable.restore(state);
        }
        if let Some(line) = self.line {
            let l = &mut state.line_point;
            (l.line_smooth, l.line_stipple, l.line_width) = (line.line_smooth, line.line_stipple, line.line_width);
            (l.line_stipple_factor, l.line_stipple_pattern) = (line.line_stipple_factor, line.line_stipple_pattern);
        }
        if let Some(point) = self.point {
            let p = &mut state.line_point;
            (p.point_smooth, p.point_sprite, p.point_size) = (point.point_smooth, point.point_sprite, point.point_size);
            (p.point_size_min, p.point_size_max) = (point.point_size_min, point.point_size_max);
            p.point_fade_threshold = point.point_fade_threshold;
            p.point_distance_attenuation = point.point_distance_attenuation;
            p.point_sprite_coord_origin = point.point_sprite_coord_origin;
        }
        restore(&mut state.current, self.current);
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
        if let Some(mut pixel_mode) = self.pixel_mode {
            // The pixel maps belong to no attribute group (GL 2.1 table 6.24; Mesa 22 agrees).
            pixel_mode.maps = std::mem::take(&mut state.pixel_mode.maps);
            state.pixel_mode = pixel_mode;
        }
        restore(&mut state.polygon_stipple, self.polygon_stipple);
        restore(&mut state.list_base, self.list_base);
    }
}

fn restore<T>(group: &mut T, saved: Option<T>) {
    if let Some(saved) = saved {
        *group = saved;
    }
}

/// One glPushClientAttrib entry: pixel storage modes and vertex array state.
#[derive(Clone, Debug, Default)]
pub struct SavedClientAttribs {
    pixel_store: Option<PixelStoreState>,
    vertex_arrays: Option<crate::vertex::arrays::ClientArrays>,
}

impl Context {
    /// glXCopyContext: copies the attribute groups `mask` names (as glPushAttrib would save
    /// them) from `source` into this context.
    pub fn copy_attribs_from(&mut self, source: &mut Context, mask: u32) {
        SavedAttribs::save(&mut source.state, mask).restore(&mut self.state);
    }

    /// glPushAttrib.
    pub fn push_attrib(&mut self, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if self.attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.error(GL_STACK_OVERFLOW);
        }
        let mut saved = SavedAttribs::save(&mut self.state, mask);
        if mask & GL_TEXTURE_BIT != 0 {
            for unit in &self.state.texture.unit_state {
                for (t, &name) in unit.bindings.iter().enumerate() {
                    if let Some(obj) = self.textures.lock().get(name, t) {
                        saved.texture_objects.push((name, t, obj.params.clone()));
                    }
                }
            }
        }
        self.attrib_stack.push(saved);
    }

    /// glPopAttrib.
    pub fn pop_attrib(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        match self.attrib_stack.pop() {
            Some(mut saved) => {
                // Objects deleted since the push are gone; the others get their parameters back.
                for (name, t, params) in std::mem::take(&mut saved.texture_objects) {
                    if let Some(obj) = self.textures.lock().get_mut(name, t) {
                        obj.params = params;
                    }
                }
                saved.restore(&mut self.state)
            }
            None => self.error(GL_STACK_UNDERFLOW),
        }
    }

    /// glPushClientAttrib. Between glBegin and glEnd the client stack is undefined in GL ("an
    /// error may or may not be generated"); Mesa 22 generates GL_INVALID_OPERATION, as here.
    pub fn push_client_attrib(&mut self, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if self.client_attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.error(GL_STACK_OVERFLOW);
        }
        let pixel_store = saved(mask, GL_CLIENT_PIXEL_STORE_BIT, &self.pixel_store);
        let vertex_arrays = saved(mask, GL_CLIENT_VERTEX_ARRAY_BIT, &self.vertex_input.arrays);
        self.client_attrib_stack.push(SavedClientAttribs { pixel_store, vertex_arrays });
    }

    /// glPopClientAttrib.
    pub fn pop_client_attrib(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        match self.client_attrib_stack.pop() {
            Some(saved) => {
                if let Some(store) = &saved.pixel_store {
                    // The pixel buffer bindings come back as glBindBuffer binds them (a
                    // buffer deleted since is a new, empty buffer of the same name), as the
                    // array bindings do.
                    let mut buffers = self.buffers.lock();
                    buffers.create_on_bind(store.pack_buffer);
                    buffers.create_on_bind(store.unpack_buffer);
                }
                restore(&mut self.pixel_store, saved.pixel_store);
                if let Some(arrays) = saved.vertex_arrays {
                    self.restore_client_arrays(arrays);
                }
            }
            None => self.error(GL_STACK_UNDERFLOW),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
    use crate::gl::CompareFunc;

    fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 16);
        Context::new(ContextConfig { visual })
    }

    /// `state` with every field of every group changed.
    fn scrambled(state: &State) -> State {
        let mut t = state.clone();
        let cur = &mut t.current;
        cur.color = [0.1, 0.2, 0.3, 0.4];
        cur.secondary_color = [0.5, 0.6, 0.7, 1.0];
        cur.normal = [1.0, 0.0, 0.0];
        cur.tex_coords[2] = [1.0, 2.0, 3.0, 4.0];
        cur.fog_coord = 5.0;
        cur.edge_flag = !cur.edge_flag;
        cur.index = 9.0;
        let c = &mut t.color;
        c.alpha_test = !c.alpha_test;
        c.alpha_func = CompareFunc::Greater;
        c.alpha_ref = 0.5;
        c.blend = [true, false, true, true, false, true, true, true];
        c.blend_src_rgb = [GL_SRC_ALPHA; MAX_DRAW_BUFFERS];
        c.blend_dst_rgb = [GL_ONE; MAX_DRAW_BUFFERS];
        c.blend_src_alpha = [GL_ZERO; MAX_DRAW_BUFFERS];
        c.blend_dst_alpha = [GL_ONE; MAX_DRAW_BUFFERS];
        c.blend_equation_rgb = [GL_FUNC_SUBTRACT; MAX_DRAW_BUFFERS];
        c.blend_equation_alpha = [GL_MAX; MAX_DRAW_BUFFERS];
        c.blend_color = [0.1, 0.2, 0.3, 0.4];
        c.dither = !c.dither;
        c.color_logic_op = !c.color_logic_op;
        c.index_logic_op = !c.index_logic_op;
        c.logic_op = GL_XOR;
        c.draw_buffers[0] = GL_FRONT_LEFT;
        c.clear_color = [1.0, 0.5, 0.25, 2.0];
        c.clear_index = 7.0;
        c.index_mask = 0x3c;
        c.color_mask[1] = [false, true, false, true];
        c.clamp_fragment_color = GL_TRUE as GLenum;
        c.clamp_read_color = GL_FALSE as GLenum;
        let d = &mut t.depth;
        (d.test, d.func, d.write_mask, d.clear) = (!d.test, CompareFunc::Greater, !d.write_mask, 0.5);
        let s = &mut t.stencil;
        (s.test, s.two_side, s.active_face_back, s.clear) = (!s.test, !s.two_side, !s.active_face_back, 9);
        for (face, reference) in [(&mut s.front, 3), (&mut s.back, 4), (&mut s.ext_back, 5)] {
            *face = StencilFace {
                func: CompareFunc::Equal,
                reference,
                value_mask: 0x0f,
                fail: GL_INCR,
                depth_fail: GL_DECR,
                depth_pass: GL_INVERT,
                write_mask: 0xf0,
            };
        }
        t.scissor = ScissorState { test: !t.scissor.test, rect: [1, 2, 3, 4] };
        t.viewport = ViewportState { rect: [5, 6, 7, 8], depth_range: [0.25, 0.5] };
        t.accum.clear = [0.5, -0.5, 0.25, 1.0];
        let h = &mut t.hint;
        h.perspective_correction = GL_NICEST;
        h.point_smooth = GL_NICEST;
        h.line_smooth = GL_FASTEST;
        h.polygon_smooth = GL_NICEST;
        h.fog = GL_FASTEST;
        h.generate_mipmap = GL_NICEST;
        h.texture_compression = GL_FASTEST;
        h.fragment_shader_derivative = GL_NICEST;
        t.fog = FogState {
            enabled: !t.fog.enabled,
            color_sum: !t.fog.color_sum,
            mode: GL_LINEAR,
            density: 0.5,
            start: -1.0,
            end: 9.0,
            index: 3.0,
            color: [0.1, 0.2, 0.3, 0.4],
            coord_src: GL_FOG_COORD,
            distance_mode: GL_EYE_RADIAL_NV,
        };
        let l = &mut t.lighting;
        (l.enabled, l.color_material, l.clamp_vertex_color) = (!l.enabled, !l.color_material, GL_FALSE as GLenum);
        l.lights = [true, false, true, false, true, false, true, true];
        (l.shade_model, l.provoking_vertex) = (GL_FLAT, GL_FIRST_VERTEX_CONVENTION);
        let x = &mut t.transform;
        x.clip_planes = [true; MAX_CLIP_PLANES];
        (x.normalize, x.rescale_normal, x.depth_clamp) = (!x.normalize, !x.rescale_normal, !x.depth_clamp);
        x.clip_plane_equations[3] = [1.0, -2.0, 0.5, 4.0];
        x.matrix_mode = GL_TEXTURE;
        (x.clip_origin, x.clip_depth_mode) = (GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        t.polygon = PolygonState {
            cull_face: true,
            smooth: true,
            stipple: true,
            offset_fill: true,
            offset_line: true,
            offset_point: true,
            cull_face_mode: GL_FRONT_AND_BACK,
            front_face: GL_CW,
            mode_front: GL_POINT,
            mode_back: GL_LINE,
            offset_factor: 2.0,
            offset_units: -1.0,
            offset_clamp: 0.5,
        };
        t.line_point = LinePointState {
            line_smooth: true,
            line_stipple: true,
            point_smooth: true,
            point_sprite: true,
            vertex_program_point_size: true,
            vertex_program_two_side: true,
            line_width: 3.0,
            line_stipple_factor: 7,
            line_stipple_pattern: 0xf0f0,
            point_size: 5.0,
            point_size_min: 2.0,
            point_size_max: 9.0,
            point_fade_threshold: 0.25,
            point_distance_attenuation: [0.5, 1.0, 2.0],
            point_sprite_coord_origin: GL_LOWER_LEFT,
        };
        t.polygon_stipple[5] = 0x1234_5678;
        t.list_base = 77;
        let m = &mut t.multisample;
        (m.enabled, m.alpha_to_coverage, m.alpha_to_one, m.coverage) =
            (!m.enabled, !m.alpha_to_coverage, !m.alpha_to_one, !m.coverage);
        t.texture.active_unit = 2;
        let all = TextureUnitEnables {
            texture_1d: true,
            texture_2d: true,
            texture_3d: true,
            texture_cube_map: true,
            gen: [true; 4],
        };
        t.texture.units = [all; MAX_TEXTURE_COORDS];
        t.eval = EvalState {
            map1: [true; 9],
            map2: [true; 9],
            auto_normal: true,
            grid1_segments: 7,
            grid1_domain: [2.0, 3.0],
            grid2_segments: [4, 5],
            grid2_domain: [1.0, 2.0, 3.0, 4.0],
        };
        t.pixel_mode.read_buffer = GL_FRONT_LEFT;
        t
    }

    /// Copies one group from the original state (second) to the expected state (first).
    type CopyGroup = fn(&mut State, &State);

    /// The state a pop of `mask` must leave after everything was scrambled, written from the
    /// tables of chapter 6 independently of the implementation.
    fn expected_after_pop(mask: u32, original: &State) -> State {
        let o = original;
        let mut e = scrambled(o);
        if mask & GL_ENABLE_BIT != 0 {
            e.color.alpha_test = o.color.alpha_test;
            e.color.blend = o.color.blend;
            e.color.dither = o.color.dither;
            e.color.color_logic_op = o.color.color_logic_op;
            e.color.index_logic_op = o.color.index_logic_op;
            e.depth.test = o.depth.test;
            e.stencil.test = o.stencil.test;
            e.stencil.two_side = o.stencil.two_side;
            e.scissor.test = o.scissor.test;
            (e.fog.enabled, e.fog.color_sum) = (o.fog.enabled, o.fog.color_sum);
            e.lighting.enabled = o.lighting.enabled;
            e.lighting.lights = o.lighting.lights;
            e.lighting.color_material = o.lighting.color_material;
            let (et, ot) = (&mut e.transform, &o.transform);
            (et.clip_planes, et.normalize, et.rescale_normal) = (ot.clip_planes, ot.normalize, ot.rescale_normal);
            et.depth_clamp = ot.depth_clamp;
            let (ep, op) = (&mut e.polygon, &o.polygon);
            (ep.cull_face, ep.smooth, ep.stipple) = (op.cull_face, op.smooth, op.stipple);
            (ep.offset_fill, ep.offset_line, ep.offset_point) = (op.offset_fill, op.offset_line, op.offset_point);
            let (el, ol) = (&mut e.line_point, &o.line_point);
            (el.line_smooth, el.line_stipple, el.point_smooth) = (ol.line_smooth, ol.line_stipple, ol.point_smooth);
            el.point_sprite = ol.point_sprite;
            el.vertex_program_point_size = ol.vertex_program_point_size;
            el.vertex_program_two_side = ol.vertex_program_two_side;
            e.multisample = o.multisample.clone();
            e.texture.units = o.texture.units;
            (e.eval.map1, e.eval.map2, e.eval.auto_normal) = (o.eval.map1, o.eval.map2, o.eval.auto_normal);
        }
        let (el, ol) = (&mut e.line_point, &o.line_point);
        if mask & GL_LINE_BIT != 0 {
            el.line_smooth = ol.line_smooth;
            el.line_stipple = ol.line_stipple;
            el.line_width = ol.line_width;
            el.line_stipple_factor = ol.line_stipple_factor;
            el.line_stipple_pattern = ol.line_stipple_pattern;
        }
        if mask & GL_POINT_BIT != 0 {
            el.point_smooth = ol.point_smooth;
            el.point_sprite = ol.point_sprite;
            el.point_size = ol.point_size;
            el.point_size_min = ol.point_size_min;
            el.point_size_max = ol.point_size_max;
            el.point_fade_threshold = ol.point_fade_threshold;
            el.point_distance_attenuation = ol.point_distance_attenuation;
            el.point_sprite_coord_origin = ol.point_sprite_coord_origin;
        }
        let whole: [(u32, CopyGroup); 18] = [
            (GL_CURRENT_BIT, |e, o| e.current = o.current.clone()),
            (GL_COLOR_BUFFER_BIT, |e, o| e.color = o.color.clone()),
            (GL_DEPTH_BUFFER_BIT, |e, o| e.depth = o.depth.clone()),
            (GL_STENCIL_BUFFER_BIT, |e, o| e.stencil = o.stencil.clone()),
            (GL_SCISSOR_BIT, |e, o| e.scissor = o.scissor.clone()),
            (GL_VIEWPORT_BIT, |e, o| e.viewport = o.viewport.clone()),
            (GL_ACCUM_BUFFER_BIT, |e, o| e.accum = o.accum.clone()),
            (GL_HINT_BIT, |e, o| e.hint = o.hint.clone()),
            (GL_FOG_BIT, |e, o| e.fog = o.fog.clone()),
            (GL_LIGHTING_BIT, |e, o| e.lighting = o.lighting.clone()),
            (GL_TRANSFORM_BIT, |e, o| e.transform = o.transform.clone()),
            (GL_POLYGON_BIT, |e, o| e.polygon = o.polygon.clone()),
            (GL_MULTISAMPLE_BIT, |e, o| e.multisample = o.multisample.clone()),
            (GL_TEXTURE_BIT, |e, o| e.texture = o.texture.clone()),
            (GL_EVAL_BIT, |e, o| e.eval = o.eval.clone()),
            (GL_PIXEL_MODE_BIT, |e, o| e.pixel_mode = o.pixel_mode.clone()),
            (GL_POLYGON_STIPPLE_BIT, |e, o| e.polygon_stipple = o.polygon_stipple),
            (GL_LIST_BIT, |e, o| e.list_base = o.list_base),
        ];
        for (bit, copy) in whole {
            if mask & bit != 0 {
                copy(&mut e, o);
            }
        }
        e
    }

    const GROUPS: [u32; 24] = [
        GL_CURRENT_BIT,
        GL_POINT_BIT,
        GL_LINE_BIT,
        GL_POLYGON_BIT,
        GL_POLYGON_STIPPLE_BIT,
        GL_PIXEL_MODE_BIT,
        GL_LIGHTING_BIT,
        GL_FOG_BIT,
        GL_DEPTH_BUFFER_BIT,
        GL_ACCUM_BUFFER_BIT,
        GL_STENCIL_BUFFER_BIT,
        GL_VIEWPORT_BIT,
        GL_TRANSFORM_BIT,
        GL_ENABLE_BIT,
        GL_COLOR_BUFFER_BIT,
        GL_HINT_BIT,
        GL_EVAL_BIT,
        GL_LIST_BIT,
        GL_TEXTURE_BIT,
        GL_SCISSOR_BIT,
        GL_MULTISAMPLE_BIT,
        0,
        GL_ENABLE_BIT | GL_LINE_BIT | GL_VIEWPORT_BIT,
        GL_LINE_BIT | GL_POINT_BIT | GL_POLYGON_STIPPLE_BIT,
    ];

    #[test]
    fn scrambling_changes_every_group() {
        let o = context().state;
        let t = scrambled(&o);
        assert_ne!(t.current, o.current);
        assert_ne!(t.color, o.color);
        assert_ne!(t.depth, o.depth);
        assert_ne!(t.stencil, o.stencil);
        assert_ne!(t.scissor, o.scissor);
        assert_ne!(t.viewport, o.viewport);
        assert_ne!(t.accum, o.accum);
        assert_ne!(t.hint, o.hint);
        assert_ne!(t.fog, o.fog);
        assert_ne!(t.lighting, o.lighting);
        assert_ne!(t.transform, o.transform);
        assert_ne!(t.polygon, o.polygon);
        assert_ne!(t.line_point, o.line_point);
        assert_ne!(t.multisample, o.multisample);
        assert_ne!(t.texture, o.texture);
        assert_ne!(t.eval, o.eval);
        assert_ne!(t.pixel_mode, o.pixel_mode);
        assert_ne!(t.polygon_stipple, o.polygon_stipple);
        assert_ne!(t.list_base, o.list_base);
        // Every field of the groups with enables outside GL_ENABLE_BIT changed too.
        let only_enables = expected_after_pop(GL_ENABLE_BIT, &o);
        assert_ne!(only_enables.transform, o.transform);
        assert_ne!(only_enables.polygon, o.polygon);
        assert_ne!(only_enables.line_point, o.line_point);
        assert_ne!(only_enables.lighting, o.lighting);
        // Nothing but the scramble itself survives a pop of every group.
        assert_eq!(expected_after_pop(GL_ALL_ATTRIB_BITS, &o), o);
    }

    #[test]
    fn each_group_restores_exactly_its_state() {
        for mask in GROUPS {
            let mut ctx = context();
            ctx.state.color.blend[3] = true;
            ctx.state.texture.units[1].gen[2] = true;
            let original = ctx.state.clone();
            ctx.push_attrib(mask);
            ctx.state = scrambled(&original);
            ctx.pop_attrib();
            assert_eq!(ctx.state, expected_after_pop(mask, &original), "mask {mask:#x}");
            assert_eq!(ctx.take_error(), GL_NO_ERROR);
        }
    }

    #[test]
    fn all_attrib_bits_restore_everything() {
        let mut ctx = context();
        let original = ctx.state.clone();
        ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        ctx.state = scrambled(&original);
        ctx.pop_attrib();
        assert_eq!(ctx.state, original);
    }

    #[test]
    fn enable_bit_restores_every_capability_of_every_unit() {
        let mut ctx = context();
        ctx.state.texture.active_unit = 3;
        ctx.push_attrib(GL_ENABLE_BIT);
        for &cap in CAPABILITIES {
            let on = ctx.is_enabled(cap) != 0;
            ctx.set_capability(cap, !on);
        }
        ctx.state.texture.active_unit = 0;
        ctx.set_capability(GL_TEXTURE_CUBE_MAP, true);
        ctx.pop_attrib();
        // Everything is back to the initial state; the active unit, which is not an enable,
        // stays what it was set to (0) rather than what it was at the push (3). Enabling
        // GL_COLOR_MATERIAL copied the current color into the materials, which stay.
        let mut expected = context().state;
        expected.lighting.materials[0].ambient = ctx.state.current.color;
        expected.lighting.materials[0].diffuse = ctx.state.current.color;
        expected.lighting.materials[1] = expected.lighting.materials[0];
        assert_eq!(ctx.state, expected);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn the_stack_overflows_at_its_depth_and_underflows_when_empty() {
        let mut ctx = context();
        ctx.pop_attrib();
        assert_eq!(ctx.take_error(), GL_STACK_UNDERFLOW);
        for i in 0..MAX_ATTRIB_STACK_DEPTH {
            ctx.state.stencil.clear = i as i32;
            ctx.push_attrib(GL_STENCIL_BUFFER_BIT);
        }
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.state.stencil.clear = 100;
        ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        assert_eq!(ctx.take_error(), GL_STACK_OVERFLOW);
        assert_eq!(ctx.attrib_stack.len(), MAX_ATTRIB_STACK_DEPTH);
        for i in (0..MAX_ATTRIB_STACK_DEPTH).rev() {
            ctx.pop_attrib();
            assert_eq!(ctx.state.stencil.clear, i as i32);
        }
        ctx.pop_attrib();
        assert_eq!(ctx.take_error(), GL_STACK_UNDERFLOW);
        assert_eq!(ctx.state.stencil.clear, 0);
    }

    #[test]
    fn both_stacks_are_illegal_between_begin_and_end() {
        let mut ctx = context();
        ctx.inside_begin_end = true;
        ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert!(ctx.attrib_stack.is_empty());
        ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert!(ctx.client_attrib_stack.is_empty());
        ctx.inside_begin_end = false;
        ctx.push_attrib(0);
        ctx.push_client_attrib(0);
        ctx.inside_begin_end = true;
        ctx.pop_attrib();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.attrib_stack.len(), 1);
        ctx.pop_client_attrib();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.client_attrib_stack.len(), 1);
    }

    #[test]
    fn client_stack_restores_pixel_store_only_for_its_bit() {
        let mut ctx = context();
        ctx.pixel_store.pack.alignment = 2;
        ctx.pixel_store.unpack.row_length = 7;
        let original = ctx.pixel_store.clone();
        ctx.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
        ctx.pixel_store.pack.alignment = 8;
        ctx.pixel_store.unpack.swap_bytes = true;
        ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        ctx.pixel_store.unpack.skip_images = 3;
        let changed = ctx.pixel_store.clone();
        ctx.pop_client_attrib();
        assert_eq!(ctx.pixel_store, changed);
        ctx.pop_client_attrib();
        assert_eq!(ctx.pixel_store, original);
        // The server stack does not hold client state.
        ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        ctx.pixel_store.pack.lsb_first = true;
        ctx.pop_attrib();
        assert!(ctx.pixel_store.pack.lsb_first);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn client_stack_overflows_and_underflows() {
        let mut ctx = context();
        ctx.pop_client_attrib();
        assert_eq!(ctx.take_error(), GL_STACK_UNDERFLOW);
        for _ in 0..MAX_ATTRIB_STACK_DEPTH {
            ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
        }
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
        assert_eq!(ctx.take_error(), GL_STACK_OVERFLOW);
        assert_eq!(ctx.client_attrib_stack.len(), MAX_ATTRIB_STACK_DEPTH);
        assert!(ctx.attrib_stack.is_empty());
    }
}
