//! The index maps of a mesh repair that changed nothing.

use crate::mesh::{IndexMaps, Mesh};

/// Identity maps of every slot of the mesh's vertices, half-edges, edges and faces.
pub(super) fn identity_maps(mesh: &Mesh) -> IndexMaps {
    IndexMaps {
        vertices: (0..mesh.n_vertex_slots() as u32).collect(),
        halfedges: (0..mesh.n_halfedge_slots() as u32).collect(),
        edges: (0..mesh.n_edge_slots() as u32).collect(),
        faces: (0..mesh.n_face_slots() as u32).collect(),
    }
}
