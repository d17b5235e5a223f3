//! The rasterization state setters: shading and provoking vertex, face orientation and
//! culling, polygon modes and offset, line width and stipple, point size and parameters, and
//! the polygon stipple pattern, with the errors the GL 2.1 specification names.
//!
//! Sizes are kept as given (glLineWidth(300) reads back 300); the rasterizer clamps them to the
//! ranges below. Where the specification is silent, Mesa 22 decides: glPointParameter{f,i}
//! with GL_POINT_DISTANCE_ATTENUATION sets (param, 0, 0), GL_POINT_SPRITE_COORD_ORIGIN given as
//! a float is truncated to an enum, and glPolygonOffset resets the offset clamp to 0 (as
//! EXT_polygon_offset_clamp specifies).
//!
//! The polygon stipple is a 32×32 bitmap moved through the pixel store: glPolygonStipple reads
//! it with the unpack modes (alignment, row length, skips, GL_UNPACK_LSB_FIRST) and
//! glGetPolygonStipple writes it with the pack modes. Packing writes only the pattern's bits:
//! Mesa 22 zeroes the rest of the first and last byte of each row when GL_PACK_SKIP_PIXELS is
//! not a multiple of 8, which tessera does not copy.
use super::pixel_buffers::{ClientBytes, ClientBytesMut};
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::{MAX_LINE_WIDTH, MAX_POINT_SIZE};
use crate::gl::types::GLenum;
use crate::pixel::layout::ImageLayout;
use crate::pixel::{ClientFormat, ClientType, PackModes};
use std::ops::Range;

/// Aliased and smooth line widths the rasterizer draws (GL_ALIASED_LINE_WIDTH_RANGE,
/// GL_LINE_WIDTH_RANGE); wider or narrower requests are clamped.
pub const LINE_WIDTH_RANGE: [f32; 2] = [1.0, MAX_LINE_WIDTH];
/// Point sizes the rasterizer draws (GL_ALIASED_POINT_SIZE_RANGE, GL_POINT_SIZE_RANGE).
pub const POINT_SIZE_RANGE: [f32; 2] = [1.0, MAX_POINT_SIZE];
/// The step between supported smooth widths and sizes (GL_LINE_WIDTH_GRANULARITY,
/// GL_POINT_SIZE_GRANULARITY).
pub const LINE_WIDTH_GRANULARITY: f32 = 0.125;
pub const POINT_SIZE_GRANULARITY: f32 = 0.125;

/// Side of the polygon stipple pattern, in pixels.
const STIPPLE_SIZE: usize = 32;

/// The layout of the 32×32 stipple bitmap in client memory under `modes`, and the bytes it
/// spans; `None` if the layout leaves the address space.
fn stipple_layout(modes: &PackModes) -> Option<(ImageLayout, Range<usize>)> {
    let layout = ImageLayout::new(ClientFormat::StencilIndex, ClientType::Bitmap, modes, STIPPLE_SIZE)?;
    let span = layout.span(0..STIPPLE_SIZE, 0..STIPPLE_SIZE)?;
    Some((layout, span))
}

/// The mask of bit `bit` within its byte.
fn bit_mask(bit: usize, lsb_first: bool) -> u8 {
    if lsb_first {
        1 << (bit % 8)
    } else {
        0x80 >> (bit % 8)
    }
}

/// Reads a stipple pattern (rows bottom-up, bit 31 leftmost) from `client`, which starts at the
/// first byte of the layout's span.
fn unpack_stipple(client: &[u8], layout: &ImageLayout, start: usize, lsb_first: bool) -> Option<[u32; 32]> {
    let mut pattern = [0u32; STIPPLE_SIZE];
    for (row, word) in pattern.iter_mut().enumerate() {
        let row_offset = layout.row_offset(row)?;
        for col in 0..STIPPLE_SIZE {
            let bit = layout.bit_index(col);
            let byte = client.get((row_offset + bit / 8).checked_sub(start)?)?;
            if byte & bit_mask(bit, lsb_first) != 0 {
                *word |= 0x8000_0000 >> col;
            }
        }
    }
    Some(pattern)
}

/// Writes a stipple pattern to `client`, which starts at the first byte of the layout's span;
/// the other bits of the bytes it touches keep their values.
fn pack_stipple(pattern: &[u32; 32], client: &mut [u8], layout: &ImageLayout, start: usize, lsb_first: bool) {
    for (row, &word) in pattern.iter().enumerate() {
        let Some(row_offset) = layout.row_offset(row) else {
            return;
        };
        for col in 0..STIPPLE_SIZE {
            let bit = layout.bit_index(col);
            let Some(byte) = (row_offset + bit / 8).checked_sub(start).and_then(|i| client.get_mut(i)) else {
                return;
            };
            let mask = bit_mask(bit, lsb_first);
            if word & (0x8000_0000 >> col) != 0 {
                *byte |= mask;
            } else {
                *byte &= !mask;
            }
        }
    }
}

impl Context {
    /// Records GL_INVALID_ENUM unless `valid`; returns `valid`.
    fn require_enum(&mut self, valid: bool) -> bool {
        if !valid {
            self.error(GL_INVALID_ENUM);
        }
        valid
    }

    /// glShadeModel.
    pub fn shade_model(&mut self, mode: GLenum) {
        if self.check_outside_begin_end() && self.require_enum(matches!(mode, GL_FLAT | GL_SMOOTH)) {
            self.state.lighting.shade_model = mode;
        }
    }

    /// glProvokingVertex.
    pub fn provoking_vertex(&mut self, mode: GLenum) {
        let valid = matches!(mode, GL_FIRST_VERTEX_CONVENTION | GL_LAST_VERTEX_CONVENTION);
        if self.check_outside_begin_end() && self.require_enum(valid) {
            self.state.lighting.provoking_vertex = mode;
        }
    }

    /// glFrontFace.
    pub fn front_face(&mut self, mode: GLenum) {
        if self.check_outside_begin_end() && self.require_enum(matches!(mode, GL_CW | GL_CCW)) {
            self.state.polygon.front_face = mode;
        }
    }

    /// glCullFace.
    pub fn cull_face(&mut self, mode: GLenum) {
        let valid = matches!(mode, GL_FRONT | GL_BACK | GL_FRONT_AND_BACK);
        if self.check_outside_begin_end() && self.require_enum(valid) {
            self.state.polygon.cull_face_mode = mode;
        }
    }

    /// glPolygonMode.
    pub fn polygon_mode(&mut self, face: GLenum, mode: GLenum) {
        let valid =
            matches!(mode, GL_POINT | GL_LINE | GL_FILL) && matches!(face, GL_FRONT | GL_BACK | GL_FRONT_AND_BACK);
        if !self.check_outside_begin_end() || !self.require_enum(valid) {
            return;
        }
        let polygon = &mut self.state.polygon;
        if face != GL_BACK {
            polygon.mode_front = mode;
        }
        if face != GL_FRONT {
            polygon.mode_back = mode;
        }
    }

    /// glPolygonOffsetClamp (and glPolygonOffset, with a clamp of 0).
    pub fn polygon_offset(&mut self, factor: f32, units: f32, clamp: f32) {
        if self.check_outside_begin_end() {
            let polygon = &mut self.state.polygon;
            (polygon.offset_factor, polygon.offset_units, polygon.offset_clamp) = (factor, units, clamp);
        }
    }

    /// glLineWidth: GL_INVALID_VALUE unless positive (NaN is accepted, as in Mesa).
    pub fn line_width(&mut self, width: f32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if width <= 0.0 {
            return self.error(GL_INVALID_VALUE);
        }
        self.state.line_point.line_width = width;
    }

    /// glLineStipple: the factor is clamped to [1, 256].
    pub fn line_stipple(&mut self, factor: i32, pattern: u16) {
        if self.check_outside_begin_end() {
            self.state.line_point.line_stipple_factor = factor.clamp(1, 256);
            self.state.line_point.line_stipple_pattern = pattern;
        }
    }

    /// glPointSize: GL_INVALID_VALUE unless positive.
    pub fn point_size(&mut self, size: f32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if size <= 0.0 {
            return self.error(GL_INVALID_VALUE);
        }
        self.state.line_point.point_size = size;
    }

    /// glPointParameterfv; the scalar and integer forms pass `[param, 0, 0]` (the integer
    /// vector form converts all three for GL_POINT_DISTANCE_ATTENUATION).
    pub fn point_parameter(&mut self, pname: GLenum, params: [f32; 3]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let points = &mut self.state.line_point;
        let size = params[0];
        let field = match pname {
            GL_POINT_DISTANCE_ATTENUATION => {
                points.point_distance_attenuation = params;
                return;
            }
            GL_POINT_SPRITE_COORD_ORIGIN => {
                // A float parameter names the enum by C's truncating conversion.
                let origin = size as GLenum;
                if !matches!(origin, GL_LOWER_LEFT | GL_UPPER_LEFT) {
                    return self.error(GL_INVALID_VALUE);
                }
                points.point_sprite_coord_origin = origin;
                return;
            }
            GL_POINT_SIZE_MIN => &mut points.point_size_min,
            GL_POINT_SIZE_MAX => &mut points.point_size_max,
            GL_POINT_FADE_THRESHOLD_SIZE => &mut points.point_fade_threshold,
            _ => return self.error(GL_INVALID_ENUM),
        };
        if size < 0.0 {
            return self.error(GL_INVALID_VALUE);
        }
        *field = size;
    }

    /// How many values glPointParameter{f,i}v reads for `pname`.
    pub fn point_parameter_count(pname: GLenum) -> usize {
        if pname == GL_POINT_DISTANCE_ATTENUATION {
            3
        } else {
            1
        }
    }

    /// glPolygonStipple: `source` maps the span of client bytes the pattern occupies under the
    /// unpack modes to those bytes (`None`: a NULL pointer, which changes nothing).
    pub fn polygon_stipple<'a>(&mut self, source: impl FnOnce(Range<usize>) -> ClientBytes<'a>) {
        let pattern = self.unpack_polygon_stipple(source);
        self.set_polygon_stipple(pattern)
    }

    /// The pattern glPolygonStipple reads under the unpack modes (`Ok(None)`: a NULL pointer),
    /// read when the command is issued (also when it is compiled into a display list).
    pub fn unpack_polygon_stipple<'a>(
        &self,
        source: impl FnOnce(Range<usize>) -> ClientBytes<'a>,
    ) -> Result<Option<[u32; 32]>, GLenum> {
        let modes = PackModes::from(&self.pixel_store.unpack);
        let (layout, span) = stipple_layout(&modes).ok_or(GL_INVALID_VALUE)?;
        let start = span.start;
        Ok(source(span)?.and_then(|client| unpack_stipple(client, &layout, start, modes.lsb_first)))
    }

    /// glPolygonStipple with its pattern already read.
    pub fn set_polygon_stipple(&mut self, pattern: Result<Option<[u32; 32]>, GLenum>) {
        if !self.check_outside_begin_end() {
            return;
        }
        match pattern {
            Ok(Some(pattern)) => self.state.polygon_stipple = pattern,
            Ok(None) => {}
            Err(error) => self.error(error),
        }
    }

    /// glGetPolygonStipple: `dest` maps the span of client bytes the pattern occupies under
    /// the pack modes to those bytes (`None`: a NULL pointer, which writes nothing).
    pub fn get_polygon_stipple<'a>(&mut self, dest: impl FnOnce(Range<usize>) -> ClientBytesMut<'a>) {
        if !self.check_outside_begin_end() {
            return;
        }
        let modes = PackModes::from(&self.pixel_store.pack);
        let Some((layout, span)) = stipple_layout(&modes) else {
            return self.error(GL_INVALID_VALUE);
        };
        let start = span.start;
        match dest(span) {
            Ok(Some(client)) => pack_stipple(&self.state.polygon_stipple, client, &layout, start, modes.lsb_first),
            Ok(None) => {}
            Err(error) => self.error(error),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::state::State;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};

    fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 0);
        Context::new(ContextConfig { visual })
    }

    #[test]
    fn enum_setters_accept_their_values_and_reject_others() {
        let mut ctx = context();
        ctx.shade_model(GL_FLAT);
        ctx.provoking_vertex(GL_FIRST_VERTEX_CONVENTION);
        ctx.front_face(GL_CW);
        ctx.cull_face(GL_FRONT_AND_BACK);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let expected = ctx.state.clone();
        ctx.shade_model(GL_FRONT);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.provoking_vertex(GL_FLAT);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.front_face(GL_FRONT);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.cull_face(GL_FRONT_LEFT);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.polygon_mode(GL_FRONT_LEFT, GL_LINE);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.polygon_mode(GL_FRONT, GL_FRONT);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state, expected);
        assert_eq!(
            (ctx.state.lighting.shade_model, ctx.state.lighting.provoking_vertex),
            (GL_FLAT, GL_FIRST_VERTEX_CONVENTION)
        );
        assert_eq!((ctx.state.polygon.front_face, ctx.state.polygon.cull_face_mode), (GL_CW, GL_FRONT_AND_BACK));
    }

    #[test]
    fn polygon_mode_sets_the_named_faces() {
        let mut ctx = context();
        ctx.polygon_mode(GL_FRONT, GL_LINE);
        ctx.polygon_mode(GL_BACK, GL_POINT);
        assert_eq!((ctx.state.polygon.mode_front, ctx.state.polygon.mode_back), (GL_LINE, GL_POINT));
        ctx.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
        assert_eq!((ctx.state.polygon.mode_front, ctx.state.polygon.mode_back), (GL_FILL, GL_FILL));
    }

    #[test]
    fn widths_and_sizes_must_be_positive_and_are_kept_unclamped() {
        let mut ctx = context();
        for bad in [0.0, -1.0, -0.0] {
            ctx.line_width(bad);
            assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
            ctx.point_size(bad);
            assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        }
        ctx.line_width(300.0);
        ctx.point_size(1000.0);
        assert_eq!((ctx.state.line_point.line_width, ctx.state.line_point.point_size), (300.0, 1000.0));
        ctx.line_stipple(0, 0x2345);
        assert_eq!(ctx.state.line_point.line_stipple_factor, 1);
        ctx.line_stipple(1000, 0xffff);
        assert_eq!(ctx.state.line_point.line_stipple_factor, 256);
        ctx.line_stipple(-5, 1);
        assert_eq!((ctx.state.line_point.line_stipple_factor, ctx.state.line_point.line_stipple_pattern), (1, 1));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn point_parameters_follow_mesa() {
        let mut ctx = context();
        ctx.point_parameter(GL_POINT_DISTANCE_ATTENUATION, [5.0, 0.0, 0.0]);
        assert_eq!(ctx.state.line_point.point_distance_attenuation, [5.0, 0.0, 0.0]);
        for pname in [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE] {
            ctx.point_parameter(pname, [-1.0, 0.0, 0.0]);
            assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        }
        ctx.point_parameter(GL_POINT_SIZE_MIN, [300.0, 0.0, 0.0]);
        ctx.point_parameter(GL_POINT_SIZE_MAX, [0.0, 0.0, 0.0]);
        ctx.point_parameter(GL_POINT_FADE_THRESHOLD_SIZE, [2.5, 0.0, 0.0]);
        let p = &ctx.state.line_point;
        assert_eq!((p.point_size_min, p.point_size_max, p.point_fade_threshold), (300.0, 0.0, 2.5));
        ctx.point_parameter(GL_POINT_SPRITE_COORD_ORIGIN, [GL_LOWER_LEFT as f32, 0.0, 0.0]);
        assert_eq!(ctx.state.line_point.point_sprite_coord_origin, GL_LOWER_LEFT);
        ctx.point_parameter(GL_POINT_SPRITE_COORD_ORIGIN, [GL_UPPER_LEFT as f32 + 0.5, 0.0, 0.0]);
        assert_eq!(ctx.state.line_point.point_sprite_coord_origin, GL_UPPER_LEFT);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.point_parameter(GL_POINT_SPRITE_COORD_ORIGIN, [GL_RGBA as f32, 0.0, 0.0]);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.point_parameter(GL_POINT_SIZE, [1.0, 0.0, 0.0]);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.line_point.point_sprite_coord_origin, GL_UPPER_LEFT);
        assert_eq!(Context::point_parameter_count(GL_POINT_DISTANCE_ATTENUATION), 3);
        assert_eq!(Context::point_parameter_count(GL_POINT_SIZE_MIN), 1);
    }

    #[test]
    fn offset_clamp_is_reset_by_polygon_offset() {
        let mut ctx = context();
        ctx.polygon_offset(1.0, 2.0, 0.75);
        assert_eq!(ctx.state.polygon.offset_clamp, 0.75);
        ctx.polygon_offset(2.5, -3.5, 0.0);
        let p = &ctx.state.polygon;
        assert_eq!((p.offset_factor, p.offset_units, p.offset_clamp), (2.5, -3.5, 0.0));
    }

    /// A recognisable pattern: row r holds r * 0x01020408 + 0x80000001 (bit 31 leftmost).
    fn pattern() -> [u32; 32] {
        std::array::from_fn(|r| (r as u32).wrapping_mul(0x0102_0408) ^ 0x8000_0001)
    }

    #[test]
    fn stipple_round_trips_through_default_modes() {
        let mut ctx = context();
        let mut bytes = Vec::new();
        for word in pattern() {
            bytes.extend_from_slice(&word.to_be_bytes());
        }
        ctx.polygon_stipple(|span| {
            assert_eq!(span, 0..128);
            Ok(Some(&bytes[span]))
        });
        assert_eq!(ctx.state.polygon_stipple, pattern());
        let mut out = [0u8; 128];
        ctx.get_polygon_stipple(|span| Ok(Some(&mut out[span])));
        assert_eq!(out.to_vec(), bytes);
    }

    #[test]
    fn stipple_honours_lsb_first_skips_row_length_and_alignment() {
        let mut ctx = context();
        let u = &mut ctx.pixel_store.unpack;
        (u.lsb_first, u.skip_pixels, u.skip_rows, u.row_length, u.alignment) = (true, 3, 2, 40, 8);
        // Rows of ⌈40/8⌉ = 5 bytes, aligned to 8; the pattern starts 2 rows and 3 bits in.
        let mut client = vec![0u8; 8 * 34];
        for (r, word) in pattern().iter().enumerate() {
            for c in 0..32 {
                if word & (0x8000_0000 >> c) != 0 {
                    let bit = 3 + c;
                    client[(r + 2) * 8 + bit / 8] |= 1 << (bit % 8);
                }
            }
        }
        ctx.polygon_stipple(|span| {
            assert_eq!(span, 16..(33 * 8 + 5));
            Ok(Some(&client[span]))
        });
        assert_eq!(ctx.state.polygon_stipple, pattern());

        // Packing with the same modes reproduces the bytes and leaves the others alone.
        let p = &mut ctx.pixel_store.pack;
        (p.lsb_first, p.skip_pixels, p.skip_rows, p.row_length, p.alignment) = (true, 3, 2, 40, 8);
        let mut out = vec![0xa5u8; 8 * 34];
        ctx.get_polygon_stipple(|span| Ok(Some(&mut out[span])));
        for (i, (&o, &c)) in out.iter().zip(&client).enumerate() {
            let (row, byte) = (i / 8, i % 8);
            let inside = (2..34).contains(&row) && byte < 5;
            let mask: u8 = match byte {
                0 if inside => 0xf8,
                4 if inside => 0x07,
                1..=3 if inside => 0xff,
                _ => 0,
            };
            assert_eq!(o & mask, c & mask, "byte {i}");
            assert_eq!(o & !mask, 0xa5 & !mask, "byte {i}");
        }
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn whole_byte_skips_move_the_span_start() {
        let mut ctx = context();
        ctx.pixel_store.unpack.skip_pixels = 8;
        ctx.pixel_store.unpack.alignment = 1;
        let client: Vec<u8> = (0..=255).collect();
        ctx.polygon_stipple(|span| {
            assert_eq!(span, 1..129);
            Ok(Some(&client[span]))
        });
        // Row r is bytes 4r+1 .. 4r+4 of the client image.
        assert_eq!(ctx.state.polygon_stipple[0], 0x0102_0304);
        assert_eq!(ctx.state.polygon_stipple[31], 0x7d7e_7f80);
        ctx.pixel_store.pack.skip_pixels = 16;
        let mut out = [0u8; 132];
        ctx.get_polygon_stipple(|span| {
            assert_eq!(span, 2..130);
            Ok(Some(&mut out[span]))
        });
        assert_eq!(&out[..7], &[0, 0, 1, 2, 3, 4, 5]);
        assert_eq!(&out[128..], &[0x7f, 0x80, 0, 0]);
    }

    #[test]
    fn msb_first_bit_order() {
        let mut ctx = context();
        let mut bytes = [0u8; 128];
        bytes[0] = 0x80; // row 0, leftmost pixel
        bytes[127] = 0x01; // row 31, rightmost pixel
        ctx.polygon_stipple(|span| Ok(Some(&bytes[span])));
        assert_eq!(ctx.state.polygon_stipple[0], 0x8000_0000);
        assert_eq!(ctx.state.polygon_stipple[31], 1);
        ctx.pixel_store.unpack.lsb_first = true;
        ctx.polygon_stipple(|span| Ok(Some(&bytes[span])));
        assert_eq!(ctx.state.polygon_stipple[0], 0x0100_0000);
        assert_eq!(ctx.state.polygon_stipple[31], 0x80);
    }

    #[test]
    fn null_stipple_pointers_change_nothing() {
        let mut ctx = context();
        ctx.polygon_stipple(|_| Ok(None));
        ctx.get_polygon_stipple(|_| Ok(None));
        assert_eq!(ctx.state, State::new(GL_FRONT));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn setters_are_invalid_between_begin_and_end() {
        let mut ctx = context();
        ctx.inside_begin_end = true;
        let before = ctx.state.clone();
        let commands: [fn(&mut Context); 14] = [
            |c| c.shade_model(GL_FLAT),
            |c| c.provoking_vertex(GL_FIRST_VERTEX_CONVENTION),
            |c| c.front_face(GL_CW),
            |c| c.cull_face(GL_FRONT),
            |c| c.polygon_mode(GL_FRONT, GL_LINE),
            |c| c.polygon_offset(1.0, 1.0, 1.0),
            |c| c.line_width(2.0),
            |c| c.line_stipple(2, 3),
            |c| c.point_size(2.0),
            |c| c.point_parameter(GL_POINT_SIZE_MIN, [2.0, 0.0, 0.0]),
            |c| c.point_parameter(0xdead, [2.0, 0.0, 0.0]),
            |c| c.line_width(-1.0),
            |c| c.polygon_stipple(|_| Ok(Some(&[0u8; 128][..]))),
            |c| c.get_polygon_stipple(|_| panic!("must not write")),
        ];
        for command in commands {
            command(&mut ctx);
            assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        }
        assert_eq!(ctx.state, before);
    }
}
