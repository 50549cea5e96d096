//! Writing numbers as text that reads back bit for bit.
//!
//! Floats use Rust's shortest round-trip form (`{:?}`): the fewest digits that parse back to the
//! same `f64`, with an exponent for very large or small magnitudes (`1e-7`, `1e300`), and `NaN`,
//! `inf`, `-inf` for non-finite values.

use std::io::{self, Write};

/// Writes `prefix` followed by each value after a space, and a newline.
pub(crate) fn write_row(out: &mut impl Write, prefix: &str, values: &[f64]) -> io::Result<()> {
    out.write_all(prefix.as_bytes())?;
    for (i, value) in values.iter().enumerate() {
        let separator = if i == 0 && prefix.is_empty() { "" } else { " " };
        write!(out, "{separator}{value:?}")?;
    }
    out.write_all(b"\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_read_back_exactly() {
        let values = [
            0.1,
            -0.0,
            1e300,
            5e-324,
            f64::MAX,
            1.0 / 3.0,
            f64::NEG_INFINITY,
        ];
        let mut out = Vec::new();
        write_row(&mut out, "v", &values).unwrap();
        let text = String::from_utf8(out).unwrap();
        let back: Vec<f64> = text
            .split_whitespace()
            .skip(1)
            .map(|t| t.parse().unwrap())
            .collect();
        assert_eq!(back.len(), values.len());
        for (a, b) in values.iter().zip(&back) {
            assert_eq!(a.to_bits(), b.to_bits());
        }
        let mut out = Vec::new();
        write_row(&mut out, "", &[1.5, 2.0]).unwrap();
        assert_eq!(out, b"1.5 2.0\n");
    }
}
