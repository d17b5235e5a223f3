//! Setters of the per-fragment operations' state (alpha test, stencil, depth, blending, logic
//! op, fog), with their validation.
//!
//! Validation follows GL 2.1: factors, equations and modes of later versions or extensions
//! tessera does not expose are GL_INVALID_ENUM. Mesa 22 (a GL 4.5 context) accepts more:
//! GL_SRC_ALPHA_SATURATE as a destination factor and the GL_SRC1_* factors
//! (ARB_blend_func_extended), and the KHR_blend_equation_advanced modes in glBlendEquation.
//!
//! Stencil follows Mesa's three-face model (see [`StencilState`]): glStencilFunc, glStencilOp
//! and glStencilMask set the EXT back face alone while GL_ACTIVE_STENCIL_FACE_EXT is GL_BACK
//! (whether or not GL_STENCIL_TEST_TWO_SIDE_EXT is enabled), and front and back otherwise;
//! the *Separate calls never touch the EXT back face.
//!
//! Colors (alpha reference, blend color, fog color) are stored as given and clamped where
//! they are used or queried, because fragment color clamping may be off (ARB_color_buffer_float).
use super::state::{StencilFace, StencilState};
use super::Context;
use crate::fragment::blend::{Blend, BlendEquation, BlendFactor, BlendFunc};
use crate::fragment::fog::{Fog, FogMode};
use crate::fragment::logic_op::LogicOp;
use crate::fragment::stencil::{StencilFace as CompiledStencilFace, StencilOp};
use crate::fragment::{AlphaTest, FragmentState, StencilTest};
use crate::framebuffer::ColorFormat;
use crate::gl::enums::*;
use crate::gl::limits::MAX_DRAW_BUFFERS;
use crate::gl::types::GLenum;
use crate::gl::CompareFunc;

/// Whether `factor` is a legal GL 2.1 blend factor, as source (`source`) or destination.
pub fn is_blend_factor(factor: GLenum, source: bool) -> bool {
    match factor {
        GL_ZERO
        | GL_ONE
        | GL_SRC_COLOR
        | GL_ONE_MINUS_SRC_COLOR
        | GL_DST_COLOR
        | GL_ONE_MINUS_DST_COLOR
        | GL_SRC_ALPHA
        | GL_ONE_MINUS_SRC_ALPHA
        | GL_DST_ALPHA
        | GL_ONE_MINUS_DST_ALPHA
        | GL_CONSTANT_COLOR
        | GL_ONE_MINUS_CONSTANT_COLOR
        | GL_CONSTANT_ALPHA
        | GL_ONE_MINUS_CONSTANT_ALPHA => true,
        // GL 2.1 4.1.8: "SRC_ALPHA_SATURATE is valid only for source RGB and alpha".
        GL_SRC_ALPHA_SATURATE => source,
        _ => false,
    }
}

/// Whether `mode` is a GL 2.1 blend equation.
pub fn is_blend_equation(mode: GLenum) -> bool {
    matches!(mode, GL_FUNC_ADD | GL_FUNC_SUBTRACT | GL_FUNC_REVERSE_SUBTRACT | GL_MIN | GL_MAX)
}

/// Whether `op` is one of the sixteen logic ops (GL_CLEAR ..= GL_SET).
pub fn is_logic_op(op: GLenum) -> bool {
    (GL_CLEAR..=GL_SET).contains(&op)
}

/// Whether `op` is a stencil operation.
pub fn is_stencil_op(op: GLenum) -> bool {
    matches!(op, GL_KEEP | GL_ZERO | GL_REPLACE | GL_INCR | GL_DECR | GL_INVERT | GL_INCR_WRAP | GL_DECR_WRAP)
}

/// Mesa's INT_TO_FLOAT, computed in single precision as Mesa does: maps [-2³¹, 2³¹−1] onto
/// [-1, 1] by (2i + 1) / (2³² − 1); used for integer colors (glFogiv(GL_FOG_COLOR)).
pub fn int_to_normalized_float(i: i32) -> f32 {
    (2.0 * i as f32 + 1.0) * (1.0 / 4294967294.0)
}

/// The blend factor a validated GLenum names.
pub fn blend_factor(factor: GLenum) -> BlendFactor {
    match factor {
        GL_ZERO => BlendFactor::Zero,
        GL_SRC_COLOR => BlendFactor::SrcColor,
        GL_ONE_MINUS_SRC_COLOR => BlendFactor::OneMinusSrcColor,
        GL_DST_COLOR => BlendFactor::DstColor,
        GL_ONE_MINUS_DST_COLOR => BlendFactor::OneMinusDstColor,
        GL_SRC_ALPHA => BlendFactor::SrcAlpha,
        GL_ONE_MINUS_SRC_ALPHA => BlendFactor::OneMinusSrcAlpha,
        GL_DST_ALPHA => BlendFactor::DstAlpha,
        GL_ONE_MINUS_DST_ALPHA => BlendFactor::OneMinusDstAlpha,
        GL_CONSTANT_COLOR => BlendFactor::ConstantColor,
        GL_ONE_MINUS_CONSTANT_COLOR => BlendFactor::OneMinusConstantColor,
        GL_CONSTANT_ALPHA => BlendFactor::ConstantAlpha,
        GL_ONE_MINUS_CONSTANT_ALPHA => BlendFactor::OneMinusConstantAlpha,
        GL_SRC_ALPHA_SATURATE => BlendFactor::SrcAlphaSaturate,
        _ => BlendFactor::One,
    }
}

/// The blend equation a validated GLenum names.
pub fn blend_equation(mode: GLenum) -> BlendEquation {
    match mode {
        GL_FUNC_SUBTRACT => BlendEquation::Subtract,
        GL_FUNC_REVERSE_SUBTRACT => BlendEquation::ReverseSubtract,
        GL_MIN => BlendEquation::Min,
        GL_MAX => BlendEquation::Max,
        _ => BlendEquation::Add,
    }
}

/// The stencil operation a validated GLenum names.
pub fn stencil_op(op: GLenum) -> StencilOp {
    match op {
        GL_ZERO => StencilOp::Zero,
        GL_REPLACE => StencilOp::Replace,
        GL_INCR => StencilOp::Incr,
        GL_DECR => StencilOp::Decr,
        GL_INCR_WRAP => StencilOp::IncrWrap,
        GL_DECR_WRAP => StencilOp::DecrWrap,
        GL_INVERT => StencilOp::Invert,
        _ => StencilOp::Keep,
    }
}

/// One face's stencil state for an 8-bit stencil buffer: the reference clamped to
/// [0, 255] (GL 2.1 §4.1.5), the masks cut to 8 bits.
pub fn compile_stencil_face(face: &StencilFace) -> CompiledStencilFace {
    CompiledStencilFace {
        func: face.func,
        reference: face.reference.clamp(0, 255) as u8,
        value_mask: face.value_mask as u8,
        write_mask: face.write_mask as u8,
        sfail: stencil_op(face.fail),
        zfail: stencil_op(face.depth_fail),
        zpass: stencil_op(face.depth_pass),
    }
}

/// The faces a glStencil*Separate `face` names (front, back), or `None` if it is not a face.
fn separate_faces(face: GLenum) -> Option<(bool, bool)> {
    match face {
        GL_FRONT => Some((true, false)),
        GL_BACK => Some((false, true)),
        GL_FRONT_AND_BACK => Some((true, true)),
        _ => None,
    }
}

impl StencilState {
    /// Applies `set` to the faces a non-separate call addresses: the EXT back face alone when
    /// it is the active face, else front and back.
    fn for_active_faces(&mut self, set: impl Fn(&mut StencilFace)) {
        if self.active_face_back {
            set(&mut self.ext_back);
        } else {
            set(&mut self.front);
            set(&mut self.back);
        }
    }

    /// Applies `set` to the faces of a glStencil*Separate call.
    fn for_faces(&mut self, (front, back): (bool, bool), set: impl Fn(&mut StencilFace)) {
        if front {
            set(&mut self.front);
        }
        if back {
            set(&mut self.back);
        }
    }
}

impl Context {
    /// Compiles the alpha test, stencil, blending, logic op and dither state into
    /// `fragment`, whose color targets are written from the draw buffers `buffer_of[i]`
    /// (`None`: not written) of a framebuffer of `format` with `stencil_bits`.
    pub fn compile_fragment_ops(
        &self,
        fragment: &mut FragmentState,
        buffer_of: &[Option<usize>],
        format: ColorFormat,
        stencil_bits: u32,
    ) {
        let fog = &self.state.fog;
        fragment.color_sum = self.color_sum_active();
        fragment.fog = fog.enabled.then(|| Fog {
            mode: match fog.mode {
                GL_LINEAR => FogMode::Linear,
                GL_EXP2 => FogMode::Exp2,
                _ => FogMode::Exp,
            },
            start: fog.start,
            end: fog.end,
            density: fog.density,
            color: fog.color.map(|x| if x > 0.0 { x.min(1.0) } else { 0.0 }),
        });
        let c = &self.state.color;
        fragment.alpha = c.alpha_test.then_some(AlphaTest {
            func: c.alpha_func,
            reference: c.alpha_ref,
            // llvmpipe compares in 8 bits only for 8-bit targets: on RGB565 alpha 126/255
            // fails GEQUAL 126.2/255 (measured on Mesa 22.3.6), a float comparison.
            unorm8: matches!(format, ColorFormat::Unorm8 { .. }),
        });
        let st = &self.state.stencil;
        fragment.stencil = (st.test && stencil_bits > 0).then(|| StencilTest {
            front: compile_stencil_face(&st.front),
            back: compile_stencil_face(st.back_face_in_use()),
        });
        // The logic op replaces blending; it does not apply to float buffers, which blend.
        fragment.logic_op =
            (c.color_logic_op && !format.is_float()).then(|| LogicOp::from_truth_table(c.logic_op as u8));
        fragment.blend = buffer_of
            .iter()
            .map(|buffer| {
                let i = (*buffer)?;
                (c.blend[i] && fragment.logic_op.is_none()).then(|| {
                    let func = |src, dst, equation| BlendFunc {
                        src: blend_factor(src),
                        dst: blend_factor(dst),
                        equation: blend_equation(equation),
                    };
                    Blend {
                        rgb: func(c.blend_src_rgb[i], c.blend_dst_rgb[i], c.blend_equation_rgb[i]),
                        alpha: func(c.blend_src_alpha[i], c.blend_dst_alpha[i], c.blend_equation_alpha[i]),
                    }
                    .for_target(format.has_alpha())
                })
            })
            .collect();
        fragment.blend_color = c.blend_color;
        fragment.dither = c.dither && format == ColorFormat::Rgb565;
    }

    /// glDepthFunc.
    pub fn depth_func(&mut self, func: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        match CompareFunc::from_gl(func) {
            Some(f) => self.state.depth.func = f,
            None => self.error(GL_INVALID_ENUM),
        }
    }

    /// glAlphaFunc.
    pub fn alpha_func(&mut self, func: GLenum, reference: f32) {
        if !self.check_outside_begin_end() {
            return;
        }
        match CompareFunc::from_gl(func) {
            Some(f) => (self.state.color.alpha_func, self.state.color.alpha_ref) = (f, reference),
            None => self.error(GL_INVALID_ENUM),
        }
    }

    /// glStencilFunc: the active face(s).
    pub fn stencil_func(&mut self, func: GLenum, reference: i32, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(func) = CompareFunc::from_gl(func) else {
            return self.error(GL_INVALID_ENUM);
        };
        self.state.stencil.for_active_faces(|f| (f.func, f.reference, f.value_mask) = (func, reference, mask));
    }

    /// glStencilFuncSeparate.
    pub fn stencil_func_separate(&mut self, face: GLenum, func: GLenum, reference: i32, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let (Some(faces), Some(func)) = (separate_faces(face), CompareFunc::from_gl(func)) else {
            return self.error(GL_INVALID_ENUM);
        };
        self.state.stencil.for_faces(faces, |f| (f.func, f.reference, f.value_mask) = (func, reference, mask));
    }

    /// glStencilFuncSeparateATI: one function per face, one reference and mask for both.
    pub fn stencil_func_separate_ati(&mut self, front_func: GLenum, back_func: GLenum, reference: i32, mask: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let (Some(front), Some(back)) = (CompareFunc::from_gl(front_func), CompareFunc::from_gl(back_func)) else {
            return self.error(GL_INVALID_ENUM);
        };
        let s = &mut self.state.stencil;
        (s.front.func, s.front.reference, s.front.value_mask) = (front, reference, mask);
        (s.back.func, s.back.reference, s.back.value_mask) = (back, reference, mask);
    }

    /// glStencilOp: the active face(s).
    pub fn stencil_op(&mut self, fail: GLenum, depth_fail: GLenum, depth_pass: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if ![fail, depth_fail, depth_pass].into_iter().all(is_stencil_op) {
            return self.error(GL_INVALID_ENUM);
        }
        self.state.stencil.for_active_faces(|f| (f.fail, f.depth_fail, f.depth_pass) = (fail, depth_fail, depth_pass));
    }

    /// glStencilOpSeparate.
    pub fn stencil_op_separate(&mut self, face: GLenum, fail: GLenum, depth_fail: GLenum, depth_pass: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        let faces = separate_faces(face);
        let (Some(faces), true) = (faces, [fail, depth_fail, depth_pass].into_iter().all(is_stencil_op)) else {
            return self.error(GL_INVALID_ENUM);
        };
        self.state.stencil.for_faces(faces, |f| (f.fail, f.depth_fail, f.depth_pass) = (fail, depth_fail, depth_pass));
    }

    /// glStencilMask: the active face(s) (glStencilMaskSeparate is `stencil_mask`).
    pub fn stencil_mask_active(&mut self, mask: u32) {
        if self.check_outside_begin_end() {
            self.state.stencil.for_active_faces(|f| f.write_mask = mask);
        }
    }

    /// glActiveStencilFaceEXT.
    pub fn active_stencil_face(&mut self, face: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        match face {
            GL_FRONT | GL_BACK => self.state.stencil.active_face_back = face == GL_BACK,
            _ => self.error(GL_INVALID_ENUM),
        }
    }

    /// The draw buffers an indexed blend call addresses (`None`: all of them), or
    /// GL_INVALID_VALUE for an index beyond GL_MAX_DRAW_BUFFERS.
    fn blend_buffers(&mut self, buffer: Option<u32>) -> Option<std::ops::Range<usize>> {
        match buffer {
            None => Some(0..MAX_DRAW_BUFFERS),
            Some(b) if (b as usize) < MAX_DRAW_BUFFERS => Some(b as usize..b as usize + 1),
            Some(_) => {
                self.error(GL_INVALID_VALUE);
                None
            }
        }
    }

    /// glBlendFuncSeparate (`buffer` None) and glBlendFuncSeparatei; glBlendFunc(i) passes
    /// the same factors for RGB and alpha.
    pub fn blend_func(&mut self, buffer: Option<u32>, src_rgb: GLenum, dst_rgb: GLenum, src_a: GLenum, dst_a: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(buffers) = self.blend_buffers(buffer) else { return };
        let legal = is_blend_factor(src_rgb, true)
            && is_blend_factor(dst_rgb, false)
            && is_blend_factor(src_a, true)
            && is_blend_factor(dst_a, false);
        if !legal {
            return self.error(GL_INVALID_ENUM);
        }
        let c = &mut self.state.color;
        for i in buffers {
            (c.blend_src_rgb[i], c.blend_dst_rgb[i]) = (src_rgb, dst_rgb);
            (c.blend_src_alpha[i], c.blend_dst_alpha[i]) = (src_a, dst_a);
        }
    }

    /// glBlendEquationSeparate (`buffer` None) and glBlendEquationSeparatei; glBlendEquation(i)
    /// passes the same mode twice.
    pub fn blend_equation(&mut self, buffer: Option<u32>, rgb: GLenum, alpha: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(buffers) = self.blend_buffers(buffer) else { return };
        if !is_blend_equation(rgb) || !is_blend_equation(alpha) {
            return self.error(GL_INVALID_ENUM);
        }
        let c = &mut self.state.color;
        for i in buffers {
            (c.blend_equation_rgb[i], c.blend_equation_alpha[i]) = (rgb, alpha);
        }
    }

    /// glBlendColor.
    pub fn blend_color(&mut self, rgba: [f32; 4]) {
        if self.check_outside_begin_end() {
            self.state.color.blend_color = rgba;
        }
    }

    /// glLogicOp.
    pub fn logic_op(&mut self, op: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if is_logic_op(op) {
            self.state.color.logic_op = op;
        } else {
            self.error(GL_INVALID_ENUM);
        }
    }

    /// glFogfv (and glFogf, glFogi: `params[0]` the value, the rest 0, as Mesa passes them).
    /// Enumerated values arrive as floats and are truncated to integers, as in Mesa.
    pub fn fog(&mut self, pname: GLenum, params: [f32; 4]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let value = params[0];
        let as_enum = value as i32 as GLenum;
        let fog = &mut self.state.fog;
        match pname {
            GL_FOG_MODE if matches!(as_enum, GL_LINEAR | GL_EXP | GL_EXP2) => fog.mode = as_enum,
            // NaN is not negative: Mesa accepts it.
            GL_FOG_DENSITY if value < 0.0 => self.error(GL_INVALID_VALUE),
            GL_FOG_DENSITY => fog.density = value,
            GL_FOG_START => fog.start = value,
            GL_FOG_END => fog.end = value,
            GL_FOG_INDEX => fog.index = value,
            GL_FOG_COLOR => fog.color = params,
            GL_FOG_COORD_SRC if matches!(as_enum, GL_FOG_COORD | GL_FRAGMENT_DEPTH) => fog.coord_src = as_enum,
            GL_FOG_DISTANCE_MODE_NV
                if matches!(as_enum, GL_EYE_RADIAL_NV | GL_EYE_PLANE | GL_EYE_PLANE_ABSOLUTE_NV) =>
            {
                fog.distance_mode = as_enum
            }
            // A known pname with an illegal value, or an unknown pname.
            _ => self.error(GL_INVALID_ENUM),
        }
    }

    /// glFogiv: the color maps integers onto [-1, 1]; other values convert as numbers.
    pub fn fog_integers(&mut self, pname: GLenum, params: [i32; 4]) {
        let floats =
            if pname == GL_FOG_COLOR { params.map(int_to_normalized_float) } else { [params[0] as f32, 0.0, 0.0, 0.0] };
        self.fog(pname, floats)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};

    fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 16);
        Context::new(ContextConfig { visual })
    }

    #[test]
    fn source_alpha_saturate_is_a_source_factor_only() {
        assert!(is_blend_factor(GL_SRC_ALPHA_SATURATE, true));
        assert!(!is_blend_factor(GL_SRC_ALPHA_SATURATE, false));
        for f in [GL_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_ZERO] {
            assert!(is_blend_factor(f, true) && is_blend_factor(f, false), "{f:#x}");
        }
        // ARB_blend_func_extended and non-factors.
        for f in [GL_SRC1_ALPHA, 0x88F9, GL_FUNC_ADD, GL_ALPHA, 2] {
            assert!(!is_blend_factor(f, true) && !is_blend_factor(f, false), "{f:#x}");
        }
    }

    #[test]
    fn blend_equations_logic_ops_and_stencil_ops() {
        assert!([GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX]
            .into_iter()
            .all(is_blend_equation));
        // GL_LOGIC_OP (EXT_blend_logic_op) and GL_MULTIPLY_KHR are not GL 2.1 equations.
        assert!(!is_blend_equation(0x0BF1) && !is_blend_equation(0x9294) && !is_blend_equation(GL_ONE));
        assert_eq!((0..0x2000).filter(|&op| is_logic_op(op)).count(), 16);
        assert!(is_logic_op(GL_CLEAR) && is_logic_op(GL_SET) && !is_logic_op(GL_SET + 1));
        assert_eq!((0..0x10000).filter(|&op| is_stencil_op(op)).count(), 8);
        assert!(is_stencil_op(GL_ZERO) && !is_stencil_op(GL_ONE));
    }

    #[test]
    fn integer_colors_map_as_mesa_s_int_to_float() {
        // Measured on Mesa 22 through glFogiv(GL_FOG_COLOR) with clamping off.
        assert_eq!(int_to_normalized_float(i32::MAX), 1.0);
        assert_eq!(int_to_normalized_float(-i32::MAX), -1.0);
        assert_eq!(int_to_normalized_float(0x4000_0000), 0.5);
        assert_eq!(int_to_normalized_float(0), 2.3283064e-10);
    }

    #[test]
    fn invalid_blend_calls_change_nothing() {
        let mut ctx = context();
        let before = ctx.state.color.clone();
        ctx.blend_func(None, GL_ONE, GL_SRC_ALPHA_SATURATE, GL_ONE, GL_ONE);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.blend_func(Some(8), GL_ONE, GL_ONE, GL_ONE, GL_ONE);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        // The index is checked before the factors.
        ctx.blend_func(Some(8), 0x9999, GL_ONE, GL_ONE, GL_ONE);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.blend_equation(Some(3), GL_MIN, GL_LOGIC_OP_MODE);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.logic_op(GL_SET + 1);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.color, before);
    }

    #[test]
    fn indexed_blend_calls_set_one_buffer_and_plain_ones_all() {
        let mut ctx = context();
        ctx.blend_func(None, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
        ctx.blend_func(Some(7), GL_SRC_ALPHA_SATURATE, GL_DST_COLOR, GL_ZERO, GL_ONE);
        ctx.blend_equation(Some(2), GL_MIN, GL_MAX);
        let c = &ctx.state.color;
        assert_eq!(c.blend_src_rgb[..7], [GL_SRC_ALPHA; 7]);
        assert_eq!((c.blend_src_rgb[7], c.blend_dst_rgb[7]), (GL_SRC_ALPHA_SATURATE, GL_DST_COLOR));
        assert_eq!((c.blend_src_alpha[7], c.blend_dst_alpha[7]), (GL_ZERO, GL_ONE));
        assert_eq!(c.blend_dst_alpha[6], GL_ZERO);
        assert_eq!((c.blend_equation_rgb[2], c.blend_equation_alpha[2]), (GL_MIN, GL_MAX));
        assert_eq!(c.blend_equation_rgb[1], GL_FUNC_ADD);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn non_separate_stencil_calls_follow_the_active_face() {
        let mut ctx = context();
        ctx.stencil_func(GL_LESS, 1, 0xf);
        ctx.active_stencil_face(GL_BACK);
        // Two-side disabled: the EXT back face is still what the calls address.
        ctx.stencil_func(GL_EQUAL, 2, 0x3);
        ctx.stencil_op(GL_INCR, GL_DECR, GL_INVERT);
        ctx.stencil_mask_active(5);
        let s = &ctx.state.stencil;
        assert_eq!(
            (s.front.func, s.back.func, s.ext_back.func),
            (CompareFunc::Less, CompareFunc::Less, CompareFunc::Equal)
        );
        assert_eq!((s.back.reference, s.ext_back.reference, s.ext_back.value_mask), (1, 2, 3));
        assert_eq!((s.front.fail, s.back.fail, s.ext_back.fail), (GL_KEEP, GL_KEEP, GL_INCR));
        assert_eq!((s.back.write_mask, s.ext_back.write_mask), (!0, 5));
        assert_eq!(s.active_face().func, CompareFunc::Equal);
        assert_eq!(s.back_face_in_use().func, CompareFunc::Less);
        ctx.set_capability(GL_STENCIL_TEST_TWO_SIDE_EXT, true);
        assert_eq!(ctx.state.stencil.back_face_in_use().func, CompareFunc::Equal);
        // The separate calls never touch the EXT face.
        ctx.stencil_func_separate(GL_FRONT_AND_BACK, GL_GREATER, 3, 7);
        ctx.stencil_func_separate_ati(GL_NEVER, GL_ALWAYS, 4, 9);
        let s = &ctx.state.stencil;
        assert_eq!(
            (s.front.func, s.back.func, s.ext_back.func),
            (CompareFunc::Never, CompareFunc::Always, CompareFunc::Equal)
        );
        assert_eq!((s.front.reference, s.back.value_mask), (4, 9));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn invalid_stencil_calls_change_nothing() {
        let mut ctx = context();
        let before = ctx.state.stencil.clone();
        ctx.stencil_func(GL_NEVER + 8, 0, 0);
        ctx.stencil_func_separate(GL_FRONT_LEFT, GL_LESS, 0, 0);
        ctx.stencil_func_separate_ati(GL_LESS, 0x9999, 0, 0);
        ctx.stencil_op(GL_KEEP, GL_ONE, GL_KEEP);
        ctx.stencil_op_separate(GL_BACK, GL_KEEP, GL_KEEP, GL_NONE + 1);
        ctx.stencil_op_separate(GL_LEFT, GL_KEEP, GL_KEEP, GL_KEEP);
        ctx.active_stencil_face(GL_FRONT_AND_BACK);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.stencil, before);
        ctx.inside_begin_end = true;
        ctx.active_stencil_face(GL_BACK);
        ctx.stencil_mask_active(0);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.state.stencil, before);
    }

    #[test]
    fn fog_parameters_are_validated_as_mesa_does() {
        let mut ctx = context();
        let before = ctx.state.fog.clone();
        for (pname, value, error) in [
            (GL_FOG_MODE, 0x9999 as f32, GL_INVALID_ENUM),
            (GL_FOG_MODE, GL_EYE_PLANE as f32, GL_INVALID_ENUM),
            (GL_FOG_DENSITY, -0.5, GL_INVALID_VALUE),
            (GL_FOG_COORD_SRC, GL_FOG_COORD_SRC as f32, GL_INVALID_ENUM),
            (GL_FOG_DISTANCE_MODE_NV, GL_LINEAR as f32, GL_INVALID_ENUM),
            (GL_FOG_HINT, 0.0, GL_INVALID_ENUM),
            (GL_FOG, 1.0, GL_INVALID_ENUM),
        ] {
            ctx.fog(pname, [value, 0.0, 0.0, 0.0]);
            assert_eq!(ctx.take_error(), error, "{pname:#x} {value}");
        }
        assert_eq!(ctx.state.fog, before);
        ctx.fog(GL_FOG_MODE, [GL_LINEAR as f32 + 0.75, 0.0, 0.0, 0.0]);
        ctx.fog(GL_FOG_DENSITY, [0.0; 4]);
        ctx.fog(GL_FOG_START, [-7.0, 0.0, 0.0, 0.0]);
        ctx.fog(GL_FOG_END, [-8.0, 0.0, 0.0, 0.0]);
        ctx.fog(GL_FOG_INDEX, [2.5, 0.0, 0.0, 0.0]);
        ctx.fog(GL_FOG_COLOR, [2.0, -1.0, 0.5, 0.25]);
        ctx.fog_integers(GL_FOG_COORD_SRC, [GL_FOG_COORD as i32, 0, 0, 0]);
        ctx.fog_integers(GL_FOG_DISTANCE_MODE_NV, [GL_EYE_RADIAL_NV as i32, 0, 0, 0]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let f = &ctx.state.fog;
        assert_eq!((f.mode, f.density, f.start, f.end, f.index), (GL_LINEAR, 0.0, -7.0, -8.0, 2.5));
        assert_eq!((f.color, f.coord_src, f.distance_mode), ([2.0, -1.0, 0.5, 0.25], GL_FOG_COORD, GL_EYE_RADIAL_NV));
        assert_eq!(ctx.get_floats(GL_FOG_COLOR), Some(vec![1.0, 0.0, 0.5, 0.25]));
        ctx.fog_integers(GL_FOG_COLOR, [i32::MAX, 0x4000_0000, 0, -i32::MAX]);
        assert_eq!(ctx.state.fog.color, [1.0, 0.5, 2.3283064e-10, -1.0]);
    }
}
