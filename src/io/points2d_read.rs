//! Reading 2D point files, as point sets for Voronoi diagrams come: `.xy` and `.cin` (a point per
//! line), `.node` and `.poly` (Triangle's format: a header `count 2 ...`, then `index x y ...`
//! lines), `.txt` (a count line, then a point per line) and `.json` (a flat or nested array of
//! coordinates). In the line formats `#` starts a comment and numbers may also be separated by
//! commas.
//!
//! Memory grows with the points the file holds, never with a count it announces: a header
//! claiming more points than follow is refused after the lines run out.

use std::fmt;
use std::path::Path;

use super::error::{FileAction, IoError};
use super::text::{Lines, is_blank, parse_f64, quote, strip_comment};
use crate::support::allocation::try_push;

/// A 2D point file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PointFormat {
    /// A point per line, `x y` (`.xy`, `.cin`); further numbers on a line are ignored.
    Xy,
    /// Triangle's node and poly files (`.node`, `.poly`): a header `count 2 ...`, then `count`
    /// lines `index x y ...`. The segments of a `.poly` file that follow are not read.
    Triangle,
    /// A count line, then that many lines `x y` (`.txt`).
    Counted,
    /// A flat or nested array of numbers taken in pairs (`.json`).
    Json,
}

impl PointFormat {
    /// The format a path's extension names (case-insensitive), or `None` for any other extension.
    pub fn from_path(path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?;
        [
            ("xy", PointFormat::Xy),
            ("cin", PointFormat::Xy),
            ("node", PointFormat::Triangle),
            ("poly", PointFormat::Triangle),
            ("txt", PointFormat::Counted),
            ("json", PointFormat::Json),
        ]
        .into_iter()
        .find(|(name, _)| extension.eq_ignore_ascii_case(name))
        .map(|(_, format)| format)
    }

    /// A short name of the format, for messages.
    pub fn name(self) -> &'static str {
        match self {
            PointFormat::Xy => "XY",
            PointFormat::Triangle => "Triangle node",
            PointFormat::Counted => "counted text",
            PointFormat::Json => "JSON",
        }
    }
}

impl fmt::Display for PointFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Reads the 2D points of the file at `path`, in file order, choosing the format by the
/// extension (`.xy`, `.cin`, `.node`, `.poly`, `.txt`, `.json`, in any case). A malformed file
/// gives [`IoError::PointParse`] naming the file and the line; an unknown extension
/// [`IoError::Unsupported`]; an unreadable file [`IoError::File`]. Non-finite coordinates are
/// read as values (what uses the points decides about them).
pub fn read_points2d(path: impl AsRef<Path>) -> Result<Vec<[f64; 2]>, IoError> {
    let path = path.as_ref();
    let format = PointFormat::from_path(path).ok_or_else(|| {
        IoError::Unsupported(format!(
            "'{}': unknown point format (use .xy, .cin, .node, .poly, .txt or .json)",
            path.display()
        ))
    })?;
    let bytes =
        std::fs::read(path).map_err(|e| IoError::from(e).on_file(FileAction::Read, path))?;
    read_points2d_bytes(format, &bytes).map_err(|e| e.in_file(path))
}

/// Reads 2D points held in memory in the given format (as [`read_points2d`], the error naming
/// no file).
pub fn read_points2d_bytes(format: PointFormat, bytes: &[u8]) -> Result<Vec<[f64; 2]>, IoError> {
    match format {
        PointFormat::Json => read_json(bytes),
        PointFormat::Xy => read_lines(bytes, format, None),
        PointFormat::Triangle => read_lines(bytes, format, Some(1)),
        PointFormat::Counted => read_lines(bytes, format, Some(0)),
    }
}

/// A parse error of `format` at `line`.
fn fail(format: PointFormat, line: u64, message: impl Into<String>) -> IoError {
    IoError::PointParse {
        path: None,
        format,
        line,
        message: message.into(),
    }
}

/// Numbers of a line format are separated by white space and commas.
fn line_numbers(line: &[u8]) -> impl Iterator<Item = &[u8]> {
    line.split(|&b| b.is_ascii_whitespace() || b == b',')
        .filter(|token| !token.is_empty())
}

/// The number `token`, or the error naming it.
fn number(format: PointFormat, line: u64, token: &[u8]) -> Result<f64, IoError> {
    parse_f64(token).ok_or_else(|| fail(format, line, format!("{} is not a number", quote(token))))
}

/// The points of a line format. With `header_x_column`, the first line is a header giving the
/// point count (and, for Triangle's format, the dimension 2), and each point line has its `x`
/// in that column; otherwise every line is a point `x y`.
fn read_lines(
    bytes: &[u8],
    format: PointFormat,
    header_x_column: Option<usize>,
) -> Result<Vec<[f64; 2]>, IoError> {
    let mut lines = Lines::new(bytes)
        .map(|(number, line)| (number, strip_comment(line)))
        .filter(|(_, line)| !is_blank(line));
    let (x_column, count) = match header_x_column {
        None => (0, None),
        Some(x_column) => {
            let (line, header) = lines
                .next()
                .ok_or_else(|| fail(format, 1, "no header (a point count)"))?;
            let mut values = line_numbers(header);
            let count = values
                .next()
                .and_then(|t| std::str::from_utf8(t).ok()?.parse::<u64>().ok())
                .ok_or_else(|| fail(format, line, "the header must start with a point count"))?;
            if format == PointFormat::Triangle {
                let dimension = values.next().map(|t| number(format, line, t)).transpose()?;
                if dimension != Some(2.0) {
                    return Err(fail(format, line, "the header must give dimension 2"));
                }
            }
            (x_column, Some((line, count)))
        }
    };
    let mut points = Vec::new();
    let mut read = 0u64;
    for (line, text) in lines {
        if count.is_some_and(|(_, count)| read == count) {
            break;
        }
        let mut values = line_numbers(text).skip(x_column);
        let mut coordinate = || -> Result<f64, IoError> {
            let token = values.next().ok_or_else(|| {
                fail(
                    format,
                    line,
                    format!(
                        "expected a point, found {} numbers",
                        line_numbers(text).count()
                    ),
                )
            })?;
            number(format, line, token)
        };
        let point = [coordinate()?, coordinate()?];
        // The rest of the line must be numbers too (Triangle's attributes and markers).
        for token in values {
            number(format, line, token)?;
        }
        try_push(&mut points, point, "points")?;
        read += 1;
    }
    if let Some((header_line, count)) = count
        && read < count
    {
        return Err(fail(
            format,
            header_line,
            format!("{count} points announced, {read} lines follow"),
        ));
    }
    Ok(points)
}

/// The points of a JSON array of numbers (nested arrays flattened), taken in pairs.
fn read_json(bytes: &[u8]) -> Result<Vec<[f64; 2]>, IoError> {
    let format = PointFormat::Json;
    let mut points = Vec::new();
    let mut pending: Option<f64> = None;
    let mut depth = 0usize;
    let mut seen_array = false;
    for (line, text) in Lines::new(bytes) {
        let mut rest = text;
        while let Some(&byte) = rest.first() {
            let token_end = rest
                .iter()
                .position(|&b| b.is_ascii_whitespace() || b == b',' || b == b'[' || b == b']')
                .unwrap_or(rest.len());
            if token_end == 0 {
                match byte {
                    b'[' => {
                        depth += 1;
                        seen_array = true;
                    }
                    b']' => {
                        depth = depth
                            .checked_sub(1)
                            .ok_or_else(|| fail(format, line, "unmatched ']'"))?;
                    }
                    _ => {}
                }
                rest = &rest[1..];
                continue;
            }
            let token = &rest[..token_end];
            if depth == 0 {
                return Err(fail(
                    format,
                    line,
                    format!("{} outside the array", quote(token)),
                ));
            }
            let value = number(format, line, token)?;
            match pending.take() {
                None => pending = Some(value),
                Some(x) => try_push(&mut points, [x, value], "points")?,
            }
            rest = &rest[token_end..];
        }
    }
    let last_line = Lines::new(bytes).count().max(1) as u64;
    if !seen_array || depth != 0 {
        return Err(fail(format, last_line, "expected one array of numbers"));
    }
    if pending.is_some() {
        return Err(fail(
            format,
            last_line,
            format!("{} coordinates: not pairs", 2 * points.len() + 1),
        ));
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(format: PointFormat, text: &str) -> Result<Vec<[f64; 2]>, IoError> {
        read_points2d_bytes(format, text.as_bytes())
    }

    fn line_of(error: IoError) -> u64 {
        error.line().expect("a parse error with a line")
    }

    #[test]
    fn every_format_reads_its_points_in_order() {
        let expected = vec![[0.0, 1.0], [2.5, -3.0]];
        assert_eq!(
            read(PointFormat::Xy, "# two\n0 1\n\n2.5, -3 7\n").unwrap(),
            expected
        );
        assert_eq!(
            read(
                PointFormat::Triangle,
                "2 2 0 1\n1 0 1 0\n2 2.5 -3 1\n# segments\n2 0\n"
            )
            .unwrap(),
            expected
        );
        assert_eq!(
            read(PointFormat::Counted, "2\n0 1\n2.5 -3\n9 9\n").unwrap(),
            expected
        );
        assert_eq!(
            read(PointFormat::Json, "[[0, 1],\n [2.5, -3]]\n").unwrap(),
            expected
        );
        assert_eq!(read(PointFormat::Json, "[0,1,2.5,-3]").unwrap(), expected);
        assert_eq!(read(PointFormat::Xy, "").unwrap(), Vec::<[f64; 2]>::new());
        assert_eq!(
            read(PointFormat::Json, "[]").unwrap(),
            Vec::<[f64; 2]>::new()
        );
    }

    #[test]
    fn malformed_files_name_the_line_and_the_problem() {
        let error = read(PointFormat::Xy, "0 1\n2 x\n").unwrap_err();
        assert!(error.to_string().contains("`x` is not a number"), "{error}");
        assert_eq!(line_of(error), 2);
        assert_eq!(line_of(read(PointFormat::Xy, "0 1\n\n5\n").unwrap_err()), 3);
        let error = read(PointFormat::Counted, "# header next\n3\n0 1\n").unwrap_err();
        assert!(
            error
                .to_string()
                .contains("3 points announced, 1 lines follow")
        );
        assert_eq!(line_of(error), 2);
        assert_eq!(line_of(read(PointFormat::Counted, "").unwrap_err()), 1);
        assert_eq!(line_of(read(PointFormat::Counted, "-1\n").unwrap_err()), 1);
        let error = read(PointFormat::Triangle, "1 3 0 0\n1 0 0 0\n").unwrap_err();
        assert!(error.to_string().contains("dimension 2"));
        assert_eq!(
            line_of(read(PointFormat::Triangle, "1 2\n1 0 0 x\n").unwrap_err()),
            2
        );
        assert_eq!(
            line_of(read(PointFormat::Json, "[0, 1,\n 2]").unwrap_err()),
            2
        );
        assert_eq!(
            line_of(read(PointFormat::Json, "[0, 1]]\n").unwrap_err()),
            1
        );
        assert_eq!(line_of(read(PointFormat::Json, "[0, 1\n").unwrap_err()), 1);
        assert_eq!(line_of(read(PointFormat::Json, "7").unwrap_err()), 1);
        assert_eq!(
            line_of(read(PointFormat::Json, "[0, \"a\"]").unwrap_err()),
            1
        );
    }

    /// A header announcing more points than memory holds is refused once the lines run out:
    /// nothing is allocated for the announced count.
    #[test]
    fn a_huge_announced_count_allocates_nothing_for_it() {
        let error = read(PointFormat::Counted, "18446744073709551615\n0 1\n").unwrap_err();
        assert!(
            matches!(error, IoError::PointParse { line: 1, .. }),
            "{error}"
        );
        let error = read(PointFormat::Triangle, "99999999999 2\n").unwrap_err();
        assert!(error.to_string().contains("99999999999 points announced"));
    }

    #[test]
    fn files_are_named_in_errors_and_chosen_by_extension() {
        let dir = std::env::temp_dir().join(format!("halfwing-points-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let good = dir.join("good.XY");
        std::fs::write(&good, "1 2\n3 4\n").unwrap();
        assert_eq!(read_points2d(&good).unwrap(), vec![[1.0, 2.0], [3.0, 4.0]]);
        let bad = dir.join("bad.node");
        std::fs::write(&bad, "1 2\n1 0 zero\n").unwrap();
        let error = read_points2d(&bad).unwrap_err();
        assert_eq!(error.line(), Some(2));
        assert!(
            error
                .to_string()
                .starts_with(&format!("'{}' line 2:", bad.display())),
            "{error}"
        );
        assert!(matches!(
            read_points2d(dir.join("points.csv")),
            Err(IoError::Unsupported(_))
        ));
        assert!(matches!(
            read_points2d(dir.join("missing.xy")),
            Err(IoError::File { .. })
        ));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
