//! Geometry: vectors, exact predicates, normals, intersections.

mod newell;

pub use newell::{is_degenerate_polygon, newell_vector};
