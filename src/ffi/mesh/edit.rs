//! Editing a `hw_mesh *`: adding and deleting elements, the standard operators, compaction.
//!
//! Every operator checks its preconditions first: a refused operation returns `HW_ERR_REFUSED`
//! (or `HW_ERR_INVALID_HANDLE` for a bad id) with a message, and leaves the mesh exactly as it
//! was. Deletions only mark elements (ids stay stable); hw_mesh_garbage_collect() compacts.
//! Every edit invalidates views taken with hw_mesh_view() and running circulators.

use crate::mesh::{EditError, IndexMaps, VertexId};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{
    Out, arg_mut, arg_ref, arg_slice, give_view, guard, guard_void, point_arg,
};
use crate::ffi::mesh::elements::*;
use crate::ffi::mesh::lifecycle::hw_mesh;

impl From<EditError> for FfiError {
    fn from(error: EditError) -> Self {
        let status = match error {
            EditError::Handle(_) => HW_ERR_INVALID_HANDLE,
            EditError::Refused { .. } | EditError::Full { .. } => HW_ERR_REFUSED,
            EditError::NonFinitePosition { .. } => HW_ERR_INVALID_INPUT,
        };
        FfiError::new(status, error.to_string())
    }
}

/// Runs an edit on a `hw_mesh *` argument.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses.
unsafe fn edit(
    mesh: *mut hw_mesh,
    operation: impl FnOnce(&mut crate::mesh::Mesh) -> Result<(), FfiError>,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    guard(|| operation(&mut unsafe { arg_mut(mesh, "mesh") }?.mesh))
}

/// Adds an isolated vertex at `xyz[0..3]` (finite) and gives its id in `*out_vertex`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `xyz` 3 doubles; `out_vertex`
/// writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_add_vertex(
    mesh: *mut hw_mesh,
    xyz: *const f64,
    out_vertex: *mut hw_vertex,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let out = Out::new(out_vertex, "out_vertex")?;
            let point = point_arg(xyz, "xyz")?;
            let v = mesh.add_vertex(point)?;
            out.write(v.into());
            Ok(())
        })
    }
}

/// Adds the face with corners `vertices[0..n]` (counter-clockwise seen from outside; at least 3,
/// distinct, live) and gives its id in `*out_face`; its loop starts at `vertices[0]`. Existing
/// boundary sides are reused, missing edges created; the face and its corners have zero
/// attributes. `HW_ERR_INVALID_HANDLE` for a bad vertex id; `HW_ERR_REFUSED`, with the mesh
/// unchanged, for fewer than 3 or repeated corners, a side that has a face on this side already
/// (complex edge), or a corner with no gap for the face (complex vertex).
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `vertices` NULL (when `n` is 0) or
/// `n` ids; `out_face` writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_add_face(
    mesh: *mut hw_mesh,
    vertices: *const hw_vertex,
    n: usize,
    out_face: *mut hw_face,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let out = Out::new(out_face, "out_face")?;
            let corners: Vec<VertexId> = arg_slice(vertices, n, "vertices")?
                .iter()
                .map(|&v| v.into())
                .collect();
            let f = mesh.add_face(&corners)?;
            out.write(f.into());
            Ok(())
        })
    }
}

/// Deletes face `f`; its edges with no face left go too, and, when `delete_isolated_vertices`,
/// its vertices left without edges.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_delete_face(
    mesh: *mut hw_mesh,
    f: hw_face,
    delete_isolated_vertices: bool,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            Ok(mesh.delete_face(f.into(), delete_isolated_vertices)?)
        })
    }
}

/// Deletes edge `e` with the faces on both its sides (see hw_mesh_delete_face()).
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_delete_edge(
    mesh: *mut hw_mesh,
    e: hw_edge,
    delete_isolated_vertices: bool,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            Ok(mesh.delete_edge(e.into(), delete_isolated_vertices)?)
        })
    }
}

/// Deletes vertex `v` with every face around it.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_delete_vertex(mesh: *mut hw_mesh, v: hw_vertex) -> hw_status {
    unsafe { edit(mesh, |mesh| Ok(mesh.delete_vertex(v.into())?)) }
}

/// Flips interior edge `e` between two triangles to join their other two corners. Refused on a
/// boundary edge, between non-triangles, or when the new edge exists already.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_flip_edge(mesh: *mut hw_mesh, e: hw_edge) -> hw_status {
    unsafe { edit(mesh, |mesh| Ok(mesh.flip_edge(e.into())?)) }
}

/// Splits edge `e` at a new vertex placed at `xyz[0..3]`, given in `*out_vertex`; the faces beside
/// the edge gain a corner (they are not triangulated).
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `xyz` 3 doubles; `out_vertex`
/// writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_split_edge(
    mesh: *mut hw_mesh,
    e: hw_edge,
    xyz: *const f64,
    out_vertex: *mut hw_vertex,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let out = Out::new(out_vertex, "out_vertex")?;
            let v = mesh.split_edge(e.into(), point_arg(xyz, "xyz")?)?;
            out.write(v.into());
            Ok(())
        })
    }
}

/// Splits the face holding half-edges `h0` and `h1` with a new edge from `target(h0)` to
/// `target(h1)`; `*out_halfedge` receives the new half-edge inside the original face.
/// `HW_ERR_REFUSED`, the mesh unchanged, when the two corners are one vertex or already joined
/// by an edge, or a side would have fewer than 3 corners.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_halfedge` writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_split_face(
    mesh: *mut hw_mesh,
    h0: hw_halfedge,
    h1: hw_halfedge,
    out_halfedge: *mut hw_halfedge,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let out = Out::new(out_halfedge, "out_halfedge")?;
            let h = mesh.split_face(h0.into(), h1.into())?;
            out.write(h.into());
            Ok(())
        })
    }
}

/// Collapses half-edge `h`: its origin merges into its target (which keeps its position, given in
/// `*out_vertex`). Refused unless the link condition holds and the triangles beside the edge can
/// vanish without breaking the surface.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_vertex` writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_collapse_halfedge(
    mesh: *mut hw_mesh,
    h: hw_halfedge,
    out_vertex: *mut hw_vertex,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let out = Out::new(out_vertex, "out_vertex")?;
            let kept = mesh.collapse_halfedge(h.into())?;
            out.write(kept.into());
            Ok(())
        })
    }
}

/// Splits polygon `f` into triangles, the ones the render buffers draw for it (none folded on a
/// non-convex face; O(n log n) for n corners); `*out_n_faces`, when not NULL, receives the number
/// of triangles (`f` is the first of them). When a diagonal of those triangles is an edge
/// already, a few other triangulations are tried; `HW_ERR_REFUSED`, the mesh unchanged, when
/// each needs an existing edge or joins a vertex to itself.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_n_faces` NULL or writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_triangulate_face(
    mesh: *mut hw_mesh,
    f: hw_face,
    out_n_faces: *mut usize,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let triangles = mesh.triangulate_face(f.into())?;
            if let Some(out) = Out::optional(out_n_faces) {
                out.write(triangles.len());
            }
            Ok(())
        })
    }
}

/// The old-to-new id maps of a compaction (see hw_mesh_garbage_collect()). Opaque; read with
/// hw_index_maps_view(), release with hw_index_maps_free().
/// \ingroup edit
pub struct hw_index_maps {
    pub(crate) maps: IndexMaps,
}

/// Removes deleted elements for good, renumbering the live ones in their order. When
/// `out_maps` is not NULL it receives the old-to-new maps (deleted → `HW_INVALID_INDEX`).
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_maps` NULL or writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_garbage_collect(
    mesh: *mut hw_mesh,
    out_maps: *mut *mut hw_index_maps,
) -> hw_status {
    unsafe {
        edit(mesh, |mesh| {
            let out = Out::optional(out_maps);
            let maps = mesh.garbage_collect();
            if let Some(out) = out {
                out.write(into_handle(hw_index_maps { maps }));
            }
            Ok(())
        })
    }
}

/// A read-only view of the old-to-new map of one element kind (`*out_map`, NULL when empty, with
/// `*out_len` entries, one per old id slot). Lives as long as the maps.
///
/// # Safety
/// `maps` must be NULL or live; `out_map` and `out_len` writable.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_index_maps_view(
    maps: *const hw_index_maps,
    kind: hw_element_kind,
    out_map: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_map, "out_map", out_len, || {
            let maps = &arg_ref(maps, "maps")?.maps;
            match kind {
                HW_ELEMENT_KIND_VERTEX => Ok(&maps.vertices[..]),
                HW_ELEMENT_KIND_HALFEDGE => Ok(&maps.halfedges[..]),
                HW_ELEMENT_KIND_EDGE => Ok(&maps.edges[..]),
                HW_ELEMENT_KIND_FACE => Ok(&maps.faces[..]),
                other => Err(FfiError::invalid_input(format!(
                    "unknown element kind {other}"
                ))),
            }
        })
    }
}

/// Releases index maps. NULL is a no-op; a second free is refused (within the limits the
/// ownership conventions at the top of the header state).
///
/// # Safety
/// `maps` must be NULL or maps from this library, not in use by another thread.
/// \ingroup edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_index_maps_free(maps: *mut hw_index_maps) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(maps, "hw_index_maps") });
}
