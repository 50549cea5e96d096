//! A set of ids below a known bound, one bit each: adding an id is one store, and the set reads
//! back in increasing order without a sort.

pub(crate) struct IdSet {
    words: Vec<u64>,
}

impl IdSet {
    /// The empty set of ids below `bound`.
    pub fn new(bound: usize) -> Self {
        IdSet {
            words: vec![0; bound.div_ceil(64)],
        }
    }

    /// Adds `id` (below the bound).
    #[inline(always)]
    pub fn insert(&mut self, id: u32) {
        self.words[(id / 64) as usize] |= 1 << (id % 64);
    }

    /// Is `id` (below the bound) in the set?
    #[inline(always)]
    pub fn contains(&self, id: u32) -> bool {
        self.words[(id / 64) as usize] & (1 << (id % 64)) != 0
    }

    /// The ids in increasing order; `expected` is a guess of how many there are.
    pub fn into_sorted(self, expected: usize) -> Vec<u32> {
        let mut ids = Vec::with_capacity(expected);
        for (word_index, &word) in (0u32..).zip(&self.words) {
            let mut bits = word;
            while bits != 0 {
                ids.push(64 * word_index + bits.trailing_zeros());
                bits &= bits - 1;
            }
        }
        ids
    }
}

#[cfg(test)]
mod tests {
    use super::IdSet;

    #[test]
    fn ids_read_back_sorted_once_each() {
        let mut set = IdSet::new(200);
        for id in [199, 0, 64, 63, 5, 64, 128, 5] {
            set.insert(id);
        }
        assert!(set.contains(63) && set.contains(199) && !set.contains(62) && !set.contains(1));
        assert_eq!(set.into_sorted(0), vec![0, 5, 63, 64, 128, 199]);
        assert!(IdSet::new(0).into_sorted(4).is_empty());
    }
}
