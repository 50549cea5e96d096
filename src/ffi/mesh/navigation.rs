//! Navigation on a `const hw_mesh *`: one step from an element to its neighbour.
//!
//! These return the id (or value) directly so that textbook half-edge loops read almost word for
//! word in C:
//! ```c
//! hw_halfedge start = hw_mesh_face_halfedge(mesh, f), h = start;
//! do { visit(h); h = hw_mesh_he_next(mesh, h); } while (h.idx != start.idx);
//! ```
//! An invalid, out-of-range or deleted id (or a NULL mesh) gives an invalid id (`HW_INVALID_INDEX`),
//! `false` or 0, and records an `HW_ERR_INVALID_HANDLE` message; it never crashes.

use crate::ffi::boundary::error::FfiError;
use crate::ffi::mesh::elements::{hw_edge, hw_face, hw_halfedge, hw_vertex};
use crate::ffi::mesh::lifecycle::{hw_mesh, query};

/// The vertex half-edge `h` leaves (`Origin` or `v` in textbook notation).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_origin(mesh: *const hw_mesh, h: hw_halfedge) -> hw_vertex {
    unsafe {
        query(mesh, hw_vertex::INVALID, |m| {
            Ok(m.try_origin(h.into())?.into())
        })
    }
}

/// The vertex half-edge `h` points to.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_target(mesh: *const hw_mesh, h: hw_halfedge) -> hw_vertex {
    unsafe {
        query(mesh, hw_vertex::INVALID, |m| {
            Ok(m.try_target(h.into())?.into())
        })
    }
}

/// The opposite half-edge of `h` (`h.idx ^ 1`; `Twin` or `sym` in textbook notation).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_twin(mesh: *const hw_mesh, h: hw_halfedge) -> hw_halfedge {
    unsafe {
        query(mesh, hw_halfedge::INVALID, |m| {
            Ok(m.try_twin(h.into())?.into())
        })
    }
}

/// The next half-edge around `h`'s face (counter-clockwise seen from outside), or along its
/// boundary loop when `h` is a boundary half-edge.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_next(mesh: *const hw_mesh, h: hw_halfedge) -> hw_halfedge {
    unsafe {
        query(mesh, hw_halfedge::INVALID, |m| {
            Ok(m.try_next(h.into())?.into())
        })
    }
}

/// The previous half-edge around `h`'s face or boundary loop.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_prev(mesh: *const hw_mesh, h: hw_halfedge) -> hw_halfedge {
    unsafe {
        query(mesh, hw_halfedge::INVALID, |m| {
            Ok(m.try_prev(h.into())?.into())
        })
    }
}

/// The face `h` borders; an invalid face (without an error) for a boundary half-edge.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_face(mesh: *const hw_mesh, h: hw_halfedge) -> hw_face {
    unsafe { query(mesh, hw_face::INVALID, |m| Ok(m.try_face(h.into())?.into())) }
}

/// The undirected edge of `h` (`h.idx >> 1`).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_edge(mesh: *const hw_mesh, h: hw_halfedge) -> hw_edge {
    unsafe { query(mesh, hw_edge::INVALID, |m| Ok(m.try_edge(h.into())?.into())) }
}

/// One of the two half-edges of `e`: `side` 0 gives `2 e`, 1 gives `2 e + 1`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_edge_halfedge(
    mesh: *const hw_mesh,
    e: hw_edge,
    side: u32,
) -> hw_halfedge {
    unsafe {
        query(mesh, hw_halfedge::INVALID, |m| {
            if side > 1 {
                return Err(FfiError::invalid_input(format!(
                    "edge side {side} is not 0 or 1"
                )));
            }
            Ok(m.try_edge_halfedge(e.into(), side)?.into())
        })
    }
}

/// The outgoing half-edge stored at `v` (its boundary half-edge when `v` is on a boundary, so
/// circulating from it visits the whole fan); invalid, without an error, for an isolated vertex.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_vertex_halfedge(
    mesh: *const hw_mesh,
    v: hw_vertex,
) -> hw_halfedge {
    unsafe {
        query(mesh, hw_halfedge::INVALID, |m| {
            Ok(m.try_vertex_halfedge(v.into())?.into())
        })
    }
}

/// One half-edge of `f` (where its loops start).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_face_halfedge(mesh: *const hw_mesh, f: hw_face) -> hw_halfedge {
    unsafe {
        query(mesh, hw_halfedge::INVALID, |m| {
            Ok(m.try_face_halfedge(f.into())?.into())
        })
    }
}

/// `true` when `h` has no face (it lies on a boundary loop).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_he_is_boundary(mesh: *const hw_mesh, h: hw_halfedge) -> bool {
    unsafe { query(mesh, false, |m| Ok(m.try_is_boundary_halfedge(h.into())?)) }
}

/// `true` when one side of `e` has no face.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_edge_is_boundary(mesh: *const hw_mesh, e: hw_edge) -> bool {
    unsafe { query(mesh, false, |m| Ok(m.try_is_boundary_edge(e.into())?)) }
}

/// `true` when `v` is on a boundary (or isolated).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_vertex_is_boundary(mesh: *const hw_mesh, v: hw_vertex) -> bool {
    unsafe { query(mesh, false, |m| Ok(m.try_is_boundary_vertex(v.into())?)) }
}

/// `true` when a side of `f` is on a boundary.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_face_is_boundary(mesh: *const hw_mesh, f: hw_face) -> bool {
    unsafe { query(mesh, false, |m| Ok(m.try_is_boundary_face(f.into())?)) }
}

/// Number of edges at `v` (0 when isolated, or for an invalid id).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_vertex_valence(mesh: *const hw_mesh, v: hw_vertex) -> u32 {
    unsafe { query(mesh, 0, |m| Ok(m.try_valence(v.into())? as u32)) }
}

/// Number of sides of `f` (0 for an invalid id).
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_face_degree(mesh: *const hw_mesh, f: hw_face) -> u32 {
    unsafe { query(mesh, 0, |m| Ok(m.try_face_degree(f.into())? as u32)) }
}
