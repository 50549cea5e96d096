//! Faces back out as an indexed face list.

use crate::soup::PolygonSoup;

use super::Mesh;
use super::ids::{FaceId, INVALID_INDEX, VertexId};

impl Mesh {
    /// The live faces as an indexed face list, corners in face-loop order from
    /// [`Mesh::face_halfedge`]. Deleted vertices and faces are compacted away (live elements keep
    /// their relative order); isolated vertices are kept. Building from the result reproduces
    /// the mesh.
    pub fn to_soup(&self) -> PolygonSoup {
        let mut new_index = vec![INVALID_INDEX; self.vertex_capacity()];
        let mut positions = Vec::with_capacity(self.n_vertices());
        for (v, slot) in new_index.iter_mut().enumerate() {
            if !self.is_vertex_deleted(VertexId(v as u32)) {
                *slot = positions.len() as u32;
                positions.push(self.positions[v]);
            }
        }
        let mut face_sizes = Vec::with_capacity(self.n_faces());
        let mut indices = Vec::with_capacity(self.n_halfedges());
        for f in 0..self.face_capacity() {
            let f = FaceId(f as u32);
            if self.is_face_deleted(f) {
                continue;
            }
            let start = indices.len();
            indices.extend(
                self.face_vertices(f)
                    .map(|v| new_index.get(v.idx()).copied().unwrap_or(INVALID_INDEX)),
            );
            face_sizes.push((indices.len() - start) as u32);
        }
        PolygonSoup {
            positions,
            face_sizes,
            indices,
            corner_normals: None,
            corner_uvs: None,
        }
    }
}
