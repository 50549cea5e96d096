//! Connected components: faces reachable from each other across shared edges.

use super::Mesh;
use super::ids::{FaceId, INVALID_INDEX};

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
    pub fn connected_components(&self) -> Components {
        let n_faces = self.face_capacity();
        let mut face_component = vec![INVALID_INDEX; n_faces];
        let mut stack = Vec::new();
        let mut count = 0u32;
        for seed in 0..n_faces {
            if face_component[seed] != INVALID_INDEX || self.is_face_deleted(FaceId(seed as u32)) {
                continue;
            }
            face_component[seed] = count;
            stack.push(seed as u32);
            while let Some(f) = stack.pop() {
                // The face loop is bounded, so a corrupt mesh cannot trap this search.
                for h in self.face_loop(FaceId(f)) {
                    let across = self.face[h.twin().idx()];
                    if across != INVALID_INDEX && face_component[across as usize] == INVALID_INDEX {
                        face_component[across as usize] = count;
                        stack.push(across);
                    }
                }
            }
            count += 1;
        }
        Components {
            count: count as usize,
            face_component,
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
        let (mesh, _) = Mesh::from_face_list(
            &FaceList::polygons(&positions, &sizes, &indices),
            BuildPolicy::Strict,
        )
        .unwrap();
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
