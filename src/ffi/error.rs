//! The error type of the C boundary and the thread-local "last error" message.

use std::cell::RefCell;
use std::ffi::c_char;

use super::boundary::{copy_text, drop_payload};
use super::status::*;

/// A failure inside an exported function: the status to return and the message to record.
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

    pub fn invalid_handle(message: impl Into<String>) -> Self {
        Self::new(HW_ERR_INVALID_HANDLE, message)
    }
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
        last.clear();
        // An interior NUL would cut the C string short: show it instead.
        last.extend(
            error
                .message
                .chars()
                .map(|c| if c == '\0' { '\u{FFFD}' } else { c }),
        );
    });
    error.status
}

/// Copies the message of the last failed call on this thread into `buf`, NUL-terminated.
///
/// `*needed` (when `needed` is not NULL) always receives the size the message needs, terminator
/// included — also when the buffer is too small, so a caller can allocate and call again. The
/// message is empty (`needed` = 1) when no call has failed on this thread yet. Successful calls
/// do not clear it, and neither does this function, so it can be read as often as wanted. Calls
/// made from a thread-local destructor after this thread's storage is torn down still return
/// their status, but record no message (it reads empty).
///
/// Returns `HW_OK`, or `HW_ERR_BUFFER_TOO_SMALL` when `buf` is NULL or `len` is less than the size
/// needed (nothing is written to `buf` then).
///
/// # Safety
/// `buf` must be NULL or point to `len` writable bytes; `needed` must be NULL or point to a
/// writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_last_error_message(
    buf: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> hw_status {
    // Not through `guard`: reading the last error must not overwrite it.
    let result = std::panic::catch_unwind(|| {
        // SAFETY: the caller's guarantees are those of `copy_text`.
        let copy = |text: &str| unsafe { copy_text(text, buf, len, needed) };
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
