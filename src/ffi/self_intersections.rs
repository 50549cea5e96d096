//! `hw_face_pairs`: the self-intersections of an indexed face list, on their own (the doctor
//! reports them among its findings).

use crate::geom::{SelfIntersectionError, face_self_intersections};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, arg_ref, guard, guard_void, view_start};

/// Pairs of faces. Opaque; from hw_self_intersections_indexed(); read with hw_face_pairs_view();
/// release with hw_face_pairs_free().
/// \ingroup doctor
pub struct hw_face_pairs {
    pairs: Vec<[u32; 2]>,
}

/// The pairs of faces of an indexed face list (same arrays as hw_mesh_from_indexed()) that
/// intersect other than along the vertices and edges they share (by vertex index), with the
/// semantics of CGAL's `Polygon_mesh_processing::self_intersections`: faces sharing no vertex
/// that touch anywhere, faces sharing one vertex that meet elsewhere, faces sharing an edge that
/// overlap beyond it (coplanar, third corners on the same side). A face whose triangle has
/// exactly collinear corners is degenerate: it is reported once as the pair (f, f) and not
/// tested against the others. Polygons are tested as the triangles hw_render_buffers_build()
/// gives them; the triangles of one face are not tested against each other.
///
/// Every decision is exact, at any magnitude of finite coordinates. O(n log n + k) for n
/// triangles and k pairs of overlapping bounding boxes; on hw_set_thread_count() threads. On
/// success `*out_pairs` receives the pairs, sorted, smaller face first; release them with
/// hw_face_pairs_free(). `HW_ERR_INVALID_INPUT`: the sizes do not add up to `n_indices`, an
/// index is out of range, or a corner of a face has a NaN or infinite coordinate (the
/// message names the face and the vertex). `HW_ERR_OUT_OF_MEMORY`: the search needs more
/// memory than the system gives (checked before it starts).
///
/// # Safety
/// As for hw_mesh_from_indexed(); `out_pairs` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_self_intersections_indexed(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    out_pairs: *mut *mut hw_face_pairs,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_pairs, "out_pairs")?;
        // SAFETY: forwarded from the caller.
        let list = unsafe {
            face_list_arg(
                positions, n_vertices, face_sizes, n_faces, indices, n_indices,
            )
        }?;
        let pairs =
            with_threads(|| face_self_intersections(&list)).map_err(|error| match error {
                SelfIntersectionError::OutOfMemory(refusal) => FfiError::from(refusal),
                other => FfiError::invalid_input(other.to_string()),
            })?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_face_pairs { pairs })) };
        Ok(())
    })
}

/// A zero-copy view of the pairs: `*out_ids` holds `2 * *out_n_pairs` face ids (NULL when there
/// are none), valid as long as `pairs`.
///
/// # Safety
/// `pairs` must be NULL or live; `out_ids` and `out_n_pairs` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_face_pairs_view(
    pairs: *const hw_face_pairs,
    out_ids: *mut *const u32,
    out_n_pairs: *mut usize,
) -> hw_status {
    guard(|| {
        let out_ids = Out::new(out_ids, "out_ids")?;
        let out_n_pairs = Out::new(out_n_pairs, "out_n_pairs")?;
        // SAFETY: forwarded from the caller.
        let pairs = &unsafe { arg_ref(pairs, "pairs") }?.pairs;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_ids.write(view_start(pairs.as_flattened()));
            out_n_pairs.write(pairs.len());
        }
        Ok(())
    })
}

/// Releases face pairs. NULL is a no-op; freeing twice is detected and refused.
///
/// # Safety
/// `pairs` must be NULL or from this library, not in use by another thread.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_face_pairs_free(pairs: *mut hw_face_pairs) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(pairs, "hw_face_pairs") });
}
