//! The navigation view: every connectivity array of a mesh in one struct, for the inline
//! navigation and circulators of `include/halfwing_nav.h` (steps that compile to array reads).
//!
//! The view is handed out by one checked call and stays valid until the next call that modifies
//! the mesh; the inline functions then trust the ids they are given.

use crate::mesh::Mesh;

use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, guard, view_start};
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// A navigation view of a mesh: its connectivity arrays (zero-copy, as hw_mesh_view() gives them)
/// and their sizes, filled by hw_mesh_nav() and read by the inline `hw_nav_*` functions of
/// halfwing_nav.h. Valid until the next call that modifies the mesh (or frees it). Arrays are
/// indexed by id, deleted slots included until hw_mesh_garbage_collect(); an unused slot holds
/// `HW_INVALID_INDEX`. A pointer is NULL when its array is empty.
/// \ingroup nav
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_nav {
    /// Per half-edge: the vertex it leaves.
    pub origin: *const u32,
    /// Per half-edge: the next half-edge around its face or boundary loop.
    pub next: *const u32,
    /// Per half-edge: the previous half-edge around its face or boundary loop.
    pub prev: *const u32,
    /// Per half-edge: its face (`HW_INVALID_INDEX` on a boundary).
    pub face: *const u32,
    /// Per vertex: its outgoing half-edge (the boundary one on a boundary; invalid when isolated
    /// or deleted).
    pub vertex_halfedge: *const u32,
    /// Per face: one of its half-edges.
    pub face_halfedge: *const u32,
    /// Per vertex slot: `true` when deleted; NULL while no vertex has been deleted.
    pub vertex_deleted: *const bool,
    /// Per edge slot: `true` when deleted (both half-edges); NULL while no edge has been deleted.
    pub edge_deleted: *const bool,
    /// Per face slot: `true` when deleted; NULL while no face has been deleted.
    pub face_deleted: *const bool,
    /// Vertex slots (valid vertex ids are below this), deleted ones included.
    pub n_vertex_slots: usize,
    /// Half-edge slots, deleted ones included.
    pub n_halfedge_slots: usize,
    /// Face slots, deleted ones included.
    pub n_face_slots: usize,
}

impl hw_nav {
    fn of(mesh: &Mesh) -> Self {
        hw_nav {
            origin: view_start(mesh.halfedge_origins()),
            next: view_start(mesh.halfedge_nexts()),
            prev: view_start(mesh.halfedge_prevs()),
            face: view_start(mesh.halfedge_faces()),
            vertex_halfedge: view_start(mesh.vertex_halfedges()),
            face_halfedge: view_start(mesh.face_halfedges()),
            vertex_deleted: view_start(mesh.vertex_deletion_marks()),
            edge_deleted: view_start(mesh.edge_deletion_marks()),
            face_deleted: view_start(mesh.face_deletion_marks()),
            n_vertex_slots: mesh.n_vertex_slots(),
            n_halfedge_slots: mesh.n_halfedge_slots(),
            n_face_slots: mesh.n_face_slots(),
        }
    }
}

/// Fills `*out` with the navigation view of `mesh` (see ::hw_nav and halfwing_nav.h).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out` NULL or writable.
/// \ingroup nav
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_nav(mesh: *const hw_mesh, out: *mut hw_nav) -> hw_status {
    guard(|| {
        let out = Out::new(out, "out")?;
        // SAFETY: forwarded from the caller.
        let nav = hw_nav::of(unsafe { mesh_ref(mesh) }?);
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(nav) };
        Ok(())
    })
}
