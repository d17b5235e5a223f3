//! glAccum and the accumulation buffer clear.
//!
//! The context decides which buffers and which rectangle an operation touches; the arithmetic
//! (Mesa 22's, bit for bit) lives with the storage in [`AccumBuffer`]. The rules, each checked
//! against Mesa 22.3 llvmpipe OSMesa:
//! - an invalid `op` is GL_INVALID_ENUM, a framebuffer without accumulation buffer
//!   GL_INVALID_OPERATION (in that order), and so is a call between glBegin and glEnd;
//! - every operation, and the accumulation clear, is confined to the scissor box when the
//!   scissor test is on; the color write mask does not affect the accumulation clear;
//! - GL_LOAD and GL_ACCUM read the current read buffer (nothing happens when it is GL_NONE);
//! - GL_RETURN writes every current draw buffer (none for GL_NONE), honouring that draw
//!   buffer's color mask, with no other fragment operation, no clamping of float buffers
//!   (Mesa ignores GL_CLAMP_FRAGMENT_COLOR here) and no dithering.
//!
//! Still to do when the rest exists: glAccum is a flush point for deferred rendering (it
//! reads and writes resolved pixels), and Mesa ignores it outside glRenderMode(GL_RENDER).
use super::Context;
use crate::framebuffer::surface::accum_clear_value;
use crate::framebuffer::{AccumBuffer, Rect};
use crate::gl::enums::*;
use crate::gl::types::GLenum;

/// Clears `rect` of the accumulation buffer to `value` (each in [-1, 1]).
pub fn clear(accum: &mut AccumBuffer, rect: Rect, value: [f32; 4]) {
    accum.fill(rect, value.map(accum_clear_value));
}

/// The five glAccum operations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AccumOp {
    Accum,
    Load,
    Return,
    Mult,
    Add,
}

impl AccumOp {
    fn from_gl(op: GLenum) -> Option<AccumOp> {
        Some(match op {
            GL_ACCUM => AccumOp::Accum,
            GL_LOAD => AccumOp::Load,
            GL_RETURN => AccumOp::Return,
            GL_MULT => AccumOp::Mult,
            GL_ADD => AccumOp::Add,
            _ => return None,
        })
    }
}

impl Context {
    /// glAccum.
    pub fn accum(&mut self, op: GLenum, value: f32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(op) = AccumOp::from_gl(op) else {
            return self.error(GL_INVALID_ENUM);
        };
        if self.draw_config().accum_bits == 0 {
            return self.error(GL_INVALID_OPERATION);
        }
        self.flush_rendering();
        // Mesa skips the operations that cannot change anything (truncating a product with 0
        // gives 0 whatever the color, even for NaN and infinities).
        let no_op = match op {
            AccumOp::Add | AccumOp::Accum => value == 0.0,
            AccumOp::Mult => value == 1.0,
            AccumOp::Load | AccumOp::Return => false,
        };
        if no_op {
            return;
        }
        let read_slot = self.current_read_slot();
        let draw_targets = if op == AccumOp::Return { self.draw_targets() } else { Vec::new() };
        let color_masks = self.state.color.color_mask;
        let scissor = self.state.scissor.clone();
        let _ = self.with_framebuffer(|fb| {
            let rect = scissor.clip(fb.bounds());
            if rect.is_empty() {
                return;
            }
            match op {
                AccumOp::Add => {
                    if let Some(accum) = fb.accum_mut() {
                        accum.add(rect, value);
                    }
                }
                AccumOp::Mult => {
                    if let Some(accum) = fb.accum_mut() {
                        accum.multiply(rect, value);
                    }
                }
                AccumOp::Load | AccumOp::Accum => {
                    if let Some((accum, color)) = read_slot.and_then(|slot| fb.accum_and_color_mut(slot)) {
                        accum.load_from(color, rect, value, op == AccumOp::Accum);
                    }
                }
                AccumOp::Return => {
                    for &(slot, index) in &draw_targets {
                        if let Some((accum, color)) = fb.accum_and_color_mut(slot) {
                            accum.return_to(color, rect, value, color_masks[index]);
                        }
                        fb.broadcast_to_samples(slot, rect);
                    }
                }
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::surface::ColorPixels;
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, FramebufferConfig};

    const W: i32 = 4;
    const H: i32 = 2;

    fn context(accum_bits: u32) -> Context {
        let config = FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::None,
            accum_bits,
        );
        Context::with_test_drawable(config, W as usize, H as usize).0
    }

    fn pixels(ctx: &Context) -> Vec<[u8; 4]> {
        ctx.with_window_framebuffer(|fb| match fb.color(ColorSlot::FrontLeft).unwrap().pixels() {
            ColorPixels::Unorm8(px) => px.clone(),
            _ => unreachable!(),
        })
        .unwrap()
    }

    fn accum_values(ctx: &Context) -> Vec<[i16; 4]> {
        ctx.with_window_framebuffer(|fb| fb.accum().unwrap().pixels().to_vec()).unwrap()
    }

    fn clear_color(ctx: &mut Context, rgba: [f32; 4]) {
        ctx.clear_color(rgba);
        ctx.clear(GL_COLOR_BUFFER_BIT);
    }

    #[test]
    fn errors_change_nothing() {
        let mut ctx = context(16);
        ctx.clear_accum([0.5; 4]);
        ctx.clear(GL_ACCUM_BUFFER_BIT);
        ctx.accum(GL_ADD + 1, 1.0);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.inside_begin_end = true;
        ctx.accum(GL_ADD, 0.5);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.accum(GL_ADD + 1, 0.5);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION, "begin/end is checked first");
        ctx.inside_begin_end = false;
        assert_eq!(accum_values(&ctx), vec![[16383; 4]; (W * H) as usize]);

        let mut ctx = context(0);
        ctx.accum(GL_RETURN, 1.0);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.accum(0, 1.0);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM, "the enum is checked before the buffer");
        ctx.accum(GL_ADD, 0.0);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.clear(GL_ACCUM_BUFFER_BIT);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn load_return_round_trip_and_saturation() {
        let mut ctx = context(16);
        clear_color(&mut ctx, [0.2, 0.4, 0.6, 0.8]);
        ctx.accum(GL_LOAD, 1.0);
        clear_color(&mut ctx, [0.0; 4]);
        ctx.accum(GL_RETURN, 1.0);
        assert_eq!(pixels(&ctx)[0], [51, 102, 153, 204]);
        ctx.accum(GL_RETURN, 2.0);
        assert_eq!(pixels(&ctx)[0], [102, 204, 255, 255]);
        ctx.accum(GL_RETURN, -1.0);
        assert_eq!(pixels(&ctx)[0], [0; 4]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn operations_are_confined_to_the_scissor_box() {
        let mut ctx = context(16);
        ctx.clear_accum([1.0; 4]);
        ctx.clear(GL_ACCUM_BUFFER_BIT);
        ctx.set_capability(GL_SCISSOR_TEST, true);
        ctx.scissor(1, 1, 2, 5);
        ctx.clear_accum([-1.0; 4]);
        ctx.color_mask(None, [false; 4]);
        ctx.clear(GL_ACCUM_BUFFER_BIT);
        let acc = accum_values(&ctx);
        assert_eq!(acc[0], [32767; 4]);
        assert_eq!(acc[5], [-32768; 4], "the color mask does not affect the accumulation clear");
        ctx.color_mask(None, [true; 4]);
        ctx.accum(GL_ADD, 0.5);
        ctx.accum(GL_MULT, 0.5);
        let acc = accum_values(&ctx);
        assert_eq!(acc[0], [32767; 4]);
        assert_eq!(acc[5], [-8192; 4], "-8192.5 truncates toward zero");
        ctx.accum(GL_RETURN, -1.0);
        let px = pixels(&ctx);
        assert_eq!(px[4], [0; 4]);
        assert_eq!(px[5], [64; 4]);
        ctx.scissor(0, 0, 0, 0);
        ctx.accum(GL_RETURN, 1.0);
        assert_eq!(pixels(&ctx), px, "an empty box changes nothing");
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn return_honours_mask_and_draw_buffer_load_honours_read_buffer() {
        let mut ctx = context(16);
        ctx.clear_accum([1.0, 0.5, 0.25, 1.0]);
        ctx.clear(GL_ACCUM_BUFFER_BIT);
        clear_color(&mut ctx, [0.2, 0.2, 0.2, 0.2]);
        ctx.color_mask(None, [true, false, true, false]);
        ctx.accum(GL_RETURN, 1.0);
        assert_eq!(pixels(&ctx)[3], [255, 51, 64, 51]);
        ctx.color_mask(None, [true; 4]);

        ctx.draw_buffer(GL_NONE);
        ctx.accum(GL_RETURN, 0.0);
        assert_eq!(pixels(&ctx)[3], [255, 51, 64, 51]);
        ctx.draw_buffer(GL_FRONT);

        ctx.read_buffer(GL_NONE);
        ctx.accum(GL_LOAD, 0.0);
        ctx.accum(GL_ACCUM, 1.0);
        assert_eq!(accum_values(&ctx)[3], [32767, 16383, 8191, 32767]);
        ctx.read_buffer(GL_FRONT);
        ctx.accum(GL_LOAD, 0.0);
        assert_eq!(accum_values(&ctx)[3], [0; 4]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }
}
