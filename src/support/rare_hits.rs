//! Scans for the few items of a large array that match a test (boundary twins after a build,
//! isolated vertices, non-finite coordinates): nearly every run of items has none.

/// The indices, counted from `first`, of the items of `items` for which `hit` holds, ascending.
/// Runs of items are tested as a whole first, without branches (so the test runs packed, when
/// `hit` has no branches either), and only a run with a hit is searched item by item.
#[inline]
pub(crate) fn rare_hits<T>(items: &[T], first: usize, hit: impl Fn(&T) -> bool) -> Vec<u32> {
    rare_hits_by_runs(
        items,
        first,
        |run| run.iter().fold(false, |any, item| any | hit(item)),
        &hit,
    )
}

/// [`rare_hits`] with the test of a whole run given apart (`run_has_hit(run)` holds when `hit`
/// holds for an item of `run`), for items whose test packs better over the run's raw contents
/// than item by item.
#[inline]
pub(crate) fn rare_hits_by_runs<T>(
    items: &[T],
    first: usize,
    run_has_hit: impl Fn(&[T]) -> bool,
    hit: impl Fn(&T) -> bool,
) -> Vec<u32> {
    const RUN: usize = 256;
    let mut hits = Vec::new();
    for (r, run) in items.chunks(RUN).enumerate() {
        if run_has_hit(run) {
            let start = first + r * RUN;
            hits.extend(
                (0..run.len())
                    .filter(|&i| hit(&run[i]))
                    .map(|i| (start + i) as u32),
            );
        }
    }
    hits
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_in_any_run_and_none() {
        let mut items = vec![0u8; 1000];
        for i in [0, 255, 256, 700, 999] {
            items[i] = 1;
        }
        assert_eq!(
            rare_hits(&items, 10, |&x| x == 1),
            [10, 265, 266, 710, 1009]
        );
        assert!(rare_hits(&items[1..255], 0, |&x| x == 1).is_empty());
        assert!(rare_hits::<u8>(&[], 0, |_| true).is_empty());
    }
}
