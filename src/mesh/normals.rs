//! Face and vertex normals as methods, by the passes of [`crate::geom`] (Newell face normals,
//! vertex normals summed over every fan of a vertex in one linear pass).

use super::Mesh;
use super::ids::FaceId;
use super::navigation::HandleError;
use crate::geom::{VertexNormalWeighting, face_area_vector, normalized};

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

    /// Unit normals of all vertices under `weighting`, indexed by vertex id (zero for deleted
    /// and isolated vertices); [`crate::geom::vertex_normals`].
    pub fn vertex_normals(&self, weighting: VertexNormalWeighting) -> Vec<[f64; 3]> {
        crate::geom::vertex_normals(self, weighting)
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
        for weighting in [
            VertexNormalWeighting::Uniform,
            VertexNormalWeighting::Area,
            VertexNormalWeighting::Angle,
        ] {
            assert_eq!(
                mesh.vertex_normals(weighting),
                crate::geom::vertex_normals(&mesh, weighting)
            );
        }
    }
}
