//! How many threads the heavy calls (bulk construction, normals) may use.

use super::boundary::guard;
use super::status::hw_status;

#[cfg(feature = "parallel")]
mod pool {
    use std::sync::{Arc, RwLock};

    use crate::ffi::error::FfiError;

    /// The pool chosen with hw_set_thread_count(); `None` = rayon's global pool.
    static CHOSEN: RwLock<Option<Arc<rayon::ThreadPool>>> = RwLock::new(None);

    pub(super) fn set(count: usize) -> Result<(), FfiError> {
        let pool = if count == 0 {
            None
        } else {
            let built = rayon::ThreadPoolBuilder::new()
                .num_threads(count)
                .thread_name(|i| format!("halfwing-{i}"))
                .build()
                .map_err(|e| {
                    FfiError::invalid_input(format!("cannot start {count} threads: {e}"))
                })?;
            Some(Arc::new(built))
        };
        *CHOSEN
            .write()
            .unwrap_or_else(|poisoned| poisoned.into_inner()) = pool;
        Ok(())
    }

    pub(crate) fn with_threads<R: Send>(work: impl FnOnce() -> R + Send) -> R {
        let chosen = CHOSEN
            .read()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .clone();
        match chosen {
            Some(pool) => pool.install(work),
            None => work(),
        }
    }
}

#[cfg(not(feature = "parallel"))]
mod pool {
    use crate::ffi::error::FfiError;

    pub(super) fn set(_count: usize) -> Result<(), FfiError> {
        Ok(())
    }

    pub(crate) fn with_threads<R: Send>(work: impl FnOnce() -> R + Send) -> R {
        work()
    }
}

pub(crate) use pool::with_threads;

/// Sets how many threads bulk construction and normal computation use from now on, for every
/// thread of the process: 1 runs them single-threaded, 0 restores the default (one per core).
/// In a build without the `parallel` feature everything is single-threaded and this is a no-op.
#[unsafe(no_mangle)]
pub extern "C" fn hw_set_thread_count(count: usize) -> hw_status {
    guard(|| pool::set(count))
}
