//! Moving attributes between vertices and corners, and the consistency check writers run first.
//!
//! [`PolygonSoup`] keeps normals and texture coordinates per corner (aligned with `indices`), which
//! is what OBJ stores. OFF and PLY store them per vertex: readers spread them onto the corners, and
//! writers fold them back when every corner of a vertex agrees bit for bit.

use crate::soup::PolygonSoup;

use super::error::IoError;

/// Per-corner values from per-vertex ones. Every index must be below `per_vertex.len()` (the
/// readers have checked it).
pub(crate) fn spread_to_corners<T: Copy>(per_vertex: &[T], indices: &[u32]) -> Vec<T> {
    indices
        .iter()
        .map(|&vertex| per_vertex[vertex as usize])
        .collect()
}

/// Per-vertex values from per-corner ones, or `None` when two corners of one vertex disagree (the
/// soup then needs a per-corner format such as OBJ). Unreferenced vertices get `fill`.
pub(crate) fn fold_to_vertices<T: Copy + PartialEq, const N: usize>(
    per_corner: &[[T; N]],
    indices: &[u32],
    vertex_count: usize,
    fill: [T; N],
    same: impl Fn(&[T; N], &[T; N]) -> bool,
) -> Option<Vec<[T; N]>> {
    let mut per_vertex = vec![fill; vertex_count];
    let mut seen = vec![false; vertex_count];
    for (&vertex, value) in indices.iter().zip(per_corner) {
        let vertex = vertex as usize;
        if seen[vertex] {
            if !same(&per_vertex[vertex], value) {
                return None;
            }
        } else {
            seen[vertex] = true;
            per_vertex[vertex] = *value;
        }
    }
    Some(per_vertex)
}

/// Bitwise equality of float arrays, so NaN equals the same NaN and `0.0` differs from `-0.0`:
/// folding must not change a single bit.
pub(crate) fn same_bits<const N: usize>(a: &[f64; N], b: &[f64; N]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// Checks what every writer relies on: face sizes add up to the index count, every index names a
/// position, and attribute arrays have one entry per corner.
pub(crate) fn check_soup(soup: &PolygonSoup) -> Result<(), IoError> {
    let corners = soup
        .face_sizes
        .iter()
        .try_fold(0u64, |sum, &size| sum.checked_add(u64::from(size)));
    if corners != Some(soup.indices.len() as u64) {
        return Err(IoError::InvalidSoup(format!(
            "face sizes add up to {} corners but there are {} indices",
            corners.map_or_else(|| "more than 2^64".to_owned(), |c| c.to_string()),
            soup.indices.len()
        )));
    }
    if let Some((corner, &vertex)) = soup
        .indices
        .iter()
        .enumerate()
        .find(|&(_, &v)| v as usize >= soup.positions.len())
    {
        return Err(IoError::InvalidSoup(format!(
            "corner {corner} refers to vertex {vertex} but there are {} positions",
            soup.positions.len()
        )));
    }
    let check_len = |name: &str, len: Option<usize>| match len {
        Some(len) if len != soup.indices.len() => Err(IoError::InvalidSoup(format!(
            "{len} corner {name} for {} corners",
            soup.indices.len()
        ))),
        _ => Ok(()),
    };
    check_len("normals", soup.corner_normals.as_ref().map(Vec::len))?;
    check_len(
        "texture coordinates",
        soup.corner_uvs.as_ref().map(Vec::len),
    )
}

/// The per-vertex normals and texture coordinates of a soup whose corners agree per vertex; an
/// attribute whose corners disagree is `None` (and left out by per-vertex formats).
pub(crate) struct VertexAttributes {
    pub(crate) normals: Option<Vec<[f64; 3]>>,
    pub(crate) uvs: Option<Vec<[f64; 2]>>,
}

impl VertexAttributes {
    pub(crate) fn of(soup: &PolygonSoup) -> Self {
        let n = soup.positions.len();
        VertexAttributes {
            normals: soup
                .corner_normals
                .as_deref()
                .and_then(|corner| fold_to_vertices(corner, &soup.indices, n, [0.0; 3], same_bits)),
            uvs: soup
                .corner_uvs
                .as_deref()
                .and_then(|corner| fold_to_vertices(corner, &soup.indices, n, [0.0; 2], same_bits)),
        }
    }

    /// Fills `row` with the values of one vertex record, in the order per-vertex formats write
    /// them: position, then normal, then texture coordinates (those present).
    pub(crate) fn vertex_row(&self, soup: &PolygonSoup, vertex: usize, row: &mut Vec<f64>) {
        row.clear();
        row.extend_from_slice(&soup.positions[vertex]);
        if let Some(normals) = &self.normals {
            row.extend_from_slice(&normals[vertex]);
        }
        if let Some(uvs) = &self.uvs {
            row.extend_from_slice(&uvs[vertex]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folding_undoes_spreading() {
        let per_vertex = vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]];
        let indices = [0, 1, 2, 2, 1, 0];
        let corners = spread_to_corners(&per_vertex, &indices);
        assert_eq!(
            fold_to_vertices(&corners, &indices, 3, [0.0; 2], same_bits),
            Some(per_vertex)
        );
    }

    #[test]
    fn disagreeing_corners_do_not_fold() {
        let corners = [[1.0], [2.0]];
        assert_eq!(
            fold_to_vertices(&corners, &[0, 0], 1, [0.0], same_bits),
            None
        );
        assert_eq!(
            fold_to_vertices(&[[0.0], [-0.0]], &[0, 0], 1, [0.0], same_bits),
            None
        );
    }

    #[test]
    fn inconsistent_soups_are_refused() {
        let mut soup = PolygonSoup {
            positions: vec![[0.0; 3]; 3],
            face_sizes: vec![3],
            indices: vec![0, 1, 2],
            ..Default::default()
        };
        assert!(check_soup(&soup).is_ok());
        soup.indices[2] = 3;
        assert!(
            matches!(check_soup(&soup), Err(IoError::InvalidSoup(m)) if m.contains("vertex 3"))
        );
        soup.indices[2] = 2;
        soup.face_sizes = vec![u32::MAX; 3];
        assert!(check_soup(&soup).is_err());
        soup.face_sizes = vec![3];
        soup.corner_uvs = Some(vec![[0.0; 2]]);
        assert!(check_soup(&soup).is_err());
    }
}
