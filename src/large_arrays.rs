//! Allocation of the large arrays that bulk construction fills (tens of MB for a million faces).
//!
//! A freshly allocated array costs a page fault per 4 KiB page on first touch, which was the
//! largest single cost of a cold bulk build. On Linux these arrays ask for transparent huge pages
//! before they are touched (`madvise(MADV_HUGEPAGE)`; systems in THP "madvise" mode only give
//! them on request), so the kernel faults in 2 MiB at a time.
//!
//! A huge page can only back a whole aligned 2 MiB of one mapping, so the arrays are also sized
//! for aligned mappings: glibc maps a large block on its own behind a header of a few bytes, and
//! Linux aligns an anonymous mapping whose length is a multiple of 2 MiB. Such an array starts
//! just past a huge-page boundary and ends just before one; its last huge page is advised as a
//! whole, and its first, where the allocator's header write has already put a small page, is
//! collapsed into a huge page (`MADV_COLLAPSE`) before the array is touched. The slack at the end
//! (under 2 MiB) is returned by [`fit`] once an array that is kept has its final length. Where
//! advice, collapse or alignment is not available, the arrays are ordinary `Vec`s and nothing
//! changes but speed.

/// Arrays smaller than this are not worth a system call (and rarely span a whole huge page).
const ADVICE_THRESHOLD_BYTES: usize = 2 << 20;
const HUGE_PAGE: usize = 2 << 20;
/// Room for the allocator's header in a block sized to end just before a huge-page boundary.
const HEADER_ROOM: usize = 4096;

/// `len` zeros, for arrays whose zeros mean something (counts, empty slots). For integers the
/// standard library takes zeroed memory from the allocator (`calloc`), so fresh pages are not
/// written twice; the advice comes before the first touch.
pub(crate) fn zeroed<T: Copy + Default>(len: usize) -> Vec<T> {
    zeroed_reusable::<T, T>(len, 0)
}

/// `len` zeros in a block that can hold `later` items of `U` once the zeros are spent (see
/// [`reused_as`]): a temporary array whose pages, already faulted in, then take a kept array
/// instead of fresh ones.
pub(crate) fn zeroed_reusable<T: Copy + Default, U>(len: usize, later: usize) -> Vec<T> {
    let mut array = vec![T::default(); reusable_capacity::<T, U>(len, later)];
    advise_huge_pages(array.as_ptr().cast(), array.len() * size_of::<T>());
    array.truncate(len);
    array
}

/// A copy of `items` in the block of `spent` (whose contents are dropped) when that block has
/// the room and suits `U`'s layout, as the blocks of [`zeroed_reusable`] do; in a new block
/// otherwise.
pub(crate) fn copied_into<T, U: Copy>(spent: Vec<T>, items: &[U]) -> Vec<U> {
    let mut array = reused_as::<T, U>(spent).unwrap_or_default();
    if array.capacity() < items.len() {
        array = with_capacity(items.len());
    }
    array.extend_from_slice(items);
    array
}

/// The block of `array`, emptied, as an empty `Vec<U>`: `None` unless `U` has `T`'s alignment
/// and the block's size is a whole number of `U`s (the layout a `Vec<U>` must free it with).
fn reused_as<T, U>(mut array: Vec<T>) -> Option<Vec<U>> {
    let bytes = array.capacity().checked_mul(size_of::<T>())?;
    if align_of::<T>() != align_of::<U>() || size_of::<U>() == 0 || bytes % size_of::<U>() != 0 {
        return None;
    }
    array.clear();
    let mut array = std::mem::ManuallyDrop::new(array);
    // SAFETY: the block was allocated by the global allocator with `T`'s alignment, which is
    // `U`'s, and `bytes` of size, which is `bytes / size_of::<U>()` items of `U`; the `Vec<T>`
    // is emptied and forgotten, so the block has one owner, which holds no item yet.
    Some(unsafe { Vec::from_raw_parts(array.as_mut_ptr().cast::<U>(), 0, bytes / size_of::<U>()) })
}

/// `len` copies of `value`.
pub(crate) fn filled<T: Copy>(len: usize, value: T) -> Vec<T> {
    let mut array = with_capacity(len);
    array.resize(len, value);
    array
}

/// An empty array with room for `capacity` items, for arrays built by pushing.
pub(crate) fn with_capacity<T>(capacity: usize) -> Vec<T> {
    let array: Vec<T> = Vec::with_capacity(huge_page_capacity::<T>(capacity));
    advise_huge_pages(array.as_ptr().cast(), array.capacity() * size_of::<T>());
    array
}

/// A copy of `items`.
pub(crate) fn copied<T: Copy>(items: &[T]) -> Vec<T> {
    let mut array = with_capacity(items.len());
    array.extend_from_slice(items);
    array
}

/// `array` truncated to `len` with its spare capacity returned (for glibc's mapped blocks a
/// `mremap` in place: nothing is copied, and pages never touched were never faulted in).
pub(crate) fn fit<T>(mut array: Vec<T>, len: usize) -> Vec<T> {
    array.truncate(len);
    array.shrink_to_fit();
    array
}

/// A capacity of at least `len` items of `T`, and room for `later` items of `U`, in a block
/// that is a whole number of `U`s (so [`reused_as`] takes it) and, for large arrays, of huge
/// pages with the allocator's header, like [`huge_page_capacity`]'s (less than one `U` short of
/// that: the header's room absorbs it).
fn reusable_capacity<T, U>(len: usize, later: usize) -> usize {
    let (t, u) = (size_of::<T>(), size_of::<U>());
    if t == 0 || u == 0 || align_of::<T>() != align_of::<U>() {
        return huge_page_capacity::<T>(len);
    }
    let needed = len.max(later.saturating_mul(u).div_ceil(t));
    // Items of `T` per whole number of `U`s: lcm(t, u) / t.
    let step = u / gcd(t, u);
    let capacity = huge_page_capacity::<T>(needed.saturating_add(step - 1));
    capacity - capacity % step
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 { a } else { gcd(b, a % b) }
}

/// A capacity of at least `len` whose block, with the allocator's header, is a whole number of
/// huge pages, for arrays large enough to be advised.
fn huge_page_capacity<T>(len: usize) -> usize {
    let bytes = len.saturating_mul(size_of::<T>());
    if bytes < ADVICE_THRESHOLD_BYTES || size_of::<T>() == 0 {
        return len;
    }
    match bytes
        .checked_add(HEADER_ROOM)
        .and_then(|b| b.checked_next_multiple_of(HUGE_PAGE))
    {
        Some(rounded) => ((rounded - HEADER_ROOM) / size_of::<T>()).max(len),
        None => len,
    }
}

/// Advises the kernel to back `[start, start + bytes)` with huge pages: all of it when it is a
/// mapping of its own (only a header before it in its first huge page, nothing after it in its
/// last), else the whole huge pages inside it. Only hints: failures are ignored, and contents
/// never change.
#[cfg(target_os = "linux")]
fn advise_huge_pages(start: *const u8, bytes: usize) {
    if bytes < ADVICE_THRESHOLD_BYTES {
        return;
    }
    let (start, end) = (start as usize, start as usize + bytes);
    let (page_start, page_end) = (start & !(HUGE_PAGE - 1), end.next_multiple_of(HUGE_PAGE));
    let own_mapping = start - page_start < HEADER_ROOM && page_end - end < HEADER_ROOM;
    let advise = |first: usize, end: usize, advice: libc::c_int| {
        if end > first {
            // SAFETY: MADV_HUGEPAGE and MADV_COLLAPSE change how pages are backed, never their
            // contents or validity; the range is the array's memory, plus, for a mapping of its
            // own, the allocator's header and the few bytes after the array in that mapping.
            unsafe {
                libc::madvise(first as *mut libc::c_void, end - first, advice);
            }
        }
    };
    if own_mapping {
        advise(page_start, page_end, libc::MADV_HUGEPAGE);
        advise(page_start, page_start + HUGE_PAGE, libc::MADV_COLLAPSE);
    } else {
        advise(
            start.next_multiple_of(HUGE_PAGE),
            end & !(HUGE_PAGE - 1),
            libc::MADV_HUGEPAGE,
        );
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge_pages(_start: *const u8, _bytes: usize) {
    let _ = (ADVICE_THRESHOLD_BYTES, HUGE_PAGE, HEADER_ROOM);
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
            let room = with_capacity::<u16>(len);
            assert!(room.is_empty() && room.capacity() >= len);
            let fitted = fit(zeroed::<u32>(len + 10), len);
            assert!(fitted.len() == len && fitted.capacity() == len);
        }
    }

    #[test]
    fn reusable_blocks_take_the_later_array_in_place() {
        for (len, later) in [
            (0, 0),
            (5, 0),
            (10, 7),
            (1000, 3000),
            (1 << 16, 1 << 20),
            (3 << 20, 1 << 20),
        ] {
            let zeros = zeroed_reusable::<u64, [f64; 3]>(len, later);
            assert!(zeros.len() == len && zeros.iter().all(|&x| x == 0));
            let bytes = zeros.capacity() * 8;
            assert!(bytes.is_multiple_of(24) && bytes >= later * 24 && zeros.capacity() >= len);
            if bytes >= ADVICE_THRESHOLD_BYTES {
                // Whole huge pages with the header, less than one position short.
                let block = bytes + HEADER_ROOM;
                assert!(
                    block.next_multiple_of(HUGE_PAGE) - block < 24,
                    "{len} {later}"
                );
            }
            let block = zeros.as_ptr() as usize;
            let items: Vec<[f64; 3]> = (0..later).map(|i| [i as f64; 3]).collect();
            let copy = copied_into(zeros, &items);
            assert_eq!(copy, items);
            if later > 0 {
                assert_eq!(copy.as_ptr() as usize, block);
            }
        }
        // Too small a block, or one of another alignment or size: the copy is made elsewhere.
        let positions = [[1.0, 2.0, 3.0]; 4];
        for spent in [zeroed_reusable::<u64, [f64; 3]>(1, 1), vec![0u64; 2]] {
            assert_eq!(copied_into(spent, &positions), positions);
        }
        assert_eq!(copied_into(vec![0u32; 30], &positions), positions);
    }

    #[test]
    fn large_capacities_fill_whole_huge_pages_and_small_ones_are_exact() {
        assert_eq!(huge_page_capacity::<u32>(1000), 1000);
        for len in [1 << 20, 3 << 20, (5 << 20) + 7] {
            let capacity = huge_page_capacity::<u32>(len);
            assert!(capacity >= len);
            assert_eq!((capacity * 4 + HEADER_ROOM) % HUGE_PAGE, 0);
            assert!(capacity * 4 - len * 4 < HUGE_PAGE);
        }
        assert_eq!(huge_page_capacity::<u64>(usize::MAX), usize::MAX);
    }
}
