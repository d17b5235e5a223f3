//! Object names: the name space of one kind of GL object (texture, buffer, framebuffer,
//! renderbuffer and query objects, display lists), written once for all of them.
//!
//! A name is unused, reserved (handed out by glGen* but not yet an object: glIs* is false
//! until the first bind) or an object. Name 0 is never handed out nor stored: each kind gives
//! it its own meaning (the default texture, the window's framebuffer, "no buffer"), so the
//! table ignores it. As in Mesa, new names continue after the largest name ever used (deleted
//! names are not reused) and only when that would pass the end of the name space are free
//! names searched from 1, as one consecutive block (which glGenLists needs, and which is what
//! Mesa's `_mesa_HashFindFreeKeyBlock` gives every glGen*).
use std::collections::HashMap;

/// What a name holds.
#[derive(Clone, Debug)]
enum Slot<T> {
    /// Handed out by glGen*, no object yet.
    Reserved,
    Object(T),
}

/// A count of names the memory cannot hold (the command's GL_OUT_OF_MEMORY).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfNames;

/// The names of one kind of object and the objects they hold.
#[derive(Clone, Debug)]
pub struct NameTable<T> {
    slots: HashMap<u32, Slot<T>>,
    /// The largest name ever used: new names continue after it.
    largest: u32,
}

impl<T> Default for NameTable<T> {
    fn default() -> Self {
        NameTable { slots: HashMap::new(), largest: 0 }
    }
}

impl<T> NameTable<T> {
    /// The first of `n` (at least 1) consecutive unused names: after the largest name ever
    /// used when they fit below the end of the name space, else the first gap large enough.
    fn free_block(&self, n: u32) -> Option<u32> {
        let last_of = |first: u32| first.checked_add(n - 1);
        if let Some(first) = self.largest.checked_add(1).filter(|&first| last_of(first).is_some()) {
            return Some(first);
        }
        // The slow path, only once names reach the end of the name space.
        let mut used_names: Vec<u32> = self.slots.keys().copied().collect();
        used_names.sort_unstable();
        let mut candidate: u32 = 1;
        for used in used_names {
            if used >= candidate {
                if used - candidate >= n {
                    return Some(candidate);
                }
                candidate = used.checked_add(1)?;
            }
        }
        last_of(candidate).map(|_| candidate)
    }

    /// Takes `n` consecutive unused names, each holding what `slot` makes of it.
    fn take_block(&mut self, n: usize, mut slot: impl FnMut() -> Slot<T>) -> Result<Vec<u32>, OutOfNames> {
        let mut names = Vec::new();
        if n == 0 {
            return Ok(names);
        }
        names.try_reserve_exact(n).map_err(|_| OutOfNames)?;
        let count = u32::try_from(n).map_err(|_| OutOfNames)?;
        let first = self.free_block(count).ok_or(OutOfNames)?;
        names.extend(first..=first + (count - 1));
        for &name in &names {
            self.slots.insert(name, slot());
        }
        self.largest = self.largest.max(first + (count - 1));
        Ok(names)
    }

    /// glGen*: `n` unused names, reserved (no objects until their first bind).
    pub fn generate(&mut self, n: usize) -> Result<Vec<u32>, OutOfNames> {
        self.take_block(n, || Slot::Reserved)
    }

    /// glGen* of kinds whose names are objects at once (queries, display lists): `n`
    /// consecutive unused names, each holding an object `make` creates.
    pub fn generate_objects(&mut self, n: usize, mut make: impl FnMut() -> T) -> Result<Vec<u32>, OutOfNames> {
        self.take_block(n, || Slot::Object(make()))
    }

    /// Whether `name` is an object (glIs*).
    pub fn is_object(&self, name: u32) -> bool {
        matches!(self.slots.get(&name), Some(Slot::Object(_)))
    }

    /// Whether `name` is in use: reserved or an object.
    pub fn is_used(&self, name: u32) -> bool {
        self.slots.contains_key(&name)
    }

    pub fn get(&self, name: u32) -> Option<&T> {
        match self.slots.get(&name) {
            Some(Slot::Object(object)) => Some(object),
            _ => None,
        }
    }

    pub fn get_mut(&mut self, name: u32) -> Option<&mut T> {
        match self.slots.get_mut(&name) {
            Some(Slot::Object(object)) => Some(object),
            _ => None,
        }
    }

    /// The object `name` holds, created by `make` if the name is unused or only reserved
    /// (glBind* of a name: any nonzero name becomes an object at its first bind). `None` for 0.
    pub fn get_or_create(&mut self, name: u32, make: impl FnOnce() -> T) -> Option<&mut T> {
        if name == 0 {
            return None;
        }
        self.largest = self.largest.max(name);
        let slot = self.slots.entry(name).or_insert(Slot::Reserved);
        if matches!(slot, Slot::Reserved) {
            *slot = Slot::Object(make());
        }
        match slot {
            Slot::Object(object) => Some(object),
            Slot::Reserved => None,
        }
    }

    /// Makes `name` (not 0) hold `object`, replacing what it held (glEndList).
    pub fn insert(&mut self, name: u32, object: T) {
        if name != 0 {
            self.largest = self.largest.max(name);
            self.slots.insert(name, Slot::Object(object));
        }
    }

    /// glDelete* of one name: frees it (reserved or object) and returns the object it held.
    /// Name 0 and unused names are ignored.
    pub fn delete(&mut self, name: u32) -> Option<T> {
        match self.slots.remove(&name)? {
            Slot::Object(object) => Some(object),
            Slot::Reserved => None,
        }
    }

    /// Frees every name of `range` that is in use (glDeleteLists).
    pub fn delete_range(&mut self, range: std::ops::RangeInclusive<u32>) {
        if range.is_empty() {
            return;
        }
        let len = u64::from(*range.end()) - u64::from(*range.start()) + 1;
        if len <= self.slots.len() as u64 {
            for name in range {
                self.slots.remove(&name);
            }
        } else {
            self.slots.retain(|name, _| !range.contains(name));
        }
    }

    /// Every object and its name.
    pub fn objects(&self) -> impl Iterator<Item = (u32, &T)> {
        self.slots.iter().filter_map(|(&name, slot)| match slot {
            Slot::Object(object) => Some((name, object)),
            Slot::Reserved => None,
        })
    }

    /// Every object.
    pub fn values(&self) -> impl Iterator<Item = &T> {
        self.objects().map(|(_, object)| object)
    }

    /// Every object, writable.
    pub fn values_mut(&mut self) -> impl Iterator<Item = &mut T> {
        self.objects_mut().map(|(_, object)| object)
    }

    /// Every object, writable.
    pub fn objects_mut(&mut self) -> impl Iterator<Item = (u32, &mut T)> {
        self.slots.iter_mut().filter_map(|(&name, slot)| match slot {
            Slot::Object(object) => Some((name, object)),
            Slot::Reserved => None,
        })
    }
}

/// `table[&name]`: the object `name` holds; panics when it holds none (as a map's index does,
/// for names the caller knows to be objects).
impl<T> std::ops::Index<&u32> for NameTable<T> {
    type Output = T;

    fn index(&self, name: &u32) -> &T {
        self.get(*name).expect("the name holds an object")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_continue_after_the_largest_ever_used_like_mesa() {
        let mut table = NameTable::<&str>::default();
        assert_eq!(table.generate(3), Ok(vec![1, 2, 3]));
        assert!(!table.is_object(1) && table.is_used(1), "a generated name is reserved, no object");
        assert_eq!(table.get_or_create(77, || "a").copied(), Some("a"));
        assert_eq!(table.get_or_create(77, || "b").copied(), Some("a"), "created once");
        assert!(table.is_object(77));
        assert_eq!(table.get_or_create(0, || "zero"), None, "0 is never an object");
        assert!(table.delete(1).is_none() && table.delete(2).is_none() && !table.is_used(2));
        assert!(table.delete(2).is_none() && table.delete(0).is_none() && table.delete(12345).is_none());
        assert_eq!(table.generate(2), Ok(vec![78, 79]), "deleted names are not reused");
        assert_eq!(table.delete(77), Some("a"));
        assert_eq!(table.generate(1), Ok(vec![80]));
        assert_eq!(table.generate(0), Ok(vec![]));
        assert_eq!(table.generate(usize::MAX / 2), Err(OutOfNames));
        // Past the end of the name space: the first free block from 1.
        table.insert(u32::MAX, "last");
        assert_eq!(table.generate(2), Ok(vec![1, 2]));
        assert_eq!(table.generate_objects(2, || "q"), Ok(vec![4, 5]), "3 is still reserved");
        assert!(table.is_object(4) && table.is_object(5));
        let mut objects: Vec<u32> = table.objects().map(|(name, _)| name).collect();
        objects.sort_unstable();
        assert_eq!(objects, vec![4, 5, u32::MAX]);
        table.delete_range(0..=4);
        assert!(!table.is_used(1) && !table.is_used(3) && !table.is_used(4) && table.is_used(5));
    }

    #[test]
    fn blocks_near_the_end_of_the_name_space_take_the_first_gap_large_enough() {
        let mut table = NameTable::<()>::default();
        table.insert(u32::MAX - 1, ());
        assert_eq!(table.free_block(1), Some(u32::MAX));
        assert_eq!(table.free_block(5), Some(1));
        table.insert(3, ());
        assert_eq!(table.free_block(2), Some(1));
        assert_eq!(table.free_block(3), Some(4));
        table.insert(u32::MAX, ());
        assert_eq!(table.free_block(1), Some(1));
    }
}
