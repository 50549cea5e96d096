//! Exact intersection tests of two closed, non-degenerate triangles, allowing for the vertices
//! they share: they *meet* when they have a point in common other than on their shared vertex or
//! shared edge.
//!
//! Every decision is the sign of an orientation determinant ([`ExactOrientation`]). Coplanar
//! configurations are decided in the projection on the coordinate plane where the triangles'
//! normal has its largest component: dropping a coordinate is exact, and that projection maps
//! their plane one to one.

use super::exact_orientation::{ExactOrientation, ExponentRange, Point, Sign, scale_points};
use super::plane_side::TrianglePlane;

/// Which corners two triangles share, by vertex identity (not by position).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SharedCorners {
    /// No common vertex.
    None,
    /// Corner `first[i]` is corner `second[j]`: `(i, j)`.
    Vertex(usize, usize),
    /// Corners `first[i]` and `first[(i + 1) % 3]` are corners of `second`, whose third corner
    /// is `second[k]`: `(i, k)`.
    Edge(usize, usize),
    /// The same three vertices.
    All,
}

impl SharedCorners {
    /// The corners shared by triangles with vertex ids `first` and `second`, each three distinct
    /// ids.
    pub(crate) fn of(first: [u32; 3], second: [u32; 3]) -> SharedCorners {
        let mut matches = [(0, 0); 3];
        let mut count = 0;
        for (i, &v) in first.iter().enumerate() {
            if let Some(j) = second.iter().position(|&w| w == v) {
                matches[count] = (i, j);
                count += 1;
            }
        }
        match count {
            0 => SharedCorners::None,
            1 => SharedCorners::Vertex(matches[0].0, matches[0].1),
            2 => {
                let [(i0, j0), (i1, j1), _] = matches;
                // The first triangle's edge from corner i0 to i1, or from i1 round to i0.
                let start = if i1 == i0 + 1 { i0 } else { i1 };
                SharedCorners::Edge(start, 3 - j0 - j1)
            }
            _ => SharedCorners::All,
        }
    }
}

/// Do the closed triangles `a` and `b` (neither degenerate) have a point in common besides
/// their shared corners (`shared`) and the edge between two shared corners?
///
/// - no shared corner: any common point counts, touching included;
/// - one shared vertex: a common point other than that vertex;
/// - a shared edge: the triangles overlap, which they do only when coplanar with their third
///   corners on the same side of the edge;
/// - all three corners: they are the same triangle, which overlaps itself.
pub(crate) fn triangles_meet(
    arithmetic: ExactOrientation,
    a: &[Point; 3],
    b: &[Point; 3],
    shared: SharedCorners,
) -> bool {
    match shared {
        SharedCorners::None => disjoint_triangles_meet(arithmetic, a, b),
        SharedCorners::Vertex(i, j) => triangles_at_a_vertex_meet(arithmetic, a, i, b, j),
        SharedCorners::Edge(i, k) => {
            let (p, q, r, s) = (a[i], a[(i + 1) % 3], a[(i + 2) % 3], b[k]);
            TrianglePlane::new(a).side(arithmetic, s) == Sign::Zero && {
                let axis = projection_axis(arithmetic, a);
                let [p, q, r, s] = [p, q, r, s].map(|x| project(x, axis));
                arithmetic.orient2d(p, q, r) == arithmetic.orient2d(p, q, s)
            }
        }
        SharedCorners::All => true,
    }
}

/// Whether the triangle at `points`, whose coordinates (finite) have the exponent range
/// `exponents`, is degenerate: its corners collinear, decided exactly.
pub(crate) fn is_degenerate_exactly(points: [Point; 3], exponents: ExponentRange) -> bool {
    let mut exact_points = points;
    let arithmetic = ExactOrientation::for_points(&mut exact_points, exponents);
    corners_are_collinear(arithmetic, &exact_points)
}

/// [`triangles_meet`] for two non-degenerate triangles given by their corners' vertex ids,
/// positions and coordinates' exponent ranges: the arithmetic is chosen for both, and which
/// corners they share is read from the ids.
pub(crate) fn triangles_meet_exactly(
    (first_ids, mut first, first_exponents): ([u32; 3], [Point; 3], ExponentRange),
    (second_ids, mut second, second_exponents): ([u32; 3], [Point; 3], ExponentRange),
) -> bool {
    let (arithmetic, shift) = ExactOrientation::for_range(first_exponents.union(second_exponents));
    if let Some(shift) = shift {
        scale_points(&mut first, shift);
        scale_points(&mut second, shift);
    }
    let shared = SharedCorners::of(first_ids, second_ids);
    triangles_meet(arithmetic, &first, &second, shared)
}

/// Are the corners of `t` collinear (coincident corners included): is it a degenerate triangle?
/// Exactly when its projections on the three coordinate planes are all flat, the components of
/// its normal all zero.
pub(crate) fn corners_are_collinear(arithmetic: ExactOrientation, t: &[Point; 3]) -> bool {
    (0..3).all(|axis| {
        let [p, q, r] = t.map(|x| project(x, axis));
        arithmetic.orient2d(p, q, r) == Sign::Zero
    })
}

/// Triangles with no vertex in common: any common point, touching included.
///
/// When their planes differ, the triangles meet exactly when an edge of one that crosses (or
/// touches) the other's plane passes through the other triangle: the ends of their common
/// segment lie on their edges, and an end on an edge lying in the other's plane is also on a
/// crossing edge (the next edge at a corner) or on an edge of the other triangle.
fn disjoint_triangles_meet(arithmetic: ExactOrientation, a: &[Point; 3], b: &[Point; 3]) -> bool {
    let plane_of_b = TrianglePlane::new(b);
    let sides_of_a = a.map(|p| plane_of_b.side(arithmetic, p));
    if strictly_one_side(sides_of_a) {
        return false;
    }
    if sides_of_a == [Sign::Zero; 3] {
        return coplanar_triangles_meet(arithmetic, a, b);
    }
    let plane_of_a = TrianglePlane::new(a);
    let sides_of_b = b.map(|p| plane_of_a.side(arithmetic, p));
    if strictly_one_side(sides_of_b) {
        return false;
    }
    crossing_edge_passes_through(arithmetic, a, sides_of_a, b)
        || crossing_edge_passes_through(arithmetic, b, sides_of_b, a)
}

/// Does an edge of `a` that crosses or touches the plane of `b` (without lying in it; `sides`
/// gives each corner's side of that plane) pass through `b`?
fn crossing_edge_passes_through(
    arithmetic: ExactOrientation,
    a: &[Point; 3],
    sides: [Sign; 3],
    b: &[Point; 3],
) -> bool {
    (0..3).any(|i| {
        let j = (i + 1) % 3;
        // Different sides (one of them possibly on the plane): the edge meets the plane once.
        sides[i] != sides[j] && line_passes_through(arithmetic, a[i], a[j], b)
    })
}

/// Triangles sharing one vertex, corner `i` of `a` and corner `j` of `b`: a common point
/// besides that vertex?
///
/// Beyond the shared vertex, a common point lies on the far edge (opposite the vertex) of one
/// of the triangles: follow the ray from the vertex through it to where it leaves them. And
/// when a far edge lies strictly on one side of the other triangle's plane, so does all of its
/// triangle but the vertex, which is then all they have in common.
fn triangles_at_a_vertex_meet(
    arithmetic: ExactOrientation,
    a: &[Point; 3],
    i: usize,
    b: &[Point; 3],
    j: usize,
) -> bool {
    let far_a = [a[(i + 1) % 3], a[(i + 2) % 3]];
    let far_b = [b[(j + 1) % 3], b[(j + 2) % 3]];
    let plane_of_b = TrianglePlane::new(b);
    let sides_a = far_a.map(|p| plane_of_b.side(arithmetic, p));
    if sides_a[0] == sides_a[1] && sides_a[0] != Sign::Zero {
        return false;
    }
    let plane_of_a = TrianglePlane::new(a);
    let sides_b = far_b.map(|p| plane_of_a.side(arithmetic, p));
    if sides_b[0] == sides_b[1] && sides_b[0] != Sign::Zero {
        return false;
    }
    if sides_a == [Sign::Zero; 2] {
        // `a` lies in the plane of `b` (its third corner is the shared vertex).
        let axis = projection_axis(arithmetic, a);
        let flat = |t: &[Point; 3]| t.map(|p| project(p, axis));
        let flat_edge = |e: [Point; 2]| e.map(|p| project(p, axis));
        return segment_meets_triangle_2d(arithmetic, flat_edge(far_a), flat(b))
            || segment_meets_triangle_2d(arithmetic, flat_edge(far_b), flat(a));
    }
    // Neither is in the other's plane: each far edge crosses or touches the other's plane once.
    line_passes_through(arithmetic, far_a[0], far_a[1], b)
        || line_passes_through(arithmetic, far_b[0], far_b[1], a)
}

/// Does the line through `p` and `q`, which crosses the plane of triangle `t` once, cross it in
/// the closed triangle? The volumes spanned by the line and each edge of `t` have the sign of
/// the area spanned by the crossing point and that edge, times one factor for all three; the
/// areas add up to the triangle's, so the point is inside exactly when no two have opposite
/// signs.
fn line_passes_through(arithmetic: ExactOrientation, p: Point, q: Point, t: &[Point; 3]) -> bool {
    let sides = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| arithmetic.orient3d(p, q, t[i], t[j]));
    !has_both_signs(sides)
}

/// Coplanar triangles meet when a corner of one lies in the other or two of their edges meet.
fn coplanar_triangles_meet(arithmetic: ExactOrientation, a: &[Point; 3], b: &[Point; 3]) -> bool {
    let axis = projection_axis(arithmetic, a);
    let a = a.map(|p| project(p, axis));
    let b = b.map(|p| project(p, axis));
    a.iter().any(|&p| point_in_triangle_2d(arithmetic, p, b))
        || b.iter().any(|&p| point_in_triangle_2d(arithmetic, p, a))
        || (0..3).any(|i| {
            let edge = [a[i], a[(i + 1) % 3]];
            (0..3).any(|j| segments_meet_2d(arithmetic, edge, [b[j], b[(j + 1) % 3]]))
        })
}

/// The coordinate to drop so that the plane of triangle `t` (not degenerate) projects one to
/// one: the largest component of its normal, as estimated in floating point, unless the exact
/// test finds that projection flat (then the next largest, and so on).
fn projection_axis(arithmetic: ExactOrientation, t: &[Point; 3]) -> usize {
    let (u, v) = (difference(t[1], t[0]), difference(t[2], t[0]));
    let normal = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    // NaN (an overflowed estimate) sorts as the largest under total_cmp; the exact check below
    // corrects any wrong preference.
    let mut axes = [0, 1, 2];
    axes.sort_by(|&i, &j| normal[j].abs().total_cmp(&normal[i].abs()));
    axes.into_iter()
        .find(|&axis| {
            let [p, q, r] = t.map(|x| project(x, axis));
            arithmetic.orient2d(p, q, r) != Sign::Zero
        })
        .unwrap_or(axes[0])
}

/// `p` without coordinate `axis`.
#[inline]
pub(crate) fn project(p: Point, axis: usize) -> [f64; 2] {
    match axis {
        0 => [p[1], p[2]],
        1 => [p[2], p[0]],
        _ => [p[0], p[1]],
    }
}

fn difference(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// All three strictly on the same side.
fn strictly_one_side(sides: [Sign; 3]) -> bool {
    sides[0] != Sign::Zero && sides[0] == sides[1] && sides[1] == sides[2]
}

fn has_both_signs(signs: [Sign; 3]) -> bool {
    signs.contains(&Sign::Positive) && signs.contains(&Sign::Negative)
}

/// Is `x` in the closed triangle `t` (not degenerate), whatever its orientation? `x` is inside
/// when it is on the inner side of, or on, each edge's line, and the three signed areas it spans
/// with the edges add up to the triangle's, so it is outside exactly when two have opposite
/// signs.
fn point_in_triangle_2d(arithmetic: ExactOrientation, x: [f64; 2], t: [[f64; 2]; 3]) -> bool {
    let sides = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| arithmetic.orient2d(t[i], t[j], x));
    !has_both_signs(sides)
}

/// Does the closed segment `[p, q]` meet the closed triangle `t`, both in the plane?
fn segment_meets_triangle_2d(
    arithmetic: ExactOrientation,
    [p, q]: [[f64; 2]; 2],
    t: [[f64; 2]; 3],
) -> bool {
    point_in_triangle_2d(arithmetic, p, t)
        || point_in_triangle_2d(arithmetic, q, t)
        || (0..3).any(|i| segments_meet_2d(arithmetic, [p, q], [t[i], t[(i + 1) % 3]]))
}

/// Do the closed segments `[p, q]` and `[r, s]` (each of two distinct points) meet?
fn segments_meet_2d(
    arithmetic: ExactOrientation,
    [p, q]: [[f64; 2]; 2],
    [r, s]: [[f64; 2]; 2],
) -> bool {
    let (side_r, side_s) = (arithmetic.orient2d(p, q, r), arithmetic.orient2d(p, q, s));
    if side_r == Sign::Zero && side_s == Sign::Zero {
        // On one line: compare their extents along a coordinate that varies along it.
        let k = usize::from(p[0] == q[0]);
        let extent = |u: f64, v: f64| (u.min(v), u.max(v));
        let (first, second) = (extent(p[k], q[k]), extent(r[k], s[k]));
        return first.0 <= second.1 && second.0 <= first.1;
    }
    if side_r == side_s {
        return false;
    }
    // Not both zero, or r and s would be on the line through p and q.
    arithmetic.orient2d(r, s, p) != arithmetic.orient2d(r, s, q)
}

#[cfg(test)]
mod tests {
    use super::*;

    const ADAPTIVE: ExactOrientation = ExactOrientation::Adaptive;

    #[test]
    fn shared_corners_are_found_in_any_rotation() {
        assert_eq!(SharedCorners::of([0, 1, 2], [3, 4, 5]), SharedCorners::None);
        assert_eq!(
            SharedCorners::of([0, 1, 2], [5, 2, 4]),
            SharedCorners::Vertex(2, 1)
        );
        // Edge 1 → 2 of the first; the second's third corner is 7, at index 0.
        assert_eq!(
            SharedCorners::of([0, 1, 2], [7, 2, 1]),
            SharedCorners::Edge(1, 0)
        );
        // Edge 2 → 0 (wrapping round) of the first.
        assert_eq!(
            SharedCorners::of([0, 1, 2], [0, 9, 2]),
            SharedCorners::Edge(2, 1)
        );
        assert_eq!(
            SharedCorners::of([0, 1, 2], [1, 0, 9]),
            SharedCorners::Edge(0, 2)
        );
        assert_eq!(SharedCorners::of([0, 1, 2], [2, 0, 1]), SharedCorners::All);
    }

    #[test]
    fn collinear_segments_meet_by_their_extents() {
        let meet = |a: [[f64; 2]; 2], b: [[f64; 2]; 2]| segments_meet_2d(ADAPTIVE, a, b);
        assert!(
            meet([[0.0, 0.0], [2.0, 2.0]], [[2.0, 2.0], [3.0, 3.0]]),
            "touching ends"
        );
        assert!(!meet([[0.0, 0.0], [2.0, 2.0]], [[2.5, 2.5], [3.0, 3.0]]));
        assert!(
            meet([[0.0, 0.0], [0.0, 4.0]], [[0.0, 3.0], [0.0, 1.0]]),
            "vertical, nested"
        );
        assert!(!meet([[0.0, 0.0], [0.0, 4.0]], [[0.0, 5.0], [0.0, 6.0]]));
        assert!(
            meet([[0.0, 0.0], [2.0, 0.0]], [[1.0, 0.0], [1.0, 5.0]]),
            "T"
        );
        assert!(!meet([[0.0, 0.0], [2.0, 0.0]], [[3.0, 0.0], [3.0, 5.0]]));
        assert!(
            meet([[0.0, 0.0], [2.0, 2.0]], [[0.0, 2.0], [2.0, 0.0]]),
            "crossing"
        );
    }

    /// A triangle against a second one sharing its corner at the origin, whose far edge is
    /// `[p, q]`.
    #[test]
    fn triangles_at_a_vertex_meet_where_a_far_edge_reaches_the_other() {
        let t = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]];
        let meets = |p: Point, q: Point| {
            let other = [t[0], p, q];
            let forward = triangles_meet(ADAPTIVE, &t, &other, SharedCorners::Vertex(0, 0));
            let backward = triangles_meet(ADAPTIVE, &other, &t, SharedCorners::Vertex(0, 0));
            assert_eq!(forward, backward, "{p:?} {q:?}");
            forward
        };
        assert!(
            meets([-1.0, 1.0, 0.0], [1.0, 1.0, 0.0]),
            "coplanar, overlapping"
        );
        assert!(
            !meets([-1.0, 1.0, 0.0], [-1.0, -1.0, 0.0]),
            "coplanar, apart"
        );
        assert!(meets([1.0, 1.0, -1.0], [1.0, 1.0, 1.0]), "piercing");
        assert!(meets([1.0, 1.0, 0.0], [1.0, 1.0, 1.0]), "standing on it");
        assert!(!meets([1.0, 1.0, 1e-300], [1.0, 1.0, 1.0]), "hovering");
        assert!(
            meets([4.0, 0.0, -1.0], [4.0, 0.0, 1.0]),
            "along an edge, to a corner"
        );
        assert!(
            meets([5.0, 0.0, -1.0], [5.0, 0.0, 1.0]),
            "along an edge, beyond it"
        );
        assert!(
            !meets([5.0, -1.0, -1.0], [5.0, -1.0, 1.0]),
            "beside an edge"
        );
        // Both far edges cross the other's plane, on opposite sides of the shared vertex.
        assert!(
            !meets([-1.0, -1.0, -1.0], [-1.0, -1.0, 1.0]),
            "crossing the planes' line"
        );
    }
}
