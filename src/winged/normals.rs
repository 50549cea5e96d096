//! Face normals (Newell's method) and vertex normals, as Baumgart's structure computes them.

use super::error::WingedError;
use super::ids::{FaceId, VertexId};
use super::structure::Winged;
use crate::geom::{face_corners_area_vector, normalized, rescued_area_vector};

impl Winged {
    /// The unit normal of `f` from its area vector (Newell's method: exact for planar
    /// polygons, a least-squares plane normal for non-planar ones); zero for a degenerate face.
    /// The half-edge kernel's formula ([`face_corners_area_vector`]), so the two kernels give
    /// the same normals for the same faces.
    ///
    /// Points outward for a counter-clockwise face.
    pub fn face_normal(&self, f: FaceId) -> Result<[f64; 3], WingedError> {
        let corners = self
            .face_loop(f)?
            .map(|u| self.positions[self.tail_of(u).index()]);
        // One walk for the area vector; its unwalked copy serves the rare rescaling.
        let area_vector = face_corners_area_vector(corners.clone());
        Ok(normalized(rescued_area_vector(area_vector, || {
            corners.collect()
        })))
    }

    /// Unit normals of all faces, indexed by face id (zero for deleted and degenerate faces).
    pub fn face_normals(&self) -> Vec<[f64; 3]> {
        let normal = |f: u32| self.face_normal(FaceId(f)).unwrap_or([0.0; 3]);
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            (0..self.n_face_slots())
                .into_par_iter()
                .map(normal)
                .collect()
        }
        #[cfg(not(feature = "parallel"))]
        {
            (0..self.n_face_slots()).map(normal).collect()
        }
    }

    /// The unit normal of `v`: the normalised sum of the unit normals of the faces around it
    /// (Baumgart's `v->norm += e->f->norm; e = e->prev->sym`), holes left out; zero if none.
    pub fn vertex_normal(&self, v: VertexId) -> Result<[f64; 3], WingedError> {
        self.vertex_normal_from(v, |f| self.face_normal(f).unwrap_or([0.0; 3]))
    }

    /// Unit normals of all vertices, indexed by vertex id (face normals are computed once).
    pub fn vertex_normals(&self) -> Vec<[f64; 3]> {
        let face_normals = self.face_normals();
        let normal = |v: u32| {
            self.vertex_normal_from(VertexId(v), |f| face_normals[f.index()])
                .unwrap_or([0.0; 3])
        };
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            (0..self.n_vertex_slots())
                .into_par_iter()
                .map(normal)
                .collect()
        }
        #[cfg(not(feature = "parallel"))]
        {
            (0..self.n_vertex_slots()).map(normal).collect()
        }
    }

    fn vertex_normal_from(
        &self,
        v: VertexId,
        face_normal: impl Fn(FaceId) -> [f64; 3],
    ) -> Result<[f64; 3], WingedError> {
        let mut sum = [0.0; 3];
        for f in self.vertex_faces(v)? {
            let n = face_normal(f);
            for k in 0..3 {
                sum[k] += n[k];
            }
        }
        Ok(normalized(sum))
    }
}
