//! Where Voronoi edges cross the sides of a clip region, from their sites: the crossings
//! themselves, which sides a bisector enters and leaves by, the exact order of crossings along
//! one side, and which side of a side's line a Voronoi vertex lies on.
//!
//! The bisector of sites `p` and `q` meets the line `a + t·(b − a)` at
//! `t = (|a − q|² − |a − p|²) / (2 (b − a)·(q − p))`. Two such parameters are compared without
//! rounding, in integers of any size: their floating-point values can agree (or both round to a
//! corner) for crossings that lie apart by far less than an ulp, where the region is narrow beside
//! its distance from the origin.

use std::cmp::Ordering;

use super::exact_distance::Metric;
use super::predicates::normalising_scale_of_box;
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

/// Is the point where the bisector of `[p, q]` crosses the line of the edge from `a` to `b`
/// nearer to `p` than to `other` (`Less`), as near (`Equal`) or farther (`Greater`)? `None`
/// when the bisector is parallel to the edge.
///
/// A point of the bisector lies on the Voronoi edge of `p` and `q` when it is nearer to them
/// than to the third site of the Delaunay triangle at either end: past an end, that site is
/// nearer. Exact, so it tells a crossing on an edge from one just beyond a vertex rounded to
/// ulps of its distance from the origin.
pub(crate) fn crossing_nearer_than(
    [a, b]: [[f64; 2]; 2],
    [p, q]: [[f64; 2]; 2],
    other: [f64; 2],
) -> Option<Ordering> {
    let [ax, ay, bx, by, px, py, qx, qy, ox, oy] = integers([
        a[0], a[1], b[0], b[1], p[0], p[1], q[0], q[1], other[0], other[1],
    ]);
    let (ex, ey) = (bx.sub(&ax), by.sub(&ay));
    let squared_distance = |x: &WideInteger, y: &WideInteger| {
        let (dx, dy) = (ax.sub(x), ay.sub(y));
        dx.mul(&dx).add(&dy.mul(&dy))
    };
    // The crossing is `a + (N / 2D)·e`, and at `a + τ·e`,
    // `|x − p|² − |x − o|² = |a − p|² − |a − o|² + 2τ·e·(o − p)`.
    let numerator = squared_distance(&qx, &qy).sub(&squared_distance(&px, &py));
    let denominator = ex.mul(&qx.sub(&px)).add(&ey.mul(&qy.sub(&py)));
    if denominator.signum() == 0 {
        return None;
    }
    let at_a = squared_distance(&px, &py).sub(&squared_distance(&ox, &oy));
    let towards_other = ex.mul(&ox.sub(&px)).add(&ey.mul(&oy.sub(&py)));
    let difference = at_a.mul(&denominator).add(&numerator.mul(&towards_other));
    Some((difference.signum() * denominator.signum()).cmp(&0))
}

/// Which side of the line from `a` to `b` the circumcentre of `[p, q, r]` lies on: `Greater`
/// on its left (inside a counter-clockwise region), `Equal` on the line. `None` for collinear
/// sites.
///
/// Exact: a Voronoi vertex within an ulp of a side is rounded to either side of it, and the
/// clipping of its edges follows where the vertex is.
pub(crate) fn circumcentre_side(
    [a, b]: [[f64; 2]; 2],
    [p, q, r]: [[f64; 2]; 3],
) -> Option<Ordering> {
    let [ax, ay, bx, by, px, py, qx, qy, rx, ry] =
        integers([a[0], a[1], b[0], b[1], p[0], p[1], q[0], q[1], r[0], r[1]]);
    let (ex, ey) = (bx.sub(&ax), by.sub(&ay));
    let (ux, uy, wx, wy) = (qx.sub(&px), qy.sub(&py), rx.sub(&px), ry.sub(&py));
    let determinant = ux.mul(&wy).sub(&uy.mul(&wx));
    if determinant.signum() == 0 {
        return None;
    }
    // The circumcentre is `p + (cx, cy) / 2D`, with `D` the determinant, so its side of the
    // line has the sign of `2D·(e × (p − a)) + e × (cx, cy)` times that of `D`.
    let (u2, w2) = (ux.mul(&ux).add(&uy.mul(&uy)), wx.mul(&wx).add(&wy.mul(&wy)));
    let (cx, cy) = (wy.mul(&u2).sub(&uy.mul(&w2)), ux.mul(&w2).sub(&wx.mul(&u2)));
    let from_a = ex.mul(&py.sub(&ay)).sub(&ey.mul(&px.sub(&ax)));
    let offset = ex.mul(&cy).sub(&ey.mul(&cx));
    let twice = determinant.add(&determinant);
    let side = twice.mul(&from_a).add(&offset).signum() * determinant.signum();
    Some(side.cmp(&0))
}

/// Where a bisector crosses the line of an edge of the region (see [`bisector_crossing`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct BisectorCrossing {
    /// The parameter `t` of `a + t·(b − a)` and `t − 1`: the one that places the point (`t` up
    /// to the middle of the edge, `t − 1` beyond) within 3e-12 of its exact value, relative
    /// (`t − 1` is computed from `b`, as `(|b − q|² − |b − p|²) / D`, so it keeps its own low
    /// bits near `b`).
    pub parameters: [f64; 2],
    /// Does the bisector of `[p, q]`, run along `rot90(q − p)`, go into the region there (cross
    /// the edge from its outer side)? Exact.
    pub goes_in: bool,
}

/// Where the bisector of `[p, q]` crosses the line of the edge from `a` to `b`, and which way;
/// `None` when it is parallel to the edge.
///
/// Computed from the sites and corners, not from a point on the Voronoi edge: an edge placed
/// from a vertex far beyond a large region is rounded there to ulps of that distance, which can
/// be far wider than the cells beside a corner of the region.
pub(crate) fn bisector_crossing(
    edge: [[f64; 2]; 2],
    sites: [[f64; 2]; 2],
) -> Option<BisectorCrossing> {
    fast_bisector_crossing(edge, sites).or_else(|| exact_bisector_crossing(edge, sites))
}

/// [`bisector_crossing`] in floating point, when a bound on its rounding says the parameter
/// that places the point (`t` up to the middle of the edge, `t − 1` beyond) is within 3e-12 of
/// its value; `None` elsewhere (a crossing near a corner seen from sites far from it, extreme
/// magnitudes, a bisector nearly parallel to the edge).
fn fast_bisector_crossing(
    [a, b]: [[f64; 2]; 2],
    [p, q]: [[f64; 2]; 2],
) -> Option<BisectorCrossing> {
    // Each value below is rounded by at most five ulps of the sum of its terms' magnitudes (its
    // size); one whose size is at most this many times the value is within 5120 ulps of it,
    // and a ratio of two such within 3e-12.
    const CANCELLATION: f64 = 1024.0;
    let differences = [
        [0, 1].map(|k| b[k] - a[k]),
        [0, 1].map(|k| p[k] - q[k]),
        [0, 1].map(|k| a[k] - p[k]),
        [0, 1].map(|k| a[k] - q[k]),
        [0, 1].map(|k| b[k] - p[k]),
        [0, 1].map(|k| b[k] - q[k]),
    ];
    let largest = differences
        .iter()
        .flatten()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    if !(largest.is_finite() && largest > 0.0) {
        return None;
    }
    // A power of two that brings the largest difference near 1: products neither overflow nor
    // (short of differences 1e-150 times smaller, which the bound then refuses) underflow.
    let unit = normalising_scale_of_box([[-largest, -largest], [largest, largest]]);
    let [e, w, ap, aq, bp, bq] = differences.map(|d| d.map(|x| x * unit));
    // `|c − q|² − |c − p|² = (p − q)·((c − p) + (c − q))`, and the size of its terms.
    let from_corner = |cp: [f64; 2], cq: [f64; 2]| {
        let sum = [0, 1].map(|k| cp[k] + cq[k]);
        let size: f64 = (0..2)
            .map(|k| w[k].abs() * (cp[k].abs() + cq[k].abs()))
            .sum();
        (w[0] * sum[0] + w[1] * sum[1], size)
    };
    let numerator = from_corner(ap, aq);
    let end_numerator = from_corner(bp, bq);
    // `D = 2 (b − a)·(q − p)`.
    let denominator = (
        -2.0 * (e[0] * w[0] + e[1] * w[1]),
        2.0 * ((e[0] * w[0]).abs() + (e[1] * w[1]).abs()),
    );
    let accurate = |(value, size): (f64, f64)| {
        value.abs() >= f64::MIN_POSITIVE && size <= CANCELLATION * value.abs()
    };
    let t = numerator.0 / denominator.0;
    let placing = if t <= 0.5 { numerator } else { end_numerator };
    (accurate(denominator) && accurate(placing)).then(|| BisectorCrossing {
        parameters: [t, end_numerator.0 / denominator.0],
        goes_in: denominator.0 > 0.0,
    })
}

/// [`bisector_crossing`] from the exact numerators and denominator, in integers of any size.
#[cold]
fn exact_bisector_crossing(
    [a, b]: [[f64; 2]; 2],
    [p, q]: [[f64; 2]; 2],
) -> Option<BisectorCrossing> {
    let [ax, ay, bx, by, px, py, qx, qy] =
        integers([a[0], a[1], b[0], b[1], p[0], p[1], q[0], q[1]]);
    let from_corner = |cx: &WideInteger, cy: &WideInteger| {
        let squared = |x: &WideInteger, y: &WideInteger| {
            let (dx, dy) = (cx.sub(x), cy.sub(y));
            dx.mul(&dx).add(&dy.mul(&dy))
        };
        squared(&qx, &qy).sub(&squared(&px, &py))
    };
    let along = bx
        .sub(&ax)
        .mul(&qx.sub(&px))
        .add(&by.sub(&ay).mul(&qy.sub(&py)));
    if along.signum() == 0 {
        return None;
    }
    let denominator = along.add(&along);
    let numerators = [from_corner(&ax, &ay), from_corner(&bx, &by)];
    Some(BisectorCrossing {
        parameters: numerators.map(|n| n.ratio(&denominator, 0)),
        goes_in: denominator.signum() > 0,
    })
}

/// The sides across which the bisector of `[p, q]`, run along `rot90(q − p)` (reversed when
/// `reversed`), enters and leaves the convex region with counter-clockwise `corners`, when it
/// has a piece of positive length inside: that is, when it is strictly inside every side it is
/// parallel to, and crosses the last of the sides it goes in across (the entry) strictly before
/// the first of those it goes out across (the exit). `None` when it has no such piece.
///
/// The crossing of side `[a, b]` lies at `a + t·(b − a)` with `t = N / D` (see the module
/// documentation), at `(d·a·D + N·d·(b − a)) / D` along the bisector's direction `d`; `D` is
/// positive where the bisector goes in. Compared without rounding, the positions tell a piece
/// narrower than an ulp (a bisector passing a corner by far less than an ulp, inside it) from
/// none, and the side it enters by from its neighbour across a corner. O(corners) comparisons.
pub(crate) fn bisector_piece_sides(
    corners: &[[f64; 2]],
    [p, q]: [[f64; 2]; 2],
    reversed: bool,
) -> Option<[usize; 2]> {
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
                return None;
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
            if last_in
                .as_ref()
                .is_none_or(|(_, last)| before(last, &position))
            {
                last_in = Some((i, position));
            }
        } else if first_out
            .as_ref()
            .is_none_or(|(_, first)| before(&position, first))
        {
            first_out = Some((i, position));
        }
    }
    // A bounded region: a line not parallel to every side both enters and leaves it.
    let ((entry, entry_at), (exit, exit_at)) = (last_in?, first_out?);
    before(&entry_at, &exit_at).then_some([entry, exit])
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

/// Does the bisector of `[p, q]` meet the edge from `a` to `b` between its corners or at one,
/// exactly? (A crossing 2 units beyond a corner at 6e63 rounds onto it.)
pub(crate) fn bisector_meets_edge([a, b]: [[f64; 2]; 2], [p, q]: [[f64; 2]; 2]) -> bool {
    let nearer_p = |corner: [f64; 2]| Metric::Euclidean.compare(corner, p, q);
    nearer_p(a) != nearer_p(b) || nearer_p(a) == Ordering::Equal
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
    fn a_crossing_lies_on_the_edge_between_the_third_sites_bisectors() {
        // The bisector of (0, 1) and (0, -1) is the x axis; it crosses the side x = 3 at (3, 0).
        let side = [[3.0, -5.0], [3.0, 5.0]];
        let sites = [[0.0, 1.0], [0.0, -1.0]];
        // (3, 0) is 10 from the sites (squared): nearer to them than to (10, 0), as near as to
        // (6, 1), and farther than from (4, 0).
        let nearer = |other| crossing_nearer_than(side, sites, other);
        assert_eq!(nearer([10.0, 0.0]), Some(Ordering::Less));
        assert_eq!(nearer([6.0, 1.0]), Some(Ordering::Equal));
        assert_eq!(nearer([4.0, 0.0]), Some(Ordering::Greater));
        // Either way along the side, and with the sites swapped.
        let reversed = [side[1], side[0]];
        assert_eq!(
            crossing_nearer_than(reversed, [sites[1], sites[0]], [4.0, 0.0]),
            Some(Ordering::Greater)
        );
        // A bisector parallel to the side crosses it nowhere.
        assert_eq!(
            crossing_nearer_than([[0.0, 3.0], [1.0, 3.0]], sites, [9.0, 0.0]),
            None
        );
    }

    #[test]
    fn a_crossing_near_the_end_of_a_long_side_keeps_its_offset_from_it() {
        // The bisector of (-2, 6) and (1, -3) crosses y = 21 at x = 58, 65 from the side's end
        // (-7, 21) and 9e25 from its start.
        let side = [[9e25, 21.0], [-7.0, 21.0]];
        let crossing = bisector_crossing(side, [[-2.0, 6.0], [1.0, -3.0]]).unwrap();
        let [t, from_end] = crossing.parameters;
        assert_eq!(t, 1.0);
        let offset = from_end * (-7.0 - 9e25);
        assert!((offset - 65.0).abs() <= 1e-13, "{offset}");
        // Along rot90(q − p) = (9, 3) the bisector goes up, out across the top side.
        assert!(!crossing.goes_in);
    }

    #[test]
    fn fast_crossings_agree_with_exact_ones() {
        let mut uniform = crate::support::test_random::uniform(0x9e37_79b9_7f4a_7c15);
        let mut next = || 2.0 * uniform() - 1.0;
        let mut fast_ones = 0;
        for _ in 0..10_000 {
            let mut point = || [next(), next()];
            let (edge, sites) = ([point(), point()], [point(), point()]);
            let Some(fast) = fast_bisector_crossing(edge, sites) else {
                continue;
            };
            fast_ones += 1;
            let exact = exact_bisector_crossing(edge, sites).unwrap();
            assert_eq!(fast.goes_in, exact.goes_in);
            let [t, from_end] = exact.parameters;
            let placing = if t <= 0.5 { 0 } else { 1 };
            let (got, want) = (fast.parameters[placing], exact.parameters[placing]);
            assert!(
                (got - want).abs() <= 3e-12 * want.abs(),
                "{edge:?} {sites:?}: {got} vs {want} ({t}, {from_end})"
            );
        }
        assert!(fast_ones > 9_500, "{fast_ones}");
    }

    fn has_piece(corners: &[[f64; 2]], sites: [[f64; 2]; 2], reversed: bool) -> bool {
        bisector_piece_sides(corners, sites, reversed).is_some()
    }

    #[test]
    fn a_piece_far_narrower_than_an_ulp_inside_a_corner_is_found() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        // The bisector of the corner and a point 1e-200 along the diagonal cuts a triangle
        // 1e-200 wide off the corner; that of two points on the far side of it misses.
        let tiny = 1e-200;
        assert!(has_piece(&square, [[0.0, 0.0], [tiny, tiny]], false));
        assert!(has_piece(&square, [[0.0, 0.0], [tiny, tiny]], true));
        assert!(!has_piece(
            &square,
            [[-tiny, -tiny], [-3.0 * tiny, -tiny]],
            false
        ));
        // Through the corner only (x + y = 0): a point, no piece.
        assert!(!has_piece(&square, [[tiny, tiny], [-tiny, -tiny]], false));
        // Parallel to the bottom side: inside by 2^-60, and on it.
        let y = 2.0_f64.powi(-60);
        assert!(has_piece(&square, [[0.5, 0.0], [0.5, 2.0 * y]], false));
        assert!(!has_piece(&square, [[0.5, -y], [0.5, y]], false));
    }

    #[test]
    fn a_bisector_through_a_corner_is_exact() {
        // Squared distances 1 + 1e-600 and 1 from the corner: apart only exactly.
        assert!(!bisector_meets([0.0, 0.0], [[1.0, 1e-300], [0.0, 1.0]]));
        assert!(bisector_meets([0.0, 0.0], [[1.0, 1e-300], [1e-300, 1.0]]));
    }

    #[test]
    fn a_circumcentre_an_ulp_from_a_side_is_placed_exactly() {
        // The circumcentre of these sites is (-0.4, 1.5) in reals; in doubles it lies 2.8e-17
        // right of the line x = -0.4 (the double nearest -0.4), and rounds 2 ulps left of it.
        let sites = [[0.1, 0.1], [1.0, 1.0], [1.0, 2.0]];
        let down = [[-0.4, 4.4], [-0.4, -0.4]];
        assert_eq!(circumcentre_side(down, sites), Some(Ordering::Greater));
        assert_eq!(
            circumcentre_side([down[1], down[0]], sites),
            Some(Ordering::Less)
        );
        // (1, 1): on the line x = 1, and on the left of the line y = 3 run leftwards.
        let right_angle = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        assert_eq!(
            circumcentre_side([[1.0, 0.0], [1.0, 5.0]], right_angle),
            Some(Ordering::Equal)
        );
        assert_eq!(
            circumcentre_side([[9.0, 3.0], [-9.0, 3.0]], right_angle),
            Some(Ordering::Greater)
        );
        let collinear = [[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]];
        assert_eq!(circumcentre_side(down, collinear), None);
    }

    #[test]
    fn a_bisector_meets_an_edge_only_between_its_corners() {
        let corner = -6.000000000000001e63;
        let left = [[corner, 6.6e64], [corner, corner]];
        let bottom = [[corner, corner], [1.6e64, corner]];
        // y = x - 2: 2 below the corner on the left side's line, 2 right of it on the bottom.
        let below = [[2.0, 1.0], [3.0, 0.0]];
        assert!(!bisector_meets_edge(left, below));
        assert!(bisector_meets_edge(bottom, below));
        // y = x passes through the corner itself.
        let through = [[2.0, 1.0], [1.0, 2.0]];
        assert!(bisector_meets_edge(left, through));
        assert!(bisector_meets_edge(bottom, through));
    }
}
