//! Data-parallel passes of the Voronoi construction (rayon behind the `parallel` feature).

/// `(0..len).map(f).collect()`, in parallel when the `parallel` feature is on. Every pass it
/// serves is a pure per-element function over up to millions of elements; runs of at least
/// 2^14 elements keep the scheduling overhead negligible.
pub(crate) fn map_indexed<T: Send>(len: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        (0..len)
            .into_par_iter()
            .with_min_len(1 << 14)
            .map(f)
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        (0..len).map(f).collect()
    }
}

/// `f(k, run)` for the consecutive runs of `run_len` elements of `items` (`k` counts runs),
/// in parallel when the `parallel` feature is on; results in run order.
pub(crate) fn map_runs<T: Sync, R: Send>(
    items: &[T],
    run_len: usize,
    f: impl Fn(usize, &[T]) -> R + Sync + Send,
) -> Vec<R> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items
            .par_chunks(run_len)
            .enumerate()
            .map(|(k, run)| f(k, run))
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items
            .chunks(run_len)
            .enumerate()
            .map(|(k, run)| f(k, run))
            .collect()
    }
}

/// [`map_runs`] over runs that `f` fills in.
pub(crate) fn map_runs_mut<T: Send, R: Send>(
    items: &mut [T],
    run_len: usize,
    f: impl Fn(usize, &mut [T]) -> R + Sync + Send,
) -> Vec<R> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items
            .par_chunks_mut(run_len)
            .enumerate()
            .map(|(k, run)| f(k, run))
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items
            .chunks_mut(run_len)
            .enumerate()
            .map(|(k, run)| f(k, run))
            .collect()
    }
}
