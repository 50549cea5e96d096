//! Wavefront OBJ reader.
//!
//! Why not `tobj`: tobj renumbers vertices per object/group in order of first use, so it drops
//! unreferenced vertices, changes vertex order and splits a vertex shared by two groups into two
//! (a connected mesh with `g` records would fall apart); its errors carry no line number; it reads
//! `f32` unless a feature is set; and it allocates a `String` per line. This reader keeps the
//! file's vertex numbering, so a soup written and read again is the same soup.
//!
//! What is read: `v x y z` (extra components such as `w` or vertex colours are ignored), `vn`,
//! `vt u [v [w]]` (a missing `v` is 0), and `f`/`fo` records whose corners are `v`, `v/vt`,
//! `v//vn` or `v/vt/vn`, with 1-based or negative (relative) indices. Polygons stay polygons;
//! faces with one or two corners are kept for the builder's diagnostic to report. Everything else
//! (`o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, free-form geometry) is ignored, so a missing
//! `.mtl` file is harmless. `#` starts a comment anywhere on a line.
//!
//! A line whose last character before any comment and trailing whitespace is `\` continues on
//! the next line, as if the `\` were a space (any record may be continued, over any number of
//! lines; a `\` on the last line of the file continues onto nothing). A `\` inside a comment is
//! part of the comment, so commented-out text never swallows the next record. Errors name the
//! line of the offending token.
//!
//! Corner attributes: if any corner has a normal (texture coordinate), `corner_normals`
//! (`corner_uvs`) is present, and every corner has a defined value. A corner without a normal
//! gets the zero vector, which is no direction (a `vn 0 0 0` reads the same) and which the render
//! buffers replace by the normal they compute; Blender's custom normals use the same convention.
//! A corner without a texture coordinate gets `(0, 0)`, as Blender's and three.js's OBJ loaders
//! give it: the faces of an OBJ that lack `vt` are typically those whose material has no
//! texture, so their uvs are never looked up, while dropping every uv would untexture the faces
//! that have them, and a NaN would poison any arithmetic on the uvs.
//!
//! Indices may refer to vertices defined further down the file (some exporters do that); an index
//! that is still out of range at the end is an error at the line of its face.

use std::io::Read;

use crate::soup::PolygonSoup;
use crate::support::allocation::{OutOfMemory, try_push, try_vec_with_capacity};

use super::error::IoError;
use super::format::MeshFormat;
use super::text::{Lines, Tokens, first_nul_line, parse_f64, parse_i64, quote, strip_comment};

/// Marks a corner without a normal or texture coordinate.
const ABSENT: u32 = u32::MAX;

/// Reads an OBJ file from any reader (the whole input is read first).
pub fn read_obj(mut reader: impl Read) -> Result<PolygonSoup, IoError> {
    let mut bytes = Vec::new();
    reader.read_to_end(&mut bytes)?;
    read_obj_bytes(&bytes)
}

/// Reads an OBJ file held in memory.
pub fn read_obj_bytes(bytes: &[u8]) -> Result<PolygonSoup, IoError> {
    // OBJ readers skip statements they do not know, so binary data would read as an empty mesh.
    if let Some(line) = first_nul_line(bytes) {
        return Err(IoError::at_line(
            MeshFormat::Obj,
            line,
            "the file holds a NUL byte: it is not a text file",
        ));
    }
    // OBJ declares no counts; vectors grow as records come (large regrowths are cheap `mremap`s).
    let mut reader = ObjReader::default();
    // A record continued over several lines is joined here, its lines separated by `\n` so the
    // tokens still know their line; a record on one line is read in place.
    let mut joined = Vec::new();
    let mut joined_from: Option<u64> = None;
    for (line_number, line) in Lines::new(bytes) {
        let content = strip_comment(line);
        let (content, continues) = match content.trim_ascii_end().strip_suffix(b"\\") {
            Some(head) => (head, true),
            None => (content, false),
        };
        match joined_from {
            None if !continues => reader.record(line_number, content)?,
            None => {
                joined.clear();
                joined.extend_from_slice(content);
                joined_from = Some(line_number);
            }
            Some(first_line) => {
                joined.push(b'\n');
                joined.extend_from_slice(content);
                if !continues {
                    reader.record(first_line, &joined)?;
                    joined_from = None;
                }
            }
        }
    }
    // A continuation on the last line continues onto nothing: the record ends with the file.
    if let Some(first_line) = joined_from {
        reader.record(first_line, &joined)?;
    }
    reader.finish()
}

/// One of the three arrays a corner index refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Position,
    TexCoord,
    Normal,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Position => "vertex",
            Kind::TexCoord => "texture coordinate",
            Kind::Normal => "normal",
        }
    }
}

/// An index that pointed past the end of its array when its face was read.
struct ForwardReference {
    line: u64,
    kind: Kind,
    index: u32,
}

#[derive(Default)]
struct ObjReader {
    line: u64,
    positions: Vec<[f64; 3]>,
    normals: Vec<[f64; 3]>,
    uvs: Vec<[f64; 2]>,
    face_sizes: Vec<u32>,
    indices: Vec<u32>,
    corner_normal_refs: Vec<u32>,
    corner_uv_refs: Vec<u32>,
    forward_references: Vec<ForwardReference>,
}

impl ObjReader {
    fn error(&self, message: impl Into<String>) -> IoError {
        IoError::at_line(MeshFormat::Obj, self.line, message)
    }

    /// Reads one record starting on line `first_line`, its lines joined by `\n` when continued.
    /// `self.line` follows the tokens, so errors name the line of the offending token.
    fn record(&mut self, first_line: u64, record: &[u8]) -> Result<(), IoError> {
        self.line = first_line;
        let mut tokens = Tokens::new(record, first_line);
        let keyword = tokens.next();
        self.line = tokens.line();
        match keyword {
            Some(b"v") => {
                let position = self.floats::<3>(&mut tokens, 3, "vertex")?;
                if self.positions.len() >= u32::MAX as usize {
                    return Err(self.error("more than 4294967295 vertices"));
                }
                try_push(&mut self.positions, position, "vertices")?;
            }
            Some(b"vn") => {
                let normal = self.floats::<3>(&mut tokens, 3, "normal")?;
                try_push(&mut self.normals, normal, "normals")?;
            }
            Some(b"vt") => {
                let uv = self.floats::<2>(&mut tokens, 1, "texture coordinate")?;
                try_push(&mut self.uvs, uv, "texture coordinates")?;
            }
            Some(b"f" | b"fo") => self.face(tokens)?,
            _ => {}
        }
        Ok(())
    }

    /// Up to `N` numbers after a keyword, at least `required`; missing optional ones are 0 and
    /// extra ones are ignored.
    fn floats<const N: usize>(
        &mut self,
        tokens: &mut Tokens<'_>,
        required: usize,
        what: &str,
    ) -> Result<[f64; N], IoError> {
        let mut values = [0.0; N];
        for (i, value) in values.iter_mut().enumerate() {
            let token = tokens.next();
            self.line = tokens.line();
            match token {
                Some(token) => {
                    *value = parse_f64(token).ok_or_else(|| {
                        self.error(format!(
                            "{what} component {} is not a number: {}",
                            i + 1,
                            quote(token)
                        ))
                    })?;
                }
                None if i < required => {
                    return Err(
                        self.error(format!("{what} has {i} components, expected {required}"))
                    );
                }
                None => break,
            }
        }
        Ok(values)
    }

    fn face(&mut self, mut tokens: Tokens<'_>) -> Result<(), IoError> {
        let mut size = 0u32;
        while let Some(corner) = tokens.next() {
            self.line = tokens.line();
            let mut parts = corner.split(|&b| b == b'/');
            let vertex = parts.next().unwrap_or_default();
            let uv = parts.next().unwrap_or_default();
            let normal = parts.next().unwrap_or_default();
            if parts.next().is_some() {
                return Err(self.error(format!(
                    "corner {} has more than three indices",
                    quote(corner)
                )));
            }
            if vertex.is_empty() {
                return Err(self.error(format!("corner {} has no vertex index", quote(corner))));
            }
            let vertex = self.resolve(vertex, Kind::Position)?;
            try_push(&mut self.indices, vertex, "corners")?;
            let uv = if uv.is_empty() {
                ABSENT
            } else {
                self.resolve(uv, Kind::TexCoord)?
            };
            try_push(&mut self.corner_uv_refs, uv, "corners")?;
            let normal = if normal.is_empty() {
                ABSENT
            } else {
                self.resolve(normal, Kind::Normal)?
            };
            try_push(&mut self.corner_normal_refs, normal, "corners")?;
            size = size
                .checked_add(1)
                .ok_or_else(|| self.error("face has more than 2^32 - 1 corners"))?;
        }
        if size == 0 {
            return Err(self.error("face record without vertices"));
        }
        try_push(&mut self.face_sizes, size, "faces")?;
        Ok(())
    }

    fn defined(&self, kind: Kind) -> usize {
        match kind {
            Kind::Position => self.positions.len(),
            Kind::TexCoord => self.uvs.len(),
            Kind::Normal => self.normals.len(),
        }
    }

    /// A 0-based index from a 1-based or negative (relative to the records read so far) one.
    fn resolve(&mut self, token: &[u8], kind: Kind) -> Result<u32, IoError> {
        let value = parse_i64(token).ok_or_else(|| {
            self.error(format!(
                "{} index {} is not an integer",
                kind.name(),
                quote(token)
            ))
        })?;
        let defined = self.defined(kind);
        let resolved = match value {
            0 => {
                return Err(self.error(format!(
                    "{} index 0 is invalid (OBJ counts from 1)",
                    kind.name()
                )));
            }
            1.. => value - 1,
            _ => {
                let back = value.unsigned_abs();
                if back > defined as u64 {
                    return Err(self.error(format!(
                        "relative {} index {value} reaches before the first of the {defined} defined so far",
                        kind.name()
                    )));
                }
                (defined as u64 - back) as i64
            }
        };
        let resolved = u32::try_from(resolved)
            .ok()
            .filter(|&index| index != u32::MAX)
            .ok_or_else(|| self.error(format!("{} index {value} is too large", kind.name())))?;
        if resolved as usize >= defined {
            let reference = ForwardReference {
                line: self.line,
                kind,
                index: resolved,
            };
            try_push(
                &mut self.forward_references,
                reference,
                "forward references",
            )?;
        }
        Ok(resolved)
    }

    fn finish(self) -> Result<PolygonSoup, IoError> {
        if let Some(bad) = self
            .forward_references
            .iter()
            .find(|r| r.index as usize >= self.defined(r.kind))
        {
            let defined = self.defined(bad.kind);
            return Err(IoError::at_line(
                MeshFormat::Obj,
                bad.line,
                format!(
                    "{} index {} is out of range: the file defines {defined}",
                    bad.kind.name(),
                    u64::from(bad.index) + 1
                ),
            ));
        }
        let corner_normals = gather(&self.corner_normal_refs, &self.normals, "corner normals")?;
        let corner_uvs = gather(
            &self.corner_uv_refs,
            &self.uvs,
            "corner texture coordinates",
        )?;
        Ok(PolygonSoup {
            positions: self.positions,
            face_sizes: self.face_sizes,
            indices: self.indices,
            corner_normals,
            corner_uvs,
        })
    }
}

/// Per-corner values from per-corner references, zero where a corner has none (see the module
/// docs); `None` when no corner has one.
fn gather<const N: usize>(
    references: &[u32],
    values: &[[f64; N]],
    what: &'static str,
) -> Result<Option<Vec<[f64; N]>>, OutOfMemory> {
    if references.iter().all(|&r| r == ABSENT) {
        return Ok(None);
    }
    let mut gathered = try_vec_with_capacity(references.len(), what)?;
    gathered.extend(
        references
            .iter()
            .map(|&r| values.get(r as usize).copied().unwrap_or([0.0; N])),
    );
    Ok(Some(gathered))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<PolygonSoup, IoError> {
        read_obj_bytes(text.as_bytes())
    }

    #[test]
    fn polygons_stay_polygons_and_groups_keep_vertices_shared() {
        let soup =
            read("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ng a\nf 1 2 3 4\ng b\nf 1 3 2\n").unwrap();
        assert_eq!(soup.face_sizes, vec![4, 3]);
        assert_eq!(soup.indices, vec![0, 1, 2, 3, 0, 2, 1]);
        assert_eq!(soup.corner_normals, None);
        assert_eq!(soup.corner_uvs, None);
    }

    #[test]
    fn relative_indices_count_back_from_the_latest_record() {
        let soup = read("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -1 -2\n").unwrap();
        assert_eq!(soup.indices, vec![0, 1, 2, 0, 3, 2]);
    }

    #[test]
    fn corner_attributes_follow_their_corners() {
        let text =
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nvt 0.25 0.75\nvn 0 0 1\nf 1/1/1 2/2/1 3//1\n";
        let soup = read(text).unwrap();
        assert_eq!(soup.corner_normals, Some(vec![[0.0, 0.0, 1.0]; 3]));
        assert_eq!(
            soup.corner_uvs,
            Some(vec![[0.5, 0.0], [0.25, 0.75], [0.0, 0.0]])
        );
    }

    #[test]
    fn corners_without_attributes_get_zero() {
        // Normals on one face only, and mixed corner forms within a face.
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\n\
                    f 1//1 2//1 3//1\nf 1 2 3\nf 1/1 2 3/1/1\n";
        let soup = read(text).unwrap();
        let z = [0.0, 0.0, 1.0];
        assert_eq!(
            soup.corner_normals,
            Some(vec![
                z, z, z, [0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3], z
            ])
        );
        let h = [0.5, 0.5];
        assert_eq!(
            soup.corner_uvs,
            Some(vec![
                [0.0; 2], [0.0; 2], [0.0; 2], [0.0; 2], [0.0; 2], [0.0; 2], h, [0.0; 2], h
            ])
        );
    }

    #[test]
    fn continued_lines_join_into_one_record() {
        let one_line = read("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").unwrap();
        let continued = [
            // Over three lines, `\` glued to a token or followed by blanks and CRLF.
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 \\\n 2\\  \t\r\n3 4\n",
            // A comment after the `\`, and one on the continued line.
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 \\ # first two\n3 4 # last two\n",
            // A keyword alone on its line; a continued vertex record.
            "v 0 0 0\nv 1 0 0\nv \\\n1 1 0\nv 0 1 0\nf\\\n1 2 3 4\n",
            // A continuation on the last line, with and without a line end.
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4 \\\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4 \\",
            // Old Mac line ends.
            "v 0 0 0\rv 1 0 0\rv 1 1 0\rv 0 1 0\rf 1 2 \\\r3 4\r",
        ];
        for text in continued {
            assert_eq!(read(text).unwrap(), one_line, "{text:?}");
        }
        // A `\` inside a comment is part of it: the next line is a record of its own.
        let commented = read("# note \\\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
        assert_eq!(commented.unwrap(), one_line);
        // A continuation into a blank line ends the record there.
        let soup = read("v 0 0 0\nf 1 1 \\\n\nf 1 1 1\n").unwrap();
        assert_eq!(soup.face_sizes, vec![2, 3]);
    }

    #[test]
    fn errors_in_continued_records_name_the_line_of_the_offending_token() {
        let cases: [(&str, u64, &str); 5] = [
            (
                "v 0 0 0\nf 1 \\\n1 \\\n x\n",
                4,
                "index `x` is not an integer",
            ),
            (
                "v 0 0 0\nf 1 \\\n1 \\\n 9\n",
                4,
                "vertex index 9 is out of range",
            ),
            ("v 0 \\\n0 \\\n", 2, "2 components"),
            ("v 0 \\\n0 \\\n\n", 3, "2 components"),
            ("v 0 \\\n0 y\n", 2, "not a number: `y`"),
        ];
        for (text, line, message) in cases {
            let error = read(text).unwrap_err();
            assert_eq!(error.line(), Some(line), "{text:?}: {error}");
            assert!(error.to_string().contains(message), "{text:?}: {error}");
        }
    }

    #[test]
    fn forward_references_resolve_at_the_end() {
        let soup = read("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n").unwrap();
        assert_eq!(soup.indices, vec![0, 1, 2]);
    }

    #[test]
    fn errors_name_their_line() {
        let cases: [(&str, u64, &str); 9] = [
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 7\n",
                5,
                "vertex index 7 is out of range",
            ),
            ("v 0 0 0\nf 0 1 1\n", 2, "index 0 is invalid"),
            ("v 0 0 0\nf -2 1 1\n", 2, "reaches before"),
            ("v 0 0 x\n", 1, "not a number: `x`"),
            ("v 0 0\n", 1, "2 components"),
            ("\n\nf\n", 3, "without vertices"),
            ("v 0 0 0\nf 1/1/1/1\n", 2, "more than three"),
            ("v 0 0 0\nf 1 a 1\n", 2, "not an integer"),
            (
                "v 0 0 0\nvt 0 0\nf 1/2 1/1 1/1\n",
                3,
                "texture coordinate index 2 is out of range",
            ),
        ];
        for (text, line, message) in cases {
            let error = read(text).unwrap_err();
            assert_eq!(error.line(), Some(line), "{text:?}: {error}");
            assert!(error.to_string().contains(message), "{text:?}: {error}");
        }
    }

    #[test]
    fn byte_order_marks_and_old_mac_line_ends_lose_no_record() {
        let soup = read("\u{FEFF}v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r").unwrap();
        assert_eq!(soup.positions.len(), 3);
        assert_eq!(soup.face_sizes, vec![3]);
        assert_eq!(read("v 0 0 0\rf 1 1 9\r").unwrap_err().line(), Some(2));
    }

    #[test]
    fn nan_coordinates_are_values() {
        let soup = read("v nan 0 inf\n").unwrap();
        assert!(soup.positions[0][0].is_nan());
        assert_eq!(soup.positions[0][2], f64::INFINITY);
    }
}
