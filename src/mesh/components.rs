//! Connected components: faces reachable from each other across shared edges.

use super::Mesh;
use super::ids::{EdgeId, FaceId, INVALID_INDEX};
use crate::support::disjoint_sets;

/// The faces of a mesh split into edge-connected components.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Components {
    /// Number of components.
    pub count: usize,
    /// Component of each face, `0..count`, numbered in order of their lowest face;
    /// `INVALID_INDEX` for deleted faces. Indexed by face id.
    pub face_component: Vec<u32>,
}

impl Mesh {
    /// Splits the faces into components connected across edges (as CGAL's
    /// `connected_components` and OpenMesh's do). Two fans that only touch at a non-manifold
    /// vertex are separate components; isolated vertices belong to none.
    ///
    /// Union-find over the faces, in one sequential pass over the edges (each edge joins the
    /// faces of its two half-edges), instead of a search that hops from face to face: every
    /// array is read in order except the forest itself. Roots are always the smallest face of
    /// their set, so the forest turns into the component numbering in place, in one more pass.
    pub fn connected_components(&self) -> Components {
        let n_faces = self.n_face_slots();
        // parent[f] <= f; a root is its own parent.
        let mut parent: Vec<u32> = (0..n_faces as u32).collect();
        let check_deleted = self.has_deleted_elements();
        for (e, faces) in self.face.chunks_exact(2).enumerate() {
            let (a, b) = (faces[0], faces[1]);
            if a == INVALID_INDEX
                || b == INVALID_INDEX
                || (check_deleted
                    && (self.is_edge_deleted(EdgeId(e as u32))
                        || self.is_face_deleted(FaceId(a))
                        || self.is_face_deleted(FaceId(b))))
            {
                continue;
            }
            disjoint_sets::join(&mut parent, 0, a, b);
        }
        // Deleted faces were never joined: they become INVALID_INDEX (u32::MAX), no component.
        let count = disjoint_sets::number_sets(
            &mut parent,
            |f| check_deleted && self.is_face_deleted(FaceId(f as u32)),
            |_, _| {},
        );
        Components {
            count,
            face_component: parent,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::Mesh;
    use crate::soup::{BuildPolicy, FaceList};

    #[test]
    fn two_triangles_touching_at_a_vertex_are_two_components() {
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
        ];
        let sizes = [3, 3];
        let indices = [0, 1, 2, 0, 3, 4];
        // Strict refuses the shared vertex; Skip gives the second triangle a copy of it.
        let (mesh, diagnostic) = Mesh::from_face_list(
            &FaceList::polygons(&positions, &sizes, &indices),
            BuildPolicy::Skip,
        )
        .unwrap();
        assert_eq!(diagnostic.vertex_copies, [0]);
        let components = mesh.connected_components();
        assert_eq!(components.count, 2);
        assert_eq!(components.face_component, vec![0, 1]);
    }

    #[test]
    fn a_strip_of_quads_is_one_component() {
        let positions: Vec<[f64; 3]> = (0..8)
            .map(|i| [(i / 2) as f64, (i % 2) as f64, 0.0])
            .collect();
        let sizes = [4, 4, 4];
        let indices = [0, 2, 3, 1, 2, 4, 5, 3, 4, 6, 7, 5];
        let (mesh, _) = Mesh::from_face_list(
            &FaceList::polygons(&positions, &sizes, &indices),
            BuildPolicy::Strict,
        )
        .unwrap();
        assert_eq!(mesh.connected_components().count, 1);
        assert_eq!(Mesh::default().connected_components().count, 0);
    }
}
