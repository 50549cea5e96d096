//! Faces back out as an indexed face list.

use crate::soup::PolygonSoup;

use super::Mesh;
use super::ids::{FaceId, HalfedgeId, INVALID_INDEX, VertexId};

impl Mesh {
    /// The live faces as an indexed face list, corners in face-loop order from
    /// [`Mesh::face_halfedge`]. Deleted vertices and faces are compacted away (live elements keep
    /// their relative order); isolated vertices are kept. Corner normals and texture
    /// coordinates, when the mesh has them, become the soup's per-corner arrays. Building from
    /// the result with [`Mesh::from_soup`] reproduces the mesh.
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
        let mut corners = Vec::with_capacity(self.n_halfedges());
        for f in 0..self.face_capacity() {
            let f = FaceId(f as u32);
            if self.is_face_deleted(f) {
                continue;
            }
            let start = corners.len();
            corners.extend(self.face_loop(f));
            face_sizes.push((corners.len() - start) as u32);
        }
        let indices = corners
            .iter()
            .map(|&h| {
                let v = self.origin(h);
                new_index.get(v.index()).copied().unwrap_or(INVALID_INDEX)
            })
            .collect();
        PolygonSoup {
            positions,
            face_sizes,
            indices,
            corner_normals: self.corner_normals().map(|n| per_corner(n, &corners)),
            corner_uvs: self.corner_uvs().map(|uv| per_corner(uv, &corners)),
        }
    }
}

/// The values of the given half-edges, in order.
fn per_corner<T: Copy>(values: &[T], corners: &[HalfedgeId]) -> Vec<T> {
    corners.iter().map(|h| values[h.index()]).collect()
}
