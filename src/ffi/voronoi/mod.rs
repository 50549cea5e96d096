//! The Voronoi diagram's C functions (`hw_points2d_*`, `hw_voronoi_*`, `hw_delaunay_*`): the
//! sites read from a point file, the diagram, the bare triangulation, clipped cells, Lloyd
//! relaxation, then pictures.

pub(crate) mod points2d;

pub(crate) mod ids;

pub(crate) mod diagram;

pub(crate) mod delaunay;

pub(crate) mod cells;

pub(crate) mod lloyd;

pub(crate) mod images;

pub use cells::*;
pub use delaunay::*;
pub use diagram::*;
pub use ids::*;
pub use images::*;
pub use lloyd::*;
pub use points2d::*;
