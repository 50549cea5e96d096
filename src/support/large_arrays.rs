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
//!
//! Arrays too small for huge pages (a 100k-face model's) still fault in 4 KiB at a time, and
//! there the trap per page, more than the page itself, was about a third of a cold build (its
//! system time). So the part of such an array that is sure to be written is faulted in up front,
//! by one `madvise(MADV_POPULATE_WRITE)` (see [`populate`]); pages that may stay unused are left
//! to fault in on first touch, if ever.

/// Arrays smaller than this are not worth a system call (and rarely span a whole huge page).
const ADVICE_THRESHOLD_BYTES: usize = 2 << 20;
const HUGE_PAGE: usize = 2 << 20;
/// Room for the allocator's header in a block sized to end just before a huge-page boundary.
const HEADER_ROOM: usize = 4096;
/// Parts smaller than this are not worth a system call to fault in (see [`populate`]).
const POPULATE_THRESHOLD_BYTES: usize = 64 << 10;

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
    let bytes = array.len() * size_of::<T>();
    advise_huge_pages(array.as_ptr().cast(), bytes);
    // The zeros are written, or the later array fills the rest of the block.
    populate(array.as_ptr().cast(), bytes, bytes);
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
    let mut array = with_capacity_written(len, len);
    array.resize(len, value);
    array
}

/// An empty array with room for `capacity` items, for arrays built by pushing.
pub(crate) fn with_capacity<T>(capacity: usize) -> Vec<T> {
    with_capacity_written(capacity, 0)
}

/// [`with_capacity`] for an array whose first `written` items (at most `capacity`) are sure
/// to be written: their pages are faulted in now (see [`populate`]).
pub(crate) fn with_capacity_written<T>(capacity: usize, written: usize) -> Vec<T> {
    let array: Vec<T> = Vec::with_capacity(huge_page_capacity::<T>(capacity));
    let bytes = array.capacity() * size_of::<T>();
    advise_huge_pages(array.as_ptr().cast(), bytes);
    populate(
        array.as_ptr().cast(),
        written.min(capacity) * size_of::<T>(),
        bytes,
    );
    array
}

/// A copy of `items`.
pub(crate) fn copied<T: Copy>(items: &[T]) -> Vec<T> {
    let mut array = with_capacity_written(items.len(), items.len());
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

/// Faults in the whole pages of `[start, start + bytes)`, a part of a block of `block_bytes`
/// that is about to be written, in one system call: the kernel's loop instead of a trap per
/// page (cold memory, one thread, best of 150 builds, six rounds taking turns: armadillo, 86k
/// faces, 7.97-8.34 → 7.25-7.78 ms; the open bunny, 69k, 5.45-6.15 → 4.79-5.10 ms). Only for
/// blocks left to small pages ([`advise_huge_pages`] gives larger ones few faults anyway) and
/// parts worth the call. A hint like the advice: failures (kernels before Linux 5.14) are
/// ignored, and the pages then fault in on first touch as before.
#[cfg(target_os = "linux")]
fn populate(start: *const u8, bytes: usize, block_bytes: usize) {
    if bytes < POPULATE_THRESHOLD_BYTES || block_bytes >= ADVICE_THRESHOLD_BYTES {
        return;
    }
    // SAFETY: sysconf only reads a system setting.
    let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) }).unwrap_or(0);
    if !page.is_power_of_two() {
        return;
    }
    let (first, end) = (
        (start as usize).next_multiple_of(page),
        (start as usize + bytes) & !(page - 1),
    );
    if end <= first {
        return;
    }
    // A block the allocator reuses is resident already, and walking its pages would only cost
    // time (armadillo on a reused heap: 5.4-5.7 → 5.7-6.1 ms); a page from the middle of the part
    // tells (the allocator's header write has touched the first page of even a fresh block).
    let middle = (first + (end - first) / 2) & !(page - 1);
    let mut resident = 0u8;
    // SAFETY: one page of the block, and one byte to write its state into.
    let asked = unsafe { libc::mincore(middle as *mut libc::c_void, page, &mut resident) };
    if asked == 0 && resident & 1 == 0 {
        // SAFETY: MADV_POPULATE_WRITE only faults in pages of the range as writable, without
        // writing them; the range lies inside the block, which is this process's own memory.
        unsafe {
            libc::madvise(
                first as *mut libc::c_void,
                end - first,
                libc::MADV_POPULATE_WRITE,
            );
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn populate(_start: *const u8, _bytes: usize, _block_bytes: usize) {
    let _ = POPULATE_THRESHOLD_BYTES;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_hold_what_was_asked_at_every_size() {
        // Below the threshold of faulting in, between it and huge pages, and huge pages.
        for len in [0, 1, 1000, 100_000, 3 << 20] {
            let zeros = zeroed::<u32>(len);
            assert!(zeros.len() == len && zeros.iter().all(|&x| x == 0));
            let sevens = filled(len, 7u64);
            assert!(sevens.len() == len && sevens.iter().all(|&x| x == 7));
            assert_eq!(copied(&sevens), sevens);
            let room = with_capacity::<u16>(len);
            assert!(room.is_empty() && room.capacity() >= len);
            let mut room = with_capacity_written::<u16>(len, len / 2);
            assert!(room.is_empty() && room.capacity() >= len);
            room.extend((0..len).map(|i| i as u16));
            assert!(room.iter().enumerate().all(|(i, &x)| x == i as u16));
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

    /// On a fresh mapping of small pages, [`populate`] faults in the whole pages of the part it
    /// is given and nothing after it (where the kernel can: Linux 5.14 and later); on one whose
    /// middle page is resident already, as in a block the allocator reuses, it does nothing.
    #[cfg(target_os = "linux")]
    #[test]
    fn populate_faults_in_the_part_given_of_fresh_memory_only() {
        // SAFETY: sysconf only reads a system setting.
        let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) }).unwrap();
        let (block_bytes, part) = (1 << 20, 1 << 19);
        let resident_pages = |start: *mut u8, bytes: usize| {
            let mut states = vec![0u8; bytes / page];
            // SAFETY: whole pages of a live mapping, and a byte per page to write to.
            let asked = unsafe { libc::mincore(start.cast(), bytes, states.as_mut_ptr()) };
            assert_eq!(asked, 0);
            states.iter().filter(|&&state| state & 1 != 0).count()
        };
        // SAFETY: a private anonymous mapping of our own, unmapped below.
        let fresh = || unsafe {
            let start = libc::mmap(
                std::ptr::null_mut(),
                block_bytes,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
                -1,
                0,
            );
            assert_ne!(start, libc::MAP_FAILED);
            start.cast::<u8>()
        };
        let start = fresh();
        populate(start, part, block_bytes);
        let populated = resident_pages(start, part);
        if populated > 0 {
            assert_eq!(populated, part / page);
            // SAFETY: inside the mapping.
            assert_eq!(resident_pages(unsafe { start.add(part) }, part), 0);
        }
        let reused = fresh();
        // SAFETY: inside the mapping: its middle page, as a reused block would have it.
        unsafe { reused.add(part / 2).write(1) };
        populate(reused, part, block_bytes);
        assert_eq!(resident_pages(reused, part), 1);
        for mapping in [start, reused] {
            // SAFETY: the mappings made above, no longer used.
            assert_eq!(unsafe { libc::munmap(mapping.cast(), block_bytes) }, 0);
        }
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
