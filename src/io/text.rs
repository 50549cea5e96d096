//! Allocation-free scanning of text mesh files held in memory: numbered lines, whitespace
//! separated tokens and number parsing, shared by the OBJ, OFF and ASCII PLY readers.
//!
//! Numbers are parsed by the standard library, so every float form Rust accepts is accepted,
//! including `nan`, `inf` and `infinity` in any case: such coordinates are read as values and left
//! for the builder's diagnostic to report, rather than failing the whole file.

/// Whitespace between tokens: space, tab, carriage return, line feed, vertical tab, form feed.
fn is_space(byte: u8) -> bool {
    matches!(byte, b' ' | b'\t' | b'\r' | b'\n' | 0x0b | 0x0c)
}

/// The UTF-8 byte order mark some editors put at the start of a text file.
const BYTE_ORDER_MARK: &[u8] = b"\xEF\xBB\xBF";

/// The lines of a buffer with their 1-based numbers, without their terminators. A line ends at
/// `\n`, `\r\n` or a lone `\r` (old Mac files), so no convention merges a file into one line.
/// A leading UTF-8 byte order mark is skipped.
pub(crate) struct Lines<'a> {
    bytes: &'a [u8],
    position: usize,
    number: u64,
}

impl<'a> Lines<'a> {
    pub(crate) fn new(bytes: &'a [u8]) -> Self {
        let position = if bytes.starts_with(BYTE_ORDER_MARK) {
            BYTE_ORDER_MARK.len()
        } else {
            0
        };
        Lines {
            bytes,
            position,
            number: 0,
        }
    }

    /// The number of the line last returned (0 before the first); one past it is where a file that
    /// ends too early is reported.
    pub(crate) fn last_number(&self) -> u64 {
        self.number
    }

    /// The byte offset just past the line last returned and its terminator.
    pub(crate) fn offset(&self) -> usize {
        self.position
    }
}

impl<'a> Iterator for Lines<'a> {
    type Item = (u64, &'a [u8]);

    fn next(&mut self) -> Option<Self::Item> {
        let rest = &self.bytes[self.position..];
        if rest.is_empty() {
            return None;
        }
        let end = rest
            .iter()
            .position(|&b| b == b'\n' || b == b'\r')
            .unwrap_or(rest.len());
        let terminator = match rest.get(end..end + 2) {
            Some(b"\r\n") => 2,
            _ if end < rest.len() => 1,
            _ => 0,
        };
        self.position += end + terminator;
        self.number += 1;
        Some((self.number, &rest[..end]))
    }
}

/// The part of a line before a `#` comment.
pub(crate) fn strip_comment(line: &[u8]) -> &[u8] {
    match line.iter().position(|&b| b == b'#') {
        Some(start) => &line[..start],
        None => line,
    }
}

/// Whether a line holds nothing but whitespace.
pub(crate) fn is_blank(line: &[u8]) -> bool {
    line.iter().all(|&b| is_space(b))
}

/// Whitespace-separated tokens of a buffer, counting the line each token is on.
#[derive(Clone)]
pub(crate) struct Tokens<'a> {
    bytes: &'a [u8],
    position: usize,
    line: u64,
}

impl<'a> Tokens<'a> {
    /// Tokens of `bytes`, whose first byte is on line `first_line`.
    pub(crate) fn new(bytes: &'a [u8], first_line: u64) -> Self {
        Tokens {
            bytes,
            position: 0,
            line: first_line,
        }
    }

    /// The line of the token last returned, or of the end of the buffer once it is exhausted.
    pub(crate) fn line(&self) -> u64 {
        self.line
    }

    /// Everything after the token last returned.
    pub(crate) fn remainder(&self) -> &'a [u8] {
        &self.bytes[self.position..]
    }
}

impl<'a> Iterator for Tokens<'a> {
    type Item = &'a [u8];

    fn next(&mut self) -> Option<&'a [u8]> {
        let bytes = self.bytes;
        while let Some(&byte) = bytes.get(self.position) {
            if !is_space(byte) {
                break;
            }
            let lone_carriage_return =
                byte == b'\r' && bytes.get(self.position + 1) != Some(&b'\n');
            if byte == b'\n' || lone_carriage_return {
                self.line += 1;
            }
            self.position += 1;
        }
        let start = self.position;
        while bytes.get(self.position).is_some_and(|&b| !is_space(b)) {
            self.position += 1;
        }
        (self.position > start).then(|| &bytes[start..self.position])
    }
}

/// A token as a `&str`, if it is UTF-8 (every number is).
fn as_str(token: &[u8]) -> Option<&str> {
    std::str::from_utf8(token).ok()
}

/// A floating-point token (any form `f64::from_str` accepts, NaN and infinities included).
pub(crate) fn parse_f64(token: &[u8]) -> Option<f64> {
    as_str(token)?.parse().ok()
}

/// A decimal integer token with an optional sign.
pub(crate) fn parse_i64(token: &[u8]) -> Option<i64> {
    as_str(token)?.parse().ok()
}

/// A token quoted for an error message: bytes other than printable ASCII escaped (`\xff`,
/// `\t`), so that a binary file's bytes never reach a terminal raw, and shortened when long so
/// a blob cannot flood the message.
pub(crate) fn quote(token: &[u8]) -> String {
    const MAX_SHOWN: usize = 40;
    let shown = &token[..token.len().min(MAX_SHOWN)];
    let ellipsis = if token.len() > MAX_SHOWN { "…" } else { "" };
    format!("`{}{ellipsis}`", shown.escape_ascii())
}

/// The 1-based line of the first NUL byte of `bytes`, if any: text files have none, and a file
/// that does (an image, a binary mesh, UTF-16 text) is not what a text reader can read.
pub(crate) fn first_nul_line(bytes: &[u8]) -> Option<u64> {
    let at = bytes.iter().position(|&b| b == 0)?;
    Some(1 + bytes[..at].iter().filter(|&&b| b == b'\n').count() as u64)
}

/// How many records of at least `min_record_bytes` bytes a buffer of `len` bytes can hold: caps
/// the capacity reserved for a count a file declares, so a lying header cannot exhaust memory.
pub(crate) fn capacity_for(declared: u64, len: usize, min_record_bytes: usize) -> usize {
    let possible = len / min_record_bytes.max(1);
    usize::try_from(declared)
        .unwrap_or(usize::MAX)
        .min(possible)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_numbered_and_lose_their_terminators() {
        let lines: Vec<_> = Lines::new(b"a\r\nb\n\nc").collect();
        assert_eq!(
            lines,
            vec![
                (1, &b"a"[..]),
                (2, &b"b"[..]),
                (3, &b""[..]),
                (4, &b"c"[..])
            ]
        );
    }

    #[test]
    fn every_line_convention_and_a_byte_order_mark_are_understood() {
        let lines: Vec<_> = Lines::new(b"\xEF\xBB\xBFa\rb\r\nc\n")
            .map(|(n, l)| (n, l.to_vec()))
            .collect();
        assert_eq!(
            lines,
            vec![(1, b"a".to_vec()), (2, b"b".to_vec()), (3, b"c".to_vec())]
        );
        let mut tokens = Tokens::new(b"a\rb\r\nc", 1);
        let lines: Vec<_> = std::iter::from_fn(|| tokens.next().map(|_| tokens.line())).collect();
        assert_eq!(lines, vec![1, 2, 3]);
    }

    #[test]
    fn tokens_track_their_line() {
        let mut tokens = Tokens::new(b" 1\t2\n\n  3 \r\n", 7);
        assert_eq!(tokens.next(), Some(&b"1"[..]));
        assert_eq!(tokens.line(), 7);
        assert_eq!(tokens.next(), Some(&b"2"[..]));
        assert_eq!(tokens.next(), Some(&b"3"[..]));
        assert_eq!(tokens.line(), 9);
        assert_eq!(tokens.next(), None);
    }

    #[test]
    fn nan_and_infinity_are_values() {
        assert!(parse_f64(b"nan").unwrap().is_nan());
        assert!(parse_f64(b"NaN").unwrap().is_nan());
        assert_eq!(parse_f64(b"-inf"), Some(f64::NEG_INFINITY));
        assert_eq!(parse_f64(b".5"), Some(0.5));
        assert_eq!(parse_f64(b"1e-3"), Some(0.001));
        assert_eq!(parse_f64(b"1.2.3"), None);
        assert_eq!(parse_i64(b"+12"), Some(12));
        assert_eq!(parse_i64(b"1.0"), None);
    }

    #[test]
    fn capacity_is_capped_by_the_buffer() {
        assert_eq!(capacity_for(u64::MAX, 100, 4), 25);
        assert_eq!(capacity_for(3, 100, 4), 3);
    }

    #[test]
    fn comments_are_stripped() {
        assert_eq!(strip_comment(b"1 2 # three"), b"1 2 ");
        assert!(is_blank(b" \t"));
    }
}
