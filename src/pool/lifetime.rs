//! The one unsafe step of the pool: a borrowed piece of work handed to a pool thread as if
//! it lived forever, on the promise that `super::finish_own` outlives every use of it.

// The room denies unsafe code (`pool/mod.rs`); this erasure is its one exception.
#![allow(unsafe_code)]

/// Work whose borrow the pool keeps alive by waiting (see [`erase`]).
#[derive(Clone, Copy)]
pub struct Erased(&'static (dyn Fn() + Sync));

impl Erased {
    pub fn get(self) -> &'static (dyn Fn() + Sync) {
        self.0
    }
}

/// `work` with its lifetime erased. Only `super::run` and `super::run_beside` call this,
/// and neither returns nor unwinds until the job is closed and no helper runs the work any
/// more.
pub fn erase<'a>(work: &'a (dyn Fn() + Sync + 'a)) -> Erased {
    // SAFETY: the reference is only dereferenced by pool threads between taking a slot of
    // the job and reporting back, and `super::finish_own` (through its `Closing` guard, on return
    // and on unwind alike) closes the job and waits for every helper that took a slot
    // before the borrow `'a` can end. The layout of the two reference types is the same.
    Erased(unsafe { std::mem::transmute::<&'a (dyn Fn() + Sync + 'a), &'static (dyn Fn() + Sync + 'static)>(work) })
}
