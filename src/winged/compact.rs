//! Garbage collection: dropping the records the Euler operators marked deleted.

use super::ids::{EdgeId, FaceId, VertexId};
use super::structure::Winged;
use crate::support::index_maps::{IndexMaps, compaction_map};

impl Winged {
    /// Drops deleted vertices, edges and faces, renumbering the live ones densely in their old
    /// order, and returns the old-to-new maps (the half-edge map
    /// empty). Ids held from before are invalidated.
    pub fn garbage_collect(&mut self) -> IndexMaps {
        let dead = |alive: &[bool]| -> Vec<bool> { alive.iter().map(|&live| !live).collect() };
        let vertices = compaction_map(self.vertex_alive.len(), &dead(&self.vertex_alive));
        let deleted_edges: Vec<bool> = self.edges.iter().map(|r| r.is_deleted()).collect();
        let edges = compaction_map(self.edges.len(), &deleted_edges);
        let faces = compaction_map(self.face_alive.len(), &dead(&self.face_alive));
        let v = |x: VertexId| {
            if x.is_valid() {
                VertexId(vertices[x.index()])
            } else {
                x
            }
        };
        let e = |x: EdgeId| {
            if x.is_valid() {
                EdgeId(edges[x.index()])
            } else {
                x
            }
        };
        let f = |x: FaceId| {
            if x.is_valid() {
                FaceId(faces[x.index()])
            } else {
                x
            }
        };

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
        IndexMaps {
            vertices,
            halfedges: Vec::new(),
            edges,
            faces,
        }
    }
}
