//! glBegin/glEnd, glVertex, the current-attribute commands and glRect.
//!
//! The attribute commands are legal between glBegin and glEnd (section 2.6.3) and set
//! `state.current` there and outside alike; glVertex appends a snapshot of it to the open
//! primitive. glVertex outside glBegin/glEnd is undefined in GL; like Mesa, tessera ignores it
//! without an error.
//!
//! Deliberate differences from Mesa 22:
//! - glBegin takes GL 2.1's modes only: the adjacency modes and GL_PATCHES are GL_INVALID_ENUM.
//! - glMultiTexCoord with a target beyond GL_MAX_TEXTURE_COORDS is GL_INVALID_ENUM; Mesa does
//!   not check the target and writes unit `target & 7`.
//!
//! The texture coordinate sets past GL_MAX_TEXTURE_UNITS have no fixed-function use: their
//! current values live among the generic attributes' ([`crate::vertex::generic::SLOTS`]),
//! where only a GLSL vertex shader reads them.
//! - glEdgeFlag(flag) sets the edge flag for any nonzero `flag`; Mesa keeps the flag as a
//!   float and reports TRUE only for exactly 1.
use super::{independent_primitive_size, Context, BATCH_VERTICES};
use crate::gl::enums::*;
use crate::gl::limits::MAX_TEXTURE_COORDS;
use crate::gl::types::GLenum;
use crate::vertex::assembly::{continued_vertices, DrawPart};
use crate::vertex::immediate::{is_primitive_mode, rect_positions};

impl Context {
    /// glBegin.
    pub fn begin(&mut self, mode: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !is_primitive_mode(mode) {
            return self.error(GL_INVALID_ENUM);
        }
        if !self.check_program_samplers() {
            return;
        }
        self.vertex_input.begin_mode = mode;
        self.vertex_input.vertices.clear();
        self.forget_generic_rows();
        self.vertex_input.material_marks.clear();
        self.vertex_input.parts_delivered = false;
        self.inside_begin_end = true;
    }

    /// glEnd: the vertices since glBegin go to the geometry pipeline.
    pub fn end(&mut self) {
        if !self.inside_begin_end {
            return self.error(GL_INVALID_OPERATION);
        }
        self.inside_begin_end = false;
        self.deliver_open_vertices();
        self.forget_generic_rows();
        self.vertex_input.material_marks.clear();
        self.begin_materials = None;
        // Mesa updates tracked materials when it flushes the current attributes.
        self.update_color_material();
    }

    /// glVertex: appends a vertex at `position` with the current attributes (object
    /// coordinates; missing components are z = 0, w = 1).
    #[inline(always)]
    pub fn vertex(&mut self, position: [f32; 4]) {
        if !self.inside_begin_end {
            return;
        }
        let vertex = self.state.current.vertex_at(position);
        self.push_open_vertex(vertex);
    }

    /// The fast paths of the per-vertex entry points (`api::fast_or_run`): each does its whole
    /// command, or declines (returns `false`) when anything more than a store is needed. None
    /// can panic: fields are stored, limits compared before a push into reserved room.
    ///
    /// glVertex inside glBegin/glEnd when the vertex neither ends a batch nor needs more room.
    #[inline(always)]
    pub fn try_vertex(&mut self, x: f32, y: f32, z: f32, w: f32) -> bool {
        let vertices = &mut self.vertex_input.vertices;
        let len = vertices.len();
        if !self.inside_begin_end || len + 1 >= BATCH_VERTICES || len >= vertices.capacity() {
            return false;
        }
        vertices.push(self.state.current.vertex_at([x, y, z, w]));
        true
    }

    /// glColor, unless the color material has to follow it (outside glBegin/glEnd).
    #[inline(always)]
    pub fn try_set_color(&mut self, color: [f32; 4]) -> bool {
        if self.state.lighting.color_material && !self.inside_begin_end {
            return false;
        }
        self.state.current.color = color;
        true
    }

    /// glNormal3.
    #[inline(always)]
    pub fn try_set_normal(&mut self, normal: [f32; 3]) -> bool {
        self.state.current.normal = normal;
        true
    }

    /// glTexCoord (unit 0).
    #[inline(always)]
    pub fn try_set_tex_coords0(&mut self, coords: [f32; 4]) -> bool {
        match self.state.current.tex_coords.first_mut() {
            Some(current) => *current = coords,
            None => return false,
        }
        true
    }

    /// glVertex as the entry points call it: the coordinates come as four scalars, in
    /// registers. Passed as an array, they were stored as four floats and read back as one
    /// 16-byte value (or two 8-byte ones), a store-forwarding stall that cost more than the
    /// rest of the call.
    ///
    /// The common case, a vertex between glBegin and glEnd that neither fills the batch nor
    /// the vector's capacity, is written into the entry point (no call, no register saves:
    /// a bounds check and the record's stores); the rest is out of line, which keeps the
    /// entry points' closures small enough to be inlined into them.
    #[inline(always)]
    pub fn vertex_xyzw(&mut self, x: f32, y: f32, z: f32, w: f32) {
        let vertices = &mut self.vertex_input.vertices;
        let len = vertices.len();
        if self.inside_begin_end && len + 1 < BATCH_VERTICES && len < vertices.capacity() {
            vertices.push(self.state.current.vertex_at([x, y, z, w]));
        } else {
            self.vertex_out_of_line(x, y, z, w);
        }
    }

    /// [`Context::vertex_xyzw`] when the vertex ends a batch, needs more room or comes
    /// outside glBegin/glEnd.
    #[inline(never)]
    fn vertex_out_of_line(&mut self, x: f32, y: f32, z: f32, w: f32) {
        self.vertex([x, y, z, w])
    }

    /// Appends a finished vertex to the open primitive (glVertex, glEvalCoord).
    #[inline]
    pub(crate) fn push_open_vertex(&mut self, vertex: crate::vertex::Vertex) {
        if !self.inside_begin_end {
            return;
        }
        let vertices = &mut self.vertex_input.vertices;
        if vertices.len() == vertices.capacity() && vertices.try_reserve(vertices.len().max(256)).is_err() {
            return self.error(GL_OUT_OF_MEMORY);
        }
        vertices.push(vertex);
        if vertices.len() < BATCH_VERTICES {
            return;
        }
        if independent_primitive_size(self.vertex_input.begin_mode).is_some() {
            // A whole number of primitives: BATCH_VERTICES is a multiple of every size.
            self.deliver_open_vertices();
        } else if vertices.len() >= BATCH_VERTICES + 2
            && self.vertex_input.material_marks.is_empty()
            && self.may_deliver_parts()
        {
            self.deliver_open_part();
        }
    }

    /// Delivers the vertices of the open connected primitive as a part that does not end it,
    /// and keeps the vertices the next part repeats. A line loop's parts are line strips
    /// (its closing segment comes with the last part, [`Context::deliver_open_vertices`]).
    fn deliver_open_part(&mut self) {
        let mode = self.vertex_input.begin_mode;
        let mut vertices = std::mem::take(&mut self.vertex_input.vertices);
        let Some(kept) = continued_vertices(mode, vertices.len()) else {
            self.vertex_input.vertices = vertices;
            return;
        };
        let first = !self.vertex_input.parts_delivered;
        let part = DrawPart { first, last: false };
        if mode == GL_LINE_LOOP {
            // After the first part, the loop's first vertex (kept at 0) is not part of the strip.
            self.deliver_part(GL_LINE_STRIP, &vertices[usize::from(!first)..], part);
        } else {
            self.deliver_part(mode, &vertices, part);
        }
        self.vertex_input.parts_delivered = true;
        let head = vertices[0];
        vertices.drain(..vertices.len() - kept.tail);
        if kept.first {
            vertices.insert(0, head);
        }
        self.vertex_input.vertices = vertices;
    }

    /// Delivers and forgets the vertices collected since glBegin.
    fn deliver_open_vertices(&mut self) {
        if self.vertex_input.parts_delivered {
            return self.deliver_last_part();
        }
        let vertices = std::mem::take(&mut self.vertex_input.vertices);
        if !vertices.is_empty() {
            self.deliver(self.vertex_input.begin_mode, &vertices);
        }
        // Material changes after the delivered vertices now count from the next batch.
        let delivered = vertices.len();
        let marks = &mut self.vertex_input.material_marks;
        if let Some(last_applied) = marks.iter().rposition(|m| m.0 <= delivered) {
            marks.drain(..last_applied);
            for (i, m) in marks.iter_mut().enumerate() {
                m.0 = if i == 0 { 0 } else { m.0 - delivered };
            }
        }
        self.vertex_input.vertices = vertices;
        self.vertex_input.vertices.clear();
    }

    /// Delivers the rest of a connected primitive of which parts were delivered: a line
    /// loop's last part is a line strip closed by the loop's first vertex (kept at 0).
    fn deliver_last_part(&mut self) {
        let mode = self.vertex_input.begin_mode;
        let mut vertices = std::mem::take(&mut self.vertex_input.vertices);
        let part = DrawPart { first: false, last: true };
        if mode == GL_LINE_LOOP {
            vertices.push(vertices[0]);
            self.deliver_part(GL_LINE_STRIP, &vertices[1..], part);
        } else {
            self.deliver_part(mode, &vertices, part);
        }
        self.vertex_input.parts_delivered = false;
        vertices.clear();
        self.vertex_input.vertices = vertices;
    }

    /// glColor (already converted to floats; not clamped).
    #[inline]
    pub fn set_color(&mut self, color: [f32; 4]) {
        self.state.current.color = color;
        if self.state.lighting.color_material && !self.inside_begin_end {
            self.update_color_material();
        }
    }

    /// glSecondaryColor3: the alpha of the secondary color is always 1.
    #[inline]
    pub fn set_secondary_color(&mut self, [red, green, blue]: [f32; 3]) {
        self.state.current.secondary_color = [red, green, blue, 1.0];
    }

    /// glNormal3.
    #[inline]
    pub fn set_normal(&mut self, normal: [f32; 3]) {
        self.state.current.normal = normal;
    }

    /// glTexCoord (unit 0) and glMultiTexCoord once its target is checked.
    #[inline]
    pub fn set_tex_coords(&mut self, unit: usize, coords: [f32; 4]) {
        if let Some(current) = self.state.current.tex_coords.get_mut(unit) {
            *current = coords;
        } else if unit < MAX_TEXTURE_COORDS {
            self.set_generic(crate::vertex::generic::tex_coord_slot(unit), coords);
        }
    }

    /// The current texture coordinates of set `unit` (< GL_MAX_TEXTURE_COORDS).
    pub(crate) fn current_tex_coords(&self, unit: usize) -> [f32; 4] {
        let current = &self.state.current;
        match current.tex_coords.get(unit) {
            Some(&coords) => coords,
            None => current.generic[crate::vertex::generic::tex_coord_slot(unit.min(MAX_TEXTURE_COORDS - 1))],
        }
    }

    /// glMultiTexCoord: `target` is GL_TEXTUREi of an existing unit, else GL_INVALID_ENUM.
    #[inline]
    pub fn multi_tex_coord(&mut self, target: GLenum, coords: [f32; 4]) {
        match texture_unit(target) {
            Some(unit) => self.set_tex_coords(unit, coords),
            None => self.error(GL_INVALID_ENUM),
        }
    }

    /// glFogCoord.
    #[inline]
    pub fn set_fog_coord(&mut self, coord: f32) {
        self.state.current.fog_coord = coord;
    }

    /// glEdgeFlag.
    #[inline]
    pub fn set_edge_flag(&mut self, flag: bool) {
        self.state.current.edge_flag = flag;
    }

    /// glIndex.
    #[inline]
    pub fn set_index(&mut self, index: f32) {
        self.state.current.index = index;
    }

    /// glRect: a GL_POLYGON of the four corners with the current attributes (section 2.11).
    /// Illegal between glBegin and glEnd.
    pub fn rect(&mut self, corner1: [f32; 2], corner2: [f32; 2]) {
        if !self.check_outside_begin_end() {
            return;
        }
        let vertices = rect_positions(corner1, corner2).map(|p| self.state.current.vertex_at(p));
        self.deliver(GL_POLYGON, &vertices);
    }
}

/// The texture coordinate set GL_TEXTUREi names, when it exists (i < GL_MAX_TEXTURE_COORDS).
pub(crate) fn texture_unit(texture: GLenum) -> Option<usize> {
    let unit = texture.checked_sub(GL_TEXTURE0)? as usize;
    (unit < MAX_TEXTURE_COORDS).then_some(unit)
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;
    use crate::gl::limits::MAX_TEXTURE_UNITS;

    #[test]
    fn begin_end_delivers_snapshots_of_the_current_attributes() {
        let mut ctx = context();
        ctx.begin(GL_TRIANGLES);
        ctx.set_color([1.0, 0.0, 0.0, 1.0]);
        ctx.vertex([0.0, 0.0, 0.0, 1.0]);
        ctx.set_color([0.0, 1.0, 0.0, 0.5]);
        ctx.set_normal([1.0, 0.0, 0.0]);
        ctx.multi_tex_coord(GL_TEXTURE3, [1.0, 2.0, 3.0, 4.0]);
        ctx.set_edge_flag(false);
        ctx.vertex([1.0, 0.0, 0.0, 1.0]);
        ctx.set_secondary_color([0.25, 0.5, 0.75]);
        ctx.set_fog_coord(7.0);
        ctx.vertex([1.0, 1.0, 0.5, 2.0]);
        assert!(ctx.vertex_input.delivered.is_empty(), "nothing is drawn before glEnd");
        ctx.end();
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let (mode, vertices) = &ctx.vertex_input.delivered[0];
        assert_eq!((*mode, vertices.len()), (GL_TRIANGLES, 3));
        assert_eq!(vertices[0].color, [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(vertices[0].normal, [0.0, 0.0, 1.0]);
        assert!(vertices[0].edge_flag);
        assert_eq!(vertices[1].color, [0.0, 1.0, 0.0, 0.5]);
        assert_eq!(vertices[1].normal, [1.0, 0.0, 0.0]);
        assert_eq!(vertices[1].tex_coords[3], [1.0, 2.0, 3.0, 4.0]);
        assert!(!vertices[1].edge_flag);
        assert_eq!(vertices[1].secondary_color, [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(vertices[2].position, [1.0, 1.0, 0.5, 2.0]);
        assert_eq!(vertices[2].secondary_color, [0.25, 0.5, 0.75, 1.0]);
        assert_eq!(vertices[2].fog_coord, 7.0);
        // The attributes stay current after glEnd.
        assert_eq!(ctx.state.current.color, [0.0, 1.0, 0.0, 0.5]);
        // An empty primitive delivers nothing; the next one starts empty.
        ctx.begin(GL_POINTS);
        ctx.end();
        ctx.begin(GL_POINTS);
        ctx.vertex([5.0, 0.0, 0.0, 1.0]);
        ctx.end();
        assert_eq!(ctx.vertex_input.delivered.len(), 2);
        assert_eq!(ctx.vertex_input.delivered[1].1.len(), 1);
    }

    #[test]
    fn begin_and_end_errors() {
        let mut ctx = context();
        ctx.end();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.begin(GL_POLYGON + 1);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert!(!ctx.inside_begin_end);
        ctx.begin(GL_LINES);
        ctx.vertex([0.0; 4]);
        ctx.begin(GL_POINTS);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.vertex([1.0; 4]);
        ctx.end();
        // The nested glBegin changed nothing: one GL_LINES primitive of two vertices.
        assert_eq!(ctx.vertex_input.delivered.len(), 1);
        assert_eq!(ctx.vertex_input.delivered[0].0, GL_LINES);
        assert_eq!(ctx.vertex_input.delivered[0].1.len(), 2);
        ctx.end();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn long_primitives_are_delivered_in_batches_and_parts() {
        let mut ctx = context();
        for (mode, batches) in [(GL_TRIANGLES, 3), (GL_LINE_STRIP, 3)] {
            ctx.vertex_input.delivered.clear();
            ctx.begin(mode);
            for i in 0..2 * BATCH_VERTICES + 3 {
                ctx.vertex([i as f32, 0.0, 0.0, 1.0]);
            }
            if mode == GL_TRIANGLES {
                assert_eq!(ctx.vertex_input.delivered.len(), 2, "delivered while glBegin is open");
            }
            ctx.end();
            let delivered = &ctx.vertex_input.delivered;
            assert_eq!(delivered.len(), batches, "mode {mode:#x}");
            // A strip's parts after the first repeat the previous part's last vertex.
            let repeated = usize::from(mode == GL_LINE_STRIP);
            let xs: Vec<f32> = delivered
                .iter()
                .enumerate()
                .flat_map(|(k, (_, v))| v[if k == 0 { 0 } else { repeated }..].iter().map(|v| v.position[0]))
                .collect();
            assert_eq!(xs, (0..2 * BATCH_VERTICES + 3).map(|i| i as f32).collect::<Vec<_>>());
        }
        assert_eq!(BATCH_VERTICES % 12, 0);
    }

    #[test]
    fn vertices_outside_begin_end_are_ignored() {
        let mut ctx = context();
        ctx.vertex([1.0, 2.0, 3.0, 1.0]);
        ctx.begin(GL_POINTS);
        ctx.end();
        assert!(ctx.vertex_input.delivered.is_empty());
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn multi_tex_coord_targets() {
        let mut ctx = context();
        ctx.multi_tex_coord(GL_TEXTURE0 + MAX_TEXTURE_COORDS as GLenum, [1.0; 4]);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.multi_tex_coord(GL_TEXTURE0 - 1, [1.0; 4]);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.current.tex_coords, [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS]);
        ctx.set_tex_coords(0, [2.0; 4]);
        assert_eq!(ctx.state.current.tex_coords[0], [2.0; 4]);
        assert_eq!(texture_unit(GL_TEXTURE3), Some(3));
        // The sets past the fixed-function units exist: their values are kept beside them.
        ctx.multi_tex_coord(GL_TEXTURE0 + MAX_TEXTURE_UNITS as GLenum + 2, [3.0, 4.0, 5.0, 6.0]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.current_tex_coords(MAX_TEXTURE_UNITS + 2), [3.0, 4.0, 5.0, 6.0]);
        assert_eq!(ctx.current_tex_coords(MAX_TEXTURE_UNITS + 1), [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn rect_is_a_polygon_and_illegal_inside_begin_end() {
        let mut ctx = context();
        ctx.set_color([0.5; 4]);
        ctx.rect([1.0, 2.0], [3.0, 4.0]);
        let (mode, vertices) = &ctx.vertex_input.delivered[0];
        assert_eq!(*mode, GL_POLYGON);
        let positions: Vec<_> = vertices.iter().map(|v| v.position).collect();
        assert_eq!(positions, rect_positions([1.0, 2.0], [3.0, 4.0]));
        assert!(vertices.iter().all(|v| v.color == [0.5; 4]));
        ctx.begin(GL_QUADS);
        ctx.rect([0.0; 2], [1.0; 2]);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.end();
        assert_eq!(ctx.vertex_input.delivered.len(), 1);
    }

    /// Strips, fans, quads and polygons map each vertex to window space and snap it once
    /// (`vertex::pipeline`'s corners); independent triangles map theirs per triangle. The
    /// same triangles drawn either way give the same pixels, depth-tested (their order
    /// shows), with vertices beyond the far plane and the guard band (clipped) among them.
    #[test]
    fn connected_primitives_draw_the_bytes_of_their_triangles_drawn_alone() {
        use crate::context::draw::replay::{context, pixels, vertex};
        use crate::vertex::assembly::{assemble, Primitive, QuadSplit};
        let mut seed = 7u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            (seed >> 8) as f32 / (1 << 24) as f32
        };
        let mut vertices: Vec<_> = (0..42)
            .map(|_| {
                let (x, y, z) = (rnd() * 240.0 - 20.0, rnd() * 190.0 - 20.0, rnd() * 1.8 - 0.9);
                vertex(x, y, z, [rnd(), rnd(), rnd(), 1.0])
            })
            .collect();
        vertices[5].position[2] = -3.0;
        vertices[11].position[0] = 3e7;
        for mode in [GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON] {
            // Quads with a vertex outside the view volume split along their other diagonal.
            let split = if mode == GL_QUADS { QuadSplit::SecondDiagonal } else { QuadSplit::FirstDiagonal };
            let mut triangles = Vec::new();
            assemble(mode, vertices.len() as u32, false, split, |p| {
                if let Primitive::Triangle { v, .. } = p {
                    triangles.extend(v.map(|i| vertices[i as usize]));
                }
            });
            let render = |mode: GLenum, vertices: &[crate::vertex::Vertex]| {
                let (mut ctx, d) = context(200, 150);
                ctx.state.depth.test = true;
                ctx.clear(GL_DEPTH_BUFFER_BIT);
                ctx.draw_vertices(mode, vertices);
                pixels(&mut ctx, &d)
            };
            let connected = render(mode, &vertices);
            assert!(connected.iter().filter(|p| p[0] != 0).count() > 1000, "mode {mode:#x} draws");
            assert!(connected == render(GL_TRIANGLES, &triangles), "mode {mode:#x}: the pixels differ");
        }
    }
}
