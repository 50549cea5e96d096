//! Stanford PLY reader (ASCII, binary little and big endian).
//!
//! From the `vertex` element: `x y z` (any numeric type), `nx ny nz` when all three are present,
//! and texture coordinates named `u v`, `s t`, `texture_u texture_v` or `texture_s texture_t`;
//! from the `face` element: the `vertex_indices` (or `vertex_index`) list of any integer type.
//! Other elements and properties are skipped. Vertex normals and texture coordinates are spread
//! onto the corners. A file without a `face` element reads as a soup without faces. Errors give the
//! line for ASCII bodies and the element and record index for binary ones.
//!
//! Why not `ply-rs-bw` for reading: its model builds one owned value per element record (a `Vec`
//! per face) and returns them all before we can copy them into the soup, doubling peak memory and
//! allocating per face; its ASCII number grammar rejects `nan`/`inf`, `.5` and `1.`, so the NaN
//! policy could not be applied; and its errors are free text, not a line or record index. The
//! format is small and fully described by its header, so halfwing reads it directly.

use std::io::Read;

use crate::soup::PolygonSoup;
use crate::support::allocation::try_vec_with_capacity;

use super::attributes::spread_to_corners;
use super::error::{IoError, Location};
use super::format::MeshFormat;
use super::ply_header::{
    Element, PlyEncoding, PropertyType, Scalar, parse_header, record_location,
};
use super::text::{Tokens, capacity_for, parse_f64, parse_i64, quote};

/// Reads a PLY file from any reader (the whole input is read first).
pub fn read_ply(mut reader: impl Read) -> Result<PolygonSoup, IoError> {
    let mut bytes = Vec::new();
    reader.read_to_end(&mut bytes)?;
    read_ply_bytes(&bytes)
}

/// Reads a PLY file held in memory.
pub fn read_ply_bytes(bytes: &[u8]) -> Result<PolygonSoup, IoError> {
    let header = parse_header(bytes)?;
    let body = &bytes[header.body_offset..];
    match header.encoding {
        PlyEncoding::Ascii => read_body(
            &header.elements,
            AsciiValues {
                tokens: Tokens::new(body, header.body_line),
            },
        ),
        PlyEncoding::BinaryLittleEndian => read_body(
            &header.elements,
            BinaryValues::<false> {
                bytes: body,
                position: 0,
            },
        ),
        PlyEncoding::BinaryBigEndian => read_body(
            &header.elements,
            BinaryValues::<true> {
                bytes: body,
                position: 0,
            },
        ),
    }
}

/// A source of body values, ASCII or binary. Errors are messages; the caller adds the location.
trait Values {
    /// Smallest number of bytes one value of any type takes, for capacity estimates.
    const MIN_VALUE_BYTES: usize;
    fn float(&mut self, ty: Scalar) -> Result<f64, String>;
    fn integer(&mut self, ty: Scalar) -> Result<i64, String>;
    /// Skips `count` values of a type.
    fn skip(&mut self, ty: Scalar, count: u64) -> Result<(), String>;
    fn remaining_bytes(&self) -> usize;
    fn location(&self, element: &Element, record: u64) -> Location;
}

struct AsciiValues<'a> {
    tokens: Tokens<'a>,
}

impl AsciiValues<'_> {
    fn token(&mut self) -> Result<&[u8], String> {
        self.tokens
            .next()
            .ok_or_else(|| "unexpected end of file".to_owned())
    }
}

impl Values for AsciiValues<'_> {
    const MIN_VALUE_BYTES: usize = 2;

    fn float(&mut self, _ty: Scalar) -> Result<f64, String> {
        let token = self.token()?;
        parse_f64(token).ok_or_else(|| format!("{} is not a number", quote(token)))
    }

    fn integer(&mut self, _ty: Scalar) -> Result<i64, String> {
        let token = self.token()?;
        parse_i64(token).ok_or_else(|| format!("{} is not an integer", quote(token)))
    }

    fn skip(&mut self, _ty: Scalar, count: u64) -> Result<(), String> {
        for _ in 0..count {
            self.token()?;
        }
        Ok(())
    }

    fn remaining_bytes(&self) -> usize {
        self.tokens.remainder().len()
    }

    fn location(&self, _element: &Element, _record: u64) -> Location {
        Location::Line(self.tokens.line())
    }
}

/// Binary values; `BIG_ENDIAN` picks the byte order at compile time.
struct BinaryValues<'a, const BIG_ENDIAN: bool> {
    bytes: &'a [u8],
    position: usize,
}

impl<const BIG_ENDIAN: bool> BinaryValues<'_, BIG_ENDIAN> {
    fn take<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let end = self.position + N;
        let slice = self
            .bytes
            .get(self.position..end)
            .ok_or_else(|| "unexpected end of file".to_owned())?;
        self.position = end;
        let mut array = [0; N];
        array.copy_from_slice(slice);
        if !BIG_ENDIAN {
            return Ok(array);
        }
        array.reverse();
        Ok(array)
    }

    /// The next value, widened to `f64` (exact for every PLY type) or `i64`.
    fn value(&mut self, ty: Scalar) -> Result<Number, String> {
        // Bytes are brought to little-endian order by `take`.
        Ok(match ty {
            Scalar::I8 => Number::Int(i64::from(i8::from_le_bytes(self.take()?))),
            Scalar::U8 => Number::Int(i64::from(u8::from_le_bytes(self.take()?))),
            Scalar::I16 => Number::Int(i64::from(i16::from_le_bytes(self.take()?))),
            Scalar::U16 => Number::Int(i64::from(u16::from_le_bytes(self.take()?))),
            Scalar::I32 => Number::Int(i64::from(i32::from_le_bytes(self.take()?))),
            Scalar::U32 => Number::Int(i64::from(u32::from_le_bytes(self.take()?))),
            Scalar::F32 => Number::Float(f64::from(f32::from_le_bytes(self.take()?))),
            Scalar::F64 => Number::Float(f64::from_le_bytes(self.take()?)),
        })
    }
}

enum Number {
    Int(i64),
    Float(f64),
}

impl<const BIG_ENDIAN: bool> Values for BinaryValues<'_, BIG_ENDIAN> {
    const MIN_VALUE_BYTES: usize = 1;

    fn float(&mut self, ty: Scalar) -> Result<f64, String> {
        Ok(match self.value(ty)? {
            Number::Int(value) => value as f64,
            Number::Float(value) => value,
        })
    }

    fn integer(&mut self, ty: Scalar) -> Result<i64, String> {
        match self.value(ty)? {
            Number::Int(value) => Ok(value),
            Number::Float(_) => Err("an index must have an integer type".to_owned()),
        }
    }

    fn skip(&mut self, ty: Scalar, count: u64) -> Result<(), String> {
        let len = usize::try_from(count)
            .ok()
            .and_then(|n| n.checked_mul(ty.size()));
        match len.filter(|&len| len <= self.remaining_bytes()) {
            Some(len) => {
                self.position += len;
                Ok(())
            }
            None => Err(format!(
                "a list of {count} values runs past the end of the file"
            )),
        }
    }

    fn remaining_bytes(&self) -> usize {
        self.bytes.len() - self.position
    }

    fn location(&self, element: &Element, record: u64) -> Location {
        record_location(element, record)
    }
}

/// What a property of a record feeds.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Role {
    Skip,
    Position(usize),
    Normal(usize),
    TexCoord(usize),
    FaceIndices,
}

/// Texture coordinate property names, in order of preference.
const TEXCOORD_NAMES: [[&str; 2]; 4] = [
    ["u", "v"],
    ["s", "t"],
    ["texture_u", "texture_v"],
    ["texture_s", "texture_t"],
];

/// The role of every property of the `vertex` element; errors when a coordinate is missing.
fn vertex_roles(element: &Element) -> Result<(Vec<Role>, bool, bool), IoError> {
    let find = |name: &str| {
        element
            .properties
            .iter()
            .position(|p| p.name == name && matches!(p.kind, PropertyType::Scalar(_)))
    };
    let mut roles = vec![Role::Skip; element.properties.len()];
    for (axis, name) in ["x", "y", "z"].into_iter().enumerate() {
        let at = find(name).ok_or_else(|| IoError::Parse {
            format: MeshFormat::Ply,
            location: Location::Header,
            message: format!("the vertex element has no scalar `{name}` property"),
        })?;
        roles[at] = Role::Position(axis);
    }
    let normal = ["nx", "ny", "nz"].map(find);
    let has_normals = normal.iter().all(Option::is_some);
    if has_normals {
        for (axis, at) in normal.into_iter().flatten().enumerate() {
            roles[at] = Role::Normal(axis);
        }
    }
    let texcoord = TEXCOORD_NAMES
        .iter()
        .map(|names| names.map(find))
        .find(|at| at.iter().all(Option::is_some));
    if let Some(at) = texcoord {
        for (axis, at) in at.into_iter().flatten().enumerate() {
            roles[at] = Role::TexCoord(axis);
        }
    }
    Ok((roles, has_normals, texcoord.is_some()))
}

/// The role of every property of the `face` element.
fn face_roles(element: &Element) -> Result<Vec<Role>, IoError> {
    let at = element
        .properties
        .iter()
        .position(|p| p.name == "vertex_indices" || p.name == "vertex_index")
        .ok_or_else(|| header_problem("the face element has no `vertex_indices` property"))?;
    match element.properties[at].kind {
        PropertyType::List { item, .. } if item.is_integer() => {}
        _ => {
            return Err(header_problem(
                "`vertex_indices` must be a list of integers",
            ));
        }
    }
    let mut roles = vec![Role::Skip; element.properties.len()];
    roles[at] = Role::FaceIndices;
    Ok(roles)
}

fn header_problem(message: &str) -> IoError {
    IoError::Parse {
        format: MeshFormat::Ply,
        location: Location::Header,
        message: message.to_owned(),
    }
}

/// Reads every element of the body, keeping what the soup needs.
fn read_body<V: Values>(elements: &[Element], mut values: V) -> Result<PolygonSoup, IoError> {
    let vertex_element = elements.iter().position(|e| e.name == "vertex");
    let face_element = elements.iter().position(|e| e.name == "face");
    let vertex_count = vertex_element.map_or(0, |i| elements[i].count);
    if vertex_count > u64::from(u32::MAX) {
        return Err(header_problem("more vertices than 32-bit indices can name"));
    }
    let (vertex_roles, has_normals, has_texcoords) = match vertex_element {
        Some(i) => vertex_roles(&elements[i])?,
        None => (Vec::new(), false, false),
    };
    let face_roles = face_element.map(|i| face_roles(&elements[i])).transpose()?;

    // Capacities come from declared counts, capped by what the remaining bytes can hold.
    let remaining = values.remaining_bytes();
    let vertex_record_bytes = vertex_roles.len() * V::MIN_VALUE_BYTES;
    let vertex_capacity = capacity_for(vertex_count, remaining, vertex_record_bytes);
    let face_count = face_element.map_or(0, |i| elements[i].count);
    let face_capacity = capacity_for(face_count, remaining, 4 * V::MIN_VALUE_BYTES);
    let mut soup = PolygonSoup {
        positions: try_vec_with_capacity(vertex_capacity, "vertices")?,
        face_sizes: try_vec_with_capacity(face_capacity, "faces")?,
        indices: try_vec_with_capacity(face_capacity.saturating_mul(3), "corners")?,
        ..Default::default()
    };
    let mut normals = try_vec_with_capacity(
        if has_normals { vertex_capacity } else { 0 },
        "vertex normals",
    )?;
    let mut texcoords = try_vec_with_capacity(
        if has_texcoords { vertex_capacity } else { 0 },
        "vertex texture coordinates",
    )?;

    for (element_index, element) in elements.iter().enumerate() {
        let is_vertex = Some(element_index) == vertex_element;
        let roles: &[Role] = if is_vertex {
            &vertex_roles
        } else if Some(element_index) == face_element {
            face_roles.as_deref().unwrap_or_default()
        } else {
            &[]
        };
        if element.properties.is_empty() {
            // Records without properties occupy no bytes: nothing to read, however many there are
            // (looping over a declared 2^63 of them would hang).
            continue;
        }
        for record in 0..element.count {
            let mut position = [0.0; 3];
            let mut normal = [0.0; 3];
            let mut texcoord = [0.0; 2];
            for (property_index, property) in element.properties.iter().enumerate() {
                let role = roles.get(property_index).copied().unwrap_or(Role::Skip);
                let result = match (property.kind, role) {
                    (PropertyType::Scalar(ty), Role::Position(axis)) => {
                        values.float(ty).map(|v| position[axis] = v)
                    }
                    (PropertyType::Scalar(ty), Role::Normal(axis)) => {
                        values.float(ty).map(|v| normal[axis] = v)
                    }
                    (PropertyType::Scalar(ty), Role::TexCoord(axis)) => {
                        values.float(ty).map(|v| texcoord[axis] = v)
                    }
                    (PropertyType::Scalar(ty), _) => values.skip(ty, 1),
                    (PropertyType::List { length, item }, Role::FaceIndices) => {
                        face(&mut values, length, item, vertex_count, &mut soup)
                    }
                    (PropertyType::List { length, item }, _) => values
                        .integer(length)
                        .and_then(|n| values.skip(item, list_length(n)?)),
                };
                result.map_err(|message| IoError::Parse {
                    format: MeshFormat::Ply,
                    location: values.location(element, record),
                    message: format!("property `{}`: {message}", property.name),
                })?;
            }
            if is_vertex {
                soup.positions.push(position);
                if has_normals {
                    normals.push(normal);
                }
                if has_texcoords {
                    texcoords.push(texcoord);
                }
            }
        }
    }
    if has_normals {
        soup.corner_normals = Some(spread_to_corners(&normals, &soup.indices));
    }
    if has_texcoords {
        soup.corner_uvs = Some(spread_to_corners(&texcoords, &soup.indices));
    }
    Ok(soup)
}

/// A list length read from the file, refused when negative.
fn list_length(length: i64) -> Result<u64, String> {
    u64::try_from(length).map_err(|_| format!("list length {length} is negative"))
}

/// One face: its size, then its vertex indices, each checked against the declared vertex count.
fn face(
    values: &mut impl Values,
    length: Scalar,
    item: Scalar,
    vertex_count: u64,
    soup: &mut PolygonSoup,
) -> Result<(), String> {
    let size = list_length(values.integer(length)?)?;
    let size =
        u32::try_from(size).map_err(|_| format!("a face of {size} vertices is too large"))?;
    for corner in 0..size {
        let index = values.integer(item)?;
        if !(0..vertex_count as i64).contains(&index) {
            return Err(format!(
                "corner {corner} index {index} is out of range: the file declares {vertex_count} vertices"
            ));
        }
        soup.indices.push(index as u32);
    }
    soup.face_sizes.push(size);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const ASCII_HEADER: &str = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
property float z\nproperty uchar red\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

    #[test]
    fn ascii_bodies_are_token_streams() {
        let text = format!("{ASCII_HEADER}0 0 0 255\n1 0 0 0\n0 1 nan\n 7\n3 0 1\n2\n");
        let soup = read_ply_bytes(text.as_bytes()).unwrap();
        assert_eq!(soup.positions.len(), 3);
        assert!(soup.positions[2][2].is_nan());
        assert_eq!(soup.face_sizes, vec![3]);
        assert_eq!(soup.indices, vec![0, 1, 2]);
    }

    #[test]
    fn ascii_errors_name_their_line() {
        let cases = [
            (
                format!("{ASCII_HEADER}0 0 0 255\n1 0 x 0\n"),
                12,
                "`z`: `x` is not a number",
            ),
            (
                format!("{ASCII_HEADER}0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 3\n"),
                14,
                "index 3 is out of range",
            ),
            (
                format!("{ASCII_HEADER}0 0 0 0\n1 0 0 0\n"),
                13,
                "unexpected end of file",
            ),
        ];
        for (text, line, message) in cases {
            let error = read_ply_bytes(text.as_bytes()).unwrap_err();
            assert_eq!(error.line(), Some(line), "{error}");
            assert!(error.to_string().contains(message), "{error}");
        }
    }

    /// A big-endian file with a `short` length and `ushort` indices, normals and `s t`.
    fn big_endian_file(face_count: u32, index: u16) -> Vec<u8> {
        let mut bytes = format!(
            "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n\
property double z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n\
element face {face_count}\nproperty list short ushort vertex_indices\nproperty uchar flags\nend_header\n"
        )
        .into_bytes();
        for vertex in 0..3u8 {
            for coordinate in [f64::from(vertex), 0.5, -2.0] {
                bytes.extend_from_slice(&coordinate.to_be_bytes());
            }
            for value in [0.0f32, 0.0, 1.0, f32::from(vertex), 0.25] {
                bytes.extend_from_slice(&value.to_be_bytes());
            }
        }
        bytes.extend_from_slice(&3i16.to_be_bytes());
        for i in [2, 1, index] {
            bytes.extend_from_slice(&i.to_be_bytes());
        }
        bytes.push(9);
        bytes
    }

    #[test]
    fn big_endian_bodies_are_read() {
        let soup = read_ply_bytes(&big_endian_file(1, 0)).unwrap();
        assert_eq!(
            soup.positions,
            vec![[0.0, 0.5, -2.0], [1.0, 0.5, -2.0], [2.0, 0.5, -2.0]]
        );
        assert_eq!(soup.indices, vec![2, 1, 0]);
        assert_eq!(soup.corner_normals, Some(vec![[0.0, 0.0, 1.0]; 3]));
        assert_eq!(
            soup.corner_uvs,
            Some(vec![[2.0, 0.25], [1.0, 0.25], [0.0, 0.25]])
        );
    }

    #[test]
    fn binary_errors_name_their_record() {
        let expect = |bytes: &[u8], index: u64, message: &str| {
            let error = read_ply_bytes(bytes).unwrap_err();
            assert!(
                matches!(&error, IoError::Parse { location: Location::Record { element, index: i }, .. }
                    if element == "face" && *i == index),
                "{error}"
            );
            assert!(error.to_string().contains(message), "{error}");
        };
        expect(&big_endian_file(1, 3), 0, "index 3 is out of range");
        expect(&big_endian_file(2, 0), 1, "unexpected end of file");
        let mut truncated = big_endian_file(1, 0);
        truncated.truncate(truncated.len() - 2);
        expect(&truncated, 0, "unexpected end of file");
    }

    #[test]
    fn missing_coordinates_and_float_indices_are_refused() {
        let no_z = "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nend_header\n";
        assert!(
            read_ply_bytes(no_z.as_bytes())
                .unwrap_err()
                .to_string()
                .contains("`z`")
        );
        let float_list = ASCII_HEADER.replace("uchar int", "uchar float");
        assert!(
            read_ply_bytes(float_list.as_bytes())
                .unwrap_err()
                .to_string()
                .contains("list of integers")
        );
    }
}
