//! Panic injection for the tests: proof that a panic inside any entry point becomes an
//! ignored call (or the entry point's neutral return value), never an unwind into C or an
//! abort, and that the context stays usable afterwards.
//!
//! Every entry point runs its body through [`super::guard`] (directly, through
//! [`super::with_context`], or by forwarding to an entry point that does), and reaches the
//! GL state only through `context::current::with_current`. In test builds both contain an
//! injection point: armed on this thread, every entry point panics either at the edge
//! (before anything ran) or while holding the current context's lock (the worst place: a
//! poisoned lock must not make the context unusable).

use std::cell::Cell;

/// Where the armed injection fires.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Where {
    AtTheEdge,
    HoldingTheContext,
}

thread_local! {
    static ARMED: Cell<Option<Where>> = const { Cell::new(None) };
}

/// Makes every following entry point on this thread panic at `place` (`None`: disarm).
pub fn arm(place: Option<Where>) {
    ARMED.with(|a| a.set(place));
    crate::context::current::PANIC_WHILE_LOCKED.with(|p| p.set(place == Some(Where::HoldingTheContext)));
}

/// Whether an injection is armed on this thread (the unguarded fast path of
/// `api::fast_or_run` then steps aside for the guarded one).
pub fn armed() -> bool {
    ARMED.with(|a| a.get()).is_some()
}

/// The injection point at the edge (the one inside the lock is in `context::current`).
pub fn maybe_panic(here: Where) {
    if ARMED.with(|a| a.get()) == Some(here) {
        panic!("injected panic ({here:?})");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::api::caught_panics;
    use crate::api::gl_buffers::*;
    use crate::api::gl_pixels::*;
    use crate::api::gl_state::*;
    use crate::api::gl_vertex::*;
    use crate::api::osmesa::*;
    use crate::gl::enums::*;
    use crate::gl::osmesa::OSMESA_RGBA;
    use crate::gl::types::OSMesaContext;
    use std::ffi::c_void;

    const W: i32 = 4;
    const H: i32 = 4;

    /// Calls a broad sample of entry points (every kind of return value and out-pointer)
    /// and returns what they returned.
    fn call_everything(buffer: &mut [u8], ctx: OSMesaContext) -> (u32, u8, bool, i32, u8, bool, bool) {
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glColor3f(0.0, 1.0, 0.0);
        glVertex2f(-1.0, -1.0);
        glVertex2f(3.0, -1.0);
        glVertex2f(-1.0, 3.0);
        glEnd();
        let error = glGetError();
        let enabled = glIsEnabled(GL_DEPTH_TEST);
        let string = glGetString(GL_RENDERER).is_null();
        let mut viewport = [-7i32; 4];
        // SAFETY: four GLints, as GL_VIEWPORT needs.
        unsafe { glGetIntegerv(GL_VIEWPORT, viewport.as_mut_ptr()) };
        let mut pixel = [9u8; 4];
        // SAFETY: one RGBA/UNSIGNED_BYTE pixel fits in `pixel`.
        unsafe { glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.as_mut_ptr() as *mut c_void) };
        glFinish();
        // SAFETY: the buffer holds W x H RGBA pixels of 8 bits.
        let rebound =
            unsafe { OSMesaMakeCurrent(ctx, buffer.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H) } == GL_TRUE;
        let created = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, std::ptr::null_mut());
        let created_any = !created.is_null();
        OSMesaDestroyContext(created);
        (error, enabled, string, viewport[2], pixel[1], rebound, created_any)
    }

    #[test]
    fn a_panic_in_any_entry_point_is_an_ignored_call_and_the_context_survives() {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buffer = vec![0u8; (W * H * 4) as usize];
        // SAFETY: the buffer holds W x H RGBA pixels of 8 bits and outlives the binding.
        assert_eq!(
            unsafe { OSMesaMakeCurrent(ctx, buffer.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H) },
            GL_TRUE
        );
        for place in [Where::AtTheEdge, Where::HoldingTheContext] {
            let before = caught_panics();
            arm(Some(place));
            let returned = call_everything(&mut buffer, ctx);
            arm(None);
            // Neutral values everywhere; out-pointers untouched.
            let edge = place == Where::AtTheEdge;
            assert_eq!(returned.0, GL_NO_ERROR, "{place:?}");
            assert_eq!(returned.1, GL_FALSE);
            assert!(returned.2, "glGetString returned a string");
            assert_eq!(returned.3, -7, "glGetIntegerv wrote through its pointer");
            assert_eq!(returned.4, 9, "glReadPixels wrote through its pointer");
            // OSMesa entry points do not hold a GL context: they only fail at the edge.
            assert_eq!(returned.5, !edge);
            assert_eq!(returned.6, !edge);
            assert!(caught_panics() >= before + 10, "{place:?}: {} panics caught", caught_panics() - before);
            // Nothing was drawn: the buffer is still black.
            glFinish();
            assert!(buffer.iter().all(|&b| b == 0), "{place:?}: an ignored call drew");
            assert_eq!(glGetError(), GL_NO_ERROR);
        }
        // The context is still fully usable, its lock poisoned or not.
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(&buffer[..4], &[255, 0, 0, 255]);
        assert_eq!(glGetError(), GL_NO_ERROR);
        // SAFETY: releasing the current context (both NULL).
        unsafe { OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0) };
        OSMesaDestroyContext(ctx);
    }
}

#[cfg(test)]
mod every_entry_point {
    /// The body of the function whose opening brace is at or after `from`.
    fn body(source: &str, from: usize) -> &str {
        let open = from + source[from..].find('{').expect("a body");
        let mut depth = 0;
        for (i, c) in source[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        return &source[open..open + i];
                    }
                }
                _ => {}
            }
        }
        panic!("unbalanced braces")
    }

    /// The injection test above covers every entry point only if every one runs inside the
    /// guard: each `extern "C"` body calls `guard` or `with_context`, a helper of src/api
    /// that does, or forwards to another entry point.
    #[test]
    fn every_entry_point_runs_inside_the_guard() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/src/api");
        let sources: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "rs"))
            .map(|p| std::fs::read_to_string(p).unwrap())
            .collect();
        // Every function of src/api (entry point or helper) with its body.
        let mut functions = Vec::new();
        for source in &sources {
            let mut at = 0;
            while let Some(found) = source[at..].find("fn ") {
                let start = at + found + 3;
                at = start;
                let preceded = source[..start - 3].chars().next_back().is_none_or(|c| c.is_whitespace());
                let name: String = source[start..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                if !preceded || name.is_empty() || !source[start + name.len()..].trim_start().starts_with(['(', '<']) {
                    continue;
                }
                let entry = source[..start].ends_with("extern \"C\" fn ");
                functions.push((name, entry, body(source, start)));
            }
        }
        // Helpers that run their work inside the guard.
        let guarded: Vec<&str> = functions
            .iter()
            .filter(|(_, _, text)| text.contains("guard(") || text.contains("with_context"))
            .map(|(name, _, _)| name.as_str())
            .collect();
        let mut checked = 0;
        let mut unguarded = Vec::new();
        for (name, entry, text) in functions.iter().filter(|f| f.1) {
            let _ = entry;
            let forwards = text.match_indices('(').any(|(i, _)| {
                let callee: String = text[..i]
                    .chars()
                    .rev()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect::<Vec<_>>()
                    .into_iter()
                    .rev()
                    .collect();
                callee != *name
                    && (guarded.contains(&callee.as_str()) || functions.iter().any(|(n, e, _)| *e && *n == callee))
            });
            if !(text.contains("guard(") || text.contains("with_context") || forwards) {
                unguarded.push(name.clone());
            }
            checked += 1;
        }
        assert!(checked > 400, "only {checked} entry points found");
        assert!(unguarded.is_empty(), "entry points outside the panic guard: {unguarded:?}");
    }
}
