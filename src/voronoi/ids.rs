//! Typed ids of the Voronoi diagram and its Delaunay triangulation.
//!
//! Sites keep their input index and are the vertices of the triangulation. Voronoi half-edges
//! come in twin pairs (`h ^ 1`); Delaunay half-edge `e` is corner `e` of triangle `e / 3`. Bulk
//! arrays meant for buffers ([`Delaunay::triangles`](super::Delaunay::triangles),
//! [`ClippedCells::indices`](super::ClippedCells::indices), …) stay plain `u32`, with
//! [`INVALID`](super::INVALID) for "none".

use crate::support::ids::typed_id;

typed_id!(
    /// An input site: a cell of the Voronoi diagram and a vertex of the Delaunay triangulation.
    SiteId,
    "site"
);
typed_id!(
    /// A vertex of the Voronoi diagram (the circumcentre of one or more Delaunay triangles).
    VoronoiVertexId,
    "Voronoi vertex"
);
typed_id!(
    /// A half-edge of the Voronoi diagram. Its twin is `h ^ 1`.
    VoronoiHalfedgeId,
    "Voronoi half-edge"
);
typed_id!(
    /// A half-edge of the Delaunay triangulation: corner `e % 3` of triangle `e / 3`, running
    /// from that corner's site to the next corner's.
    DelaunayHalfedgeId,
    "Delaunay half-edge"
);

impl VoronoiHalfedgeId {
    /// The opposite half-edge of the same edge (`h ^ 1`; the invalid id stays invalid).
    #[inline]
    pub const fn twin(self) -> Self {
        if self.is_valid() {
            Self(self.0 ^ 1)
        } else {
            self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_say_what_they_name() {
        assert_eq!(SiteId::new(3).to_string(), "site 3");
        assert_eq!(VoronoiVertexId::new(3).to_string(), "Voronoi vertex 3");
        assert_eq!(VoronoiHalfedgeId::new(3).to_string(), "Voronoi half-edge 3");
        assert_eq!(
            format!("{:?}", DelaunayHalfedgeId::INVALID),
            "Delaunay half-edge 4294967295 (the invalid id)"
        );
    }

    #[test]
    fn voronoi_twins_pair_up_and_invalid_stays_invalid() {
        assert_eq!(VoronoiHalfedgeId::new(6).twin(), VoronoiHalfedgeId::new(7));
        assert_eq!(VoronoiHalfedgeId::new(7).twin(), VoronoiHalfedgeId::new(6));
        assert_eq!(
            VoronoiHalfedgeId::INVALID.twin(),
            VoronoiHalfedgeId::INVALID
        );
    }
}
