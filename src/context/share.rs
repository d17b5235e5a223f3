//! Share groups: the objects that contexts created with a share context have in common.
//!
//! GL 2.1 appendix D: texture objects, buffer objects, shader and program objects and
//! display lists (names and contents) are shared by a context and every context created with it as share context
//! (OSMesaCreateContextExt/Attribs' and glXCreateContext's share list argument), and so,
//! here, are the compiled fixed-function programs (`super::programs`). Each kind
//! of object is one table behind a [`Shared`] handle (an `Arc<Mutex<_>>`): the contexts of a
//! group hold the same handle, and a command locks the table only for as long as it reads or
//! changes it (never while it holds another table's lock, so two contexts drawing on two
//! threads cannot deadlock). Display lists have their own name space handle
//! ([`super::lists::ListNames`]).
//!
//! Deliberate simplification: deleting a shared object removes it from the group at once.
//! GL keeps an object deleted in one context alive while it stays bound in another; here the
//! other context's binding then names nothing (it draws untextured, or from no buffer, as
//! after its own glDelete*), and the proxy textures are shared with the textures (GL gives
//! each context its own).
use std::sync::{Arc, Mutex, MutexGuard};

/// A table shared by the contexts of a share group.
#[derive(Debug)]
pub struct Shared<T>(Arc<Mutex<T>>);

impl<T> Shared<T> {
    pub fn new(value: T) -> Self {
        Shared(Arc::new(Mutex::new(value)))
    }

    /// The table, locked for the caller (a panic while it was locked left a consistent
    /// table: commands validate before they change anything).
    pub fn lock(&self) -> MutexGuard<'_, T> {
        self.0.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Whether `other` is the same table (the two contexts share it).
    pub fn same_as(&self, other: &Shared<T>) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl<T> Clone for Shared<T> {
    fn clone(&self) -> Self {
        Shared(self.0.clone())
    }
}

impl<T: Default> Default for Shared<T> {
    fn default() -> Self {
        Shared::new(T::default())
    }
}

/// The handles of a share group's tables. A context keeps a copy beside its state
/// (`current::SharedContext`), so that a new context can join the group of one that is
/// current on another thread, whose state that thread holds.
#[derive(Clone)]
pub struct ShareGroup {
    textures: Shared<crate::context::texture::TextureTable>,
    programs: Shared<super::programs::ProgramCaches>,
    buffers: Shared<crate::vertex::buffer_objects::BufferTable>,
    shader_objects: Shared<super::shader_objects::ShaderObjects>,
    lists: super::lists::ListNames,
}

impl super::Context {
    /// The share group this context belongs to.
    pub fn share_group(&self) -> ShareGroup {
        ShareGroup {
            textures: self.textures.clone(),
            programs: self.programs.clone(),
            buffers: self.buffers.clone(),
            shader_objects: self.shader_objects.clone(),
            lists: self.lists.names(),
        }
    }

    /// Makes this (new) context share the objects of `group`: its texture objects, buffer
    /// objects, shader and program objects and display lists.
    pub fn join_share_group(&mut self, group: &ShareGroup) {
        self.textures = group.textures.clone();
        self.programs = group.programs.clone();
        self.buffers = group.buffers.clone();
        self.shader_objects = group.shader_objects.clone();
        self.lists.share(group.lists.clone());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clones_share_one_table() {
        let a = Shared::new(vec![1]);
        let b = a.clone();
        b.lock().push(2);
        assert_eq!(*a.lock(), [1, 2]);
        assert!(a.same_as(&b));
        assert!(!a.same_as(&Shared::new(vec![1, 2])));
    }
}
