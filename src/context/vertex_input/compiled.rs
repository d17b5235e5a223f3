//! Array draws compiled into display lists (GL 2.1 section 5.4: the arrays are dereferenced
//! when the command is compiled).
//!
//! The draw runs at compile time with its batches captured instead of drawn, and its error (if
//! any) held back; the recorded command raises that error, or delivers the captured vertices,
//! when the list runs. Only what the enabled arrays supplied is kept from the captured
//! vertices: the other attributes are the current values at execution, as for the same draw
//! executed then. Enabled generic attribute arrays are captured too (each vertex's values),
//! and replayed as rows of generic attributes (`crate::vertex::generic`). glArrayElement keeps the fetched values and replays the attribute commands
//! and glVertex.
use super::draws::FetchedElement;
use super::{CapturedBatch, Context};
use crate::gl::enums::*;
use crate::gl::limits::MAX_TEXTURE_UNITS;
use crate::gl::types::GLenum;
use crate::vertex::arrays::ArrayId;
use crate::vertex::Vertex;

/// Which attributes of a captured vertex came from arrays.
#[derive(Clone, Copy, Debug, Default)]
struct ArraySupplied {
    normal: bool,
    color: bool,
    secondary_color: bool,
    fog_coord: bool,
    edge_flag: bool,
    tex_coords: [bool; MAX_TEXTURE_UNITS],
    /// Generic attributes 1 and up (0 is the position), then the texture coordinate sets
    /// past GL_MAX_TEXTURE_UNITS (slots of `crate::vertex::generic`).
    generic: [bool; crate::vertex::generic::SLOTS],
}

impl ArraySupplied {
    /// Writes the array-supplied attributes of `captured` over `vertex`.
    fn merge(&self, vertex: &mut Vertex, captured: &Vertex) {
        vertex.position = captured.position;
        if self.normal {
            vertex.normal = captured.normal;
        }
        if self.color {
            vertex.color = captured.color;
        }
        if self.secondary_color {
            vertex.secondary_color = captured.secondary_color;
        }
        if self.fog_coord {
            vertex.fog_coord = captured.fog_coord;
        }
        if self.edge_flag {
            vertex.edge_flag = captured.edge_flag;
        }
        for (unit, &on) in self.tex_coords.iter().enumerate() {
            if on {
                vertex.tex_coords[unit] = captured.tex_coords[unit];
            }
        }
    }
}

/// A compiled array draw: the error it raised, or the batches it delivered.
struct CompiledDraw {
    error: GLenum,
    supplied: ArraySupplied,
    batches: Vec<CapturedBatch>,
}

impl Context {
    /// Runs the array draw `draw` now, or compiles it when a list is being compiled.
    pub fn draw_or_compile(&mut self, draw: impl FnOnce(&mut Context)) {
        if !self.lists.compiling() {
            return draw(self);
        }
        let earlier_error = std::mem::replace(&mut self.error, GL_NO_ERROR);
        // The glBegin/glEnd check belongs to execution time.
        let inside = std::mem::replace(&mut self.inside_begin_end, false);
        self.vertex_input.capture = Some(Vec::new());
        draw(self);
        let batches = self.vertex_input.capture.take().unwrap_or_default();
        self.inside_begin_end = inside;
        let error = std::mem::replace(&mut self.error, earlier_error);
        let mut supplied = ArraySupplied::default();
        for (slot, array) in self.vertex_input.arrays.generic_slots() {
            supplied.generic[slot] = array.enabled;
        }
        for (id, array) in self.vertex_input.arrays.all() {
            if !array.enabled {
                continue;
            }
            match id {
                ArrayId::Normal => supplied.normal = true,
                ArrayId::Color => supplied.color = true,
                ArrayId::SecondaryColor => supplied.secondary_color = true,
                ArrayId::FogCoord => supplied.fog_coord = true,
                ArrayId::EdgeFlag => supplied.edge_flag = true,
                ArrayId::TexCoord(unit) => supplied.tex_coords[unit] = true,
                ArrayId::Vertex | ArrayId::Index => {}
            }
        }
        let compiled = CompiledDraw { error, supplied, batches };
        self.record_or_run(move |ctx| ctx.replay_draw(&compiled));
    }

    fn replay_draw(&mut self, compiled: &CompiledDraw) {
        if !self.check_outside_begin_end() {
            return;
        }
        if compiled.error != GL_NO_ERROR {
            return self.error(compiled.error);
        }
        for captured in &compiled.batches {
            let mut batch = std::mem::take(&mut self.vertex_input.batch);
            batch.clear();
            if batch.try_reserve(captured.vertices.len()).is_err() {
                return self.error(GL_OUT_OF_MEMORY);
            }
            let base = self.state.current.vertex_at([0.0, 0.0, 0.0, 1.0]);
            batch.extend(captured.vertices.iter().map(|c| {
                let mut vertex = base;
                compiled.supplied.merge(&mut vertex, c);
                vertex
            }));
            // The captured generic attributes as rows: the arrays' values over the current
            // ones at execution.
            let rows = &mut self.vertex_input.generic_rows;
            rows.clear();
            if !captured.generic.is_empty() {
                if rows.rows.try_reserve(captured.generic.len()).is_err() {
                    self.vertex_input.batch = batch;
                    return self.error(GL_OUT_OF_MEMORY);
                }
                for (vertex, values) in batch.iter_mut().zip(&captured.generic) {
                    let mut row = self.state.current.generic;
                    for (attribute, &on) in compiled.supplied.generic.iter().enumerate() {
                        if on {
                            row[attribute] = values[attribute];
                        }
                    }
                    vertex.generic = rows.push(row);
                }
            }
            self.deliver_in_parts(captured.mode, &batch);
            self.vertex_input.generic_rows.clear();
            batch.clear();
            self.vertex_input.batch = batch;
        }
    }

    /// glArrayElement now, or its values compiled into the list being compiled.
    pub fn array_element_or_compile(&mut self, index: i32, memory: &dyn crate::vertex::arrays::ClientMemory) {
        if !self.lists.compiling() {
            return self.array_element(index, memory);
        }
        let fetched: Result<Option<FetchedElement>, GLenum> = self.fetch_array_element(index, memory);
        self.record_or_run(move |ctx| match &fetched {
            Ok(Some(fetched)) => ctx.apply_array_element(fetched),
            Ok(None) => {}
            Err(error) => ctx.error(*error),
        });
    }
}
