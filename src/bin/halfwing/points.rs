//! 2D point files, as the test point sets come: `.xy` and `.cin` (a point per line), `.node`
//! and `.poly` (Triangle: a header `count 2 ...`, then `index x y ...` lines), `.txt` (a count
//! line, then a point per line) and `.json` (a flat or nested array of coordinates). `#` starts
//! a comment in the line formats.

use crate::failure::Failure;

/// The points of the file at `path`, in file order.
pub fn read_points(path: &str) -> Result<Vec<[f64; 2]>, Failure> {
    let extension = std::path::Path::new(path)
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    if !["xy", "cin", "node", "poly", "txt", "json"].contains(&extension.as_str()) {
        return Err(Failure::input(format!(
            "{path}: unknown point format (use .xy, .cin, .node, .poly, .txt or .json)"
        )));
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::input(format!("{path}: cannot read: {e}")))?;
    let fail = |line: usize, message: String| Failure::input(format!("{path}:{line}: {message}"));
    let lines: Vec<(usize, Vec<f64>)> = if extension == "json" {
        Vec::new()
    } else {
        let mut lines = Vec::new();
        for (i, line) in text.lines().enumerate() {
            let content = line.split('#').next().unwrap_or("").trim();
            if !content.is_empty() {
                lines.push((i + 1, numbers(content).map_err(|m| fail(i + 1, m))?));
            }
        }
        lines
    };
    // The points of the lines after a header giving their count, columns `x_column` and the next.
    let counted = |x_column: usize| -> Result<Vec<[f64; 2]>, Failure> {
        let (header_line, header) = lines
            .first()
            .ok_or_else(|| fail(1, "no header (a point count)".into()))?;
        let count = header
            .first()
            .filter(|c| c.fract() == 0.0 && **c >= 0.0)
            .ok_or_else(|| {
                fail(
                    *header_line,
                    "the header must start with a point count".into(),
                )
            })?;
        let count = *count as usize;
        if lines.len() - 1 < count {
            return Err(fail(
                *header_line,
                format!("{count} points announced, {} lines follow", lines.len() - 1),
            ));
        }
        lines[1..=count]
            .iter()
            .map(|(l, v)| point(v, x_column).map_err(|m| fail(*l, m)))
            .collect()
    };
    match extension.as_str() {
        "json" => {
            let values = numbers(&text).map_err(|m| fail(1, m))?;
            if values.len() % 2 != 0 {
                return Err(fail(1, format!("{} coordinates: not pairs", values.len())));
            }
            Ok(values.chunks(2).map(|c| [c[0], c[1]]).collect())
        }
        "xy" | "cin" => lines
            .iter()
            .map(|(l, v)| point(v, 0).map_err(|m| fail(*l, m)))
            .collect(),
        "node" | "poly" => {
            if let Some((l, header)) = lines.first()
                && header.get(1) != Some(&2.0)
            {
                return Err(fail(*l, "the header must give dimension 2".into()));
            }
            counted(1)
        }
        // "txt": a count line, then a point per line.
        _ => counted(0),
    }
}

/// The numbers of a line (separated by white space, commas and brackets).
fn numbers(text: &str) -> Result<Vec<f64>, String> {
    text.split(|c: char| c.is_whitespace() || c == ',' || c == '[' || c == ']')
        .filter(|t| !t.is_empty())
        .map(|t| {
            t.parse::<f64>()
                .map_err(|_| format!("{t:?} is not a number"))
        })
        .collect()
}

fn point(values: &[f64], x_column: usize) -> Result<[f64; 2], String> {
    match values.get(x_column..x_column + 2) {
        Some(&[x, y]) => Ok([x, y]),
        _ => Err(format!("expected a point, found {} numbers", values.len())),
    }
}
