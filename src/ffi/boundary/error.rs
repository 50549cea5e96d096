//! The error type of the C boundary and the thread-local "last error" message.

use std::cell::RefCell;
use std::ffi::c_char;

use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{copy_text, drop_payload};

/// A failure inside an exported function: the status to return and the message to record.
/// \ingroup errors
#[derive(Debug, Clone)]
pub struct FfiError {
    pub status: hw_status,
    pub message: String,
}

impl FfiError {
    pub fn new(status: hw_status, message: impl Into<String>) -> Self {
        FfiError {
            status,
            message: message.into(),
        }
    }

    pub fn null_argument(name: &str) -> Self {
        Self::new(HW_ERR_NULL_ARGUMENT, format!("argument `{name}` is NULL"))
    }

    pub fn invalid_input(message: impl Into<String>) -> Self {
        Self::new(HW_ERR_INVALID_INPUT, message)
    }

    pub fn out_of_memory(refusal: crate::OutOfMemory) -> Self {
        Self::new(HW_ERR_OUT_OF_MEMORY, refusal.to_string())
    }

    pub fn invalid_handle(message: impl Into<String>) -> Self {
        Self::new(HW_ERR_INVALID_HANDLE, message)
    }
}

impl From<crate::OutOfMemory> for FfiError {
    fn from(refusal: crate::OutOfMemory) -> Self {
        FfiError::out_of_memory(refusal)
    }
}

/// The largest message halfwing gives C, in bytes with its terminating NUL: the last-error
/// message (hw_last_error_message()) and a diagnostic's summary (hw_diagnostic_summary()) never
/// need more, so a buffer of this size always takes them. Lists of elements in a message name the
/// first few and count the rest, so a message reaches this size only when it quotes a very long
/// string of the caller's (an attribute name, a path); it is then cut, and ends with
/// `… (cut)`.
/// \ingroup errors
pub const HW_MAX_MESSAGE_SIZE: usize = 8192;

/// What ends a message cut to [`HW_MAX_MESSAGE_SIZE`].
const CUT_MARK: &str = "… (cut)";

/// Replaces the contents of `out` with `message` as C is to read it: each NUL (which would end
/// the C string early) shown as U+FFFD, and the whole cut to fit [`HW_MAX_MESSAGE_SIZE`] with its
/// terminator, at a character boundary, ending with [`CUT_MARK`].
pub(crate) fn write_c_message(out: &mut String, message: &str) {
    const SHOWN_NUL: char = '\u{FFFD}';
    let shown = |c: char| if c == '\0' { SHOWN_NUL } else { c };
    let capacity = HW_MAX_MESSAGE_SIZE - 1;
    let nul_growth = SHOWN_NUL.len_utf8() - 1;
    let full_len = message.len() + message.bytes().filter(|&b| b == 0).count() * nul_growth;
    out.clear();
    if full_len <= capacity {
        out.extend(message.chars().map(shown));
        return;
    }
    let room = capacity - CUT_MARK.len();
    for c in message.chars().map(shown) {
        if out.len() + c.len_utf8() > room {
            break;
        }
        out.push(c);
    }
    out.push_str(CUT_MARK);
}

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Records `error` as this thread's last error and returns its status.
///
/// Runs outside `catch_unwind` (it reports what the guard caught), so it must not panic: a call
/// made from a thread-local destructor (a pthread key's, a C++ `thread_local`'s) after this
/// thread's own storage is gone still returns its status, and only the message is lost.
pub(crate) fn record(error: FfiError) -> hw_status {
    let _ = LAST_ERROR.try_with(|last| {
        let Ok(mut last) = last.try_borrow_mut() else {
            return;
        };
        write_c_message(&mut last, &error.message);
    });
    error.status
}

/// Copies the message of the last failed call on this thread into `out_text`, NUL-terminated.
///
/// `*out_needed` (when `out_needed` is not NULL) always receives the size the message needs,
/// terminator included — also when the buffer is too small, so a caller can allocate and call
/// again; it is never more than ::HW_MAX_MESSAGE_SIZE, so a buffer of that size always suffices.
/// The message is empty (`out_needed` = 1) when no call has failed on this thread yet. Successful
/// calls do not clear it, and neither does this function, so it can be read as often as wanted.
/// Calls made from a thread-local destructor after this thread's storage is torn down still return
/// their status, but record no message (it reads empty).
///
/// Returns `HW_OK`, or `HW_ERR_BUFFER_TOO_SMALL` when `out_text` is NULL or `capacity` is less than
/// the size needed (nothing is written to `out_text` then).
///
/// # Safety
/// `out_text` must be NULL or point to `capacity` writable bytes; `out_needed` must be NULL or
/// point to a writable `size_t`.
/// \ingroup errors
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_last_error_message(
    out_text: *mut c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    // Not through `guard`: reading the last error must not overwrite it.
    let result = crate::ffi::boundary::quiet_panics::catch_quietly(|| {
        // SAFETY: the caller's guarantees are those of `copy_text`.
        let copy = |text: &str| unsafe { copy_text(text, out_text, capacity, out_needed) };
        // Storage already torn down (see `record`): nothing was recorded, the message is empty.
        LAST_ERROR
            .try_with(|last| copy(&last.borrow()))
            .unwrap_or_else(|_| copy(""))
            .map_or_else(|error| error.status, |()| HW_OK)
    });
    result.unwrap_or_else(|payload| {
        drop_payload(payload);
        HW_ERR_PANIC
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::{BuildError, Diagnostic, EdgeReport, ListProblem};

    fn c_message(message: &str) -> String {
        let mut out = String::from("previous message");
        write_c_message(&mut out, message);
        out
    }

    #[test]
    fn a_message_that_fits_is_kept_whole_with_nuls_shown() {
        assert_eq!(c_message("face 3"), "face 3");
        assert_eq!(c_message("a\0b"), "a\u{FFFD}b");
        let longest = "x".repeat(HW_MAX_MESSAGE_SIZE - 1);
        assert_eq!(c_message(&longest), longest);
    }

    #[test]
    fn a_longer_message_is_cut_at_a_character_boundary() {
        // Before: a message was recorded whole, however long (a 10 MB attribute name made a
        // 10 MB message).
        for message in [
            "x".repeat(HW_MAX_MESSAGE_SIZE),
            "é".repeat(10 * HW_MAX_MESSAGE_SIZE),
            "\0".repeat(HW_MAX_MESSAGE_SIZE / 2),
        ] {
            let cut = c_message(&message);
            assert!(cut.len() < HW_MAX_MESSAGE_SIZE, "{} bytes", cut.len());
            assert!(cut.len() > HW_MAX_MESSAGE_SIZE - 8, "{} bytes", cut.len());
            assert!(cut.ends_with(CUT_MARK));
        }
    }

    /// How many elements of a list the summary shows (checked below: one more is counted).
    const SHOWN: usize = 8;

    #[test]
    fn the_longest_summary_fits_uncut_in_the_longest_message_carrying_it() {
        // Every list of the diagnostic one longer than the summary shows, with the longest ids.
        let ids = vec![u32::MAX - 1; SHOWN + 1];
        let edges = vec![
            EdgeReport {
                vertices: [u32::MAX - 2, u32::MAX - 1],
                faces: ids.clone(),
            };
            SHOWN + 1
        ];
        let diagnostic = Diagnostic {
            list_problem: Some(ListProblem::CornerAttributeMismatch {
                what: "corner normals",
                expected: u64::MAX,
                actual: u64::MAX,
            }),
            faces_too_small: ids.clone(),
            faces_out_of_range: ids.clone(),
            faces_repeated_vertex: ids.clone(),
            non_finite_vertices: ids.clone(),
            non_manifold_edges: edges.clone(),
            inconsistent_edges: edges,
            non_manifold_vertices: ids.clone(),
            isolated_vertices: ids.clone(),
            degenerate_faces: ids.clone(),
            skipped_faces: ids.clone(),
            reoriented_faces: ids.clone(),
            vertex_copies: ids,
        };
        let message = BuildError::NonManifold(Box::new(diagnostic)).to_string();
        // The counts here have 1 digit; a real list has up to 10 (ids are 32-bit). A count
        // starts each of the 12 lists and ends each of them and each of the 16 edges shown.
        const COUNTS: usize = 12 * 2 + 16;
        let longest = message.len() + COUNTS * 9;
        assert!(longest < HW_MAX_MESSAGE_SIZE, "{longest} bytes:\n{message}");
        assert!(message.contains("… and 1 more)"), "{message}");
        assert_eq!(c_message(&message), message);
    }
}
