//! `hw_winged`: the winged-edge (Baumgart) mesh object — creation from an indexed face list or a
//! half-edge mesh, conversion back, counts, edge records, normals, validation and the course
//! notes' tables. Walks are in `winged_circulator.rs`, the Euler operators in `winged_euler.rs`.
//!
//! Ids get their own by-value types (`hw_wvertex`, `hw_wedge`, `hw_wface`), distinct from the
//! half-edge kernel's, so the compiler refuses a winged id passed to a half-edge call. Their
//! numbering does match across hw_winged_from_mesh() and hw_winged_to_mesh(): winged vertex,
//! edge and face `i` are mesh vertex, edge and face `i`.

use crate::winged::{
    EdgeId, EdgeRecord, FaceId, Naming, TableFormat, VertexId, Winged, WingedError,
};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{
    Out, arg_mut, arg_ref, arg_slice, copy_items, copy_text, give_view, guard, guard_value,
    guard_void,
};
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
unsafe fn query<T>(
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
pub unsafe extern "C" fn hw_winged_vertex_capacity(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.vertex_capacity() as usize)) }
}

/// Size of the edge id space (see hw_winged_vertex_capacity()); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_edge_capacity(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.edge_capacity() as usize)) }
}

/// Size of the face id space (see hw_winged_vertex_capacity()); 0 for a NULL structure.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_face_capacity(winged: *const hw_winged) -> usize {
    unsafe { query(winged, 0, |w| Ok(w.face_capacity() as usize)) }
}

/// Whether `v` names a live vertex (false for a NULL structure, with the error recorded).
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_is_vertex(winged: *const hw_winged, v: hw_wvertex) -> bool {
    unsafe { query(winged, false, |w| Ok(w.is_vertex(v.into()))) }
}

/// Whether `e` names a live edge (false for a NULL structure, with the error recorded).
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_is_edge(winged: *const hw_winged, e: hw_wedge) -> bool {
    unsafe { query(winged, false, |w| Ok(w.is_edge(e.into()))) }
}

/// Whether `f` names a live face (false for a NULL structure, with the error recorded).
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_is_face(winged: *const hw_winged, f: hw_wface) -> bool {
    unsafe { query(winged, false, |w| Ok(w.is_face(f.into()))) }
}

/// Copies the record of edge `e` (its vertices, faces and wings) into `*out_record`.
/// `HW_ERR_INVALID_HANDLE` for an edge that does not exist or was deleted.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_record` writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_edge(
    winged: *const hw_winged,
    e: hw_wedge,
    out_record: *mut hw_wedge_record,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_record, "out_record")?;
        // SAFETY: forwarded from the caller.
        let record = unsafe { winged_ref(winged) }?.edge(e.into())?.into();
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe { out.write(record) };
        Ok(())
    })
}

/// A zero-copy, read-only view of all edge records, indexed by edge id: `*out_records` (NULL when
/// there are none) and `*out_len`. A deleted edge's record has `start.idx == HW_INVALID_INDEX`.
/// Valid until the next call that modifies the structure.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_records` and `out_len` writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_edge_records(
    winged: *const hw_winged,
    out_records: *mut *const hw_wedge_record,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_records, "out_records", out_len, || {
            let records = winged_ref(winged)?.edge_records();
            // SAFETY: `hw_wedge_record` and `EdgeRecord` are both `repr(C)` structs of eight
            // 32-bit ids in the same order (sizes and alignments asserted above), so the slice
            // reads as either type.
            Ok(std::slice::from_raw_parts(
                records.as_ptr().cast::<hw_wedge_record>(),
                records.len(),
            ))
        })
    }
}

/// The edge vertex `v` stores: its ring starts there (for a boundary vertex, the edge whose side
/// leaving `v` is a hole). Invalid for an isolated vertex, and (with the error recorded) for a
/// vertex that does not exist.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_vertex_edge(
    winged: *const hw_winged,
    v: hw_wvertex,
) -> hw_wedge {
    unsafe {
        query(winged, hw_wedge::INVALID, |w| {
            Ok(w.vertex_edge(v.into())?.into())
        })
    }
}

/// The edge face `f` stores: its loop starts there. Invalid for a point face (made by
/// hw_winged_mvfs()), and (with the error recorded) for a face that does not exist.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_face_edge(winged: *const hw_winged, f: hw_wface) -> hw_wedge {
    unsafe {
        query(winged, hw_wedge::INVALID, |w| {
            Ok(w.face_edge(f.into())?.into())
        })
    }
}

/// Writes the position of `v` to `out_xyz[0..3]` (required: NULL gives `HW_ERR_NULL_ARGUMENT`).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_xyz` must point to 3 writable doubles.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_position(
    winged: *const hw_winged,
    v: hw_wvertex,
    out_xyz: *mut f64,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { write_triple(winged, out_xyz, "out_xyz", |w| Ok(w.position(v.into())?)) }
}

/// Unit normal of face `f` by Newell's method (outward for a counter-clockwise face; zero for a
/// degenerate or point face), written to `out_normal[0..3]` (required: NULL gives
/// `HW_ERR_NULL_ARGUMENT`).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normal` must point to 3 writable doubles.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_face_normal(
    winged: *const hw_winged,
    f: hw_wface,
    out_normal: *mut f64,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        write_triple(winged, out_normal, "out_normal", |w| {
            Ok(w.face_normal(f.into())?)
        })
    }
}

/// Unit normal of vertex `v` as Baumgart's structure computes it: the normalised sum of the unit
/// normals of the faces around it (holes left out; zero if none), written to `out_normal[0..3]`
/// (required: NULL gives `HW_ERR_NULL_ARGUMENT`).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normal` must point to 3 writable doubles.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_vertex_normal(
    winged: *const hw_winged,
    v: hw_wvertex,
    out_normal: *mut f64,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        write_triple(winged, out_normal, "out_normal", |w| {
            Ok(w.vertex_normal(v.into())?)
        })
    }
}

/// Computes a 3-vector from the structure and writes it to `out[0..3]` on success; a NULL `out`
/// is refused.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out` NULL (refused) or 3 writable doubles.
unsafe fn write_triple(
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

/// Which elements hw_winged_normals() gives normals of.
/// \ingroup winged
pub type hw_wnormals = u32;
/// Face normals (Newell), indexed by face id.
/// \ingroup winged
pub const HW_WNORMALS_FACES: hw_wnormals = 0;
/// Vertex normals (sum of the faces' unit normals, normalised), indexed by vertex id.
/// \ingroup winged
pub const HW_WNORMALS_VERTICES: hw_wnormals = 1;

/// The unit normals of all faces or all vertices (`which`: ::HW_WNORMALS_FACES,
/// ::HW_WNORMALS_VERTICES), indexed by id, as `3 * capacity` doubles (x, y, z per element; zero for
/// deleted and degenerate elements) copied into `out_normals`, which holds `capacity` doubles.
/// `*out_needed` (when not NULL) always receives the number of doubles needed;
/// `HW_ERR_BUFFER_TOO_SMALL` when `out_normals` is NULL or too short.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normals` NULL or `capacity` writable doubles;
/// `out_needed` NULL or writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_normals(
    winged: *const hw_winged,
    which: hw_wnormals,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_ref(winged) }?;
        let normals = match which {
            HW_WNORMALS_FACES => w.face_normals(),
            HW_WNORMALS_VERTICES => w.vertex_normals(),
            other => {
                return Err(FfiError::invalid_input(format!(
                    "unknown normals kind {other}"
                )));
            }
        };
        // SAFETY: forwarded from the caller.
        unsafe {
            copy_items(
                normals.as_flattened(),
                out_normals,
                capacity,
                out_needed,
                "out_normals",
            )
        }
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

/// Which table hw_winged_table() prints.
/// \ingroup winged
pub type hw_wtable = u32;
/// The vertex table: id, coordinates, stored edge (Baumgart's "Vertex-Edge" table).
/// \ingroup winged
pub const HW_WTABLE_VERTICES: hw_wtable = 0;
/// The face table: id, stored edge ("Face-Edge").
/// \ingroup winged
pub const HW_WTABLE_FACES: hw_wtable = 1;
/// The edge table: id, vertices, faces and wings ("Edge-Edge relation").
/// \ingroup winged
pub const HW_WTABLE_EDGES: hw_wtable = 2;
/// The three tables, vertex, face and edge, separated by a blank line.
/// \ingroup winged
pub const HW_WTABLE_ALL: hw_wtable = 3;

/// Which naming scheme a table's columns use.
/// \ingroup winged
pub type hw_wnaming = u32;
/// Baumgart's (his cube example): VSTART VEND EPCW ENCW EPCCW ENCCW FCW FCCW; elements labelled
/// from 1 with a letter (V1, E1, F1).
/// \ingroup winged
pub const HW_WNAMING_CW_CCW: hw_wnaming = 0;
/// The University of Granada notes': Vi Vf Cd Ci Ada Ads Aia Ais; elements numbered from 0.
/// \ingroup winged
pub const HW_WNAMING_DIRECT_INVERSE: hw_wnaming = 1;
/// Wikipedia's winged-edge article: vert_origin ... edge_right_ccw; elements numbered from 0.
/// \ingroup winged
pub const HW_WNAMING_LEFT_RIGHT: hw_wnaming = 2;

/// How a table is written.
/// \ingroup winged
pub type hw_table_format = u32;
/// Columns aligned with spaces; a hole is `∅` (UTF-8).
/// \ingroup winged
pub const HW_TABLE_FORMAT_TEXT: hw_table_format = 0;
/// A Markdown table; a hole is `∅`.
/// \ingroup winged
pub const HW_TABLE_FORMAT_MARKDOWN: hw_table_format = 1;
/// Comma-separated values with a header row; a hole is an empty field.
/// \ingroup winged
pub const HW_TABLE_FORMAT_CSV: hw_table_format = 2;

/// Prints a table of the structure in a textbook layout (`which`: ::HW_WTABLE_VERTICES, ...;
/// `naming`: ::HW_WNAMING_CW_CCW, ...; `format`: ::HW_TABLE_FORMAT_TEXT, ...) into `out_text`
/// (`capacity` bytes), NUL-terminated, every line ending with a newline. `*out_needed` (when not
/// NULL) always receives the size needed, terminator included; `HW_ERR_BUFFER_TOO_SMALL` when
/// `out_text` is NULL or shorter (call with `out_text = NULL` to learn the size). Unknown enum
/// values give `HW_ERR_INVALID_INPUT`.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_text` NULL or `capacity` writable bytes;
/// `out_needed` NULL or writable.
/// \ingroup winged
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_table(
    winged: *const hw_winged,
    which: hw_wtable,
    naming: hw_wnaming,
    format: hw_table_format,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_ref(winged) }?;
        let naming = match naming {
            HW_WNAMING_CW_CCW => Naming::ClockwiseCounterclockwise,
            HW_WNAMING_DIRECT_INVERSE => Naming::DirectInverse,
            HW_WNAMING_LEFT_RIGHT => Naming::LeftRight,
            other => return Err(FfiError::invalid_input(format!("unknown naming {other}"))),
        };
        let format = match format {
            HW_TABLE_FORMAT_TEXT => TableFormat::Text,
            HW_TABLE_FORMAT_MARKDOWN => TableFormat::Markdown,
            HW_TABLE_FORMAT_CSV => TableFormat::Csv,
            other => {
                return Err(FfiError::invalid_input(format!(
                    "unknown table format {other}"
                )));
            }
        };
        let text = match which {
            HW_WTABLE_VERTICES => w.vertex_table(naming, format),
            HW_WTABLE_FACES => w.face_table(naming, format),
            HW_WTABLE_EDGES => w.edge_table(naming, format),
            HW_WTABLE_ALL => w.tables(naming, format),
            other => return Err(FfiError::invalid_input(format!("unknown table {other}"))),
        };
        // SAFETY: forwarded from the caller.
        unsafe { copy_text(&text, out_text, capacity, out_needed) }
    })
}
