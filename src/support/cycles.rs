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

/// The sum of the lengths [`for_each_cycle_length`] gives for `starts`, for a `step` that always
/// has a next element, walking `LANES` cycles side by side with no branch per step. Each walk is
/// a chain of dependent loads; when its elements are scattered in memory every step waits on a
/// miss, and independent chains in one loop overlap their misses. (A lane whose cycle has ended
/// keeps stepping around it, uncounted, until the longest of its group ends.)
pub(crate) fn total_cycle_length_interleaved<S: Copy + PartialEq, const LANES: usize>(
    mut starts: impl Iterator<Item = S>,
    max_steps: usize,
    step: impl Fn(S) -> S,
) -> usize {
    let mut total = 0;
    while let Some(first) = starts.next() {
        // Lanes without a walk of their own (the last group) follow the first, uncounted.
        let (mut start, mut walking) = ([first; LANES], [false; LANES]);
        walking[0] = true;
        for (lane_start, lane_walking) in start.iter_mut().zip(&mut walking).skip(1) {
            if let Some(s) = starts.next() {
                (*lane_start, *lane_walking) = (s, true);
            }
        }
        let mut current = start;
        let mut length = 0;
        while length < max_steps && walking.contains(&true) {
            length += 1;
            for lane in 0..LANES {
                let next = step(current[lane]);
                total += usize::from(walking[lane]);
                walking[lane] &= next != start[lane];
                current[lane] = next;
            }
        }
    }
    total
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

    #[test]
    fn interleaved_walks_add_up_to_the_lengths_one_by_one() {
        // Cycles of lengths 1 to 12 over 0..78, and a rho (a tail into a cycle that never
        // returns to the tail's start), each walk bounded by 30 steps.
        let mut next: Vec<usize> = Vec::new();
        let mut starts = Vec::new();
        for length in 1..=12 {
            let first = next.len();
            starts.push(first);
            next.extend((1..length).map(|i| first + i));
            next.push(first);
        }
        let rho = next.len();
        next.extend([rho + 1, rho + 2, rho + 1]);
        starts.push(rho);
        let step = |i: usize| next[i];
        let mut one_by_one = 0;
        let lengths = starts.iter().map(|&s| (s, s));
        for_each_cycle_length(lengths, 30, |i| Some(step(i)), |_, l| one_by_one += l);
        assert_eq!(one_by_one, (1..=12).sum::<usize>() + 30);
        // Every number of walks, so that the last group has every number of lanes of its own.
        for count in 0..=starts.len() {
            let mut lengths = 0;
            for_each_cycle_length(
                starts[..count].iter().map(|&s| (s, s)),
                30,
                |i| Some(step(i)),
                |_, l| lengths += l,
            );
            let iter = || starts[..count].iter().copied();
            assert_eq!(
                total_cycle_length_interleaved::<_, 1>(iter(), 30, step),
                lengths
            );
            assert_eq!(
                total_cycle_length_interleaved::<_, 4>(iter(), 30, step),
                lengths
            );
            assert_eq!(
                total_cycle_length_interleaved::<_, 8>(iter(), 30, step),
                lengths
            );
        }
    }
}
