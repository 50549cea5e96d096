//! Surface generation: cylindrical (swept), revolved and ruled surfaces from polylines, and the
//! primitives examples and tests need — the winged-edge worked example's tetrahedron, cube,
//! icosphere, torus and grid.
//!
//! Every generator returns a [`PolygonSoup`](crate::soup::PolygonSoup) whose faces are CCW seen
//! from outside, whose shared vertices are shared indices (poles and full-turn seams are welded),
//! and which has no degenerate face; bad parameters are [`SurfaceError`]s, never panics.

mod builder;
mod cube;
mod cylindrical;
mod error;
mod grid;
mod icosphere;
mod lattice;
mod polyline;
mod revolution;
mod ruled;
mod tetrahedron;
mod torus;

pub use cube::cube;
pub use cylindrical::{Sweep, cylindrical_surface};
pub use error::SurfaceError;
pub use grid::{Grid, grid};
pub use icosphere::{MAX_ICOSPHERE_LEVEL, icosphere};
pub use lattice::CellFaces;
pub use revolution::{Caps, Revolution, Turn, revolution_surface};
pub use ruled::{Ruling, ruled_surface};
pub use tetrahedron::tetrahedron;
pub use torus::{Torus, torus};
