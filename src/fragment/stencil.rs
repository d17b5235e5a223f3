//! The stencil test and stencil operations on 8-bit stencil values, as span functions.
//!
//! The order is the seed's: the stencil test runs first; fragments that fail it take the
//! `sfail` operation and are dropped; the survivors are depth-tested, and take `zfail` or
//! `zpass` by the depth result (`zpass` for all of them when there is no depth test).
//! Stencil values are loaded from their storage (the high byte of a packed 24/8 word, or a
//! separate u8 plane) into a span array, tested and updated there, and stored back.

use super::{passes, MAX_SPAN};
use crate::gl::CompareFunc;

/// A stencil operation (glStencilOp).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    /// Increment, clamped at the largest value.
    Incr,
    /// Decrement, clamped at 0.
    Decr,
    IncrWrap,
    DecrWrap,
    Invert,
}

/// The stencil state of one face, compiled per draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilFace {
    pub func: CompareFunc,
    /// The reference value, already clamped to [0, 255] (GL clamps it to the buffer's range).
    pub reference: u8,
    pub value_mask: u8,
    pub write_mask: u8,
    pub sfail: StencilOp,
    pub zfail: StencilOp,
    pub zpass: StencilOp,
}

/// The result of applying `op` to the stored value `v`, before the write mask.
#[inline]
pub fn apply_op(op: StencilOp, reference: u8, v: u8) -> u8 {
    match op {
        StencilOp::Keep => v,
        StencilOp::Zero => 0,
        StencilOp::Replace => reference,
        StencilOp::Incr => v.saturating_add(1),
        StencilOp::Decr => v.saturating_sub(1),
        StencilOp::IncrWrap => v.wrapping_add(1),
        StencilOp::DecrWrap => v.wrapping_sub(1),
        StencilOp::Invert => !v,
    }
}

/// Tests the stencil values of `live`: `(reference & mask) func (stored & mask)`. Returns
/// the fragments that pass.
pub fn stencil_test(face: &StencilFace, stored: &[u8], live: u64) -> u64 {
    let reference = (face.reference & face.value_mask) as u32;
    let mut pass = 0u64;
    for (i, &s) in stored.iter().enumerate().take(MAX_SPAN) {
        if passes(face.func, reference, (s & face.value_mask) as u32) {
            pass |= 1 << i;
        }
    }
    pass & live
}

/// Applies `op` to the values of the fragments in `which`, changing only the bits of
/// `face.write_mask`.
pub fn apply_op_span(face: &StencilFace, op: StencilOp, values: &mut [u8], which: u64) {
    if op == StencilOp::Keep || face.write_mask == 0 || which == 0 {
        return;
    }
    let keep = !face.write_mask;
    for (i, v) in values.iter_mut().enumerate().take(MAX_SPAN) {
        if which & (1 << i) != 0 {
            *v = (*v & keep) | (apply_op(op, face.reference, *v) & face.write_mask);
        }
    }
}

/// Runs the stencil test on `values` for the fragments of `live`, then `depth_test` (given
/// the stencil survivors, returning those that also pass depth), and updates `values` with
/// sfail, zfail and zpass. Returns the fragments that pass both tests.
pub fn stencil_and_depth(face: &StencilFace, values: &mut [u8], live: u64, depth_test: impl FnOnce(u64) -> u64) -> u64 {
    let stencil_pass = stencil_test(face, values, live);
    let depth_pass = depth_test(stencil_pass) & stencil_pass;
    apply_op_span(face, face.sfail, values, live & !stencil_pass);
    apply_op_span(face, face.zfail, values, stencil_pass & !depth_pass);
    apply_op_span(face, face.zpass, values, depth_pass);
    depth_pass
}

/// Copies the stencil bytes (bits 24..32) of packed 24/8 words into `out`.
pub fn load_packed(words: &[u32], out: &mut [u8]) {
    for (o, w) in out.iter_mut().zip(words) {
        *o = (w >> 24) as u8;
    }
}

/// Stores stencil bytes back into the high byte of packed 24/8 words, keeping the depth.
pub fn store_packed(values: &[u8], words: &mut [u32]) {
    for (w, &v) in words.iter_mut().zip(values) {
        *w = (*w & 0x00ff_ffff) | (v as u32) << 24;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use CompareFunc as C;
    use StencilOp as O;

    fn face(func: C, reference: u8, value_mask: u8, write_mask: u8) -> StencilFace {
        StencilFace { func, reference, value_mask, write_mask, sfail: O::Keep, zfail: O::Keep, zpass: O::Keep }
    }

    #[test]
    fn every_op_on_edge_values() {
        let r = 0x5a;
        let table: [(O, [u8; 4]); 8] = [
            (O::Keep, [0, 1, 0x80, 255]),
            (O::Zero, [0, 0, 0, 0]),
            (O::Replace, [r, r, r, r]),
            (O::Incr, [1, 2, 0x81, 255]),
            (O::Decr, [0, 0, 0x7f, 254]),
            (O::IncrWrap, [1, 2, 0x81, 0]),
            (O::DecrWrap, [255, 0, 0x7f, 254]),
            (O::Invert, [255, 254, 0x7f, 0]),
        ];
        for (op, want) in table {
            let got = [0u8, 1, 0x80, 255].map(|v| apply_op(op, r, v));
            assert_eq!(got, want, "{op:?}");
        }
    }

    #[test]
    fn write_mask_keeps_unmasked_bits() {
        let f = face(C::Always, 0xff, 0xff, 0x0f);
        let mut v = [0xa5u8, 0xa5, 0x3f];
        apply_op_span(&f, O::Replace, &mut v, 0b001);
        apply_op_span(&f, O::Invert, &mut v, 0b010);
        apply_op_span(&f, O::IncrWrap, &mut v, 0b100);
        // 0x3f + 1 = 0x40: only the low nibble (0) is written, the high nibble stays 3.
        assert_eq!(v, [0xaf, 0xaa, 0x30]);
    }

    #[test]
    fn every_function_with_value_mask() {
        // reference 0x13 & 0x0f = 3 against stored (low nibble) 2, 3, 4 with high bits set.
        let stored = [0xf2u8, 0x83, 0x14];
        let table: [(C, u64); 8] = [
            (C::Never, 0b000),
            (C::Less, 0b100),
            (C::Equal, 0b010),
            (C::LessEqual, 0b110),
            (C::Greater, 0b001),
            (C::NotEqual, 0b101),
            (C::GreaterEqual, 0b011),
            (C::Always, 0b111),
        ];
        for (func, want) in table {
            assert_eq!(stencil_test(&face(func, 0x13, 0x0f, 0xff), &stored, 0b111), want, "{func:?}");
        }
        assert_eq!(stencil_test(&face(C::Always, 0, 0xff, 0xff), &stored, 0b101), 0b101);
    }

    #[test]
    fn sfail_zfail_zpass_by_test_results() {
        let f = StencilFace { sfail: O::Zero, zfail: O::Incr, zpass: O::Replace, ..face(C::Equal, 7, 0xff, 0xff) };
        // Pixels: 0 fails stencil, 1 passes stencil fails depth, 2 passes both, 3 not live.
        let mut v = [1u8, 7, 7, 1];
        let mut seen = 0;
        let pass = stencil_and_depth(&f, &mut v, 0b0111, |m| {
            seen = m;
            0b0100
        });
        assert_eq!(seen, 0b0110, "depth sees only stencil survivors");
        assert_eq!(pass, 0b0100);
        assert_eq!(v, [0, 8, 7, 1]);
        // Depth reporting a fragment the stencil dropped does not make it pass.
        let mut v = [1u8, 7];
        assert_eq!(stencil_and_depth(&f, &mut v, 0b11, |_| 0b11), 0b10);
        assert_eq!(v, [0, 7]);
    }

    #[test]
    fn packed_high_byte_round_trip_keeps_depth() {
        let mut words = [0x12ab_cdefu32, 0xff00_0001];
        let mut v = [0u8; 2];
        load_packed(&words, &mut v);
        assert_eq!(v, [0x12, 0xff]);
        let f = StencilFace { zpass: O::IncrWrap, ..face(C::Always, 0, 0xff, 0xff) };
        stencil_and_depth(&f, &mut v, 0b11, |m| m);
        store_packed(&v, &mut words);
        assert_eq!(words, [0x13ab_cdef, 0x0000_0001]);
    }
}
