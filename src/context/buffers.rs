//! Draw and read buffer selection, clears, write masks, scissor, viewport and depth range.
//!
//! GL names color buffers with enums that may denote several buffers at once (GL_FRONT is
//! front-left and front-right); [`slots_of`] expands them to the framebuffer's
//! [`ColorSlot`]s and everything else works on slots.
use super::Context;
use crate::framebuffer::{ColorSlot, FramebufferConfig, Rect};
use crate::gl::enums::*;
use crate::gl::limits::{MAX_DRAW_BUFFERS, MAX_VIEWPORT_DIM};
use crate::gl::types::GLenum;
use crate::setup::jobs::clear::{ClearJob, ColorClear};

/// Aux buffer enums accepted as names (GL_AUX0..GL_AUX3); existence is checked separately.
const MAX_AUX_ENUMS: u32 = 4;

/// The slots an enum names, before filtering by what exists; `None` if not a buffer enum.
fn named_slots(buffer: GLenum) -> Option<&'static [ColorSlot]> {
    use ColorSlot::*;
    Some(match buffer {
        GL_NONE => &[],
        GL_FRONT_LEFT => &[FrontLeft],
        GL_FRONT_RIGHT => &[FrontRight],
        GL_BACK_LEFT => &[BackLeft],
        GL_BACK_RIGHT => &[BackRight],
        GL_FRONT => &[FrontLeft, FrontRight],
        GL_BACK => &[BackLeft, BackRight],
        GL_LEFT => &[FrontLeft, BackLeft],
        GL_RIGHT => &[FrontRight, BackRight],
        GL_FRONT_AND_BACK => &[FrontLeft, FrontRight, BackLeft, BackRight],
        b if b == GL_AUX0 => &[Aux(0)],
        b if b == GL_AUX0 + 1 => &[Aux(1)],
        b if b == GL_AUX0 + 2 => &[Aux(2)],
        b if b == GL_AUX0 + 3 => &[Aux(3)],
        _ => return None,
    })
}

/// Whether a framebuffer of `config` has `slot` (one of [`FramebufferConfig::color_slots`],
/// without building that list: every draw asks).
fn has_slot(config: &FramebufferConfig, slot: ColorSlot) -> bool {
    match slot {
        ColorSlot::FrontLeft => true,
        ColorSlot::BackLeft => config.double_buffered,
        ColorSlot::FrontRight => config.stereo,
        ColorSlot::BackRight => config.stereo && config.double_buffered,
        ColorSlot::Aux(i) => i < config.aux_buffers,
        ColorSlot::Attachment(_) => false,
    }
}

/// The existing slots `buffer` names in a framebuffer of `config`; `None` if not a buffer enum.
pub fn slots_of(config: &FramebufferConfig, buffer: GLenum) -> Option<Vec<ColorSlot>> {
    named_slots(buffer).map(|slots| slots.iter().copied().filter(|&s| has_slot(config, s)).collect())
}

/// The single slot a read buffer enum selects (GL_FRONT reads front-left, ...).
pub fn read_slot(config: &FramebufferConfig, buffer: GLenum) -> Option<ColorSlot> {
    slots_of(config, buffer)?.first().copied()
}

/// Whether `buffer` may be one entry of glDrawBuffers (a single buffer name).
fn is_single_buffer_name(buffer: GLenum) -> bool {
    matches!(buffer, GL_NONE | GL_FRONT_LEFT | GL_FRONT_RIGHT | GL_BACK_LEFT | GL_BACK_RIGHT)
        || (GL_AUX0..GL_AUX0 + MAX_AUX_ENUMS).contains(&buffer)
}

impl Context {
    /// glDrawBuffer.
    pub fn draw_buffer(&mut self, buffer: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if let Err(e) = self.check_draw_buffer_name(buffer, true) {
            return self.error(e);
        }
        let mut draw_buffers = [GL_NONE; MAX_DRAW_BUFFERS];
        draw_buffers[0] = buffer;
        self.state.color.draw_buffers = draw_buffers;
    }

    /// Whether `buffer` may be a draw buffer of the draw framebuffer (`several`: an enum
    /// naming several buffers, as glDrawBuffer accepts); the error otherwise. A framebuffer
    /// object takes GL_NONE and its color attachment points, attached or not.
    fn check_draw_buffer_name(&self, buffer: GLenum, several: bool) -> Result<(), GLenum> {
        let attachment = super::framebuffer_object::attachment_slot(buffer);
        let attachment_enum = (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + 32).contains(&buffer);
        if self.fbo.draw != 0 {
            return match attachment {
                Some(_) => Ok(()),
                None if named_slots(buffer).is_some() || attachment_enum => Err(GL_INVALID_OPERATION),
                None => Err(GL_INVALID_ENUM),
            };
        }
        let Some(slots) = slots_of(&self.config.visual, buffer) else {
            return Err(if attachment_enum { GL_INVALID_OPERATION } else { GL_INVALID_ENUM });
        };
        if !several && !is_single_buffer_name(buffer) {
            return Err(GL_INVALID_OPERATION);
        }
        if buffer != GL_NONE && slots.is_empty() {
            return Err(GL_INVALID_OPERATION);
        }
        Ok(())
    }

    /// glDrawBuffers.
    pub fn draw_buffers(&mut self, buffers: &[GLenum]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if buffers.len() > MAX_DRAW_BUFFERS {
            return self.error(GL_INVALID_VALUE);
        }
        for (i, &b) in buffers.iter().enumerate() {
            if let Err(e) = self.check_draw_buffer_name(b, false) {
                return self.error(e);
            }
            if b != GL_NONE && buffers[..i].contains(&b) {
                return self.error(GL_INVALID_OPERATION);
            }
        }
        let mut draw_buffers = [GL_NONE; MAX_DRAW_BUFFERS];
        draw_buffers[..buffers.len()].copy_from_slice(buffers);
        self.state.color.draw_buffers = draw_buffers;
    }

    /// glReadBuffer.
    pub fn read_buffer(&mut self, buffer: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if self.fbo.read != 0 {
            if super::framebuffer_object::attachment_slot(buffer).is_none() {
                let known = named_slots(buffer).is_some()
                    || (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + 32).contains(&buffer);
                return self.error(if known { GL_INVALID_OPERATION } else { GL_INVALID_ENUM });
            }
            self.state.pixel_mode.read_buffer = buffer;
            return;
        }
        if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + 32).contains(&buffer) {
            return self.error(GL_INVALID_OPERATION);
        }
        if buffer == GL_FRONT_AND_BACK || named_slots(buffer).is_none() {
            return self.error(GL_INVALID_ENUM);
        }
        if buffer != GL_NONE && read_slot(&self.config.visual, buffer).is_none() {
            return self.error(GL_INVALID_OPERATION);
        }
        self.state.pixel_mode.read_buffer = buffer;
    }

    /// The slot glReadPixels/glAccum read from, if the read buffer names an existing one.
    pub fn current_read_slot(&self) -> Option<ColorSlot> {
        self.read_slot_of(self.state.pixel_mode.read_buffer)
    }

    /// Every (slot, draw buffer index) a fragment or clear writes to.
    pub fn draw_targets(&self) -> Vec<(ColorSlot, usize)> {
        let mut targets = Vec::with_capacity(4);
        for (index, &buffer) in self.state.color.draw_buffers.iter().enumerate() {
            if buffer == GL_NONE {
                continue;
            }
            if self.fbo.draw == 0 {
                // The window's buffers, listed without building a vector per draw buffer.
                let config = &self.config.visual;
                let slots = named_slots(buffer).unwrap_or_default().iter();
                targets.extend(slots.filter(|&&s| has_slot(config, s)).map(|&s| (s, index)));
            } else {
                targets.extend(self.draw_slots(buffer).unwrap_or_default().into_iter().map(|s| (s, index)));
            }
        }
        targets
    }

    /// The rectangle clears and fragments are confined to: the framebuffer, cut by the
    /// scissor box when the scissor test is on.
    pub fn clip_rect(&self, bounds: Rect) -> Rect {
        self.state.scissor.clip(bounds)
    }

    /// glClear.
    pub fn clear(&mut self, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !known != 0 {
            return self.error(GL_INVALID_VALUE);
        }
        // Selection and feedback modes write no pixels (as Mesa).
        if !self.rendering() {
            return;
        }
        if !self.check_framebuffer_complete(true) {
            return;
        }
        // A single-sampled clear without the accumulation buffer is recorded in the scene and
        // applied by each tile's worker (`setup::jobs::clear`); the others run at once, after
        // the draws recorded before them.
        if mask & GL_ACCUM_BUFFER_BIT == 0 && self.samples_of(self.fbo.draw) == 1 {
            return self.record_clear_job(mask);
        }
        self.flush_rendering();
        let targets = self.draw_targets();
        let color = &self.state.color;
        let clear_color = color.clear_color;
        let color_masks = color.color_mask;
        let depth = (self.state.depth.write_mask, self.state.depth.clear);
        let stencil = (self.state.stencil.front.write_mask, self.state.stencil.clear);
        let accum_clear = self.state.accum.clear;
        let scissor = self.state.scissor.clone();
        let _ = self.with_framebuffer(|fb| {
            let rect = scissor.clip(fb.bounds());
            if rect.is_empty() {
                return;
            }
            if mask & GL_COLOR_BUFFER_BIT != 0 {
                for &(slot, index) in &targets {
                    let Some(format) = fb.color_format(slot) else { continue };
                    // ARB_color_buffer_float: fragment color clamping does not apply to
                    // clears; only fixed-point buffers clamp the clear color (as Mesa).
                    let value = if !format.is_float() { clear_color.map(|c| c.clamp(0.0, 1.0)) } else { clear_color };
                    if let Some(buffer) = fb.color_mut(slot) {
                        buffer.clear(rect, value, color_masks[index]);
                    }
                    fb.clear_color_samples(slot, rect, value, color_masks[index]);
                }
            }
            let (clear_depth, clear_stencil) =
                (mask & GL_DEPTH_BUFFER_BIT != 0 && depth.0, mask & GL_STENCIL_BUFFER_BIT != 0);
            if clear_depth && clear_stencil {
                fb.depth_stencil_mut().clear_depth_and_stencil(rect, depth.1, stencil.1 as u8, stencil.0 as u8);
            } else if clear_depth {
                fb.depth_stencil_mut().clear_depth(rect, depth.1);
            } else if clear_stencil {
                fb.depth_stencil_mut().clear_stencil(rect, stencil.1 as u8, stencil.0 as u8);
            }
            if clear_depth {
                fb.clear_depth_samples(rect, depth.1);
            }
            if clear_stencil {
                fb.clear_stencil_samples(rect, stencil.1 as u8, stencil.0 as u8);
            }
            if mask & GL_ACCUM_BUFFER_BIT != 0 {
                if let Some(accum) = fb.accum_mut() {
                    super::accum::clear(accum, rect, accum_clear);
                }
            }
        });
    }

    /// Records glClear(`mask`) (color, depth and stencil bits only) in the scene as a color
    /// job and a depth/stencil job, with the values and masks of the current state.
    fn record_clear_job(&mut self, mask: u32) {
        let Some((width, height, _)) = self.framebuffer_shape(true) else {
            return;
        };
        let bounds = Rect::from_xywh(0, 0, width as i32, height as i32);
        let rect = self.state.scissor.clip(bounds);
        if rect.is_empty() {
            return;
        }
        let whole = rect == bounds;
        let mut colors = Vec::new();
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            let clear_color = self.state.color.clear_color;
            for (slot, index) in self.draw_targets() {
                let mask = self.state.color.color_mask[index];
                if mask.iter().any(|&m| m) {
                    colors.push(ColorClear { slot, color: clear_color, mask });
                }
            }
        }
        let depth = (mask & GL_DEPTH_BUFFER_BIT != 0 && self.state.depth.write_mask).then_some(self.state.depth.clear);
        let stencil = (mask & GL_STENCIL_BUFFER_BIT != 0)
            .then_some((self.state.stencil.clear as u8, self.state.stencil.front.write_mask as u8));
        if !colors.is_empty() {
            self.record_clear(ClearJob { rect, whole, colors, depth: None, stencil: None });
        }
        if depth.is_some() || stencil.is_some() {
            self.record_clear(ClearJob { rect, whole, colors: Vec::new(), depth, stencil });
        }
    }

    /// glColorMask (all draw buffers) or glColorMaski (`index`).
    pub fn color_mask(&mut self, index: Option<u32>, mask: [bool; 4]) {
        if !self.check_outside_begin_end() {
            return;
        }
        match index {
            None => self.state.color.color_mask = [mask; MAX_DRAW_BUFFERS],
            Some(i) => match self.state.color.color_mask.get_mut(i as usize) {
                Some(m) => *m = mask,
                None => self.error(GL_INVALID_VALUE),
            },
        }
    }

    /// glScissor.
    pub fn scissor(&mut self, x: i32, y: i32, width: i32, height: i32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        self.state.scissor.rect = [x, y, width, height];
    }

    /// glViewport: negative sizes are GL_INVALID_VALUE; sizes clamp to the maximum.
    pub fn viewport(&mut self, x: i32, y: i32, width: i32, height: i32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        self.state.viewport.rect = [x, y, width.min(MAX_VIEWPORT_DIM), height.min(MAX_VIEWPORT_DIM)];
    }

    /// glDepthRange: both values clamp to [0, 1].
    pub fn depth_range(&mut self, near: f64, far: f64) {
        if !self.check_outside_begin_end() {
            return;
        }
        self.state.viewport.depth_range = [clamp01(near), clamp01(far)];
    }

    /// glClearColor (values are kept unclamped: float buffers may store them as given).
    pub fn clear_color(&mut self, rgba: [f32; 4]) {
        if self.check_outside_begin_end() {
            self.state.color.clear_color = rgba;
        }
    }

    /// glClearDepth: clamped to [0, 1].
    pub fn clear_depth(&mut self, depth: f64) {
        if self.check_outside_begin_end() {
            self.state.depth.clear = clamp01(depth);
        }
    }

    /// glClearStencil.
    pub fn clear_stencil(&mut self, value: i32) {
        if self.check_outside_begin_end() {
            self.state.stencil.clear = value;
        }
    }

    /// glClearAccum: clamped to [-1, 1].
    pub fn clear_accum(&mut self, rgba: [f32; 4]) {
        if self.check_outside_begin_end() {
            self.state.accum.clear = rgba.map(|c| if c.is_nan() { 0.0 } else { c.clamp(-1.0, 1.0) });
        }
    }

    /// glClearIndex (color-index state; kept for glGet and attribute stacks).
    pub fn clear_index(&mut self, index: f32) {
        if self.check_outside_begin_end() {
            self.state.color.clear_index = index;
        }
    }

    /// glIndexMask.
    pub fn index_mask(&mut self, mask: u32) {
        if self.check_outside_begin_end() {
            self.state.color.index_mask = mask;
        }
    }

    /// glDepthMask.
    pub fn depth_mask(&mut self, on: bool) {
        if self.check_outside_begin_end() {
            self.state.depth.write_mask = on;
        }
    }

    /// glStencilMask (`face` GL_FRONT_AND_BACK) and glStencilMaskSeparate.
    pub fn stencil_mask(&mut self, face: GLenum, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let stencil = &mut self.state.stencil;
        match face {
            GL_FRONT => stencil.front.write_mask = mask,
            GL_BACK => stencil.back.write_mask = mask,
            GL_FRONT_AND_BACK => {
                stencil.front.write_mask = mask;
                stencil.back.write_mask = mask;
            }
            _ => self.error(GL_INVALID_ENUM),
        }
    }
}

/// Clamps to [0, 1]; NaN becomes 0.
fn clamp01(v: f64) -> f64 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, Drawable};
    use std::sync::{Arc, Mutex};

    /// A double-buffered stereo context with two aux buffers, bound to a 4×4 drawable.
    fn stereo_context() -> (Context, Arc<Mutex<Drawable>>) {
        let visual = FramebufferConfig {
            color: ColorFormat::Unorm8 { alpha: true },
            double_buffered: true,
            stereo: true,
            aux_buffers: 2,
            depth_stencil: DepthStencilFormat::Packed24 { depth: true, stencil: true },
            accum_bits: 16,
        };
        Context::with_test_drawable(visual, 4, 4)
    }

    fn pixel(d: &Arc<Mutex<Drawable>>, slot: ColorSlot, x: i32, y: i32) -> [f32; 4] {
        let mut out = Vec::new();
        d.lock().unwrap().framebuffer.color(slot).unwrap().read_row_f32(y, x, x + 1, &mut out);
        out[0]
    }

    #[test]
    fn enums_expand_to_the_buffers_they_name() {
        let (ctx, _) = stereo_context();
        let visual = ctx.config().visual;
        use ColorSlot::*;
        assert_eq!(slots_of(&visual, GL_FRONT).unwrap(), vec![FrontLeft, FrontRight]);
        assert_eq!(slots_of(&visual, GL_LEFT).unwrap(), vec![FrontLeft, BackLeft]);
        assert_eq!(slots_of(&visual, GL_FRONT_AND_BACK).unwrap().len(), 4);
        assert_eq!(slots_of(&visual, GL_AUX1).unwrap(), vec![Aux(1)]);
        assert_eq!(slots_of(&visual, GL_AUX2).unwrap(), vec![]);
        assert_eq!(read_slot(&visual, GL_RIGHT), Some(FrontRight));
        assert_eq!(slots_of(&visual, GL_DEPTH_TEST), None);
    }

    #[test]
    fn double_buffered_contexts_draw_and_read_the_back_buffer() {
        let (ctx, _) = stereo_context();
        assert_eq!(ctx.state.color.draw_buffers[0], GL_BACK);
        assert_eq!(ctx.state.pixel_mode.read_buffer, GL_BACK);
        assert_eq!(ctx.current_read_slot(), Some(ColorSlot::BackLeft));
    }

    #[test]
    fn clear_writes_exactly_the_selected_buffers() {
        let (mut ctx, d) = stereo_context();
        ctx.draw_buffer(GL_RIGHT);
        ctx.clear_color([1.0, 0.0, 0.0, 1.0]);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.flush_rendering();
        assert_eq!(pixel(&d, ColorSlot::FrontRight, 0, 0), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(pixel(&d, ColorSlot::BackRight, 3, 3), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(pixel(&d, ColorSlot::FrontLeft, 0, 0), [0.0; 4]);
        assert_eq!(pixel(&d, ColorSlot::Aux(0), 0, 0), [0.0; 4]);
    }

    #[test]
    fn draw_buffers_apply_each_outputs_color_mask() {
        let (mut ctx, d) = stereo_context();
        ctx.draw_buffers(&[GL_AUX0, GL_BACK_LEFT]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.color_mask(Some(1), [false, true, false, true]);
        ctx.clear_color([1.0, 1.0, 1.0, 1.0]);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        assert_eq!(pixel(&d, ColorSlot::Aux(0), 1, 1), [1.0; 4]);
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 1, 1), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(pixel(&d, ColorSlot::FrontLeft, 1, 1), [0.0; 4]);
    }

    #[test]
    fn invalid_buffer_selections_are_errors_that_change_nothing() {
        let (mut ctx, _) = stereo_context();
        ctx.draw_buffer(GL_DEPTH_TEST);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.draw_buffer(GL_AUX3);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.draw_buffers(&[GL_AUX0, GL_AUX0]);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.draw_buffers(&[GL_FRONT]);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.draw_buffers(&[GL_NONE; MAX_DRAW_BUFFERS + 1]);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.read_buffer(GL_FRONT_AND_BACK);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.color.draw_buffers[0], GL_BACK);
        assert_eq!(ctx.state.pixel_mode.read_buffer, GL_BACK);
    }

    #[test]
    fn scissored_clears_touch_only_the_box() {
        let (mut ctx, d) = stereo_context();
        ctx.set_capability(GL_SCISSOR_TEST, true);
        ctx.scissor(1, 1, 2, 2);
        ctx.clear_color([0.0, 0.0, 1.0, 1.0]);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 1, 2), [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 0, 0), [0.0; 4]);
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 3, 1), [0.0; 4]);
        ctx.clear(0x8000_0000);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn clears_wait_in_the_scene_until_a_flush_point() {
        let (mut ctx, d) = stereo_context();
        ctx.clear_color([0.0, 1.0, 0.0, 1.0]);
        ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 2, 2), [0.0; 4], "recorded, not yet applied");
        ctx.set_capability(GL_SCISSOR_TEST, true);
        ctx.scissor(0, 0, 1, 1);
        ctx.clear_color([1.0, 0.0, 0.0, 1.0]);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.flush_rendering();
        // Applied in order: the scissored clear after the whole one.
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 0, 0), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 2, 2), [0.0, 1.0, 0.0, 1.0]);
        let fb = &d.lock().unwrap().framebuffer;
        assert_eq!(fb.depth_stencil().depth_value(5), 0x00ff_ffff, "depth cleared to 1.0");
        assert_eq!(fb.depth_stencil().stencil_value(5), 0);
    }

    #[test]
    fn a_covering_draw_drops_the_color_clear_and_keeps_depth_and_stencil() {
        let (mut ctx, d) = stereo_context();
        ctx.clear_color([0.0, 1.0, 0.0, 1.0]);
        ctx.clear_stencil(5);
        ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        ctx.set_color([1.0, 0.0, 0.0, 1.0]);
        // One triangle covering the whole tile (a quad's halves cover only part of it each).
        ctx.begin(GL_TRIANGLES);
        for [x, y] in [[-1.0, -1.0], [3.0, -1.0], [-1.0, 3.0]] {
            ctx.vertex([x, y, 0.0, 1.0]);
        }
        ctx.end();
        ctx.flush_rendering();
        assert_eq!(pixel(&d, ColorSlot::BackLeft, 0, 3), [1.0, 0.0, 0.0, 1.0]);
        let fb = &d.lock().unwrap().framebuffer;
        for i in [0, 5, 15] {
            assert_eq!(fb.depth_stencil().depth_value(i), 0x00ff_ffff);
            assert_eq!(fb.depth_stencil().stencil_value(i), 5);
        }
    }

    /// A presenter that shows nothing and, like an OSMesa buffer, is drawn into by one
    /// context only.
    struct PrivateSink;
    impl crate::framebuffer::Present for PrivateSink {
        fn present(&mut self, _: &crate::framebuffer::Framebuffer) {}
        fn private(&self) -> bool {
            true
        }
    }

    fn depth_word(d: &Arc<Mutex<Drawable>>, i: usize) -> u32 {
        let fb = &d.lock().unwrap().framebuffer;
        fb.depth_stencil().depth_value(i) | (fb.depth_stencil().stencil_value(i) as u32) << 24
    }

    #[test]
    fn a_whole_depth_clear_waits_for_the_first_use_of_depth_or_a_reader() {
        use crate::context::ContextConfig;
        use crate::framebuffer::Framebuffer;
        let visual = FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            0,
        );
        let private = |sink: bool| {
            let fb = Framebuffer::new(visual, 4, 4).unwrap();
            let presenter: Option<Box<dyn crate::framebuffer::Present>> =
                if sink { Some(Box::new(PrivateSink)) } else { None };
            let d = Arc::new(Mutex::new(Drawable::new(fb, presenter)));
            let mut ctx = Context::new(ContextConfig { visual });
            ctx.bind_drawable(Some(d.clone()));
            (ctx, d)
        };
        let (mut ctx, d) = private(true);
        // glFinish keeps it: the fresh buffer's pages stay untouched (zero).
        ctx.clear_depth(0.5);
        ctx.clear_stencil(3);
        ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        ctx.finish();
        assert_eq!(depth_word(&d, 5), 0, "carried across glFinish");
        // A draw without depth or stencil test leaves it carried.
        ctx.set_color([1.0, 0.0, 0.0, 1.0]);
        let triangle = |ctx: &mut Context, z: f32| {
            ctx.begin(GL_TRIANGLES);
            for [x, y] in [[-1.0, -1.0], [3.0, -1.0], [-1.0, 3.0]] {
                ctx.vertex([x, y, z, 1.0]);
            }
            ctx.end();
        };
        triangle(&mut ctx, 0.0);
        ctx.finish();
        assert_eq!(depth_word(&d, 5), 0);
        // A reader (every reader flushes first) sees the cleared values.
        ctx.flush_rendering();
        let half = crate::framebuffer::surface::depth_clear_value(visual.depth_stencil, true, 0.5);
        assert_eq!(depth_word(&d, 5), 0x0300_0000 | half, "depth 0.5, stencil 3");
        // A depth-tested draw after a carried clear sees the clear, not what was there:
        // depth 0.5 is in the buffer, the carried clear says 0.25, and GL_GREATER at 0.4
        // (z = −0.2) passes only against the carried value.
        ctx.clear_depth(0.25);
        ctx.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        ctx.finish();
        assert_eq!(depth_word(&d, 5), 0x0300_0000 | half, "still carried");
        ctx.set_capability(GL_DEPTH_TEST, true);
        ctx.depth_func(GL_GREATER);
        ctx.set_color([0.0, 0.0, 1.0, 1.0]);
        triangle(&mut ctx, -0.2);
        ctx.finish();
        assert_eq!(pixel(&d, ColorSlot::FrontLeft, 2, 1), [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(depth_word(&d, 5) >> 24, 3, "the stencil clear applied with it");
        // A partial clear comes after the carried whole one.
        ctx.set_capability(GL_DEPTH_TEST, false);
        ctx.clear_stencil(7);
        ctx.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        ctx.set_capability(GL_SCISSOR_TEST, true);
        ctx.scissor(0, 0, 1, 1);
        ctx.clear_stencil(9);
        ctx.clear(GL_STENCIL_BUFFER_BIT);
        ctx.flush_rendering();
        assert_eq!(depth_word(&d, 0) >> 24, 9);
        assert_eq!(depth_word(&d, 5) >> 24, 7);
        // Once the caller holds the depth buffer's address (OSMesaGetDepthBuffer), glFinish
        // leaves it complete.
        ctx.set_capability(GL_SCISSOR_TEST, false);
        let _ = d.lock().unwrap().lend_depth_stencil();
        ctx.clear_depth(1.0);
        ctx.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        ctx.finish();
        assert_eq!(depth_word(&d, 5), 0x0900_0000 | 0x00ff_ffff, "the last clear stencil value, 9");
        // A framebuffer other contexts may draw into is cleared at glFinish as before.
        let (mut ctx, d) = private(false);
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        ctx.finish();
        assert_eq!(depth_word(&d, 5), 0x00ff_ffff);
    }
}
