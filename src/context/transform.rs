//! The transformation commands: glMatrixMode, the matrix stack and matrix commands,
//! glActiveTexture (which selects the texture matrix stack), glClipPlane and glClipControl.
//!
//! glClipControl (ARB_clip_control) chooses the clip-space conventions every vertex (drawn
//! or glRasterPos's) is mapped with: GL_ZERO_TO_ONE clips to 0 ≤ z_c ≤ w_c and maps z_ndc
//! onto the depth range as n + (f − n)·z_ndc, which with a float depth buffer and a
//! reversed projection keeps depth precision at any distance; GL_UPPER_LEFT negates y in
//! the viewport transform (Direct3D's convention), which mirrors the window winding of
//! every polygon, so the facing rule is mirrored too and GL_CCW still means
//! counter-clockwise in normalized device coordinates. [`Context::depth_transform`] and
//! [`Context::viewport_y_sign`] are the one place these mappings are decided.
//!
//! The arithmetic is [`super::matrix`]'s, single precision as in Mesa: double-precision entry
//! points convert their arguments to float first, and so glFrustum and glOrtho validate the
//! converted values (glFrustum(1, 1 + 1e-10, ...) is GL_INVALID_VALUE, as in Mesa, because
//! the float matrix would divide by zero).
//!
//! Deliberate differences from Mesa 22:
//! - glMatrixMode(GL_COLOR) selects the color matrix stack (the imaging subset's), which Mesa
//!   no longer has; the GL_COLOR_MATRIX queries answer accordingly.
//! - glMatrixMode(GL_TEXTUREi) and glMatrixMode(GL_MATRIXi_ARB) are GL_INVALID_ENUM. Mesa 22
//!   silently ignores the former (a bug) and accepts the latter (ARB_vertex_program, which
//!   tessera does not have).
//! - glActiveTexture accepts units up to the larger of GL_MAX_TEXTURE_COORDS and
//!   GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS (GL 2.0 section 2.7), 8 and 8 here; Mesa accepts all
//!   of its 192 combined image units.
//! - A NULL matrix or plane pointer is ignored (Mesa ignores NULL matrices but crashes on a
//!   NULL plane).
use super::matrix::{transform_row_vector, transpose, StackId};
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::{MAX_ACTIVE_TEXTURE_UNITS, MAX_CLIP_PLANES};
use crate::gl::types::GLenum;

impl Context {
    /// The stack glMatrixMode selected (GL_TEXTURE: the active unit's).
    pub fn current_stack(&self) -> StackId {
        match self.state.transform.matrix_mode {
            GL_PROJECTION => StackId::Projection,
            GL_TEXTURE => StackId::Texture(self.state.texture.active_unit),
            GL_COLOR => StackId::Color,
            _ => StackId::Modelview,
        }
    }

    /// glMatrixMode.
    pub fn matrix_mode(&mut self, mode: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        match mode {
            GL_MODELVIEW | GL_PROJECTION | GL_TEXTURE | GL_COLOR => self.state.transform.matrix_mode = mode,
            _ => self.error(GL_INVALID_ENUM),
        }
    }

    /// glActiveTexture: selects the unit of texture state and of the texture matrix stack.
    pub fn active_texture(&mut self, texture: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        match texture.checked_sub(GL_TEXTURE0) {
            Some(unit) if (unit as usize) < MAX_ACTIVE_TEXTURE_UNITS => self.state.texture.active_unit = unit as usize,
            _ => self.error(GL_INVALID_ENUM),
        }
    }

    /// glPushMatrix.
    pub fn push_matrix(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        let stack = self.current_stack();
        if !self.matrices.push(stack) {
            self.error(GL_STACK_OVERFLOW);
        }
    }

    /// glPopMatrix.
    pub fn pop_matrix(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        let stack = self.current_stack();
        if !self.matrices.pop(stack) {
            self.error(GL_STACK_UNDERFLOW);
        }
    }

    /// Runs a matrix command on the current matrix, outside glBegin/glEnd only.
    fn with_current_matrix(&mut self, f: impl FnOnce(&mut super::matrix::Matrix)) {
        if !self.check_outside_begin_end() {
            return;
        }
        let stack = self.current_stack();
        f(self.matrices.top_mut(stack));
    }

    /// glLoadIdentity.
    pub fn load_identity(&mut self) {
        self.with_current_matrix(|m| m.set_identity())
    }

    /// glLoadMatrix (column-major).
    pub fn load_matrix(&mut self, m: &[f32; 16]) {
        self.with_current_matrix(|top| top.load(m))
    }

    /// glMultMatrix (column-major).
    pub fn mult_matrix(&mut self, m: &[f32; 16]) {
        self.with_current_matrix(|top| top.multiply(m))
    }

    /// glLoadTransposeMatrix (row-major).
    pub fn load_transpose_matrix(&mut self, m: &[f32; 16]) {
        self.load_matrix(&transpose(m))
    }

    /// glMultTransposeMatrix (row-major).
    pub fn mult_transpose_matrix(&mut self, m: &[f32; 16]) {
        self.mult_matrix(&transpose(m))
    }

    /// glRotate: a zero angle changes nothing.
    pub fn rotate(&mut self, angle: f32, x: f32, y: f32, z: f32) {
        self.with_current_matrix(|m| {
            if angle != 0.0 {
                m.rotate(angle, x, y, z)
            }
        })
    }

    /// glScale.
    pub fn scale(&mut self, x: f32, y: f32, z: f32) {
        self.with_current_matrix(|m| m.scale(x, y, z))
    }

    /// glTranslate.
    pub fn translate(&mut self, x: f32, y: f32, z: f32) {
        self.with_current_matrix(|m| m.translate(x, y, z))
    }

    /// glFrustum: GL_INVALID_VALUE unless near and far are positive and the planes of each
    /// pair differ.
    pub fn frustum(&mut self, left: f64, right: f64, bottom: f64, top: f64, near: f64, far: f64) {
        let [l, r, b, t, n, f] = [left, right, bottom, top, near, far].map(|v| v as f32);
        if !self.check_outside_begin_end() {
            return;
        }
        if n <= 0.0 || f <= 0.0 || n == f || l == r || t == b {
            return self.error(GL_INVALID_VALUE);
        }
        self.with_current_matrix(|m| m.frustum(l, r, b, t, n, f))
    }

    /// glOrtho: GL_INVALID_VALUE when the planes of a pair coincide.
    pub fn ortho(&mut self, left: f64, right: f64, bottom: f64, top: f64, near: f64, far: f64) {
        let [l, r, b, t, n, f] = [left, right, bottom, top, near, far].map(|v| v as f32);
        if !self.check_outside_begin_end() {
            return;
        }
        if l == r || b == t || n == f {
            return self.error(GL_INVALID_VALUE);
        }
        self.with_current_matrix(|m| m.ortho(l, r, b, t, n, f))
    }

    /// The index of user clip plane `plane`, or GL_INVALID_ENUM.
    fn clip_plane_index(&mut self, plane: GLenum) -> Option<usize> {
        match plane.checked_sub(GL_CLIP_PLANE0) {
            Some(i) if (i as usize) < MAX_CLIP_PLANES => Some(i as usize),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glClipControl (ARB_clip_control).
    pub fn clip_control(&mut self, origin: GLenum, depth: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !matches!(origin, GL_LOWER_LEFT | GL_UPPER_LEFT) || !matches!(depth, GL_NEGATIVE_ONE_TO_ONE | GL_ZERO_TO_ONE)
        {
            self.error(GL_INVALID_ENUM);
            return;
        }
        let transform = &mut self.state.transform;
        (transform.clip_origin, transform.clip_depth_mode) = (origin, depth);
    }

    /// The depth part of the viewport transform, z_w = z_ndc · scale + offset, for the depth
    /// range and GL_CLIP_DEPTH_MODE: ((f − n)/2, (n + f)/2) for GL_NEGATIVE_ONE_TO_ONE,
    /// (f − n, n) for GL_ZERO_TO_ONE. In double precision, rounded once by the caller, as
    /// Mesa computes its viewport scale and translation.
    pub(crate) fn depth_transform(&self) -> (f64, f64) {
        let [near, far] = self.state.viewport.depth_range;
        if self.clip_zero_to_one() {
            (far - near, near)
        } else {
            ((far - near) * 0.5, (far + near) * 0.5)
        }
    }

    /// Whether clip-space z is clipped to [0, w] (GL_ZERO_TO_ONE) rather than [−w, w].
    pub(crate) fn clip_zero_to_one(&self) -> bool {
        self.state.transform.clip_depth_mode == GL_ZERO_TO_ONE
    }

    /// The sign of the y scale of the viewport transform: −1 under GL_UPPER_LEFT.
    pub(crate) fn viewport_y_sign(&self) -> f32 {
        if self.state.transform.clip_origin == GL_UPPER_LEFT {
            -1.0
        } else {
            1.0
        }
    }

    /// glClipPlane: the plane (converted to float) is multiplied by the inverse of the current
    /// modelview matrix and kept in eye coordinates.
    pub fn clip_plane(&mut self, plane: GLenum, equation: [f64; 4]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(index) = self.clip_plane_index(plane) else {
            return;
        };
        let modelview = self.matrices.top_mut(StackId::Modelview);
        if modelview.is_dirty() {
            modelview.analyse();
        }
        let eye = transform_row_vector(equation.map(|v| v as f32), modelview.inverse());
        self.state.transform.clip_plane_equations[index] = eye.map(f64::from);
        // Mesa brings the plane into clip space when it is enabled, analysing the projection
        // matrix on the way (which can change the flags its later products depend on).
        if self.state.transform.clip_planes[index] {
            self.matrices.top_mut(StackId::Projection).analyse();
        }
    }

    /// glGetClipPlane: the plane in eye coordinates.
    pub fn get_clip_plane(&mut self, plane: GLenum) -> Option<[f64; 4]> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let index = self.clip_plane_index(plane)?;
        Some(self.state.transform.clip_plane_equations[index])
    }

    /// The elements of the top matrix of `stack` (for glGet).
    pub fn matrix_elements(&self, stack: StackId) -> [f32; 16] {
        *self.matrices.top(stack).elements()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
    use crate::gl::limits::{MAX_MODELVIEW_STACK_DEPTH, MAX_PROJECTION_STACK_DEPTH};

    fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 0);
        Context::new(ContextConfig { visual })
    }

    #[test]
    fn matrix_mode_selects_the_stack_and_rejects_other_enums() {
        let mut ctx = context();
        assert_eq!(ctx.current_stack(), StackId::Modelview);
        for (mode, stack) in
            [(GL_PROJECTION, StackId::Projection), (GL_COLOR, StackId::Color), (GL_TEXTURE, StackId::Texture(0))]
        {
            ctx.matrix_mode(mode);
            assert_eq!(ctx.current_stack(), stack);
        }
        ctx.active_texture(GL_TEXTURE0 + 3);
        assert_eq!(ctx.current_stack(), StackId::Texture(3));
        for bad in [GL_TEXTURE0, GL_MODELVIEW + 3, 0] {
            ctx.matrix_mode(bad);
            assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        }
        assert_eq!(ctx.state.transform.matrix_mode, GL_TEXTURE);
        ctx.active_texture(GL_TEXTURE0 + MAX_ACTIVE_TEXTURE_UNITS as GLenum);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.active_texture(GL_TEXTURE0 - 1);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.texture.active_unit, 3);
    }

    #[test]
    fn stacks_overflow_and_underflow_per_mode() {
        let mut ctx = context();
        ctx.pop_matrix();
        assert_eq!(ctx.take_error(), GL_STACK_UNDERFLOW);
        for _ in 1..MAX_MODELVIEW_STACK_DEPTH {
            ctx.push_matrix();
        }
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.translate(1.0, 0.0, 0.0);
        ctx.push_matrix();
        assert_eq!(ctx.take_error(), GL_STACK_OVERFLOW);
        ctx.matrix_mode(GL_PROJECTION);
        for _ in 1..MAX_PROJECTION_STACK_DEPTH {
            ctx.push_matrix();
        }
        ctx.push_matrix();
        assert_eq!(ctx.take_error(), GL_STACK_OVERFLOW);
        ctx.matrix_mode(GL_MODELVIEW);
        ctx.pop_matrix();
        assert_eq!(ctx.matrices.modelview().w_axis.x, 0.0);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn frustum_and_ortho_validate_the_float_values() {
        let mut ctx = context();
        for args in [
            [0.0, 1.0, 0.0, 1.0, 0.0, 1.0],
            [0.0, 1.0, 0.0, 1.0, 1.0, -1.0],
            [0.0, 1.0, 0.0, 1.0, 1.0, 1.0],
            [1.0, 1.0, 0.0, 1.0, 1.0, 2.0],
            [0.0, 1.0, 2.0, 2.0, 1.0, 2.0],
            [1.0, 1.0 + 1e-10, 0.0, 1.0, 1.0, 2.0],
            [0.0, 1.0, 0.0, 1.0, 1e-50, 2.0],
        ] {
            let [l, r, b, t, n, f] = args;
            ctx.frustum(l, r, b, t, n, f);
            assert_eq!(ctx.take_error(), GL_INVALID_VALUE, "{args:?}");
        }
        ctx.ortho(1.0, 1.0, 0.0, 1.0, 0.0, 1.0);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.ortho(0.0, 1.0, 0.0, 1.0, 1.0, 1.0);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        assert_eq!(ctx.matrices.modelview(), glam::Mat4::IDENTITY);
        ctx.ortho(0.0, 1.0, 0.0, 1.0, -1.0, -2.0);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.matrices.modelview().z_axis.z, 2.0);
    }

    #[test]
    fn transpose_forms_transpose() {
        let mut ctx = context();
        let m: [f32; 16] = std::array::from_fn(|i| i as f32 + 1.0);
        ctx.load_transpose_matrix(&m);
        assert_eq!(ctx.matrix_elements(StackId::Modelview), transpose(&m));
        ctx.load_identity();
        ctx.mult_transpose_matrix(&m);
        assert_eq!(ctx.matrix_elements(StackId::Modelview), transpose(&m));
    }

    #[test]
    fn clip_planes_go_to_eye_space_through_the_inverse_modelview() {
        let mut ctx = context();
        ctx.translate(0.0, 0.0, -5.0);
        ctx.scale(2.0, 2.0, 2.0);
        // The plane z = -1 in object space is z = -7 in eye space: (0,0,1,1) becomes
        // (0, 0, 1/2, 1 + 5/2).
        ctx.clip_plane(GL_CLIP_PLANE0 + 2, [0.0, 0.0, 1.0, 1.0]);
        assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE0 + 2), Some([0.0, 0.0, 0.5, 3.5]));
        assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE0), Some([0.0; 4]));
        // Stored as float, as Mesa keeps it.
        ctx.load_identity();
        ctx.clip_plane(GL_CLIP_PLANE0, [0.1, 0.0, 0.0, 0.0]);
        assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE0), Some([0.1f32 as f64, 0.0, 0.0, 0.0]));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.clip_plane(GL_CLIP_PLANE0 + MAX_CLIP_PLANES as GLenum, [1.0; 4]);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE0 - 1), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn everything_is_invalid_between_begin_and_end() {
        let mut ctx = context();
        ctx.inside_begin_end = true;
        let before = (ctx.matrices.clone(), ctx.state.clone());
        let commands: [fn(&mut Context); 15] = [
            |c| c.matrix_mode(GL_PROJECTION),
            |c| c.active_texture(GL_TEXTURE1),
            |c| c.push_matrix(),
            |c| c.pop_matrix(),
            |c| c.load_identity(),
            |c| c.load_matrix(&[2.0; 16]),
            |c| c.mult_matrix(&[2.0; 16]),
            |c| c.rotate(30.0, 1.0, 0.0, 0.0),
            |c| c.scale(2.0, 2.0, 2.0),
            |c| c.translate(1.0, 0.0, 0.0),
            |c| c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0),
            |c| c.ortho(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0),
            |c| c.clip_plane(GL_CLIP_PLANE0, [1.0; 4]),
            |c| assert_eq!(c.get_clip_plane(GL_CLIP_PLANE0), None),
            |c| c.clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE),
        ];
        for command in commands {
            command(&mut ctx);
            assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        }
        assert_eq!((ctx.matrices.clone(), ctx.state.clone()), before);
    }

    #[test]
    fn clip_control_accepts_only_its_enums_and_changes_nothing_on_error() {
        let mut ctx = context();
        let clip = |c: &Context| (c.state.transform.clip_origin, c.state.transform.clip_depth_mode);
        assert_eq!(clip(&ctx), (GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE));
        ctx.clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        assert_eq!((ctx.take_error(), clip(&ctx)), (GL_NO_ERROR, (GL_UPPER_LEFT, GL_ZERO_TO_ONE)));
        // A bad value of either argument leaves both alone.
        for (origin, depth) in [(GL_LOWER_LEFT, GL_LOWER_LEFT), (GL_ZERO_TO_ONE, GL_NEGATIVE_ONE_TO_ONE), (0, 0)] {
            ctx.clip_control(origin, depth);
            assert_eq!((ctx.take_error(), clip(&ctx)), (GL_INVALID_ENUM, (GL_UPPER_LEFT, GL_ZERO_TO_ONE)));
        }
    }

    /// The depth mapping of ARB_clip_control's equations: z_w = (f − n)/2 · z_ndc + (n + f)/2
    /// by default, (f − n) · z_ndc + n under GL_ZERO_TO_ONE (so z_ndc = 0 is the near value).
    #[test]
    fn zero_to_one_maps_ndc_zero_to_the_near_value() {
        let mut ctx = context();
        ctx.state.viewport.depth_range = [0.25, 0.75];
        let z = |c: &Context, ndc: f64| {
            let (scale, offset) = c.depth_transform();
            ndc * scale + offset
        };
        assert_eq!([z(&ctx, -1.0), z(&ctx, 0.0), z(&ctx, 1.0)], [0.25, 0.5, 0.75]);
        ctx.clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        assert_eq!([z(&ctx, 0.0), z(&ctx, 0.5), z(&ctx, 1.0)], [0.25, 0.5, 0.75]);
        // Reversed range: n = 1, f = 0.
        ctx.state.viewport.depth_range = [1.0, 0.0];
        assert_eq!([z(&ctx, 0.0), z(&ctx, 1.0)], [1.0, 0.0]);
    }

    /// glRasterPos goes through the same transform as vertices: under GL_ZERO_TO_ONE a point
    /// at z_ndc = 0 lies at the near value and one at z_ndc = −0.5 is clipped (it is inside
    /// by default); under GL_UPPER_LEFT y is mirrored about the viewport's centre.
    #[test]
    fn raster_position_follows_clip_control() {
        let visual = FramebufferConfig::single_buffered(
            ColorFormat::Unorm8 { alpha: true },
            DepthStencilFormat::Packed24 { depth: true, stencil: true },
            0,
        );
        let (mut ctx, _d) = Context::with_test_drawable(visual, 100, 100);
        ctx.state.viewport = crate::context::state::ViewportState { rect: [10, 20, 80, 60], depth_range: [0.25, 0.75] };
        let window = |c: &mut Context, p: [f32; 4]| {
            c.raster_pos(p);
            let r = c.state.current.raster;
            r.valid.then_some(r.window)
        };
        assert_eq!(window(&mut ctx, [0.5, 0.5, 0.0, 1.0]), Some([70.0, 65.0, 0.5, 1.0]));
        assert!(window(&mut ctx, [0.0, 0.0, -0.5, 1.0]).is_some());
        ctx.clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        assert_eq!(window(&mut ctx, [0.5, 0.5, 0.0, 1.0]), Some([70.0, 35.0, 0.25, 1.0]));
        assert_eq!(window(&mut ctx, [0.0, 0.0, 1.0, 1.0]), Some([50.0, 50.0, 0.75, 1.0]));
        assert_eq!(window(&mut ctx, [0.0, 0.0, -0.5, 1.0]), None);
        // glWindowPos is in window coordinates: unaffected.
        ctx.window_pos([3.0, 4.0, 0.5]);
        assert_eq!(ctx.state.current.raster.window, [3.0, 4.0, 0.5, 1.0]);
    }
}
