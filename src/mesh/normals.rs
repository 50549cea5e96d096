//! Face and vertex normals as methods, by the passes of [`crate::geom`] that the winged kernel
//! runs too (Newell face normals, vertex normals summed over every fan of a vertex in one linear
//! pass).

use super::Mesh;
use super::ids::{FaceId, VertexId};
use super::navigation::HandleError;
use crate::geom::{
    PolygonFaces, SmallFace, VertexNormalWeighting, face_area_vector, normalized, vertex_normal_of,
};

impl Mesh {
    /// The unit normal of `f` (Newell's method: exact for planar polygons, the best-fit plane's
    /// normal for non-planar ones); zero for a degenerate face. Points outward for a
    /// counter-clockwise face. What [`Mesh::face_normals`] gives `f`, bit for bit.
    pub fn face_normal(&self, f: FaceId) -> Result<[f64; 3], HandleError> {
        self.try_face_halfedge(f)?;
        Ok(normalized(face_area_vector(self, f)))
    }

    /// Unit normals of all faces, indexed by face id (zero for deleted and degenerate faces);
    /// [`crate::geom::face_normals`].
    pub fn face_normals(&self) -> Vec<[f64; 3]> {
        crate::geom::face_normals(self)
    }

    /// The unit normal of `v`: the normalised sum of the normals of the faces around it, in
    /// every fan of a non-manifold vertex, weighed by `weighting`; zero when it has no face. What
    /// [`Mesh::vertex_normals`] gives `v`, bit for bit.
    pub fn vertex_normal(
        &self,
        v: VertexId,
        weighting: VertexNormalWeighting,
    ) -> Result<[f64; 3], HandleError> {
        self.check_vertex(v)?;
        Ok(vertex_normal_of(self, v.0, weighting))
    }

    /// Unit normals of all vertices under `weighting`, indexed by vertex id (zero for deleted
    /// and isolated vertices); [`crate::geom::vertex_normals`].
    pub fn vertex_normals(&self, weighting: VertexNormalWeighting) -> Vec<[f64; 3]> {
        crate::geom::vertex_normals(self, weighting)
    }
}

/// The faces and corners the normal passes read: a face's corners are the origins of its loop's
/// half-edges, from its stored half-edge.
impl PolygonFaces for Mesh {
    fn positions(&self) -> &[[f64; 3]] {
        Mesh::positions(self)
    }

    fn face_slot_count(&self) -> usize {
        self.n_face_slots()
    }

    fn is_live_face(&self, f: u32) -> bool {
        (f as usize) < self.n_face_slots() && !self.is_face_deleted(FaceId(f))
    }

    fn live_faces(&self) -> impl Iterator<Item = u32> + '_ {
        let check_deleted = self.has_deleted_elements();
        (0..self.n_face_slots() as u32)
            .filter(move |&f| !(check_deleted && self.is_face_deleted(FaceId(f))))
    }

    fn corners(&self, f: u32) -> impl Iterator<Item = u32> + Clone + '_ {
        self.face_loop(FaceId(f)).map(|h| self.origin(h).0)
    }

    #[inline(always)]
    fn small_face(&self, f: u32) -> SmallFace {
        let h0 = self.face_halfedges().get(f as usize).copied();
        SmallFace::of_halfedge(
            self.halfedge_nexts(),
            self.halfedge_prevs(),
            self.halfedge_origins(),
            h0.unwrap_or(u32::MAX),
        )
    }

    fn faces_at(&self, v: u32) -> Vec<u32> {
        let leaving = self.halfedges_leaving_every_fan(VertexId(v));
        leaving
            .into_iter()
            .map(|h| self.face(h))
            .filter(|f| f.is_valid())
            .map(|f| f.0)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::geom::VertexNormalWeighting;
    use crate::mesh::{FaceId, Mesh};
    use crate::soup::{BuildPolicy, FaceList};

    #[test]
    fn methods_give_the_geometry_module_s_normals() {
        // A unit square folded along its diagonal: two faces with different normals.
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 1.0],
            [0.0, 1.0, 0.0],
        ];
        let indices = [0, 1, 2, 0, 2, 3];
        let list = FaceList::triangles(&positions, &indices);
        let (mesh, _) = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap();
        let faces = mesh.face_normals();
        assert_eq!(faces, crate::geom::face_normals(&mesh));
        for f in 0..2 {
            assert_eq!(mesh.face_normal(FaceId(f)), Ok(faces[f as usize]));
        }
        assert_ne!(faces[0], faces[1]);
        assert!(mesh.face_normal(FaceId(2)).is_err());
        for weighting in VertexNormalWeighting::ALL {
            assert_eq!(
                mesh.vertex_normals(weighting),
                crate::geom::vertex_normals(&mesh, weighting)
            );
        }
    }
}
