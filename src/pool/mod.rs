//! The worker threads that every scene of every context shares: spawned once, on first need,
//! and parked between scenes, so that a flush point does not pay a thread spawn (30–60 µs
//! each, and a fresh 2 MiB stack) for each helper it wants.
//!
//! [`run`] runs one piece of `work` on the calling thread and on up to `helpers` pool threads
//! at once, and returns when every copy has returned. The work pulls its items from a queue
//! of its own (the tile bands of a scene, the two halves of a draw), so it is complete
//! whichever threads take part: a helper that is busy with another context's scene, or not
//! woken in time, simply does not join, and the calling thread does what is left. The bytes
//! a scene writes do not depend on the threads that ran it (tiles own pixels, `crate::raster`),
//! so they are the same for any `TESSERA_THREADS`, any pool size and any contention.
//! [`run_beside`] gives the calling thread other work than its helper (a long draw records
//! while a pool thread renders), and [`help`] lets a thread that would wait join another
//! caller's [`run`] job as one more helper.
//!
//! Lifetimes: `work` borrows the caller's stack (the framebuffer's bands, the scene). A
//! helper gets it with its lifetime erased ([`lifetime`]), which is sound because [`run`]
//! (and [`run_beside`]) does not return, nor unwind, before the job is closed to new helpers
//! and every helper that joined (through [`help`] too) has finished (the [`Closing`] guard
//! runs on both paths). A panic in a helper
//! is caught there, handed to the caller and raised on the calling thread, as
//! `std::thread::scope` does; the helper itself lives on.
//!
//! The edges:
//! - Many contexts on many threads share the pool; each caller waits only for the helpers
//!   that joined its own job, never for a slot to be taken, so no caller can wait on another.
//! - Context destruction leaves the pool alone: it holds nothing of any context between jobs.
//! - fork(): the child has none of the parent's threads. The pool remembers the process it
//!   was made in, and a child's first job makes a fresh pool (the parent's is leaked: its
//!   lock may have been held by a thread that no longer exists). A fork while another thread
//!   of the parent is inside the pool's short critical sections is unsupported, as with any
//!   library that takes locks.
//! - Process exit: parked helpers hold no lock and run no code; exit ends them like any
//!   other thread, with nothing to join.
//! - dlclose: a parked helper's stack returns into this library, so the libraries are linked
//!   with `-z nodelete` (`lib/dropin-build.rs`, `build.rs`): dlclose then keeps the code
//!   mapped, as glibc already did for a library with thread-local destructors pending.
#![deny(unsafe_code)]

mod lifetime;

use lifetime::Erased;
use std::any::Any;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};

/// Runs `work` on the calling thread and on up to `helpers` pool threads at the same time,
/// and returns when every copy that started has returned. A panic in any copy is raised
/// here (the caller's own first) after all of them have finished.
pub fn run(helpers: usize, work: &(dyn Fn() + Sync)) {
    if helpers == 0 {
        return work();
    }
    let pool = Pool::current();
    let id = pool.post(lifetime::erase(work), helpers, true);
    finish_own(&pool, id, work);
}

/// As [`run`] with other work for the calling thread: `own` runs there while up to
/// `helpers` pool threads run `helper`, and its result is returned once every helper that
/// joined has returned. A helper that is busy or not woken in time does not join at all, so
/// `own` must finish whether or not `helper` ever runs, and `helper` must return once `own`
/// has (a long draw's recording beside the render of its segments, `context::draw`).
pub fn run_beside<R>(helpers: usize, helper: &(dyn Fn() + Sync), own: impl FnOnce() -> R) -> R {
    let pool = Pool::current();
    let id = pool.post(lifetime::erase(helper), helpers, false);
    finish_own(&pool, id, own)
}

/// Runs the caller's `own` work of job `id`, then closes the job; raises a panic of either.
fn finish_own<R>(pool: &Arc<Pool>, id: u64, own: impl FnOnce() -> R) -> R {
    let closing = Closing { pool, id };
    let own = catch_unwind(AssertUnwindSafe(own));
    let helper_panic = closing.close();
    let own = own.unwrap_or_else(|payload| resume_unwind(payload));
    if let Some(payload) = helper_panic {
        resume_unwind(payload);
    }
    own
}

/// Runs, on the calling thread, the work of one [`run`] job of another caller that has room
/// for one more helper, as a pool thread would; whether there was one. A thread that would
/// otherwise wait for another's rendering helps it this way (a long draw's recording
/// thread, `context::draw`): the work pulls its items from its own queue, so it is
/// complete whichever threads take part. Jobs of [`run_beside`] are not joined: their
/// helper work may wait for their caller.
pub fn help() -> bool {
    Pool::current().help()
}

/// Spawns pool threads until there are `helpers`, without waiting for them to start: a
/// context calls this when it is made, so that the threads have started and parked (a fresh
/// thread's start-up, its stack and its allocator arena take tens of microseconds, and
/// longer on a loaded machine) by the time its first scene wants them, instead of the
/// calling thread doing the first scene mostly alone.
pub fn prestart(helpers: usize) {
    if helpers == 0 {
        return;
    }
    Pool::current().prestart(helpers);
}

/// Runs `a` and `b`, `a` on a pool thread when one is free at once, else both on the calling
/// thread, and returns both results.
pub fn join<A, B, RA, RB>(a: A, b: B) -> (RA, RB)
where
    A: FnOnce() -> RA + Send,
    B: FnOnce() -> RB + Send,
    RA: Send,
    RB: Send,
{
    let (a, b) = (Mutex::new(Some(a)), Mutex::new(Some(b)));
    let (ra, rb) = (Mutex::new(None), Mutex::new(None));
    run(1, &|| {
        // Whoever comes first takes `b`, which the caller reaches first: `a` is the part
        // meant for the helper.
        if let Some(f) = relock(&b).take() {
            let r = f();
            *relock(&rb) = Some(r);
        }
        if let Some(f) = relock(&a).take() {
            let r = f();
            *relock(&ra) = Some(r);
        }
    });
    let ra = relock(&ra).take().expect("run returns after every task ran");
    let rb = relock(&rb).take().expect("run returns after every task ran");
    (ra, rb)
}

/// A lock whose data stays consistent under a panic (the pool's state is updated in steps
/// that cannot panic halfway; the tasks' slots hold plain values).
fn relock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

/// The most pool threads ever spawned (`TESSERA_THREADS` is capped at 256 as well).
const MAX_THREADS: usize = 255;

struct Pool {
    /// The process the pool's threads belong to.
    pid: u32,
    state: Mutex<State>,
    /// Signalled when a job is posted (parked helpers wait here).
    posted: Condvar,
    /// Signalled when a job's last helper finishes (closing callers wait here).
    finished: Condvar,
}

#[derive(Default)]
struct State {
    jobs: Vec<Job>,
    next_id: u64,
    /// Threads spawned, and those among them parked waiting for a job.
    threads: usize,
    idle: usize,
}

struct Job {
    id: u64,
    work: Erased,
    /// Helpers that may still join (0 once the caller closes the job).
    slots: usize,
    /// Helpers running the work now.
    active: usize,
    /// Whether a thread outside the pool may join as a helper ([`help`]).
    helpable: bool,
    panic: Option<Box<dyn Any + Send>>,
}

/// Closes a job when [`run`]'s caller is done with its own copy of the work, or unwinds.
struct Closing<'a> {
    pool: &'a Arc<Pool>,
    id: u64,
}

impl Closing<'_> {
    /// Closes the job and waits for its helpers; the first panic of a helper, if any.
    fn close(self) -> Option<Box<dyn Any + Send>> {
        let panic = self.pool.close(self.id);
        std::mem::forget(self);
        panic
    }
}

impl Drop for Closing<'_> {
    fn drop(&mut self) {
        // Unwinding out of the caller's work: the helpers must be done with the borrowed
        // work before the borrow ends. Their panic, if any, is dropped with this one.
        self.pool.close(self.id);
    }
}

impl Pool {
    /// The pool of this process, made on first use (and again in a forked child).
    fn current() -> Arc<Pool> {
        static CURRENT: Mutex<Option<Arc<Pool>>> = Mutex::new(None);
        let pid = std::process::id();
        let mut current = relock(&CURRENT);
        match current.as_ref() {
            Some(pool) if pool.pid == pid => pool.clone(),
            _ => {
                // A parent's pool in a forked child: its threads are gone and its lock may
                // be held forever, so it is never touched (nor dropped) again.
                std::mem::forget(current.take());
                let pool = Arc::new(Pool {
                    pid,
                    state: Mutex::new(State::default()),
                    posted: Condvar::new(),
                    finished: Condvar::new(),
                });
                *current = Some(pool.clone());
                pool
            }
        }
    }

    /// Offers `work` to up to `helpers` threads, spawning threads while fewer are parked
    /// than the job wants (up to the job's size); the job's id.
    fn post(self: &Arc<Self>, work: Erased, helpers: usize, helpable: bool) -> u64 {
        let mut state = relock(&self.state);
        let id = state.next_id;
        state.next_id += 1;
        state.jobs.push(Job { id, work, slots: helpers, active: 0, helpable, panic: None });
        let wanted = helpers.min(MAX_THREADS);
        while state.idle < wanted && state.threads < wanted {
            if !self.spawn(&mut state) {
                break; // the caller does the work itself
            }
        }
        drop(state);
        for _ in 0..helpers.min(MAX_THREADS) {
            self.posted.notify_one();
        }
        id
    }

    /// [`prestart`] on this pool.
    fn prestart(self: &Arc<Self>, helpers: usize) {
        let mut state = relock(&self.state);
        while state.threads < helpers.min(MAX_THREADS) {
            if !self.spawn(&mut state) {
                break;
            }
        }
    }

    /// Spawns one more pool thread (counted as parked); false when the system refuses.
    fn spawn(self: &Arc<Self>, state: &mut State) -> bool {
        let pool = self.clone();
        let spawned = std::thread::Builder::new().name("tessera-worker".into()).spawn(move || pool.serve()).is_ok();
        if spawned {
            state.threads += 1;
            state.idle += 1;
        }
        spawned
    }

    /// Closes job `id` to new helpers, waits until those that joined have finished, and
    /// removes it; the first panic of a helper, if any.
    fn close(&self, id: u64) -> Option<Box<dyn Any + Send>> {
        let mut state = relock(&self.state);
        // Only `close` removes a job, so it is there until then.
        let position = |state: &State| state.jobs.iter().position(|j| j.id == id);
        let i = position(&state)?;
        state.jobs[i].slots = 0;
        loop {
            let i = position(&state)?;
            if state.jobs[i].active == 0 {
                return state.jobs.swap_remove(i).panic;
            }
            state = self.finished.wait(state).unwrap_or_else(|p| p.into_inner());
        }
    }

    /// A pool thread: parks until a job has a free slot, runs its work, reports back.
    fn serve(&self) {
        let mut state = relock(&self.state);
        loop {
            let Some(job) = state.jobs.iter_mut().find(|j| j.slots > 0) else {
                state = self.posted.wait(state).unwrap_or_else(|p| p.into_inner());
                continue;
            };
            job.slots -= 1;
            job.active += 1;
            let (id, work) = (job.id, job.work);
            state.idle -= 1;
            drop(state);
            state = self.run_as_helper(id, work);
            state.idle += 1;
        }
    }

    /// [`help`] on this pool.
    fn help(&self) -> bool {
        let mut state = relock(&self.state);
        let Some(job) = state.jobs.iter_mut().find(|j| j.slots > 0 && j.helpable) else {
            return false;
        };
        job.slots -= 1;
        job.active += 1;
        let (id, work) = (job.id, job.work);
        drop(state);
        drop(self.run_as_helper(id, work));
        true
    }

    /// Runs `work` as a helper of job `id` (whose slot the caller took) and reports back;
    /// the pool's state, locked.
    fn run_as_helper(&self, id: u64, work: Erased) -> MutexGuard<'_, State> {
        let result = catch_unwind(AssertUnwindSafe(|| (work.get())()));
        let mut state = relock(&self.state);
        if let Some(job) = state.jobs.iter_mut().find(|j| j.id == id) {
            job.active -= 1;
            if let Err(payload) = result {
                job.panic.get_or_insert(payload);
            }
            if job.active == 0 && job.slots == 0 {
                self.finished.notify_all();
            }
        }
        state
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Items pulled from a shared queue by the caller and its helpers: each item done
    /// exactly once, whoever ran it.
    fn sum_of_items(helpers: usize, items: usize) -> usize {
        let next = AtomicUsize::new(0);
        let done = Mutex::new(vec![0u8; items]);
        run(helpers, &|| loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            if i >= items {
                break;
            }
            relock(&done)[i] += 1;
        });
        let done = done.into_inner().unwrap();
        assert!(done.iter().all(|&n| n == 1), "every item once: {done:?}");
        done.len()
    }

    #[test]
    fn every_item_runs_once_for_any_number_of_helpers() {
        for helpers in [0, 1, 2, 3, 7] {
            assert_eq!(sum_of_items(helpers, 1000), 1000);
        }
    }

    #[test]
    fn many_threads_share_the_pool_without_waiting_on_each_other() {
        let handles: Vec<_> =
            (0..8).map(|_| std::thread::spawn(|| (0..50).map(|_| sum_of_items(3, 64)).sum::<usize>())).collect();
        for h in handles {
            assert_eq!(h.join().unwrap(), 50 * 64);
        }
    }

    #[test]
    fn a_helper_that_joins_finishes_before_run_returns() {
        // The work borrows a local; after run returns, nothing may still be running it.
        for _ in 0..200 {
            let running = AtomicUsize::new(0);
            let finished = AtomicUsize::new(0);
            run(2, &|| {
                running.fetch_add(1, Ordering::SeqCst);
                std::thread::yield_now();
                finished.fetch_add(1, Ordering::SeqCst);
            });
            assert_eq!(running.load(Ordering::SeqCst), finished.load(Ordering::SeqCst));
            assert!(finished.load(Ordering::SeqCst) >= 1, "the caller always runs the work");
        }
    }

    #[test]
    fn a_panic_in_the_work_reaches_the_caller_and_the_pool_lives_on() {
        let calls = AtomicUsize::new(0);
        let result = catch_unwind(AssertUnwindSafe(|| {
            run(2, &|| {
                calls.fetch_add(1, Ordering::SeqCst);
                panic!("work failed");
            })
        }));
        assert!(result.is_err(), "the panic is raised on the calling thread");
        assert_eq!(sum_of_items(2, 100), 100, "the pool still works after a panic");
    }

    #[test]
    fn prestarted_threads_are_spawned_at_once_and_serve_later_jobs() {
        // A pool of its own, so that the other tests' jobs do not change its thread count.
        let pool = Arc::new(Pool {
            pid: 0,
            state: Mutex::new(State::default()),
            posted: Condvar::new(),
            finished: Condvar::new(),
        });
        pool.prestart(3);
        assert_eq!(relock(&pool.state).threads, 3);
        pool.prestart(2);
        assert_eq!(relock(&pool.state).threads, 3, "no more threads than asked for");
        let done = AtomicUsize::new(0);
        let work = || {
            done.fetch_add(1, Ordering::SeqCst);
        };
        let id = pool.post(lifetime::erase(&work), 3, true);
        work();
        assert!(pool.close(id).is_none());
        assert_eq!(relock(&pool.state).threads, 3, "the job found the prestarted threads");
        assert!((1..=4).contains(&done.load(Ordering::SeqCst)));
    }

    #[test]
    fn help_joins_a_run_job_with_room_but_never_a_run_beside_job() {
        // A pool of its own without threads, its jobs posted by hand: only `help` joins them.
        let pool = Pool { pid: 0, state: Mutex::default(), posted: Condvar::new(), finished: Condvar::new() };
        let done = AtomicUsize::new(0);
        let work = || {
            done.fetch_add(1, Ordering::SeqCst);
        };
        let push = |helpable: bool| {
            let mut state = relock(&pool.state);
            let id = state.next_id;
            state.next_id += 1;
            state.jobs.push(Job { id, work: lifetime::erase(&work), slots: 1, active: 0, helpable, panic: None });
            id
        };
        let beside = push(false);
        assert!(!pool.help(), "a run_beside job's helper work may wait for its caller");
        let shared = push(true);
        assert!(pool.help(), "a run job with room is joined");
        assert!(!pool.help(), "the job had room for one helper only");
        assert_eq!(done.load(Ordering::SeqCst), 1);
        assert!(pool.close(shared).is_none() && pool.close(beside).is_none());
    }

    #[test]
    fn join_returns_both_results() {
        let mut left = [0; 4];
        let (a, b) = join(
            || 6 * 7,
            || {
                left[0] = 1;
                "b"
            },
        );
        assert_eq!((a, b, left[0]), (42, "b", 1));
    }
}
