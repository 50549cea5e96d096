//! Geometry: vectors, exact predicates, normals, intersections, polygon triangulation.

mod newell;
pub(crate) use newell::{
    is_clearly_not_degenerate_triangle, polygon_area_test, quad_squared_perimeter,
    triangle_squared_size,
};
mod normals;
mod polygon_faces;
pub(crate) use newell::{cross, difference};
pub(crate) use normals::{dot, normalized};
pub(crate) use normals::{face_normal_of, face_normals_of, vertex_normal_of, vertex_normals_of};
pub(crate) use polygon_faces::{PolygonFaces, SmallFace};
pub(crate) mod box_tree;
mod embedded_stars;
pub(crate) mod exact_orientation;
mod parallel;
mod plane_side;
mod polygon_triangulation;
mod self_intersections;
pub(crate) mod triangle_intersection;
pub(crate) mod wide_integer;

pub use newell::{
    face_corners_area_vector, is_degenerate_polygon, is_degenerate_quad, is_degenerate_triangle,
    newell_vector, quad_area_vector, triangle_area_vector,
};
pub use normals::{
    VertexNormalWeighting, corner_angle, corner_normals, face_and_vertex_normals, face_area_vector,
    face_normals, face_normals_into, normals_into, vertex_normals,
};
pub use polygon_triangulation::{
    FallbackReason, PolygonOutcome, PolygonTriangulator, triangulate_polygon,
};
pub use self_intersections::{SelfIntersectionError, face_self_intersections, self_intersections};
