//! Wavefront OBJ writer.
//!
//! Writes `v` records for every position, then the distinct texture coordinates (`vt`) and
//! normals (`vn`) of the corners (bitwise duplicates are written once), then one `f` record per
//! face with 1-based `v`, `v/vt`, `v//vn` or `v/vt/vn` corners. Reading the file back gives the
//! same soup, attributes included (an attribute array of a soup without corners has nothing to
//! write and reads back as `None`).

use std::collections::HashMap;
use std::io::{BufWriter, Write};

use crate::soup::PolygonSoup;

use super::attributes::check_soup;
use super::error::IoError;
use super::float_text::write_row;

/// Writes a soup as OBJ. A face without corners cannot be written (OBJ has no such record) and is
/// refused with [`IoError::InvalidSoup`].
pub fn write_obj(out: impl Write, soup: &PolygonSoup) -> Result<(), IoError> {
    check_soup(soup)?;
    if let Some(face) = soup.face_sizes.iter().position(|&size| size == 0) {
        return Err(IoError::InvalidSoup(format!(
            "face {face} has no corners, which OBJ cannot store"
        )));
    }
    let mut out = BufWriter::new(out);
    writeln!(out, "# written by halfwing {}", crate::VERSION)?;
    for position in &soup.positions {
        write_row(&mut out, "v", position)?;
    }
    let uv_refs = soup
        .corner_uvs
        .as_deref()
        .map(|uvs| write_distinct(&mut out, "vt", uvs))
        .transpose()?;
    let normal_refs = soup
        .corner_normals
        .as_deref()
        .map(|normals| write_distinct(&mut out, "vn", normals))
        .transpose()?;
    let mut corner = 0usize;
    for &size in &soup.face_sizes {
        out.write_all(b"f")?;
        for _ in 0..size {
            write!(out, " {}", u64::from(soup.indices[corner]) + 1)?;
            match (&uv_refs, &normal_refs) {
                (None, None) => {}
                (Some(uv), None) => write!(out, "/{}", uv[corner] + 1)?,
                (None, Some(normal)) => write!(out, "//{}", normal[corner] + 1)?,
                (Some(uv), Some(normal)) => {
                    write!(out, "/{}/{}", uv[corner] + 1, normal[corner] + 1)?
                }
            }
            corner += 1;
        }
        out.write_all(b"\n")?;
    }
    out.flush()?;
    Ok(())
}

/// Writes each bitwise-distinct value once, in order of first use, and returns every corner's
/// 0-based reference into what was written.
fn write_distinct<const N: usize>(
    out: &mut impl Write,
    keyword: &str,
    values: &[[f64; N]],
) -> Result<Vec<u64>, IoError> {
    let mut written: HashMap<[u64; N], u64> = HashMap::new();
    let mut references = Vec::with_capacity(values.len());
    for value in values {
        let next = written.len() as u64;
        let reference = *written.entry(value.map(f64::to_bits)).or_insert(next);
        if reference == next {
            write_row(out, keyword, value)?;
        }
        references.push(reference);
    }
    Ok(references)
}
