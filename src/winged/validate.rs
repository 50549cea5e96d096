//! Input validation of an indexed face list.
//!
//! TEMPORARY: this is the winged kernel's private stand-in for the shared face-list analysis
//! that `crate::soup` will provide (one `Diagnostic` type and `BuildPolicy {Strict, Skip,
//! Repair}` for both kernels). When that lands, replace [`validate_face_list`] by a call to it;
//! the rest of the builder only needs the face offsets returned here.

use super::error::WingedError;
use crate::soup::{FaceList, FaceSizes};

/// Largest element count a `u32` id can name (`u32::MAX` is the invalid id).
pub(crate) const MAX_ELEMENTS: u64 = u32::MAX as u64 - 1;

/// Refuses `count` elements of kind `what` if they do not fit a `u32` id.
pub(crate) fn check_count(what: &'static str, count: usize) -> Result<u32, WingedError> {
    let count = count as u64;
    if count > MAX_ELEMENTS {
        return Err(WingedError::TooManyElements { what, count });
    }
    Ok(count as u32)
}

/// Checks a face list (strict policy) and returns the corner offset of every face plus the
/// total corner count (`offsets.len() == n_faces + 1`).
///
/// Checked: counts fit `u32` ids, sizes ≥ 3 and summing to the index count, indices in range,
/// no vertex twice in one face, finite positions. Edge-level problems (non-manifold or
/// inconsistently oriented edges) are found while pairing corners in the builder.
pub(crate) fn validate_face_list(list: &FaceList<'_>) -> Result<Vec<u32>, WingedError> {
    let n_vertices = check_count("vertices", list.positions.len())?;
    check_count("corners", list.indices.len())?;
    if let Some(vertex) = list
        .positions
        .iter()
        .position(|p| !p.iter().all(|c| c.is_finite()))
    {
        return Err(WingedError::NonFinitePosition {
            vertex: vertex as u32,
        });
    }

    let n_faces = face_count(list)?;
    check_count("faces", n_faces)?;
    let mut offsets = Vec::with_capacity(n_faces + 1);
    offsets.push(0u32);
    let mut total: u32 = 0;
    for f in 0..n_faces {
        // Cannot overflow: face_count checked that the sizes sum to the index count (< u32::MAX).
        total += match list.sizes {
            FaceSizes::Uniform(s) => s,
            FaceSizes::PerFace(sizes) => sizes[f],
        };
        offsets.push(total);
    }

    for f in 0..n_faces {
        let corners = &list.indices[offsets[f] as usize..offsets[f + 1] as usize];
        for (k, &v) in corners.iter().enumerate() {
            if v >= n_vertices {
                return Err(WingedError::IndexOutOfRange {
                    face: f as u32,
                    vertex: v,
                    n_vertices,
                });
            }
            // Real polygons are short: a scan of the earlier corners beats any set.
            if corners.len() <= SHORT_FACE && corners[..k].contains(&v) {
                return Err(WingedError::RepeatedVertex {
                    face: f as u32,
                    vertex: v,
                });
            }
        }
        if corners.len() > SHORT_FACE {
            let mut sorted = corners.to_vec();
            sorted.sort_unstable();
            if let Some(pair) = sorted.windows(2).find(|w| w[0] == w[1]) {
                return Err(WingedError::RepeatedVertex {
                    face: f as u32,
                    vertex: pair[0],
                });
            }
        }
    }
    Ok(offsets)
}

/// Faces up to this many corners are checked for repeats by scanning, longer ones by sorting.
const SHORT_FACE: usize = 32;

/// Number of faces, after checking every size is at least 3 and the sizes cover the indices.
fn face_count(list: &FaceList<'_>) -> Result<usize, WingedError> {
    let actual = list.indices.len() as u64;
    match list.sizes {
        FaceSizes::Uniform(_) if list.indices.is_empty() => Ok(0),
        FaceSizes::Uniform(size) if size < 3 => Err(WingedError::FaceTooSmall { face: 0, size }),
        FaceSizes::Uniform(size) => {
            let n_faces = list.indices.len() / size as usize;
            if n_faces as u64 * u64::from(size) != actual {
                return Err(WingedError::CornerCountMismatch {
                    expected: (n_faces as u64 + 1) * u64::from(size),
                    actual,
                });
            }
            Ok(n_faces)
        }
        FaceSizes::PerFace(sizes) => {
            if let Some(face) = sizes.iter().position(|&s| s < 3) {
                return Err(WingedError::FaceTooSmall {
                    face: face as u32,
                    size: sizes[face],
                });
            }
            // Saturating: a saturated sum differs from any real index count anyway.
            let expected = sizes
                .iter()
                .fold(0u64, |sum, &s| sum.saturating_add(u64::from(s)));
            if expected != actual {
                return Err(WingedError::CornerCountMismatch { expected, actual });
            }
            Ok(sizes.len())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: [[f64; 3]; 4] = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]];

    #[test]
    fn offsets_follow_the_sizes() {
        let list = FaceList::polygons(&P, &[3, 4], &[0, 1, 2, 0, 1, 3, 2]);
        assert_eq!(validate_face_list(&list).unwrap(), [0, 3, 7]);
        let triangles = FaceList::triangles(&P, &[0, 1, 2, 2, 1, 3]);
        assert_eq!(validate_face_list(&triangles).unwrap(), [0, 3, 6]);
        assert_eq!(
            validate_face_list(&FaceList::triangles(&P, &[])).unwrap(),
            [0]
        );
    }

    #[test]
    fn counts_beyond_u32_ids_are_refused() {
        assert!(check_count("faces", u32::MAX as usize - 1).is_ok());
        assert_eq!(
            check_count("faces", u32::MAX as usize),
            Err(WingedError::TooManyElements {
                what: "faces",
                count: u64::from(u32::MAX)
            })
        );
        let list = FaceList::polygons(&P, &[u32::MAX, u32::MAX, u32::MAX, 3], &[0, 1, 2]);
        assert!(matches!(
            validate_face_list(&list),
            Err(WingedError::CornerCountMismatch { actual: 3, .. })
        ));
    }

    #[test]
    fn uniform_sizes_below_three_are_refused() {
        let list = FaceList {
            positions: &P,
            sizes: FaceSizes::Uniform(2),
            indices: &[0, 1],
        };
        assert_eq!(
            validate_face_list(&list),
            Err(WingedError::FaceTooSmall { face: 0, size: 2 })
        );
        let list = FaceList {
            positions: &P,
            sizes: FaceSizes::Uniform(0),
            indices: &[0],
        };
        assert_eq!(
            validate_face_list(&list),
            Err(WingedError::FaceTooSmall { face: 0, size: 0 })
        );
    }
}
