//! Reading and writing mesh files through the library, failures naming the file.

use crate::failure::Failure;
use crate::progress::Progress;
use halfwing::io::{IoError, MeshFormat, PlyEncoding, read_path, write_obj, write_off, write_ply};
use halfwing::soup::PolygonSoup;
use std::path::Path;

/// The mesh in `path`, read by the reader its extension names.
pub fn read_mesh(path: &str) -> Result<PolygonSoup, Failure> {
    let _progress = Progress::start(format!("reading {path}"));
    read_path(path).map_err(|e| Failure::input(describe(path, &e)))
}

/// Writes `soup` to `path` in the format its extension names; `binary` says how a PLY file is
/// encoded (OBJ and OFF are written as text).
pub fn write_mesh(path: &str, soup: &PolygonSoup, binary: bool) -> Result<(), Failure> {
    let format = output_format(path)?;
    let _progress = Progress::start(format!("writing {path}"));
    let file = std::fs::File::create(path)
        .map_err(|e| Failure::output(format!("{path}: cannot create: {e}")))?;
    let file = std::io::BufWriter::new(file);
    match format {
        MeshFormat::Obj => write_obj(file, soup),
        MeshFormat::Off => write_off(file, soup),
        MeshFormat::Ply if binary => write_ply(file, soup, PlyEncoding::BinaryLittleEndian),
        MeshFormat::Ply => write_ply(file, soup, PlyEncoding::Ascii),
    }
    .map_err(|e| Failure::output(describe(path, &e)))
}

/// The format of an output path, refused (a usage error) before anything is read.
pub fn output_format(path: &str) -> Result<MeshFormat, Failure> {
    MeshFormat::from_path(Path::new(path)).ok_or_else(|| {
        Failure::usage(format!(
            "{path}: unknown output format (use .obj, .off or .ply)"
        ))
    })
}

/// The error's message, naming the file when the message does not already.
fn describe(path: &str, error: &IoError) -> String {
    let message = error.to_string();
    if message.contains(path) {
        message
    } else {
        format!("{path}: {message}")
    }
}
