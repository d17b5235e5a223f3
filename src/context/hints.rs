//! glHint and glClampColor: small state setters with their own validation.
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;

impl Context {
    /// glHint: any of the GL 2.1 targets, mode GL_FASTEST, GL_NICEST or GL_DONT_CARE.
    pub fn hint(&mut self, target: GLenum, mode: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            return self.error(GL_INVALID_ENUM);
        }
        let hints = &mut self.state.hint;
        let slot = match target {
            GL_PERSPECTIVE_CORRECTION_HINT => &mut hints.perspective_correction,
            GL_POINT_SMOOTH_HINT => &mut hints.point_smooth,
            GL_LINE_SMOOTH_HINT => &mut hints.line_smooth,
            GL_POLYGON_SMOOTH_HINT => &mut hints.polygon_smooth,
            GL_FOG_HINT => &mut hints.fog,
            GL_GENERATE_MIPMAP_HINT => &mut hints.generate_mipmap,
            GL_TEXTURE_COMPRESSION_HINT => &mut hints.texture_compression,
            GL_FRAGMENT_SHADER_DERIVATIVE_HINT => &mut hints.fragment_shader_derivative,
            _ => return self.error(GL_INVALID_ENUM),
        };
        *slot = mode;
    }

    /// glClampColor (and OSMesaColorClamp): target CLAMP_VERTEX/FRAGMENT/READ_COLOR, value
    /// GL_TRUE, GL_FALSE or GL_FIXED_ONLY.
    pub fn clamp_color(&mut self, target: GLenum, clamp: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !(clamp == GL_TRUE as GLenum || clamp == GL_FALSE as GLenum || clamp == GL_FIXED_ONLY) {
            return self.error(GL_INVALID_ENUM);
        }
        match target {
            GL_CLAMP_VERTEX_COLOR => self.state.lighting.clamp_vertex_color = clamp,
            GL_CLAMP_FRAGMENT_COLOR => self.state.color.clamp_fragment_color = clamp,
            GL_CLAMP_READ_COLOR => self.state.color.clamp_read_color = clamp,
            _ => self.error(GL_INVALID_ENUM),
        }
    }
}
