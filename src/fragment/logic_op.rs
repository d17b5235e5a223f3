//! The sixteen color logic operations, applied bitwise to the stored representation of a
//! target (8-bit channels, or packed RGB565 words).
//!
//! Each operation is its truth table: bit 0 is the result for (s, d) = (1, 1), bit 1 for
//! (1, 0), bit 2 for (0, 1), bit 3 for (0, 0). GL's enums GL_CLEAR..GL_SET are 0x1500 plus
//! exactly this table, so the context converts with `op & 0xf`, and the span functions
//! evaluate the table branch-free with four masks chosen once per call.

/// A logic operation; the discriminant is its truth table (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum LogicOp {
    Clear = 0,
    And = 1,
    AndReverse = 2,
    Copy = 3,
    AndInverted = 4,
    Noop = 5,
    Xor = 6,
    Or = 7,
    Nor = 8,
    Equiv = 9,
    Invert = 10,
    OrReverse = 11,
    CopyInverted = 12,
    OrInverted = 13,
    Nand = 14,
    Set = 15,
}

impl LogicOp {
    /// All sixteen, in truth-table (and GL enum) order.
    pub const ALL: [LogicOp; 16] = [
        Self::Clear,
        Self::And,
        Self::AndReverse,
        Self::Copy,
        Self::AndInverted,
        Self::Noop,
        Self::Xor,
        Self::Or,
        Self::Nor,
        Self::Equiv,
        Self::Invert,
        Self::OrReverse,
        Self::CopyInverted,
        Self::OrInverted,
        Self::Nand,
        Self::Set,
    ];

    /// The operation whose truth table is the low four bits of `table`.
    pub fn from_truth_table(table: u8) -> Self {
        Self::ALL[(table & 0xf) as usize]
    }

    /// The four all-ones-or-zero masks of the truth table, for 32-bit words.
    #[inline]
    fn masks(self) -> [u32; 4] {
        let t = self as u32;
        [0, 1, 2, 3].map(|b| 0u32.wrapping_sub((t >> b) & 1))
    }

    /// Applies the operation to one word (any width up to 32 bits; the caller truncates).
    #[inline]
    pub fn apply(self, s: u32, d: u32) -> u32 {
        let [sd, s_nd, ns_d, ns_nd] = self.masks();
        (s & d & sd) | (s & !d & s_nd) | (!s & d & ns_d) | (!s & !d & ns_nd)
    }
}

#[inline(always)]
fn apply_masks(m: &[u32; 4], s: u32, d: u32) -> u32 {
    (s & d & m[0]) | (s & !d & m[1]) | (!s & d & m[2]) | (!s & !d & m[3])
}

/// Applies `op` to 8-bit RGBA pixels for every bit of `live`: `dst = op(src, dst)`.
pub fn logic_op_unorm8(op: LogicOp, src: &[[u8; 4]], dst: &mut [[u8; 4]], live: u64) {
    let m = op.masks();
    for (i, (d, s)) in dst.iter_mut().zip(src).enumerate().take(super::MAX_SPAN) {
        if live & (1 << i) != 0 {
            let v = apply_masks(&m, u32::from_le_bytes(*s), u32::from_le_bytes(*d));
            *d = v.to_le_bytes();
        }
    }
}

/// Applies `op` to packed 16-bit pixels (RGB565) for every bit of `live`.
pub fn logic_op_u16(op: LogicOp, src: &[u16], dst: &mut [u16], live: u64) {
    let m = op.masks();
    for (i, (d, &s)) in dst.iter_mut().zip(src).enumerate().take(super::MAX_SPAN) {
        if live & (1 << i) != 0 {
            *d = apply_masks(&m, s as u32, *d as u32) as u16;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each operation on s = 0b1100, d = 0b1010: the result's bits, high to low, are the
    /// results for (1,1), (1,0), (0,1), (0,0), i.e. the table reversed.
    #[test]
    fn every_op_on_all_four_input_pairs() {
        let expect: [(LogicOp, u32); 16] = [
            (LogicOp::Clear, 0b0000),
            (LogicOp::And, 0b1000),
            (LogicOp::AndReverse, 0b0100),
            (LogicOp::Copy, 0b1100),
            (LogicOp::AndInverted, 0b0010),
            (LogicOp::Noop, 0b1010),
            (LogicOp::Xor, 0b0110),
            (LogicOp::Or, 0b1110),
            (LogicOp::Nor, 0b0001),
            (LogicOp::Equiv, 0b1001),
            (LogicOp::Invert, 0b0101),
            (LogicOp::OrReverse, 0b1101),
            (LogicOp::CopyInverted, 0b0011),
            (LogicOp::OrInverted, 0b1011),
            (LogicOp::Nand, 0b0111),
            (LogicOp::Set, 0b1111),
        ];
        for (op, want) in expect {
            assert_eq!(op.apply(0b1100, 0b1010) & 0xf, want, "{op:?}");
            assert_eq!(LogicOp::from_truth_table(op as u8 | 0xf0), op);
        }
    }

    #[test]
    fn unorm8_span_per_byte_and_live_mask() {
        let src = [[0x0f, 0xf0, 0xaa, 0x55], [1, 2, 3, 4]];
        let mut dst = [[0xff, 0x0f, 0x55, 0x55], [9, 9, 9, 9]];
        logic_op_unorm8(LogicOp::Xor, &src, &mut dst, 0b01);
        assert_eq!(dst, [[0xf0, 0xff, 0xff, 0x00], [9, 9, 9, 9]]);
        let mut dst = [[0xff, 0x0f, 0x55, 0x55]];
        logic_op_unorm8(LogicOp::CopyInverted, &src, &mut dst, 1);
        assert_eq!(dst, [[0xf0, 0x0f, 0x55, 0xaa]]);
    }

    #[test]
    fn rgb565_span_stays_in_16_bits() {
        let mut dst = [0xf800u16, 0x1234];
        logic_op_u16(LogicOp::Invert, &[0; 2], &mut dst, 0b11);
        assert_eq!(dst, [0x07ff, 0xedcb]);
        let mut dst = [0x1234u16];
        logic_op_u16(LogicOp::Set, &[0], &mut dst, 1);
        assert_eq!(dst, [0xffff]);
        logic_op_u16(LogicOp::AndReverse, &[0x0ff0], &mut dst, 1);
        assert_eq!(dst, [0x0000]);
    }
}
