//! Cycle lengths by walking: the fan checks of both kernels run one walk per vertex over every
//! edge after each build.

/// Walks the cycle from each `(id, start)` of `starts` by `step` and calls `visit(id, length)`:
/// `length` counts the elements met until `step` returns to `start`, gives `None`, or
/// `max_steps` is reached.
#[inline]
pub(crate) fn for_each_cycle_length<S: Copy + PartialEq>(
    starts: impl Iterator<Item = (usize, S)>,
    max_steps: usize,
    step: impl Fn(S) -> Option<S>,
    mut visit: impl FnMut(usize, usize),
) {
    for (id, start) in starts {
        let (mut current, mut length) = (start, 0);
        loop {
            length += 1;
            match step(current) {
                Some(next) if next != start && length < max_steps => current = next,
                _ => break,
            }
        }
        visit(id, length);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_of_cycles_broken_walks_and_bounded_walks() {
        // A permutation with cycles (0 1 2), (3), (4 5); 6 leads to 7, which ends the walk.
        let next = [1, 2, 0, 3, 5, 4, 7, usize::MAX];
        let step = |i: usize| next.get(i).copied().filter(|&n| n != usize::MAX);
        let mut lengths = vec![0; 8];
        let starts = [0, 3, 4, 6, 7].into_iter().map(|i| (i, i));
        for_each_cycle_length(starts, 100, step, |id, length| lengths[id] = length);
        assert_eq!(lengths, [3, 0, 0, 1, 2, 0, 2, 1]);
        let mut bounded = 0;
        for_each_cycle_length([(0, 0)].into_iter(), 2, step, |_, l| bounded = l);
        assert_eq!(bounded, 2);
    }
}
