//! The tile workers: a scene's bins rendered band by band by a pool of threads, and the
//! coverage walkers that turn a primitive's per-row coverage into spans for the fragment
//! pipeline.
//!
//! At a flush point the framebuffer is split into bands (rows of 64×64 tiles),
//! `TESSERA_THREADS` workers (the calling thread included) take bands one at a time, and
//! each band renders its tiles, each tile its bin in submission order ([`render_tiles`]).
//! A pixel is only ever touched by the one worker owning its band, in submission order, so
//! the bytes are identical for any number of threads. Each band's work is compiled once per
//! SIMD level and runs the CPU's copy (`crate::simd`), with identical bytes at every level. What a bin holds and how each
//! primitive is rendered is `setup`'s (the room above); this room only knows tiles, bands,
//! threads and coverage: 4×4 blocks of filled triangles walked hierarchically
//! ([`blocks`]), spans for everything else ([`walk`]).
#![deny(unsafe_code)]

pub mod blocks;
pub mod samples;
pub mod walk;

use crate::fragment::pipeline::Scratch;
use crate::framebuffer::band::Band;
use crate::framebuffer::{ColorSlot, Framebuffer, Rect};
use std::sync::{Mutex, OnceLock};

/// Tile side in pixels.
pub const TILE_SIZE: usize = 64;

/// Renders `bins` (per tile, row-major, `tiles_x` tiles a row: what to render there, in
/// order) into the color `targets` of `framebuffer` on up to `threads` threads (the caller's
/// included): `render(items, tile, band, scratch, local)` renders a tile's bin entries, in
/// order, into the part `tile` (a rectangle of the framebuffer) of `band` (the whole bin at
/// once, so that the caller may render runs of entries together: small triangles). `local`
/// is the caller's own per-band state (made once per band, not per entry: a batch of
/// blocks).
pub fn render_tiles<T: Sync, L: Default>(
    framebuffer: &mut Framebuffer,
    targets: &[ColorSlot],
    tiles_x: usize,
    bins: &[Vec<T>],
    threads: usize,
    render: impl Fn(&[T], Rect, &mut Band<'_>, &mut Scratch, &mut L) + Sync,
) {
    let bounds = framebuffer.bounds();
    let bands = framebuffer.bands(TILE_SIZE, targets);
    run_parallel(bands, threads, |mut band| {
        // One copy of the band's work per SIMD level (`crate::simd`): the tile loop and what
        // the compiler inlines into it run with the CPU's instructions, same bytes at each.
        crate::simd::per_level!({
            let ty = band.y0 as usize / TILE_SIZE;
            let mut scratch = Scratch::default();
            let mut local = L::default();
            for tx in 0..tiles_x {
                let tile = Rect::from_xywh((tx * TILE_SIZE) as i32, band.y0, TILE_SIZE as i32, band.rows as i32)
                    .intersect(bounds);
                let bin = &bins[ty * tiles_x + tx];
                if !bin.is_empty() {
                    render(bin, tile, &mut band, &mut scratch, &mut local);
                }
            }
        })
    });
}

/// The number of rasterizer threads: `TESSERA_THREADS`, or the number of cores.
pub fn thread_count() -> usize {
    static COUNT: OnceLock<usize> = OnceLock::new();
    *COUNT.get_or_init(|| {
        std::env::var("TESSERA_THREADS")
            .ok()
            .and_then(|v| v.trim().parse::<usize>().ok())
            .filter(|&n| n >= 1)
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
            .min(256)
    })
}

/// Runs `work` on every item, on up to `threads` threads (the caller's included).
fn run_parallel<T: Send>(items: Vec<T>, threads: usize, work: impl Fn(T) + Sync) {
    let threads = threads.min(items.len());
    if threads <= 1 {
        items.into_iter().for_each(work);
        return;
    }
    let queue = Mutex::new(items.into_iter());
    let next = || queue.lock().unwrap_or_else(|p| p.into_inner()).next();
    let worker = || {
        while let Some(item) = next() {
            work(item);
        }
    };
    // The shared pool's threads help (`crate::pool`): no thread spawned per scene.
    crate::pool::run(threads - 1, &worker);
}
