//! The file formats halfwing reads and writes, and how a path names one.

use std::fmt;
use std::path::Path;

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// Wavefront OBJ (`.obj`).
    Obj,
    /// Geomview Object File Format (`.off`), including the `NOFF`, `COFF` and `STOFF` variants.
    Off,
    /// Stanford polygon file (`.ply`), ASCII or binary.
    Ply,
}

impl MeshFormat {
    /// The format a path's extension names (case-insensitive), or `None` for any other extension.
    pub fn from_path(path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?;
        [
            ("obj", MeshFormat::Obj),
            ("off", MeshFormat::Off),
            ("ply", MeshFormat::Ply),
        ]
        .into_iter()
        .find(|(name, _)| extension.eq_ignore_ascii_case(name))
        .map(|(_, format)| format)
    }

    /// The format's usual short name (`OBJ`, `OFF`, `PLY`).
    pub fn name(self) -> &'static str {
        match self {
            MeshFormat::Obj => "OBJ",
            MeshFormat::Off => "OFF",
            MeshFormat::Ply => "PLY",
        }
    }
}

impl fmt::Display for MeshFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
