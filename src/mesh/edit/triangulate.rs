//! Triangulating a polygon face.

use super::{EditError, refuse};
use crate::mesh::{FaceId, HalfedgeId, Mesh};

const TRIANGULATE: &str = "face triangulation";

impl Mesh {
    /// Splits face `f` into triangles by a fan of diagonals from one of its corners: the first
    /// corner (in face order from [`Mesh::face_halfedge`]) none of whose diagonals already exists
    /// as an edge. A fan suits convex and star-shaped polygons (the usual mesh faces). Returns the
    /// faces, `f` first. Refused, with the mesh unchanged, when no corner has a free fan.
    pub fn triangulate_face(&mut self, f: FaceId) -> Result<Vec<FaceId>, EditError> {
        self.check_face(f)?;
        let loop_: Vec<HalfedgeId> = self.face_loop(f).collect();
        let n = loop_.len();
        if n <= 3 {
            return Ok(vec![f]);
        }
        // Apex `target(loop_[i])`; its diagonals reach the targets of loop_[i + 2 .. i + n - 2].
        let apex = (0..n).find(|&i| {
            let apex = self.target(loop_[i]);
            (2..n - 1).all(|k| {
                let other = self.target(loop_[(i + k) % n]);
                self.find_halfedge(apex, other).is_none()
                    && self.find_halfedge(other, apex).is_none()
            })
        });
        let Some(i) = apex else {
            return refuse(
                TRIANGULATE,
                "every corner's fan would duplicate an existing edge",
            );
        };
        let needed_edges = (n - 3) as u64;
        if self.origin.len() as u64 + 2 * needed_edges >= u64::from(u32::MAX)
            || self.face_halfedge.len() as u64 + needed_edges >= u64::from(u32::MAX)
        {
            return Err(EditError::Full {
                operation: TRIANGULATE,
            });
        }
        let h0 = loop_[i];
        let mut faces = vec![f];
        // Each split cuts the triangle (apex, target(next(h0)), target(next(next(h0)))) off `f`.
        for _ in 0..n - 3 {
            let h1 = self.next(self.next(h0));
            self.split_face(h0, h1)?;
            faces.push(FaceId((self.face_halfedge.len() - 1) as u32));
        }
        Ok(faces)
    }
}
