//! Data-parallel passes of the Voronoi construction (rayon behind the `parallel` feature).

/// `(0..len).map(f).collect()`, in parallel when the `parallel` feature is on. Every pass it
/// serves is a pure per-element function over up to millions of elements, too cheap per element
/// for [`run_length`]'s runs: runs of at least 2^14 elements keep the scheduling overhead
/// negligible, and a pass no longer than one run is done on the calling thread.
pub(crate) fn map_indexed<T: Send>(len: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(feature = "parallel")]
    {
        const MIN_INDEXED_RUN: usize = 1 << 14;
        if len > MIN_INDEXED_RUN && pool_can_help() {
            use rayon::prelude::*;
            return (0..len)
                .into_par_iter()
                .with_min_len(MIN_INDEXED_RUN)
                .map(f)
                .collect();
        }
    }
    (0..len).map(f).collect()
}

/// Does the pool have a thread besides the one that would wait for it? With one thread, handing
/// a pass to the pool and sleeping until it is done only adds the round trip.
#[cfg(feature = "parallel")]
fn pool_can_help() -> bool {
    rayon::current_num_threads() > 1
}

/// Length of the runs that a pass over `len` independent elements is split into for
/// [`map_each`]: an eighth of the pass, but at least 2^12 elements (from 10k sites on, such a run
/// takes tenths of a millisecond, well above a task's round trip through the pool) and at most
/// 2^15 (many runs keep the threads evenly loaded when one of them is slowed down).
pub(crate) fn run_length(len: usize) -> usize {
    len.div_ceil(8).clamp(MIN_RUN, MAX_RUN)
}

/// Length of the runs of a pass that does extra work at the seams between runs: an eighth of the
/// pass (work for every thread of a small machine, few seams), but at least 2^12 elements. With
/// one thread the pass is one run, with no seams to pay for (the Voronoi vertices of 100k sites:
/// 5% fewer instructions).
pub(crate) fn seamed_run_length(len: usize) -> usize {
    #[cfg(feature = "parallel")]
    if pool_can_help() {
        return len.div_ceil(8).max(MIN_RUN);
    }
    len.max(1)
}

const MIN_RUN: usize = 1 << 12;
const MAX_RUN: usize = 1 << 15;

/// `f(k, item)` for every item of `items` (`k` its position), in parallel when the `parallel`
/// feature is on; results in order. Serves passes over a few long runs of elements (slices,
/// shared or mutable, that the caller splits off), one task per run. A single run, or a pool of
/// one thread, is served on the calling thread.
pub(crate) fn map_each<I: Send, R: Send>(
    items: Vec<I>,
    f: impl Fn(usize, I) -> R + Sync + Send,
) -> Vec<R> {
    #[cfg(feature = "parallel")]
    if items.len() > 1 && pool_can_help() {
        use rayon::prelude::*;
        return items
            .into_par_iter()
            .enumerate()
            .map(|(k, item)| f(k, item))
            .collect();
    }
    items
        .into_iter()
        .enumerate()
        .map(|(k, item)| f(k, item))
        .collect()
}
