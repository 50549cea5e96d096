//! Projecting a polygon onto the coordinate plane most nearly parallel to it (the one across
//! the largest component of its Newell normal), so that it runs counter-clockwise in 2D whenever
//! it is simple. The projection only drops a coordinate (and swaps the other two to keep the
//! winding), so it rounds nothing: corners on a line stay on it, corners at one place stay
//! there, and the exact predicates decide about the input's own numbers.

use robust::Coord;

use crate::geom::newell_vector;

/// Sets `projected` to the projection of `corners` (finite) described in the module docs.
/// `false` when the polygon has no area to speak of against its size (its Newell normal
/// vanishes, or the numbers overflow): there is no plane to project on.
pub(super) fn project_on_dominant_plane(
    corners: &[[f64; 3]],
    projected: &mut Vec<Coord<f64>>,
) -> bool {
    let normal = newell_vector(corners.iter().copied());
    let length = (normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]).sqrt();
    let perimeter: f64 = (0..corners.len())
        .map(|i| distance(corners[i], corners[(i + 1) % corners.len()]))
        .sum();
    // Twice the area against the perimeter squared: a scale-free flatness test.
    let flatness = corners.len() as f64 * f64::EPSILON * perimeter * perimeter;
    // Huge coordinates can overflow the normal to infinity or NaN: treated as no plane too.
    if !length.is_finite() || length <= flatness {
        return false;
    }
    let across = (0..3)
        .max_by(|&a, &b| normal[a].abs().total_cmp(&normal[b].abs()))
        .expect("three axes");
    // (u, v, across) is a right-handed cycle of the axes, so looking down `across` the polygon
    // runs counter-clockwise in (u, v) when that normal component is positive; otherwise swap.
    let (mut u, mut v) = ((across + 1) % 3, (across + 2) % 3);
    if normal[across] < 0.0 {
        std::mem::swap(&mut u, &mut v);
    }
    projected.clear();
    // Adding 0.0 turns -0.0 into 0.0: the predicates compare coordinates as numbers.
    projected.extend(corners.iter().map(|c| Coord {
        x: c[u] + 0.0,
        y: c[v] + 0.0,
    }));
    true
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_plane_and_both_windings_come_out_counter_clockwise() {
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
        for across in 0..3 {
            for reversed in [false, true] {
                let mut corners: Vec<[f64; 3]> = square
                    .iter()
                    .map(|p| {
                        let mut c = [7.0; 3];
                        c[(across + 1) % 3] = p[0];
                        c[(across + 2) % 3] = p[1] + 0.1 * p[0]; // tilted a little
                        c
                    })
                    .collect();
                if reversed {
                    corners.reverse();
                }
                let mut projected = Vec::new();
                assert!(project_on_dominant_plane(&corners, &mut projected));
                let twice_area: f64 = (0..4)
                    .map(|i| {
                        let (a, b) = (projected[i], projected[(i + 1) % 4]);
                        a.x * b.y - a.y * b.x
                    })
                    .sum();
                assert!(twice_area > 0.0, "{across} {reversed}: {twice_area}");
            }
        }
        let line = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0], [3.0; 3]];
        assert!(!project_on_dominant_plane(&line, &mut Vec::new()));
    }
}
