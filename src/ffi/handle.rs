//! Owning object handles (`hw_mesh *`, ...): boxed Rust values handed to C.
//!
//! Every live handle is registered, so that `_free` can tell a pointer it gave out from one
//! already freed (or never given) and refuse it with a recorded error instead of freeing twice.
//! Only creation and `_free` consult the registry; other calls trust the pointer, as C APIs do,
//! to keep navigation calls free of locks.

use std::any::TypeId;
use std::collections::HashSet;
use std::sync::Mutex;

use super::error::FfiError;

static LIVE: Mutex<Option<HashSet<(usize, TypeId)>>> = Mutex::new(None);

/// Handles are registered by a scrambled address, not the address itself: a leak checker
/// (LeakSanitizer, valgrind) scanning this set must not mistake it for a reference that keeps a
/// leaked object alive.
fn key<T: 'static>(ptr: *mut T) -> (usize, TypeId) {
    const SCRAMBLE: usize = 0xA5A5_A5A5_A5A5_A5A5_u64 as usize;
    (ptr as usize ^ SCRAMBLE, TypeId::of::<T>())
}

fn with_live<R>(f: impl FnOnce(&mut HashSet<(usize, TypeId)>) -> R) -> R {
    // A poisoned lock only means another thread panicked while holding it; the set is still sound
    // (every operation on it is a single insert or remove).
    let mut guard = LIVE.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    f(guard.get_or_insert_with(HashSet::new))
}

/// Gives `value` to C as an owning handle.
pub(crate) fn into_handle<T: 'static>(value: T) -> *mut T {
    let ptr = Box::into_raw(Box::new(value));
    with_live(|live| live.insert(key(ptr)));
    ptr
}

/// Takes a handle back from C and drops it. NULL is a no-op; a pointer that is not a live handle
/// of this type (freed already, or never created by halfwing) is refused with an error.
///
/// # Safety
/// A registered pointer must not be in use by another thread.
pub(crate) unsafe fn free_handle<T: 'static>(ptr: *mut T, type_name: &str) -> Result<(), FfiError> {
    if ptr.is_null() {
        return Ok(());
    }
    if !with_live(|live| live.remove(&key(ptr))) {
        return Err(FfiError::invalid_handle(format!(
            "{type_name}_free: {ptr:p} is not a live {type_name} (already freed?)"
        )));
    }
    // SAFETY: the pointer came from `into_handle::<T>` and was still registered, so it is a live,
    // uniquely owned box.
    drop(unsafe { Box::from_raw(ptr) });
    Ok(())
}
