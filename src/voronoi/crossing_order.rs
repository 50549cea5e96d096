//! Exact order of the points where Voronoi edges cross one edge of a clip region.
//!
//! The bisector of sites `p` and `q` meets the line `a + t·(b − a)` at
//! `t = (|a − q|² − |a − p|²) / (2 (b − a)·(q − p))`. Two such parameters are compared without
//! rounding, in integers of any size: their floating-point values can agree (or both round to a
//! corner) for crossings that lie apart by far less than an ulp, where the region is narrow beside
//! its distance from the origin.

use std::cmp::Ordering;

use super::exact_distance::Metric;
use crate::geom::exact_orientation::{integer_list, integers};
use crate::geom::wide_integer::WideInteger;

/// How the crossings of the bisectors of `first` and of `second` (pairs of sites) lie along the
/// edge from corner `a` to corner `b`: `Less` when the first comes before the second. `None`
/// when a bisector is parallel to the edge (it has no single crossing).
pub(crate) fn compare_crossings(
    [a, b]: [[f64; 2]; 2],
    first: [[f64; 2]; 2],
    second: [[f64; 2]; 2],
) -> Option<Ordering> {
    let [ax, ay, bx, by, p0x, p0y, q0x, q0y, p1x, p1y, q1x, q1y] = integers([
        a[0],
        a[1],
        b[0],
        b[1],
        first[0][0],
        first[0][1],
        first[1][0],
        first[1][1],
        second[0][0],
        second[0][1],
        second[1][0],
        second[1][1],
    ]);
    let (ex, ey) = (bx.sub(&ax), by.sub(&ay));
    let squared_distance = |x: &WideInteger, y: &WideInteger| {
        let (dx, dy) = (ax.sub(x), ay.sub(y));
        dx.mul(&dx).add(&dy.mul(&dy))
    };
    // `t = numerator / denominator` (the factor 2 is common to both and dropped).
    let parameter = |px: &WideInteger, py: &WideInteger, qx: &WideInteger, qy: &WideInteger| {
        let numerator = squared_distance(qx, qy).sub(&squared_distance(px, py));
        let denominator = ex.mul(&qx.sub(px)).add(&ey.mul(&qy.sub(py)));
        (numerator, denominator)
    };
    let (n0, d0) = parameter(&p0x, &p0y, &q0x, &q0y);
    let (n1, d1) = parameter(&p1x, &p1y, &q1x, &q1y);
    if d0.signum() == 0 || d1.signum() == 0 {
        return None;
    }
    let difference = n0.mul(&d1).sub(&n1.mul(&d0)).signum() * d0.signum() * d1.signum();
    Some(difference.cmp(&0))
}

/// Does the bisector of `[p, q]`, run along `rot90(q − p)` (reversed when `reversed`), have a
/// piece of positive length inside the convex region with counter-clockwise `corners`? That
/// is: is it strictly inside every side it is parallel to, and does it cross the last of the
/// sides it goes in across strictly before the first of those it goes out across?
///
/// The crossing of side `[a, b]` lies at `a + t·(b − a)` with `t = N / D` (see the module
/// documentation), at `(d·a·D + N·d·(b − a)) / D` along the bisector's direction `d`; `D` is
/// positive where the bisector goes in. Compared without rounding, the positions tell a piece
/// narrower than an ulp (a bisector passing a corner by far less than an ulp, inside it) from
/// none. O(corners) comparisons.
pub(crate) fn bisector_has_piece_inside(
    corners: &[[f64; 2]],
    [p, q]: [[f64; 2]; 2],
    reversed: bool,
) -> bool {
    // Swapping the sites reverses `d` (and leaves every crossing where it is).
    let [p, q] = if reversed { [q, p] } else { [p, q] };
    let values: Vec<f64> = corners.iter().chain([&p, &q]).flatten().copied().collect();
    let integers = integer_list(&values);
    let m = corners.len();
    let point = |k: usize| (&integers[2 * k], &integers[2 * k + 1]);
    let ((px, py), (qx, qy)) = (point(m), point(m + 1));
    let (ux, uy) = (qx.sub(px), qy.sub(py));
    let (dx, dy) = (py.sub(qy), ux.clone());
    // `first < second` for positions `(numerator, denominator)`, denominators of either sign.
    let before = |first: &(WideInteger, WideInteger), second: &(WideInteger, WideInteger)| {
        let difference = second.0.mul(&first.1).sub(&first.0.mul(&second.1));
        difference.signum() * first.1.signum() * second.1.signum() > 0
    };
    let (mut last_in, mut first_out) = (None, None);
    for i in 0..m {
        let ((ax, ay), (bx, by)) = (point(i), point((i + 1) % m));
        let (ex, ey) = (bx.sub(ax), by.sub(ay));
        // `e·u`, which is `e × d`: how fast the side's edge function grows along `d`.
        let along_sites = ex.mul(&ux).add(&ey.mul(&uy));
        if along_sites.signum() == 0 {
            // Parallel: strictly inside where the sites' midpoint is, `e × (p + q − 2a) > 0`.
            let (mx, my) = (px.add(qx).sub(ax).sub(ax), py.add(qy).sub(ay).sub(ay));
            if ex.mul(&my).sub(&ey.mul(&mx)).signum() <= 0 {
                return false;
            }
            continue;
        }
        let squared = |x: &WideInteger, y: &WideInteger| {
            let (dx, dy) = (ax.sub(x), ay.sub(y));
            dx.mul(&dx).add(&dy.mul(&dy))
        };
        let numerator = squared(qx, qy).sub(&squared(px, py));
        let denominator = along_sites.add(&along_sites);
        let start = dx.mul(ax).add(&dy.mul(ay));
        let along_edge = dx.mul(&ex).add(&dy.mul(&ey));
        let position = (
            start.mul(&denominator).add(&numerator.mul(&along_edge)),
            denominator,
        );
        if position.1.signum() > 0 {
            if last_in.as_ref().is_none_or(|last| before(last, &position)) {
                last_in = Some(position);
            }
        } else if first_out
            .as_ref()
            .is_none_or(|first| before(&position, first))
        {
            first_out = Some(position);
        }
    }
    match (last_in, first_out) {
        (Some(entry), Some(exit)) => before(&entry, &exit),
        _ => true,
    }
}

/// Does the bisector of `sites` cross the line of the edge from `a` to `b` at a single point
/// (is it not parallel to it)?
pub(crate) fn crosses_edge([a, b]: [[f64; 2]; 2], [p, q]: [[f64; 2]; 2]) -> bool {
    let [ax, ay, bx, by, px, py, qx, qy] =
        integers([a[0], a[1], b[0], b[1], p[0], p[1], q[0], q[1]]);
    let along = bx
        .sub(&ax)
        .mul(&qx.sub(&px))
        .add(&by.sub(&ay).mul(&qy.sub(&py)));
    along.signum() != 0
}

/// Does the bisector of `sites` pass exactly through `corner`?
pub(crate) fn bisector_meets(corner: [f64; 2], [p, q]: [[f64; 2]; 2]) -> bool {
    Metric::Euclidean.compare(corner, p, q) == Ordering::Equal
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossings_an_ulp_apart_far_out_are_ordered() {
        // Vertical bisectors at x = 1e15 + 49.125 and 1e15 + 49.25 (the ulp there is 0.125),
        // crossing the edge along the x axis.
        let a = [1e15 + 48.0, 0.0];
        let b = [1e15 + 52.0, 0.0];
        let left = [[1e15 + 49.0, 1.0], [1e15 + 49.25, 1.0]];
        let right = [[1e15 + 49.0, 1.0], [1e15 + 49.5, 1.0]];
        assert_eq!(compare_crossings([a, b], left, right), Some(Ordering::Less));
        assert_eq!(
            compare_crossings([a, b], right, left),
            Some(Ordering::Greater)
        );
        assert_eq!(
            compare_crossings([b, a], left, right),
            Some(Ordering::Greater)
        );
        // The same bisector with its sites swapped crosses at the same point.
        let swapped = [left[1], left[0]];
        assert_eq!(
            compare_crossings([a, b], left, swapped),
            Some(Ordering::Equal)
        );
        // A bisector parallel to the edge has no crossing.
        let above = [[1e15 + 49.0, 1.0], [1e15 + 49.0, 2.0]];
        assert_eq!(compare_crossings([a, b], above, left), None);
    }

    #[test]
    fn a_piece_far_narrower_than_an_ulp_inside_a_corner_is_found() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        // The bisector of the corner and a point 1e-200 along the diagonal cuts a triangle
        // 1e-200 wide off the corner; that of two points on the far side of it misses.
        let tiny = 1e-200;
        assert!(bisector_has_piece_inside(
            &square,
            [[0.0, 0.0], [tiny, tiny]],
            false
        ));
        assert!(bisector_has_piece_inside(
            &square,
            [[0.0, 0.0], [tiny, tiny]],
            true
        ));
        assert!(!bisector_has_piece_inside(
            &square,
            [[-tiny, -tiny], [-3.0 * tiny, -tiny]],
            false
        ));
        // Through the corner only (x + y = 0): a point, no piece.
        assert!(!bisector_has_piece_inside(
            &square,
            [[tiny, tiny], [-tiny, -tiny]],
            false
        ));
        // Parallel to the bottom side: inside by 2^-60, and on it.
        let y = 2.0_f64.powi(-60);
        assert!(bisector_has_piece_inside(
            &square,
            [[0.5, 0.0], [0.5, 2.0 * y]],
            false
        ));
        assert!(!bisector_has_piece_inside(
            &square,
            [[0.5, -y], [0.5, y]],
            false
        ));
    }

    #[test]
    fn a_bisector_through_a_corner_is_exact() {
        // Squared distances 1 + 1e-600 and 1 from the corner: apart only exactly.
        assert!(!bisector_meets([0.0, 0.0], [[1.0, 1e-300], [0.0, 1.0]]));
        assert!(bisector_meets([0.0, 0.0], [[1.0, 1e-300], [1e-300, 1.0]]));
    }
}
