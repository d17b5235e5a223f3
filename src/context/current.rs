//! Which context is current on which thread, and where its GL state is.
//!
//! Every GL entry point looks up the current context, so the lookup is the cost of an
//! immediate-mode call: it must not lock anything. The GL state of a context therefore lives
//! in one of two places. While the context is current on a thread, that thread's slot (a
//! thread-local) *owns* the state, and an entry point reaches it with a thread-local access
//! and a `RefCell` borrow: no atomic operation, no lock. While it is current nowhere, the
//! state is parked in its [`SharedContext`], behind a mutex. Making a context current moves
//! the boxed state from its home into the slot; releasing it (another MakeCurrent, or the
//! thread's exit) flushes it and moves it back. GL forbids a context to be current on two
//! threads at once, and this layout makes that a fact rather than a check: a thread that
//! asks for a context current elsewhere finds its home empty and gets an error.
//!
//! Destruction follows GL's rule that deleting a context current on some thread is deferred
//! until it is no longer current: the window-system registries hold one `Arc` of the
//! `SharedContext` and each slot another, so a context destroyed from another thread keeps
//! working where it is current and is dropped when that thread releases it.
//!
//! The window-system code reaches a context that may or may not be current here through
//! [`SharedContext::with_gl`], and a share group's tables through the [`ShareGroup`] handles
//! kept beside the state (a context current on another thread can still be shared).
use super::share::ShareGroup;
use super::Context;
use std::cell::RefCell;
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::ThreadId;

/// A GL context as shared between its owner (OSMesa/GLX object) and the current slot.
pub struct SharedContext {
    home: Mutex<Home>,
    group: ShareGroup,
}

/// Where a context's state is: here (`gl`), or in the slot of the thread `bound_to`.
/// Exactly one of the two is `Some`.
struct Home {
    gl: Option<Box<Context>>,
    bound_to: Option<ThreadId>,
}

impl SharedContext {
    pub fn new(context: Context) -> Arc<Self> {
        let group = context.share_group();
        Arc::new(SharedContext { home: Mutex::new(Home { gl: Some(Box::new(context)), bound_to: None }), group })
    }

    /// The home, locked. A panic caught at the API edge while it was locked left it
    /// consistent (it is changed by single assignments).
    fn home(&self) -> MutexGuard<'_, Home> {
        self.home.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    /// The thread this context is current on.
    pub fn bound_thread(&self) -> Option<ThreadId> {
        self.home().bound_to
    }

    /// The share group of this context: a new context created with this one as its share
    /// context joins it.
    pub fn share_group(&self) -> &ShareGroup {
        &self.group
    }

    /// Runs `f` on this context's state, wherever it is: in the calling thread's slot when
    /// the context is current here, else parked (its home stays locked meanwhile). `None`
    /// when it is current on another thread, whose state that thread alone may touch.
    pub fn with_gl<R>(&self, f: impl FnOnce(&mut Context) -> R) -> Option<R> {
        let mut f = Some(f);
        let here = CURRENT
            .try_with(|slot| {
                let mut slot = slot.try_borrow_mut().ok()?;
                let bound = slot.0.as_mut().filter(|b| std::ptr::eq(Arc::as_ptr(&b.shared), self))?;
                f.take().map(|f| f(&mut bound.gl))
            })
            .ok()
            .flatten();
        match (here, f) {
            (Some(result), _) => Some(result),
            (None, Some(f)) => self.home().gl.as_deref_mut().map(f),
            (None, None) => None,
        }
    }

    /// Runs `f` on this context's state if it is current nowhere (its home stays locked).
    fn with_parked<R>(&self, f: impl FnOnce(&mut Context) -> R) -> Option<R> {
        self.home().gl.as_deref_mut().map(f)
    }

    /// Whether this context is current on the calling thread.
    fn current_here(self: &Arc<Self>) -> bool {
        current().is_some_and(|c| Arc::ptr_eq(&c, self))
    }
}

/// Runs `f` on the states of two different contexts (glXCopyContext): each must be current
/// on the calling thread or on none. Never holds one home's lock while waiting for another
/// in an order another thread could reverse: a context current here needs no lock, and two
/// parked ones are locked in address order.
pub fn with_two<R>(
    a: &Arc<SharedContext>,
    b: &Arc<SharedContext>,
    f: impl FnOnce(&mut Context, &mut Context) -> R,
) -> Option<R> {
    if Arc::ptr_eq(a, b) {
        return None;
    }
    if a.current_here() {
        return a.with_gl(|ga| b.with_parked(|gb| f(ga, gb))).flatten();
    }
    if b.current_here() {
        return b.with_gl(|gb| a.with_parked(|ga| f(ga, gb))).flatten();
    }
    let (x, y) = if Arc::as_ptr(a) < Arc::as_ptr(b) { (a, b) } else { (b, a) };
    let (mut home_x, mut home_y) = (x.home(), y.home());
    let (gx, gy) = (home_x.gl.as_deref_mut()?, home_y.gl.as_deref_mut()?);
    Some(if Arc::ptr_eq(x, a) { f(gx, gy) } else { f(gy, gx) })
}

/// A context current on this thread, with its state.
struct Bound {
    shared: Arc<SharedContext>,
    gl: Box<Context>,
}

impl Bound {
    /// Moves the state back home: the context is current nowhere. When this was the last
    /// reference (the context was destroyed while current), the context is dropped.
    fn park(self) {
        let Bound { shared, gl } = self;
        let mut home = shared.home();
        home.gl = Some(gl);
        home.bound_to = None;
    }
}

/// The thread-local slot; when the thread exits, its current context is released so that
/// another thread may bind it (or dropped, if it was destroyed meanwhile).
struct CurrentSlot(Option<Bound>);

impl Drop for CurrentSlot {
    fn drop(&mut self) {
        if let Some(bound) = self.0.take() {
            bound.park();
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
    /// This thread is exiting (its slot is gone) or is inside a GL call.
    NoSlot,
}

/// Makes `context` current on this thread (or releases the current one with `None`).
/// The previously current context, if different, is flushed and released.
pub fn make_current(context: Option<Arc<SharedContext>>) -> Result<(), BindError> {
    if let Some(ctx) = &context {
        if ctx.current_here() {
            return Ok(());
        }
    }
    let mut incoming = match context {
        Some(shared) => {
            let mut home = shared.home();
            let Some(gl) = home.gl.take() else {
                return Err(BindError::CurrentElsewhere);
            };
            home.bound_to = Some(std::thread::current().id());
            drop(home);
            Some(Bound { shared, gl })
        }
        None => None,
    };
    let swapped = CURRENT.try_with(|slot| {
        slot.try_borrow_mut().map(|mut slot| std::mem::replace(&mut slot.0, incoming.take())).map_err(|_| ())
    });
    let exiting = swapped.is_err();
    match swapped {
        Ok(Ok(previous)) => {
            if let Some(mut prev) = previous {
                prev.gl.flush();
                prev.park();
            }
            Ok(())
        }
        // At process exit (atexit handlers releasing their context) the slot may already be
        // destroyed: then nothing is current any more and nothing needs releasing. Inside a
        // GL call on this thread (a callback), the slot is in use and stays as it is.
        Ok(Err(())) | Err(_) => match incoming {
            Some(unplaced) => {
                unplaced.park();
                Err(BindError::NoSlot)
            }
            None if exiting => Ok(()),
            None => Err(BindError::NoSlot),
        },
    }
}

/// The context current on this thread.
pub fn current() -> Option<Arc<SharedContext>> {
    CURRENT.try_with(|slot| slot.try_borrow().ok()?.0.as_ref().map(|b| b.shared.clone())).ok().flatten()
}

/// Runs `f` on the current context; `None` when no context is current (or when called from
/// inside another GL call on this thread, e.g. from a callback: the inner call is ignored).
/// This is every entry point's path: a thread-local access and a `RefCell` borrow.
#[inline]
pub fn with_current<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    CURRENT
        .try_with(|slot| {
            let mut slot = slot.try_borrow_mut().ok()?;
            let bound = slot.0.as_mut()?;
            #[cfg(test)]
            if PANIC_WHILE_LOCKED.with(|p| p.get()) {
                panic!("injected panic while holding the context");
            }
            Some(f(&mut bound.gl))
        })
        .ok()
        .flatten()
}

#[cfg(test)]
thread_local! {
    /// Test builds: make every entry point on this thread panic while it holds the current
    /// context's state (see `api::panic_injection`).
    pub static PANIC_WHILE_LOCKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::ContextConfig;
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
    use crate::gl::enums::{GL_INVALID_ENUM, GL_INVALID_VALUE, GL_NO_ERROR};
    use std::sync::mpsc;

    fn shared() -> Arc<SharedContext> {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 0);
        SharedContext::new(Context::new(ContextConfig { visual }))
    }

    /// Runs `f` on a new thread and returns its result (the thread's slot is dropped at its end).
    fn on_thread<R: Send + 'static>(f: impl FnOnce() -> R + Send + 'static) -> R {
        std::thread::spawn(f).join().expect("test thread")
    }

    #[test]
    fn the_state_moves_with_the_binding_and_comes_home_at_release() {
        let ctx = shared();
        assert_eq!(with_current(|_| ()), None, "nothing current");
        make_current(Some(ctx.clone())).unwrap();
        assert_eq!(ctx.bound_thread(), Some(std::thread::current().id()));
        with_current(|gl| gl.error(GL_INVALID_ENUM)).unwrap();
        // The window-system path reaches the same state while it is current here.
        assert_eq!(ctx.with_gl(|gl| gl.take_error()), Some(GL_INVALID_ENUM));
        with_current(|gl| gl.error(GL_INVALID_VALUE)).unwrap();
        make_current(None).unwrap();
        assert_eq!(ctx.bound_thread(), None);
        assert!(current().is_none());
        // Parked: the recorded error went home with the state.
        assert_eq!(ctx.with_gl(|gl| gl.take_error()), Some(GL_INVALID_VALUE));
        assert_eq!(ctx.with_gl(|gl| gl.take_error()), Some(GL_NO_ERROR));
    }

    #[test]
    fn a_context_current_on_one_thread_is_refused_to_another_until_that_thread_exits() {
        let ctx = shared();
        let (bound_tx, bound_rx) = mpsc::channel();
        let (exit_tx, exit_rx) = mpsc::channel::<()>();
        let holder = {
            let ctx = ctx.clone();
            std::thread::spawn(move || {
                make_current(Some(ctx)).unwrap();
                with_current(|gl| gl.error(GL_INVALID_ENUM)).unwrap();
                bound_tx.send(()).unwrap();
                exit_rx.recv().unwrap();
            })
        };
        bound_rx.recv().unwrap();
        let elsewhere = ctx.clone();
        assert_eq!(on_thread(move || make_current(Some(elsewhere))), Err(BindError::CurrentElsewhere));
        assert_eq!(ctx.with_gl(|_| ()), None, "another thread's state is out of reach");
        exit_tx.send(()).unwrap();
        holder.join().unwrap();
        // The exiting thread released it: this thread may bind it, with its state.
        make_current(Some(ctx.clone())).unwrap();
        assert_eq!(with_current(|gl| gl.take_error()), Some(GL_INVALID_ENUM));
        make_current(None).unwrap();
    }

    #[test]
    fn a_context_destroyed_while_current_elsewhere_lives_until_released() {
        let ctx = shared();
        let weak = Arc::downgrade(&ctx);
        let (bound_tx, bound_rx) = mpsc::channel();
        let (go_tx, go_rx) = mpsc::channel::<()>();
        let user = std::thread::spawn(move || {
            make_current(Some(ctx)).unwrap();
            bound_tx.send(()).unwrap();
            go_rx.recv().unwrap();
            // Still usable after its owner dropped it.
            let usable = with_current(|gl| {
                gl.error(GL_INVALID_VALUE);
                gl.take_error()
            });
            make_current(None).unwrap();
            usable
        });
        bound_rx.recv().unwrap();
        // The owner (a registry) lets go of it from this thread: deletion is deferred.
        assert!(weak.upgrade().is_some());
        go_tx.send(()).unwrap();
        assert_eq!(user.join().unwrap(), Some(GL_INVALID_VALUE));
        assert!(weak.upgrade().is_none(), "dropped once released");
    }

    #[test]
    fn a_gl_call_from_inside_a_gl_call_is_ignored_not_a_deadlock() {
        let ctx = shared();
        make_current(Some(ctx.clone())).unwrap();
        let inner = with_current(|_| with_current(|_| ()));
        assert_eq!(inner, Some(None));
        assert_eq!(with_current(|_| make_current(None)), Some(Err(BindError::NoSlot)));
        assert!(current().is_some_and(|c| Arc::ptr_eq(&c, &ctx)), "still current");
        make_current(None).unwrap();
    }

    #[test]
    fn two_contexts_reach_each_other_for_a_copy_in_either_place() {
        let (a, b) = (shared(), shared());
        let copy = |x: &Arc<SharedContext>, y: &Arc<SharedContext>| {
            with_two(x, y, |gx, gy| {
                let e = gx.take_error();
                gy.error(e);
            })
        };
        a.with_gl(|gl| gl.error(GL_INVALID_ENUM));
        assert!(copy(&a, &b).is_some(), "both parked");
        assert_eq!(b.with_gl(|gl| gl.take_error()), Some(GL_INVALID_ENUM));
        make_current(Some(a.clone())).unwrap();
        with_current(|gl| gl.error(GL_INVALID_VALUE));
        assert!(copy(&a, &b).is_some(), "source current here");
        assert!(copy(&b, &a).is_some(), "target current here (the caller refuses that case)");
        make_current(None).unwrap();
        assert_eq!(a.with_gl(|gl| gl.take_error()), Some(GL_INVALID_VALUE));
        assert!(copy(&a, &a).is_none(), "the same context");
    }
}
