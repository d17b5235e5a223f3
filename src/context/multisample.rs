//! Multisampling state: glSampleCoverage, the sample-count queries, and the multisample
//! state a draw compiles into its [`DrawState`](crate::fragment::pipeline::DrawState).
use super::Context;
use crate::fragment::multisample::{sample_coverage_mask, MultisampleState};

impl Context {
    /// glSampleCoverage(value, invert): the value is clamped to [0, 1] (GL 2.1 §4.1.3).
    pub fn sample_coverage(&mut self, value: f32, invert: bool) {
        if self.check_outside_begin_end() {
            let ms = &mut self.state.multisample;
            // NaN clamps to 0, as Mesa's CLAMP does.
            ms.coverage_value = if value.is_nan() { 0.0 } else { value.clamp(0.0, 1.0) };
            ms.coverage_invert = invert;
        }
    }

    /// Samples per pixel of the draw framebuffer (1 without a multisample buffer or drawable).
    pub fn framebuffer_samples(&self) -> usize {
        self.samples_of(self.fbo.draw)
    }

    /// Reads of pixels (glReadPixels, glCopyTexImage) from a multisampled framebuffer
    /// object are GL_INVALID_OPERATION (ARB_framebuffer_object); they need a resolving blit.
    /// A multisampled window reads its resolved image. Returns whether the read may go on.
    pub fn check_read_single_sampled(&mut self) -> bool {
        if self.fbo.read != 0 && self.read_samples() > 1 {
            self.error(crate::gl::enums::GL_INVALID_OPERATION);
            return false;
        }
        true
    }

    /// The multisample state of a draw into a framebuffer of `samples` samples per pixel;
    /// `None` when single-sampled (the multisample operations then do nothing, §4.1.3).
    pub(super) fn multisample_state(&self, samples: usize) -> Option<MultisampleState> {
        if samples <= 1 {
            return None;
        }
        let ms = &self.state.multisample;
        let all = ((1u32 << samples) - 1) as u8;
        Some(MultisampleState {
            samples: samples as u8,
            enabled: ms.enabled,
            alpha_to_coverage: ms.alpha_to_coverage,
            alpha_to_one: ms.alpha_to_one,
            coverage_mask: if ms.coverage {
                sample_coverage_mask(ms.coverage_value, ms.coverage_invert, samples)
            } else {
                all
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::draw::replay::vertex;
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, Drawable, Framebuffer, FramebufferConfig};
    use crate::gl::enums::*;
    use std::sync::{Arc, Mutex};

    /// A context drawing into a `samples`-sample 8×4 framebuffer with window coordinates as
    /// object coordinates.
    fn context(samples: usize) -> (Context, Arc<Mutex<Drawable>>) {
        sized_context(samples, 8, 4)
    }

    fn sized_context(samples: usize, width: usize, height: usize) -> (Context, Arc<Mutex<Drawable>>) {
        let visual = FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            0,
        );
        let framebuffer = Framebuffer::with_samples(visual, width, height, samples).unwrap();
        let drawable = Arc::new(Mutex::new(Drawable::new(framebuffer, None)));
        let mut ctx = Context::new(super::super::ContextConfig { visual });
        ctx.bind_drawable(Some(drawable.clone()));
        ctx.matrix_mode(GL_PROJECTION);
        ctx.ortho(0.0, width as f64, 0.0, height as f64, -1.0, 1.0);
        (ctx, drawable)
    }

    /// A quad from x = 0 to `x1` over the whole height, its depth going from `z0` at x = 0
    /// to `z1` at x = 8 (NDC).
    fn quad(ctx: &mut Context, x1: f32, color: [f32; 4], z0: f32, z1: f32) {
        let z = |x: f32| z0 + (z1 - z0) * x / 8.0;
        let v = |x: f32, y: f32| vertex(x, y, z(x), color);
        ctx.draw_vertices(GL_QUADS, &[v(0.0, 0.0), v(x1, 0.0), v(x1, 4.0), v(0.0, 4.0)]);
    }

    /// Row 1 of the resolved image (red and alpha channels).
    fn row(ctx: &mut Context, d: &Arc<Mutex<Drawable>>) -> Vec<[u8; 2]> {
        ctx.flush_rendering();
        let guard = d.lock().unwrap();
        let crate::framebuffer::surface::ColorPixels::Unorm8(px) =
            guard.framebuffer.color(ColorSlot::FrontLeft).unwrap().pixels()
        else {
            unreachable!()
        };
        px[8..16].iter().map(|p| [p[0], p[3]]).collect()
    }

    const WHITE: [f32; 4] = [1.0; 4];

    #[test]
    fn an_edge_resolves_to_the_fraction_of_covered_samples() {
        // The right edge at x = 2.3 covers, in pixel 2, the samples left of 0.3: of the 4×
        // pattern (x = 0.375, 0.875, 0.125, 0.625) one, so 255/4 → 64; of the 8× pattern
        // (x = 9, 7, 13, 5, 3, 1, 11, 15 sixteenths) 0.0625 and 0.1875: 2/8 → 64; of the 2×
        // (0.75, 0.25) one: 128.
        for (samples, edge) in [(4, 64), (8, 64), (2, 128)] {
            let (mut ctx, d) = context(samples);
            quad(&mut ctx, 2.3, WHITE, 0.0, 0.0);
            let r = row(&mut ctx, &d);
            assert_eq!(r[..4], [[255, 255], [255, 255], [edge, edge], [0, 0]], "{samples} samples");
        }
        assert_eq!(context(4).0.get_integers(GL_SAMPLES), Some(vec![4]));
        assert_eq!(context(4).0.get_integers(GL_SAMPLE_BUFFERS), Some(vec![1]));
        assert_eq!(context(1).0.get_integers(GL_SAMPLE_BUFFERS), Some(vec![0]));
    }

    #[test]
    fn without_gl_multisample_pixel_centres_decide_for_every_sample() {
        let (mut ctx, d) = context(4);
        ctx.set_capability(GL_MULTISAMPLE, false);
        quad(&mut ctx, 2.6, WHITE, 0.0, 0.0);
        assert_eq!(row(&mut ctx, &d)[..4], [[255, 255], [255, 255], [255, 255], [0, 0]]);
    }

    #[test]
    fn sample_coverage_and_alpha_to_coverage_drop_samples() {
        let (mut ctx, d) = context(4);
        ctx.set_capability(GL_SAMPLE_COVERAGE, true);
        ctx.sample_coverage(0.5, false);
        quad(&mut ctx, 8.0, WHITE, 0.0, 0.0);
        assert_eq!(row(&mut ctx, &d)[0], [128, 128]);
        ctx.sample_coverage(0.5, true);
        quad(&mut ctx, 8.0, [0.0, 0.0, 0.0, 0.0], 0.0, 0.0);
        // The inverted mask writes the other two samples.
        assert_eq!(row(&mut ctx, &d)[0], [128, 128]);

        let (mut ctx, d) = context(4);
        ctx.set_capability(GL_SAMPLE_ALPHA_TO_COVERAGE, true);
        // Alpha 0.5 covers samples 0 and 1 (alpha > 0 and > 0.25).
        quad(&mut ctx, 8.0, [1.0, 1.0, 1.0, 0.5], 0.0, 0.0);
        assert_eq!(row(&mut ctx, &d)[0], [128, 64]);
        ctx.set_capability(GL_SAMPLE_ALPHA_TO_ONE, true);
        quad(&mut ctx, 8.0, [1.0, 1.0, 1.0, 0.5], 0.0, 0.0);
        assert_eq!(row(&mut ctx, &d)[0], [128, 128]);
    }

    #[test]
    fn depth_is_tested_at_each_sample() {
        // Window depth x/8 against a cleared 0.3: samples left of x = 2.4 pass, i.e. in pixel
        // 2 those at x = 0.375 and 0.125.
        let (mut ctx, d) = context(4);
        ctx.set_capability(GL_DEPTH_TEST, true);
        ctx.clear_depth(0.3);
        ctx.clear(GL_DEPTH_BUFFER_BIT);
        // glOrtho maps object z to NDC −z.
        quad(&mut ctx, 8.0, WHITE, 1.0, -1.0);
        assert_eq!(row(&mut ctx, &d)[..4], [[255, 255], [255, 255], [128, 128], [0, 0]]);
    }

    #[test]
    fn samples_are_identical_for_any_thread_count() {
        let render = |threads: usize| {
            let (mut ctx, d) = sized_context(4, 150, 140);
            ctx.set_capability(GL_DEPTH_TEST, true);
            ctx.set_capability(GL_BLEND, true);
            ctx.clear(GL_DEPTH_BUFFER_BIT);
            let mut seed = 12345u32;
            let mut rnd = || {
                seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
                (seed >> 8) as f32 / (1 << 24) as f32
            };
            let mut vertices = Vec::new();
            for _ in 0..150 {
                let c = [rnd(), rnd(), rnd(), rnd()];
                vertices.push(vertex(rnd() * 170.0 - 10.0, rnd() * 160.0 - 10.0, rnd() * 2.0 - 1.0, c));
            }
            ctx.blend_func(None, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            ctx.draw_vertices(GL_TRIANGLES, &vertices);
            let scene = ctx.scene.take().unwrap();
            let mut guard = d.lock().unwrap();
            scene.execute_on(&mut guard.framebuffer, threads);
            let (samples, _) = guard.framebuffer.color_samples(ColorSlot::FrontLeft).unwrap();
            let crate::framebuffer::surface::ColorPixels::Unorm8(px) = samples.pixels() else { unreachable!() };
            px.clone()
        };
        let one = render(1);
        assert!(one.iter().any(|p| p[0] != 0));
        for threads in [2, 3] {
            assert!(one == render(threads), "{threads} threads differ");
        }
    }

    #[test]
    fn sample_coverage_state_is_clamped_and_queried() {
        let (mut ctx, _d) = context(4);
        ctx.sample_coverage(1.5, true);
        assert_eq!(ctx.get_floats(GL_SAMPLE_COVERAGE_VALUE), Some(vec![1.0]));
        assert_eq!(ctx.get_integers(GL_SAMPLE_COVERAGE_INVERT), Some(vec![1]));
    }
}
