//! glLight, glLightModel, glMaterial, glColorMaterial and their queries: the lighting state
//! of GL 2.1 section 2.14, validated as the specification says.
//!
//! Positions and spot directions are transformed into eye coordinates when they are
//! specified (by the modelview matrix and by its upper 3×3, with Mesa's single-precision
//! expressions), so later modelview changes do not move a light. Integer parameters follow
//! Mesa: colors convert as normalized values (`int_to_normalized_float`), everything else by
//! a plain cast; as integers, queried colors map onto the integer range and other values are
//! truncated (glGetLightiv) or rounded (glGetMaterialiv's shininess and color indexes).
//!
//! GL_COLOR_MATERIAL makes the current color track the selected material parameters: the
//! material is updated from the current color when tracking is enabled, when glColorMaterial
//! changes what is tracked, at glColor outside glBegin/glEnd and at glEnd (as Mesa updates it
//! when it flushes the current attributes); between glBegin and glEnd each vertex's own
//! color is its material (see `crate::vertex::lighting`). glMaterial is legal between
//! glBegin and glEnd and applies to the vertices that follow it.
//!
//! Deliberate differences from Mesa 22: the scalar entry points (glLightf, glLightModelf,
//! glMaterialf and their integer forms) accept only single-valued parameters, as the
//! specification says; Mesa accepts vector parameters there too, filling the other
//! components with zeros or garbage.
use super::state::{Light, Material};
use super::Context;
use crate::context::fragment_state::int_to_normalized_float;
use crate::context::get::Value;
use crate::context::matrix::StackId;
use crate::gl::enums::*;
use crate::gl::limits::MAX_LIGHTS;
use crate::gl::types::GLenum;
use crate::vertex::lighting::set_material_parameter;

/// Largest GL_SHININESS and GL_SPOT_EXPONENT.
pub const MAX_SHININESS: f32 = 128.0;

/// How many values a glLight*v parameter takes (0: not a light parameter).
pub fn light_param_count(pname: GLenum) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
        GL_SPOT_DIRECTION => 3,
        GL_SPOT_EXPONENT
        | GL_SPOT_CUTOFF
        | GL_CONSTANT_ATTENUATION
        | GL_LINEAR_ATTENUATION
        | GL_QUADRATIC_ATTENUATION => 1,
        _ => 0,
    }
}

/// How many values a glLightModel*v parameter takes (0: not a light model parameter).
pub fn light_model_param_count(pname: GLenum) -> usize {
    match pname {
        GL_LIGHT_MODEL_AMBIENT => 4,
        GL_LIGHT_MODEL_LOCAL_VIEWER | GL_LIGHT_MODEL_TWO_SIDE | GL_LIGHT_MODEL_COLOR_CONTROL => 1,
        _ => 0,
    }
}

/// How many values a glMaterial*v parameter takes (0: not a material parameter).
pub fn material_param_count(pname: GLenum) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
        GL_COLOR_INDEXES => 3,
        GL_SHININESS => 1,
        _ => 0,
    }
}

/// Whether a parameter's integer form is a normalized color.
fn is_color(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE | GL_LIGHT_MODEL_AMBIENT
    )
}

/// Integer parameters as floats: colors as normalized values, the rest by a cast.
pub fn int_params_to_float(pname: GLenum, params: &[i32]) -> Vec<f32> {
    if is_color(pname) {
        params.iter().map(|&i| int_to_normalized_float(i)).collect()
    } else {
        params.iter().map(|&i| i as f32).collect()
    }
}

fn vec4(p: &[f32]) -> [f32; 4] {
    [p[0], p[1], p[2], p[3]]
}

/// Which materials a face enum addresses: front, back or both.
fn faces(face: GLenum) -> Option<&'static [usize]> {
    match face {
        GL_FRONT => Some(&[0]),
        GL_BACK => Some(&[1]),
        GL_FRONT_AND_BACK => Some(&[0, 1]),
        _ => None,
    }
}

/// Copies `color` into the material parameters glColorMaterial selected.
pub fn track_color(materials: &mut [Material; 2], face: GLenum, mode: GLenum, color: [f32; 4]) {
    for &f in faces(face).unwrap_or(&[]) {
        set_material_parameter(&mut materials[f], mode, &color);
    }
}

impl Context {
    fn light_index(&mut self, light: GLenum) -> Option<usize> {
        match light.checked_sub(GL_LIGHT0) {
            Some(i) if (i as usize) < MAX_LIGHTS => Some(i as usize),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glLight*v: `params` holds at least [`light_param_count`] values for a valid `pname`.
    pub fn light(&mut self, light: GLenum, pname: GLenum, params: &[f32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(index) = self.light_index(light) else { return };
        if light_param_count(pname) == 0 || params.len() < light_param_count(pname) {
            return self.error(GL_INVALID_ENUM);
        }
        let p = params;
        let value_ok = match pname {
            GL_SPOT_EXPONENT => (0.0..=MAX_SHININESS).contains(&p[0]),
            GL_SPOT_CUTOFF => (0.0..=90.0).contains(&p[0]) || p[0] == 180.0,
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => p[0] >= 0.0,
            _ => true,
        };
        if !value_ok {
            return self.error(GL_INVALID_VALUE);
        }
        if pname == GL_POSITION {
            // Mesa's TRANSFORM_POINT: m · p, each row summed left to right.
            let m = *self.matrices.top(StackId::Modelview).elements();
            let row = |r: usize| m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3];
            self.state.lighting.light[index].position = [row(0), row(1), row(2), row(3)];
            return;
        }
        if pname == GL_SPOT_DIRECTION {
            // Mesa analyses the modelview first (its flags matter to later products).
            let top = self.matrices.top_mut(StackId::Modelview);
            if top.is_dirty() {
                top.analyse();
            }
            let m = *top.elements();
            let row = |r: usize| p[0] * m[r] + p[1] * m[4 + r] + p[2] * m[8 + r];
            self.state.lighting.light[index].spot_direction = [row(0), row(1), row(2)];
            return;
        }
        let l: &mut Light = &mut self.state.lighting.light[index];
        match pname {
            GL_AMBIENT => l.ambient = vec4(p),
            GL_DIFFUSE => l.diffuse = vec4(p),
            GL_SPECULAR => l.specular = vec4(p),
            GL_SPOT_EXPONENT => l.spot_exponent = p[0],
            GL_SPOT_CUTOFF => l.spot_cutoff = p[0],
            GL_CONSTANT_ATTENUATION => l.attenuation[0] = p[0],
            GL_LINEAR_ATTENUATION => l.attenuation[1] = p[0],
            _ => l.attenuation[2] = p[0],
        }
    }

    /// glLightf / glLighti: single-valued parameters only.
    pub fn light_scalar(&mut self, light: GLenum, pname: GLenum, param: f32) {
        if light_param_count(pname) != 1 {
            if self.check_outside_begin_end() && self.light_index(light).is_some() {
                self.error(GL_INVALID_ENUM);
            }
            return;
        }
        self.light(light, pname, &[param]);
    }

    /// glGetLightfv / glGetLightiv: the values of `pname` (empty after an error).
    pub fn get_light(&mut self, light: GLenum, pname: GLenum) -> Vec<Value> {
        if !self.check_outside_begin_end() {
            return Vec::new();
        }
        let Some(index) = self.light_index(light) else { return Vec::new() };
        let l = &self.state.lighting.light[index];
        let color = |c: [f32; 4]| c.map(Value::NormFloat).to_vec();
        let floats = |v: &[f32]| v.iter().map(|&x| Value::Float(x)).collect::<Vec<_>>();
        match pname {
            GL_AMBIENT => color(l.ambient),
            GL_DIFFUSE => color(l.diffuse),
            GL_SPECULAR => color(l.specular),
            GL_POSITION => floats(&l.position),
            GL_SPOT_DIRECTION => floats(&l.spot_direction),
            GL_SPOT_EXPONENT => floats(&[l.spot_exponent]),
            GL_SPOT_CUTOFF => floats(&[l.spot_cutoff]),
            GL_CONSTANT_ATTENUATION => floats(&l.attenuation[0..1]),
            GL_LINEAR_ATTENUATION => floats(&l.attenuation[1..2]),
            GL_QUADRATIC_ATTENUATION => floats(&l.attenuation[2..3]),
            _ => {
                self.error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glLightModel*v: `params` holds at least [`light_model_param_count`] values.
    pub fn light_model(&mut self, pname: GLenum, params: &[f32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let n = light_model_param_count(pname);
        if n == 0 || params.len() < n {
            return self.error(GL_INVALID_ENUM);
        }
        let lighting = &mut self.state.lighting;
        match pname {
            GL_LIGHT_MODEL_AMBIENT => lighting.model_ambient = vec4(params),
            GL_LIGHT_MODEL_LOCAL_VIEWER => lighting.local_viewer = params[0] != 0.0,
            GL_LIGHT_MODEL_TWO_SIDE => lighting.two_side = params[0] != 0.0,
            _ => match params[0] as i32 as GLenum {
                mode @ (GL_SINGLE_COLOR | GL_SEPARATE_SPECULAR_COLOR) => lighting.color_control = mode,
                _ => self.error(GL_INVALID_ENUM),
            },
        }
    }

    /// glLightModelf / glLightModeli: single-valued parameters only.
    pub fn light_model_scalar(&mut self, pname: GLenum, param: f32) {
        if light_model_param_count(pname) != 1 {
            if self.check_outside_begin_end() {
                self.error(GL_INVALID_ENUM);
            }
            return;
        }
        self.light_model(pname, &[param]);
    }

    /// glMaterial*v (legal between glBegin and glEnd).
    pub fn material(&mut self, face: GLenum, pname: GLenum, params: &[f32]) {
        let Some(faces) = faces(face) else { return self.error(GL_INVALID_ENUM) };
        let n = material_param_count(pname);
        if n == 0 || params.len() < n {
            return self.error(GL_INVALID_ENUM);
        }
        if pname == GL_SHININESS && !(0.0..=MAX_SHININESS).contains(&params[0]) {
            return self.error(GL_INVALID_VALUE);
        }
        if self.inside_begin_end && self.vertex_input.material_marks.is_empty() {
            // The vertices so far keep the material they had at glBegin.
            let materials = self.state.lighting.materials;
            self.vertex_input.material_marks.push((0, materials));
        }
        if self.inside_begin_end && self.begin_materials.is_none() {
            self.begin_materials = Some(self.state.lighting.materials);
        }
        for &f in faces {
            set_material_parameter(&mut self.state.lighting.materials[f], pname, params);
        }
        if self.inside_begin_end {
            self.mark_material_change();
        }
    }

    /// glMaterialf / glMateriali: GL_SHININESS only.
    pub fn material_scalar(&mut self, face: GLenum, pname: GLenum, param: f32) {
        if pname != GL_SHININESS {
            return self.error(GL_INVALID_ENUM);
        }
        self.material(face, pname, &[param]);
    }

    /// glGetMaterialfv / glGetMaterialiv: GL_FRONT or GL_BACK (empty after an error). The
    /// shininess and color indexes round as integers, as in Mesa.
    pub fn get_material(&mut self, face: GLenum, pname: GLenum) -> Vec<Value> {
        if !self.check_outside_begin_end() {
            return Vec::new();
        }
        let f = match face {
            GL_FRONT => 0,
            GL_BACK => 1,
            _ => {
                self.error(GL_INVALID_ENUM);
                return Vec::new();
            }
        };
        let m = &self.state.lighting.materials[f];
        let color = |c: [f32; 4]| c.map(Value::NormFloat).to_vec();
        match pname {
            GL_AMBIENT => color(m.ambient),
            GL_DIFFUSE => color(m.diffuse),
            GL_SPECULAR => color(m.specular),
            GL_EMISSION => color(m.emission),
            GL_SHININESS => vec![Value::Float(m.shininess)],
            GL_COLOR_INDEXES => m.color_indexes.map(Value::Float).to_vec(),
            _ => {
                self.error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glColorMaterial.
    pub fn color_material(&mut self, face: GLenum, mode: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        let mode_ok = matches!(mode, GL_EMISSION | GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_AMBIENT_AND_DIFFUSE);
        if faces(face).is_none() || !mode_ok {
            return self.error(GL_INVALID_ENUM);
        }
        self.state.lighting.color_material_face = face;
        self.state.lighting.color_material_mode = mode;
        self.update_color_material();
    }

    /// While GL_COLOR_MATERIAL is enabled, copies the current color into the tracked
    /// material parameters.
    pub fn update_color_material(&mut self) {
        let l = &mut self.state.lighting;
        if l.color_material {
            track_color(&mut l.materials, l.color_material_face, l.color_material_mode, self.state.current.color);
        }
    }
}

/// Values of a glGetLightiv / glGetMaterialiv answer: colors map onto the integer range;
/// other values are truncated (`round` false) or rounded.
pub fn values_to_integers(values: &[Value], round: bool) -> Vec<i32> {
    values
        .iter()
        .map(|v| match *v {
            Value::Float(f) if !round => f as i32,
            other => other.to_integer(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::{ColorFormat, ColorSlot, DepthStencilFormat, FramebufferConfig};

    fn context() -> Context {
        let visual =
            FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0);
        Context::with_test_drawable(visual, 4, 4).0
    }

    #[test]
    fn positions_are_stored_in_eye_coordinates() {
        let mut ctx = context();
        ctx.matrix_mode(GL_MODELVIEW);
        ctx.translate(1.0, 2.0, 3.0);
        ctx.light(GL_LIGHT1, GL_POSITION, &[1.0, 1.0, 1.0, 1.0]);
        ctx.light(GL_LIGHT2, GL_POSITION, &[1.0, 1.0, 1.0, 0.0]);
        ctx.light(GL_LIGHT1, GL_SPOT_DIRECTION, &[0.0, 0.0, -1.0]);
        let l = &ctx.state.lighting.light;
        assert_eq!(l[1].position, [2.0, 3.0, 4.0, 1.0]);
        assert_eq!(l[2].position, [1.0, 1.0, 1.0, 0.0], "directions ignore the translation");
        assert_eq!(l[1].spot_direction, [0.0, 0.0, -1.0]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn range_errors_change_nothing() {
        let mut ctx = context();
        let before = ctx.state.lighting.clone();
        for (pname, value) in [
            (GL_SPOT_EXPONENT, 128.5),
            (GL_SPOT_EXPONENT, -1.0),
            (GL_SPOT_CUTOFF, 90.5),
            (GL_SPOT_CUTOFF, 179.0),
            (GL_CONSTANT_ATTENUATION, -0.1),
            (GL_QUADRATIC_ATTENUATION, -2.0),
        ] {
            ctx.light_scalar(GL_LIGHT0, pname, value);
            assert_eq!(ctx.take_error(), GL_INVALID_VALUE, "{pname:#x} {value}");
        }
        ctx.material_scalar(GL_FRONT, GL_SHININESS, 129.0);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.light_scalar(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 10.0);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.light_scalar(GL_LIGHT0, GL_AMBIENT, 1.0);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.material(GL_FRONT, GL_POSITION, &[0.0; 4]);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.light_model_scalar(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT as f32);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.lighting, before);
        ctx.light_scalar(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0);
        ctx.light_scalar(GL_LIGHT0, GL_SPOT_CUTOFF, 90.0);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn color_material_tracks_the_current_color() {
        let mut ctx = context();
        ctx.set_color([0.1, 0.2, 0.3, 0.4]);
        ctx.color_material(GL_BACK, GL_SPECULAR);
        assert_eq!(ctx.state.lighting.materials[1].specular, [0.0, 0.0, 0.0, 1.0], "not enabled yet");
        ctx.set_capability(GL_COLOR_MATERIAL, true);
        assert_eq!(ctx.state.lighting.materials[1].specular, [0.1, 0.2, 0.3, 0.4]);
        ctx.set_color([0.5; 4]);
        assert_eq!(ctx.state.lighting.materials[1].specular, [0.5; 4]);
        assert_eq!(ctx.state.lighting.materials[0], Material::default());
    }

    /// glMaterial before each vertex of a long GL_POINTS primitive (delivered in several
    /// batches): every point is lit with the material given just before it.
    #[test]
    fn material_between_begin_and_end_applies_from_the_next_vertex_across_batches() {
        let visual =
            FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, DepthStencilFormat::None, 0);
        let (w, h) = (96usize, 80usize);
        let (mut ctx, d) = Context::with_test_drawable(visual, w, h);
        ctx.matrix_mode(GL_PROJECTION);
        ctx.ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
        ctx.set_capability(GL_LIGHTING, true);
        ctx.set_capability(GL_LIGHT0, true);
        ctx.light_model(GL_LIGHT_MODEL_AMBIENT, &[0.0; 4]);
        ctx.material(GL_FRONT, GL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
        let diffuse = |i: usize| [(i % 251) as f32 / 255.0, (i / 251) as f32 / 255.0, 0.5, 1.0];
        ctx.begin(GL_POINTS);
        for i in 0..w * h {
            // Every third vertex keeps the previous material.
            if i % 3 != 2 {
                ctx.material(GL_FRONT, GL_DIFFUSE, &diffuse(i));
            }
            ctx.vertex([(i % w) as f32 + 0.5, (i / w) as f32 + 0.5, 0.0, 1.0]);
        }
        ctx.end();
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.flush_rendering();
        let guard = d.lock().unwrap();
        for y in 0..h {
            let mut row = Vec::new();
            guard.framebuffer.color(ColorSlot::FrontLeft).unwrap().read_row_f32(y as i32, 0, w as i32, &mut row);
            for (x, p) in row.iter().enumerate() {
                let i = y * w + x;
                let expected = diffuse(if i % 3 == 2 { i - 1 } else { i });
                let got = p.map(|c| (c * 255.0).round());
                let want = expected.map(|c| (c * 255.0).round());
                assert_eq!(got, want, "point {i}");
            }
        }
        assert_eq!(ctx.state.lighting.materials[0].diffuse, diffuse(w * h - 2), "the last material stays");
    }

    #[test]
    fn integer_queries_truncate_lights_and_round_materials() {
        let mut ctx = context();
        ctx.light_scalar(GL_LIGHT3, GL_SPOT_EXPONENT, 2.7);
        ctx.material_scalar(GL_BACK, GL_SHININESS, 2.7);
        assert_eq!(values_to_integers(&ctx.get_light(GL_LIGHT3, GL_SPOT_EXPONENT), false), [2]);
        assert_eq!(values_to_integers(&ctx.get_material(GL_BACK, GL_SHININESS), true), [3]);
        assert_eq!(values_to_integers(&ctx.get_light(GL_LIGHT0, GL_DIFFUSE), false), [i32::MAX; 4]);
        assert!(ctx.get_material(GL_FRONT_AND_BACK, GL_SHININESS).is_empty());
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
    }
}
