//! Polygon offset (glPolygonOffset, EXT_polygon_offset_clamp): the depth offset of a
//! filled triangle, and its bound.
use crate::framebuffer::format::DepthEncoding;
use crate::setup::jobs::triangle::WindowVertex;

/// A polygon offset bounded by GL_POLYGON_OFFSET_CLAMP as EXT_polygon_offset_clamp says:
/// at most `clamp` when it is positive, at least `clamp` when negative, unbounded when it
/// is 0 (or NaN).
pub fn clamp_offset(offset: f32, clamp: f32) -> f32 {
    if clamp > 0.0 {
        offset.min(clamp)
    } else if clamp < 0.0 {
        offset.max(clamp)
    } else {
        offset
    }
}

/// The smallest resolvable difference r of a depth buffer for a primitive whose depths are
/// `z`: 1 / (2ⁿ − 1) for n-bit unorm depth; for float depth (GL 3.0 §3.6.5,
/// ARB_depth_buffer_float) 2^(e − 23), e the exponent of the largest |z|. That one is
/// computed on the bit pattern as Mesa's offset stage does, including its clamp to 0 when
/// e − 23 falls below the smallest exponent (llvmpipe's triangle setup omits that clamp and
/// scales by a huge negative number for depths below 2⁻¹⁰³, which no program relies on).
pub fn depth_resolution(depth: DepthEncoding, z: impl Iterator<Item = f32>) -> f32 {
    match depth {
        DepthEncoding::Unorm(0) => 0.0,
        DepthEncoding::Unorm(bits) => 1.0 / ((1u64 << bits) - 1) as f32,
        DepthEncoding::Float => {
            let max = z.fold(0.0f32, |m, z| m.max(z.abs()));
            let exponent = (max.to_bits() & (0xff << 23)) as i32;
            f32::from_bits((exponent - (23 << 23)).max(0) as u32)
        }
    }
}

/// glPolygonOffset's depth offset for a triangle: factor × max depth slope + units × r,
/// where r is the smallest resolvable difference of the depth buffer.
pub fn polygon_offset<const N: usize>(w: &[WindowVertex<N>; 3], factor: f32, units: f32, depth: DepthEncoding) -> f32 {
    let (x1, y1, z1) = (w[1].x - w[0].x, w[1].y - w[0].y, w[1].z - w[0].z);
    let (x2, y2, z2) = (w[2].x - w[0].x, w[2].y - w[0].y, w[2].z - w[0].z);
    let det = x1 * y2 - x2 * y1;
    let slope = if det != 0.0 {
        let dzdx = (z1 * y2 - z2 * y1) / det;
        let dzdy = (x1 * z2 - x2 * z1) / det;
        dzdx.abs().max(dzdy.abs())
    } else {
        0.0
    };
    let r = depth_resolution(depth, w.iter().map(|v| v.z));
    factor * slope + units * r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_clamp_bounds_the_offset_on_its_own_side_only() {
        assert_eq!(clamp_offset(0.3, 0.1), 0.1);
        assert_eq!(clamp_offset(0.05, 0.1), 0.05);
        assert_eq!(clamp_offset(-0.3, 0.1), -0.3);
        assert_eq!(clamp_offset(-0.3, -0.1), -0.1);
        assert_eq!(clamp_offset(0.3, -0.1), 0.3);
        assert_eq!(clamp_offset(0.3, 0.0), 0.3);
        assert_eq!(clamp_offset(-0.3, f32::NAN), -0.3);
    }
}
