//! Packing rows of depth and stencil values into GL_DEPTH_COMPONENT, GL_STENCIL_INDEX and
//! GL_DEPTH_STENCIL client data, as Mesa 22's `read_depth_pixels`, `read_stencil_pixels` and
//! `read_depth_stencil_pixels` do.
//!
//! Depth values arrive as stored, in a [`DepthEncoding`]: n-bit fixed point (16, 24 or 32
//! bits) or float (ARB_depth_buffer_float). For fixed point Mesa has two paths, and so does
//! this module, because their results differ:
//! - GL_UNSIGNED_INT without byte swapping, and GL_UNSIGNED_INT_24_8 without byte swapping,
//!   widen the integer by bit replication (24-bit 0x19999a → 0x19999a19);
//! - everything else converts to float first (`d / (2ⁿ − 1)`) and then uses Mesa's depth
//!   macros, most of which truncate (0x19999a → GL_UNSIGNED_INT 0x19999a1f when swapped).
//!
//! Stencil indices are masked to the type's non-sign bits (GL_BYTE keeps 7 bits); GL_BITMAP
//! keeps bit 0 of each index and writes only the bits of the pixels read, as the layout of
//! GL 2.1 §3.6.4 places them (Mesa 22 cannot read stencil as GL_BITMAP: it loops forever).
use super::convert::{depth_pack, float_to_half};
use super::ClientType;
use crate::framebuffer::format::{unorm_widen_to_u32, DepthEncoding};

/// Writes `value`'s `N` bytes (native order, or reversed).
#[inline(always)]
fn put<const N: usize>(out: &mut [u8], bytes: [u8; N], swap: bool) {
    let mut bytes = bytes;
    if swap {
        bytes.reverse();
    }
    out[..N].copy_from_slice(&bytes);
}

/// Packs one row of stored depth values as GL_DEPTH_COMPONENT of type `ty` into `out`.
pub fn pack_depth_row(values: &[u32], encoding: DepthEncoding, ty: ClientType, swap: bool, out: &mut [u8]) {
    fn each<const N: usize>(values: &[u32], out: &mut [u8], swap: bool, f: impl Fn(u32) -> [u8; N]) {
        for (o, &v) in out.chunks_exact_mut(N).zip(values) {
            put(o, f(v), swap);
        }
    }
    let d = |v: u32| encoding.decode(v);
    match (ty, encoding) {
        (ClientType::UnsignedInt, DepthEncoding::Unorm(bits)) if !swap => match bits {
            // Bit replication, specialized for the common widths.
            16 => each(values, out, false, |v| ((v << 16) | v).to_ne_bytes()),
            24 => each(values, out, false, |v| ((v << 8) | (v >> 16)).to_ne_bytes()),
            _ => each(values, out, false, |v| unorm_widen_to_u32(v, bits).to_ne_bytes()),
        },
        (ClientType::UnsignedInt, _) => each(values, out, true, |v| depth_pack::to_u32(d(v)).to_ne_bytes()),
        (ClientType::UnsignedByte, _) => each(values, out, false, |v| [depth_pack::to_u8(d(v))]),
        (ClientType::Byte, _) => each(values, out, false, |v| depth_pack::to_i8(d(v)).to_ne_bytes()),
        (ClientType::UnsignedShort, _) => each(values, out, swap, |v| depth_pack::to_u16(d(v)).to_ne_bytes()),
        (ClientType::Short, _) => each(values, out, swap, |v| depth_pack::to_i16(d(v)).to_ne_bytes()),
        (ClientType::Int, _) => each(values, out, swap, |v| depth_pack::to_i32(d(v)).to_ne_bytes()),
        (ClientType::Float, _) => each(values, out, swap, |v| d(v).to_ne_bytes()),
        (ClientType::HalfFloat, _) => each(values, out, swap, |v| float_to_half(d(v)).to_ne_bytes()),
        // Not depth types (validated before).
        (
            ClientType::Packed(_)
            | ClientType::Bitmap
            | ClientType::UnsignedInt24_8
            | ClientType::Float32UnsignedInt24_8Rev,
            _,
        ) => {}
    }
}

/// Packs one row of stencil indices as GL_STENCIL_INDEX of type `ty` (not GL_BITMAP).
pub fn pack_stencil_row(values: &[u8], ty: ClientType, swap: bool, out: &mut [u8]) {
    fn each<const N: usize>(values: &[u8], out: &mut [u8], swap: bool, f: impl Fn(u8) -> [u8; N]) {
        for (o, &v) in out.chunks_exact_mut(N).zip(values) {
            put(o, f(v), swap);
        }
    }
    match ty {
        ClientType::UnsignedByte => out[..values.len()].copy_from_slice(values),
        ClientType::Byte => each(values, out, false, |s| [s & 0x7f]),
        ClientType::UnsignedShort | ClientType::Short => each(values, out, swap, |s| (s as u16).to_ne_bytes()),
        ClientType::UnsignedInt | ClientType::Int => each(values, out, swap, |s| (s as u32).to_ne_bytes()),
        ClientType::Float => each(values, out, swap, |s| (s as f32).to_ne_bytes()),
        ClientType::HalfFloat => each(values, out, swap, |s| float_to_half(s as f32).to_ne_bytes()),
        ClientType::Packed(_)
        | ClientType::Bitmap
        | ClientType::UnsignedInt24_8
        | ClientType::Float32UnsignedInt24_8Rev => {}
    }
}

/// Packs one row of stencil indices as GL_BITMAP: bit 0 of index `i` goes to bit
/// `first_bit + i` of `out` (most significant bit of each byte first unless `lsb_first`);
/// other bits keep their value.
pub fn pack_stencil_bitmap_row(values: &[u8], first_bit: usize, lsb_first: bool, out: &mut [u8]) {
    for (i, &s) in values.iter().enumerate() {
        let bit = first_bit + i;
        let mask = if lsb_first { 1u8 << (bit % 8) } else { 0x80u8 >> (bit % 8) };
        let byte = &mut out[bit / 8];
        *byte = if s & 1 != 0 { *byte | mask } else { *byte & !mask };
    }
}

/// Packs one row of stored depth and stencil values as GL_DEPTH_STENCIL /
/// GL_UNSIGNED_INT_24_8: depth in the high 24 bits, stencil in the low 8.
pub fn pack_depth_stencil_row(depth: &[u32], encoding: DepthEncoding, stencil: &[u8], swap: bool, out: &mut [u8]) {
    fn each(depth: &[u32], stencil: &[u8], out: &mut [u8], swap: bool, word: impl Fn(u32, u8) -> u32) {
        for ((o, &z), &s) in out.chunks_exact_mut(4).zip(depth).zip(stencil) {
            put(o, word(z, s).to_ne_bytes(), swap);
        }
    }
    let bits = match encoding {
        DepthEncoding::Unorm(bits) => bits,
        DepthEncoding::Float => 0,
    };
    if swap || encoding == DepthEncoding::Float {
        // Mesa's general path (taken when swapping, and for float depth): through float,
        // truncated.
        each(depth, stencil, out, swap, |z, s| (depth_pack::to_u24(encoding.decode(z)) << 8) | s as u32);
    } else if bits == 24 {
        each(depth, stencil, out, false, |z, s| (z << 8) | s as u32);
    } else {
        each(depth, stencil, out, false, |z, s| (unorm_widen_to_u32(z, bits) & 0xffff_ff00) | s as u32);
    }
}

/// Packs one row of stored depth and stencil values as GL_DEPTH_STENCIL /
/// GL_FLOAT_32_UNSIGNED_INT_24_8_REV: per pixel the depth as a float in [0, 1], then a
/// 32-bit word holding the stencil index (each word byte-swapped on its own when `swap`).
pub fn pack_depth_stencil_float_row(
    depth: &[u32],
    encoding: DepthEncoding,
    stencil: &[u8],
    swap: bool,
    out: &mut [u8],
) {
    for ((o, &z), &s) in out.chunks_exact_mut(8).zip(depth).zip(stencil) {
        put(&mut o[..4], encoding.decode(z).to_ne_bytes(), swap);
        put(&mut o[4..], (s as u32).to_ne_bytes(), swap);
    }
}

/// One GL_FLOAT_32_UNSIGNED_INT_24_8_REV pixel (8 bytes): its depth (clamped to [0, 1],
/// as every depth stored) and stencil index.
pub fn unpack_depth_stencil_float(bytes: &[u8], swap: bool) -> (f32, u8) {
    let word = |at: usize| {
        let mut b = [bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]];
        if swap {
            b.reverse();
        }
        b
    };
    let depth = f32::from_ne_bytes(word(0));
    let depth = f32::from_bits(crate::framebuffer::format::float_depth_bits(depth));
    (depth, u32::from_ne_bytes(word(4)) as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn depth(values: &[u32], bits: u32, ty: ClientType, swap: bool) -> Vec<u8> {
        let mut out = vec![0xcd; values.len() * ty.element_bytes()];
        pack_depth_row(values, DepthEncoding::Unorm(bits), ty, swap, &mut out);
        out
    }

    #[test]
    fn depth_matches_mesa_measurements() {
        // glClearDepth(0.1) of a 24-bit depth buffer, read on Mesa 22.
        let z = [0x19999a];
        assert_eq!(depth(&z, 24, ClientType::UnsignedInt, false), 0x1999_9a19_u32.to_ne_bytes());
        assert_eq!(depth(&z, 24, ClientType::UnsignedInt, true), 0x1999_9a1f_u32.to_be_bytes());
        assert_eq!(depth(&z, 24, ClientType::UnsignedShort, false), 0x199a_u16.to_ne_bytes());
        assert_eq!(depth(&z, 24, ClientType::Float, false), 0x3dcc_ccd1_u32.to_ne_bytes()); // 0.100000031
        assert_eq!(depth(&z, 24, ClientType::UnsignedByte, false), [0x19]);
        assert_eq!(depth(&z, 24, ClientType::Byte, false), [0x0c]);
        assert_eq!(depth(&z, 24, ClientType::Short, false), 0x0ccc_u16.to_ne_bytes());
        assert_eq!(depth(&z, 24, ClientType::Int, false), 0x0ccc_cd0f_u32.to_ne_bytes());
        assert_eq!(depth(&z, 24, ClientType::HalfFloat, false), 0x2e66_u16.to_ne_bytes());
        assert_eq!(depth(&[0x199a], 16, ClientType::UnsignedInt, false), 0x199a_199a_u32.to_ne_bytes());
        assert_eq!(depth(&[0xffff_ffff], 32, ClientType::UnsignedInt, false), [0xff; 4]);
    }

    #[test]
    fn depth_stencil_packs_24_8() {
        let mut out = [0u8; 8];
        pack_depth_stencil_row(&[0x19999a, 0xffffff], DepthEncoding::Unorm(24), &[0x5a, 0x01], false, &mut out);
        assert_eq!(out[..4], 0x1999_9a5a_u32.to_ne_bytes());
        assert_eq!(out[4..], 0xffff_ff01_u32.to_ne_bytes());
        // Swapped: Mesa's float path, then bytes reversed (measured: 19 99 9a 00).
        pack_depth_stencil_row(&[0x19999a], DepthEncoding::Unorm(24), &[0], true, &mut out);
        assert_eq!(out[..4], [0x19, 0x99, 0x9a, 0x00]);
        // 16- and 32-bit depth keep their top 24 bits.
        pack_depth_stencil_row(&[0x8001, 0x1234_5678], DepthEncoding::Unorm(16), &[3, 4], false, &mut out);
        assert_eq!(out[..4], 0x8001_8003_u32.to_ne_bytes());
        pack_depth_stencil_row(&[0x1234_5678], DepthEncoding::Unorm(32), &[4], false, &mut out);
        assert_eq!(out[..4], 0x1234_5604_u32.to_ne_bytes());
    }

    #[test]
    fn stencil_types_mask_and_convert() {
        let s = [2, 0, 0xff, 0x81];
        let mut out = [0u8; 16];
        pack_stencil_row(&s, ClientType::Byte, false, &mut out);
        assert_eq!(out[..4], [2, 0, 0x7f, 0x01]);
        pack_stencil_row(&s, ClientType::UnsignedShort, true, &mut out);
        assert_eq!(out[..8], [0, 2, 0, 0, 0, 0xff, 0, 0x81]);
        pack_stencil_row(&s, ClientType::Float, false, &mut out);
        assert_eq!(out[8..12], 255.0f32.to_ne_bytes());
        pack_stencil_row(&s, ClientType::HalfFloat, false, &mut out);
        assert_eq!(out[..2], 0x4000_u16.to_ne_bytes());
    }

    #[test]
    fn bitmaps_set_only_the_pixels_bits() {
        let s = [1, 0, 3, 2, 1, 1, 1, 1, 0, 1];
        let mut out = [0xaa, 0xaa, 0xaa];
        // Bits 3..13, most significant first.
        pack_stencil_bitmap_row(&s, 3, false, &mut out);
        assert_eq!(out, [0b1011_0101, 0b1110_1010, 0xaa]);
        let mut out = [0x00, 0x00];
        pack_stencil_bitmap_row(&s, 0, true, &mut out);
        assert_eq!(out, [0b1111_0101, 0b0000_0010]);
    }
}
