//! Overlapped draws: a long draw into the window is recorded in segments, each while a pool
//! thread renders the segment before it ([`Context::record_in_segments`]), so that the
//! recording thread and the tile workers no longer take turns.
//!
//! The two threads meet at one [`HandOff`] (a lock and a condition variable): the recording
//! thread hands a recorded segment's scene over, records the next one while it renders, and
//! takes the scene back, emptied, to record into after that. The pool may not lend a thread
//! at once (busy with another context's scene, or not woken yet): a segment recorded before
//! the renderer has started renders in turn on the recording thread, as a scene over its
//! budget does. Every segment renders as it would at a flush point that presents the window
//! (`Drawable::render_for_presentation`): into an OSMesa caller's buffer in place, so that
//! the draw's last flush need not copy the image there.
use super::super::Context;
use crate::framebuffer::Drawable;
use crate::raster::thread_count;
use crate::setup::Scene;
use std::ops::Range;
use std::sync::{Condvar, Mutex, MutexGuard};

/// Where the recording thread and the renderer of a long draw's segments meet.
#[derive(Default)]
struct HandOff {
    slot: Mutex<Slot>,
    changed: Condvar,
}

/// What the two threads tell each other, under [`HandOff::slot`]'s lock.
#[derive(Default)]
struct Slot {
    /// A recorded segment's scene waiting for the renderer, and whether it starts by
    /// replacing the whole front image (the scene's `scene_overwrites_front`).
    pending: Option<(Scene, bool)>,
    /// Whether the renderer holds the drawable's lock for the scene it took: from then on
    /// whatever the recording does to the drawable waits until that scene is rendered.
    locked: bool,
    /// The scene last rendered, emptied, for the recording thread to take back.
    rendered: Option<Scene>,
    /// Whether a segment is with the renderer (taken or waiting) and not yet given back.
    in_flight: bool,
    /// Whether the renderer runs: segments are handed to it only then.
    running: bool,
    /// Whether the recording is over (or the renderer failed): the renderer returns, and
    /// one that starts only now returns at once.
    finished: bool,
}

impl Slot {
    /// Whether a segment is with a renderer that has not given it back yet.
    fn rendering(&self) -> bool {
        self.in_flight && self.rendered.is_none() && !self.finished
    }
}

impl HandOff {
    fn slot(&self) -> MutexGuard<'_, Slot> {
        self.slot.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn wait<'a>(&self, slot: MutexGuard<'a, Slot>) -> MutexGuard<'a, Slot> {
        self.changed.wait(slot).unwrap_or_else(|p| p.into_inner())
    }

    /// Hands `scene` to the renderer, if it runs, and returns once the renderer holds the
    /// drawable's lock for it; gives the scene back when there is no renderer (or it failed).
    fn hand_over(&self, scene: Scene, overwrites: bool) -> Option<Scene> {
        let mut slot = self.slot();
        if !slot.running || slot.finished {
            return Some(scene);
        }
        slot.pending = Some((scene, overwrites));
        slot.in_flight = true;
        self.changed.notify_all();
        while !slot.locked && !slot.finished {
            slot = self.wait(slot);
        }
        slot.locked = false;
        None
    }

    /// Waits until the segment with the renderer (if any) is rendered, helping to render it
    /// meanwhile (`crate::pool::help`: its tile bands not taken yet, where the renderer
    /// renders on more than one thread); its scene, emptied.
    fn take_back(&self) -> Option<Scene> {
        let mut slot = self.slot();
        while slot.rendering() {
            drop(slot);
            let helped = crate::pool::help();
            slot = self.slot();
            if !helped && slot.rendering() {
                slot = self.wait(slot);
            }
        }
        slot.in_flight = false;
        slot.rendered.take()
    }

    /// Ends the hand-off: the renderer returns once it has rendered what it took.
    fn finish(&self) {
        self.slot().finished = true;
        self.changed.notify_all();
    }

    /// The renderer (a pool thread): renders each scene handed over into `drawable` on
    /// `threads` threads, until the recording finishes.
    fn render(&self, drawable: &Mutex<Drawable>, threads: usize) {
        // A renderer that unwinds ends the hand-off too, so that the recording thread never
        // waits for it (the pool raises its panic on the recording thread). Declared before
        // the slot's guard, so that it is dropped after it (`finish` takes the lock).
        let _finishing = Finishing(self);
        let mut slot = self.slot();
        if slot.finished {
            return;
        }
        slot.running = true;
        loop {
            let Some((mut scene, overwrites)) = slot.pending.take() else {
                if slot.finished {
                    break;
                }
                slot = self.wait(slot);
                continue;
            };
            let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
            slot.locked = true;
            self.changed.notify_all();
            drop(slot);
            render_segment(&mut guard, &mut scene, overwrites, threads);
            drop(guard);
            scene.clear();
            slot = self.slot();
            slot.rendered = Some(scene);
            self.changed.notify_all();
        }
    }
}

/// Ends its hand-off when dropped ([`HandOff::finish`]), on return and on unwind alike.
struct Finishing<'a>(&'a HandOff);

impl Drop for Finishing<'_> {
    fn drop(&mut self) {
        self.0.finish();
    }
}

/// Renders a segment's `scene` into the window's drawable on `threads` threads, as a flush
/// point that presents would ([`Drawable::render_for_presentation`]); `overwrites` when the
/// scene starts by replacing every front-left pixel.
fn render_segment(drawable: &mut Drawable, scene: &mut Scene, overwrites: bool, threads: usize) {
    if overwrites {
        // No need to bring home an image the scene replaces whole (as `run_scene`).
        drawable.front_image_replaced();
    }
    drawable.render_for_presentation(overwrites, |fb| {
        if scene.size() == (fb.width(), fb.height()) {
            scene.execute_on(fb, threads);
        }
    });
}

impl Context {
    /// Records the vertices `0..count` of a long draw with `record` (which records a range of
    /// them, false when it could not), in segments of `segment` vertices into the window:
    /// each segment after the first while the scene of the one before renders on a pool
    /// thread (see the module doc). Rendering a scene early changes no pixel (as for a
    /// scene over its budget, `Context::keep_scene`): each pixel still sees every primitive
    /// in submission order, and the drawable's lock keeps that order (the renderer holds it
    /// before the next segment records, and anything the recording did to the framebuffer
    /// would wait for it). While a segment records beside a render, the window's shape is
    /// answered from what it was (`window_pinned`), without waiting for the lock.
    pub(in crate::context) fn record_in_segments(
        &mut self,
        count: usize,
        segment: usize,
        mut record: impl FnMut(&mut Context, Range<usize>) -> bool,
    ) {
        self.record_segments(count, segment.max(1), &mut record);
    }

    /// [`Context::record_in_segments`], once for every kind of draw.
    fn record_segments(
        &mut self,
        count: usize,
        segment: usize,
        record: &mut dyn FnMut(&mut Context, Range<usize>) -> bool,
    ) {
        let range = |start: usize| start..(start + segment).min(count);
        let rest = (segment..count).step_by(segment);
        if !record(self, range(0)) {
            return;
        }
        let Some(drawable) = self.drawable.clone().filter(|_| self.fbo.draw == 0 && segment < count) else {
            // The rest recorded in turn, up to a segment that could not be.
            rest.clone().all(|start| record(self, range(start)));
            return;
        };
        let pinned = self.window_shape(false).map(|shape| (shape, self.samples_of(0)));
        let hand_off = HandOff::default();
        // As many render threads as a flush: the recording thread is one of them only once
        // it has recorded its segment and would wait (`HandOff::take_back`).
        let threads = thread_count();
        let renderer = || hand_off.render(&drawable, threads);
        crate::pool::run_beside(1, &renderer, || {
            // The renderer returns once the recording is over, however it ends.
            let _finishing = Finishing(&hand_off);
            for start in rest {
                if let Some(scene) = self.scene.take() {
                    let overwrites = std::mem::take(&mut self.scene_overwrites_front);
                    if let Some(scene) = hand_off.hand_over(scene, overwrites) {
                        // No renderer yet: this segment renders in turn.
                        self.render_in_turn(scene, overwrites, &drawable);
                    }
                }
                self.window_pinned = pinned;
                let complete = record(self, range(start));
                self.window_pinned = None;
                if let Some(spare) = hand_off.take_back() {
                    self.spare_scene.get_or_insert(spare);
                }
                if !complete {
                    break;
                }
            }
        });
    }

    /// Renders a segment's `scene` (which `overwrites` the front image, or not) on the
    /// recording thread when no renderer has started, on every render thread, as the
    /// renderer would.
    fn render_in_turn(&mut self, mut scene: Scene, overwrites: bool, drawable: &Mutex<Drawable>) {
        let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
        render_segment(&mut guard, &mut scene, overwrites, thread_count());
        drop(guard);
        scene.clear();
        self.spare_scene = Some(scene);
    }
}
