//! Triangulating a polygon face.

use super::{EditError, refuse};
use crate::mesh::{FaceId, HalfedgeId, Mesh};
use crate::render::EarClipper;

const TRIANGULATE: &str = "face triangulation";

impl Mesh {
    /// Splits face `f` into triangles, the ones the render buffers draw for it: ear clipping in
    /// the plane of the face's Newell normal, so non-convex polygons come out with every
    /// triangle facing the face's way (a simple polygon is covered exactly once). A polygon
    /// with no area, non-finite corners or crossing sides gets the fan [`EarClipper`] falls back
    /// to. Returns the faces, `f` first (it keeps the last triangle). Refused, with the mesh
    /// unchanged, when a diagonal the triangulation needs already exists as an edge (the two
    /// corners are joined outside the face: a second edge between them would make the mesh
    /// non-manifold).
    pub fn triangulate_face(&mut self, f: FaceId) -> Result<Vec<FaceId>, EditError> {
        self.check_face(f)?;
        let loop_: Vec<HalfedgeId> = self.face_loop(f).collect();
        let n = loop_.len();
        if n <= 3 {
            return Ok(vec![f]);
        }
        // Corner k is the target of loop_[k].
        let corners: Vec<[f64; 3]> = loop_
            .iter()
            .map(|&h| self.position(self.target(h)))
            .collect();
        let mut triangles = Vec::with_capacity(n - 2);
        EarClipper::new().triangulate(&corners, &mut triangles);
        let cuts = &triangles[..n - 3];
        for &[a, _, c] in cuts {
            let (u, v) = (
                self.target(loop_[a as usize]),
                self.target(loop_[c as usize]),
            );
            if self.find_halfedge(u, v).is_some() || self.find_halfedge(v, u).is_some() {
                return refuse(
                    TRIANGULATE,
                    "a diagonal of its triangulation already exists as an edge",
                );
            }
        }
        let needed_edges = (n - 3) as u64;
        if self.origin.len() as u64 + 2 * needed_edges >= u64::from(u32::MAX)
            || self.face_halfedge.len() as u64 + needed_edges >= u64::from(u32::MAX)
        {
            return Err(EditError::Full {
                operation: TRIANGULATE,
            });
        }
        // Each triangle [a, e, c] cuts the ear e off what is left of `f` (a and c are its
        // neighbours there). With `into[k]` the half-edge of `f` whose target is corner k,
        // splitting `f` from target(into[a]) to target(into[c]) gives the new face the side
        // through e, and `f` the rest, where the new half-edge a → c leads into c.
        let mut into = loop_;
        let mut faces = vec![f];
        for &[a, _, c] in cuts {
            let new_into_c = self.split_face(into[a as usize], into[c as usize])?;
            into[c as usize] = new_into_c;
            faces.push(FaceId((self.face_halfedge.len() - 1) as u32));
        }
        Ok(faces)
    }
}
