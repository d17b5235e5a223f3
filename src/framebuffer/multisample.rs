//! Multisample storage and its resolve: 2, 4 or 8 samples per pixel.
//!
//! A multisampled layer of `width` × `height` pixels with `S` samples is an ordinary layer
//! of `width` × `height·S` storage rows: storage row `y·S + s` holds sample `s` of pixel row
//! `y`. So the samples of a pixel row are `S` consecutive rows, a band of whole pixel rows is
//! one contiguous slice holding every sample of its pixels ("tiles still own pixels": the
//! binner and the thread pool work unchanged), and the fragment operations, written for
//! spans of consecutive pixels, run unchanged on one sample of a span at a time.
//!
//! A multisampled [`Framebuffer`] keeps its single-sample layers too: they hold the
//! *resolved* image (each pixel the average of its samples, depth and stencil those of
//! sample 0), written after every scene and every clear, so that everything reading the
//! framebuffer (glReadPixels, glCopyPixels, glCopyTexImage, glAccum, presentation) reads the
//! resolved image without knowing about samples.
use super::surface::{ColorBuffer, ColorPixels, DepthStencilBuffer, DepthStencilPixels};
use super::{ColorFormat, ColorSlot, DepthStencilFormat, Framebuffer, FramebufferConfig, OutOfMemory, Rect};

/// The sample counts a multisampled layer may have.
pub const SAMPLE_COUNTS: [usize; 3] = [2, 4, 8];

/// The largest number of samples per pixel (GL_MAX_SAMPLES).
pub const MAX_SAMPLES: usize = 8;

/// The smallest supported sample count of at least `requested` (0 and 1: single-sampled,
/// returned as 1); `None` above [`MAX_SAMPLES`].
pub fn supported_samples(requested: usize) -> Option<usize> {
    if requested <= 1 {
        return Some(1);
    }
    SAMPLE_COUNTS.iter().copied().find(|&s| s >= requested)
}

impl Rect {
    /// The storage rows of this pixel rectangle in a layer of `samples` samples per pixel.
    pub fn sample_rows(self, samples: usize) -> Rect {
        let s = samples as i32;
        Rect { x0: self.x0, y0: self.y0 * s, x1: self.x1, y1: self.y1 * s }
    }
}

/// The multisampled layers of a framebuffer (storage rows as the module says).
pub(super) struct SampleLayers {
    pub(super) samples: usize,
    pub(super) color: Vec<(ColorSlot, ColorBuffer)>,
    pub(super) depth_stencil: DepthStencilBuffer,
}

impl SampleLayers {
    pub(super) fn new(
        config: &FramebufferConfig,
        width: usize,
        height: usize,
        samples: usize,
    ) -> Result<SampleLayers, OutOfMemory> {
        let rows = height.checked_mul(samples).ok_or(OutOfMemory)?;
        let pixels = width.checked_mul(rows).ok_or(OutOfMemory)?;
        let mut color = Vec::new();
        for slot in config.color_slots() {
            color.push((slot, ColorBuffer::new(config.color, width, rows, pixels)?));
        }
        let depth_stencil = DepthStencilBuffer::new(config.depth_stencil, width, pixels)?;
        Ok(SampleLayers { samples, color, depth_stencil })
    }
}

/// Averages the samples of pixel rows `[y0, y1)` of `samples` (a layer of `count` samples
/// per pixel) into the same rows of `resolved`, which has the same width and format.
/// Fixed-point channels round the average to nearest, float channels average in f32.
pub fn resolve_color(samples: &ColorBuffer, count: usize, resolved: &mut ColorBuffer, rect: Rect) {
    if rect.is_empty() {
        return;
    }
    let (x0, n) = (rect.x0 as usize, rect.width());
    for y in rect.y0 as usize..rect.y1 as usize {
        resolve_color_span(samples, count, (x0, y), resolved, (x0, y), n);
    }
}

/// Averages the samples of the `n` pixels from `(sx, sy)` of `samples` (a layer of `count`
/// samples per pixel) into the `n` pixels from `(dx, dy)` of `resolved` (single-sampled, of
/// the same format; nothing is written for another format), as [`resolve_color`] does.
pub fn resolve_color_span(
    samples: &ColorBuffer,
    count: usize,
    (sx, sy): (usize, usize),
    resolved: &mut ColorBuffer,
    (dx, dy): (usize, usize),
    n: usize,
) {
    let (width, out_width) = (samples.width(), resolved.width());
    let row = |s: usize| (sy * count + s) * width + sx;
    let out = dy * out_width + dx;
    match (samples.pixels(), resolved.pixels_mut()) {
        (ColorPixels::Unorm8(src), ColorPixels::Unorm8(dst)) => {
            for (x, d) in dst[out..out + n].iter_mut().enumerate() {
                *d = average_unorm((0..count).map(|s| src[row(s) + x].map(u32::from)), count).map(|c| c as u8);
            }
        }
        (ColorPixels::Unorm16(src), ColorPixels::Unorm16(dst)) => {
            for (x, d) in dst[out..out + n].iter_mut().enumerate() {
                *d = average_unorm((0..count).map(|s| src[row(s) + x].map(u32::from)), count).map(|c| c as u16);
            }
        }
        (ColorPixels::Rgb565(src), ColorPixels::Rgb565(dst)) => {
            for (x, d) in dst[out..out + n].iter_mut().enumerate() {
                let channels = (0..count).map(|s| {
                    let p = src[row(s) + x] as u32;
                    [p >> 11, (p >> 5) & 63, p & 31, 0]
                });
                let [r, g, b, _] = average_unorm(channels, count);
                *d = ((r << 11) | (g << 5) | b) as u16;
            }
        }
        (ColorPixels::Float32(src), ColorPixels::Float32(dst)) => {
            let scale = 1.0 / count as f32;
            for (x, d) in dst[out..out + n].iter_mut().enumerate() {
                let mut sum = [0.0f32; 4];
                for s in 0..count {
                    for (a, v) in sum.iter_mut().zip(src[row(s) + x]) {
                        *a += v;
                    }
                }
                *d = sum.map(|a| a * scale);
            }
        }
        _ => {}
    }
}

/// The rounded average of `count` 4-channel values (`(sum + count/2) / count`).
#[inline]
fn average_unorm(values: impl Iterator<Item = [u32; 4]>, count: usize) -> [u32; 4] {
    let mut sum = [0u32; 4];
    for v in values {
        for (a, c) in sum.iter_mut().zip(v) {
            *a += c;
        }
    }
    let half = count as u32 / 2;
    if count.is_power_of_two() {
        // The usual sample counts (2, 4, 8): a shift, not four divisions per pixel.
        let shift = count.trailing_zeros();
        sum.map(|a| (a + half) >> shift)
    } else {
        sum.map(|a| (a + half) / count as u32)
    }
}

/// Copies sample 0's depth and stencil of pixel rows `[y0, y1)` into `resolved` (GL leaves
/// which sample a single-sample read of depth returns to the implementation; Mesa reads
/// sample 0 too).
pub fn resolve_depth_stencil(
    samples: &DepthStencilBuffer,
    count: usize,
    resolved: &mut DepthStencilBuffer,
    rect: Rect,
) {
    if rect.is_empty() {
        return;
    }
    let width = resolved.width();
    let (x0, x1) = (rect.x0 as usize, rect.x1 as usize);
    for y in rect.y0 as usize..rect.y1 as usize {
        let from = y * count * width;
        let to = y * width;
        let (src, dst) = (from + x0..from + x1, to + x0..to + x1);
        match (samples.pixels(), resolved.pixels_mut()) {
            (DepthStencilPixels::Depth16(s), DepthStencilPixels::Depth16(d)) => d[dst].copy_from_slice(&s[src]),
            (DepthStencilPixels::Packed24(s), DepthStencilPixels::Packed24(d)) => d[dst].copy_from_slice(&s[src]),
            (DepthStencilPixels::Depth32(s, ss), DepthStencilPixels::Depth32(d, ds)) => {
                d[dst.clone()].copy_from_slice(&s[src.clone()]);
                if let (Some(ss), Some(ds)) = (ss, ds) {
                    ds[dst].copy_from_slice(&ss[src]);
                }
            }
            _ => return,
        }
    }
}

/// Writes pixel rows `[y0, y1)` of `resolved` into every sample of the same pixels of
/// `samples` (for writes that bypass the rasterizer, such as glAccum's GL_RETURN).
pub fn broadcast_color(resolved: &ColorBuffer, count: usize, samples: &mut ColorBuffer, rect: Rect) {
    fn copy<T: Copy>(src: &[T], dst: &mut [T], width: usize, count: usize, rect: Rect) {
        let (x0, x1) = (rect.x0 as usize, rect.x1 as usize);
        for y in rect.y0 as usize..rect.y1 as usize {
            for s in 0..count {
                let to = (y * count + s) * width;
                dst[to + x0..to + x1].copy_from_slice(&src[y * width + x0..y * width + x1]);
            }
        }
    }
    if rect.is_empty() {
        return;
    }
    let width = samples.width();
    match (resolved.pixels(), samples.pixels_mut()) {
        (ColorPixels::Unorm8(s), ColorPixels::Unorm8(d)) => copy(s, d, width, count, rect),
        (ColorPixels::Unorm16(s), ColorPixels::Unorm16(d)) => copy(s, d, width, count, rect),
        (ColorPixels::Rgb565(s), ColorPixels::Rgb565(d)) => copy(s, d, width, count, rect),
        (ColorPixels::Float32(s), ColorPixels::Float32(d)) => copy(s, d, width, count, rect),
        _ => {}
    }
}

impl Framebuffer {
    /// A framebuffer whose color and depth/stencil layers have `samples` samples per pixel
    /// (1: an ordinary one; otherwise one of [`SAMPLE_COUNTS`]), zero-filled.
    pub fn with_samples(
        config: FramebufferConfig,
        width: usize,
        height: usize,
        samples: usize,
    ) -> Result<Framebuffer, OutOfMemory> {
        let mut framebuffer = Framebuffer::new(config, width, height)?;
        if samples > 1 {
            framebuffer.multisample = Some(SampleLayers::new(&config, width, height, samples)?);
        }
        Ok(framebuffer)
    }

    /// A `width` × `height` framebuffer of `samples` samples per pixel made of multisampled
    /// layers (`height · samples` storage rows each) owned elsewhere (multisampled
    /// renderbuffers). It has no resolved layers: rendering and clears reach the samples,
    /// reads of the image go through a resolve ([`resolve_color`]).
    pub fn from_sample_layers(
        config: FramebufferConfig,
        width: usize,
        height: usize,
        samples: usize,
        color: Vec<(ColorSlot, ColorBuffer)>,
        depth_stencil: Option<DepthStencilBuffer>,
    ) -> Framebuffer {
        let none =
            || DepthStencilBuffer::new(DepthStencilFormat::None, width, 0).expect("an empty buffer allocates nothing");
        let depth_stencil = depth_stencil.unwrap_or_else(none);
        Framebuffer {
            config,
            width,
            height,
            color: Vec::new(),
            depth_stencil: none(),
            accum: None,
            multisample: Some(SampleLayers { samples, color, depth_stencil }),
            in_place_front: None,
        }
    }

    /// The format of color buffer `slot`, resolved or multisampled.
    pub fn color_format(&self, slot: ColorSlot) -> Option<ColorFormat> {
        let sampled = self.multisample.as_ref().and_then(|l| l.color.iter().find(|(s, _)| *s == slot));
        self.color.iter().find(|(s, _)| *s == slot).or(sampled).map(|(_, b)| b.format())
    }

    /// The format of color buffer `slot` as the bands render into it (its multisampled
    /// layer's when multisampled; `None` when the bands have no such target).
    pub fn band_color_format(&self, slot: ColorSlot) -> Option<ColorFormat> {
        match &self.multisample {
            Some(layers) => layers.color.iter().find(|(s, _)| *s == slot).map(|(_, b)| b.format()),
            None => self.color.iter().find(|(s, _)| *s == slot).map(|(_, b)| b.format()),
        }
    }

    /// The format of the depth/stencil layer the bands render into: the multisampled one's
    /// when multisampled (a framebuffer object of multisampled attachments has no resolved
    /// depth/stencil layer).
    pub fn band_depth_stencil_format(&self) -> DepthStencilFormat {
        match &self.multisample {
            Some(layers) => layers.depth_stencil.format(),
            None => self.depth_stencil.format(),
        }
    }

    /// Samples per pixel: 1 unless multisampled.
    pub fn samples(&self) -> usize {
        self.multisample.as_ref().map_or(1, |m| m.samples)
    }

    /// Clears `rect` of every sample of color buffer `slot` (no-op unless multisampled);
    /// the caller clears the resolved buffer itself.
    pub fn clear_color_samples(&mut self, slot: ColorSlot, rect: Rect, color: [f32; 4], mask: [bool; 4]) {
        if let Some(layers) = self.multisample.as_mut() {
            let rows = rect.sample_rows(layers.samples);
            if let Some((_, buffer)) = layers.color.iter_mut().find(|(s, _)| *s == slot) {
                buffer.clear(rows, color, mask);
            }
        }
    }

    /// As [`Framebuffer::clear_color_samples`] for depth.
    pub fn clear_depth_samples(&mut self, rect: Rect, depth: f64) {
        if let Some(layers) = self.multisample.as_mut() {
            layers.depth_stencil.clear_depth(rect.sample_rows(layers.samples), depth);
        }
    }

    /// As [`Framebuffer::clear_color_samples`] for stencil.
    pub fn clear_stencil_samples(&mut self, rect: Rect, value: u8, write_mask: u8) {
        if let Some(layers) = self.multisample.as_mut() {
            layers.depth_stencil.clear_stencil(rect.sample_rows(layers.samples), value, write_mask);
        }
    }

    /// Resolves pixel rows `rows` (a rectangle) of the color buffers `slots` and of depth and
    /// stencil into the single-sample layers. No-op unless multisampled.
    pub fn resolve(&mut self, slots: &[ColorSlot], rect: Rect) {
        let Some(layers) = self.multisample.as_ref() else {
            return;
        };
        let rect = rect.intersect(self.bounds());
        for (slot, samples) in layers.color.iter().filter(|(s, _)| slots.contains(s)) {
            if let Some((_, resolved)) = self.color.iter_mut().find(|(s, _)| s == slot) {
                resolve_color(samples, layers.samples, resolved, rect);
            }
        }
        resolve_depth_stencil(&layers.depth_stencil, layers.samples, &mut self.depth_stencil, rect);
    }

    /// Writes `rect` of the resolved color buffer `slot` back into its samples (after a write
    /// that bypassed the samples). No-op unless multisampled.
    pub fn broadcast_to_samples(&mut self, slot: ColorSlot, rect: Rect) {
        let Some(layers) = self.multisample.as_mut() else {
            return;
        };
        let rect = rect.intersect(Rect::from_xywh(0, 0, self.width as i32, self.height as i32));
        let resolved = self.color.iter().find(|(s, _)| *s == slot).map(|(_, b)| b);
        let samples = layers.color.iter_mut().find(|(s, _)| *s == slot).map(|(_, b)| b);
        if let (Some(resolved), Some(samples)) = (resolved, samples) {
            broadcast_color(resolved, layers.samples, samples, rect);
        }
    }

    /// The multisampled color buffer of `slot` and its sample count, if multisampled.
    pub fn color_samples(&self, slot: ColorSlot) -> Option<(&ColorBuffer, usize)> {
        let layers = self.multisample.as_ref()?;
        layers.color.iter().find(|(s, _)| *s == slot).map(|(_, b)| (b, layers.samples))
    }

    /// The multisampled depth/stencil buffer and its sample count, if multisampled.
    pub fn depth_stencil_samples(&self) -> Option<(&DepthStencilBuffer, usize)> {
        self.multisample.as_ref().map(|l| (&l.depth_stencil, l.samples))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config(color: ColorFormat) -> FramebufferConfig {
        FramebufferConfig::single_buffered(color, DepthStencilFormat::Packed24 { depth: true, stencil: true }, 0)
    }

    #[test]
    fn supported_counts_round_up() {
        assert_eq!(supported_samples(0), Some(1));
        assert_eq!(supported_samples(1), Some(1));
        assert_eq!(supported_samples(2), Some(2));
        assert_eq!(supported_samples(3), Some(4));
        assert_eq!(supported_samples(5), Some(8));
        assert_eq!(supported_samples(9), None);
    }

    #[test]
    fn resolve_rounds_the_average_of_each_pixels_samples() {
        let format = ColorFormat::Unorm8 { alpha: true };
        let mut fb = Framebuffer::with_samples(config(format), 3, 2, 4).unwrap();
        assert_eq!(fb.samples(), 4);
        // Pixel (1, 1): two samples white, two black → 127.5 rounds to 128; pixel (2, 1): one
        // of four → 63.75 → 64.
        fb.clear_color_samples(ColorSlot::FrontLeft, Rect::from_xywh(0, 0, 3, 2), [0.0; 4], [true; 4]);
        {
            let layers = fb.multisample.as_mut().unwrap();
            let ColorPixels::Unorm8(px) = layers.color[0].1.pixels_mut() else { unreachable!() };
            for s in 0..2 {
                px[(4 + s) * 3 + 1] = [255; 4];
            }
            px[(4 + 3) * 3 + 2] = [255, 0, 0, 255];
        }
        fb.resolve(&[ColorSlot::FrontLeft], fb.bounds());
        let ColorPixels::Unorm8(px) = fb.color(ColorSlot::FrontLeft).unwrap().pixels() else { unreachable!() };
        assert_eq!(px[3 + 1], [128; 4]);
        assert_eq!(px[3 + 2], [64, 0, 0, 64]);
        assert_eq!(px[0], [0; 4]);
    }

    #[test]
    fn averages_round_to_nearest_for_every_count() {
        for count in 1..=8usize {
            for base in [0u32, 1, 2, 127, 128, 254, 255, 65535] {
                let values: Vec<[u32; 4]> =
                    (0..count as u32).map(|s| [base, base / (s + 1), 255 - base % 256, s]).collect();
                let expect: [u32; 4] = std::array::from_fn(|k| {
                    let sum: u32 = values.iter().map(|v| v[k]).sum();
                    (sum + count as u32 / 2) / count as u32
                });
                assert_eq!(average_unorm(values.iter().copied(), count), expect, "{count} {base}");
            }
        }
    }

    #[test]
    fn clears_reach_every_sample_and_broadcast_writes_them_back() {
        let format = ColorFormat::Float32 { alpha: true };
        let mut fb = Framebuffer::with_samples(config(format), 2, 2, 2).unwrap();
        let rect = Rect::from_xywh(1, 1, 1, 1);
        fb.clear_color_samples(ColorSlot::FrontLeft, rect, [0.25, 0.5, 1.0, 2.0], [true; 4]);
        fb.clear_depth_samples(rect, 1.0);
        fb.resolve(&[ColorSlot::FrontLeft], fb.bounds());
        let ColorPixels::Float32(px) = fb.color(ColorSlot::FrontLeft).unwrap().pixels() else { unreachable!() };
        assert_eq!(px[3], [0.25, 0.5, 1.0, 2.0]);
        assert_eq!(px[2], [0.0; 4]);
        let mut depth = Vec::new();
        fb.depth_stencil().read_depth_row(1, 0, 2, &mut depth);
        assert_eq!(depth, vec![0, 0x00ff_ffff]);

        fb.color_mut(ColorSlot::FrontLeft).unwrap().clear(Rect::from_xywh(0, 0, 1, 1), [1.0; 4], [true; 4]);
        fb.broadcast_to_samples(ColorSlot::FrontLeft, Rect::from_xywh(0, 0, 1, 1));
        let (samples, count) = fb.color_samples(ColorSlot::FrontLeft).unwrap();
        assert_eq!(count, 2);
        let ColorPixels::Float32(px) = samples.pixels() else { unreachable!() };
        assert_eq!((px[0], px[2], px[1]), ([1.0; 4], [1.0; 4], [0.0; 4]));
    }
}
