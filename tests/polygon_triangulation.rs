//! Properties of the polygon triangulation shared by the render buffers and the half-edge
//! kernel: on random simple polygons (polyomino outlines, with straight corners, repeated
//! corners and spikes added), polygons that touch themselves (polyominoes pinched at a corner,
//! squares with holes joined to the outside by slits) and their rotations, the triangles are
//! `n − 2`, triangulate the ring of corners, and add up to the polygon's area; on simple
//! polygons none is inverted.

use std::collections::{HashMap, HashSet};

use glam::{DQuat, DVec3};
use halfwing::geom::{PolygonOutcome, triangulate_polygon};
use proptest::prelude::*;

/// Lattice points of a polygon in the plane.
type Outline = Vec<[i64; 2]>;

/// Checks that `triangles` triangulate the ring of corners `0..n`: `n − 2` triangles of distinct
/// corners, each side of the ring in one of them, each other pair of corners they join (a
/// diagonal) in two, and no two diagonals crossing as chords of the ring.
fn assert_ring_triangulation(n: usize, triangles: &[[u32; 3]]) {
    assert_eq!(triangles.len(), n - 2);
    let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
    for t in triangles {
        assert!(t[0] != t[1] && t[1] != t[2] && t[0] != t[2], "{t:?}");
        assert!(t.iter().all(|&k| (k as usize) < n), "{t:?}");
        for k in 0..3 {
            let (a, b) = (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]));
            *uses.entry((a, b)).or_default() += 1;
        }
    }
    let is_side = |(a, b): (u32, u32)| b == a + 1 || (a == 0 && b as usize == n - 1);
    for (&pair, &count) in &uses {
        assert_eq!(count, if is_side(pair) { 1 } else { 2 }, "{pair:?}");
    }
    let mut chords: Vec<(u32, u32)> = uses.into_keys().filter(|&p| !is_side(p)).collect();
    chords.sort_unstable_by(|a, b| a.0.cmp(&b.0).then(b.1.cmp(&a.1)));
    let mut open: Vec<u32> = Vec::new();
    for (a, b) in chords {
        while open.last().is_some_and(|&end| end <= a) {
            open.pop();
        }
        assert!(open.last().is_none_or(|&end| b <= end), "crossing chords");
        open.push(b);
    }
}

/// The Newell normal (twice the vector area) of a polygon.
fn newell(corners: &[[f64; 3]]) -> DVec3 {
    let p: Vec<DVec3> = corners.iter().map(|c| DVec3::from_array(*c)).collect();
    (0..p.len()).map(|i| p[i].cross(p[(i + 1) % p.len()])).sum()
}

/// Checks the triangulation of `corners` as a ring, and that its triangles' areas along the
/// polygon's normal add up to the polygon's area; returns the outcome and whether a triangle is
/// inverted (by more than rounding).
fn triangulate_and_check(corners: &[[f64; 3]]) -> (PolygonOutcome, bool) {
    let (triangles, outcome) = triangulate_polygon(corners);
    assert_ring_triangulation(corners.len(), &triangles);
    let normal = newell(corners);
    let unit = normal.normalize();
    let tolerance = 1e-9 * normal.length();
    let mut total = 0.0;
    let mut inverted = false;
    for t in &triangles {
        let p = t.map(|k| DVec3::from_array(corners[k as usize]));
        let twice_area = (p[1] - p[0]).cross(p[2] - p[0]).dot(unit);
        inverted |= twice_area < -tolerance;
        total += twice_area;
    }
    assert!(
        (total - normal.length()).abs() <= tolerance,
        "triangles cover {total}, the polygon {}",
        normal.length()
    );
    (outcome, inverted)
}

/// The outline of the polyomino made of `cells`, counter-clockwise, through every lattice point
/// on it (so with straight corners); where two cells touch only at a corner the outline turns
/// `left` or right there. `None` for a polyomino with holes (several loops).
fn polyomino_outline(cells: &HashSet<[i64; 2]>, left: bool) -> Option<Outline> {
    // Unit sides with the polyomino on their left.
    let mut out: HashMap<[i64; 2], Vec<[i64; 2]>> = HashMap::new();
    let mut sides = 0;
    for &[x, y] in cells {
        for (neighbour, from, to) in [
            ([x, y - 1], [x, y], [x + 1, y]),
            ([x + 1, y], [x + 1, y], [x + 1, y + 1]),
            ([x, y + 1], [x + 1, y + 1], [x, y + 1]),
            ([x - 1, y], [x, y + 1], [x, y]),
        ] {
            if !cells.contains(&neighbour) {
                out.entry(from).or_default().push(to);
                sides += 1;
            }
        }
    }
    let start = *out.keys().min()?;
    let (mut at, mut heading) = (start, [1, 0]);
    let mut outline = Vec::with_capacity(sides);
    let mut walked = HashSet::new();
    loop {
        outline.push(at);
        let turn = |to: &&[i64; 2]| heading[0] * (to[1] - at[1]) - heading[1] * (to[0] - at[0]);
        let choices = out[&at].iter().filter(|&&to| !walked.contains(&(at, to)));
        let to = *if left {
            choices.max_by_key(turn)?
        } else {
            choices.min_by_key(turn)?
        };
        walked.insert((at, to));
        heading = [to[0] - at[0], to[1] - at[1]];
        at = to;
        if at == start {
            break;
        }
    }
    (outline.len() == sides).then_some(outline)
}

/// A polyomino grown by a walk of `steps` (0..4: east, north, west, south).
fn polyomino(steps: &[u8]) -> HashSet<[i64; 2]> {
    let mut at = [0i64, 0];
    let mut cells = HashSet::from([at]);
    for &step in steps {
        let [dx, dy] = [[1, 0], [0, 1], [-1, 0], [0, -1]][step as usize % 4];
        at = [at[0] + dx, at[1] + dy];
        cells.insert(at);
    }
    cells
}

/// A square `[0, 40]²` with square holes, each joined to the bottom side by a slit (a side
/// walked up and back down): a polygon that touches itself along every slit. Each hole is
/// `(column, height, size)`; holes in one column are one.
fn keyhole(holes: &[(i64, i64, i64)]) -> Outline {
    let mut holes: Vec<(i64, i64, i64)> = holes
        .iter()
        .map(|&(column, height, size)| (2 + 6 * (column % 6), 2 + height % 10, 1 + size % 4))
        .collect();
    holes.sort_unstable_by_key(|hole| hole.0);
    holes.dedup_by_key(|hole| hole.0);
    let mut outline = vec![[0, 0]];
    for (x, y, s) in holes {
        // Up the slit, round the hole clockwise, back down.
        outline.extend([
            [x, 0],
            [x, y],
            [x, y + s],
            [x + s, y + s],
            [x + s, y],
            [x, y],
            [x, 0],
        ]);
    }
    outline.extend([[40, 0], [40, 40], [0, 40]]);
    outline
}

/// What is added after each corner of an outline (in units of a quarter of the side after it).
#[derive(Clone, Copy, Debug)]
enum Spice {
    Nothing,
    /// The corner again.
    Repeat,
    /// The side's midpoint: a straight corner.
    Midpoint,
    /// A spike along the side: out to the midpoint, back to a quarter, out to the midpoint.
    Spike,
}

fn spice() -> impl Strategy<Value = Spice> {
    prop_oneof![
        3 => Just(Spice::Nothing),
        1 => Just(Spice::Repeat),
        1 => Just(Spice::Midpoint),
        1 => Just(Spice::Spike),
    ]
}

/// `outline` scaled by 4 (so quarters are lattice points) with `spices` added after its corners
/// (cycled), then started at corner `start`.
fn seasoned(outline: &Outline, spices: &[Spice], start: usize) -> Outline {
    let mut out = Vec::new();
    for (i, &[x, y]) in outline.iter().enumerate() {
        let a = [4 * x, 4 * y];
        let [nx, ny] = outline[(i + 1) % outline.len()];
        let b = [4 * nx, 4 * ny];
        let at = |quarters: i64| {
            [
                a[0] + (b[0] - a[0]) * quarters / 4,
                a[1] + (b[1] - a[1]) * quarters / 4,
            ]
        };
        out.push(a);
        match spices
            .get(i % spices.len().max(1))
            .copied()
            .unwrap_or(Spice::Nothing)
        {
            Spice::Nothing => {}
            Spice::Repeat => out.push(a),
            Spice::Midpoint => out.push(at(2)),
            Spice::Spike => out.extend([at(2), at(1), at(2)]),
        }
    }
    let start = start % out.len();
    out.rotate_left(start);
    out
}

/// `outline` placed in 3D exactly: turned by `quarter_turns` quarter turns, mirrored (and
/// reversed, to keep its winding) when `mirrored`, and lying in the coordinate plane across
/// axis `across`, shifted off it.
fn placed(outline: &Outline, quarter_turns: u8, mirrored: bool, across: usize) -> Vec<[f64; 3]> {
    let mut points: Vec<[f64; 3]> = outline
        .iter()
        .map(|&[x, y]| {
            let (mut x, mut y) = (x as f64, y as f64);
            for _ in 0..quarter_turns % 4 {
                (x, y) = (-y, x);
            }
            if mirrored {
                x = -x;
            }
            let mut p = [7.0; 3];
            p[(across + 1) % 3] = x;
            p[(across + 2) % 3] = y;
            p
        })
        .collect();
    if mirrored {
        points.reverse();
    }
    points
}

/// `corners` rotated about a random axis and shifted: the coordinates are rounded, so the
/// polygon may touch or cross itself where it did not.
fn rotated(corners: &[[f64; 3]], axis: [f64; 3], angle: f64) -> Vec<[f64; 3]> {
    let axis = DVec3::from_array(axis) + DVec3::new(0.0, 0.0, 1e-3);
    let rotation = DQuat::from_axis_angle(axis.normalize(), angle);
    let shift = DVec3::new(13.0, -5.0, 2.5);
    corners
        .iter()
        .map(|c| (rotation * DVec3::from_array(*c) + shift).to_array())
        .collect()
}

/// Whether an outline comes back to a lattice point it has passed (it touches itself).
fn touches_itself(outline: &Outline) -> bool {
    let mut seen = HashSet::new();
    !outline.iter().all(|p| seen.insert(*p))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Polyomino outlines without holes, simple or pinched at corners, seasoned with straight
    /// corners, repeats and spikes, placed exactly in any plane: a ring triangulation of their
    /// area; on simple ones, and wherever the outcome is exact, no triangle is inverted.
    #[test]
    fn polyomino_outlines_are_triangulated_exactly(
        steps in prop::collection::vec(0u8..4, 0..40),
        left in any::<bool>(),
        spices in prop::collection::vec(spice(), 1..12),
        start in 0usize..1000,
        quarter_turns in 0u8..4,
        mirrored in any::<bool>(),
        across in 0usize..3,
    ) {
        let outline = polyomino_outline(&polyomino(&steps), left);
        prop_assume!(outline.is_some());
        let outline = outline.unwrap();
        let corners = placed(&seasoned(&outline, &spices, start), quarter_turns, mirrored, across);
        let (outcome, inverted) = triangulate_and_check(&corners);
        if !touches_itself(&outline) {
            prop_assert_eq!(outcome, PolygonOutcome::Exact);
        }
        prop_assert_eq!(inverted, outcome != PolygonOutcome::Exact);
    }

    /// Squares with holes joined by slits, seasoned: a ring triangulation of their area, none
    /// inverted when the outcome is exact.
    #[test]
    fn keyholes_are_triangulated_as_rings(
        holes in prop::collection::vec((0i64..6, 0i64..10, 0i64..4), 1..6),
        spices in prop::collection::vec(spice(), 1..12),
        start in 0usize..1000,
        quarter_turns in 0u8..4,
        mirrored in any::<bool>(),
        across in 0usize..3,
    ) {
        let outline = keyhole(&holes);
        let corners = placed(&seasoned(&outline, &spices, start), quarter_turns, mirrored, across);
        let (outcome, inverted) = triangulate_and_check(&corners);
        prop_assert_eq!(inverted, outcome != PolygonOutcome::Exact);
    }

    /// Any of the above turned about a random axis (rounded coordinates): still a ring
    /// triangulation of the polygon's area, none inverted when the outcome is exact.
    #[test]
    fn rotated_polygons_are_triangulated_as_rings(
        steps in prop::collection::vec(0u8..4, 0..40),
        holes in prop::collection::vec((0i64..6, 0i64..10, 0i64..4), 1..6),
        keyholed in any::<bool>(),
        spices in prop::collection::vec(spice(), 1..12),
        start in 0usize..1000,
        axis in prop::array::uniform3(-1.0f64..1.0),
        angle in -3.0f64..3.0,
    ) {
        let outline = if keyholed { Some(keyhole(&holes)) } else { polyomino_outline(&polyomino(&steps), true) };
        prop_assume!(outline.is_some());
        let corners = placed(&seasoned(&outline.unwrap(), &spices, start), 0, false, 2);
        let (outcome, inverted) = triangulate_and_check(&rotated(&corners, axis, angle));
        prop_assert!(!inverted || outcome != PolygonOutcome::Exact);
    }
}

/// How often polygons that touch themselves come out exact: over a fixed sample of seasoned
/// keyholes and pinched polyominoes in every exact placement, each outcome that is not exact
/// is a reported fallback (the touching could not be followed); they must stay rare.
#[test]
fn polygons_that_touch_themselves_are_mostly_exact() {
    let mut state = 2024u64;
    let mut next = |n: u64| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 33) % n) as i64
    };
    let spices = [
        Spice::Nothing,
        Spice::Nothing,
        Spice::Repeat,
        Spice::Midpoint,
        Spice::Spike,
    ];
    let (mut exact, mut total) = (0, 0);
    while total < 4000 {
        let outline = if total % 2 == 0 {
            let holes: Vec<_> = (0..1 + next(5))
                .map(|_| (next(6), next(10), next(4)))
                .collect();
            keyhole(&holes)
        } else {
            let steps: Vec<u8> = (0..next(40)).map(|_| next(4) as u8).collect();
            match polyomino_outline(&polyomino(&steps), next(2) == 0) {
                Some(outline) if touches_itself(&outline) => outline,
                _ => continue,
            }
        };
        let seasoning: Vec<Spice> = (0..12).map(|_| spices[next(5) as usize]).collect();
        let seasoned = seasoned(&outline, &seasoning, next(1000) as usize);
        let corners = placed(&seasoned, next(4) as u8, next(2) == 0, next(3) as usize);
        let (outcome, _) = triangulate_and_check(&corners);
        exact += usize::from(outcome == PolygonOutcome::Exact);
        total += 1;
    }
    println!("{exact} of {total} polygons that touch themselves exact");
    assert!(exact * 100 >= total * 99, "{exact} of {total} exact");
}
