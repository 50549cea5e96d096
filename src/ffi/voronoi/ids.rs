//! Voronoi ids as small by-value C structs, distinct from each other and from the mesh kernels'
//! ids, so the compiler refuses a Voronoi vertex passed where a site is expected.

use crate::ffi::mesh::elements::id_conversions;
use crate::voronoi::{SiteId, VoronoiHalfedgeId, VoronoiVertexId};

/// A site of an ::hw_voronoi: its input index, which is also its Delaunay vertex and the index of
/// its cell.
/// \ingroup voronoi
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_site {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// A vertex of an ::hw_voronoi (a circumcentre of Delaunay triangles).
/// \ingroup voronoi
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_voronoi_vertex {
    /// The index; `HW_INVALID_INDEX` means none (an end at infinity).
    pub idx: u32,
}

/// A half-edge of an ::hw_voronoi. Half-edges come in pairs: the twin of `h` is `h.idx ^ 1`.
/// \ingroup voronoi
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_voronoi_halfedge {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

id_conversions!(hw_site <=> SiteId, hw_voronoi_vertex <=> VoronoiVertexId, hw_voronoi_halfedge <=> VoronoiHalfedgeId);
