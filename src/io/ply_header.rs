//! The PLY header: encoding, elements and their properties.

use super::error::{IoError, Location};
use super::format::MeshFormat;
use super::text::{Lines, Tokens, parse_i64, quote};

/// How the body of a PLY file is encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlyEncoding {
    /// Whitespace-separated decimal text.
    Ascii,
    /// Binary, least significant byte first.
    BinaryLittleEndian,
    /// Binary, most significant byte first.
    BinaryBigEndian,
}

/// A PLY scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn from_name(name: &[u8]) -> Option<Self> {
        Some(match name {
            b"char" | b"int8" => Scalar::I8,
            b"uchar" | b"uint8" => Scalar::U8,
            b"short" | b"int16" => Scalar::I16,
            b"ushort" | b"uint16" => Scalar::U16,
            b"int" | b"int32" => Scalar::I32,
            b"uint" | b"uint32" => Scalar::U32,
            b"float" | b"float32" => Scalar::F32,
            b"double" | b"float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Bytes per value in a binary body.
    pub(crate) fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    pub(crate) fn is_integer(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }
}

/// A property's type: one value, or a list with its length's type and its items' type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PropertyType {
    Scalar(Scalar),
    List { length: Scalar, item: Scalar },
}

/// One declared property.
#[derive(Clone, Debug)]
pub(crate) struct Property {
    pub(crate) name: String,
    pub(crate) kind: PropertyType,
}

/// One declared element: its name, record count and properties in file order.
#[derive(Clone, Debug)]
pub(crate) struct Element {
    pub(crate) name: String,
    pub(crate) count: u64,
    pub(crate) properties: Vec<Property>,
}

/// A parsed header and where the body starts.
#[derive(Debug)]
pub(crate) struct Header {
    pub(crate) encoding: PlyEncoding,
    pub(crate) elements: Vec<Element>,
    /// Byte offset of the body's first byte.
    pub(crate) body_offset: usize,
    /// Line number of the body's first line (for ASCII bodies).
    pub(crate) body_line: u64,
}

pub(crate) fn header_error(line: u64, message: impl Into<String>) -> IoError {
    IoError::at_line(MeshFormat::Ply, line, message)
}

/// Parses the header at the start of `bytes`.
pub(crate) fn parse_header(bytes: &[u8]) -> Result<Header, IoError> {
    let mut lines = Lines::new(bytes);
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    match lines.next() {
        Some((_, line)) if line.trim_ascii_end() == b"ply" => {}
        _ => return Err(header_error(1, "the file does not start with `ply`")),
    }
    loop {
        let Some((number, line)) = lines.next() else {
            return Err(header_error(
                lines_after(bytes),
                "the header has no `end_header` line",
            ));
        };
        let mut tokens = Tokens::new(line, number);
        match tokens.next() {
            Some(b"format") => {
                let name = tokens.next().unwrap_or_default();
                encoding = Some(match name {
                    b"ascii" => PlyEncoding::Ascii,
                    b"binary_little_endian" => PlyEncoding::BinaryLittleEndian,
                    b"binary_big_endian" => PlyEncoding::BinaryBigEndian,
                    _ => {
                        return Err(header_error(
                            number,
                            format!("unknown format {}", quote(name)),
                        ));
                    }
                });
                let version = tokens.next().unwrap_or_default();
                if !version.starts_with(b"1.") && version != b"1" {
                    return Err(IoError::Unsupported(format!(
                        "PLY version {}",
                        quote(version)
                    )));
                }
            }
            Some(b"element") => {
                let name = tokens
                    .next()
                    .ok_or_else(|| header_error(number, "element without a name"))?;
                let count_token = tokens.next().unwrap_or_default();
                let count = parse_i64(count_token)
                    .and_then(|n| u64::try_from(n).ok())
                    .ok_or_else(|| {
                        header_error(
                            number,
                            format!(
                                "element count {} is not a non-negative integer",
                                quote(count_token)
                            ),
                        )
                    })?;
                elements.push(Element {
                    name: String::from_utf8_lossy(name).into_owned(),
                    count,
                    properties: Vec::new(),
                });
            }
            Some(b"property") => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| header_error(number, "property declared before any element"))?;
                let scalar = |token: Option<&[u8]>| {
                    let token = token.unwrap_or_default();
                    Scalar::from_name(token).ok_or_else(|| {
                        header_error(number, format!("unknown property type {}", quote(token)))
                    })
                };
                let first = tokens.next();
                let kind = if first == Some(b"list") {
                    let length = scalar(tokens.next())?;
                    let item = scalar(tokens.next())?;
                    if !length.is_integer() {
                        return Err(header_error(
                            number,
                            "a list length must have an integer type",
                        ));
                    }
                    PropertyType::List { length, item }
                } else {
                    PropertyType::Scalar(scalar(first)?)
                };
                let name = tokens
                    .next()
                    .ok_or_else(|| header_error(number, "property without a name"))?;
                element.properties.push(Property {
                    name: String::from_utf8_lossy(name).into_owned(),
                    kind,
                });
            }
            Some(b"end_header") => {
                let encoding = encoding
                    .ok_or_else(|| header_error(number, "the header has no `format` line"))?;
                return Ok(Header {
                    encoding,
                    elements,
                    body_offset: lines.offset(),
                    body_line: number + 1,
                });
            }
            Some(b"comment" | b"obj_info") | None => {}
            Some(other) => {
                return Err(header_error(
                    number,
                    format!("unknown header keyword {}", quote(other)),
                ));
            }
        }
    }
}

/// The number of the line after the last one of a buffer.
fn lines_after(bytes: &[u8]) -> u64 {
    Lines::new(bytes).count() as u64 + 1
}

/// The location of a record of an element, as errors report it.
pub(crate) fn record_location(element: &Element, index: u64) -> Location {
    Location::Record {
        element: element.name.clone(),
        index,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_is_read_with_its_body_offset() {
        let text = b"ply\r\nformat binary_big_endian 1.0\r\ncomment hi\r\nelement vertex 2\r\n\
property float x\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\nBODY";
        let header = parse_header(text).unwrap();
        assert_eq!(header.encoding, PlyEncoding::BinaryBigEndian);
        assert_eq!(&text[header.body_offset..], b"BODY");
        assert_eq!(header.body_line, 9);
        assert_eq!(
            header.elements[1].properties[0].kind,
            PropertyType::List {
                length: Scalar::U8,
                item: Scalar::I32
            }
        );
    }

    #[test]
    fn header_errors_name_their_line() {
        let cases: [(&[u8], u64, &str); 5] = [
            (b"plx\n", 1, "does not start"),
            (
                b"ply\nformat ascii 1.0\nelement vertex -1\n",
                3,
                "not a non-negative",
            ),
            (
                b"ply\nformat ascii 1.0\nproperty float x\n",
                3,
                "before any element",
            ),
            (
                b"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n",
                4,
                "unknown property type",
            ),
            (b"ply\nformat ascii 1.0\n", 3, "no `end_header`"),
        ];
        for (text, line, message) in cases {
            let error = parse_header(text).unwrap_err();
            assert_eq!(error.line(), Some(line), "{error}");
            assert!(error.to_string().contains(message), "{error}");
        }
    }
}
