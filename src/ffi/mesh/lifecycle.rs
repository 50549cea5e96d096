//! `hw_mesh`: the half-edge mesh object — creation from an indexed face list, counts, release.

use crate::mesh::Mesh;
use crate::soup::{BuildError, BuildPolicy};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{arg_ref, guard_value, guard_void};
use crate::ffi::mesh::diagnostic::{give_built, hw_diagnostic};

/// A half-edge polygon mesh. Opaque; create it with hw_mesh_new() or hw_mesh_from_indexed() and
/// release it with hw_mesh_free().
/// \ingroup mesh
pub struct hw_mesh {
    pub(crate) mesh: Mesh,
}

/// What hw_mesh_from_indexed() does with faces that cannot be placed in a half-edge structure.
/// \ingroup mesh
#[allow(non_camel_case_types)]
pub type hw_build_policy = u32;
/// Build the input exactly as it is, or refuse it whole: `HW_ERR_INVALID_INPUT` for a malformed
/// face or a NaN/infinite coordinate, `HW_ERR_NON_MANIFOLD` for a non-manifold or inconsistently
/// oriented edge or a non-manifold vertex. The message names the offending faces, edges and
/// vertices.
/// \ingroup mesh
pub const HW_BUILD_POLICY_STRICT: hw_build_policy = 0;
/// Leave out what cannot be placed, and list it (::HW_DIAGNOSTIC_LIST_SKIPPED_FACES): malformed
/// faces, faces on a NaN/infinite vertex, then, in input order, a face whose edge is already used
/// in its direction; split non-manifold vertices (one vertex per fan,
/// ::HW_DIAGNOSTIC_LIST_VERTEX_COPIES).
/// \ingroup mesh
pub const HW_BUILD_POLICY_SKIP: hw_build_policy = 1;
/// Keep every face that can be kept, and make it fit: collapse repeated corners, reverse faces so
/// neighbours agree (::HW_DIAGNOSTIC_LIST_REORIENTED_FACES), cut the surface along edges still
/// non-manifold or inconsistent and give each fan its own vertex, split non-manifold vertices, and
/// turn every closed component to face outward. Faces that cannot be kept (fewer than 3 distinct
/// corners, an out-of-range index, a corner on a NaN/infinite vertex) are left out and listed
/// (::HW_DIAGNOSTIC_LIST_SKIPPED_FACES). Accepts every input ::HW_BUILD_POLICY_SKIP accepts.
/// \ingroup mesh
pub const HW_BUILD_POLICY_REPAIR: hw_build_policy = 2;

pub(crate) fn build_policy(raw: hw_build_policy) -> Result<BuildPolicy, FfiError> {
    match raw {
        HW_BUILD_POLICY_STRICT => Ok(BuildPolicy::Strict),
        HW_BUILD_POLICY_SKIP => Ok(BuildPolicy::Skip),
        HW_BUILD_POLICY_REPAIR => Ok(BuildPolicy::Repair),
        other => Err(FfiError::invalid_input(format!(
            "unknown build policy {other}"
        ))),
    }
}

impl From<BuildError> for FfiError {
    fn from(error: BuildError) -> Self {
        let status = match &error {
            BuildError::NonManifold(_) => HW_ERR_NON_MANIFOLD,
            BuildError::InvalidInput(_) => HW_ERR_INVALID_INPUT,
            BuildError::OutOfMemory(_) => HW_ERR_OUT_OF_MEMORY,
        };
        FfiError::new(status, error.to_string())
    }
}

/// Borrows the mesh of a `const hw_mesh *` argument.
///
/// # Safety
/// `mesh` must be NULL or a live `hw_mesh`.
pub(crate) unsafe fn mesh_ref<'a>(mesh: *const hw_mesh) -> Result<&'a Mesh, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(mesh, "mesh") }?.mesh)
}

/// Creates an empty mesh. Returns NULL only if the allocation fails.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub extern "C" fn hw_mesh_new() -> *mut hw_mesh {
    guard_value(std::ptr::null_mut(), || {
        Ok(into_handle(hw_mesh {
            mesh: Mesh::default(),
        }))
    })
}

/// Builds a mesh from an indexed polygon list.
///
/// `positions` holds `3 * n_vertices` doubles (x, y, z per vertex); `face_sizes` holds the corner
/// count of each of the `n_faces` faces; `indices` holds the `n_indices` vertex indices of all
/// corners, face after face (so `n_indices` must equal the sum of `face_sizes`). Faces are
/// counter-clockwise seen from outside. Pairing is done in bulk by sorting edge keys.
///
/// `policy` decides what happens to faces that do not fit a half-edge structure (see
/// ::HW_BUILD_POLICY_STRICT, ::HW_BUILD_POLICY_SKIP, ::HW_BUILD_POLICY_REPAIR). Malformed data —
/// sizes below 3 or not summing to `n_indices`, indices out of range, NaN or infinite coordinates —
/// give `HW_ERR_INVALID_INPUT` under ::HW_BUILD_POLICY_STRICT; the message names the faces and
/// vertices.
///
/// Whatever the policy, the mesh holds no NaN or infinite coordinate (such a vertex is there as a
/// deleted vertex, its id kept) and no non-manifold vertex: every vertex query (valence,
/// circulators, normals) sees every face at its vertex.
///
/// On success `*out_mesh` receives a new mesh to release with hw_mesh_free(), and, when
/// `out_diagnostic` is not NULL, `*out_diagnostic` a diagnostic of the input and of what the
/// policy changed, to release with hw_diagnostic_free(). When the policy refuses the input,
/// `*out_mesh` is not written but `*out_diagnostic` (when asked for) receives the refusal's
/// diagnostic, to release the same way; on any other failure neither is written.
///
/// # Safety
/// Array arguments must point to at least as many elements as their counts say (they may be NULL
/// when the count is 0); `out_mesh` must be writable; `out_diagnostic` NULL or writable.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_from_indexed(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    policy: hw_build_policy,
    out_mesh: *mut *mut hw_mesh,
    out_diagnostic: *mut *mut hw_diagnostic,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_built(out_mesh, "out_mesh", out_diagnostic, || {
            let list = face_list_arg(
                positions, n_vertices, face_sizes, n_faces, indices, n_indices,
            )?;
            let policy = build_policy(policy)?;
            let built = with_threads(|| Mesh::from_face_list(&list, policy));
            Ok(built.map(|(mesh, diagnostic)| (hw_mesh { mesh }, diagnostic)))
        })
    }
}

/// Releases a mesh. NULL is a no-op; a mesh freed already is refused, the last error saying so
/// (within the limits the ownership conventions at the top of the header state).
///
/// # Safety
/// `mesh` must be NULL or a mesh from this library not in use by another thread.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_free(mesh: *mut hw_mesh) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(mesh, "hw_mesh") });
}

/// Answers a value-returning query on a `const hw_mesh *`: `fallback` (with the error recorded)
/// for a NULL mesh or when the query fails.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
pub(crate) unsafe fn query<T>(
    mesh: *const hw_mesh,
    fallback: T,
    answer: impl FnOnce(&Mesh) -> Result<T, FfiError>,
) -> T {
    // SAFETY: forwarded from the caller.
    guard_value(fallback, || answer(unsafe { mesh_ref(mesh) }?))
}

/// Reads one count of a mesh; 0 (with the error recorded) for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
unsafe fn count(mesh: *const hw_mesh, of: impl FnOnce(&Mesh) -> usize) -> usize {
    // SAFETY: forwarded from the caller.
    unsafe { query(mesh, 0, |mesh| Ok(of(mesh))) }
}

// cbindgen reads these signatures as written, so they are spelled out rather than generated.

/// Number of vertices (deleted ones not counted); 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_vertices(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_vertices) }
}

/// Number of faces (deleted ones not counted); 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_faces(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_faces) }
}

/// Number of undirected edges (deleted ones not counted); 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_edges(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_edges) }
}

/// Number of half-edges, boundary ones included (twice the edge count); 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_halfedges(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_halfedges) }
}

/// Number of vertex slots: vertex ids run from 0 to this minus one. Equal to the vertex count
/// unless vertices were deleted and not yet garbage-collected; arrays indexed by vertex id (views,
/// normals) have this length. 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_vertex_slots(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_vertex_slots) }
}

/// Number of half-edge slots (twice the edge slots), as hw_mesh_n_vertex_slots() counts vertex
/// slots; 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_halfedge_slots(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_halfedge_slots) }
}

/// Number of edge slots, as hw_mesh_n_vertex_slots() counts vertex slots; 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_edge_slots(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_edge_slots) }
}

/// Number of face slots, as hw_mesh_n_vertex_slots() counts vertex slots; 0 for a NULL mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_face_slots(mesh: *const hw_mesh) -> usize {
    unsafe { count(mesh, Mesh::n_face_slots) }
}
