//! Reading and writing meshes: Wavefront OBJ, Geomview OFF and Stanford PLY; reading 2D point
//! files ([`read_points2d`]).
//!
//! Readers produce a [`PolygonSoup`]: positions, polygon sizes and 0-based vertex indices exactly
//! as the file numbers its vertices (nothing is welded, reordered, triangulated or dropped,
//! unreferenced vertices included), with per-corner normals and texture coordinates when the file
//! has them (per-vertex attributes of OFF and PLY are copied onto every corner of their vertex).
//! When an OBJ gives normals or texture coordinates to some corners only, the others get defined
//! values: the zero vector for a missing normal (no direction: render buffers use their computed
//! normal there) and `(0, 0)` for a missing texture coordinate.
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
//!
//! The readers are halfwing's own: `tobj` renumbers and splits vertices per group and `ply-rs-bw`
//! allocates per face and rejects `nan`; the reasons are spelled out in `obj_read.rs` and
//! `ply_read.rs`.

mod attributes;
mod error;
mod float_text;
mod format;
mod obj_read;
mod obj_write;
mod off_read;
mod off_write;
mod ply_header;
mod ply_read;
mod ply_write;
mod points2d_read;
mod text;

pub use error::{FileAction, IoError, Location};
pub use format::MeshFormat;
pub use obj_read::{read_obj, read_obj_bytes};
pub use obj_write::write_obj;
pub use off_read::{read_off, read_off_bytes};
pub use off_write::write_off;
pub use ply_header::PlyEncoding;
pub use ply_read::{read_ply, read_ply_bytes};
pub use ply_write::write_ply;
pub use points2d_read::{PointFormat, read_points2d, read_points2d_bytes};

use std::path::Path;

use crate::soup::PolygonSoup;

/// Reads a mesh file, choosing the reader by the path's extension (`.obj`, `.off`, `.ply`, in any
/// case).
pub fn read_path(path: impl AsRef<Path>) -> Result<PolygonSoup, IoError> {
    use std::io::Read;
    let path = path.as_ref();
    let format = format_of(path)?;
    let mut file = std::fs::File::open(path)
        .map_err(|error| IoError::from(error).on_file(FileAction::Open, path))?;
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes)
        .map_err(|error| IoError::from(error).on_file(FileAction::Read, path))?;
    read_bytes(format, &bytes)
}

/// Reads a mesh held in memory in the given format.
pub fn read_bytes(format: MeshFormat, bytes: &[u8]) -> Result<PolygonSoup, IoError> {
    match format {
        MeshFormat::Obj => read_obj_bytes(bytes),
        MeshFormat::Off => read_off_bytes(bytes),
        MeshFormat::Ply => read_ply_bytes(bytes),
    }
}

/// Writes a mesh file, choosing the writer by the path's extension; `.ply` files are written in
/// binary little endian.
pub fn write_path(path: impl AsRef<Path>, soup: &PolygonSoup) -> Result<(), IoError> {
    let path = path.as_ref();
    let format = format_of(path)?;
    let file = std::fs::File::create(path)
        .map_err(|error| IoError::from(error).on_file(FileAction::Create, path))?;
    match format {
        MeshFormat::Obj => write_obj(file, soup),
        MeshFormat::Off => write_off(file, soup),
        MeshFormat::Ply => write_ply(file, soup, PlyEncoding::BinaryLittleEndian),
    }
    .map_err(|error| error.on_file(FileAction::Write, path))
}

fn format_of(path: &Path) -> Result<MeshFormat, IoError> {
    MeshFormat::from_path(path).ok_or_else(|| {
        IoError::Unsupported(format!(
            "{}: the extension names no mesh format (obj, off, ply)",
            path.display()
        ))
    })
}
