//! Assembling a mesh from connectivity arrays made elsewhere in the crate (the winged-edge
//! kernel's conversion), checked before it is handed out.

use super::check::InvariantError;
use super::structure::{Deletions, Mesh};

/// The arrays of a mesh without deletions or attributes, in [`Mesh`]'s layout: per half-edge `origin`,
/// `next`, `prev`, `face` (half-edge `2e` and `2e + 1` form edge `e`), per vertex its outgoing
/// half-edge and position, per face one half-edge; `u32::MAX` means none.
pub(crate) struct MeshArrays {
    pub(crate) origin: Vec<u32>,
    pub(crate) next: Vec<u32>,
    pub(crate) prev: Vec<u32>,
    pub(crate) face: Vec<u32>,
    pub(crate) vertex_halfedge: Vec<u32>,
    pub(crate) positions: Vec<[f64; 3]>,
    pub(crate) face_halfedge: Vec<u32>,
    /// Deletion marks per vertex, edge and face (each empty, or as long as its element array).
    pub(crate) deleted_vertices: Vec<bool>,
    pub(crate) deleted_edges: Vec<bool>,
    pub(crate) deleted_faces: Vec<bool>,
}

/// Deletion marks as the mesh keeps them: an empty vector when nothing is deleted.
fn marks(flags: Vec<bool>) -> (Vec<bool>, usize) {
    match flags.iter().filter(|&&deleted| deleted).count() {
        0 => (Vec::new(), 0),
        n => (flags, n),
    }
}

impl Mesh {
    /// The mesh of `arrays`, after [`Mesh::check`] accepted it: arrays from a converter can
    /// never yield a mesh that breaks the kernel's invariants.
    pub(crate) fn from_arrays(arrays: MeshArrays) -> Result<Mesh, InvariantError> {
        let (vertices, n_vertices) = marks(arrays.deleted_vertices);
        let (edges, n_edges) = marks(arrays.deleted_edges);
        let (faces, n_faces) = marks(arrays.deleted_faces);
        let mut mesh = Mesh {
            origin: arrays.origin,
            next: arrays.next,
            prev: arrays.prev,
            face: arrays.face,
            vertex_halfedge: arrays.vertex_halfedge,
            positions: arrays.positions,
            face_halfedge: arrays.face_halfedge,
            deleted: Deletions {
                vertices,
                edges,
                faces,
                n_vertices,
                n_edges,
                n_faces,
            },
            // Until the vertices are looked at below, operators must not assume single fans.
            may_have_pinched_vertices: true,
            attributes: Default::default(),
        };
        mesh.check()?;
        mesh.may_have_pinched_vertices = !mesh.non_manifold_vertices().is_empty();
        Ok(mesh)
    }
}
