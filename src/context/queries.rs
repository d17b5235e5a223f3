//! Occlusion queries (GL 1.5): glGenQueries, glDeleteQueries, glIsQuery,
//! glBeginQuery/glEndQuery(GL_SAMPLES_PASSED), glGetQueryiv, glGetQueryObject(u)iv.
//!
//! A query's counter is shared with the draw states recorded while it is active; the
//! rasterizer adds the fragments of each span that pass the depth and stencil tests (a sum,
//! so the count is exact and the same for any number of threads). Asking for the result
//! runs the pending scene first, so a result is always available when asked for.
use super::Context;
use crate::gl::enums::*;
use crate::gl::names::{NameTable, OutOfNames};
use crate::gl::types::GLenum;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// One query object.
#[derive(Debug, Default)]
struct QueryObject {
    /// The counter of its last glBeginQuery (none before the first).
    counter: Option<Arc<AtomicU64>>,
}

/// The query objects of a context and the active occlusion query.
#[derive(Debug, Default)]
pub struct QueryState {
    objects: NameTable<QueryObject>,
    active: Option<(u32, Arc<AtomicU64>)>,
}

impl QueryState {
    /// The counter draws add their passing fragments to, while a query is active.
    pub fn active_counter(&self) -> Option<Arc<AtomicU64>> {
        self.active.as_ref().map(|(_, counter)| counter.clone())
    }
}

impl Context {
    /// glGenQueries: `n` unused names (created as query objects, as in Mesa).
    pub fn gen_queries(&mut self, n: i32) -> Option<Vec<u32>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if n < 0 {
            self.error(GL_INVALID_VALUE);
            return None;
        }
        match self.queries.objects.generate_objects(n as usize, QueryObject::default) {
            Ok(names) => Some(names),
            Err(OutOfNames) => {
                self.error(GL_OUT_OF_MEMORY);
                None
            }
        }
    }

    /// glDeleteQueries: deleting the active query ends it.
    pub fn delete_queries(&mut self, n: i32, names: &[u32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if n < 0 {
            return self.error(GL_INVALID_VALUE);
        }
        for name in names {
            if self.queries.active.as_ref().is_some_and(|(active, _)| active == name) {
                self.queries.active = None;
            }
            self.queries.objects.delete(*name);
        }
    }

    /// glIsQuery.
    pub fn is_query(&mut self, name: u32) -> bool {
        if !self.check_outside_begin_end() {
            return false;
        }
        name != 0 && self.queries.objects.is_object(name)
    }

    /// glBeginQuery.
    pub fn begin_query(&mut self, target: GLenum, name: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        if target != GL_SAMPLES_PASSED {
            return self.error(GL_INVALID_ENUM);
        }
        if name == 0 || self.queries.active.is_some() {
            return self.error(GL_INVALID_OPERATION);
        }
        let counter = Arc::new(AtomicU64::new(0));
        if let Some(object) = self.queries.objects.get_or_create(name, QueryObject::default) {
            object.counter = Some(counter.clone());
        }
        self.queries.active = Some((name, counter));
    }

    /// glEndQuery.
    pub fn end_query(&mut self, target: GLenum) {
        if !self.check_outside_begin_end() {
            return;
        }
        if target != GL_SAMPLES_PASSED {
            return self.error(GL_INVALID_ENUM);
        }
        if self.queries.active.take().is_none() {
            self.error(GL_INVALID_OPERATION);
        }
    }

    /// glGetQueryiv.
    pub fn get_query(&mut self, target: GLenum, pname: GLenum) -> Option<i32> {
        if !self.check_outside_begin_end() {
            return None;
        }
        if target != GL_SAMPLES_PASSED {
            self.error(GL_INVALID_ENUM);
            return None;
        }
        match pname {
            GL_QUERY_COUNTER_BITS => Some(64),
            GL_CURRENT_QUERY => Some(self.queries.active.as_ref().map_or(0, |(name, _)| *name as i32)),
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGetQueryObject(u)iv: the result (running the pending scene first) or its
    /// availability (always true then).
    pub fn get_query_object(&mut self, name: u32, pname: GLenum) -> Option<u64> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let active = self.queries.active.as_ref().is_some_and(|(a, _)| *a == name);
        let Some(object) = self.queries.objects.get(name).filter(|_| name != 0 && !active) else {
            self.error(GL_INVALID_OPERATION);
            return None;
        };
        let counter = object.counter.clone();
        match pname {
            GL_QUERY_RESULT | GL_QUERY_RESULT_AVAILABLE => {
                self.flush_rendering();
                let count = counter.map_or(0, |c| c.load(Ordering::Relaxed));
                Some(if pname == GL_QUERY_RESULT { count } else { 1 })
            }
            _ => {
                self.error(GL_INVALID_ENUM);
                None
            }
        }
    }
}
