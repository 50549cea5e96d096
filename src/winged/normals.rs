//! Face and vertex normals, by the passes of [`crate::geom`] that the half-edge kernel runs: the
//! same formulas over the same corners, so a structure and the mesh built from the same faces
//! have the same normals, bit for bit.

use super::error::WingedError;
use super::ids::{FaceId, Side, VertexId};
use super::structure::Winged;
use crate::geom::{
    PolygonFaces, SmallFace, VertexNormalWeighting, face_normal_of, face_normals_of,
    vertex_normal_of, vertex_normals_of,
};

impl Winged {
    /// The unit normal of `f` (Newell's method: exact for planar polygons, the best-fit plane's
    /// normal for non-planar ones); zero for a degenerate or point face. Points outward for a
    /// counter-clockwise face. What [`Winged::face_normals`] gives `f`, bit for bit.
    pub fn face_normal(&self, f: FaceId) -> Result<[f64; 3], WingedError> {
        self.require_face(f)?;
        Ok(face_normal_of(self, f.0))
    }

    /// Unit normals of all faces, indexed by face id (zero for deleted and degenerate faces).
    pub fn face_normals(&self) -> Vec<[f64; 3]> {
        face_normals_of(self)
    }

    /// The unit normal of `v`: the normalised sum of the normals of the faces around it, in
    /// every fan of a non-manifold vertex, weighed by `weighting` (holes left out); zero when it
    /// has no face. Baumgart's vertex normal, the unit face normals summed around the vertex, is
    /// [`VertexNormalWeighting::Uniform`]. What [`Winged::vertex_normals`] gives `v`, bit for
    /// bit.
    pub fn vertex_normal(
        &self,
        v: VertexId,
        weighting: VertexNormalWeighting,
    ) -> Result<[f64; 3], WingedError> {
        self.require_vertex(v)?;
        Ok(vertex_normal_of(self, v.0, weighting))
    }

    /// Unit normals of all vertices under `weighting`, indexed by vertex id, in one pass over the
    /// faces (zero for deleted vertices and those without faces).
    pub fn vertex_normals(&self, weighting: VertexNormalWeighting) -> Vec<[f64; 3]> {
        vertex_normals_of(self, weighting)
    }
}

/// The faces and corners the normal passes read: a face's corners are the tails of its loop's
/// uses, from its stored edge (the corners the half-edge mesh of the same faces gives it).
impl PolygonFaces for Winged {
    fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    fn face_slot_count(&self) -> usize {
        self.face_edge.len()
    }

    fn is_live_face(&self, f: u32) -> bool {
        self.is_face(FaceId(f))
    }

    fn live_faces(&self) -> impl Iterator<Item = u32> + '_ {
        self.faces().map(|f| f.0)
    }

    fn corners(&self, f: u32) -> impl Iterator<Item = u32> + Clone + '_ {
        let uses = self.face_loop(FaceId(f)).into_iter().flatten();
        uses.map(|u| self.tail_of(u).0)
    }

    /// One walk of at most four uses, stepped as [`Winged::face_loop`] steps, its tails the
    /// corners: a face otherwise walked twice (for its normal, then for its corners) is walked
    /// once, and the arrays take the place of the loop iterator.
    #[inline(always)]
    fn small_face(&self, f: u32) -> SmallFace {
        let Some(first) = self.face_first_use(FaceId(f)) else {
            return SmallFace::Larger;
        };
        let mut corners = [0; 4];
        let mut here = first;
        for k in 0..corners.len() {
            corners[k] = self.tail_of(here).0;
            match self.use_next(here) {
                Some(next) if next == first => {
                    let [a, b, c, d] = corners;
                    return match k {
                        2 => SmallFace::Triangle([a, b, c]),
                        3 => SmallFace::Quad([a, b, c, d]),
                        _ => SmallFace::Larger,
                    };
                }
                Some(next) => here = next,
                None => return SmallFace::Larger,
            }
        }
        SmallFace::Larger
    }

    /// The faces of `v`'s ring; while the structure may have pinched vertices (whose other fans
    /// a ring does not reach), of every edge at `v`, found by a scan of the edges.
    fn faces_at(&self, v: u32) -> Vec<u32> {
        let v = VertexId(v);
        if !self.may_have_pinched_vertices {
            let ring = self.vertex_faces(v).into_iter().flatten();
            return ring.map(|f| f.0).collect();
        }
        let uses = self
            .edges()
            .flat_map(|e| [Side::Left, Side::Right].map(|s| (e, s)));
        uses.filter(|&(e, side)| self.rec(e).tail(side) == v)
            .map(|(e, side)| self.rec(e).face(side))
            .filter(|f| f.is_valid())
            .map(|f| f.0)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::{BuildPolicy, FaceList};

    #[test]
    fn small_faces_are_the_corners_of_the_loop() {
        // A triangle, a quad and a pentagon in a strip, each face's corners read both ways.
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.1],
            [0.0, 2.0, 0.0],
            [1.0, 2.0, 0.0],
            [1.5, 3.0, 0.2],
            [0.5, 3.5, 0.0],
            [-0.5, 3.0, 0.0],
        ];
        let sizes = [3, 4, 5];
        let indices = [0, 1, 2, 2, 1, 3, 5, 4, 5, 6, 7, 8];
        let list = FaceList::polygons(&positions, &sizes[..2], &indices[..7]);
        let (w, _) = Winged::from_face_list(&list, BuildPolicy::Strict).unwrap();
        let pentagon = FaceList::polygons(&positions, &sizes[2..], &indices[7..12]);
        let (p, _) = Winged::from_face_list(&pentagon, BuildPolicy::Strict).unwrap();
        let small = |w: &Winged, f: u32| match w.small_face(f) {
            SmallFace::Triangle(corners) => Some(corners.to_vec()),
            SmallFace::Quad(corners) => Some(corners.to_vec()),
            SmallFace::Larger => None,
        };
        let walked = |w: &Winged, f: u32| w.corners(f).collect::<Vec<_>>();
        for f in 0..2 {
            assert_eq!(small(&w, f), Some(walked(&w, f)), "face {f}");
        }
        assert_eq!(walked(&w, 1).len(), 4);
        assert_eq!(small(&p, 0), None, "a pentagon is walked");
        assert_eq!(walked(&p, 0).len(), 5);
    }

    #[test]
    fn a_vertex_alone_scans_the_edges_while_fans_may_be_apart() {
        // Two fans of triangles at vertex 0: a strict build refuses them, a skipping one gives
        // the second fan a copy of the vertex; the scan must find the faces of both rings.
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.2],
            [1.0, 1.0, 0.0],
            [-1.0, 0.0, 0.5],
            [-1.0, -1.0, 0.0],
        ];
        let list = FaceList::triangles(&positions, &[0, 1, 2, 0, 3, 4]);
        let (mut w, _) = Winged::from_face_list(&list, BuildPolicy::Skip).unwrap();
        for weighting in VertexNormalWeighting::ALL {
            let all = w.vertex_normals(weighting);
            w.may_have_pinched_vertices = true;
            for v in w.vertices().collect::<Vec<_>>() {
                let one = w.vertex_normal(v, weighting).unwrap();
                assert_eq!(one, all[v.index()], "{weighting:?} {v}");
                assert_ne!(one, [0.0; 3]);
            }
            w.may_have_pinched_vertices = false;
        }
        assert_eq!(
            w.faces_at(0),
            [0],
            "one face at vertex 0, its copy has the other"
        );
    }
}
