//! Which context is current on which thread.
//!
//! A context is shared (`Arc<SharedContext>`) between the window-system object that created
//! it and the thread-local "current" slot. GL state lives behind a mutex that only the thread
//! the context is current on locks in practice, so the lock is uncontended; it exists so that
//! a misbehaving program (destroying or binding a context from another thread) gets an error
//! instead of memory corruption.
use super::Context;
use std::cell::RefCell;
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::ThreadId;

/// A GL context as shared between its owner (OSMesa/GLX object) and the current slot.
pub struct SharedContext {
    gl: Mutex<Context>,
    /// The thread this context is current on, if any.
    bound_to: Mutex<Option<ThreadId>>,
}

impl SharedContext {
    pub fn new(context: Context) -> Arc<Self> {
        Arc::new(SharedContext { gl: Mutex::new(context), bound_to: Mutex::new(None) })
    }

    /// Locks the GL state. A panic caught at the API edge while the lock was held leaves the
    /// state as it was at that point; the context stays usable.
    pub fn lock(&self) -> MutexGuard<'_, Context> {
        self.gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    /// The thread this context is current on.
    pub fn bound_thread(&self) -> Option<ThreadId> {
        *self.bound_to.lock().unwrap_or_else(|p| p.into_inner())
    }
}

/// The thread-local slot; when the thread exits, its current context is released so that
/// another thread may bind it.
struct CurrentSlot(Option<Arc<SharedContext>>);

impl Drop for CurrentSlot {
    fn drop(&mut self) {
        if let Some(ctx) = self.0.take() {
            *ctx.bound_to.lock().unwrap_or_else(|p| p.into_inner()) = None;
        }
    }
}

thread_local! {
    static CURRENT: RefCell<CurrentSlot> = const { RefCell::new(CurrentSlot(None)) };
}

/// Why a context could not be made current.
#[derive(Debug, PartialEq, Eq)]
pub enum BindError {
    /// The context is current on another thread (GLX: BadAccess).
    CurrentElsewhere,
}

/// Makes `context` current on this thread (or releases the current one with `None`).
/// The previously current context, if different, is flushed and released.
pub fn make_current(context: Option<Arc<SharedContext>>) -> Result<(), BindError> {
    let me = std::thread::current().id();
    if let Some(ctx) = &context {
        let mut bound = ctx.bound_to.lock().unwrap_or_else(|p| p.into_inner());
        match *bound {
            Some(other) if other != me => return Err(BindError::CurrentElsewhere),
            _ => *bound = Some(me),
        }
    }
    // At process exit (atexit handlers releasing their context) the slot may already be
    // destroyed: then nothing is current any more and nothing needs releasing.
    let previous = CURRENT.try_with(|slot| std::mem::replace(&mut slot.borrow_mut().0, context.clone())).ok().flatten();
    if let Some(prev) = previous {
        let same = context.as_ref().is_some_and(|c| Arc::ptr_eq(c, &prev));
        if !same {
            prev.lock().flush();
            *prev.bound_to.lock().unwrap_or_else(|p| p.into_inner()) = None;
        }
    }
    Ok(())
}

/// The context current on this thread.
pub fn current() -> Option<Arc<SharedContext>> {
    CURRENT.try_with(|slot| slot.borrow().0.clone()).ok().flatten()
}

/// Runs `f` on the current context; `None` when no context is current.
pub fn with_current<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    CURRENT
        .try_with(|slot| {
            let slot = slot.borrow();
            let shared = slot.0.as_ref()?;
            let mut gl = shared.lock();
            #[cfg(test)]
            if PANIC_WHILE_LOCKED.with(|p| p.get()) {
                panic!("injected panic while holding the context");
            }
            Some(f(&mut gl))
        })
        .ok()
        .flatten()
}

#[cfg(test)]
thread_local! {
    /// Test builds: make every entry point on this thread panic while it holds the current
    /// context's lock (see `api::panic_injection`).
    pub static PANIC_WHILE_LOCKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}
