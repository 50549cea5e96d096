//! Geodesic spheres: an icosahedron whose triangles are split in four `level` times, with the new
//! vertices pushed onto the sphere.

use std::collections::HashMap;

use glam::DVec3;

use super::SurfaceError;
use super::builder::{SoupBuilder, ensure_fits};
use super::polyline::checked_length;
use crate::soup::PolygonSoup;

/// Deepest subdivision accepted: level 10 already has 20·4¹⁰ ≈ 21 million triangles.
pub const MAX_ICOSPHERE_LEVEL: u32 = 10;

#[rustfmt::skip]
const ICOSAHEDRON_FACES: [[u32; 3]; 20] = [
    [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
    [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
    [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
    [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
];

/// A sphere of `radius` centred at the origin: `10·4^level + 2` vertices and `20·4^level`
/// triangles, CCW from outside. Level 0 is the regular icosahedron.
///
/// # Errors
/// `radius` not finite or not positive; `level` above [`MAX_ICOSPHERE_LEVEL`].
pub fn icosphere(radius: f64, level: u32) -> Result<PolygonSoup, SurfaceError> {
    let radius = checked_length("radius", radius)?;
    if level > MAX_ICOSPHERE_LEVEL {
        return Err(SurfaceError::TooManySteps {
            what: "level",
            max: MAX_ICOSPHERE_LEVEL,
            got: level,
        });
    }
    let split = 4usize.pow(level);
    ensure_fits(Some(10 * split + 2), Some(60 * split))?;

    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let corners = [
        (-1.0, phi, 0.0),
        (1.0, phi, 0.0),
        (-1.0, -phi, 0.0),
        (1.0, -phi, 0.0),
        (0.0, -1.0, phi),
        (0.0, 1.0, phi),
        (0.0, -1.0, -phi),
        (0.0, 1.0, -phi),
        (phi, 0.0, -1.0),
        (phi, 0.0, 1.0),
        (-phi, 0.0, -1.0),
        (-phi, 0.0, 1.0),
    ];
    let mut directions: Vec<DVec3> = corners
        .iter()
        .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
        .collect();
    directions.reserve(10 * split + 2 - 12);
    let mut triangles: Vec<[u32; 3]> = ICOSAHEDRON_FACES.to_vec();
    for _ in 0..level {
        let mut midpoints: HashMap<(u32, u32), u32> =
            HashMap::with_capacity(triangles.len() * 3 / 2);
        let mut midpoint = |a: u32, b: u32| -> u32 {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                directions.push((directions[a as usize] + directions[b as usize]).normalize());
                (directions.len() - 1) as u32
            })
        };
        triangles = triangles
            .iter()
            .flat_map(|&[a, b, c]| {
                let (ab, bc, ca) = (midpoint(a, b), midpoint(b, c), midpoint(c, a));
                [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
            })
            .collect();
    }

    let mut out =
        SoupBuilder::with_capacity(directions.len(), triangles.len(), triangles.len() * 3)?;
    for d in directions {
        out.vertex(d * radius);
    }
    for t in &triangles {
        out.face(t);
    }
    out.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_follow_the_subdivision_formula() {
        for level in 0..4 {
            let s = icosphere(2.0, level).unwrap();
            assert_eq!(s.positions.len(), 10 * 4usize.pow(level) + 2);
            assert_eq!(s.n_faces(), 20 * 4usize.pow(level));
            assert!(
                s.positions
                    .iter()
                    .all(|p| (DVec3::from_array(*p).length() - 2.0).abs() < 1e-12)
            );
        }
    }

    #[test]
    fn rejects_bad_parameters() {
        assert_eq!(
            icosphere(-1.0, 1),
            Err(SurfaceError::NonPositive {
                what: "radius",
                value: -1.0
            })
        );
        assert_eq!(
            icosphere(1.0, 11),
            Err(SurfaceError::TooManySteps {
                what: "level",
                max: 10,
                got: 11
            })
        );
    }
}
