//! RGBA8 pictures and their PNG files: every PNG the programs write is read as 8-bit RGBA
//! (grey, grey+alpha, RGB and palette files are expanded; 16-bit channels are reduced).

use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

/// An 8-bit RGBA picture, rows from the top, four bytes per pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub rgba: Vec<u8>,
}

impl Image {
    /// A picture of one color.
    pub fn filled(width: usize, height: usize, rgba: [u8; 4]) -> Image {
        Image { width, height, rgba: rgba.iter().copied().cycle().take(width * height * 4).collect() }
    }

    /// The four channels of pixel (x, y), y counted from the top.
    pub fn pixel(&self, x: usize, y: usize) -> [u8; 4] {
        let i = (y * self.width + x) * 4;
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2], self.rgba[i + 3]]
    }

    pub fn set_pixel(&mut self, x: usize, y: usize, value: [u8; 4]) {
        let i = (y * self.width + x) * 4;
        self.rgba[i..i + 4].copy_from_slice(&value);
    }
}

/// Reads a PNG file as RGBA8.
pub fn read_png(path: &Path) -> Result<Image, String> {
    let file = File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().map_err(|e| format!("{}: {e}", path.display()))?;
    let mut buffer = vec![0; reader.output_buffer_size().ok_or("PNG too large")?];
    let info = reader.next_frame(&mut buffer).map_err(|e| format!("{}: {e}", path.display()))?;
    let (width, height) = (info.width as usize, info.height as usize);
    let samples = &buffer[..info.buffer_size()];
    let channels = info.color_type.samples();
    let mut rgba = Vec::with_capacity(width * height * 4);
    for px in samples.chunks_exact(channels) {
        let pixel = match channels {
            1 => [px[0], px[0], px[0], 255],
            2 => [px[0], px[0], px[0], px[1]],
            3 => [px[0], px[1], px[2], 255],
            _ => [px[0], px[1], px[2], px[3]],
        };
        rgba.extend_from_slice(&pixel);
    }
    Ok(Image { width, height, rgba })
}

/// Writes an RGBA8 PNG file.
pub fn write_png(path: &Path, image: &Image) -> Result<(), String> {
    let file = File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), image.width as u32, image.height as u32);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| format!("{}: {e}", path.display()))?;
    writer.write_image_data(&image.rgba).map_err(|e| format!("{}: {e}", path.display()))
}
