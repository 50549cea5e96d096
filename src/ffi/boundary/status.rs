//! Status codes returned by every fallible C function.

use std::ffi::c_char;

/// The result of a fallible C call. `HW_OK` (0) is success; every other value is an error whose
/// details `hw_last_error_message` gives.
///
/// A plain integer type with named constants, not a Rust enum, so that a value coming back from C
/// (as in `hw_status_str`) can never be an invalid enum discriminant. Every other enumeration's
/// constants start with its type's name (`hw_normal_weighting`: `HW_NORMAL_WEIGHTING_*`); status
/// codes keep the short `HW_OK` / `HW_ERR_*` that C libraries give them, success told from
/// failure at a glance.
/// \ingroup errors
#[allow(non_camel_case_types)]
pub type hw_status = u32;

/// Success.
/// \ingroup errors
pub const HW_OK: hw_status = 0;
/// A required pointer argument was NULL.
/// \ingroup errors
pub const HW_ERR_NULL_ARGUMENT: hw_status = 1;
/// An element id (vertex, half-edge, edge, face) is out of range or deleted, or an object handle
/// was already freed.
/// \ingroup errors
pub const HW_ERR_INVALID_HANDLE: hw_status = 2;
/// The input data are malformed: bad sizes or counts, indices out of range, NaN or infinite
/// coordinates, an unknown enum value.
/// \ingroup errors
pub const HW_ERR_INVALID_INPUT: hw_status = 3;
/// The input is not a manifold and the chosen policy refuses it.
/// \ingroup errors
pub const HW_ERR_NON_MANIFOLD: hw_status = 4;
/// A caller's buffer is too small; the needed size was reported.
/// \ingroup errors
pub const HW_ERR_BUFFER_TOO_SMALL: hw_status = 5;
/// Reading or writing a file failed.
/// \ingroup errors
pub const HW_ERR_IO: hw_status = 6;
/// A file's contents could not be parsed.
/// \ingroup errors
pub const HW_ERR_PARSE: hw_status = 7;
/// A mesh operation's precondition does not hold (e.g. flipping a boundary edge); nothing changed.
/// \ingroup errors
pub const HW_ERR_REFUSED: hw_status = 8;
/// A Rust panic was caught at the C boundary: a bug in halfwing. The object passed in is left
/// as it was before the call only if the call does not mutate it.
/// \ingroup errors
pub const HW_ERR_PANIC: hw_status = 9;
/// A named item (an attribute) does not exist.
/// \ingroup errors
pub const HW_ERR_NOT_FOUND: hw_status = 10;
/// The system refused memory the call needed (an array proportional to a count given: cells,
/// pixels, vertices); the message names the size. Nothing was changed, and calls needing less
/// memory still work.
/// \ingroup errors
pub const HW_ERR_OUT_OF_MEMORY: hw_status = 11;

/// Static text for every status.
const STATUS_TEXT: [&str; 12] = [
    "ok\0",
    "a required pointer argument was NULL\0",
    "invalid or deleted handle\0",
    "invalid input\0",
    "non-manifold input refused\0",
    "buffer too small\0",
    "I/O error\0",
    "parse error\0",
    "operation refused: precondition does not hold\0",
    "internal error (panic caught at the C boundary)\0",
    "not found\0",
    "out of memory\0",
];

/// A short, static, NUL-terminated English description of `status`. Unknown values give
/// `"unknown status"`. Never returns NULL; the string must not be freed.
/// \ingroup errors
#[unsafe(no_mangle)]
pub extern "C" fn hw_status_str(status: hw_status) -> *const c_char {
    let text = STATUS_TEXT
        .get(status as usize)
        .copied()
        .unwrap_or("unknown status\0");
    text.as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::CStr;

    #[test]
    fn every_status_has_text_and_unknown_values_are_safe() {
        for status in HW_OK..=HW_ERR_OUT_OF_MEMORY {
            let text = unsafe { CStr::from_ptr(hw_status_str(status)) };
            assert!(!text.to_bytes().is_empty());
        }
        let unknown = unsafe { CStr::from_ptr(hw_status_str(u32::MAX)) };
        assert_eq!(unknown.to_str().unwrap(), "unknown status");
    }
}
