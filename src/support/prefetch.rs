//! A hint to the processor to start loading an item that will be read soon, for passes that
//! gather through an index array (whose future indices are known) faster than memory answers.

/// Starts loading the cache line of `item` into every cache level. Only a hint: it never faults
/// and changes nothing but timing (a no-op on other architectures).
#[inline(always)]
pub(crate) fn prefetch<T>(item: &T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch reads no data the program sees and cannot fault; the address is a live
    // reference's.
    unsafe {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        _mm_prefetch::<_MM_HINT_T0>((item as *const T).cast());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = item;
}
