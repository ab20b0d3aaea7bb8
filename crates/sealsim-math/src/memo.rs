//! A small process-wide memo: the results of pure, costly functions of a few inputs (a contact
//! table's nodes per spectral shape, a compound's T10, a parsed library file), kept for the
//! whole process so that the cases of a study, which ask again and again, compute each once.

use std::sync::Mutex;

/// At most `capacity` (key, value) pairs, the least recently used dropped first. Keys compare
/// by `==` (exact bits for floats), so a hit returns exactly what the function gave. The value
/// is computed outside the lock: two threads that miss together both compute it, and since the
/// function is pure they get the same bits, whichever is kept.
pub struct Memo<K, V> {
    entries: Mutex<Vec<(K, V)>>,
    capacity: usize,
}

impl<K: PartialEq, V: Clone> Memo<K, V> {
    /// An empty memo (usable in a `static`).
    pub const fn new(capacity: usize) -> Self {
        Memo {
            entries: Mutex::new(Vec::new()),
            capacity,
        }
    }

    /// The value for `key`: remembered, or `compute()` remembered now.
    pub fn get_or_insert_with(&self, key: K, compute: impl FnOnce() -> V) -> V {
        {
            let mut entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
            if let Some(at) = entries.iter().position(|(k, _)| *k == key) {
                let entry = entries.remove(at);
                let value = entry.1.clone();
                entries.push(entry);
                return value;
            }
        }
        let value = compute();
        let mut entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
        if !entries.iter().any(|(k, _)| *k == key) {
            if entries.len() >= self.capacity.max(1) {
                entries.remove(0);
            }
            entries.push((key, value.clone()));
        }
        value
    }
}

#[cfg(test)]
mod tests {
    use super::Memo;
    use std::cell::Cell;

    #[test]
    fn computes_once_per_key_and_forgets_the_least_recent() {
        let memo: Memo<u32, u32> = Memo::new(2);
        let calls = Cell::new(0);
        let square = |k: u32| {
            calls.set(calls.get() + 1);
            k * k
        };
        assert_eq!(memo.get_or_insert_with(3, || square(3)), 9);
        assert_eq!(memo.get_or_insert_with(3, || square(3)), 9);
        assert_eq!(calls.get(), 1);
        memo.get_or_insert_with(4, || square(4));
        // touching 3 makes 4 the least recently used
        memo.get_or_insert_with(3, || square(3));
        assert_eq!(calls.get(), 2);
        // a third key evicts the least recently used, 4
        memo.get_or_insert_with(5, || square(5));
        memo.get_or_insert_with(3, || square(3));
        assert_eq!(calls.get(), 3);
        memo.get_or_insert_with(4, || square(4));
        assert_eq!(calls.get(), 4);
    }
}
