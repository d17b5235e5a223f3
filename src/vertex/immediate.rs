//! Immediate mode: what glBegin accepts and glRect's polygon.
use crate::gl::enums::*;
use crate::gl::types::GLenum;

/// Whether `mode` is a primitive mode of GL 2.1 (GL_POINTS … GL_POLYGON). Mesa 22, at GL 4.5,
/// also takes the adjacency modes; GL 2.1 has none of them, so they are GL_INVALID_ENUM here.
pub fn is_primitive_mode(mode: GLenum) -> bool {
    mode <= GL_POLYGON
}

/// glRect's corners in the order section 2.11 gives them: (x1, y1), (x2, y1), (x2, y2),
/// (x1, y2), at z = 0, drawn as one GL_POLYGON.
pub fn rect_positions([x1, y1]: [f32; 2], [x2, y2]: [f32; 2]) -> [[f32; 4]; 4] {
    [[x1, y1, 0.0, 1.0], [x2, y1, 0.0, 1.0], [x2, y2, 0.0, 1.0], [x1, y2, 0.0, 1.0]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primitive_modes_are_points_to_polygon() {
        assert!((GL_POINTS..=GL_POLYGON).all(is_primitive_mode));
        assert!(!is_primitive_mode(0xA), "GL_LINES_ADJACENCY");
        assert!(!is_primitive_mode(0xE), "GL_PATCHES");
        assert!(!is_primitive_mode(u32::MAX));
    }

    #[test]
    fn rect_corners_run_counterclockwise_from_the_first_corner() {
        assert_eq!(
            rect_positions([1.0, 2.0], [3.0, 4.0]),
            [[1.0, 2.0, 0.0, 1.0], [3.0, 2.0, 0.0, 1.0], [3.0, 4.0, 0.0, 1.0], [1.0, 4.0, 0.0, 1.0]]
        );
    }
}
