//! Geomview OFF writer.
//!
//! Writes `OFF` with the counts `vertices faces 0` (the edge count is optional in practice and
//! readers ignore it), one vertex per line and one `n i0 … i(n-1)` line per face. OFF stores
//! attributes per vertex: normals are written (`NOFF`) and texture coordinates (`STOFF`) when every
//! corner of each vertex carries the same value; otherwise that attribute is left out and OBJ is
//! the format that keeps it.

use std::io::{BufWriter, Write};

use crate::soup::PolygonSoup;

use super::attributes::{VertexAttributes, check_soup};
use super::error::IoError;
use super::float_text::write_row;

/// Writes a soup as OFF.
pub fn write_off(out: impl Write, soup: &PolygonSoup) -> Result<(), IoError> {
    check_soup(soup)?;
    let attributes = VertexAttributes::of(soup);
    let mut out = BufWriter::new(out);
    let texture = if attributes.uvs.is_some() { "ST" } else { "" };
    let normal = if attributes.normals.is_some() {
        "N"
    } else {
        ""
    };
    writeln!(out, "{texture}{normal}OFF")?;
    writeln!(out, "{} {} 0", soup.positions.len(), soup.face_sizes.len())?;
    let mut row = Vec::with_capacity(8);
    for vertex in 0..soup.positions.len() {
        attributes.vertex_row(soup, vertex, &mut row);
        write_row(&mut out, "", &row)?;
    }
    let mut corners = soup.indices.iter();
    for &size in &soup.face_sizes {
        write!(out, "{size}")?;
        for index in corners.by_ref().take(size as usize) {
            write!(out, " {index}")?;
        }
        out.write_all(b"\n")?;
    }
    out.flush()?;
    Ok(())
}
