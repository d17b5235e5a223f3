//! A cache of compiled programs keyed by the state that shapes them, evicting the least
//! recently used when full: the fixed-function generators' programs are found here by their
//! compact keys (`VertexKey`, `FragmentKey`), so a state seen before costs a hash lookup
//! instead of a generation and a compilation (tens of microseconds).
//!
//! The cache is per share group (`context::programs`): contexts that share objects share
//! compiled programs too, as Mesa shares its program cache within a screen. Values are handed
//! out as `Arc`s, so a scene that holds a program keeps it alive after an eviction.
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// How many programs of one kind a cache keeps by default: a client switching between more
/// fixed-function states than this in every frame is rare (MuJoCo uses a few dozen).
pub const DEFAULT_CAPACITY: usize = 256;

/// What a cache has done since it was made: reported by `TESSERA_DEBUG=programs` and the
/// benchmarks (the cost of program generation with a cold cache).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheStats {
    pub hits: u64,
    pub misses: u64,
    pub evictions: u64,
    /// Time spent generating and compiling on misses.
    pub generation: Duration,
}

struct Entry<V> {
    value: Arc<V>,
    last_used: u64,
}

/// The cache's hasher: a fixed multiplicative hash (FxHash's), not the per-map random
/// SipHash keys, so that a run does the same allocations and frees in the same order every
/// time (dropping a cache frees its programs in the map's order; with random keys, the heap
/// that the leak test measures varied from run to run by a few KiB), and cheap: a draw looks
/// its programs up every time, and SipHash over a key cost more than the rest of the
/// lookup. The keys are the library's own state, not attacker-chosen.
type FixedHasher = BuildHasherDefault<KeyHasher>;

/// FxHash's word step (rotate, xor, multiply) over the key's bytes, a word at a time.
#[derive(Clone, Copy, Default)]
pub struct KeyHasher(u64);

impl KeyHasher {
    #[inline(always)]
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

impl Hasher for KeyHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for c in &mut chunks {
            self.add(u64::from_le_bytes(c.try_into().expect("8 bytes")));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut word = [0u8; 8];
            word[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(word));
        }
    }
    #[inline]
    fn write_u8(&mut self, i: u8) {
        self.add(i as u64);
    }
    #[inline]
    fn write_u16(&mut self, i: u16) {
        self.add(i as u64);
    }
    #[inline]
    fn write_u32(&mut self, i: u32) {
        self.add(i as u64);
    }
    #[inline]
    fn write_u64(&mut self, i: u64) {
        self.add(i);
    }
    #[inline]
    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }
    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
}

/// A program cache: at most `capacity` programs, the least recently used evicted first.
pub struct ProgramCache<K, V> {
    entries: HashMap<K, Entry<V>, FixedHasher>,
    /// The key of the last lookup and its program, found again by one comparison (a draw
    /// usually has the state of the one before it); its entry's `last_used` is brought up
    /// to date when another key is looked up (or before an eviction).
    last: Option<(K, Arc<V>)>,
    /// The lookup count at `last`'s latest lookup.
    last_used: u64,
    /// Lookups so far (the recency of `Entry::last_used`).
    clock: u64,
    capacity: usize,
    stats: CacheStats,
}

impl<K: Hash + Eq + Clone, V> ProgramCache<K, V> {
    /// An empty cache holding up to `capacity` programs (at least one).
    pub fn new(capacity: usize) -> Self {
        ProgramCache {
            entries: HashMap::default(),
            last: None,
            last_used: 0,
            clock: 0,
            capacity: capacity.max(1),
            stats: CacheStats::default(),
        }
    }

    /// Writes the recency of `last` into its entry.
    fn settle_last(&mut self) {
        if let Some((key, _)) = &self.last {
            if let Some(entry) = self.entries.get_mut(key) {
                entry.last_used = self.last_used;
            }
        }
    }

    pub fn get_or_generate(&mut self, key: &K, generate: impl FnOnce(&K) -> V) -> Arc<V> {
        self.clock += 1;
        if let Some((last, value)) = &self.last {
            if last == key {
                self.last_used = self.clock;
                self.stats.hits += 1;
                return value.clone();
            }
        }
        self.settle_last();
        if let Some(entry) = self.entries.get_mut(key) {
            entry.last_used = self.clock;
            self.stats.hits += 1;
            let value = entry.value.clone();
            self.last = Some((key.clone(), value.clone()));
            self.last_used = self.clock;
            return value;
        }
        let start = Instant::now();
        let value = Arc::new(generate(key));
        self.stats.generation += start.elapsed();
        self.stats.misses += 1;
        if self.entries.len() >= self.capacity {
            self.evict_least_recent();
        }
        self.entries.insert(key.clone(), Entry { value: value.clone(), last_used: self.clock });
        self.last = Some((key.clone(), value.clone()));
        self.last_used = self.clock;
        value
    }

    /// A linear scan: evictions happen only when a client cycles through more states than
    /// the capacity, and then generation costs far more than the scan.
    fn evict_least_recent(&mut self) {
        let oldest = self.entries.iter().min_by_key(|(_, e)| e.last_used).map(|(k, _)| k.clone());
        if let Some(key) = oldest {
            if self.last.as_ref().is_some_and(|(last, _)| *last == key) {
                self.last = None;
            }
            self.entries.remove(&key);
            self.stats.evictions += 1;
        }
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    pub fn stats(&self) -> CacheStats {
        self.stats
    }
}

impl<K: Hash + Eq + Clone, V> Default for ProgramCache<K, V> {
    fn default() -> Self {
        ProgramCache::new(DEFAULT_CAPACITY)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hit_returns_the_same_program_without_generating() {
        let mut cache = ProgramCache::new(4);
        let a = cache.get_or_generate(&1u32, |k| k * 10);
        let b = cache.get_or_generate(&1u32, |_| panic!("generated twice"));
        assert!(Arc::ptr_eq(&a, &b));
        assert_eq!(*a, 10);
        let stats = cache.stats();
        assert_eq!((stats.hits, stats.misses, stats.evictions), (1, 1, 0));
    }

    #[test]
    fn lookups_of_the_last_key_keep_it_recent() {
        // 1 is looked up again and again (found by the comparison with the last key), then 0:
        // the least recently used is 2, not 1.
        let mut cache = ProgramCache::new(3);
        for k in 0..3u32 {
            cache.get_or_generate(&k, |k| *k);
        }
        for _ in 0..3 {
            cache.get_or_generate(&1, |_| panic!("1 was cached"));
        }
        cache.get_or_generate(&0, |_| panic!("0 was cached"));
        cache.get_or_generate(&3, |k| *k);
        let mut regenerated = [false; 3];
        for k in [1u32, 0, 2] {
            cache.get_or_generate(&k, |k| {
                regenerated[*k as usize] = true;
                *k
            });
        }
        assert_eq!(regenerated, [false, false, true]);
        assert_eq!(cache.stats().hits, 6);
    }

    #[test]
    fn the_least_recently_used_program_is_evicted() {
        let mut cache = ProgramCache::new(3);
        for k in 0..3u32 {
            cache.get_or_generate(&k, |k| *k);
        }
        // Use 0 again: 1 is now the least recently used.
        cache.get_or_generate(&0, |_| panic!("0 was cached"));
        let held = cache.get_or_generate(&1, |_| panic!("1 was cached"));
        cache.get_or_generate(&2, |_| panic!("2 was cached"));
        // Order of use: 0, 1, 2 → 0 is the oldest now.
        cache.get_or_generate(&3, |k| *k);
        assert_eq!(cache.len(), 3);
        assert_eq!(cache.stats().evictions, 1);
        let mut regenerated = false;
        cache.get_or_generate(&0, |k| {
            regenerated = true;
            *k
        });
        assert!(regenerated, "0 should have been evicted");
        // 1 was evicted by that insertion (0, 1, 2, 3 used in order 1, 2, 3, 0), yet the
        // Arc handed out earlier still holds its program.
        assert_eq!(*held, 1);
        let mut regenerated_one = false;
        cache.get_or_generate(&1, |k| {
            regenerated_one = true;
            *k
        });
        assert!(regenerated_one, "1 should have been evicted second");
    }
}
