//! The C form of an indexed face list, shared by every function that takes one.

use crate::soup::FaceList;

use crate::ffi::boundary::arg_slice;
use crate::ffi::boundary::error::FfiError;

/// Borrows the arrays of an indexed face list passed from C: `3 * n_vertices` coordinates,
/// `n_faces` face sizes and `n_indices` corner indices.
///
/// # Safety
/// Each pointer must be NULL (allowed only with a zero count) or point to as many initialised
/// elements as its count says, valid for `'a`.
pub(crate) unsafe fn face_list_arg<'a>(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
) -> Result<FaceList<'a>, FfiError> {
    let n_coordinates = n_vertices.checked_mul(3).ok_or_else(|| {
        FfiError::invalid_input(format!("n_vertices = {n_vertices} is too large"))
    })?;
    // SAFETY: forwarded from the caller.
    let (coordinates, sizes, indices) = unsafe {
        (
            arg_slice(positions, n_coordinates, "positions")?,
            arg_slice(face_sizes, n_faces, "face_sizes")?,
            arg_slice(indices, n_indices, "indices")?,
        )
    };
    Ok(FaceList::polygons(
        coordinates.as_chunks::<3>().0,
        sizes,
        indices,
    ))
}
