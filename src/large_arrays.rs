//! Allocation of the large arrays that bulk construction fills (tens of MB for a million faces).
//!
//! A freshly allocated array costs a page fault per 4 KiB page on first touch, which is about half
//! the time of a cold bulk build. On Linux these arrays ask for transparent huge pages before they
//! are touched (`madvise(MADV_HUGEPAGE)`; systems in THP "madvise" mode only give them on
//! request), so the kernel faults in 2 MiB at a time. Where the advice is not available or not
//! taken, the arrays are ordinary `Vec`s and nothing changes but speed.

/// Arrays smaller than this are not worth a system call (and rarely span a whole huge page).
const ADVICE_THRESHOLD_BYTES: usize = 2 << 20;

/// `len` zeros, for arrays every slot of which is written later. For integers the standard
/// library takes zeroed memory from the allocator (`calloc`), so fresh pages are not written
/// twice; the advice comes before the first touch.
pub(crate) fn zeroed<T: Copy + Default>(len: usize) -> Vec<T> {
    let array = vec![T::default(); len];
    advise_huge_pages(array.as_ptr().cast(), len * size_of::<T>());
    array
}

/// `len` copies of `value`.
pub(crate) fn filled<T: Copy>(len: usize, value: T) -> Vec<T> {
    let mut array: Vec<T> = Vec::with_capacity(len);
    advise_huge_pages(array.as_ptr().cast(), len * size_of::<T>());
    array.resize(len, value);
    array
}

/// An empty array with room for `capacity` items, for arrays built by pushing.
pub(crate) fn with_capacity<T>(capacity: usize) -> Vec<T> {
    let array: Vec<T> = Vec::with_capacity(capacity);
    advise_huge_pages(array.as_ptr().cast(), capacity * size_of::<T>());
    array
}

/// A copy of `items`.
pub(crate) fn copied<T: Copy>(items: &[T]) -> Vec<T> {
    let mut array: Vec<T> = Vec::with_capacity(items.len());
    advise_huge_pages(array.as_ptr().cast(), std::mem::size_of_val(items));
    array.extend_from_slice(items);
    array
}

/// Advises the kernel to back the whole 2 MiB pages inside `[start, start + bytes)` with huge
/// pages. Only a hint: failure is ignored.
#[cfg(target_os = "linux")]
fn advise_huge_pages(start: *const u8, bytes: usize) {
    const HUGE_PAGE: usize = 2 << 20;
    if bytes < ADVICE_THRESHOLD_BYTES {
        return;
    }
    let first = (start as usize).next_multiple_of(HUGE_PAGE);
    let end = (start as usize + bytes) & !(HUGE_PAGE - 1);
    if end > first {
        // SAFETY: the range lies inside one live allocation of ours; MADV_HUGEPAGE changes how
        // pages are backed, never their contents or validity.
        unsafe {
            libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge_pages(_start: *const u8, _bytes: usize) {
    let _ = ADVICE_THRESHOLD_BYTES;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_hold_what_was_asked_at_every_size() {
        for len in [0, 1, 1000, 3 << 20] {
            let zeros = zeroed::<u32>(len);
            assert!(zeros.len() == len && zeros.iter().all(|&x| x == 0));
            let sevens = filled(len, 7u64);
            assert!(sevens.len() == len && sevens.iter().all(|&x| x == 7));
            assert_eq!(copied(&sevens), sevens);
            let room = with_capacity::<u64>(len);
            assert!(room.is_empty() && room.capacity() >= len);
        }
    }
}
