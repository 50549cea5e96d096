//! Geometry: vectors, exact predicates, normals, intersections.
