//! The comparison function of the alpha, depth and stencil tests and of depth textures.

use super::enums::*;
use super::types::GLenum;

/// A comparison function for alpha, depth and stencil tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl CompareFunc {
    /// Every function, in GL's enum order (`GL_NEVER` … `GL_ALWAYS`).
    pub const ALL: [CompareFunc; 8] = [
        Self::Never,
        Self::Less,
        Self::Equal,
        Self::LessEqual,
        Self::Greater,
        Self::NotEqual,
        Self::GreaterEqual,
        Self::Always,
    ];

    pub fn from_gl(e: GLenum) -> Option<Self> {
        Some(match e {
            GL_NEVER => Self::Never,
            GL_LESS => Self::Less,
            GL_EQUAL => Self::Equal,
            GL_LEQUAL => Self::LessEqual,
            GL_GREATER => Self::Greater,
            GL_NOTEQUAL => Self::NotEqual,
            GL_GEQUAL => Self::GreaterEqual,
            GL_ALWAYS => Self::Always,
            _ => return None,
        })
    }

    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Never => GL_NEVER,
            Self::Less => GL_LESS,
            Self::Equal => GL_EQUAL,
            Self::LessEqual => GL_LEQUAL,
            Self::Greater => GL_GREATER,
            Self::NotEqual => GL_NOTEQUAL,
            Self::GreaterEqual => GL_GEQUAL,
            Self::Always => GL_ALWAYS,
        }
    }
}
