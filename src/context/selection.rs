//! glRenderMode(GL_SELECT) and the name stack: glSelectBuffer, glInitNames, glPushName,
//! glPopName, glLoadName (GL 2.1 section 5.2).
//!
//! In selection mode draws rasterize nothing: every primitive that survives clipping and
//! culling (and every valid glRasterPos) sets the hit flag and widens the hit's depth range
//! (`draw::select`). A hit record (name count, min and max depth scaled to 2³²−1 as Mesa
//! does, the names) is written when the name stack changes or selection ends. Records are
//! kept here and copied to the caller's buffer when glRenderMode leaves GL_SELECT; words
//! beyond the buffer's size are dropped and glRenderMode then returns −1.
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;

/// GL_MAX_NAME_STACK_DEPTH (Mesa's value).
pub const MAX_NAME_STACK_DEPTH: usize = 64;

/// The render mode and the selection state of a context.
#[derive(Debug)]
pub struct Selection {
    pub mode: GLenum,
    buffer_address: usize,
    buffer_size: usize,
    names: Vec<u32>,
    hit: bool,
    min_z: f32,
    max_z: f32,
    records: Vec<u32>,
    hits: u32,
    feedback_type: GLenum,
    feedback_address: usize,
    feedback_size: usize,
    /// The feedback values since entering GL_FEEDBACK.
    pub feedback: Vec<f32>,
}

impl Default for Selection {
    fn default() -> Self {
        Selection {
            mode: GL_RENDER,
            buffer_address: 0,
            buffer_size: 0,
            names: Vec::new(),
            hit: false,
            min_z: 1.0,
            max_z: 0.0,
            records: Vec::new(),
            hits: 0,
            feedback_type: GL_2D,
            feedback_address: 0,
            feedback_size: 0,
            feedback: Vec::new(),
        }
    }
}

/// A depth in [0, 1] as a hit record holds it: times 2³²−1 computed in single precision and
/// truncated, as Mesa 22 does.
pub fn scaled_depth(z: f32) -> u32 {
    (z * 4294967295.0f32) as u32
}

impl Selection {
    /// The address glSelectBuffer or glFeedbackBuffer was given (glGetPointerv).
    pub fn buffer_pointer(&self, pname: GLenum) -> usize {
        if pname == GL_FEEDBACK_BUFFER_POINTER {
            self.feedback_address
        } else {
            self.buffer_address
        }
    }

    /// Records a hit at window depth `z`.
    pub fn hit(&mut self, z: f32) {
        self.hit = true;
        self.min_z = self.min_z.min(z);
        self.max_z = self.max_z.max(z);
    }

    fn write_hit_record(&mut self) {
        if !self.hit {
            return;
        }
        self.records.push(self.names.len() as u32);
        self.records.push(scaled_depth(self.min_z));
        self.records.push(scaled_depth(self.max_z));
        self.records.extend_from_slice(&self.names);
        self.hits += 1;
        self.hit = false;
        self.min_z = 1.0;
        self.max_z = 0.0;
    }
}

/// What glRenderMode hands back to the API edge: its return value and the words to copy to
/// the select buffer at `address`.
pub struct RenderModeResult {
    pub value: i32,
    pub copy: Option<(usize, Vec<u32>)>,
    /// Feedback values to copy to the feedback buffer at the address.
    pub feedback: Option<(usize, Vec<f32>)>,
}

/// One vertex as feedback reports it: window x, y, z, the clip w, color and texture
/// coordinates of unit 0.
#[derive(Clone, Copy, Debug)]
pub struct FeedbackVertex {
    pub window: [f32; 4],
    pub color: [f32; 4],
    pub tex: [f32; 4],
}

impl Context {
    /// Whether draws rasterize (GL_RENDER) rather than select or feed back.
    #[inline]
    pub fn rendering(&self) -> bool {
        self.selection.mode == GL_RENDER
    }

    /// glSelectBuffer: `address` is the caller's buffer of `size` words.
    pub fn select_buffer(&mut self, size: i32, address: usize) {
        if !self.check_outside_begin_end() {
            return;
        }
        if size < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if self.selection.mode == GL_SELECT {
            return self.error(GL_INVALID_OPERATION);
        }
        self.selection.buffer_address = address;
        self.selection.buffer_size = size as usize;
    }

    /// glRenderMode.
    pub fn render_mode(&mut self, mode: GLenum) -> RenderModeResult {
        let none = RenderModeResult { value: 0, copy: None, feedback: None };
        if !self.check_outside_begin_end() {
            return none;
        }
        if !matches!(mode, GL_RENDER | GL_SELECT | GL_FEEDBACK) {
            self.error(GL_INVALID_ENUM);
            return none;
        }
        let mut result = none;
        let s = &mut self.selection;
        if s.mode == GL_SELECT {
            s.write_hit_record();
            let overflow = s.records.len() > s.buffer_size;
            let mut words = std::mem::take(&mut s.records);
            words.truncate(s.buffer_size);
            result = RenderModeResult {
                value: if overflow { -1 } else { s.hits as i32 },
                copy: (s.buffer_address != 0 && !words.is_empty()).then_some((s.buffer_address, words)),
                feedback: None,
            };
            s.hits = 0;
            s.names.clear();
            s.hit = false;
            s.min_z = 1.0;
            s.max_z = 0.0;
        }
        if s.mode == GL_FEEDBACK {
            let overflow = s.feedback.len() > s.feedback_size;
            let mut values = std::mem::take(&mut s.feedback);
            values.truncate(s.feedback_size);
            let count = values.len() as i32;
            result = RenderModeResult {
                value: if overflow { -1 } else { count },
                copy: None,
                feedback: (s.feedback_address != 0 && !values.is_empty()).then_some((s.feedback_address, values)),
            };
        }
        // As Mesa: entering a mode without its buffer is an error, but the mode changes.
        let no_buffer = match mode {
            GL_SELECT => self.selection.buffer_size == 0,
            GL_FEEDBACK => self.selection.feedback_size == 0,
            _ => false,
        };
        if no_buffer {
            self.error(GL_INVALID_OPERATION);
        }
        self.flush_rendering();
        self.selection.mode = mode;
        result
    }

    /// glFeedbackBuffer: `address` is the caller's buffer of `size` floats.
    pub fn feedback_buffer(&mut self, size: i32, ty: GLenum, address: usize) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !matches!(ty, GL_2D | GL_3D | GL_3D_COLOR | GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
            return self.error(GL_INVALID_ENUM);
        }
        if size < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if self.selection.mode == GL_FEEDBACK {
            return self.error(GL_INVALID_OPERATION);
        }
        let s = &mut self.selection;
        (s.feedback_type, s.feedback_size, s.feedback_address) = (ty, size as usize, address);
    }

    /// glPassThrough.
    pub fn pass_through(&mut self, token: f32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if self.selection.mode == GL_FEEDBACK {
            self.selection.feedback.extend([GL_PASS_THROUGH_TOKEN as f32, token]);
        }
    }

    /// Appends a feedback token and its vertices in the feedback buffer's type.
    pub fn feedback_token(&mut self, token: GLenum, count: Option<usize>, vertices: &[FeedbackVertex]) {
        let s = &mut self.selection;
        s.feedback.push(token as f32);
        if let Some(n) = count {
            s.feedback.push(n as f32);
        }
        for v in vertices {
            let [x, y, z, w] = v.window;
            match s.feedback_type {
                GL_2D => s.feedback.extend([x, y]),
                GL_3D => s.feedback.extend([x, y, z]),
                GL_3D_COLOR => s.feedback.extend([x, y, z].iter().chain(&v.color)),
                GL_3D_COLOR_TEXTURE => s.feedback.extend([x, y, z].iter().chain(&v.color).chain(&v.tex)),
                _ => s.feedback.extend([x, y, z, w].iter().chain(&v.color).chain(&v.tex)),
            }
        }
    }

    /// glInitNames.
    pub fn init_names(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        let s = &mut self.selection;
        if s.mode == GL_SELECT {
            s.write_hit_record();
        }
        s.names.clear();
        s.hit = false;
        s.min_z = 1.0;
        s.max_z = 0.0;
    }

    /// glPushName.
    pub fn push_name(&mut self, name: u32) {
        if !self.check_outside_begin_end() || self.selection.mode != GL_SELECT {
            return;
        }
        self.selection.write_hit_record();
        if self.selection.names.len() >= MAX_NAME_STACK_DEPTH {
            return self.error(GL_STACK_OVERFLOW);
        }
        self.selection.names.push(name);
    }

    /// glPopName.
    pub fn pop_name(&mut self) {
        if !self.check_outside_begin_end() || self.selection.mode != GL_SELECT {
            return;
        }
        self.selection.write_hit_record();
        if self.selection.names.pop().is_none() {
            self.error(GL_STACK_UNDERFLOW);
        }
    }

    /// glLoadName.
    pub fn load_name(&mut self, name: u32) {
        if !self.check_outside_begin_end() || self.selection.mode != GL_SELECT {
            return;
        }
        if self.selection.names.is_empty() {
            return self.error(GL_INVALID_OPERATION);
        }
        self.selection.write_hit_record();
        if let Some(top) = self.selection.names.last_mut() {
            *top = name;
        }
    }

    /// The glGet values of the selection state; `None` for other pnames.
    pub(crate) fn selection_values(&self, pname: GLenum) -> Option<Vec<super::get::Value>> {
        use super::get::Value::*;
        Some(vec![match pname {
            GL_RENDER_MODE => Enum(self.selection.mode),
            GL_NAME_STACK_DEPTH => Int(self.selection.names.len() as i32),
            GL_MAX_NAME_STACK_DEPTH => Int(MAX_NAME_STACK_DEPTH as i32),
            GL_SELECTION_BUFFER_SIZE => Int(self.selection.buffer_size as i32),
            GL_FEEDBACK_BUFFER_SIZE => Int(self.selection.feedback_size as i32),
            GL_FEEDBACK_BUFFER_TYPE => Enum(self.selection.feedback_type),
            _ => return None,
        }])
    }
}
