//! Immediate mode: what glBegin accepts, the vertex a glVertex call makes from the current
//! attributes, and glRect's polygon.
use super::Vertex;
use crate::context::state::CurrentState;
use crate::gl::enums::*;
use crate::gl::types::GLenum;

/// Whether `mode` is a primitive mode of GL 2.1 (GL_POINTS … GL_POLYGON). Mesa 22, at GL 4.5,
/// also takes the adjacency modes; GL 2.1 has none of them, so they are GL_INVALID_ENUM here.
pub fn is_primitive_mode(mode: GLenum) -> bool {
    mode <= GL_POLYGON
}

/// The vertex at `position` with every other attribute taken from `current`.
#[inline]
pub fn vertex_from_current(current: &CurrentState, position: [f32; 4]) -> Vertex {
    Vertex {
        position,
        color: current.color,
        secondary_color: current.secondary_color,
        normal: current.normal,
        tex_coords: current.tex_coords,
        fog_coord: current.fog_coord,
        edge_flag: current.edge_flag,
    }
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
    fn vertices_snapshot_every_current_attribute() {
        let mut current =
            CurrentState { color: [0.1, 0.2, 0.3, 0.4], edge_flag: false, fog_coord: 9.0, ..Default::default() };
        current.tex_coords[3] = [5.0, 6.0, 7.0, 8.0];
        let v = vertex_from_current(&current, [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(v.position, [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(v.color, [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(v.secondary_color, [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(v.normal, [0.0, 0.0, 1.0]);
        assert_eq!(v.tex_coords[3], [5.0, 6.0, 7.0, 8.0]);
        assert_eq!(v.tex_coords[0], [0.0, 0.0, 0.0, 1.0]);
        assert_eq!((v.fog_coord, v.edge_flag), (9.0, false));
    }

    #[test]
    fn rect_corners_run_counterclockwise_from_the_first_corner() {
        assert_eq!(
            rect_positions([1.0, 2.0], [3.0, 4.0]),
            [[1.0, 2.0, 0.0, 1.0], [3.0, 2.0, 0.0, 1.0], [3.0, 4.0, 0.0, 1.0], [1.0, 4.0, 0.0, 1.0]]
        );
    }
}
