//! Assembling a mesh from connectivity arrays made elsewhere in the crate (the winged-edge
//! kernel's conversion), checked before it is handed out.

use super::check::InvariantError;
use super::connectivity::{Deletions, Mesh};

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
}

impl Mesh {
    /// The mesh of `arrays`, after [`Mesh::check`] accepted it: arrays from a converter can
    /// never yield a mesh that breaks the kernel's invariants.
    pub(crate) fn from_arrays(arrays: MeshArrays) -> Result<Mesh, InvariantError> {
        let mut mesh = Mesh {
            origin: arrays.origin,
            next: arrays.next,
            prev: arrays.prev,
            face: arrays.face,
            vertex_halfedge: arrays.vertex_halfedge,
            positions: arrays.positions,
            face_halfedge: arrays.face_halfedge,
            deleted: Deletions::default(),
            // Until the vertices are looked at below, operators must not assume single fans.
            may_have_pinched_vertices: true,
            attributes: Default::default(),
        };
        mesh.check()?;
        mesh.may_have_pinched_vertices = !mesh.non_manifold_vertices().is_empty();
        Ok(mesh)
    }
}
