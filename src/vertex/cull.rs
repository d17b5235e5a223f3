//! Facing and culling (glFrontFace, glCullFace): the one front-face decision every
//! primitive path takes, from a triangle's signed area in GL's y-up window space.
use crate::gl::enums::{GL_BACK, GL_FRONT, GL_FRONT_AND_BACK};
use crate::gl::types::GLenum;
use crate::setup::jobs::triangle::WindowVertex;

/// Twice the signed area of a window-space triangle, positive when counter-clockwise.
#[inline]
pub fn area2<const N: usize>(w: &[WindowVertex<N>; 3]) -> f32 {
    (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y)
}

/// Whether a triangle with twice the signed area `area2` in GL's y-up window space
/// (positive when counter-clockwise) faces front under GL_FRONT_FACE (`front_ccw`: GL_CCW).
/// The only place that decides facing: paths that compute the area otherwise (y-down
/// window space, other vertex order) pass it in the y-up orientation.
#[inline]
pub fn faces_front(front_ccw: bool, area2: f32) -> bool {
    (area2 > 0.0) == front_ccw
}

/// Whether glCullFace's `cull` (when GL_CULL_FACE is on) removes a triangle facing `front`.
#[inline]
pub fn culls(cull: Option<GLenum>, front: bool) -> bool {
    match cull {
        Some(GL_FRONT_AND_BACK) => true,
        Some(GL_FRONT) => front,
        Some(GL_BACK) => !front,
        _ => false,
    }
}
