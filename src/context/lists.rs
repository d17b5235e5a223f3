//! Display lists: glNewList/glEndList, glCallList(s), glListBase, glGenLists, glDeleteLists,
//! glIsList and the GL_LIST_* queries.
//!
//! A list is a sequence of recorded commands, each an owned closure over the context
//! ([`Command`]). The API edge sends every compilable command through
//! [`Context::record_or_run`]: outside glNewList/glEndList that is one branch and a direct
//! call; while compiling, the closure is stored (and, under GL_COMPILE_AND_EXECUTE, also run).
//! Commands keep their arguments by value, so everything a pointer argument designates (vector
//! forms, matrices, images under the unpack modes, vertex arrays) is read when the command is
//! compiled, as GL 2.1 section 5.4 requires; the recorded closure validates when it runs, so
//! the errors of a compiled command are raised at execution. The commands section 5.4 lists as
//! not compiled (glGen*/glGet*/glIs*, client state, glReadPixels, glPixelStore, glFlush,
//! glFinish, glFeedbackBuffer, glSelectBuffer, glRenderMode, the buffer object commands, the
//! array pointers, ...) simply do not go through `record_or_run` and always execute.
//!
//! The name space is an `Arc` shared by the contexts created with a share context. A list is
//! installed at glEndList (until then the name keeps its old list, or none), and a list being
//! executed is held by its own `Arc`, so deleting or redefining it meanwhile is harmless.
//!
//! Nesting: glCallList inside a list executes the named list as it is when the outer list
//! runs; beyond [`MAX_LIST_NESTING`] levels further calls are ignored, as the specification
//! says.
use super::get::Value;
use super::Context;
use crate::gl::enums::*;
use crate::gl::names::{NameTable, OutOfNames};
use crate::gl::types::GLenum;
use std::sync::{Arc, Mutex, MutexGuard};

/// GL_MAX_LIST_NESTING (the specification's minimum, and Mesa's value).
pub const MAX_LIST_NESTING: u32 = 64;

/// One recorded command: it runs the command on the context that executes the list.
pub type Command = Box<dyn Fn(&mut Context) + Send + Sync>;

/// A compiled display list.
#[derive(Default)]
pub struct DisplayList {
    commands: Vec<Command>,
}

/// The largest block of names one glGenLists reserves (about 4 million: a few hundred MiB of
/// table entries); larger requests are GL_OUT_OF_MEMORY.
pub const MAX_RESERVED_BLOCK: u32 = 1 << 22;

/// The display list names of a share group: a name maps to its list (an empty list for names
/// reserved by glGenLists).
pub type ListNames = Arc<Mutex<NameTable<Arc<DisplayList>>>>;

/// The list under construction between glNewList and glEndList.
struct Compiling {
    name: u32,
    execute: bool,
    commands: Vec<Command>,
}

/// The display list state of one context (the list base is `state.list_base`, in GL_LIST_BIT).
pub struct ListState {
    names: ListNames,
    compiling: Option<Compiling>,
    /// How many glCallList levels are executing.
    depth: u32,
}

impl Default for ListState {
    fn default() -> Self {
        ListState { names: Arc::new(Mutex::new(NameTable::default())), compiling: None, depth: 0 }
    }
}

impl ListState {
    /// The name space, to give to a context that shares it.
    pub fn names(&self) -> ListNames {
        self.names.clone()
    }

    /// Uses `names` (another context's) as this context's name space.
    pub fn share(&mut self, names: ListNames) {
        self.names = names;
    }

    /// Whether a list is being compiled (commands are recorded).
    #[inline]
    pub fn compiling(&self) -> bool {
        self.compiling.is_some()
    }

    fn table(&self) -> MutexGuard<'_, NameTable<Arc<DisplayList>>> {
        self.names.lock().unwrap_or_else(|p| p.into_inner())
    }
}

/// Decodes glCallLists' `lists` array of `n` names of `type_` (the caller passes exactly the
/// bytes: `n` times [`call_lists_type_size`]); the names are offsets to add to the list base.
pub fn decode_call_lists(type_: GLenum, bytes: &[u8]) -> Vec<i64> {
    let size = call_lists_type_size(type_).unwrap_or(1);
    bytes
        .chunks_exact(size)
        .map(|c| match type_ {
            GL_BYTE => c[0] as i8 as i64,
            GL_UNSIGNED_BYTE => c[0] as i64,
            GL_SHORT => i16::from_ne_bytes([c[0], c[1]]) as i64,
            GL_UNSIGNED_SHORT => u16::from_ne_bytes([c[0], c[1]]) as i64,
            GL_INT => i32::from_ne_bytes([c[0], c[1], c[2], c[3]]) as i64,
            GL_UNSIGNED_INT => u32::from_ne_bytes([c[0], c[1], c[2], c[3]]) as i64,
            // C's float-to-unsigned conversion, as Mesa (saturating here, where C is undefined).
            GL_FLOAT => f32::from_ne_bytes([c[0], c[1], c[2], c[3]]) as u32 as i64,
            // The multi-byte types are big-endian byte sequences whatever the host order.
            GL_2_BYTES => (c[0] as i64) << 8 | c[1] as i64,
            GL_3_BYTES => (c[0] as i64) << 16 | (c[1] as i64) << 8 | c[2] as i64,
            GL_4_BYTES => (c[0] as i64) << 24 | (c[1] as i64) << 16 | (c[2] as i64) << 8 | c[3] as i64,
            _ => 0,
        })
        .collect()
}

/// Bytes per name of a glCallLists type; `None` for an invalid type.
pub fn call_lists_type_size(type_: GLenum) -> Option<usize> {
    Some(match type_ {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT | GL_2_BYTES => 2,
        GL_3_BYTES => 3,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT | GL_4_BYTES => 4,
        _ => return None,
    })
}

impl Context {
    /// Runs `command` now, or records it when a list is being compiled (and also runs it under
    /// GL_COMPILE_AND_EXECUTE). The path of every compilable command from the API edge.
    #[inline]
    pub fn record_or_run<F: Fn(&mut Context) + Send + Sync + 'static>(&mut self, command: F) {
        if self.lists.compiling.is_none() {
            command(self)
        } else {
            self.record(command)
        }
    }

    /// Boxes `command` for [`Self::record_boxed`]: the only part compiled once per command
    /// type (about 300), so that the rest, compiled once, is not copied into each.
    #[cold]
    fn record<F: Fn(&mut Context) + Send + Sync + 'static>(&mut self, command: F) {
        self.record_boxed(Box::new(command))
    }

    /// [`Self::record`] of a boxed command (run through its vtable under
    /// GL_COMPILE_AND_EXECUTE, as list playback runs it).
    #[inline(never)]
    fn record_boxed(&mut self, command: Command) {
        if self.lists.compiling.as_ref().is_some_and(|c| c.execute) {
            command(self);
        }
        // Running the command cannot end the compilation (glEndList is not compiled).
        let Some(compiling) = self.lists.compiling.as_mut() else {
            return;
        };
        if compiling.commands.try_reserve(1).is_err() {
            return self.error(GL_OUT_OF_MEMORY);
        }
        compiling.commands.push(command);
    }

    /// glNewList.
    pub fn new_list(&mut self, name: u32, mode: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if name == 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE {
            return self.error(GL_INVALID_ENUM);
        }
        if self.lists.compiling() {
            return self.error(GL_INVALID_OPERATION);
        }
        let execute = mode == GL_COMPILE_AND_EXECUTE;
        self.lists.compiling = Some(Compiling { name, execute, commands: Vec::new() });
    }

    /// glEndList: installs the compiled list under its name.
    pub fn end_list(&mut self) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some(compiling) = self.lists.compiling.take() else {
            return self.error(GL_INVALID_OPERATION);
        };
        let list = Arc::new(DisplayList { commands: compiling.commands });
        self.lists.table().insert(compiling.name, list);
    }

    /// glCallList: executes list `name` (nothing if there is none).
    pub fn call_list(&mut self, name: u32) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(list) = self.lists.table().get(name).cloned() else {
            return;
        };
        self.lists.depth += 1;
        for command in &list.commands {
            command(self);
        }
        self.lists.depth -= 1;
    }

    /// glCallLists after decoding: `offsets` are added to the list base (with wrap-around, as
    /// GLuint arithmetic). `Err` holds the error the arguments raised.
    pub fn call_lists(&mut self, offsets: &Result<Vec<i64>, GLenum>) {
        match offsets {
            Ok(offsets) => {
                for &offset in offsets {
                    let name = (self.state.list_base as i64).wrapping_add(offset) as u32;
                    self.call_list(name);
                }
            }
            Err(error) => self.error(*error),
        }
    }

    /// glListBase.
    pub fn list_base(&mut self, base: u32) {
        if self.check_outside_begin_end() {
            self.state.list_base = base;
        }
    }

    /// glGenLists: reserves `range` consecutive names (as empty lists) and returns the first.
    pub fn gen_lists(&mut self, range: i32) -> u32 {
        if !self.check_outside_begin_end() {
            return 0;
        }
        if range < 0 {
            self.error(GL_INVALID_VALUE);
            return 0;
        }
        if range == 0 {
            return 0;
        }
        // Reserved names are table entries: a block larger than this would take gigabytes
        // (or abort the process), so it fails as an allocation failure would.
        if range as u32 > MAX_RESERVED_BLOCK {
            self.error(GL_OUT_OF_MEMORY);
            return 0;
        }
        let empty = Arc::new(DisplayList::default());
        let names = self.lists.table().generate_objects(range as usize, || empty.clone());
        match names {
            Ok(names) => names[0],
            Err(OutOfNames) => {
                self.error(GL_OUT_OF_MEMORY);
                0
            }
        }
    }

    /// glDeleteLists.
    pub fn delete_lists(&mut self, first: u32, range: i32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if range < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        if range == 0 {
            return;
        }
        let last = first.saturating_add(range as u32 - 1);
        self.lists.table().delete_range(first..=last);
    }

    /// glIsList.
    pub fn is_list(&mut self, name: u32) -> bool {
        if !self.check_outside_begin_end() {
            return false;
        }
        self.lists.table().is_object(name)
    }

    /// The glGet values of the display list state; `None` for other pnames.
    pub(crate) fn list_values(&self, pname: GLenum) -> Option<Vec<Value>> {
        let (index, mode) = self.list_compilation();
        Some(vec![match pname {
            GL_LIST_BASE => Value::Int(self.state.list_base as i32),
            GL_LIST_INDEX => Value::Int(index as i32),
            GL_LIST_MODE => Value::Enum(mode),
            GL_MAX_LIST_NESTING => Value::Int(MAX_LIST_NESTING as i32),
            _ => return None,
        }])
    }

    /// GL_LIST_INDEX and GL_LIST_MODE: the list being compiled and its mode (0 when none).
    pub(crate) fn list_compilation(&self) -> (u32, GLenum) {
        match &self.lists.compiling {
            Some(c) => (c.name, if c.execute { GL_COMPILE_AND_EXECUTE } else { GL_COMPILE }),
            None => (0, 0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::vertex_input::test_support::context;

    #[test]
    fn call_lists_types_decode_as_the_spec_says() {
        assert_eq!(decode_call_lists(GL_BYTE, &[0xff, 3]), vec![-1, 3]);
        assert_eq!(decode_call_lists(GL_UNSIGNED_BYTE, &[0xff, 3]), vec![255, 3]);
        assert_eq!(decode_call_lists(GL_SHORT, &(-2i16).to_ne_bytes()), vec![-2]);
        assert_eq!(decode_call_lists(GL_UNSIGNED_SHORT, &65535u16.to_ne_bytes()), vec![65535]);
        assert_eq!(decode_call_lists(GL_INT, &(-7i32).to_ne_bytes()), vec![-7]);
        assert_eq!(decode_call_lists(GL_UNSIGNED_INT, &4_000_000_000u32.to_ne_bytes()), vec![4_000_000_000]);
        assert_eq!(decode_call_lists(GL_FLOAT, &3.75f32.to_ne_bytes()), vec![3]);
        assert_eq!(decode_call_lists(GL_2_BYTES, &[1, 2, 0, 5]), vec![258, 5]);
        assert_eq!(decode_call_lists(GL_3_BYTES, &[1, 0, 2]), vec![65538]);
        assert_eq!(decode_call_lists(GL_4_BYTES, &[1, 0, 0, 3]), vec![16777219]);
        assert_eq!(call_lists_type_size(GL_DOUBLE), None);
    }

    #[test]
    fn gen_lists_continues_after_the_largest_name_then_finds_gaps() {
        let mut ctx = context();
        assert_eq!(ctx.gen_lists(3), 1);
        assert_eq!(ctx.gen_lists(2), 4);
        ctx.delete_lists(2, 1);
        assert_eq!(ctx.gen_lists(1), 6, "after the largest name, as Mesa");
        assert!(ctx.is_list(5) && !ctx.is_list(2) && !ctx.is_list(8));
        assert_eq!(ctx.gen_lists(0), 0);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.gen_lists(-1), 0);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        // Near the end of the name space, the first gap large enough (context::names).
        ctx.new_list(u32::MAX - 1, GL_COMPILE);
        ctx.end_list();
        assert_eq!(ctx.gen_lists(5), 7, "5 names do not fit after u32::MAX - 1: the first gap");
        assert_eq!(ctx.gen_lists(1), u32::MAX, "one does");
        assert_eq!(ctx.gen_lists(1), 2, "then the first gap from 1");
    }

    #[test]
    fn compiled_commands_run_at_call_time_and_nest_to_the_limit() {
        let mut ctx = context();
        ctx.new_list(1, GL_COMPILE);
        ctx.record_or_run(|ctx| ctx.state.list_base += 1);
        assert_eq!(ctx.state.list_base, 0, "GL_COMPILE does not execute");
        assert_eq!(ctx.list_compilation(), (1, GL_COMPILE));
        assert!(!ctx.is_list(1), "the list exists from glEndList on");
        ctx.end_list();
        ctx.call_list(1);
        ctx.call_list(1);
        assert_eq!(ctx.state.list_base, 2);
        // A list that calls itself runs MAX_LIST_NESTING times.
        ctx.state.list_base = 0;
        ctx.new_list(2, GL_COMPILE_AND_EXECUTE);
        ctx.record_or_run(|ctx| ctx.state.list_base += 1);
        ctx.record_or_run(|ctx| ctx.call_list(2));
        assert_eq!(ctx.state.list_base, 1, "executed once while compiling, list 2 not yet defined");
        ctx.end_list();
        ctx.state.list_base = 0;
        ctx.call_list(2);
        assert_eq!(ctx.state.list_base, MAX_LIST_NESTING);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        // Errors of glNewList/glEndList.
        ctx.end_list();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        ctx.new_list(0, GL_COMPILE);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.new_list(3, GL_FLOAT);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.new_list(3, GL_COMPILE);
        ctx.new_list(4, GL_COMPILE);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.list_compilation(), (3, GL_COMPILE));
    }
}
