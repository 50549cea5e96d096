//! Newell's method: the area vector of a polygon, planar or not (Baumgart's face-normal loop).

/// The Newell vector of the closed polygon `points`: perpendicular to the polygon's best-fit
/// plane, pointing to the side from which the polygon runs counter-clockwise, with length twice
/// its area (for planar polygons). Zero for fewer than 3 points.
pub fn newell_vector(points: impl IntoIterator<Item = [f64; 3]>) -> [f64; 3] {
    let mut points = points.into_iter();
    let Some(first) = points.next() else {
        return [0.0; 3];
    };
    let mut sum = [0.0; 3];
    let mut add = |a: [f64; 3], b: [f64; 3]| {
        sum[0] += (a[1] - b[1]) * (a[2] + b[2]);
        sum[1] += (a[2] - b[2]) * (a[0] + b[0]);
        sum[2] += (a[0] - b[0]) * (a[1] + b[1]);
    };
    let mut previous = first;
    for point in points {
        add(previous, point);
        previous = point;
    }
    add(previous, first);
    sum
}

/// `true` when the polygon's area is negligible against its size: the Newell vector is no longer
/// than a few rounding errors of the sum of squared edge lengths (so collinear corners, repeated
/// positions and needles thinner than ~1e-15 of their length count as degenerate). One pass;
/// non-finite coordinates give `false` (they are reported as such, not as degenerate).
pub fn is_degenerate_polygon<P>(points: P) -> bool
where
    P: IntoIterator<Item = [f64; 3]>,
    P::IntoIter: Clone,
{
    polygon_area_test(points).0
}

/// [`is_degenerate_polygon`], with the polygon's squared perimeter, the size it judged the area
/// against (finite as [`triangle_squared_size`] is; zero for no points).
pub(crate) fn polygon_area_test<P>(points: P) -> (bool, f64)
where
    P: IntoIterator<Item = [f64; 3]>,
    P::IntoIter: Clone,
{
    let points = points.into_iter();
    let (degenerate, squared_perimeter) = unscaled_polygon_area_test(points.clone());
    if degenerate && squares_may_be_off(squared_perimeter) {
        let points: Vec<[f64; 3]> = points.collect();
        if let Some(scaled) = scaled_to_unit_size(&points) {
            return (unscaled_polygon_area_test(scaled).0, squared_perimeter);
        }
    }
    (degenerate, squared_perimeter)
}

/// [`polygon_area_test`] on the coordinates as they are.
fn unscaled_polygon_area_test(points: impl IntoIterator<Item = [f64; 3]>) -> (bool, f64) {
    let mut points = points.into_iter();
    let Some(first) = points.next() else {
        return (true, 0.0);
    };
    let mut area_vector = [0.0; 3];
    let mut squared_perimeter = 0.0;
    let mut add = |a: [f64; 3], b: [f64; 3]| {
        area_vector[0] += (a[1] - b[1]) * (a[2] + b[2]);
        area_vector[1] += (a[2] - b[2]) * (a[0] + b[0]);
        area_vector[2] += (a[0] - b[0]) * (a[1] + b[1]);
        squared_perimeter += squared_distance(a, b);
    };
    let mut previous = first;
    for point in points {
        add(previous, point);
        previous = point;
    }
    add(previous, first);
    (
        is_negligible_area(area_vector, squared_perimeter),
        squared_perimeter,
    )
}

/// The area vector of a face from its corners in loop order, as both kernels compute it: the
/// cross-product forms of [`triangle_area_vector`] and [`quad_area_vector`] for triangles and
/// quads (fewer operations, and the bulk passes use them), Newell's sums for larger polygons.
pub fn face_corners_area_vector(corners: impl IntoIterator<Item = [f64; 3]>) -> [f64; 3] {
    let mut corners = corners.into_iter();
    let first: [Option<[f64; 3]>; 5] = std::array::from_fn(|_| corners.next());
    match first {
        [Some(a), Some(b), Some(c), None, _] => triangle_area_vector(a, b, c),
        [Some(a), Some(b), Some(c), Some(d), None] => quad_area_vector(a, b, c, d),
        _ => newell_vector(first.into_iter().flatten().chain(corners)),
    }
}

/// `area_vector`, the area vector of a face whose corners `corners` gives, when its length is a
/// normal double; when the length overflowed (coordinates near 1e308) or underflowed (a face
/// smaller than about 1e-154), the area vector of the corners moved to the origin and scaled to
/// unit size: the same direction, another length. Zero stays zero for a face without area.
pub(crate) fn rescued_area_vector(
    area_vector: [f64; 3],
    corners: impl FnOnce() -> Vec<[f64; 3]>,
) -> [f64; 3] {
    /// Faces whose corners differ by more than this have area vectors that cannot underflow:
    /// a zero one is a face without area.
    const UNDERFLOW_FREE_SIZE: f64 = 1e-140;
    let squared = squared_length(area_vector);
    if squared.is_normal() && squared < f64::INFINITY {
        return area_vector;
    }
    let corners = corners();
    let overflowed = !squared.is_finite();
    let tiny = corners
        .iter()
        .all(|p| (0..3).all(|k| (p[k] - corners[0][k]).abs() <= UNDERFLOW_FREE_SIZE));
    match scaled_to_unit_size(&corners) {
        Some(scaled) if overflowed || tiny => face_corners_area_vector(scaled),
        _ => area_vector,
    }
}

/// The area vector of triangle `abc` (as [`newell_vector`]: along its normal, twice its area
/// long) from the cross product of two edges: fewer operations than Newell's sums, for the bulk
/// passes over triangle meshes.
#[inline]
pub fn triangle_area_vector(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    cross(difference(b, a), difference(c, a))
}

/// The area vector of quad `abcd` (as [`newell_vector`], planar or not): the cross product of
/// its diagonals, which Newell's sums reduce to for four corners.
#[inline]
pub fn quad_area_vector(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> [f64; 3] {
    cross(difference(c, a), difference(d, b))
}

/// [`is_degenerate_polygon`] for a triangle, from [`triangle_area_vector`]; bulk builds check
/// every face this way.
#[inline]
pub fn is_degenerate_triangle(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> bool {
    if is_clearly_not_degenerate_triangle(a, b, c) {
        return false;
    }
    let (ab, ac) = (difference(b, a), difference(c, a));
    let squared_perimeter = triangle_squared_size(a, b, c) + squared_distance(b, c);
    let degenerate = is_negligible_area(cross(ab, ac), squared_perimeter);
    if degenerate && squares_may_be_off(squared_perimeter) {
        return polygon_area_test([a, b, c]).0;
    }
    degenerate
}

/// The first test of [`is_degenerate_triangle`], which decides almost every face: `true` when
/// the area vector is not negligible even against four times the squares of the two edges from
/// `a`. Since |bc|² ≤ 2(|ab|² + |ac|²), that bounds the squared perimeter, so such a triangle is
/// not degenerate. Branch-free, for bulk passes that test several faces side by side.
#[inline(always)]
pub(crate) fn is_clearly_not_degenerate_triangle(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> bool {
    let (ab, ac) = (difference(b, a), difference(c, a));
    !is_negligible_area(cross(ab, ac), 4.0 * triangle_squared_size(a, b, c))
}

/// The size the triangle tests judge `abc`'s area against: the squares of its two edges from `a`.
/// Like every squared size here it is finite only when all the coordinates it reads are (or
/// when the squares overflow), so bulk checks learn from it whether their corners were finite.
#[inline(always)]
pub(crate) fn triangle_squared_size(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    squared_distance(b, a) + squared_distance(c, a)
}

/// [`is_degenerate_polygon`] for a quad, its area vector from the diagonals (as
/// [`quad_area_vector`]) against the sum of its squared sides.
#[inline]
pub fn is_degenerate_quad(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> bool {
    let squared_perimeter = quad_squared_perimeter(a, b, c, d);
    let degenerate = is_negligible_area(quad_area_vector(a, b, c, d), squared_perimeter);
    if degenerate && squares_may_be_off(squared_perimeter) {
        return polygon_area_test([a, b, c, d]).0;
    }
    degenerate
}

/// Whether squares of coordinate differences summing to `squared_size` may have underflowed or
/// overflowed (sizes below about 1e-125 or above 1e150), so that an area test on them can call a
/// real face degenerate: such faces are judged again at unit size.
fn squares_may_be_off(squared_size: f64) -> bool {
    const SMALLEST_SAFE: f64 = 1e-250;
    const LARGEST_SAFE: f64 = 1e300;
    !(SMALLEST_SAFE..=LARGEST_SAFE).contains(&squared_size)
}

/// `points` moved so the first is at the origin and scaled so the largest coordinate difference
/// is about 1 (halved first, so no difference of finite coordinates overflows); `None` when a
/// coordinate is not finite or all points coincide.
fn scaled_to_unit_size(points: &[[f64; 3]]) -> Option<impl Iterator<Item = [f64; 3]> + '_> {
    let origin = *points.first()?;
    let half_difference =
        move |p: &[f64; 3]| -> [f64; 3] { std::array::from_fn(|k| 0.5 * p[k] - 0.5 * origin[k]) };
    let scale = points
        .iter()
        .flat_map(half_difference)
        .fold(0.0f64, |m, x| m.max(x.abs()));
    (scale > 0.0 && scale.is_finite()).then(move || {
        points
            .iter()
            .map(move |p| half_difference(p).map(|x| x / scale))
    })
}

/// The sum of quad `abcd`'s squared sides, the size [`is_degenerate_quad`] judges its area
/// against (finite as [`triangle_squared_size`] is).
#[inline(always)]
pub(crate) fn quad_squared_perimeter(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> f64 {
    squared_distance(a, b)
        + squared_distance(b, c)
        + squared_distance(c, d)
        + squared_distance(d, a)
}

/// `true` when an area vector is rounding noise against the squared perimeter.
#[inline(always)]
fn is_negligible_area(area_vector: [f64; 3], squared_perimeter: f64) -> bool {
    /// Relative size of the area vector below which it is rounding noise.
    const RELATIVE_TOLERANCE: f64 = 16.0 * f64::EPSILON;
    let bound = RELATIVE_TOLERANCE * squared_perimeter;
    squared_length(area_vector) <= bound * bound
}

pub(crate) fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

pub(crate) fn difference(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn squared_distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    squared_length(difference(a, b))
}

fn squared_length(v: [f64; 3]) -> f64 {
    v[0] * v[0] + v[1] * v[1] + v[2] * v[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_square_has_area_vector_of_twice_its_area_along_z() {
        let square = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        assert_eq!(newell_vector(square), [0.0, 0.0, 2.0]);
        let reversed: Vec<_> = square.iter().rev().copied().collect();
        assert_eq!(newell_vector(reversed), [0.0, 0.0, -2.0]);
        assert!(!is_degenerate_polygon(square));
    }

    #[test]
    fn collinear_and_coincident_corners_are_degenerate() {
        assert!(is_degenerate_polygon([
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 1.0],
            [2.0, 2.0, 2.0]
        ]));
        assert!(is_degenerate_polygon([[1.0, 2.0, 3.0]; 3]));
        assert!(is_degenerate_polygon([[0.0; 3]; 0]));
        assert!(!is_degenerate_polygon([
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1e-6, 0.0]
        ]));
    }

    #[test]
    fn triangle_and_quad_checks_agree_with_the_polygon_check_and_survive_a_far_origin() {
        let mid = |p: [f64; 3], q: [f64; 3]| {
            [
                0.5 * (p[0] + q[0]),
                0.5 * (p[1] + q[1]),
                0.5 * (p[2] + q[2]),
            ]
        };
        let triangles = [
            [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]],
            [[1.0, 2.0, 3.0]; 3],
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1e-6, 0.0]],
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1e-17, 0.0]],
            [[0.3, -2.0, 5.0], [1.0, 4.0, -1.0], [-7.0, 0.5, 2.0]],
        ];
        let quad = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.5],
            [2.0, 1.0, -0.25],
            [0.0, 1.0, 1.0],
        ];
        let [a, b, c, d] = quad;
        let newell = newell_vector(quad);
        let diagonals = quad_area_vector(a, b, c, d);
        for i in 0..3 {
            assert!(
                (newell[i] - diagonals[i]).abs() < 1e-12,
                "{newell:?} {diagonals:?}"
            );
        }
        for [a, b, c] in triangles {
            assert_eq!(
                is_degenerate_triangle(a, b, c),
                is_degenerate_polygon([a, b, c]),
                "{a:?} {b:?} {c:?}"
            );
            // The same triangle with a corner repeated or split along an edge is a quad.
            for quad in [[a, b, c, c], [a, b, c, a], [a, mid(a, b), b, c]] {
                let [p, q, r, s] = quad;
                assert_eq!(
                    is_degenerate_quad(p, q, r, s),
                    is_degenerate_polygon(quad),
                    "{quad:?}"
                );
            }
        }
        assert!(!is_degenerate_quad(a, b, c, d));
        assert!(is_degenerate_quad(a, b, a, b), "a bowtie folded flat");
        // The tolerance is relative to the triangle's size, not to its distance from the origin.
        let far = |x: f64| [1e6 + x, 1e6 + 2.0 * x, 1e6 + 3.0 * x];
        assert!(is_degenerate_triangle(far(0.0), far(0.25), far(0.5)));
        assert!(!is_degenerate_triangle(
            far(0.0),
            far(0.25),
            [1e6, 1e6 + 1.0, 1e6]
        ));
    }

    /// Faces at 1e-300 and 1e300 are judged as at unit size: their squares under- or overflow,
    /// which alone would call every one of them degenerate.
    #[test]
    fn extreme_magnitudes_are_judged_at_unit_size() {
        for scale in [1e-300, 1e-160, 1e160, 1e300] {
            let s = |p: [f64; 3]| p.map(|x| x * scale);
            let (a, b, c, d) = (
                s([0.0, 0.0, 0.0]),
                s([1.0, 0.0, 0.0]),
                s([1.0, 1.0, 0.0]),
                s([0.0, 1.0, 0.0]),
            );
            assert!(!is_degenerate_triangle(a, b, c), "{scale}");
            assert!(!is_degenerate_quad(a, b, c, d), "{scale}");
            assert!(
                !is_degenerate_polygon([a, b, c, d, s([-0.5, 0.5, 0.0])]),
                "{scale}"
            );
            let on_line = s([2.0, 0.0, 0.0]);
            assert!(is_degenerate_triangle(a, b, on_line), "{scale}");
            assert!(is_degenerate_quad(a, b, on_line, b), "{scale}");
            assert!(
                is_degenerate_polygon([a, b, on_line, s([3.0, 0.0, 0.0]), b]),
                "{scale}"
            );
        }
    }
}
