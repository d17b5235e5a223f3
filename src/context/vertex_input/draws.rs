//! Drawing from the arrays: glArrayElement, glDrawArrays, glDrawElements,
//! glDrawRangeElements, glMultiDrawArrays and glMultiDrawElements.
//!
//! A draw first finds the smallest and largest element it uses (from `first`/`count` or by
//! scanning the indices), then takes from each enabled array exactly the bytes of that range:
//! from a buffer object's storage, or from client memory through the [`ClientMemory`] the API
//! edge provides. Vertices start as a snapshot of the current attributes and take what the
//! enabled arrays hold; the color index array is only read by glArrayElement (it has no place
//! in an RGBA vertex). As in Mesa, draws leave the current attributes as they were, and
//! glArrayElement sets them as the attribute commands would.
//!
//! What GL leaves undefined draws nothing, without an error: a disabled vertex array, a
//! negative `first` or glArrayElement index (Mesa reads before the array), a null client
//! pointer, indices beyond their element buffer, an array whose buffer was deleted. Array
//! bytes beyond the end of a buffer object read as zero.
//!
//! Deliberate differences from Mesa 22: the modes are GL 2.1's (no adjacency, no patches:
//! GL_INVALID_ENUM), and drawing from a mapped buffer object is GL_INVALID_OPERATION (the GL
//! 1.5 specification allows it to be; Mesa draws the mapped contents).
use super::{independent_primitive_size, Context, BATCH_VERTICES};
use crate::context::state::CurrentState;
use crate::gl::enums::*;
use crate::gl::limits::MAX_TEXTURE_UNITS;
use crate::gl::types::GLenum;
use crate::vertex::arrays::{
    byte_extent, index_range, ArrayId, ArrayState, BoundArray, ClientArrays, ClientMemory, IndexType,
};
use crate::vertex::assembly::{continued_vertices, DrawPart};
use crate::vertex::buffer_objects::BufferTable;
use crate::vertex::generic::{GenericRows, SLOTS as GENERIC_SLOTS};
use crate::vertex::immediate::is_primitive_mode;
use crate::vertex::Vertex;

/// How many arrays there are (`ClientArrays::all`).
const ARRAY_COUNT: usize = 7 + MAX_TEXTURE_UNITS;

/// The values of one glArrayElement, per enabled array: the fixed-function ones (with the
/// position), then the generic attributes past 0.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FetchedElement {
    arrays: [Option<(ArrayId, [f32; 4])>; ARRAY_COUNT],
    generic: [Option<[f32; 4]>; GENERIC_SLOTS],
}

/// A draw's batch vector keeps at most this many vertices of capacity between draws (the
/// connected modes are delivered whole when a display list captures them, and may be long).
const KEPT_BATCH_CAPACITY: usize = 4 * BATCH_VERTICES;

/// The elements a draw reads, in order.
#[derive(Clone, Copy)]
enum Elements<'a> {
    /// `first .. first + count`.
    Sequence { first: u32, count: u32 },
    /// Packed indices.
    Listed { kind: IndexType, bytes: &'a [u8] },
}

impl Elements<'_> {
    fn len(self) -> usize {
        match self {
            Elements::Sequence { count, .. } => count as usize,
            Elements::Listed { kind, bytes } => bytes.len() / kind.size(),
        }
    }

    /// The smallest and largest element.
    fn range(self) -> Option<(u32, u32)> {
        match self {
            Elements::Sequence { count: 0, .. } => None,
            Elements::Sequence { first, count } => Some((first, first + (count - 1))),
            Elements::Listed { kind, bytes } => index_range(kind.decode(bytes)),
        }
    }
}

/// Where a draw's indices are: a sequence, or `count` indices at `address` (client memory,
/// or an offset into the element array buffer when one is bound).
#[derive(Clone, Copy)]
enum IndexSource {
    Sequence { first: u32, count: u32 },
    Listed { kind: IndexType, address: usize, count: usize },
}

impl IndexSource {
    /// How many elements the draw reads.
    fn count(self) -> usize {
        match self {
            IndexSource::Sequence { count, .. } => count as usize,
            IndexSource::Listed { count, .. } => count,
        }
    }

    /// Elements `start .. start + count` of the draw (`None` when the address overflows).
    fn sub_range(self, start: usize, count: usize) -> Option<IndexSource> {
        Some(match self {
            IndexSource::Sequence { first, .. } => {
                IndexSource::Sequence { first: first.checked_add(u32::try_from(start).ok()?)?, count: count as u32 }
            }
            IndexSource::Listed { kind, address, .. } => {
                IndexSource::Listed { kind, address: address.checked_add(start.checked_mul(kind.size())?)?, count }
            }
        })
    }
}

/// Why an array draw makes no vertices.
enum NoDraw {
    /// Undefined in GL: nothing is drawn, no error.
    Undefined,
    OutOfMemory,
}

/// The bytes of `array` elements `first..=last` (see the module docs for the cases that
/// give none).
fn array_bytes<'a>(
    array: &ArrayState,
    buffers: &'a BufferTable,
    memory: &'a dyn ClientMemory,
    first: u32,
    last: u32,
) -> Result<&'a [u8], NoDraw> {
    if array.orphaned {
        return Err(NoDraw::Undefined);
    }
    let (offset, len) =
        byte_extent(first, last, array.effective_stride(), array.element_size()).ok_or(NoDraw::Undefined)?;
    let start = array.pointer.checked_add(offset).ok_or(NoDraw::Undefined)?;
    if array.buffer == 0 {
        return memory.bytes(start, len).ok_or(NoDraw::Undefined);
    }
    let data = buffers.get(array.buffer).ok_or(NoDraw::Undefined)?.data();
    let end = start.saturating_add(len).min(data.len());
    Ok(data.get(start.min(end)..end).unwrap_or(&[]))
}

/// Fetches element `index` of `array` for each vertex of `batch`, in order, and stores it
/// with `store`. One loop per array, monomorphized per attribute, so the per-vertex work is
/// the fetch and a plain store.
fn fill<T>(batch: &mut [T], elements: Elements, array: &BoundArray, store: impl Fn(&mut T, [f32; 4])) {
    // One loop per kind of element source (not a chain of both): the loop is simpler, and
    // valgrind does not see the optimizer's reads of the unused variant as uninitialised.
    match elements {
        Elements::Sequence { first, count } => {
            let n = batch.len().min(count as usize);
            if array.fill_floats(first, &mut batch[..n], &store) {
                return;
            }
            for (vertex, index) in batch.iter_mut().zip(first..first + count) {
                store(vertex, array.fetch(index));
            }
        }
        Elements::Listed { kind, bytes } => {
            for (vertex, index) in batch.iter_mut().zip(kind.decode(bytes)) {
                store(vertex, array.fetch(index));
            }
        }
    }
}

/// Appends the vertices of `elements` to `batch`: copies of the current attributes, then
/// each enabled array's values stored over them, one array at a time. Without a position
/// array only a GLSL vertex shader draws (`shader`): its attribute 0 is then generic
/// attribute 0's current value, as in Mesa, which draws whatever arrays are enabled.
fn assemble(
    arrays: &ClientArrays,
    buffers: &BufferTable,
    current: &CurrentState,
    shader: bool,
    elements: Elements,
    memory: &dyn ClientMemory,
    batch: &mut Vec<Vertex>,
) -> Result<(), NoDraw> {
    let positions = arrays.position().enabled;
    if !positions && !shader {
        return Err(NoDraw::Undefined);
    }
    let Some((first, last)) = elements.range() else {
        return Ok(());
    };
    let mut bound: [Option<(ArrayId, BoundArray)>; ARRAY_COUNT] = [None; ARRAY_COUNT];
    for (slot, (id, array)) in bound.iter_mut().zip(arrays.all()) {
        if array.enabled && id != ArrayId::Index {
            let bytes = array_bytes(array, buffers, memory, first, last)?;
            *slot = Some((id, BoundArray::new(id, array, bytes, first)));
        }
    }
    batch.try_reserve(elements.len()).map_err(|_| NoDraw::OutOfMemory)?;
    let start = batch.len();
    let position = if positions { [0.0, 0.0, 0.0, 1.0] } else { current.generic[0] };
    batch.resize(start + elements.len(), current.vertex_at(position));
    let vertices = &mut batch[start..];
    for (id, array) in bound.iter().flatten() {
        match *id {
            ArrayId::Vertex => fill(vertices, elements, array, |v, x| v.position = x),
            ArrayId::Normal => fill(vertices, elements, array, |v, [x, y, z, _]| v.normal = [x, y, z]),
            ArrayId::Color => fill(vertices, elements, array, |v, x| v.color = x),
            ArrayId::SecondaryColor => {
                fill(vertices, elements, array, |v, [r, g, b, _]| v.secondary_color = [r, g, b, 1.0])
            }
            ArrayId::FogCoord => fill(vertices, elements, array, |v, [f, ..]| v.fog_coord = f),
            ArrayId::EdgeFlag => fill(vertices, elements, array, |v, [e, ..]| v.edge_flag = e != 0.0),
            ArrayId::TexCoord(unit) => fill(vertices, elements, array, |v, x| {
                if let Some(coords) = v.tex_coords.get_mut(unit) {
                    *coords = x;
                }
            }),
            ArrayId::Index => {}
        }
    }
    Ok(())
}

/// Gives each of `vertices` (the vertices of `elements`) a row of generic attributes in
/// `rows`: the current values, then what the enabled generic arrays 1 and up hold (array 0
/// is the position, which [`assemble`] fetched) and the enabled texture coordinate arrays
/// past GL_MAX_TEXTURE_UNITS ([`ClientArrays::generic_slots`]).
fn assemble_generic(
    arrays: &ClientArrays,
    buffers: &BufferTable,
    current: &CurrentState,
    elements: Elements,
    memory: &dyn ClientMemory,
    rows: &mut GenericRows,
    vertices: &mut [Vertex],
) -> Result<(), NoDraw> {
    let Some((first, last)) = elements.range() else {
        return Ok(());
    };
    rows.rows.try_reserve(vertices.len()).map_err(|_| NoDraw::OutOfMemory)?;
    let start = rows.rows.len();
    for v in vertices.iter_mut() {
        v.generic = rows.push(current.generic);
    }
    let new_rows = &mut rows.rows[start..];
    for (attribute, array) in arrays.generic_slots() {
        if array.enabled {
            let bytes = array_bytes(array, buffers, memory, first, last)?;
            // ArrayId::Vertex: no normalization of its own (the array's flag decides; a
            // texture coordinate array's is false).
            let bound = BoundArray::new(ArrayId::Vertex, array, bytes, first);
            fill(new_rows, elements, &bound, |row, x| row[attribute] = x);
        }
    }
    Ok(())
}

impl Context {
    /// Whether an array draw makes generic attribute rows: some generic array past 0 is
    /// enabled, and a GLSL vertex shader in use reads generic attributes or a display list
    /// captures the draw (GL 2.1 §5.4: the arrays are dereferenced when it is compiled,
    /// whatever program runs the list); or a texture coordinate array past
    /// GL_MAX_TEXTURE_UNITS is enabled, and a GLSL vertex shader is in use (which may read
    /// `gl_MultiTexCoord4..7`) or a display list captures the draw.
    fn array_draw_needs_generic_rows(&self) -> bool {
        let vertex_shader = self.program_in_use.executable().filter(|e| e.vertex_program.is_some());
        let reads_generic =
            vertex_shader.is_some_and(|e| e.interface.attributes.iter().any(|a| a.location.is_some_and(|l| l > 0)));
        let arrays = &self.vertex_input.arrays;
        let generic_arrays = arrays.generic[1..].iter().any(|a| a.enabled);
        let set_arrays = arrays.tex_coords[MAX_TEXTURE_UNITS..].iter().any(|a| a.enabled);
        ((reads_generic || self.capturing()) && generic_arrays)
            || ((vertex_shader.is_some() || self.capturing()) && set_arrays)
    }

    /// Whether the draw would source data from a mapped buffer: an enabled array's, or the
    /// element array buffer when `with_indices`.
    fn sources_mapped_buffer(&self, with_indices: bool) -> bool {
        let arrays = &self.vertex_input.arrays;
        let mapped = |name: u32| name != 0 && self.buffers.lock().get(name).is_some_and(|b| b.mapped);
        arrays.all().any(|(_, a)| a.enabled && mapped(a.buffer))
            || (with_indices && mapped(arrays.element_array_buffer))
    }

    /// The last checks of every draw: GL_INVALID_OPERATION when the program in use has
    /// conflicting samplers or the draw would read a mapped buffer.
    fn check_unmapped(&mut self, with_indices: bool) -> bool {
        if !self.check_program_samplers() {
            return false;
        }
        if self.sources_mapped_buffer(with_indices) {
            self.error(GL_INVALID_OPERATION);
            return false;
        }
        true
    }

    /// Makes the vertices of one validated draw and delivers them: in batches of
    /// [`BATCH_VERTICES`] for independent primitives, in parts for long connected ones.
    fn draw_from_arrays(&mut self, mode: GLenum, source: IndexSource, memory: &dyn ClientMemory) {
        let count = source.count();
        if independent_primitive_size(mode).is_none() {
            if count <= BATCH_VERTICES + 2 || !self.may_deliver_parts() {
                return self.draw_batch(mode, &[source], memory, DrawPart::WHOLE);
            }
            return self.draw_in_parts(mode, source, memory);
        }
        // A long draw into the window is recorded in segments, each while the one before
        // renders (`Context::record_in_segments`); otherwise in one.
        let segment = self.overlap_segment(count).unwrap_or(count);
        // The batches of vertices `range` in order; false when one cannot be read.
        let record = |cx: &mut Context, range: std::ops::Range<usize>| {
            range.clone().step_by(BATCH_VERTICES).all(|start| {
                let batch = source.sub_range(start, (range.end - start).min(BATCH_VERTICES));
                batch.inspect(|&batch| cx.draw_batch(mode, &[batch], memory, DrawPart::WHOLE)).is_some()
            })
        };
        self.record_in_segments(count, segment, record);
    }

    /// Delivers a long strip, fan, loop or polygon in parts of [`BATCH_VERTICES`] elements,
    /// each after the first starting with the elements it shares with the one before
    /// ([`continued_vertices`]: the first element of fans and polygons, the last one or two of
    /// the previous part). A line loop's parts are line strips, the last one closed by the
    /// loop's first element.
    fn draw_in_parts(&mut self, mode: GLenum, source: IndexSource, memory: &dyn ClientMemory) {
        let count = source.count();
        let Some(kept) = continued_vertices(mode, BATCH_VERTICES) else {
            return self.draw_batch(mode, &[source], memory, DrawPart::WHOLE);
        };
        let loop_ = mode == GL_LINE_LOOP;
        let part_mode = if loop_ { GL_LINE_STRIP } else { mode };
        let Some(head) = source.sub_range(0, 1) else { return };
        let mut start = 0;
        loop {
            let end = (start + BATCH_VERTICES).min(count);
            let Some(range) = source.sub_range(start, end - start) else { return };
            let part = DrawPart { first: start == 0, last: end == count };
            let sources: &[IndexSource] = match (kept.first && !loop_ && !part.first, loop_ && part.last) {
                (true, _) => &[head, range],
                (_, true) => &[range, head],
                _ => &[range],
            };
            self.draw_batch(part_mode, sources, memory, part);
            if part.last {
                return;
            }
            start = end - kept.tail;
        }
    }

    /// Makes the vertices of one validated draw (or batch or part of a draw) from the
    /// elements of `sources`, in order, and delivers them.
    fn draw_batch(&mut self, mode: GLenum, sources: &[IndexSource], memory: &dyn ClientMemory, part: DrawPart) {
        let mut batch = std::mem::take(&mut self.vertex_input.batch);
        batch.clear();
        let generic = self.array_draw_needs_generic_rows();
        let shader = self.program_in_use.executable().is_some_and(|e| e.vertex_program.is_some());
        let mut rows = std::mem::take(&mut self.vertex_input.generic_rows);
        rows.clear();
        let mut outcome = Ok(());
        let buffers = self.buffers.lock();
        for &source in sources {
            let elements = match source {
                IndexSource::Sequence { first, count } => Some(Elements::Sequence { first, count }),
                IndexSource::Listed { kind, address, count } => {
                    let element_buffer = self.vertex_input.arrays.element_array_buffer;
                    let bytes = count.checked_mul(kind.size()).and_then(|len| match element_buffer {
                        0 => memory.bytes(address, len),
                        name => buffers.get(name).and_then(|buffer| buffer.range(address, len)),
                    });
                    bytes.map(|bytes| Elements::Listed { kind, bytes })
                }
            };
            outcome = match elements {
                Some(elements) => {
                    let (arrays, current) = (&self.vertex_input.arrays, &self.state.current);
                    let start = batch.len();
                    assemble(arrays, &buffers, current, shader, elements, memory, &mut batch).and_then(|()| {
                        if !generic {
                            return Ok(());
                        }
                        let vertices = &mut batch[start..];
                        assemble_generic(arrays, &buffers, current, elements, memory, &mut rows, vertices)
                    })
                }
                None => Err(NoDraw::Undefined),
            };
            if outcome.is_err() {
                break;
            }
        }
        drop(buffers);
        self.vertex_input.generic_rows = rows;
        match outcome {
            Ok(()) if !batch.is_empty() => self.deliver_part(mode, &batch, part),
            Err(NoDraw::OutOfMemory) => self.error(GL_OUT_OF_MEMORY),
            _ => {}
        }
        batch.clear();
        batch.shrink_to(KEPT_BATCH_CAPACITY);
        self.vertex_input.batch = batch;
        self.vertex_input.generic_rows.clear();
    }

    /// glArrayElement: as the attribute commands with element `index` of every enabled array,
    /// then glVertex when the vertex array is enabled. Legal between glBegin and glEnd.
    pub fn array_element(&mut self, index: i32, memory: &dyn ClientMemory) {
        match self.fetch_array_element(index, memory) {
            Ok(Some(fetched)) => self.apply_array_element(&fetched),
            Ok(None) => {}
            Err(error) => self.error(error),
        }
    }

    /// What glArrayElement reads: element `index` of every enabled array (`Ok(None)` where GL
    /// leaves it undefined and nothing happens).
    pub(crate) fn fetch_array_element(
        &self,
        index: i32,
        memory: &dyn ClientMemory,
    ) -> Result<Option<FetchedElement>, GLenum> {
        if self.sources_mapped_buffer(false) {
            return Err(GL_INVALID_OPERATION);
        }
        let Ok(index) = u32::try_from(index) else {
            return Ok(None);
        };
        let buffers = self.buffers.lock();
        let mut fetched = FetchedElement { arrays: [None; ARRAY_COUNT], generic: [None; GENERIC_SLOTS] };
        for (slot, (id, array)) in fetched.arrays.iter_mut().zip(self.vertex_input.arrays.all()) {
            if array.enabled {
                let Ok(bytes) = array_bytes(array, &buffers, memory, index, index) else {
                    return Ok(None);
                };
                *slot = Some((id, BoundArray::new(id, array, bytes, index).fetch(index)));
            }
        }
        for (slot, array) in self.vertex_input.arrays.generic_slots() {
            if array.enabled {
                let Ok(bytes) = array_bytes(array, &buffers, memory, index, index) else {
                    return Ok(None);
                };
                fetched.generic[slot] = Some(BoundArray::new(ArrayId::Vertex, array, bytes, index).fetch(index));
            }
        }
        Ok(Some(fetched))
    }

    /// The second half of glArrayElement: the attribute commands, then glVertex.
    pub(crate) fn apply_array_element(&mut self, fetched: &FetchedElement) {
        let mut position = None;
        for (index, value) in fetched.generic.iter().enumerate() {
            if let Some(value) = *value {
                self.set_generic(index, value);
            }
        }
        for &(id, value) in fetched.arrays.iter().flatten() {
            let current = &mut self.state.current;
            match id {
                ArrayId::Vertex => position = Some(value),
                ArrayId::Normal => current.normal = [value[0], value[1], value[2]],
                ArrayId::Color => current.color = value,
                ArrayId::SecondaryColor => current.secondary_color = [value[0], value[1], value[2], 1.0],
                ArrayId::FogCoord => current.fog_coord = value[0],
                ArrayId::Index => current.index = value[0],
                ArrayId::EdgeFlag => current.edge_flag = value[0] != 0.0,
                ArrayId::TexCoord(unit) => self.set_tex_coords(unit, value),
            }
        }
        if let Some(position) = position {
            self.vertex(position);
        }
    }

    /// glDrawArrays.
    pub fn draw_arrays(&mut self, mode: GLenum, first: i32, count: i32, memory: &dyn ClientMemory) {
        if !self.check_outside_begin_end() {
            return;
        }
        if count < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if !is_primitive_mode(mode) {
            return self.error(GL_INVALID_ENUM);
        }
        if !self.check_unmapped(false) || count == 0 || first < 0 {
            return;
        }
        self.draw_from_arrays(mode, IndexSource::Sequence { first: first as u32, count: count as u32 }, memory);
    }

    /// The checks glDrawElements and glDrawRangeElements share after their own: count, mode,
    /// index type, mapped buffers. Returns the index type.
    fn check_elements(&mut self, mode: GLenum, count: i32, type_: GLenum) -> Option<IndexType> {
        if count < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        if !is_primitive_mode(mode) {
            self.error(GL_INVALID_ENUM);
            return None;
        }
        let Some(kind) = IndexType::from_gl(type_) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        self.check_unmapped(true).then_some(kind)
    }

    /// glDrawElements: `indices` is a client address, or an offset into the element array
    /// buffer when one is bound.
    pub fn draw_elements(
        &mut self,
        mode: GLenum,
        count: i32,
        type_: GLenum,
        indices: usize,
        memory: &dyn ClientMemory,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        if let Some(kind) = self.check_elements(mode, count, type_) {
            let source = IndexSource::Listed { kind, address: indices, count: count as usize };
            self.draw_from_arrays(mode, source, memory);
        }
    }

    /// glDrawRangeElements: as glDrawElements; `start`..=`end` is a promise about the indices
    /// that is not needed (the draw finds the range itself), only checked for `end < start`.
    #[allow(clippy::too_many_arguments)]
    pub fn draw_range_elements(
        &mut self,
        mode: GLenum,
        start: u32,
        end: u32,
        count: i32,
        type_: GLenum,
        indices: usize,
        memory: &dyn ClientMemory,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        if end < start {
            return self.error(GL_INVALID_VALUE);
        }
        self.draw_elements(mode, count, type_, indices, memory)
    }

    /// glMultiDrawArrays: `firsts` and `counts` hold the caller's `drawcount` values.
    pub fn multi_draw_arrays(
        &mut self,
        mode: GLenum,
        firsts: &[i32],
        counts: &[i32],
        drawcount: i32,
        memory: &dyn ClientMemory,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        if drawcount < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if !is_primitive_mode(mode) {
            return self.error(GL_INVALID_ENUM);
        }
        if counts.iter().any(|&c| c < 0) {
            return self.error(GL_INVALID_VALUE);
        }
        if !self.check_unmapped(false) {
            return;
        }
        for (&first, &count) in firsts.iter().zip(counts) {
            if count > 0 && first >= 0 {
                self.draw_from_arrays(mode, IndexSource::Sequence { first: first as u32, count: count as u32 }, memory);
            }
        }
    }

    /// glMultiDrawElements: `counts` and `indices` hold the caller's `drawcount` values.
    pub fn multi_draw_elements(
        &mut self,
        mode: GLenum,
        counts: &[i32],
        type_: GLenum,
        indices: &[usize],
        drawcount: i32,
        memory: &dyn ClientMemory,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        if drawcount < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if !is_primitive_mode(mode) {
            return self.error(GL_INVALID_ENUM);
        }
        let Some(kind) = IndexType::from_gl(type_) else {
            return self.error(GL_INVALID_ENUM);
        };
        if counts.iter().any(|&c| c < 0) {
            return self.error(GL_INVALID_VALUE);
        }
        if !self.check_unmapped(true) {
            return;
        }
        for (&count, &address) in counts.iter().zip(indices) {
            if count > 0 {
                self.draw_from_arrays(mode, IndexSource::Listed { kind, address, count: count as usize }, memory);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;

    /// A context drawing a client vertex array of 2D positions (i, 10 i) at 0x1000 and a
    /// ubyte color array (i, 2 i, 3 i, 255) at 0x2000, for elements 0..8.
    fn drawing_context() -> (Context, FakeMemory) {
        let mut ctx = context();
        let mut memory = FakeMemory::default();
        let positions: Vec<f32> = (0..8).flat_map(|i| [i as f32, 10.0 * i as f32]).collect();
        memory.add(0x1000, floats(&positions));
        memory.add(0x2000, (0..8u8).flat_map(|i| [i, 2 * i, 3 * i, 255]).collect());
        ctx.vertex_pointer(2, GL_FLOAT, 0, 0x1000);
        ctx.color_pointer(4, GL_UNSIGNED_BYTE, 0, 0x2000);
        ctx.enable_client_state(GL_VERTEX_ARRAY, true);
        ctx.enable_client_state(GL_COLOR_ARRAY, true);
        (ctx, memory)
    }

    fn xs(vertices: &[Vertex]) -> Vec<f32> {
        vertices.iter().map(|v| v.position[0]).collect()
    }

    #[test]
    fn draw_arrays_reads_exactly_its_range() {
        let (mut ctx, memory) = drawing_context();
        ctx.set_normal([0.0, 1.0, 0.0]);
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 2, 3, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let (mode, vertices) = &ctx.vertex_input.delivered[0];
        assert_eq!(*mode, GL_TRIANGLE_STRIP);
        assert_eq!(xs(vertices), [2.0, 3.0, 4.0]);
        assert_eq!(vertices[1].position, [3.0, 30.0, 0.0, 1.0]);
        assert_eq!(vertices[1].color, [3.0 / 255.0, 6.0 / 255.0, 9.0 / 255.0, 1.0]);
        // Attributes without an enabled array come from the current values.
        assert_eq!(vertices[2].normal, [0.0, 1.0, 0.0]);
        // Elements 2..=4: 8 bytes each from 0x1000 + 16, 4 bytes each from 0x2000 + 8.
        assert_eq!(*memory.reads.borrow(), [(0x1010, 24), (0x2008, 12)]);
        // Drawing leaves the current color alone.
        assert_eq!(ctx.state.current.color, [1.0; 4]);
    }

    #[test]
    fn draw_elements_with_every_index_type() {
        let (mut ctx, mut memory) = drawing_context();
        let bytes = memory.add(0x3000, vec![5, 1, 5, 3]);
        let shorts = memory.add(0x4000, [7u16, 2, 6].iter().flat_map(|v| v.to_ne_bytes()).collect());
        let ints = memory.add(0x5000, [4u32, 0, 4].iter().flat_map(|v| v.to_ne_bytes()).collect());
        ctx.draw_elements(GL_LINES, 4, GL_UNSIGNED_BYTE, bytes, &memory);
        ctx.draw_elements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, shorts, &memory);
        ctx.draw_range_elements(GL_POINTS, 0, 4, 3, GL_UNSIGNED_INT, ints, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let delivered = &ctx.vertex_input.delivered;
        assert_eq!((delivered[0].0, xs(&delivered[0].1)), (GL_LINES, vec![5.0, 1.0, 5.0, 3.0]));
        assert_eq!((delivered[1].0, xs(&delivered[1].1)), (GL_TRIANGLES, vec![7.0, 2.0, 6.0]));
        assert_eq!((delivered[2].0, xs(&delivered[2].1)), (GL_POINTS, vec![4.0, 0.0, 4.0]));
        assert_eq!(delivered[1].1[0].color, [7.0 / 255.0, 14.0 / 255.0, 21.0 / 255.0, 1.0]);
        // Each draw read its indices, then elements min..=max of each array.
        let reads = memory.reads.borrow();
        assert_eq!(reads[..3], [(0x3000, 4), (0x1008, 5 * 8), (0x2004, 5 * 4)]);
        assert_eq!(reads[3..6], [(0x4000, 6), (0x1010, 6 * 8), (0x2008, 6 * 4)]);
        assert_eq!(reads[6..], [(0x5000, 12), (0x1000, 5 * 8), (0x2000, 5 * 4)]);
    }

    #[test]
    fn large_draws_of_independent_primitives_come_in_batches() {
        let mut ctx = context();
        let mut memory = FakeMemory::default();
        let n = 2 * BATCH_VERTICES + 5;
        let positions: Vec<f32> = (0..n).flat_map(|i| [i as f32, 0.0]).collect();
        let vertices = memory.add(0x10000, floats(&positions));
        let indices = memory.add(0x100000, (0..n as u32).rev().flat_map(|i| i.to_ne_bytes()).collect());
        ctx.vertex_pointer(2, GL_FLOAT, 0, vertices);
        ctx.enable_client_state(GL_VERTEX_ARRAY, true);
        ctx.draw_arrays(GL_TRIANGLES, 0, n as i32, &memory);
        let sizes: Vec<usize> = ctx.vertex_input.delivered.iter().map(|(_, v)| v.len()).collect();
        assert_eq!(sizes, [BATCH_VERTICES, BATCH_VERTICES, 5]);
        let all: Vec<f32> = ctx.vertex_input.delivered.iter().flat_map(|(_, v)| xs(v)).collect();
        assert_eq!(all, (0..n).map(|i| i as f32).collect::<Vec<_>>());
        // Each batch reads only its own elements.
        assert_eq!(memory.reads.borrow()[1], (vertices + BATCH_VERTICES * 8, BATCH_VERTICES * 8));
        ctx.vertex_input.delivered.clear();
        ctx.draw_elements(GL_POINTS, n as i32, GL_UNSIGNED_INT, indices, &memory);
        let all: Vec<f32> = ctx.vertex_input.delivered.iter().flat_map(|(_, v)| xs(v)).collect();
        assert_eq!(all, (0..n).rev().map(|i| i as f32).collect::<Vec<_>>());
        assert_eq!(ctx.vertex_input.delivered.len(), 3);
        // Connected primitives come in parts, each repeating the last two vertices of a strip.
        ctx.vertex_input.delivered.clear();
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, n as i32, &memory);
        let parts: Vec<(f32, usize)> =
            ctx.vertex_input.delivered.iter().map(|(_, v)| (v[0].position[0], v.len())).collect();
        let step = (BATCH_VERTICES - 2) as f32;
        assert_eq!(parts, [(0.0, BATCH_VERTICES), (step, BATCH_VERTICES), (2.0 * step, n - 2 * (BATCH_VERTICES - 2))]);
        // A fan's parts start with its first vertex; a loop's last part ends with it.
        for (mode, first, last) in [(GL_TRIANGLE_FAN, Some(0.0), None), (GL_LINE_LOOP, None, Some(0.0))] {
            ctx.vertex_input.delivered.clear();
            ctx.draw_arrays(mode, 0, n as i32, &memory);
            let delivered = &ctx.vertex_input.delivered;
            assert_eq!(delivered.len(), 3);
            if let Some(x) = first {
                assert!(delivered.iter().all(|(_, v)| v[0].position[0] == x));
            }
            if let Some(x) = last {
                assert_eq!(delivered[2].1.last().unwrap().position[0], x);
                assert!(delivered.iter().all(|(m, _)| *m == GL_LINE_STRIP));
            }
        }
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn multi_draws_deliver_one_batch_per_draw() {
        let (mut ctx, mut memory) = drawing_context();
        ctx.multi_draw_arrays(GL_LINE_STRIP, &[0, 6, 3], &[2, 2, 0], 3, &memory);
        let a = memory.add(0x3000, vec![1, 2]);
        let b = memory.add(0x3100, vec![7]);
        ctx.multi_draw_elements(GL_POINTS, &[2, 0, 1], GL_UNSIGNED_BYTE, &[a, 0, b], 3, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let batches: Vec<_> = ctx.vertex_input.delivered.iter().map(|(m, v)| (*m, xs(v))).collect();
        assert_eq!(
            batches,
            [
                (GL_LINE_STRIP, vec![0.0, 1.0]),
                (GL_LINE_STRIP, vec![6.0, 7.0]),
                (GL_POINTS, vec![1.0, 2.0]),
                (GL_POINTS, vec![7.0])
            ]
        );
    }

    #[test]
    fn strides_normalization_and_every_array() {
        let mut ctx = context();
        let mut memory = FakeMemory::default();
        // One interleaved element of 32 bytes: position (3 shorts), pad, normal (3 bytes), pad,
        // secondary color (3 ushorts), fog (float), edge flag (byte), texcoord (2 doubles)
        // on unit 2 from a separate array.
        let mut element = Vec::new();
        element.extend([100i16, -200, 300].iter().flat_map(|v| v.to_ne_bytes()));
        element.extend([0, 0]);
        element.extend([127u8, 0x80, 0]);
        element.push(0);
        element.extend([65535u16, 0, 257].iter().flat_map(|v| v.to_ne_bytes()));
        element.extend(2.5f32.to_ne_bytes());
        element.push(0);
        element.extend([0; 9]);
        assert_eq!(element.len(), 32);
        let base = memory.add(0x1000, [element.clone(), element].concat());
        let tex = memory.add(0x9000, [0.5f64, -1.0, 0.25, 2.0].iter().flat_map(|v| v.to_ne_bytes()).collect());
        ctx.vertex_pointer(3, GL_SHORT, 32, base);
        ctx.normal_pointer(GL_BYTE, 32, base + 8);
        ctx.secondary_color_pointer(3, GL_UNSIGNED_SHORT, 32, base + 12);
        ctx.fog_coord_pointer(GL_FLOAT, 32, base + 18);
        ctx.edge_flag_pointer(32, base + 22);
        ctx.client_active_texture(GL_TEXTURE2);
        ctx.tex_coord_pointer(2, GL_DOUBLE, 0, tex);
        for cap in [
            GL_VERTEX_ARRAY,
            GL_NORMAL_ARRAY,
            GL_SECONDARY_COLOR_ARRAY,
            GL_FOG_COORD_ARRAY,
            GL_EDGE_FLAG_ARRAY,
            GL_TEXTURE_COORD_ARRAY,
        ] {
            ctx.enable_client_state(cap, true);
        }
        ctx.draw_arrays(GL_POINTS, 0, 2, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let v = ctx.vertex_input.delivered[0].1[1];
        assert_eq!(v.position, [100.0, -200.0, 300.0, 1.0]);
        assert_eq!(v.normal, [1.0, -1.0, 1.0 / 255.0]);
        assert_eq!(v.secondary_color, [1.0, 0.0, 257.0 * (1.0 / 65535.0), 1.0]);
        assert_eq!(v.fog_coord, 2.5);
        assert!(!v.edge_flag);
        assert_eq!(v.tex_coords[2], [0.25, 2.0, 0.0, 1.0]);
        assert_eq!(v.tex_coords[0], [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(v.color, [1.0; 4]);
        // Element 1 of a stride-32 array of 6-byte positions ends 38 bytes after the pointer.
        assert_eq!(memory.reads.borrow()[0], (0x1000, 38));
    }

    #[test]
    fn buffer_objects_feed_arrays_and_indices() {
        let mut ctx = context();
        let memory = FakeMemory::default();
        let [vbo, ibo] = ctx.gen_buffers(2).unwrap()[..] else { panic!() };
        ctx.bind_buffer(GL_ARRAY_BUFFER, vbo);
        let positions: Vec<f32> = (0..4).flat_map(|i| [i as f32, 1.0, 2.0]).collect();
        let mut data = vec![0xffu8; 4];
        data.extend(floats(&positions));
        ctx.buffer_data(GL_ARRAY_BUFFER, data.len() as isize, GL_STATIC_DRAW, |n| Some(&data[..n]));
        ctx.vertex_pointer(3, GL_FLOAT, 0, 4);
        ctx.enable_client_state(GL_VERTEX_ARRAY, true);
        ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
        let indices: Vec<u8> = [9u16, 3, 0, 2].iter().flat_map(|v| v.to_ne_bytes()).collect();
        ctx.buffer_data(GL_ELEMENT_ARRAY_BUFFER, 8, GL_STATIC_DRAW, |n| Some(&indices[..n]));
        // Offsets 2.. of the index buffer: 3, 0, 2.
        ctx.draw_elements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, 2, &memory);
        // An index beyond the vertex data (9) reads zeros there.
        ctx.draw_elements(GL_POINTS, 1, GL_UNSIGNED_SHORT, 0, &memory);
        // Indices beyond the element buffer draw nothing.
        ctx.draw_elements(GL_POINTS, 4, GL_UNSIGNED_SHORT, 2, &memory);
        ctx.draw_arrays(GL_POINTS, 1, 1, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert!(memory.reads.borrow().is_empty(), "nothing came from client memory");
        let batches: Vec<_> = ctx.vertex_input.delivered.iter().map(|(_, v)| v.clone()).collect();
        assert_eq!(batches.len(), 3);
        assert_eq!(xs(&batches[0]), [3.0, 0.0, 2.0]);
        assert_eq!(batches[0][0].position, [3.0, 1.0, 2.0, 1.0]);
        assert_eq!(batches[1][0].position, [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(batches[2][0].position, [1.0, 1.0, 2.0, 1.0]);
    }

    #[test]
    fn mapped_buffers_cannot_be_drawn_from() {
        let mut ctx = context();
        let memory = FakeMemory::default();
        ctx.bind_buffer(GL_ARRAY_BUFFER, 1);
        ctx.buffer_data(GL_ARRAY_BUFFER, 64, GL_STATIC_DRAW, |_| None);
        ctx.vertex_pointer(2, GL_FLOAT, 0, 0);
        ctx.enable_client_state(GL_VERTEX_ARRAY, true);
        ctx.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
        ctx.draw_arrays(GL_POINTS, 0, 1, &memory);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.begin(GL_POINTS);
        ctx.array_element(0, &memory);
        ctx.end();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        // A mapped buffer that no enabled array uses is fine; a mapped element buffer is not.
        ctx.enable_client_state(GL_VERTEX_ARRAY, false);
        ctx.draw_arrays(GL_POINTS, 0, 1, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 1);
        ctx.draw_elements(GL_POINTS, 1, GL_UNSIGNED_BYTE, 0, &memory);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.unmap_buffer(GL_ARRAY_BUFFER);
        ctx.enable_client_state(GL_VERTEX_ARRAY, true);
        ctx.draw_elements(GL_POINTS, 1, GL_UNSIGNED_BYTE, 0, &memory);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.vertex_input.delivered.len(), 1);
    }

    #[test]
    fn draw_errors_in_mesas_order() {
        let (mut ctx, memory) = drawing_context();
        type Call<'a> = &'a dyn Fn(&mut Context);
        let cases: [(Call, GLenum); 14] = [
            (&|c| c.draw_arrays(GL_POINTS, 0, -1, &memory), GL_INVALID_VALUE),
            (&|c| c.draw_arrays(GL_POLYGON + 1, 0, -1, &memory), GL_INVALID_VALUE),
            (&|c| c.draw_arrays(GL_POLYGON + 1, 0, 1, &memory), GL_INVALID_ENUM),
            (&|c| c.draw_elements(GL_POLYGON + 1, -1, GL_FLOAT, 0, &memory), GL_INVALID_VALUE),
            (&|c| c.draw_elements(GL_POLYGON + 1, 1, GL_FLOAT, 0, &memory), GL_INVALID_ENUM),
            (&|c| c.draw_elements(GL_POINTS, 0, GL_BYTE, 0, &memory), GL_INVALID_ENUM),
            (&|c| c.draw_range_elements(GL_POLYGON + 1, 2, 1, -1, GL_FLOAT, 0, &memory), GL_INVALID_VALUE),
            (&|c| c.draw_range_elements(GL_POINTS, 1, 2, 1, GL_FLOAT, 0, &memory), GL_INVALID_ENUM),
            (&|c| c.multi_draw_arrays(GL_POLYGON + 1, &[], &[], -1, &memory), GL_INVALID_VALUE),
            (&|c| c.multi_draw_arrays(GL_POLYGON + 1, &[0], &[-1], 1, &memory), GL_INVALID_ENUM),
            (&|c| c.multi_draw_arrays(GL_POINTS, &[0, 0], &[3, -1], 2, &memory), GL_INVALID_VALUE),
            (&|c| c.multi_draw_elements(GL_POINTS, &[-1], GL_FLOAT, &[0], 1, &memory), GL_INVALID_ENUM),
            (&|c| c.multi_draw_elements(GL_POINTS, &[-1], GL_UNSIGNED_INT, &[0], 1, &memory), GL_INVALID_VALUE),
            (&|c| c.multi_draw_elements(GL_POLYGON + 1, &[], GL_FLOAT, &[], -1, &memory), GL_INVALID_VALUE),
        ];
        for (i, (call, error)) in cases.iter().enumerate() {
            call(&mut ctx);
            assert_eq!(ctx.take_error(), *error, "case {i}");
        }
        assert!(ctx.vertex_input.delivered.is_empty());
        ctx.begin(GL_POINTS);
        ctx.draw_arrays(GL_POINTS, 0, 1, &memory);
        ctx.draw_elements(GL_POINTS, 1, GL_UNSIGNED_BYTE, 0, &memory);
        ctx.multi_draw_arrays(GL_POINTS, &[0], &[1], 1, &memory);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.end();
        assert!(ctx.vertex_input.delivered.is_empty());
    }

    #[test]
    fn undefined_draws_draw_nothing() {
        let (mut ctx, memory) = drawing_context();
        ctx.draw_arrays(GL_POINTS, -1, 3, &memory);
        ctx.draw_arrays(GL_POINTS, 0, 0, &memory);
        ctx.draw_elements(GL_POINTS, 3, GL_UNSIGNED_BYTE, 0, &memory);
        ctx.color_pointer(4, GL_UNSIGNED_BYTE, 0, 0);
        ctx.draw_arrays(GL_POINTS, 0, 3, &memory);
        ctx.color_pointer(4, GL_UNSIGNED_BYTE, 0, 0x2000);
        ctx.enable_client_state(GL_VERTEX_ARRAY, false);
        ctx.draw_arrays(GL_POINTS, 0, 3, &memory);
        ctx.begin(GL_POINTS);
        ctx.array_element(-1, &memory);
        ctx.end();
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert!(ctx.vertex_input.delivered.is_empty());
        // An array whose buffer was deleted.
        ctx.enable_client_state(GL_VERTEX_ARRAY, true);
        ctx.bind_buffer(GL_ARRAY_BUFFER, 4);
        ctx.buffer_data(GL_ARRAY_BUFFER, 64, GL_STATIC_DRAW, |_| None);
        ctx.normal_pointer(GL_FLOAT, 0, 0);
        ctx.enable_client_state(GL_NORMAL_ARRAY, true);
        ctx.delete_buffers(1, &[4]);
        ctx.draw_arrays(GL_POINTS, 0, 3, &memory);
        assert!(ctx.vertex_input.delivered.is_empty());
        ctx.enable_client_state(GL_NORMAL_ARRAY, false);
        ctx.draw_arrays(GL_POINTS, 0, 3, &memory);
        assert_eq!(ctx.vertex_input.delivered.len(), 1);
    }

    #[test]
    fn array_element_sets_current_attributes_then_emits_a_vertex() {
        let (mut ctx, mut memory) = drawing_context();
        let index = memory.add(0x6000, floats(&[0.0, 1.0, 2.0, 3.0, 4.0, 5.0]));
        ctx.index_pointer(GL_FLOAT, 0, index);
        ctx.enable_client_state(GL_INDEX_ARRAY, true);
        ctx.array_element(3, &memory);
        assert_eq!(ctx.state.current.color, [3.0 / 255.0, 6.0 / 255.0, 9.0 / 255.0, 1.0]);
        assert_eq!(ctx.state.current.index, 3.0);
        assert!(ctx.vertex_input.delivered.is_empty(), "outside glBegin/glEnd no vertex is made");
        ctx.begin(GL_LINES);
        ctx.array_element(1, &memory);
        ctx.end();
        ctx.enable_client_state(GL_COLOR_ARRAY, false);
        ctx.begin(GL_LINES);
        ctx.array_element(4, &memory);
        ctx.set_color([0.5; 4]);
        ctx.array_element(5, &memory);
        ctx.end();
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        let (mode, vertices) = &ctx.vertex_input.delivered[0];
        assert_eq!((*mode, xs(vertices)), (GL_LINES, vec![1.0]));
        assert_eq!(vertices[0].color, [1.0 / 255.0, 2.0 / 255.0, 3.0 / 255.0, 1.0]);
        let vertices = &ctx.vertex_input.delivered[1].1;
        assert_eq!(xs(vertices), [4.0, 5.0]);
        // Without the color array the vertices take the current color, which the first
        // element of this primitive left at element 1's color.
        assert_eq!(vertices[0].color, [1.0 / 255.0, 2.0 / 255.0, 3.0 / 255.0, 1.0]);
        assert_eq!(vertices[1].color, [0.5; 4]);
        assert_eq!(vertices[1].position, [5.0, 50.0, 0.0, 1.0]);
        // Only element 5 was read for the last call.
        let reads = memory.reads.borrow();
        assert_eq!(reads[reads.len() - 2..], [(0x1028, 8), (0x6014, 4)]);
    }
}
