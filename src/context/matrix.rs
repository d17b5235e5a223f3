//! The matrix stacks: modelview, projection, texture (per unit) and color.
//!
//! Matrices are single precision, as in Mesa; glLoadMatrixd and friends convert.
use super::state::MAX_TEXTURE_UNITS;
use glam::Mat4;

/// The four kinds of matrix stack; each starts with the identity.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixStacks {
    pub modelview: Vec<Mat4>,
    pub projection: Vec<Mat4>,
    pub texture: [Vec<Mat4>; MAX_TEXTURE_UNITS],
    pub color: Vec<Mat4>,
}

impl Default for MatrixStacks {
    fn default() -> Self {
        MatrixStacks {
            modelview: vec![Mat4::IDENTITY],
            projection: vec![Mat4::IDENTITY],
            texture: std::array::from_fn(|_| vec![Mat4::IDENTITY]),
            color: vec![Mat4::IDENTITY],
        }
    }
}

/// The top of a stack (stacks are never empty).
fn top(stack: &[Mat4]) -> Mat4 {
    stack.last().copied().unwrap_or(Mat4::IDENTITY)
}

impl MatrixStacks {
    pub fn modelview(&self) -> Mat4 {
        top(&self.modelview)
    }

    pub fn projection(&self) -> Mat4 {
        top(&self.projection)
    }

    pub fn texture(&self, unit: usize) -> Mat4 {
        self.texture.get(unit).map_or(Mat4::IDENTITY, |s| top(s))
    }

    pub fn color(&self) -> Mat4 {
        top(&self.color)
    }
}
