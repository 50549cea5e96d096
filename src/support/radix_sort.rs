//! A stable LSD radix sort of `u64` keys by their high 32 bits: linear time for the sorts of
//! packed `(key << 32) | id` words (spatial orders, position mixes), ids keeping their order
//! among equal keys.

/// Stable LSD radix sort on the high 32 bits (three passes of 11 bits).
pub(crate) fn radix_sort_by_high_word(keys: &mut Vec<u64>) {
    const BITS: u32 = 11;
    const BUCKETS: usize = 1 << BITS;
    let mut scratch = vec![0u64; keys.len()];
    for pass in 0..3 {
        let shift = 32 + pass * BITS;
        let mut counts = [0usize; BUCKETS];
        for &k in keys.iter() {
            counts[((k >> shift) as usize) & (BUCKETS - 1)] += 1;
        }
        let mut total = 0;
        for c in counts.iter_mut() {
            let here = *c;
            *c = total;
            total += here;
        }
        for &k in keys.iter() {
            let bucket = ((k >> shift) as usize) & (BUCKETS - 1);
            scratch[counts[bucket]] = k;
            counts[bucket] += 1;
        }
        std::mem::swap(keys, &mut scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radix_sort_sorts_by_high_word_stably() {
        let mut keys: Vec<u64> = (0..5000u64)
            .map(|i| ((i * 7919 % 4099) << 32) | i)
            .collect();
        radix_sort_by_high_word(&mut keys);
        for w in keys.windows(2) {
            assert!(w[0] >> 32 < w[1] >> 32 || (w[0] >> 32 == w[1] >> 32 && w[0] < w[1]));
        }
    }
}
