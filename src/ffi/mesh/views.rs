//! Zero-copy, read-only views of a mesh's internal arrays, for C code that wants raw speed.
//!
//! A view stays valid until the next call that modifies the mesh (or frees it). Arrays are
//! indexed by element id and include deleted elements until hw_mesh_garbage_collect(); an
//! unused slot holds `HW_INVALID_INDEX`. The twin of half-edge `h` is `h ^ 1` and its edge
//! `h >> 1`, so they need no array. A one-ring walk in C:
//! ```c
//! uint32_t h = vertex_halfedge[v], start = h;
//! if (h != HW_INVALID_INDEX) do { visit(h); h = prev[h] ^ 1u; } while (h != start);
//! ```

use crate::mesh::Mesh;

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, give_view, guard, write_tuple_view};
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// Which internal array hw_mesh_view() shows.
/// \ingroup navigation
pub type hw_mesh_array = u32;
/// Per half-edge: the vertex it leaves.
/// \ingroup navigation
pub const HW_MESH_ARRAY_HALFEDGE_ORIGIN: hw_mesh_array = 0;
/// Per half-edge: the next half-edge around its face or boundary loop.
/// \ingroup navigation
pub const HW_MESH_ARRAY_HALFEDGE_NEXT: hw_mesh_array = 1;
/// Per half-edge: the previous half-edge around its face or boundary loop.
/// \ingroup navigation
pub const HW_MESH_ARRAY_HALFEDGE_PREV: hw_mesh_array = 2;
/// Per half-edge: its face (`HW_INVALID_INDEX` on a boundary).
/// \ingroup navigation
pub const HW_MESH_ARRAY_HALFEDGE_FACE: hw_mesh_array = 3;
/// Per vertex: its outgoing half-edge (the boundary one on a boundary; invalid when isolated).
/// \ingroup navigation
pub const HW_MESH_ARRAY_VERTEX_HALFEDGE: hw_mesh_array = 4;
/// Per face: one of its half-edges.
/// \ingroup navigation
pub const HW_MESH_ARRAY_FACE_HALFEDGE: hw_mesh_array = 5;

fn array(mesh: &Mesh, which: hw_mesh_array) -> Result<&[u32], FfiError> {
    Ok(match which {
        HW_MESH_ARRAY_HALFEDGE_ORIGIN => mesh.halfedge_origins(),
        HW_MESH_ARRAY_HALFEDGE_NEXT => mesh.halfedge_nexts(),
        HW_MESH_ARRAY_HALFEDGE_PREV => mesh.halfedge_prevs(),
        HW_MESH_ARRAY_HALFEDGE_FACE => mesh.halfedge_faces(),
        HW_MESH_ARRAY_VERTEX_HALFEDGE => mesh.vertex_halfedges(),
        HW_MESH_ARRAY_FACE_HALFEDGE => mesh.face_halfedges(),
        other => {
            return Err(FfiError::invalid_input(format!(
                "unknown mesh array {other}"
            )));
        }
    })
}

/// A read-only view of one connectivity array: `*out_data` (NULL when empty) and its length
/// `*out_len`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_data` and `out_len` writable.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_view(
    mesh: *const hw_mesh,
    which: hw_mesh_array,
    out_data: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_data, "out_data", out_len, || {
            array(mesh_ref(mesh)?, which)
        })
    }
}

/// A read-only view of the vertex positions: `*out_xyz` holds `3 * *out_n_vertices` doubles
/// (x, y, z per vertex; NULL when there are none).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_xyz` and `out_n_vertices` writable.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_view_positions(
    mesh: *const hw_mesh,
    out_xyz: *mut *const f64,
    out_n_vertices: *mut usize,
) -> hw_status {
    guard(|| {
        let out_xyz = Out::new(out_xyz, "out_xyz")?;
        let out_n = Out::new(out_n_vertices, "out_n_vertices")?;
        // SAFETY: forwarded from the caller.
        let positions = unsafe { mesh_ref(mesh) }?.positions();
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { write_tuple_view(out_xyz, out_n, positions) };
        Ok(())
    })
}
