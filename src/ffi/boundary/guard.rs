//! The one gate every exported function goes through: panics are caught, errors become a status
//! and a recorded message, and pointer arguments are checked before anything is read or written.
//!
//! The pattern follows rustls-ffi: a fallible body returns `Result<_, FfiError>`; outputs are
//! written only after the whole body has succeeded (see [`Out`]).

use std::any::Any;

use crate::ffi::boundary::error::{FfiError, record};
use crate::ffi::boundary::quiet_panics::{catch_quietly, last_panic_location};
use crate::ffi::boundary::status::*;

fn panic_message(payload: &(dyn Any + Send)) -> String {
    let what = payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("unknown panic payload");
    let place = last_panic_location().map_or_else(String::new, |at| format!(" at {at}"));
    format!("internal error, please report it: panic{place} caught at the C boundary: {what}")
}

/// Drops a caught panic payload without letting a second panic out: a payload whose destructor
/// panics would otherwise unwind from here into C, outside every `catch_unwind`. Such a payload
/// is leaked instead.
pub(crate) fn drop_payload(payload: Box<dyn Any + Send>) {
    if let Err(second) = catch_quietly(move || drop(payload)) {
        std::mem::forget(second);
    }
}

/// Records a caught panic as `HW_ERR_PANIC` with its message.
fn record_panic(payload: Box<dyn Any + Send>) -> hw_status {
    let status = record(FfiError::new(HW_ERR_PANIC, panic_message(&*payload)));
    drop_payload(payload);
    status
}

/// Runs the body of a status-returning exported function.
pub(crate) fn guard(body: impl FnOnce() -> Result<(), FfiError>) -> hw_status {
    match catch_quietly(body) {
        Ok(Ok(())) => HW_OK,
        Ok(Err(error)) => record(error),
        Err(payload) => record_panic(payload),
    }
}

/// Runs the body of a value-returning exported function (a getter or a navigation step). On an
/// error or a panic the message is recorded and `fallback` (an invalid id, zero, false) returned.
pub(crate) fn guard_value<T>(fallback: T, body: impl FnOnce() -> Result<T, FfiError>) -> T {
    match catch_quietly(body) {
        Ok(Ok(value)) => value,
        Ok(Err(error)) => {
            record(error);
            fallback
        }
        Err(payload) => {
            record_panic(payload);
            fallback
        }
    }
}

/// Runs a body that returns nothing (the `_free` functions).
pub(crate) fn guard_void(body: impl FnOnce() -> Result<(), FfiError>) {
    guard(body);
}

/// Borrows a read-only argument. NULL and misaligned pointers are refused, naming the argument.
///
/// # Safety
/// `ptr` must be NULL, misaligned, or valid for reads for the returned lifetime.
pub(crate) unsafe fn arg_ref<'a, T>(ptr: *const T, name: &str) -> Result<&'a T, FfiError> {
    check_aligned(ptr, name)?;
    // SAFETY: aligned (checked); the caller promises validity when not NULL.
    unsafe { ptr.as_ref() }.ok_or_else(|| FfiError::null_argument(name))
}

/// Borrows a mutable argument. NULL and misaligned pointers are refused, naming the argument.
///
/// # Safety
/// `ptr` must be NULL, misaligned, or valid for reads and writes, unaliased, for the returned
/// lifetime.
pub(crate) unsafe fn arg_mut<'a, T>(ptr: *mut T, name: &str) -> Result<&'a mut T, FfiError> {
    check_aligned(ptr, name)?;
    // SAFETY: aligned (checked); the caller promises validity and exclusivity when not NULL.
    unsafe { ptr.as_mut() }.ok_or_else(|| FfiError::null_argument(name))
}

/// Refuses a misaligned pointer argument, input or output, naming it: Rust may not read or
/// write through one, and C code only makes one by mistake (a cast of a byte buffer).
pub(crate) fn check_aligned<T>(ptr: *const T, name: &str) -> Result<(), FfiError> {
    if ptr.is_aligned() {
        Ok(())
    } else {
        Err(FfiError::invalid_input(format!(
            "argument `{name}` is misaligned"
        )))
    }
}

/// Borrows `len` elements starting at `ptr`. NULL is accepted only when `len` is 0.
///
/// # Safety
/// `ptr` must be NULL or point to `len` initialised, properly aligned elements that stay valid and
/// unmodified for the returned lifetime.
pub(crate) unsafe fn arg_slice<'a, T>(
    ptr: *const T,
    len: usize,
    name: &str,
) -> Result<&'a [T], FfiError> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(FfiError::null_argument(name));
    }
    check_aligned(ptr, name)?;
    if len
        .checked_mul(size_of::<T>())
        .is_none_or(|bytes| bytes > isize::MAX as usize)
    {
        return Err(FfiError::invalid_input(format!(
            "argument `{name}`: {len} elements do not fit in memory"
        )));
    }
    // SAFETY: non-NULL, aligned, size checked; validity promised by the caller.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// An output argument, checked for NULL up front and written only when the call succeeds.
pub(crate) struct Out<T>(*mut T);

impl<T> Out<T> {
    /// Checks an output pointer: not NULL, aligned.
    pub(crate) fn new(ptr: *mut T, name: &str) -> Result<Self, FfiError> {
        if ptr.is_null() {
            return Err(FfiError::null_argument(name));
        }
        check_aligned(ptr, name)?;
        Ok(Out(ptr))
    }

    /// An optional output: NULL means the caller does not want it.
    pub(crate) fn optional(ptr: *mut T) -> Option<Self> {
        (!ptr.is_null()).then_some(Out(ptr))
    }

    /// Writes the value. Call only once the function can no longer fail.
    ///
    /// # Safety
    /// The pointer given to [`Out::new`] must be valid for writes.
    pub(crate) unsafe fn write(self, value: T) {
        // SAFETY: non-NULL (checked in `new`), writable per the caller.
        unsafe { self.0.write(value) }
    }
}

/// Copies `text` NUL-terminated into a caller's buffer: the protocol of every "copy into caller
/// buffer" call. `*out_needed` (when not NULL) always receives the size needed, terminator
/// included; when `out_text` is NULL or `capacity` is smaller, nothing is written to `out_text` and
/// the error is `HW_ERR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `out_text` must be NULL or point to `capacity` writable bytes; `out_needed` must be NULL or
/// writable.
pub(crate) unsafe fn copy_text(
    text: &str,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> Result<(), FfiError> {
    let size = text.len() + 1;
    if !out_needed.is_null() {
        // SAFETY: writable per the caller.
        unsafe { out_needed.write(size) };
    }
    if out_text.is_null() || capacity < size {
        return Err(FfiError::new(
            HW_ERR_BUFFER_TOO_SMALL,
            format!("the buffer holds {capacity} bytes, {size} are needed"),
        ));
    }
    // SAFETY: `out_text` holds at least `size` writable bytes; `text` is a distinct Rust
    // allocation.
    unsafe {
        std::ptr::copy_nonoverlapping(text.as_ptr(), out_text.cast::<u8>(), text.len());
        out_text.add(text.len()).write(0);
    }
    Ok(())
}

/// Checks a caller's output array of `capacity` elements that must take `count` of them: the
/// array form of the [`copy_text`] protocol. `*out_needed` (when not NULL) always receives `count`;
/// when `out` is NULL or too small the error is `HW_ERR_BUFFER_TOO_SMALL`, when it is misaligned
/// `HW_ERR_INVALID_INPUT` naming it (`name`). Returns the `count` elements to fill, which the
/// caller does only once the call can no longer fail.
///
/// # Safety
/// `out` must be NULL or point to `capacity` writable elements that nothing else references
/// for the returned lifetime; `out_needed` NULL or writable.
pub(crate) unsafe fn out_array<'a, T>(
    out: *mut T,
    capacity: usize,
    count: usize,
    out_needed: *mut usize,
    name: &str,
) -> Result<&'a mut [T], FfiError> {
    if !out_needed.is_null() {
        // SAFETY: writable per the caller.
        unsafe { out_needed.write(count) };
    }
    if count == 0 {
        return Ok(&mut []);
    }
    if out.is_null() || capacity < count {
        return Err(FfiError::new(
            HW_ERR_BUFFER_TOO_SMALL,
            format!("argument `{name}` holds {capacity} elements, {count} are needed"),
        ));
    }
    check_aligned(out, name)?;
    // SAFETY: non-NULL, aligned, at least `count` writable elements per the caller (so the size
    // fits in memory).
    Ok(unsafe { std::slice::from_raw_parts_mut(out, count) })
}

/// Copies `items` into a caller's array of `capacity` elements (`name` in the C signature), with
/// the protocol of [`out_array`]: nothing is written to it on an error.
///
/// # Safety
/// As for [`out_array`].
pub(crate) unsafe fn copy_items<T: Copy>(
    items: &[T],
    out: *mut T,
    capacity: usize,
    out_needed: *mut usize,
    name: &str,
) -> Result<(), FfiError> {
    // SAFETY: forwarded from the caller.
    unsafe { out_array(out, capacity, items.len(), out_needed, name) }?.copy_from_slice(items);
    Ok(())
}

/// The whole body of a zero-copy view call: checks both outputs (`data_name` is the pointer
/// output's name in the C signature, for the message), looks the view up, then writes its start
/// (NULL when empty) and length.
///
/// # Safety
/// `out_data` and `out_len` must be NULL or writable.
pub(crate) unsafe fn give_view<'a, T: 'a>(
    out_data: *mut *const T,
    data_name: &str,
    out_len: *mut usize,
    view: impl FnOnce() -> Result<&'a [T], FfiError>,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_pointer(out_data, data_name, out_len, || {
            let data = view()?;
            Ok((view_start(data), data.len()))
        })
    }
}

/// The whole body of a call that hands out memory as a pointer and a length: checks both
/// outputs (`data_name` as for [`give_view`]), computes them, then writes both.
///
/// # Safety
/// `out_data` and `out_len` must be NULL or writable.
pub(crate) unsafe fn give_pointer<P>(
    out_data: *mut P,
    data_name: &str,
    out_len: *mut usize,
    memory: impl FnOnce() -> Result<(P, usize), FfiError>,
) -> hw_status {
    guard(|| {
        let (out_data, out_len) = (
            Out::new(out_data, data_name)?,
            Out::new(out_len, "out_len")?,
        );
        let (data, len) = memory()?;
        // SAFETY: both checked non-NULL, writable per the caller.
        unsafe {
            out_data.write(data);
            out_len.write(len);
        }
        Ok(())
    })
}

/// The start of a view as handed to C: NULL when it is empty. Every zero-copy view goes through
/// here, so an empty one is NULL whichever call gives it.
pub(crate) fn view_start<T>(data: &[T]) -> *const T {
    if data.is_empty() {
        std::ptr::null()
    } else {
        data.as_ptr()
    }
}

/// [`view_start`] of memory the caller may write through (a pointer derived from a shared
/// borrow must not be written through).
pub(crate) fn view_start_mut<T>(data: &mut [T]) -> *mut T {
    if data.is_empty() {
        std::ptr::null_mut()
    } else {
        data.as_mut_ptr()
    }
}

/// Writes a zero-copy view (`*out_data`, NULL when empty, and `*out_len`).
///
/// # Safety
/// As for [`Out::write`].
pub(crate) unsafe fn write_view<T>(out_data: Out<*const T>, out_len: Out<usize>, data: &[T]) {
    // SAFETY: forwarded from the caller.
    unsafe {
        out_data.write(view_start(data));
        out_len.write(data.len());
    }
}

/// Writes a zero-copy view of fixed-size tuples (points, normals) as their scalars: `*out_data`
/// (NULL when empty) and the number of tuples `*out_len`.
///
/// # Safety
/// As for [`Out::write`].
pub(crate) unsafe fn write_tuple_view<T, const N: usize>(
    out_data: Out<*const T>,
    out_len: Out<usize>,
    data: &[[T; N]],
) {
    // SAFETY: forwarded from the caller.
    unsafe {
        out_data.write(view_start(data.as_flattened()));
        out_len.write(data.len());
    }
}

/// Reads a position argument: 3 finite doubles (NaN or infinity is refused, naming the argument).
///
/// # Safety
/// `xyz` must be NULL or point to 3 readable doubles.
pub(crate) unsafe fn point_arg(xyz: *const f64, name: &str) -> Result<[f64; 3], FfiError> {
    // SAFETY: forwarded from the caller.
    let point = *unsafe { arg_ref(xyz.cast::<[f64; 3]>(), name) }?;
    if point.iter().any(|c| !c.is_finite()) {
        return Err(FfiError::invalid_input(format!(
            "argument `{name}` = {point:?} is not finite"
        )));
    }
    Ok(point)
}

/// The protocol of every `*_next_*` call of a stack circulator: the next element goes through
/// `out` and the call returns `true`; at the end of the walk, or on an error (recorded), it returns
/// `false` and `out` is untouched.
///
/// # Safety
/// `out` must be NULL or writable.
pub(crate) unsafe fn next_element<T>(
    out: *mut T,
    advance: impl FnOnce() -> Result<Option<T>, FfiError>,
) -> bool {
    guard_value(false, || {
        let out = Out::new(out, "out")?;
        let Some(element) = advance()? else {
            return Ok(false);
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(element) };
        Ok(true)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A panic payload whose destructor panics in turn.
    struct PanicsOnDrop;

    impl Drop for PanicsOnDrop {
        fn drop(&mut self) {
            panic!("payload destructor");
        }
    }

    #[test]
    fn a_payload_that_panics_on_drop_stays_inside_the_guard() {
        // Before: the payload was dropped after `catch_unwind` returned, and its panic left the
        // guard (in an `extern "C"` function: an abort).
        let status = guard(|| std::panic::panic_any(PanicsOnDrop));
        assert_eq!(status, HW_ERR_PANIC);
        let value = guard_value(7u32, || std::panic::panic_any(PanicsOnDrop));
        assert_eq!(value, 7);
    }

    #[test]
    fn misaligned_borrowed_arguments_are_refused() {
        // Before: `point_arg` (hw_mesh_add_vertex, hw_mesh_set_vertex_position, ...) read
        // through a misaligned pointer, which Rust may not do.
        let storage = [0u64; 4];
        let misaligned = storage.as_ptr().cast::<u8>().wrapping_add(1).cast::<f64>();
        let error = unsafe { point_arg(misaligned, "xyz") }.unwrap_err();
        assert_eq!(error.status, HW_ERR_INVALID_INPUT);
        assert_eq!(error.message, "argument `xyz` is misaligned");
        let error = unsafe { arg_mut(misaligned.cast_mut(), "xyz") }.unwrap_err();
        assert_eq!(error.message, "argument `xyz` is misaligned");
        // NULL stays a NULL argument, and an aligned point is read.
        let error = unsafe { point_arg(std::ptr::null(), "xyz") }.unwrap_err();
        assert_eq!(error.status, HW_ERR_NULL_ARGUMENT);
        let point = [1.0, 2.0, 3.0];
        assert_eq!(unsafe { point_arg(point.as_ptr(), "xyz") }.unwrap(), point);
    }
}
