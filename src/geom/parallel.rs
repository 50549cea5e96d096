//! Data-parallel helpers of the geometry passes (rayon behind the `parallel` feature).

/// `(0..len).map(f).collect()`, in parallel when the `parallel` feature is on and the pool has
/// more than one thread, in runs of at least 2^12 elements so that scheduling stays cheap.
pub(crate) fn map_indexed<T: Send>(len: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(feature = "parallel")]
    {
        const MIN_RUN: usize = 1 << 12;
        if len > MIN_RUN && rayon::current_num_threads() > 1 {
            use rayon::prelude::*;
            return (0..len)
                .into_par_iter()
                .with_min_len(MIN_RUN)
                .map(f)
                .collect();
        }
    }
    (0..len).map(f).collect()
}

/// Runs `a` and `b`, in parallel when the `parallel` feature and the thread pool allow.
pub(crate) fn join(a: impl FnOnce() + Send, b: impl FnOnce() + Send) {
    #[cfg(feature = "parallel")]
    rayon::join(a, b);
    #[cfg(not(feature = "parallel"))]
    {
        a();
        b();
    }
}
