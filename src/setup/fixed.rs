//! Integer division rounding towards −∞ and +∞, for the fixed-point setups (triangles,
//! lines): solving an edge equation for the first or last covered pixel centre of a row
//! needs the rounding the sign of the edge asks for, which `/` (towards zero) does not give.

/// Floor division for i64 (rounds towards −∞).
#[inline]
pub fn div_floor(n: i64, d: i64) -> i64 {
    let q = n / d;
    if (n % d != 0) && ((n < 0) != (d < 0)) {
        q - 1
    } else {
        q
    }
}

/// Ceiling division for i64 (rounds towards +∞).
#[inline]
pub fn div_ceil(n: i64, d: i64) -> i64 {
    -div_floor(-n, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounds_towards_the_named_infinity_for_every_sign() {
        assert_eq!([div_floor(7, 2), div_floor(-7, 2), div_floor(7, -2), div_floor(-7, -2)], [3, -4, -4, 3]);
        assert_eq!([div_ceil(7, 2), div_ceil(-7, 2), div_ceil(7, -2), div_ceil(-7, -2)], [4, -3, -3, 4]);
        assert_eq!([div_floor(-8, 2), div_ceil(-8, 2)], [-4, -4]);
    }
}
