//! The current raster position: glRasterPos, glWindowPos and the GL_CURRENT_RASTER_*
//! queries (GL 2.1 section 2.13).
//!
//! glRasterPos transforms its point as a vertex is transformed; a point outside the view
//! volume (or cut by an enabled user clip plane) makes the raster position invalid, and
//! glBitmap, glDrawPixels and glCopyPixels then do nothing. The raster color, secondary color
//! and texture coordinates are those the draws' per-vertex stage computes for the point
//! (lit under GL_LIGHTING, texture coordinates through texgen and the texture matrices,
//! clamped as vertex colors are); glWindowPos takes the current ones. The raster distance is the fog coordinate under GL_FOG_COORD, else the eye
//! distance. glWindowPos sets window coordinates directly and is always valid.
//!
//! With a GLSL vertex shader in use (GL 2.1 §2.13: "the raster position is transformed as a
//! vertex would be"), the shader runs on the point, as Mesa 22 runs it through its draw
//! module: the window position comes from gl_Position (its fourth value is 1/w_c there, as
//! Mesa reports it), user clip planes test gl_ClipVertex (else gl_Position), the raster
//! colors and texture coordinates are the shader's outputs, each one the shader does not
//! write keeping the current value of the attribute, and the raster distance is left
//! unchanged ([`ShaderOutputs`]).
//!
//! glClipControl (ARB_clip_control) applies to glRasterPos as to any vertex: GL_ZERO_TO_ONE
//! moves the near plane to z_c = 0 and maps depth as n + (f − n)·z_ndc, GL_UPPER_LEFT
//! negates y in the viewport transform. glWindowPos and glBitmap's moves are in window
//! coordinates and unaffected.
use super::get::Value;
use super::shader_objects::Executable;
use super::Context;
use crate::gl::enums::*;
use crate::gl::limits::{MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS};
use crate::gl::types::GLenum;
use crate::vertex::Vertex;
use glam::Vec4;

/// Which of the outputs a raster position or feedback vertex reports a GLSL vertex shader
/// writes: Mesa 22 takes the current value of the attribute for one it does not write.
/// Every texture coordinate set's `gl_TexCoord` element is looked at (`gl_TexCoord[i]`
/// travels in varying slot `i` whether or not a fragment shader reads it), so a raster
/// position takes sets 4–7 from the shader as it does sets 0–3, as Mesa does.
pub(super) struct ShaderOutputs {
    pub color: bool,
    pub secondary_color: bool,
    pub tex_coords: [bool; MAX_TEXTURE_COORDS],
}

impl ShaderOutputs {
    pub(super) fn of(executable: &Executable) -> ShaderOutputs {
        let words = executable.vertex_program.as_ref().map_or(&[][..], |p| &p.lowered.outputs[..]);
        let writes = |name: &str| words.iter().any(|w| w.name == name);
        ShaderOutputs {
            color: writes("gl_FrontColor"),
            secondary_color: writes("gl_FrontSecondaryColor"),
            tex_coords: std::array::from_fn(|unit| writes(&format!("gl_TexCoord[{unit}]"))),
        }
    }
}

/// The raster position and the attributes it carries (part of GL_CURRENT_BIT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterPos {
    pub valid: bool,
    /// Window x, y, z and the clip w.
    pub window: [f32; 4],
    pub distance: f32,
    pub color: [f32; 4],
    pub secondary_color: [f32; 4],
    /// One per texture coordinate set.
    pub tex_coords: [[f32; 4]; MAX_TEXTURE_COORDS],
    pub index: f32,
}

impl Default for RasterPos {
    fn default() -> Self {
        RasterPos {
            valid: true,
            window: [0.0, 0.0, 0.0, 1.0],
            distance: 0.0,
            color: [1.0; 4],
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            tex_coords: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_COORDS],
            index: 1.0,
        }
    }
}

impl Context {
    /// The current colors clamped as vertex colors are for the current framebuffer.
    fn raster_colors(&self) -> ([f32; 4], [f32; 4]) {
        let clamp = match self.state.lighting.clamp_vertex_color {
            GL_FIXED_ONLY => !self.draw_config().color.is_float(),
            c => c == GL_TRUE as GLenum,
        };
        let clamp4 = |c: [f32; 4]| if clamp { c.map(|x| x.clamp(0.0, 1.0)) } else { c };
        (clamp4(self.state.current.color), clamp4(self.state.current.secondary_color))
    }

    /// glRasterPos with object coordinates (x, y, z, w).
    pub fn raster_pos(&mut self, position: [f32; 4]) {
        if !self.check_outside_begin_end() {
            return;
        }
        self.matrices.validate();
        if let Some(executable) = self.program_in_use.executable().cloned().filter(|e| e.vertex_program.is_some()) {
            return self.raster_pos_through_shader(&executable, position);
        }
        // The point goes through the per-vertex stage of draws (lighting, texgen and the
        // texture matrices, color clamping), its texture coordinates on every unit.
        let vertex = Vertex { position, ..self.current_vertex() };
        let units = self.tex_coord_units_of(0..MAX_TEXTURE_UNITS);
        // glMaterial marks belong to a glBegin/glEnd pair, never to the raster position.
        let marks = std::mem::take(&mut self.vertex_input.material_marks);
        let float_color = self.config.visual.color.is_float();
        let transformed = self.transform_units(&[vertex], float_color, &units)[0];
        let units = std::array::from_fn(|unit| transformed.tex_coords[unit]);
        let tex_coords = self.raster_tex_coords(vertex, float_color, units);
        self.vertex_input.material_marks = marks;
        let eye = Vec4::from_array(transformed.eye);
        let clip = Vec4::from_array(transformed.clip);
        if !self.point_inside(clip, eye) {
            self.state.current.raster.valid = false;
            return;
        }
        let window = self.raster_window(clip);
        let distance = if self.state.fog.coord_src == GL_FOG_COORD {
            self.state.current.fog_coord
        } else {
            eye.truncate().length()
        };
        if self.selection.mode == GL_SELECT {
            self.selection.hit(window[2]);
        }
        self.state.current.raster = RasterPos {
            valid: true,
            window,
            distance,
            color: transformed.color,
            secondary_color: transformed.secondary_color,
            tex_coords,
            index: self.state.current.index,
        };
    }

    /// The raster texture coordinates of every set without a shader: the fixed-function
    /// units' as the per-vertex stage made them (`units`), then the sets past them through
    /// the same stage (texgen, their texture matrices), their current values and state put
    /// in the record's slots for the occasion (the record carries the units' only).
    fn raster_tex_coords(
        &self,
        vertex: Vertex,
        float_color: bool,
        units: [[f32; 4]; MAX_TEXTURE_UNITS],
    ) -> [[f32; 4]; MAX_TEXTURE_COORDS] {
        let mut all = [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_COORDS];
        all[..MAX_TEXTURE_UNITS].copy_from_slice(&units);
        for first in (MAX_TEXTURE_UNITS..MAX_TEXTURE_COORDS).step_by(MAX_TEXTURE_UNITS) {
            let sets = first..MAX_TEXTURE_COORDS.min(first + MAX_TEXTURE_UNITS);
            let mut moved = vertex;
            moved.tex_coords =
                std::array::from_fn(|k| self.current_tex_coords((first + k).min(MAX_TEXTURE_COORDS - 1)));
            let mut work = self.tex_coord_units_of(sets.clone());
            work.iter_mut().for_each(|w| w.unit -= first);
            let out = self.transform_units(&[moved], float_color, &work)[0];
            let count = sets.len();
            all[sets].copy_from_slice(&out.tex_coords[..count]);
        }
        all
    }

    /// glRasterPos with a GLSL vertex shader in use (see the module docs).
    fn raster_pos_through_shader(&mut self, executable: &Executable, position: [f32; 4]) {
        let vertex = Vertex { position, ..self.current_vertex() };
        let float_color = self.config.visual.color.is_float();
        let stage = self.vertex_shader_stage(executable, float_color);
        let rows = &self.vertex_input.generic_rows;
        let out = stage.run(&[vertex], rows, &self.state.current.generic, |v| v[0]);
        let clip = Vec4::from_array(out.clip);
        if !self.point_inside(clip, Vec4::from_array(out.eye)) {
            self.state.current.raster.valid = false;
            return;
        }
        let mut window = self.raster_window(clip);
        window[3] = 1.0 / clip.w;
        if self.selection.mode == GL_SELECT {
            self.selection.hit(window[2]);
        }
        let written = ShaderOutputs::of(executable);
        let current = &self.state.current;
        let raster = RasterPos {
            valid: true,
            window,
            distance: current.raster.distance,
            color: if written.color { out.color } else { current.color },
            secondary_color: if written.secondary_color { out.secondary_color } else { current.secondary_color },
            tex_coords: std::array::from_fn(|unit| match written.tex_coords.get(unit) {
                Some(true) => out.tex_coords[unit],
                _ => self.current_tex_coords(unit),
            }),
            index: current.index,
        };
        self.state.current.raster = raster;
    }

    /// The current vertex attributes as a vertex (position from the caller).
    fn current_vertex(&self) -> Vertex {
        let current = &self.state.current;
        Vertex {
            position: [0.0, 0.0, 0.0, 1.0],
            color: current.color,
            secondary_color: current.secondary_color,
            normal: current.normal,
            tex_coords: current.tex_coords,
            fog_coord: current.fog_coord,
            edge_flag: true,
            generic: crate::vertex::generic::CURRENT,
        }
    }

    /// Whether a point at clip coordinates `clip` is inside the view volume and on the
    /// kept side of every enabled user clip plane (tested with `eye`).
    fn point_inside(&self, clip: Vec4, eye: Vec4) -> bool {
        let transform = &self.state.transform;
        // The near plane is z = 0 under GL_ZERO_TO_ONE (ARB_clip_control).
        let near_z = if self.clip_zero_to_one() { 0.0 } else { -clip.w };
        let mut inside = [clip.x, clip.y].iter().all(|&c| -clip.w <= c && c <= clip.w)
            && (transform.depth_clamp || (near_z <= clip.z && clip.z <= clip.w));
        for (plane, &on) in transform.clip_plane_equations.iter().zip(&transform.clip_planes) {
            if on {
                let p = plane.map(|c| c as f32);
                inside &= p[0] * eye.x + p[1] * eye.y + p[2] * eye.z + p[3] * eye.w >= 0.0;
            }
        }
        inside
    }

    /// The window coordinates of a point inside the view volume, and its clip w.
    fn raster_window(&self, clip: Vec4) -> [f32; 4] {
        let [vx, vy, vw, vh] = self.state.viewport.rect;
        let [near, far] = self.state.viewport.depth_range.map(|d| d as f32);
        let inv_w = 1.0 / clip.w;
        let ndc = [clip.x * inv_w, clip.y * inv_w, clip.z * inv_w];
        let (half_w, half_h) = (vw as f32 * 0.5, vh as f32 * 0.5);
        // The viewport transform of draws, with glClipControl's depth mapping and y sign.
        let (depth_scale, depth_offset) = self.depth_transform();
        let mut z = ndc[2] * depth_scale as f32 + depth_offset as f32;
        if self.state.transform.depth_clamp {
            z = z.clamp(near.min(far), near.max(far));
        }
        let y_scale = half_h * self.viewport_y_sign();
        [ndc[0] * half_w + (vx as f32 + half_w), ndc[1] * y_scale + (vy as f32 + half_h), z, clip.w]
    }

    /// glWindowPos with window coordinates (x, y, z): z in [0, 1] maps onto the depth range.
    pub fn window_pos(&mut self, [x, y, z]: [f32; 3]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let [near, far] = self.state.viewport.depth_range.map(|d| d as f32);
        let z = near + z.clamp(0.0, 1.0) * (far - near);
        let distance = if self.state.fog.coord_src == GL_FOG_COORD { self.state.current.fog_coord } else { 0.0 };
        if self.selection.mode == GL_SELECT {
            self.selection.hit(z);
        }
        let (color, secondary_color) = self.raster_colors();
        let current = &self.state.current;
        self.state.current.raster = RasterPos {
            valid: true,
            window: [x, y, z, 1.0],
            distance,
            color,
            secondary_color,
            tex_coords: std::array::from_fn(|unit| self.current_tex_coords(unit)),
            index: current.index,
        };
    }

    /// The glGet values of the raster position; `None` for other pnames.
    pub(crate) fn raster_pos_values(&self, pname: GLenum) -> Option<Vec<Value>> {
        let r = &self.state.current.raster;
        Some(match pname {
            GL_CURRENT_RASTER_POSITION => r.window.map(Value::Float).to_vec(),
            GL_CURRENT_RASTER_POSITION_VALID => vec![Value::Bool(r.valid)],
            GL_CURRENT_RASTER_DISTANCE => vec![Value::Float(r.distance)],
            GL_CURRENT_RASTER_COLOR => r.color.map(Value::NormFloat).to_vec(),
            GL_CURRENT_RASTER_SECONDARY_COLOR => r.secondary_color.map(Value::NormFloat).to_vec(),
            GL_CURRENT_RASTER_INDEX => vec![Value::Float(r.index)],
            GL_CURRENT_RASTER_TEXTURE_COORDS => {
                let unit = self.state.texture.active_unit.min(MAX_TEXTURE_COORDS - 1);
                r.tex_coords[unit].map(Value::Float).to_vec()
            }
            GL_ZOOM_X => vec![Value::Float(self.state.pixel_mode.zoom[0])],
            GL_ZOOM_Y => vec![Value::Float(self.state.pixel_mode.zoom[1])],
            _ => return None,
        })
    }

    /// glPixelZoom.
    pub fn pixel_zoom(&mut self, x: f32, y: f32) {
        if self.check_outside_begin_end() {
            self.state.pixel_mode.zoom = [x, y];
        }
    }
}
