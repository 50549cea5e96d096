//! Garbage collection: dropping the records the Euler operators marked deleted.

use super::ids::{EdgeId, FaceId, VertexId};
use super::structure::Winged;

/// Where every old id went in [`Winged::garbage_collect`]: `vertices[old] = new` (invalid for a
/// dropped element), likewise for edges and faces.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Compaction {
    /// New id of every old vertex.
    pub vertices: Vec<VertexId>,
    /// New id of every old edge.
    pub edges: Vec<EdgeId>,
    /// New id of every old face.
    pub faces: Vec<FaceId>,
}

/// New ids for the live slots, in order; `INVALID` for the dead ones.
fn renumber(alive: impl Iterator<Item = bool>) -> Vec<u32> {
    let mut next = 0u32;
    alive
        .map(|live| {
            if live {
                next += 1;
                next - 1
            } else {
                u32::MAX
            }
        })
        .collect()
}

impl Winged {
    /// Drops deleted vertices, edges and faces, renumbering the live ones densely in their old
    /// order, and returns the old-to-new maps. Ids held from before are invalidated.
    pub fn garbage_collect(&mut self) -> Compaction {
        let vertices: Vec<VertexId> = renumber(self.vertex_alive.iter().copied())
            .into_iter()
            .map(VertexId)
            .collect();
        let edges: Vec<EdgeId> = renumber(self.edges.iter().map(|r| !r.is_deleted()))
            .into_iter()
            .map(EdgeId)
            .collect();
        let faces: Vec<FaceId> = renumber(self.face_alive.iter().copied())
            .into_iter()
            .map(FaceId)
            .collect();
        let v = |x: VertexId| if x.is_valid() { vertices[x.index()] } else { x };
        let e = |x: EdgeId| if x.is_valid() { edges[x.index()] } else { x };
        let f = |x: FaceId| if x.is_valid() { faces[x.index()] } else { x };

        let live_vertices: Vec<usize> = (0..self.positions.len())
            .filter(|&i| self.vertex_alive[i])
            .collect();
        self.positions = live_vertices.iter().map(|&i| self.positions[i]).collect();
        self.vertex_edge = live_vertices
            .iter()
            .map(|&i| e(self.vertex_edge[i]))
            .collect();
        self.vertex_alive = vec![true; live_vertices.len()];

        let live_faces: Vec<usize> = (0..self.face_edge.len())
            .filter(|&i| self.face_alive[i])
            .collect();
        self.face_edge = live_faces.iter().map(|&i| e(self.face_edge[i])).collect();
        self.face_alive = vec![true; live_faces.len()];

        self.edges.retain(|r| !r.is_deleted());
        for r in &mut self.edges {
            r.start = v(r.start);
            r.end = v(r.end);
            r.left_face = f(r.left_face);
            r.right_face = f(r.right_face);
            for wing in [
                &mut r.left_prev,
                &mut r.left_next,
                &mut r.right_prev,
                &mut r.right_next,
            ] {
                *wing = e(*wing);
            }
        }
        for (face, vertex) in &mut self.point_faces {
            *face = f(*face);
            *vertex = v(*vertex);
        }
        if self.may_have_pinched_vertices {
            // Kills may have left every vertex with one ring: look again (one linear pass).
            self.may_have_pinched_vertices = !self.non_manifold_vertices().is_empty();
        }
        Compaction {
            vertices,
            edges,
            faces,
        }
    }
}
