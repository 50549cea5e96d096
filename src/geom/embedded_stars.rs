//! Vertices whose star — the triangles around them — provably does not intersect itself, so that
//! the self-intersection search can settle every pair of triangles meeting there without a test.
//!
//! On a mesh, most pairs of triangles with overlapping boxes share a vertex or an edge (on a
//! smooth triangulated surface, about fourteen pairs per vertex against one pair sharing
//! nothing), and each pair costs several orientation tests. One pass over the stars replaces
//! them: a star is *embedded* when it projects one to one on a coordinate plane, which is
//! decided exactly with a handful of 2D orientation signs per vertex.
//!
//! Why it suffices: let triangles `A` and `B` of the star of `v` share `v` or an edge at `v`,
//! and let the star's projection be one to one. Two triangles of such a projection overlap only
//! where they share a vertex or an edge; a common point `p` of `A` and `B` projects into that
//! shared part, and since the projection of `A` is one to one, `p` is the point of `A` above it,
//! which lies on the shared part. So `A` and `B` do not *meet* in the sense of
//! [`triangles_meet`](super::triangle_intersection::triangles_meet).

use super::exact_orientation::{ExactOrientation, ExponentRange, Point, Sign};
use super::parallel::map_indexed;
use super::triangle_intersection::project;

/// Stars of more triangles are not examined (their pairs are tested one by one): the closed-fan
/// check below is quadratic in the star's size.
const LARGEST_STAR: usize = 24;
const _: () = assert!(LARGEST_STAR <= 32, "a star's triangles are flags of a u32");

/// A triangle for the star pass: corner vertex ids and the exponent range of its coordinates.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StarTriangle {
    pub(crate) corners: [u32; 3],
    pub(crate) exponents: ExponentRange,
}

/// For each vertex id below `positions.len()`, whether its star among the `count` triangles
/// `triangle(0..count)` (each with three distinct corners below that, and with area) is
/// embedded: the triangles around it form one closed, consistently oriented fan whose projection
/// on a coordinate plane winds once around it, every triangle keeping its orientation there.
/// `false` is always a safe answer; it is given for open fans, pinched vertices, folds, large
/// stars and coordinates outside the adaptive arithmetic's range.
pub(crate) fn embedded_stars(
    positions: &[Point],
    count: usize,
    triangle: impl Fn(usize) -> StarTriangle + Sync,
) -> Vec<bool> {
    let stars = StarIndex::new(positions.len(), count, &triangle);
    map_indexed(positions.len(), |v| {
        let star = stars.star(v);
        (3..=LARGEST_STAR).contains(&star.len())
            && star_is_embedded(positions, &triangle, v as u32, star)
    })
}

/// The triangles around each vertex, in compressed rows.
struct StarIndex {
    /// Row `v` is `triangles[offsets[v]..offsets[v + 1]]`.
    offsets: Vec<u32>,
    triangles: Vec<u32>,
}

impl StarIndex {
    fn new(
        vertex_count: usize,
        count: usize,
        triangle: impl Fn(usize) -> StarTriangle,
    ) -> StarIndex {
        let mut offsets = vec![0u32; vertex_count + 1];
        for t in 0..count {
            for v in triangle(t).corners {
                offsets[v as usize + 1] += 1;
            }
        }
        for v in 0..vertex_count {
            offsets[v + 1] += offsets[v];
        }
        let mut next = offsets.clone();
        let mut members = vec![0u32; offsets[vertex_count] as usize];
        for t in 0..count {
            for v in triangle(t).corners {
                let slot = &mut next[v as usize];
                members[*slot as usize] = t as u32;
                *slot += 1;
            }
        }
        StarIndex {
            offsets,
            triangles: members,
        }
    }

    fn star(&self, v: usize) -> &[u32] {
        &self.triangles[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }
}

/// Is the star of `v` (`star`: indices into `triangles`, at least three) embedded?
fn star_is_embedded(
    positions: &[Point],
    triangle: impl Fn(usize) -> StarTriangle,
    v: u32,
    star: &[u32],
) -> bool {
    // Each triangle as its two other corners, in its own turning order from `v`: (a, b) for
    // the triangle (v, a, b).
    let mut spokes = [(0u32, 0u32); LARGEST_STAR];
    let mut exponents = ExponentRange::EMPTY;
    for (slot, &t) in spokes.iter_mut().zip(star) {
        let triangle = triangle(t as usize);
        let [c0, c1, c2] = triangle.corners;
        *slot = if c0 == v {
            (c1, c2)
        } else if c1 == v {
            (c2, c0)
        } else {
            (c0, c1)
        };
        exponents = exponents.union(triangle.exponents);
    }
    let spokes = &spokes[..star.len()];
    // Orientation signs on the points as given: outside the adaptive range (scaling or integer
    // arithmetic needed), the star is left to the pair tests.
    if ExactOrientation::for_range(exponents) != (ExactOrientation::Adaptive, None) {
        return false;
    }
    closed_fan_successors(spokes).is_some_and(|next| winds_once(positions, v, spokes, &next))
}

/// For each triangle `(v, a, b)`, the triangle `(v, b, c)` that follows it round the vertex,
/// when every far corner starts exactly one triangle and ends exactly one: then each edge at the
/// vertex has one triangle on either side, running it in opposite directions, and the triangles
/// form closed fans (one or more).
fn closed_fan_successors(spokes: &[(u32, u32)]) -> Option<[u8; LARGEST_STAR]> {
    let mut next = [0u8; LARGEST_STAR];
    let mut ended = 0u32;
    for (i, &(a, b)) in spokes.iter().enumerate() {
        if spokes[i + 1..].iter().any(|&(other, _)| other == a) {
            return None;
        }
        // Starts are distinct, so at most one triangle starts at `b`.
        let j = spokes.iter().position(|&(c, _)| c == b)?;
        if ended & (1 << j) != 0 {
            return None;
        }
        ended |= 1 << j;
        next[i] = j as u8;
    }
    Some(next)
}

/// Does the projection of the fans around `v` on the coordinate plane facing their mean normal
/// keep every triangle's orientation and wind once around `v`? `next` links each triangle to the
/// one that follows it.
///
/// Every triangle then covers a sector of less than half a turn, all turning the same way, and
/// closed fans of such sectors cover each direction from `v` as many times as they wind around
/// it: once exactly when they tile the directions around `v`, each once. The count is taken in
/// the direction of the first spoke, each sector counted from its start, exclusive of its end.
fn winds_once(
    positions: &[Point],
    v: u32,
    spokes: &[(u32, u32)],
    next: &[u8; LARGEST_STAR],
) -> bool {
    let at = |w: u32| positions[w as usize];
    let centre = at(v);
    let mut normal = [0.0; 3];
    for &(a, b) in spokes {
        let (u, w) = (difference(at(a), centre), difference(at(b), centre));
        normal[0] += u[1] * w[2] - u[2] * w[1];
        normal[1] += u[2] * w[0] - u[0] * w[2];
        normal[2] += u[0] * w[1] - u[1] * w[0];
    }
    let axis = (0..3)
        .max_by(|&i, &j| normal[i].abs().total_cmp(&normal[j].abs()))
        .unwrap_or(2);
    // Projections keep or reverse every orientation together; which one is the normal's sign.
    let turning = match normal[axis] {
        n if n > 0.0 => Sign::Positive,
        n if n < 0.0 => Sign::Negative,
        _ => return false,
    };
    let flat = |w: u32| project(at(w), axis);
    let orient = |p, q, r| ExactOrientation::Adaptive.orient2d(p, q, r);
    let (o, x) = (flat(v), flat(spokes[0].0));
    // The side of the first spoke's line on which each spoke lies: a sector's start is spoke
    // `a` of its triangle, its end spoke `a` of the next.
    let mut sides = [Sign::Zero; LARGEST_STAR];
    for (side, &(a, _)) in sides.iter_mut().zip(spokes) {
        *side = orient(o, flat(a), x);
    }
    let mut covering = 0;
    for (i, &(a, b)) in spokes.iter().enumerate() {
        if orient(o, flat(a), flat(b)) != turning {
            return false;
        }
        let j = usize::from(next[i]);
        let from_start = sides[i];
        let to_end = opposite(sides[j]);
        if (from_start == Sign::Zero && i != 0) || (to_end == Sign::Zero && j != 0) {
            // A spoke on the first spoke's line (never both: the sector has area). It points
            // the first spoke's way when the sector's other side turns as the sector does,
            // and then two spokes overlap: give up. Pointing the other way, it is half a turn
            // from the first spoke, and a sector of less than that cannot hold it.
            if from_start == turning || to_end == turning {
                return false;
            }
            continue;
        }
        if (from_start == turning || i == 0) && to_end == turning {
            covering += 1;
        }
    }
    covering == 1
}

fn opposite(sign: Sign) -> Sign {
    match sign {
        Sign::Negative => Sign::Positive,
        Sign::Zero => Sign::Zero,
        Sign::Positive => Sign::Negative,
    }
}

fn difference(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn star_triangles(positions: &[Point], triangles: &[[u32; 3]]) -> Vec<StarTriangle> {
        triangles
            .iter()
            .map(|&corners| StarTriangle {
                corners,
                exponents: ExponentRange::of(
                    corners
                        .iter()
                        .flat_map(|&v| positions[v as usize])
                        .collect::<Vec<_>>(),
                ),
            })
            .collect()
    }

    /// A pyramid's apex over a square: 4 triangles round vertex 0, closed.
    fn apex(height: f64) -> (Vec<Point>, Vec<[u32; 3]>) {
        let positions = vec![
            [0.0, 0.0, height],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
        ];
        let triangles = vec![[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]];
        (positions, triangles)
    }

    fn embedded_at(positions: &[Point], triangles: &[[u32; 3]], v: usize) -> bool {
        let triangles = star_triangles(positions, triangles);
        embedded_stars(positions, triangles.len(), |t| triangles[t])[v]
    }

    #[test]
    fn a_closed_fan_that_projects_one_to_one_is_embedded() {
        for height in [1.0, 0.0, -1.0, 1e-12] {
            let (positions, triangles) = apex(height);
            assert!(embedded_at(&positions, &triangles, 0), "{height}");
        }
    }

    #[test]
    fn open_and_reoriented_fans_are_not() {
        let (positions, mut triangles) = apex(1.0);
        triangles.pop();
        assert!(!embedded_at(&positions, &triangles, 0), "open");
        let (positions, mut triangles) = apex(1.0);
        triangles[1] = [0, 3, 2];
        assert!(!embedded_at(&positions, &triangles, 0), "one face flipped");
        // Every spoke starts one triangle, but spoke 2 ends two (one twice, both ways round).
        let (positions, _) = apex(1.0);
        let triangles = [[0, 1, 2], [0, 2, 3], [0, 3, 2]];
        assert!(
            !embedded_at(&positions, &triangles, 0),
            "two ends at one spoke"
        );
    }

    #[test]
    fn a_fan_winding_twice_is_not() {
        // Eight quarter turns round vertex 0: the square's spokes twice, one floor apart.
        let mut positions = vec![[0.0, 0.0, 0.0]];
        for floor in [0.0, 1.0] {
            for (x, y) in [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)] {
                positions.push([x, y, floor]);
            }
        }
        let triangles: Vec<[u32; 3]> = (0..8).map(|i| [0, 1 + i, 1 + (i + 1) % 8]).collect();
        assert!(!embedded_at(&positions, &triangles, 0));
    }

    #[test]
    fn a_folded_fan_is_not() {
        // A spoke pushed across its neighbour: one triangle turns the other way in projection.
        let (mut positions, triangles) = apex(0.1);
        positions[2] = [1.0, -0.2, 0.0];
        assert!(!embedded_at(&positions, &triangles, 0));
    }

    #[test]
    fn two_fans_at_a_pinched_vertex_are_not() {
        // An hourglass: a second square fan at the apex, below it and facing the other way.
        let (mut positions, mut triangles) = apex(0.0);
        for p in &mut positions[1..] {
            p[2] = 1.0;
        }
        positions.extend(positions.clone()[1..].iter().map(|p| [p[0], p[1], -1.0]));
        triangles.extend([[0, 6, 5], [0, 7, 6], [0, 8, 7], [0, 5, 8]]);
        assert!(!embedded_at(&positions, &triangles, 0));
        // The same two fans facing the same way project onto each other: wound twice.
        triangles.truncate(4);
        triangles.extend([[0, 5, 6], [0, 6, 7], [0, 7, 8], [0, 8, 5]]);
        assert!(!embedded_at(&positions, &triangles, 0));
    }

    /// Random closed fans, flat, bumpy, folded or wound twice: whenever a star is found
    /// embedded, no two of its triangles meet in the exact test.
    #[test]
    fn embedded_stars_have_no_meeting_triangles() {
        use crate::geom::triangle_intersection::{SharedCorners, triangles_meet};
        let mut next = crate::support::test_random::uniform(0x2545_f491_4f6c_dd1d);
        let (mut embedded_count, mut rejected) = (0, 0);
        for case in 0..4000 {
            let k = 3 + case % 9;
            let turns = if case % 7 == 0 { 2.0 } else { 1.0 };
            let bumps = [0.0, 0.1, 1.0, 10.0][case % 4];
            let mut positions = vec![[0.0, 0.0, 0.0]];
            for i in 0..k {
                // Spokes at increasing angles, jittered (sometimes past their neighbours).
                let angle = std::f64::consts::TAU * turns * (i as f64 + 0.9 * next()) / k as f64;
                let length = 0.2 + next();
                let height = bumps * (next() - 0.5);
                // Rounded to a grid so that exactly coplanar spokes occur too.
                let grid = |x: f64| (x * 64.0).round() / 64.0;
                positions.push([
                    grid(length * angle.cos()),
                    grid(length * angle.sin()),
                    grid(height),
                ]);
            }
            let triangles: Vec<[u32; 3]> = (0..k as u32)
                .map(|i| [0, 1 + i, 1 + (i + 1) % k as u32])
                .collect();
            if triangles.iter().any(|t| {
                let points = t.map(|v| positions[v as usize]);
                crate::geom::triangle_intersection::corners_are_collinear(
                    ExactOrientation::Adaptive,
                    &points,
                )
            }) {
                continue;
            }
            if !embedded_at(&positions, &triangles, 0) {
                rejected += 1;
                continue;
            }
            embedded_count += 1;
            for (i, a) in triangles.iter().enumerate() {
                for b in &triangles[i + 1..] {
                    let points = |t: &[u32; 3]| t.map(|v| positions[v as usize]);
                    let shared = SharedCorners::of(*a, *b);
                    assert!(
                        !triangles_meet(ExactOrientation::Adaptive, &points(a), &points(b), shared),
                        "case {case}: {a:?} and {b:?} meet in an embedded star {positions:?}"
                    );
                }
            }
        }
        assert!(
            embedded_count > 500 && rejected > 500,
            "{embedded_count} {rejected}"
        );
    }
}
