//! An axis-aligned cube made of six quads.

use super::SurfaceError;
use super::polyline::checked_length;
use crate::soup::PolygonSoup;

/// A cube of edge length `side` centred at the origin: 8 vertices, 6 quads, CCW from outside.
///
/// Vertex `i` has coordinates `±side/2` with bit 0 of `i` choosing +x, bit 1 +y and bit 2 +z.
///
/// # Errors
/// `side` not finite or not positive.
pub fn cube(side: f64) -> Result<PolygonSoup, SurfaceError> {
    let half = checked_length("side", side)? / 2.0;
    let positions = (0..8u32)
        .map(|i| {
            let coordinate = |bit: u32| if i & (1 << bit) != 0 { half } else { -half };
            [coordinate(0), coordinate(1), coordinate(2)]
        })
        .collect();
    #[rustfmt::skip]
    let indices = vec![
        0, 2, 3, 1, // -z
        4, 5, 7, 6, // +z
        0, 1, 5, 4, // -y
        2, 6, 7, 3, // +y
        0, 4, 6, 2, // -x
        1, 3, 7, 5, // +x
    ];
    Ok(PolygonSoup {
        positions,
        face_sizes: vec![4; 6],
        indices,
        corner_normals: None,
        corner_uvs: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_sides() {
        assert_eq!(
            cube(0.0),
            Err(SurfaceError::NonPositive {
                what: "side",
                value: 0.0
            })
        );
        assert_eq!(
            cube(f64::NAN),
            Err(SurfaceError::NonFiniteParameter { what: "side" })
        );
        assert_eq!(cube(2.0).unwrap().positions[7], [1.0, 1.0, 1.0]);
    }
}
