//! Geomview OFF reader.
//!
//! Layout: a keyword `[ST][C][N]OFF`, the counts `vertices faces [edges]` (on the keyword's line,
//! even glued to it as in `OFF8 6 12`, or on the next line; the edge count is ignored), one vertex
//! per line (`x y z`, then `nx ny nz` with `N`, colour components with `C`, and `s t` as the last
//! two numbers with `ST`), then the faces (`n i0 … i(n-1)`, 0-based, followed by an optional
//! colour that is ignored). A face starts on a new line and its indices may run on over the
//! following lines; its colour is the rest of the line holding its last index, as in Geomview's
//! definition of the format (the colour runs to the end of the line) and in the OpenMesh and CGAL
//! readers.
//! `#` starts a comment anywhere; blank lines and any leading or trailing whitespace are skipped.
//! Vertex normals and texture coordinates are spread onto the corners. `4OFF`, `nOFF` and binary
//! OFF are refused as unsupported. Text after the last face is ignored.

use std::io::Read;

use crate::soup::PolygonSoup;
use crate::support::allocation::try_vec_with_capacity;

use super::attributes::spread_to_corners;
use super::error::IoError;
use super::format::MeshFormat;
use super::text::{
    Lines, Tokens, capacity_for, is_blank, parse_f64, parse_i64, quote, strip_comment,
};

/// Reads an OFF file from any reader (the whole input is read first).
pub fn read_off(mut reader: impl Read) -> Result<PolygonSoup, IoError> {
    let mut bytes = Vec::new();
    reader.read_to_end(&mut bytes)?;
    read_off_bytes(&bytes)
}

/// What the keyword announces besides positions.
#[derive(Default)]
struct Variant {
    normals: bool,
    texture: bool,
}

/// Lines that carry data: comments stripped, blank lines skipped.
struct Records<'a> {
    lines: Lines<'a>,
}

impl<'a> Records<'a> {
    fn next(&mut self) -> Option<(u64, &'a [u8])> {
        self.lines
            .by_ref()
            .map(|(n, line)| (n, strip_comment(line)))
            .find(|(_, line)| !is_blank(line))
    }

    /// The next record, or an error at the line after the file's end naming what is missing.
    fn expect(&mut self, missing: impl FnOnce() -> String) -> Result<(u64, &'a [u8]), IoError> {
        match self.next() {
            Some(record) => Ok(record),
            None => Err(IoError::at_line(
                MeshFormat::Off,
                self.lines.last_number() + 1,
                format!("unexpected end of file: {}", missing()),
            )),
        }
    }
}

/// Reads an OFF file held in memory.
pub fn read_off_bytes(bytes: &[u8]) -> Result<PolygonSoup, IoError> {
    let mut records = Records {
        lines: Lines::new(bytes),
    };
    let (header_line, header) = records.expect(|| "no OFF header".to_owned())?;
    let error = |line: u64, message: String| IoError::at_line(MeshFormat::Off, line, message);

    let mut tokens = Tokens::new(header, header_line);
    let keyword = tokens.next().unwrap_or_default();
    let (variant, glued_count) = parse_keyword(keyword).map_err(|problem| match problem {
        KeywordProblem::Unsupported(what) => IoError::Unsupported(what),
        KeywordProblem::Malformed(message) => error(header_line, message),
    })?;
    let mut count_tokens: Vec<(u64, &[u8])> =
        glued_count.into_iter().map(|t| (header_line, t)).collect();
    count_tokens.extend(tokens.map(|t| (header_line, t)));
    if count_tokens
        .first()
        .is_some_and(|(_, t)| t.eq_ignore_ascii_case(b"BINARY"))
    {
        return Err(IoError::Unsupported("binary OFF".to_owned()));
    }
    if count_tokens.len() < 2 {
        let (line, counts) = records.expect(|| "no vertex and face counts".to_owned())?;
        count_tokens.extend(Tokens::new(counts, line).map(|t| (line, t)));
    }
    let count = |i: usize, what: &str| -> Result<u64, IoError> {
        let (line, token) = count_tokens.get(i).copied().unwrap_or((header_line, b""));
        parse_i64(token)
            .and_then(|n| u64::try_from(n).ok())
            .ok_or_else(|| {
                error(
                    line,
                    format!(
                        "{what} count {} is not a non-negative integer",
                        quote(token)
                    ),
                )
            })
    };
    let vertex_count = count(0, "vertex")?;
    let face_count = count(1, "face")?;
    if vertex_count > u64::from(u32::MAX) {
        return Err(error(
            header_line,
            format!("{vertex_count} vertices cannot be indexed by 32-bit indices"),
        ));
    }

    let vertex_capacity = capacity_for(vertex_count, bytes.len(), 6);
    let mut positions = try_vec_with_capacity(vertex_capacity, "vertices")?;
    let mut normals = try_vec_with_capacity(
        if variant.normals { vertex_capacity } else { 0 },
        "vertex normals",
    )?;
    let mut uvs = try_vec_with_capacity(
        if variant.texture { vertex_capacity } else { 0 },
        "vertex texture coordinates",
    )?;
    for vertex in 0..vertex_count {
        let (line, record) =
            records.expect(|| format!("{vertex} of {vertex_count} vertices read"))?;
        let values = |skip: usize, what: &str| -> Result<[f64; 3], IoError> {
            let mut out = [0.0; 3];
            let mut tokens = Tokens::new(record, line).skip(skip);
            for (i, slot) in out.iter_mut().enumerate() {
                let token = tokens.next().ok_or_else(|| {
                    error(
                        line,
                        format!("vertex {vertex} has {} of 3 {what} components", i),
                    )
                })?;
                *slot = parse_f64(token).ok_or_else(|| {
                    error(
                        line,
                        format!(
                            "vertex {vertex} {what} component is not a number: {}",
                            quote(token)
                        ),
                    )
                })?;
            }
            Ok(out)
        };
        positions.push(values(0, "coordinate")?);
        if variant.normals {
            normals.push(values(3, "normal")?);
        }
        if variant.texture {
            // Colour components vary in number, so `s t` are found as the last two tokens.
            let (token_count, last_two) = Tokens::new(record, line)
                .fold((0usize, [&b""[..]; 2]), |(n, [_, last]), token| {
                    (n + 1, [last, token])
                });
            let first_extra = if variant.normals { 6 } else { 3 };
            if token_count < first_extra + 2 {
                return Err(error(
                    line,
                    format!("vertex {vertex} has no texture coordinates"),
                ));
            }
            match (parse_f64(last_two[0]), parse_f64(last_two[1])) {
                (Some(s), Some(t)) => uvs.push([s, t]),
                _ => {
                    return Err(error(
                        line,
                        format!("vertex {vertex} texture coordinate is not a number"),
                    ));
                }
            }
        }
    }

    let face_capacity = capacity_for(face_count, bytes.len(), 8);
    let mut face_sizes = try_vec_with_capacity(face_capacity, "faces")?;
    let mut indices = try_vec_with_capacity(face_capacity.saturating_mul(3), "corners")?;
    for face in 0..face_count {
        let (line, record) = records.expect(|| format!("{face} of {face_count} faces read"))?;
        let mut tokens = Tokens::new(record, line);
        let size_token = tokens.next().unwrap_or_default();
        let size = parse_i64(size_token)
            .and_then(|n| u32::try_from(n).ok())
            .ok_or_else(|| {
                error(
                    line,
                    format!(
                        "face {face} size {} is not a 32-bit count",
                        quote(size_token)
                    ),
                )
            })?;
        for corner in 0..size {
            // Indices run on over as many lines as they need; the colour, if any, is the rest
            // of the line of the last index (so the next face starts on a line of its own).
            let token = loop {
                if let Some(token) = tokens.next() {
                    break token;
                }
                let (next_line, next_record) = records.next().ok_or_else(|| {
                    error(
                        line,
                        format!("face {face} declares {size} vertices but lists {corner}"),
                    )
                })?;
                tokens = Tokens::new(next_record, next_line);
            };
            let index = parse_i64(token).ok_or_else(|| {
                error(
                    tokens.line(),
                    format!("face {face} index {} is not an integer", quote(token)),
                )
            })?;
            if !(0..vertex_count as i64).contains(&index) {
                return Err(error(
                    tokens.line(),
                    format!(
                        "face {face} index {index} is out of range: the file declares {vertex_count} vertices"
                    ),
                ));
            }
            indices.push(index as u32);
        }
        face_sizes.push(size);
    }

    let corner_normals = variant
        .normals
        .then(|| spread_to_corners(&normals, &indices));
    let corner_uvs = variant.texture.then(|| spread_to_corners(&uvs, &indices));
    Ok(PolygonSoup {
        positions,
        face_sizes,
        indices,
        corner_normals,
        corner_uvs,
    })
}

/// Why a keyword was refused.
enum KeywordProblem {
    Unsupported(String),
    Malformed(String),
}

/// The variant a keyword such as `STCNOFF` announces, and a count glued to its end (`OFF8`).
fn parse_keyword(keyword: &[u8]) -> Result<(Variant, Option<&[u8]>), KeywordProblem> {
    let at = keyword
        .windows(3)
        .position(|w| w == b"OFF")
        .ok_or_else(|| {
            KeywordProblem::Malformed(format!("expected an OFF keyword, found {}", quote(keyword)))
        })?;
    let (mut prefix, rest) = (&keyword[..at], &keyword[at + 3..]);
    let mut variant = Variant::default();
    if let Some(after) = prefix.strip_prefix(b"ST") {
        variant.texture = true;
        prefix = after;
    }
    if let Some(after) = prefix.strip_prefix(b"C") {
        prefix = after;
    }
    if let Some(after) = prefix.strip_prefix(b"N") {
        variant.normals = true;
        prefix = after;
    }
    if prefix.contains(&b'4') || prefix.contains(&b'n') {
        return Err(KeywordProblem::Unsupported(format!(
            "{} (4D or n-dimensional OFF)",
            quote(keyword)
        )));
    }
    if !prefix.is_empty() {
        return Err(KeywordProblem::Malformed(format!(
            "unknown OFF keyword {}",
            quote(keyword)
        )));
    }
    Ok((variant, (!rest.is_empty()).then_some(rest)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<PolygonSoup, IoError> {
        read_off_bytes(text.as_bytes())
    }

    #[test]
    fn counts_may_be_glued_or_on_their_own_line() {
        let glued = read("\t  OFF3 1 0 # note\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 0 0 0.5\n").unwrap();
        let separate = read("OFF\n# comment\n\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
        assert_eq!(glued, separate);
        assert_eq!(glued.face_sizes, vec![3]);
        assert_eq!(glued.indices, vec![0, 1, 2]);
    }

    #[test]
    fn normals_and_texture_coordinates_spread_to_corners() {
        let text =
            "STNOFF 3 1 0\n0 0 0 0 0 1 0.5 0.25\n1 0 0 0 0 1 1 0\n0 1 0 0 0 1 0 1\n3 2 1 0\n";
        let soup = read(text).unwrap();
        assert_eq!(soup.corner_normals, Some(vec![[0.0, 0.0, 1.0]; 3]));
        assert_eq!(
            soup.corner_uvs,
            Some(vec![[0.0, 1.0], [1.0, 0.0], [0.5, 0.25]])
        );
    }

    #[test]
    fn face_indices_may_run_on_over_several_lines() {
        let header = "OFF 5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n";
        let one_line = read(&format!("{header}4 0 1 2 3\n3 1 4 2\n")).unwrap();
        assert_eq!(one_line.face_sizes, vec![4, 3]);
        let split = [
            // Split after the size, between indices, with blank and comment lines between.
            "4\n0 1\n2 3\n3 1 4 2\n",
            "4 0 # first\n\n# more\n 1 2 \r\n3\n3\n1\n4\n2\n",
            // Colours after the last index, on its line; the next face starts on the next line.
            "4 0 1\n2 3 255 0 0\n3 1 4 2 0.5 0.5 0.5 1\n",
            "4 0 1 2\n3 0.1 0.2 0.3\n3 1\n4 2\n",
            // The last face split with no line end after it.
            "4 0 1 2 3\n3 1\n4\n2",
        ];
        for faces in split {
            let text = format!("{header}{faces}");
            assert_eq!(read(&text).unwrap(), one_line, "{text:?}");
        }
        // An empty face keeps the rest of its line as its colour.
        let soup = read(&format!("{header}0 1 1 1\n3 0 1 2\n")).unwrap();
        assert_eq!(soup.face_sizes, vec![0, 3]);
    }

    #[test]
    fn errors_in_split_faces_name_the_line_of_the_offending_token() {
        let header = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
        let cases: [(&str, u64, &str); 3] = [
            ("3 0\n1\n\n", 5, "declares 3 vertices but lists 2"),
            ("3 0\n\n1 x\n", 7, "index `x` is not an integer"),
            ("3\n0 1\n3\n", 7, "index 3 is out of range"),
        ];
        for (faces, line, message) in cases {
            let text = format!("{header}{faces}");
            let error = read(&text).unwrap_err();
            assert_eq!(error.line(), Some(line), "{text:?}: {error}");
            assert!(error.to_string().contains(message), "{text:?}: {error}");
        }
    }

    #[test]
    fn unsupported_variants_are_named() {
        assert!(matches!(
            read("4OFF\n0 0 0\n"),
            Err(IoError::Unsupported(_))
        ));
        assert!(matches!(read("XOFF\n0 0 0\n"), Err(IoError::Parse { .. })));
        assert!(matches!(read("OFF BINARY\n"), Err(IoError::Unsupported(_))));
    }

    #[test]
    fn errors_name_their_line() {
        let cases: [(&str, u64, &str); 8] = [
            ("", 1, "no OFF header"),
            ("PLY\n", 1, "expected an OFF keyword"),
            ("OFF\n3 x 0\n", 2, "face count `x`"),
            ("OFF 3 1 0\n0 0 0\n1 0 0\n", 4, "2 of 3 vertices"),
            (
                "OFF 3 1 0\n0 0 0\n1 0 a\n0 1 0\n3 0 1 2\n",
                3,
                "not a number: `a`",
            ),
            (
                "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
                5,
                "index 3 is out of range",
            ),
            (
                "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
                5,
                "declares 4 vertices but lists 3",
            ),
            (
                "OFF 3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                6,
                "1 of 2 faces",
            ),
        ];
        for (text, line, message) in cases {
            let error = read(text).unwrap_err();
            assert_eq!(error.line(), Some(line), "{text:?}: {error}");
            assert!(error.to_string().contains(message), "{text:?}: {error}");
        }
    }

    #[test]
    fn a_lying_header_does_not_exhaust_memory() {
        let error = read("OFF 4000000000 4000000000 0\n0 0 0\n").unwrap_err();
        assert_eq!(error.line(), Some(3));
    }
}
