//! Reading and writing meshes: Wavefront OBJ, Geomview OFF and Stanford PLY.
//!
//! Readers produce a [`PolygonSoup`]: positions, polygon sizes and 0-based vertex indices exactly
//! as the file numbers its vertices (nothing is welded, reordered, triangulated or dropped,
//! unreferenced vertices included), with per-corner normals and texture coordinates when the file
//! has them (per-vertex attributes of OFF and PLY are copied onto every corner of their vertex).
//! The soup is not validated beyond what parsing needs: faces with repeated vertices, one or two
//! corners, or NaN coordinates are passed on for the builder's diagnostic to report.
//!
//! Malformed input never panics: it gives [`IoError::Parse`] with the line (text) or element
//! record (binary PLY) and a message naming the problem. Indices are checked against the vertex
//! count the file declares (OFF, PLY) or defines (OBJ). NaN and infinity literals (`nan`, `inf`,
//! in any case) are read as values.
//!
//! Writers take a `&PolygonSoup` and write floats in Rust's shortest round-trip form, so writing
//! and reading again reproduces every bit. Output is buffered internally.

mod attributes;
mod error;
mod format;
mod obj_read;
mod off_read;
mod text;

pub use error::{IoError, Location};
pub use format::MeshFormat;
pub use obj_read::{read_obj, read_obj_bytes};
pub use off_read::{read_off, read_off_bytes};
