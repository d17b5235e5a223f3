//! The extern "C" edge: every `gl*` and `OSMesa*` entry point.
//!
//! An entry point validates nothing itself beyond turning C pointers into safe Rust values; it
//! forwards to the current [`Context`], which validates, records GL errors and changes state.
//! No panic crosses this edge ([`with_context`] and [`guard`] catch them), and a call made
//! with no current context does nothing and returns a neutral value.
//!
//! cbindgen reads these files to generate `include/GL/tessera.h`, so entry points are written
//! out literally (no macro-generated functions).

// Entry points keep the C names of the GL headers, parameters included.
#![allow(non_snake_case)]

mod caller_memory;
pub mod gl_aliases;
pub mod gl_arrays;
pub mod gl_buffer_objects;
pub mod gl_buffers;
pub mod gl_evaluators;
pub mod gl_fragment;
pub mod gl_framebuffer;
pub mod gl_lighting;
pub mod gl_lists;
pub mod gl_pixel_rect;
pub mod gl_pixels;
pub mod gl_queries;
pub mod gl_raster_state;
pub mod gl_selection;
pub mod gl_shaders;
pub mod gl_state;
pub mod gl_texture;
pub mod gl_transform;
pub mod gl_uniforms;
pub mod gl_vertex;
pub mod gl_vertex_attribs;
/// GLX needs the X types of <GL/glx.h>: kept out of tessera.h.
/// cbindgen:ignore
pub mod glx;
pub mod osmesa;
mod pixel_source;
pub mod procs;
pub mod tessera_ext;

#[cfg(test)]
mod panic_injection;

use crate::context::{current, Context};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU64, Ordering};

/// How many panics the API edge has caught in this process (see [`caught_panics`]).
static CAUGHT_PANICS: AtomicU64 = AtomicU64::new(0);

/// How many panics the API edge has caught so far: each is a tessera bug that became an
/// ignored call. The fuzz target and the reliability tests read it to turn such a bug into
/// a finding.
pub fn caught_panics() -> u64 {
    CAUGHT_PANICS.load(Ordering::Relaxed)
}

/// Runs `f` on the calling thread's current context; returns `default` when there is none or
/// when `f` panics (the panic is reported on stderr and becomes an ignored call).
pub(crate) fn with_context<R: Copy>(default: R, f: impl FnOnce(&mut Context) -> R) -> R {
    guard(default, || current::with_current(f).unwrap_or(default))
}

/// Runs `f` on the calling thread's current context for a value that is not `Copy` (an
/// object's string, a list of names): `None` when there is no context, when `f` records an
/// error, or when it panics.
pub(crate) fn query<R>(f: impl FnOnce(&mut Context) -> Option<R>) -> Option<R> {
    guard(None, || current::with_current(f).flatten())
}

/// The path of every command that display lists compile: runs `command` on the current
/// context, or records it in the list being compiled (see `context::lists`). The closure owns
/// its arguments (`move`), so anything a pointer argument designates must be read into owned
/// values before (vector forms call the scalar form; arrays are copied).
///
/// The closure is used by reference and cloned only when a list records it: moved into the
/// guarded closure, its captured arguments were copied through memory with loads wider than
/// the stores that wrote them (two `f32` stores read back as one `u64`), a store-forwarding
/// stall that was most of an immediate-mode call's cost (glColor3f: 20 ns against 5).
pub(crate) fn record_or_run<F: Fn(&mut Context) + Clone + Send + Sync + 'static>(command: F) {
    let command = &command;
    with_context((), |ctx| if ctx.lists.compiling() { ctx.record_or_run(command.clone()) } else { command(ctx) })
}

/// The path of the per-vertex commands (glVertex, glColor, glNormal, glTexCoord): `fast` runs
/// on the current context without the panic guard when no display list is being compiled,
/// and returns whether it did the whole call; when it declines, or nothing is current, the
/// command runs as [`record_or_run`] runs it, guarded.
///
/// The guard's landing pad makes every guarded entry point save and restore six registers
/// around its work, a third of a glColor3f; `fast` may go without it only because it cannot
/// panic: plain stores into the current state, limits checked by comparisons before a
/// `push` into reserved room, no indexing, no allocation. So no panic can cross the C ABI.
#[inline(always)]
pub(crate) fn fast_or_run<F: Fn(&mut Context) + Clone + Send + Sync + 'static>(
    fast: impl FnOnce(&mut Context) -> bool,
    command: F,
) {
    // Test builds: an armed panic injection takes the guarded path, where it fires.
    #[cfg(test)]
    let fast_allowed = !panic_injection::armed();
    #[cfg(not(test))]
    let fast_allowed = true;
    if fast_allowed && current::with_current(|ctx| !ctx.lists.compiling() && fast(ctx)) == Some(true) {
        return;
    }
    cold(move || {
        with_context((), |ctx| if ctx.lists.compiling() { ctx.record_or_run(command.clone()) } else { command(ctx) })
    })
}

/// Runs `f` out of line (the slow path of [`fast_or_run`]).
#[cold]
#[inline(never)]
fn cold(f: impl FnOnce()) {
    f()
}

/// Runs `f` with panics caught; returns `default` if it panicked.
pub(crate) fn guard<R>(default: R, f: impl FnOnce() -> R) -> R {
    let f = || {
        #[cfg(test)]
        panic_injection::maybe_panic(panic_injection::Where::AtTheEdge);
        f()
    };
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(value) => value,
        Err(payload) => {
            report_caught_panic(payload);
            default
        }
    }
}

/// Counts a panic [`guard`] caught and reports it on stderr. Out of line and not generic: one
/// copy instead of one in each of the ~800 entry points (inlined, the message's downcasts,
/// string copies and `eprintln!` were about 450 bytes of each: outlined, the stripped
/// libraries are 272 KB smaller).
#[cold]
#[inline(never)]
fn report_caught_panic(payload: Box<dyn std::any::Any + Send>) {
    let message = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_string());
    CAUGHT_PANICS.fetch_add(1, Ordering::Relaxed);
    eprintln!("tessera: internal error caught at the API edge: {message}");
}
