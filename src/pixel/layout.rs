//! Where the pixels of a client image live: the glPixelStore layout rules of GL 2.1 §3.6.4
//! (used in reverse by packing, §4.3.2), and the byte span a transfer touches.
//!
//! Row `j` of an image `width` pixels wide starts `(skip_rows + j) · stride` bytes after the
//! pointer, where the stride is `row_length` (or `width`) pixels rounded up to the alignment;
//! pixel `i` of a row is `skip_pixels + i` pixels further. Bitmaps address bits: rows of
//! `⌈row_length / 8⌉` bytes (aligned), pixel `i` at bit `skip_pixels + i`. GL's rule pads only
//! when the component size is below the alignment; since sizes and alignments are powers of
//! two, rounding the row's byte count up to the alignment is the same thing (and is what Mesa
//! computes).
//!
//! All arithmetic is checked: a layout that would address beyond `isize::MAX` bytes is
//! refused (`None`) rather than wrapped.
use super::{ClientFormat, ClientType, PackModes};
use std::ops::Range;

/// The addressing of one client image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageLayout {
    /// Bytes per pixel; 0 for bitmaps, which have one bit per pixel.
    pixel_bytes: usize,
    /// Bytes from the start of one row to the next.
    row_stride: usize,
    skip_rows: usize,
    skip_pixels: usize,
}

impl ImageLayout {
    /// The layout of an image `width` pixels wide (the width the application passed, before
    /// any clipping) in `format`/`ty` under `modes`; `None` if it overflows.
    pub fn new(format: ClientFormat, ty: ClientType, modes: &PackModes, width: usize) -> Option<ImageLayout> {
        let pixel_bytes = ty.pixel_bytes(format);
        let row_pixels = if modes.row_length > 0 { modes.row_length } else { width };
        let row_bytes = if pixel_bytes == 0 { row_pixels.div_ceil(8) } else { row_pixels.checked_mul(pixel_bytes)? };
        let alignment = modes.alignment.max(1);
        let row_stride = row_bytes.checked_next_multiple_of(alignment)?;
        let layout =
            ImageLayout { pixel_bytes, row_stride, skip_rows: modes.skip_rows, skip_pixels: modes.skip_pixels };
        Some(layout)
    }

    pub fn row_stride(&self) -> usize {
        self.row_stride
    }

    pub fn pixel_bytes(&self) -> usize {
        self.pixel_bytes
    }

    /// Byte offset of the start of row `row`.
    pub fn row_offset(&self, row: usize) -> Option<usize> {
        self.skip_rows.checked_add(row)?.checked_mul(self.row_stride)
    }

    /// Byte offset of pixel `col` of row `row` (bitmaps: of the byte holding its bit).
    pub fn pixel_offset(&self, col: usize, row: usize) -> Option<usize> {
        let pixel = self.skip_pixels.checked_add(col)?;
        let within = if self.pixel_bytes == 0 { pixel / 8 } else { pixel.checked_mul(self.pixel_bytes)? };
        self.row_offset(row)?.checked_add(within)
    }

    /// Bit index, within its row, of pixel `col` of a bitmap.
    pub fn bit_index(&self, col: usize) -> usize {
        self.skip_pixels + col
    }

    /// The bytes a transfer of columns `cols` of rows `rows` touches: from the first byte of
    /// its first pixel to the last byte of its last pixel. Empty when there are no pixels;
    /// `None` if the span leaves the address space.
    pub fn span(&self, cols: Range<usize>, rows: Range<usize>) -> Option<Range<usize>> {
        if cols.is_empty() || rows.is_empty() {
            return Some(0..0);
        }
        let start = self.pixel_offset(cols.start, rows.start)?;
        let last = self.pixel_offset(cols.end - 1, rows.end - 1)?;
        let end = last.checked_add(self.pixel_bytes.max(1))?;
        (end <= isize::MAX as usize).then_some(start..end)
    }
}

/// The addressing of a client volume (glTexImage3D; 1D and 2D images are volumes one image
/// deep): images of `image_height` rows (GL_UNPACK_IMAGE_HEIGHT, or the height) follow each
/// other, the first `skip_images` of them skipped (GL 2.1 §3.8.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VolumeLayout {
    layout: ImageLayout,
    image_stride: usize,
    skip_images: usize,
}

impl VolumeLayout {
    /// The layout of images `width` × `height` in `format`/`ty` under `modes`, `image_height`
    /// rows apart (0: `height`), `skip_images` of them skipped; `None` if it overflows.
    pub fn new(
        format: ClientFormat,
        ty: ClientType,
        modes: &PackModes,
        [width, height]: [usize; 2],
        image_height: usize,
        skip_images: usize,
    ) -> Option<VolumeLayout> {
        let layout = ImageLayout::new(format, ty, modes, width)?;
        let rows = if image_height > 0 { image_height } else { height };
        let image_stride = rows.checked_mul(layout.row_stride())?;
        Some(VolumeLayout { layout, image_stride, skip_images })
    }

    /// Bytes per pixel; 0 for bitmaps.
    pub fn pixel_bytes(&self) -> usize {
        self.layout.pixel_bytes()
    }

    /// Byte offset of the first pixel of row `y` of image `z`.
    pub fn row_offset(&self, y: usize, z: usize) -> Option<usize> {
        let image = self.skip_images.checked_add(z)?.checked_mul(self.image_stride)?;
        image.checked_add(self.layout.pixel_offset(0, y)?)
    }

    /// The bit of the first pixel of a row within the row's first byte (bitmaps).
    pub fn first_bit(&self) -> usize {
        self.layout.bit_index(0) % 8
    }

    /// The bytes a `width` × `height` × `depth` transfer touches; `None` if the span leaves
    /// the address space.
    pub fn span(&self, width: usize, height: usize, depth: usize) -> Option<Range<usize>> {
        if width == 0 || height == 0 || depth == 0 {
            return Some(0..0);
        }
        let start = self.row_offset(0, 0)?;
        let last_row_bytes = if self.pixel_bytes() == 0 {
            // A bitmap row: the bytes from the one holding its first bit to its last bit's.
            self.layout.bit_index(width - 1) / 8 - self.layout.bit_index(0) / 8 + 1
        } else {
            width.checked_mul(self.pixel_bytes())?
        };
        let end = self.row_offset(height - 1, depth - 1)?.checked_add(last_row_bytes)?;
        (end <= isize::MAX as usize).then_some(start..end)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pixel::PackedType;

    fn modes(alignment: usize) -> PackModes {
        PackModes { alignment, ..PackModes::default() }
    }

    #[test]
    fn rows_are_padded_to_the_alignment() {
        let rgb = ImageLayout::new(ClientFormat::Rgb, ClientType::UnsignedByte, &modes(4), 5).unwrap();
        assert_eq!(rgb.row_stride(), 16);
        let rgb1 = ImageLayout::new(ClientFormat::Rgb, ClientType::UnsignedByte, &modes(1), 5).unwrap();
        assert_eq!(rgb1.row_stride(), 15);
        let short = ImageLayout::new(ClientFormat::Rgb, ClientType::Short, &modes(8), 1).unwrap();
        assert_eq!(short.row_stride(), 8);
        let float = ImageLayout::new(ClientFormat::Red, ClientType::Float, &modes(2), 3).unwrap();
        assert_eq!(float.row_stride(), 12);
        let packed =
            ImageLayout::new(ClientFormat::Rgb, ClientType::Packed(PackedType::UnsignedByte332), &modes(8), 9).unwrap();
        assert_eq!(packed.row_stride(), 16);
    }

    #[test]
    fn row_length_and_skips_move_pixels() {
        let m = PackModes { row_length: 10, skip_rows: 2, skip_pixels: 3, alignment: 8, ..PackModes::default() };
        let l = ImageLayout::new(ClientFormat::Rgba, ClientType::UnsignedByte, &m, 4).unwrap();
        assert_eq!(l.row_stride(), 40);
        assert_eq!(l.pixel_offset(0, 0), Some(2 * 40 + 3 * 4));
        assert_eq!(l.pixel_offset(1, 1), Some(3 * 40 + 4 * 4));
        // Two rows of two pixels starting at column 1.
        assert_eq!(l.span(1..3, 0..2), Some(96..144));
        assert_eq!(l.span(1..1, 0..2), Some(0..0));
    }

    #[test]
    fn volumes_skip_whole_images() {
        let m = PackModes { alignment: 1, ..PackModes::default() };
        let v = VolumeLayout::new(ClientFormat::Rgba, ClientType::UnsignedByte, &m, [2, 3], 5, 1).unwrap();
        // Images of 5 rows of 8 bytes; the first one skipped.
        assert_eq!(v.row_offset(0, 0), Some(40));
        assert_eq!(v.row_offset(2, 1), Some(80 + 16));
        assert_eq!(v.span(2, 3, 2), Some(40..80 + 24));
        assert_eq!(v.span(0, 3, 2), Some(0..0));
        let flat = VolumeLayout::new(ClientFormat::Rgba, ClientType::UnsignedByte, &m, [2, 3], 0, 0).unwrap();
        assert_eq!(flat.row_offset(0, 1), Some(24), "image height 0: the height");
    }

    #[test]
    fn bitmaps_address_bits() {
        let m = PackModes { skip_pixels: 11, alignment: 2, ..PackModes::default() };
        let l = ImageLayout::new(ClientFormat::StencilIndex, ClientType::Bitmap, &m, 17).unwrap();
        assert_eq!(l.row_stride(), 4); // 3 bytes, aligned to 2
        assert_eq!(l.pixel_offset(0, 1), Some(4 + 1));
        assert_eq!(l.bit_index(6), 17);
        assert_eq!(l.span(0..17, 0..2), Some(1..8));
    }

    #[test]
    fn overflow_is_refused() {
        let m = PackModes { row_length: usize::MAX / 2, alignment: 4, ..PackModes::default() };
        assert_eq!(ImageLayout::new(ClientFormat::Rgba, ClientType::Float, &m, 1), None);
        let m = PackModes { skip_rows: usize::MAX / 4, alignment: 4, ..PackModes::default() };
        let l = ImageLayout::new(ClientFormat::Rgba, ClientType::Float, &m, 4).unwrap();
        assert_eq!(l.span(0..1, 0..1), None);
    }
}
