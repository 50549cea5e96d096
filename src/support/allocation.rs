//! Fallible allocation of arrays proportional to a count from the input.
//!
//! A count a caller gives (cells of a grid, pixels of a picture, records a file declares) can ask
//! for more memory than the system has. `Vec::with_capacity` then aborts the process; the arrays
//! such counts size are allocated here instead, and a refusal comes back as [`OutOfMemory`],
//! naming the size and what it was for, which every error type of the crate carries as it is.

use std::fmt;

/// An allocation the system refused: `bytes` for `count` items of `what`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, thiserror::Error)]
#[error("cannot allocate {} for {count} {what}", Bytes(*bytes))]
pub struct OutOfMemory {
    /// The size asked for, in bytes (saturated at `u64::MAX` when it overflows).
    pub bytes: u64,
    /// How many items.
    pub count: u64,
    /// What the items are (plural: "vertices", "pixels").
    pub what: &'static str,
}

impl OutOfMemory {
    /// The refusal of `count` items of `T`.
    pub(crate) fn of<T>(count: usize, what: &'static str) -> Self {
        let bytes = (count as u64).saturating_mul(size_of::<T>() as u64);
        OutOfMemory {
            bytes,
            count: count as u64,
            what,
        }
    }
}

/// A byte count in decimal units with one decimal ("9.6 GB"), exact below a kilobyte.
struct Bytes(u64);

impl fmt::Display for Bytes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const UNITS: [&str; 6] = ["kB", "MB", "GB", "TB", "PB", "EB"];
        if self.0 < 1000 {
            return write!(f, "{} bytes", self.0);
        }
        let mut value = self.0 as f64 / 1000.0;
        let mut unit = 0;
        while value >= 999.95 && unit + 1 < UNITS.len() {
            value /= 1000.0;
            unit += 1;
        }
        write!(f, "{value:.1} {}", UNITS[unit])
    }
}

/// An empty array with room for `count` items of `what`, or the refusal.
pub(crate) fn try_vec_with_capacity<T>(
    count: usize,
    what: &'static str,
) -> Result<Vec<T>, OutOfMemory> {
    let mut array = Vec::new();
    try_reserve(&mut array, count, what)?;
    Ok(array)
}

/// `count` copies of `value` (items of `what`), or the refusal.
pub(crate) fn try_filled<T: Clone>(
    count: usize,
    value: T,
    what: &'static str,
) -> Result<Vec<T>, OutOfMemory> {
    let mut array = try_vec_with_capacity(count, what)?;
    array.resize(count, value);
    Ok(array)
}

/// Room in `array` for `additional` more items of `what` (exactly, as the count is known), or
/// the refusal.
pub(crate) fn try_reserve<T>(
    array: &mut Vec<T>,
    additional: usize,
    what: &'static str,
) -> Result<(), OutOfMemory> {
    array
        .try_reserve_exact(additional)
        .map_err(|_| OutOfMemory::of::<T>(array.len().saturating_add(additional), what))
}

/// Appends `item` to an array that grows one item at a time, as records of a file without
/// declared counts come (items of `what`): growth doubles as `push`'s does, but a refusal comes
/// back instead of aborting.
#[inline]
pub(crate) fn try_push<T>(
    array: &mut Vec<T>,
    item: T,
    what: &'static str,
) -> Result<(), OutOfMemory> {
    if array.len() == array.capacity() {
        array
            .try_reserve(1)
            .map_err(|_| OutOfMemory::of::<T>(array.len().saturating_mul(2).max(1), what))?;
    }
    array.push(item);
    Ok(())
}

/// Working memory smaller than this is not worth asking for ahead (see [`ensure_room`]).
const ROOM_CHECK_THRESHOLD_BYTES: u64 = 64 << 20;

/// Makes sure `bytes` of memory, the most an operation's arrays for `count` items of `what` add
/// up to, can be had before the operation starts, so that it does not stop half way (or abort,
/// in the many arrays of a hand-tuned build that are not allocated here): the block is asked for
/// and given back untouched (no page of it is ever faulted in), a mapping made and unmade.
pub(crate) fn ensure_room(bytes: u64, count: usize, what: &'static str) -> Result<(), OutOfMemory> {
    if bytes < ROOM_CHECK_THRESHOLD_BYTES {
        return Ok(());
    }
    let refusal = OutOfMemory {
        bytes,
        count: count as u64,
        what,
    };
    let bytes = usize::try_from(bytes).map_err(|_| refusal)?;
    Vec::<u8>::new()
        .try_reserve_exact(bytes)
        .map_err(|_| refusal)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_named_in_decimal_units() {
        let refusal = OutOfMemory::of::<[f64; 3]>(400_000_000, "vertices");
        assert_eq!(
            refusal.to_string(),
            "cannot allocate 9.6 GB for 400000000 vertices"
        );
        for (bytes, shown) in [
            (0, "0 bytes"),
            (999, "999 bytes"),
            (1000, "1.0 kB"),
            (1_500_000, "1.5 MB"),
            (999_960_000, "1.0 GB"),
            (u64::MAX, "18.4 EB"),
        ] {
            assert_eq!(Bytes(bytes).to_string(), shown);
        }
    }

    #[test]
    fn an_impossible_size_is_refused_and_a_possible_one_given() {
        let refused = try_vec_with_capacity::<u64>(usize::MAX / 4, "faces").unwrap_err();
        assert_eq!(refused.count, (usize::MAX / 4) as u64);
        assert_eq!(refused.what, "faces");
        assert!(try_filled(usize::MAX / 2, 0u32, "ids").is_err());
        let zeros = try_filled(1000, 0u32, "ids").unwrap();
        assert!(zeros.len() == 1000 && zeros.iter().all(|&x| x == 0));
        let mut room = try_vec_with_capacity::<u8>(10, "bytes").unwrap();
        assert!(room.capacity() >= 10);
        room.push(1);
        let refused = try_reserve(&mut room, usize::MAX, "bytes").unwrap_err();
        assert_eq!(refused.count, u64::MAX);
        assert_eq!(room, [1]);
    }

    #[test]
    fn room_is_checked_for_large_operations_only() {
        assert!(ensure_room(u64::MAX, 7, "faces").is_err());
        // Beyond what a slice may span, so refused whatever the system overcommits.
        assert_eq!(
            ensure_room(u64::MAX - 1, 7, "faces").unwrap_err(),
            OutOfMemory {
                bytes: u64::MAX - 1,
                count: 7,
                what: "faces"
            }
        );
        assert!(ensure_room(1 << 20, 7, "faces").is_ok());
        assert!(ensure_room(256 << 20, 7, "faces").is_ok());
    }
}
