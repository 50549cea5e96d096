//! Stanford PLY writer (ASCII, binary little or big endian).
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

/// Writes a soup as PLY in the given encoding.
pub fn write_ply(
    out: impl Write,
    soup: &PolygonSoup,
    encoding: PlyEncoding,
) -> Result<(), IoError> {
    check_soup(soup)?;
    let attributes = VertexAttributes::of(soup);
    let mut out = BufWriter::new(out);
    let format = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
        PlyEncoding::BinaryBigEndian => "binary_big_endian",
    };
    let big_endian = encoding == PlyEncoding::BinaryBigEndian;
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
    for vertex in 0..soup.positions.len() {
        attributes.vertex_row(soup, vertex, &mut row);
        if encoding == PlyEncoding::Ascii {
            write_row(&mut out, "", &row)?;
        } else {
            for value in &row {
                let bytes = if big_endian {
                    value.to_be_bytes()
                } else {
                    value.to_le_bytes()
                };
                out.write_all(&bytes)?;
            }
        }
    }
    let put_u32 = |out: &mut BufWriter<_>, value: u32| {
        out.write_all(&if big_endian {
            value.to_be_bytes()
        } else {
            value.to_le_bytes()
        })
    };
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
            if wide_sizes {
                put_u32(&mut out, size)?;
            } else {
                // Every size fits in a byte unless `wide_sizes`.
                out.write_all(&[size as u8])?;
            }
            for &index in face {
                // `int` items hold every index when there are at most 2^31 - 1 vertices, and the
                // bytes of such a `u32` are those of the same `i32`.
                put_u32(&mut out, index)?;
            }
        }
    }
    out.flush()?;
    Ok(())
}
