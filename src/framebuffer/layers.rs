//! Framebuffers assembled from layers owned elsewhere: the attachments of framebuffer objects.
//!
//! A framebuffer object's images live in renderbuffers and textures, not in one drawable.
//! To draw into them, the context moves each attached image into a [`Framebuffer`] made by
//! [`Framebuffer::from_layers`], runs the same scene execution, clears and reads on it as on
//! a window's framebuffer, and takes the images back with [`Framebuffer::into_layers`].
//! Texture images are stored as these layers store pixels (see `crate::texture`), so a
//! texture's texel vector is moved in as a layer ([`ColorBuffer::from_pixels`], or the
//! depth texture's own [`DepthStencilBuffer`]) just as a renderbuffer's storage is.
//! Moving a buffer moves its pixel vector, not the pixels, so the tiled rasterizer, the
//! binner and the thread pool see a framebuffer like any other: tiles still own pixels.
use super::{
    ColorBuffer, ColorFormat, ColorSlot, DepthStencilBuffer, DepthStencilFormat, Framebuffer, FramebufferConfig,
    OutOfMemory,
};

/// A zero-filled `width` × `height` color buffer of `format` (as a fresh renderbuffer).
pub fn color_buffer(format: ColorFormat, width: usize, height: usize) -> Result<ColorBuffer, OutOfMemory> {
    let pixels = width.checked_mul(height).ok_or(OutOfMemory)?;
    ColorBuffer::new(format, width, height, pixels)
}

/// A zero-filled `width` × `height` depth/stencil buffer of `format`.
pub fn depth_stencil_buffer(
    format: DepthStencilFormat,
    width: usize,
    height: usize,
) -> Result<DepthStencilBuffer, OutOfMemory> {
    let pixels = width.checked_mul(height).ok_or(OutOfMemory)?;
    DepthStencilBuffer::new(format, width, pixels)
}

impl Framebuffer {
    /// A `width` × `height` framebuffer made of the given layers, which must all be that
    /// size; `config` describes them (its color format is the one draws compile for).
    pub fn from_layers(
        config: FramebufferConfig,
        width: usize,
        height: usize,
        color: Vec<(ColorSlot, ColorBuffer)>,
        depth_stencil: Option<DepthStencilBuffer>,
    ) -> Framebuffer {
        let depth_stencil = depth_stencil.unwrap_or_else(|| {
            DepthStencilBuffer::new(DepthStencilFormat::None, width, 0).expect("an empty buffer allocates nothing")
        });
        Framebuffer {
            config,
            width,
            height,
            color,
            depth_stencil,
            accum: None,
            multisample: None,
            in_place_front: None,
        }
    }

    /// The layers back, as [`Framebuffer::from_layers`] or
    /// [`Framebuffer::from_sample_layers`] took them.
    pub fn into_layers(self) -> (Vec<(ColorSlot, ColorBuffer)>, DepthStencilBuffer) {
        match self.multisample {
            Some(layers) => (layers.color, layers.depth_stencil),
            None => (self.color, self.depth_stencil),
        }
    }
}
