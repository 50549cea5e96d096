//! `hw_winged`: the winged-edge (Baumgart) mesh object — creation from an indexed face list or a
//! half-edge mesh, conversion back, counts and validation. One-step navigation is in
//! `navigation.rs`, walks in `circulator.rs`, the Euler operators in `euler.rs`, positions,
//! normals and the course notes' tables in `positions.rs`, `normals.rs` and `table.rs`.
//!
//! Ids get their own by-value types (`hw_wvertex`, `hw_wedge`, `hw_wface`), distinct from the
//! half-edge kernel's, so the compiler refuses a winged id passed to a half-edge call. Their
//! numbering does match across hw_winged_from_mesh() and hw_winged_to_mesh(): winged vertex,
//! edge and face `i` are mesh vertex, edge and face `i`.

use crate::winged::{EdgeId, EdgeRecord, FaceId, VertexId, Winged, WingedError};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, arg_mut, arg_ref, arg_slice, guard, guard_value, guard_void};
use crate::ffi::mesh::diagnostic::{give_built, hw_diagnostic};
use crate::ffi::mesh::elements::id_conversions;
use crate::ffi::mesh::lifecycle::{build_policy, hw_build_policy, hw_mesh, mesh_ref};

/// A winged-edge (Baumgart) polygon mesh: one record per edge with its two vertices, its two
/// faces and its four wings. Opaque; create it with hw_winged_new(), hw_winged_from_indexed() or
/// hw_winged_from_mesh() and release it with hw_winged_free().
/// \ingroup winged
pub struct hw_winged {
    pub(crate) winged: Winged,
}

/// A vertex id of an ::hw_winged.
/// \ingroup winged
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_wvertex {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// An edge id of an ::hw_winged (one record per undirected edge).
/// \ingroup winged
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_wedge {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// A face id of an ::hw_winged. On an edge side, `idx == HW_INVALID_INDEX` means a hole
/// (a boundary).
/// \ingroup winged
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_wface {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

id_conversions!(hw_wvertex <=> VertexId, hw_wedge <=> EdgeId, hw_wface <=> FaceId);

/// Baumgart's edge record. An edge runs `start → end`; its **left** side is the loop that walks
/// it `start → end`, its **right** side the loop that walks it `end → start`; each side has the
/// previous and next edge of that loop (its wings). The same fields under three naming
/// conventions:
///
/// | field        | Baumgart            | Granada            | Wikipedia            |
/// |--------------|---------------------|--------------------|----------------------|
/// | `start`      | VSTART              | Vi                 | vert_origin          |
/// | `end`        | VEND                | Vf                 | vert_destination     |
/// | `left_face`  | FCW                 | Cd                 | face_left            |
/// | `right_face` | FCCW                | Ci                 | face_right           |
/// | `left_prev`  | EPCW                | Ada                | edge_left_cw         |
/// | `left_next`  | ENCW                | Ads                | edge_left_ccw        |
/// | `right_prev` | EPCCW               | Aia                | edge_right_cw        |
/// | `right_next` | ENCCW               | Ais                | edge_right_ccw       |
///
/// A face id of `HW_INVALID_INDEX` is a hole; its wings still link the boundary loop.
/// \ingroup winged
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_wedge_record {
    /// The vertex the edge starts at.
    pub start: hw_wvertex,
    /// The vertex the edge ends at.
    pub end: hw_wvertex,
    /// The face on its left (the loop that walks it `start → end`).
    pub left_face: hw_wface,
    /// The face on its right (the loop that walks it `end → start`).
    pub right_face: hw_wface,
    /// The edge before it in the left loop.
    pub left_prev: hw_wedge,
    /// The edge after it in the left loop.
    pub left_next: hw_wedge,
    /// The edge before it in the right loop.
    pub right_prev: hw_wedge,
    /// The edge after it in the right loop.
    pub right_next: hw_wedge,
}

// hw_winged_edge_records() hands out the Rust record array as `hw_wedge_record`s: both are eight
// 32-bit ids in the same order.
const _: () = assert!(size_of::<hw_wedge_record>() == size_of::<EdgeRecord>());
const _: () = assert!(align_of::<hw_wedge_record>() == align_of::<EdgeRecord>());

impl From<&EdgeRecord> for hw_wedge_record {
    fn from(r: &EdgeRecord) -> Self {
        hw_wedge_record {
            start: r.start.into(),
            end: r.end.into(),
            left_face: r.left_face.into(),
            right_face: r.right_face.into(),
            left_prev: r.left_prev.into(),
            left_next: r.left_next.into(),
            right_prev: r.right_prev.into(),
            right_next: r.right_next.into(),
        }
    }
}

impl From<WingedError> for FfiError {
    fn from(error: WingedError) -> Self {
        let status = match &error {
            WingedError::InvalidVertex(_)
            | WingedError::InvalidEdge(_)
            | WingedError::InvalidFace(_) => HW_ERR_INVALID_HANDLE,
            WingedError::InvalidFaceList(build) => return build.clone().into(),
            WingedError::OutOfMemory(_) => HW_ERR_OUT_OF_MEMORY,
            WingedError::VertexNotOnFace { .. }
            | WingedError::AmbiguousCorner { .. }
            | WingedError::SelfLoop(_)
            | WingedError::VertexNotDangling { .. }
            | WingedError::PointFaceAtSharedVertex { .. }
            | WingedError::EdgeNotBetweenTwoFaces(_)
            | WingedError::NotAPointFace(_)
            | WingedError::NotConvertible(_) => HW_ERR_REFUSED,
            WingedError::NonFinitePosition { .. }
            | WingedError::TooManyElements { .. }
            | WingedError::EdgeOrderMismatch { .. }
            | WingedError::NotIncident { .. }
            | WingedError::InvariantViolated { .. } => HW_ERR_INVALID_INPUT,
        };
        FfiError::new(status, error.to_string())
    }
}

/// Borrows the structure of a `const hw_winged *` argument.
///
/// # Safety
/// `winged` must be NULL or a live `hw_winged`.
pub(crate) unsafe fn winged_ref<'a>(winged: *const hw_winged) -> Result<&'a Winged, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(winged, "winged") }?.winged)
}

/// Borrows the structure of a `hw_winged *` argument for a change.
///
/// # Safety
/// `winged` must be NULL or a live `hw_winged` not used elsewhere during the call.
pub(crate) unsafe fn winged_mut<'a>(winged: *mut hw_winged) -> Result<&'a mut Winged, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&mut unsafe { arg_mut(winged, "winged") }?.winged)
}

/// Answers a value-returning query on a `const hw_winged *`: `fallback` (with the error
/// recorded) for a NULL structure or when the query fails.
///
/// # Safety
/// `winged` must be NULL or a live `hw_winged`.
pub(crate) unsafe fn query<T>(
    winged: *const hw_winged,
    fallback: T,
    answer: impl FnOnce(&Winged) -> Result<T, FfiError>,
) -> T {
    // SAFETY: forwarded from the caller.
    guard_value(fallback, || answer(unsafe { winged_ref(winged) }?))
}

/// Creates an empty structure, to build with the Euler operators (hw_winged_mvfs() first).
/// Returns NULL only if the allocation fails.
/// \ingroup winged
#[unsafe(no_mangle)]
pub extern "C" fn hw_winged_new() -> *mut hw_winged {
    guard_value(std::ptr::null_mut(), || {
        Ok(into_handle(hw_winged {
            winged: Winged::new(),
        }))
    })
}

/// Builds a winged-edge structure from an indexed polygon list: each face's edges are found
/// or created through a bulk edge lookup, as in the classic construction from an indexed mesh.
///
/// The arrays, `policy`, the statuses and the diagnostic are exactly those of
/// hw_mesh_from_indexed(): the same input is refused, skipped or repaired the same way by both
/// kernels. Edges are numbered in order of first appearance walking the faces in order and
/// point the way their first face walks them (that face is their left face); each face's loop
/// starts at its first corner; input vertex `i` is vertex `i`.
///
/// On success `*out_winged` receives a new structure to release with hw_winged_free(), and, when
/// `out_diagnostic` is not NULL, `*out_diagnostic` a diagnostic to release with
/// hw_diagnostic_free(). A refused input writes its diagnostic as hw_mesh_from_indexed() does.
///
/// # Safety
/// Array arguments must point to at least as many elements as their counts say (they may be NULL
/// when the count is 0); `out_winged` must be writable; `out_diagnostic` NULL or writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_from_indexed(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    policy: hw_build_policy,
    out_winged: *mut *mut hw_winged,
    out_diagnostic: *mut *mut hw_diagnostic,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_built(out_winged, "out_winged", out_diagnostic, || {
            let list = face_list_arg(
                positions, n_vertices, face_sizes, n_faces, indices, n_indices,
            )?;
            let policy = build_policy(policy)?;
            let built = with_threads(|| Winged::from_face_list(&list, policy));
            Ok(built.map(|(winged, diagnostic)| (hw_winged { winged }, diagnostic)))
        })
    }
}

/// Builds like hw_winged_from_indexed() (strict policy), but numbers and directs the edges as
/// `edge_order` lists them: edge `i` runs from `edge_order[2 i]` to `edge_order[2 i + 1]`, and
/// the face walking it that way is its left face. This reproduces tables whose edge numbering was
/// made by hand, as textbook examples are. `n_edges` must be the edge count of the faces and
/// every edge must be listed once, in either direction; otherwise `HW_ERR_INVALID_INPUT` with
/// the first mismatch in the message.
///
/// # Safety
/// As for hw_winged_from_indexed(); `edge_order` must point to `2 * n_edges` indices (NULL
/// when `n_edges` is 0).
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_from_indexed_ordered(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    edge_order: *const u32,
    n_edges: usize,
    out_winged: *mut *mut hw_winged,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_winged, "out_winged")?;
        let n_endpoints = n_edges
            .checked_mul(2)
            .ok_or_else(|| FfiError::invalid_input(format!("n_edges = {n_edges} is too large")))?;
        // SAFETY: forwarded from the caller.
        let (list, order) = unsafe {
            (
                face_list_arg(
                    positions, n_vertices, face_sizes, n_faces, indices, n_indices,
                )?,
                arg_slice(edge_order, n_endpoints, "edge_order")?,
            )
        };
        let order: Vec<[u32; 2]> = order.chunks_exact(2).map(|e| [e[0], e[1]]).collect();
        let winged = with_threads(|| Winged::from_face_list_with_edge_order(&list, &order))?;
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe { out.write(into_handle(hw_winged { winged })) };
        Ok(())
    })
}

/// Builds the winged-edge structure of a half-edge mesh, record for record: winged edge `e` is
/// mesh edge `e`, directed as its half-edge `2e` (its left side; half-edge `2e + 1` is its right
/// side); vertices and faces keep their ids and their stored edge. Deleted mesh elements are left
/// out and the rest renumbered densely in order.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_winged` writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_from_mesh(
    mesh: *const hw_mesh,
    out_winged: *mut *mut hw_winged,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_winged, "out_winged")?;
        // SAFETY: forwarded from the caller.
        let winged = Winged::from_mesh(unsafe { mesh_ref(mesh) }?);
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe { out.write(into_handle(hw_winged { winged })) };
        Ok(())
    })
}

/// Converts to a half-edge mesh (the inverse of hw_winged_from_mesh()): edge `e`'s left side
/// becomes half-edge `2e`, its right side `2e + 1`; ids are kept, deleted elements included
/// (they stay deleted in the mesh until hw_mesh_garbage_collect()). Converting a structure built
/// by hw_winged_from_indexed() gives the mesh hw_mesh_from_indexed() builds from the same input,
/// under every policy (input vertices with a non-finite coordinate are deleted in both).
///
/// Returns `HW_ERR_REFUSED` when a face has no edges (a point face made by hw_winged_mvfs():
/// a half-edge face needs a half-edge).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_mesh` writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_to_mesh(
    winged: *const hw_winged,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { winged_ref(winged) }?.to_mesh()?;
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe { out.write(into_handle(hw_mesh { mesh })) };
        Ok(())
    })
}

/// Releases a structure. NULL is a no-op; a structure freed already is refused, the last error
/// saying so (within the limits the ownership conventions at the top of the header state).
///
/// # Safety
/// `winged` must be NULL or a structure from this library not in use by another thread.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_free(winged: *mut hw_winged) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(winged, "hw_winged") });
}

// cbindgen reads these signatures as written, so they are spelled out rather than generated.

/// Number of vertices (deleted ones not counted); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_n_vertices(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.n_vertices() as usize)) }
}

/// Number of edges (deleted ones not counted); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_n_edges(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.n_edges() as usize)) }
}

/// Number of faces (deleted ones not counted); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_n_faces(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.n_faces() as usize)) }
}

/// Size of the vertex id space: ids `0 .. capacity - 1`, deleted ones included until
/// hw_winged_garbage_collect(); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_n_vertex_slots(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.n_vertex_slots() as usize)) }
}

/// Size of the edge id space (see hw_winged_n_vertex_slots()); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_n_edge_slots(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.n_edge_slots() as usize)) }
}

/// Size of the face id space (see hw_winged_n_vertex_slots()); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_n_face_slots(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.n_face_slots() as usize)) }
}

/// Computes a 3-vector from the structure and writes it to `out[0..3]` on success; a NULL `out`
/// is refused.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out` NULL (refused) or 3 writable doubles.
pub(crate) unsafe fn write_triple(
    winged: *const hw_winged,
    out: *mut f64,
    name: &str,
    compute: impl FnOnce(&Winged) -> Result<[f64; 3], FfiError>,
) -> hw_status {
    guard(|| {
        let out = Out::new(out.cast::<[f64; 3]>(), name)?;
        // SAFETY: forwarded from the caller.
        let value = compute(unsafe { winged_ref(winged) }?)?;
        // SAFETY: non-NULL, 3 writable doubles per the caller; `[f64; 3]` has the alignment of
        // `f64`.
        unsafe { out.write(value) };
        Ok(())
    })
}

/// Checks every structural invariant (records in range, wings linking closed loops, stored
/// edges incident, counts). `HW_OK`, or `HW_ERR_INVALID_INPUT` with the first broken invariant
/// in the message. A structure made by this library always passes.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_check(winged: *const hw_winged) -> hw_status {
    // SAFETY: forwarded from the caller.
    guard(|| Ok(unsafe { winged_ref(winged) }?.check()?))
}
