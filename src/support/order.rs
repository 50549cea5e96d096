//! Whether a sequence of ids mostly advances in small steps: data indexed by them is then met
//! almost in memory order, and walks over it are best made one after another; otherwise nearly
//! every step waits on memory, and walks are best overlapped (prefetched or interleaved).

/// Do the ids `id(i)` of the items `0..n` mostly lie within `nearby` of the item before's? Judged
/// from about a thousand pairs of consecutive items spread over the range: the order is near
/// when at most a quarter of the pairs jump (an item without an id counts as a jump).
pub(crate) fn mostly_nearby(n: usize, nearby: u32, id: impl Fn(usize) -> Option<u32>) -> bool {
    const SAMPLES: usize = 1024;
    let step = (n.saturating_sub(1) / SAMPLES).max(1);
    let (mut pairs, mut jumps) = (0, 0);
    for i in (1..n).step_by(step) {
        let near = match (id(i), id(i - 1)) {
            (Some(id), Some(before)) => id.abs_diff(before) <= nearby,
            _ => false,
        };
        pairs += 1;
        jumps += usize::from(!near);
    }
    4 * jumps <= pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_jumps_and_missing_ids() {
        let ramp = |i: usize| Some(3 * i as u32);
        assert!(mostly_nearby(100_000, 3, ramp));
        assert!(!mostly_nearby(100_000, 2, ramp));
        // Every third item jumps: a third of the pairs jump, more than a quarter.
        let sawtooth = |i: usize| Some(if i.is_multiple_of(3) { 1_000_000 } else { 0 });
        assert!(!mostly_nearby(3000, 10, sawtooth));
        // Every fifth item has no id: two pairs in five jump.
        assert!(!mostly_nearby(5000, 10, |i| (i % 5 != 0).then_some(0)));
        assert!(mostly_nearby(0, 0, |_| None) && mostly_nearby(1, 0, |_| None));
    }
}
