//! Stanford PLY writer (ASCII or binary little endian).
//!
//! Vertices carry `double x y z`, plus `double nx ny nz` and `double u v` when every corner of
//! each vertex has the same normal or texture coordinate (PLY stores attributes per vertex; OBJ is
//! the format for per-corner ones). Faces carry `vertex_indices` as a list whose length type is
//! `uchar` when every face has at most 255 corners (`uint` otherwise) and whose items are `int`
//! (`uint` past 2^31 vertices), the types most readers expect.

use std::io::{BufWriter, Write};

use crate::soup::PolygonSoup;

use super::attributes::{VertexAttributes, check_soup};
use super::error::IoError;
use super::float_text::write_row;
use super::ply_header::PlyEncoding;

/// Writes a soup as PLY. Big-endian output is not offered: no current tool needs it.
pub fn write_ply(
    out: impl Write,
    soup: &PolygonSoup,
    encoding: PlyEncoding,
) -> Result<(), IoError> {
    check_soup(soup)?;
    if encoding == PlyEncoding::BinaryBigEndian {
        return Err(IoError::Unsupported("writing big-endian PLY".to_owned()));
    }
    let attributes = VertexAttributes::of(soup);
    let mut out = BufWriter::new(out);
    let format = if encoding == PlyEncoding::Ascii {
        "ascii"
    } else {
        "binary_little_endian"
    };
    let wide_sizes = soup
        .face_sizes
        .iter()
        .any(|&size| size > u32::from(u8::MAX));
    let wide_indices = soup.positions.len() > i32::MAX as usize;
    writeln!(
        out,
        "ply\nformat {format} 1.0\ncomment written by halfwing {}",
        crate::VERSION
    )?;
    writeln!(out, "element vertex {}", soup.positions.len())?;
    writeln!(
        out,
        "property double x\nproperty double y\nproperty double z"
    )?;
    if attributes.normals.is_some() {
        writeln!(
            out,
            "property double nx\nproperty double ny\nproperty double nz"
        )?;
    }
    if attributes.uvs.is_some() {
        writeln!(out, "property double u\nproperty double v")?;
    }
    writeln!(out, "element face {}", soup.face_sizes.len())?;
    let size_type = if wide_sizes { "uint" } else { "uchar" };
    let index_type = if wide_indices { "uint" } else { "int" };
    writeln!(
        out,
        "property list {size_type} {index_type} vertex_indices\nend_header"
    )?;

    let mut row = Vec::with_capacity(8);
    for (vertex, position) in soup.positions.iter().enumerate() {
        row.clear();
        row.extend_from_slice(position);
        if let Some(normals) = &attributes.normals {
            row.extend_from_slice(&normals[vertex]);
        }
        if let Some(uvs) = &attributes.uvs {
            row.extend_from_slice(&uvs[vertex]);
        }
        if encoding == PlyEncoding::Ascii {
            write_row(&mut out, "", &row)?;
        } else {
            for value in &row {
                out.write_all(&value.to_le_bytes())?;
            }
        }
    }
    let mut corners = soup.indices.iter();
    for &size in &soup.face_sizes {
        let face = corners.by_ref().take(size as usize);
        if encoding == PlyEncoding::Ascii {
            write!(out, "{size}")?;
            for index in face {
                write!(out, " {index}")?;
            }
            out.write_all(b"\n")?;
        } else {
            match wide_sizes {
                // Checked above: every size fits in a byte unless `wide_sizes`.
                false => out.write_all(&[size as u8])?,
                true => out.write_all(&size.to_le_bytes())?,
            }
            for &index in face {
                // `int` items hold every index when there are at most 2^31 - 1 vertices.
                out.write_all(&index.to_le_bytes())?;
            }
        }
    }
    out.flush()?;
    Ok(())
}
