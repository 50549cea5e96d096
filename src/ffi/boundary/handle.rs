//! Owning object handles (`hw_mesh *`, ...): boxed Rust values handed to C.
//!
//! Every live handle is registered, so that `_free` can tell a pointer it gave out from one
//! already freed (or never given) and refuse it with a recorded error instead of freeing twice.
//! Only creation and `_free` consult the registry; other calls trust the pointer, as C APIs do,
//! to keep navigation calls free of locks.
//!
//! A pointer is all a caller passes, so a stale one can only be told from a live one while no
//! new object has its address. `_free` therefore drops the object but keeps its memory for the
//! next [`HW_FREED_ADDRESSES_KEPT`] frees: the allocator cannot give that address to a new object
//! meanwhile, and a second `_free` finds it among the freed handles. Past that window the memory
//! is released and the address may be reused; a stale pointer that then equals a live handle
//! cannot be told from it.

use std::alloc::Layout;
use std::any::TypeId;
use std::collections::{HashSet, VecDeque};
use std::sync::Mutex;

use crate::ffi::boundary::error::FfiError;

/// How many of the most recently freed objects keep their address out of reuse: a second
/// `_free` of an object is refused as long as fewer objects than this were freed since its first.
/// Each keeps a few hundred bytes (its large arrays are released at once): 2 MB at most in all.
/// \ingroup mesh
pub const HW_FREED_ADDRESSES_KEPT: usize = 4096;

/// A handle's registry key: its scrambled address and its type.
type Key = (usize, TypeId);

/// The memory of a freed handle, held back from the allocator.
struct Tombstone {
    /// The allocation's address, unscrambled: a leak checker scanning the registry sees freed
    /// objects' memory as still referenced, which it is (only live handles can leak).
    address: usize,
    layout: Layout,
    key: Key,
}

#[derive(Default)]
struct Registry {
    live: HashSet<Key>,
    /// The keys of the held-back handles (a handle is in `live` or here, not both).
    freed: HashSet<Key>,
    /// The held-back memory, oldest first; once [`HW_FREED_ADDRESSES_KEPT`] long, each new entry
    /// releases the oldest.
    held_back: VecDeque<Tombstone>,
}

static REGISTRY: Mutex<Option<Registry>> = Mutex::new(None);

/// Handles are registered by a scrambled address, not the address itself: a leak checker
/// (LeakSanitizer, valgrind) scanning this set must not mistake it for a reference that keeps a
/// leaked object alive.
fn key<T: 'static>(ptr: *mut T) -> Key {
    const SCRAMBLE: usize = 0xA5A5_A5A5_A5A5_A5A5_u64 as usize;
    (ptr as usize ^ SCRAMBLE, TypeId::of::<T>())
}

fn with_registry<R>(f: impl FnOnce(&mut Registry) -> R) -> R {
    // A poisoned lock only means another thread panicked while holding it; the registry is still
    // sound (no operation on it can panic half-way but an allocation failure, which aborts).
    let mut guard = REGISTRY
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    f(guard.get_or_insert_with(Registry::default))
}

/// Gives `value` to C as an owning handle.
pub(crate) fn into_handle<T: 'static>(value: T) -> *mut T {
    let ptr = Box::into_raw(Box::new(value));
    with_registry(|registry| registry.live.insert(key(ptr)));
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
    let key = key(ptr);
    let was_live = with_registry(|registry| {
        let was_live = registry.live.remove(&key);
        if was_live {
            registry.freed.insert(key);
        }
        was_live
    });
    if !was_live {
        let freed = with_registry(|registry| registry.freed.contains(&key));
        return Err(FfiError::invalid_handle(if freed {
            format!("{type_name}_free: {ptr:p} was already freed")
        } else {
            format!(
                "{type_name}_free: {ptr:p} is not a live {type_name} (never created, or freed \
                 {HW_FREED_ADDRESSES_KEPT} or more frees ago)"
            )
        }));
    }
    // SAFETY: the pointer came from `into_handle::<T>` and was still registered, so it is a live,
    // uniquely owned box; it is now in `freed`, so no other `_free` drops it again.
    unsafe { std::ptr::drop_in_place(ptr) };
    // Zeroed so that the held-back memory keeps no stale pointer a leak checker could take for a
    // reference to another allocation.
    // SAFETY: `ptr` is valid for writes of one `T`, and `T` is dropped.
    unsafe { ptr.cast::<u8>().write_bytes(0, size_of::<T>()) };
    let released = with_registry(|registry| {
        registry.held_back.push_back(Tombstone {
            address: ptr as usize,
            layout: Layout::new::<T>(),
            key,
        });
        let oldest = (registry.held_back.len() > HW_FREED_ADDRESSES_KEPT)
            .then(|| registry.held_back.pop_front())
            .flatten()?;
        registry.freed.remove(&oldest.key);
        Some(oldest)
    });
    if let Some(oldest) = released.filter(|oldest| oldest.layout.size() != 0) {
        // SAFETY: the memory of a `Box` of a type with this layout (a zero-sized one has none),
        // whose value was dropped; it left the registry, so nothing else releases it.
        unsafe { std::alloc::dealloc(oldest.address as *mut u8, oldest.layout) };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::boundary::status::HW_ERR_INVALID_HANDLE;

    /// A handle type of its own, so that other tests' handles never share its keys.
    struct Probe(#[allow(dead_code)] [u64; 8]);

    /// Taken by the tests that free many handles and those that count on a freed address staying
    /// held back, which the former would release.
    static MANY_FREES: Mutex<()> = Mutex::new(());

    fn serial() -> std::sync::MutexGuard<'static, ()> {
        MANY_FREES
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    #[test]
    fn a_stale_handle_is_refused_after_a_new_handle_is_made() {
        // Before: the allocator gave the freed address to the next object, and freeing the stale
        // pointer again silently freed that object.
        let _serial = serial();
        let first = into_handle(Probe([1; 8]));
        unsafe { free_handle(first, "probe") }.unwrap();
        let second = into_handle(Probe([2; 8]));
        assert_ne!(second, first, "a freed handle's address was reused at once");
        let error = unsafe { free_handle(first, "probe") }.unwrap_err();
        assert_eq!(error.status, HW_ERR_INVALID_HANDLE);
        assert!(
            error.message.contains("was already freed"),
            "{}",
            error.message
        );
        // The new object is still live: it frees once, then is refused.
        unsafe { free_handle(second, "probe") }.unwrap();
        assert!(unsafe { free_handle(second, "probe") }.is_err());
    }

    #[test]
    fn held_back_memory_stays_within_its_window() {
        let _serial = serial();
        for _ in 0..HW_FREED_ADDRESSES_KEPT + 10 {
            unsafe { free_handle(into_handle(Probe([3; 8])), "probe") }.unwrap();
        }
        let held_back = with_registry(|registry| registry.held_back.len());
        assert_eq!(held_back, HW_FREED_ADDRESSES_KEPT);
    }

    #[test]
    fn held_back_objects_fit_the_documented_two_megabytes() {
        use crate::ffi::*;
        let largest = [
            size_of::<hw_mesh>(),
            size_of::<hw_diagnostic>(),
            size_of::<hw_index_maps>(),
            size_of::<hw_soup>(),
            size_of::<hw_voronoi>(),
            size_of::<hw_voronoi_cells>(),
            size_of::<hw_winged>(),
            size_of::<hw_render_buffers>(),
        ]
        .into_iter()
        .max()
        .unwrap();
        assert!(
            largest * HW_FREED_ADDRESSES_KEPT <= 2 << 20,
            "{largest} bytes"
        );
    }

    #[test]
    fn pointers_that_are_not_handles_are_refused() {
        let mut not_a_handle = Probe([0; 8]);
        let error = unsafe { free_handle(&raw mut not_a_handle, "probe") }.unwrap_err();
        assert!(
            error.message.contains("is not a live probe"),
            "{}",
            error.message
        );
        assert!(unsafe { free_handle(std::ptr::null_mut::<Probe>(), "probe") }.is_ok());
    }
}
