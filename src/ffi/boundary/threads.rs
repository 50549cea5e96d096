//! How many threads the heavy calls (bulk construction, normals) may use.

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::guard;
use crate::ffi::boundary::status::hw_status;

#[cfg(feature = "parallel")]
mod pool {
    use std::sync::{Arc, RwLock};

    use crate::ffi::boundary::error::FfiError;

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
    use crate::ffi::boundary::error::FfiError;

    pub(super) fn set(_count: usize) -> Result<(), FfiError> {
        Ok(())
    }

    pub(crate) fn with_threads<R: Send>(work: impl FnOnce() -> R + Send) -> R {
        work()
    }
}

pub(crate) use pool::with_threads;

/// The largest count hw_set_thread_count() accepts. Above the core count of any machine halfwing
/// targets, so it limits no real use; it stops a mistaken value (`(size_t)-1`, a byte count)
/// from trying to start that many threads, each with its own stack, and rayon from silently
/// capping it.
/// \ingroup errors
pub const HW_MAX_THREAD_COUNT: usize = 1024;

/// Sets how many threads bulk construction and normal computation use from now on, for every
/// thread of the process: 1 runs them single-threaded, 0 restores the default (one per core).
/// A count above ::HW_MAX_THREAD_COUNT gives `HW_ERR_INVALID_INPUT` and keeps the current
/// setting. In a build without the `parallel` feature everything is single-threaded and a valid
/// count changes nothing.
/// \ingroup errors
#[unsafe(no_mangle)]
pub extern "C" fn hw_set_thread_count(count: usize) -> hw_status {
    guard(|| {
        if count > HW_MAX_THREAD_COUNT {
            return Err(FfiError::invalid_input(format!(
                "thread count {count} is above the maximum of {HW_MAX_THREAD_COUNT}"
            )));
        }
        pool::set(count)
    })
}
