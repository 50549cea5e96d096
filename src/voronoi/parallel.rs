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

/// The indices `i < len` for which `keep(i)` holds, in increasing order; in parallel when the
/// `parallel` feature is on. Serves passes that find a few exceptions among millions of elements.
pub(crate) fn filter_indexed(len: usize, keep: impl Fn(usize) -> bool + Sync + Send) -> Vec<u32> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        (0..len)
            .into_par_iter()
            .with_min_len(1 << 14)
            .filter(|&i| keep(i))
            .map(|i| i as u32)
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        (0..len).filter(|&i| keep(i)).map(|i| i as u32).collect()
    }
}
