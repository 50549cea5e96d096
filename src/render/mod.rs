//! Rendering buffers: what `glBufferData` wants (vertex and index buffers).
//!
//! - [`surface_buffer`]: a mesh's triangles (`u32` indices, every polygon triangulated) and
//!   `f32` vertex attributes, flat, smooth or crease shaded or with given corner normals (a
//!   file's own), separate or interleaved;
//! - [`wireframe_lines`], [`boundary_lines`], [`non_manifold_lines`], [`vertex_normal_glyphs`],
//!   [`face_normal_glyphs`]: [`LineBuffer`]s for `GL_LINES`;
//! - [`mesh_buffers`]: all of the above in one call;
//! - [`polygon_buffer`], [`polygon_buffer_2d`]: fills and outlines of a polygon list;
//!   [`voronoi_cell_buffer`]: those of a Voronoi diagram's clipped cells;
//! - [`finding_buffers`]: one kind of the mesh doctor's findings (faces, lines, points).

mod bounds;
mod error;
mod finding_buffers;
mod line_buffer;
mod mesh_buffers;
mod mesh_lines;
mod normal_glyphs;
mod polygon_buffer;
mod shading;
mod surface;
mod triangulate;
mod voronoi_cells;

pub use crate::geom::{FallbackReason, PolygonOutcome, PolygonTriangulator, triangulate_polygon};
pub use bounds::Bounds;
pub use error::RenderError;
pub use finding_buffers::{FindingBuffers, finding_buffers};
pub use line_buffer::LineBuffer;
pub use mesh_buffers::{MeshBufferOptions, MeshBuffers, mesh_buffers};
pub use mesh_lines::{boundary_lines, non_manifold_lines, wireframe_lines};
pub use normal_glyphs::{face_normal_glyphs, mean_edge_length, vertex_normal_glyphs};
pub use polygon_buffer::{PolygonBuffer, PolygonList, polygon_buffer, polygon_buffer_2d};
pub use shading::{Shading, VertexLayout};
pub use surface::{SurfaceBuffer, SurfaceOptions, surface_buffer};
pub use triangulate::{TriangleBuffer, TriangulateError, triangulate_faces};
pub use voronoi_cells::voronoi_cell_buffer;
