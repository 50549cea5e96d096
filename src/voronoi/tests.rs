//! Unit tests of the Delaunay triangulation (exactness checks shared with the Voronoi tests).

use super::predicates::incircle;
use super::*;

/// Deterministic pseudo-random points in the unit square.
pub(crate) fn random_points(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut state = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n).map(|_| [next(), next()]).collect()
}

/// Checks the structure and the exact empty-circle property against every site (small inputs)
/// or against the neighbouring triangles' apexes (large inputs, which is equivalent).
pub(crate) fn check_delaunay(d: &Delaunay, against_all: bool) {
    let tri = d.triangles();
    for e in 0..tri.len() as u32 {
        let t = d.twin(e);
        if t != INVALID {
            assert_eq!(d.twin(t), e);
            assert_eq!(d.origin(t), d.origin(d.next(e)));
            assert_eq!(d.origin(d.next(t)), d.origin(e));
        }
    }
    for t in 0..d.n_triangles() {
        let [a, b, c] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
        assert!(
            d.orient(a, b, c) > 0.0,
            "triangle {t} is not counter-clockwise"
        );
        let (pa, pb, pc) = (d.scaled_point(a), d.scaled_point(b), d.scaled_point(c));
        if against_all {
            for s in 0..d.n_sites() as u32 {
                if d.representative()[s as usize] == s {
                    assert!(
                        incircle(pa, pb, pc, d.scaled_point(s)) <= 0.0,
                        "site {s} inside circle of {t}"
                    );
                }
            }
        } else {
            for e in 3 * t..3 * t + 3 {
                let o = d.twin(e as u32);
                if o != INVALID {
                    let apex = d.origin(d.prev(o));
                    assert!(
                        incircle(pa, pb, pc, d.scaled_point(apex)) <= 0.0,
                        "edge {e} not locally Delaunay"
                    );
                }
            }
        }
    }
    // Euler: for a triangulated convex region, T = 2n - h - 2 (h counts hull vertices).
    if d.dimension() == Dimension::Plane {
        assert_eq!(d.n_triangles(), 2 * d.n_unique_sites() - d.hull().len() - 2);
        let h = d.hull();
        for i in 0..h.len() {
            let (a, b, c) = (h[i], h[(i + 1) % h.len()], h[(i + 2) % h.len()]);
            assert!(d.orient(a, b, c) >= 0.0, "hull not convex at {b}");
        }
    }
}

#[test]
fn random_points_are_triangulated_exactly() {
    for (n, seed) in [(3, 1), (4, 2), (10, 3), (100, 4), (1000, 5)] {
        let d = Delaunay::new(&random_points(n, seed)).unwrap();
        assert_eq!(d.dimension(), Dimension::Plane);
        check_delaunay(&d, true);
    }
    let d = Delaunay::new(&random_points(50_000, 9)).unwrap();
    check_delaunay(&d, false);
}

#[test]
fn integer_grid_is_triangulated() {
    let pts: Vec<[f64; 2]> = (0..40 * 40)
        .map(|i| [(i % 40) as f64, (i / 40) as f64])
        .collect();
    let d = Delaunay::new(&pts).unwrap();
    check_delaunay(&d, true);
    assert_eq!(d.n_triangles(), 2 * 39 * 39);
}

#[test]
fn duplicates_are_merged_to_smallest_index() {
    let mut pts = random_points(200, 7);
    pts.push(pts[5]);
    pts.push(pts[5]);
    pts.insert(0, pts[10]);
    let d = Delaunay::new(&pts).unwrap();
    check_delaunay(&d, true);
    assert_eq!(d.n_unique_sites(), 200);
    let dups: Vec<(u32, u32)> = d.duplicates().collect();
    assert_eq!(dups, vec![(11, 0), (201, 6), (202, 6)]);
    assert!(
        d.triangles()
            .iter()
            .all(|&v| d.representative()[v as usize] == v)
    );
}

#[test]
fn tiny_and_collinear_inputs() {
    let d = Delaunay::new(&[]).unwrap();
    assert_eq!(
        (d.dimension(), d.n_triangles(), d.hull().len()),
        (Dimension::Empty, 0, 0)
    );
    let d = Delaunay::new(&[[1.0, 2.0], [1.0, 2.0]]).unwrap();
    assert_eq!((d.dimension(), d.hull()), (Dimension::Point, &[0u32][..]));
    let d = Delaunay::new(&[[3.0, 3.0], [1.0, 1.0], [2.0, 2.0], [1.0, 1.0]]).unwrap();
    assert_eq!(d.dimension(), Dimension::Line);
    assert_eq!(d.hull(), &[1, 2, 0]);
    assert_eq!(d.edges(), vec![(1, 2), (2, 0)]);
    assert_eq!(d.duplicates().collect::<Vec<_>>(), vec![(3, 1)]);
}

#[test]
fn non_finite_sites_are_refused() {
    assert!(matches!(
        Delaunay::new(&[[0.0, 0.0], [f64::NAN, 1.0]]),
        Err(VoronoiError::NonFiniteSite { site: 1, .. })
    ));
    assert!(matches!(
        Delaunay::new(&[[f64::INFINITY, 0.0]]),
        Err(VoronoiError::NonFiniteSite { site: 0, .. })
    ));
}

#[test]
fn circulation_visits_every_incident_triangle() {
    let d = Delaunay::new(&random_points(500, 11)).unwrap();
    let mut seen = vec![0usize; d.n_sites()];
    for v in 0..d.n_sites() as u32 {
        for e in d.outgoing(v) {
            assert_eq!(d.origin(e), v);
            seen[v as usize] += 1;
        }
    }
    let mut expected = vec![0usize; d.n_sites()];
    for &v in d.triangles() {
        expected[v as usize] += 1;
    }
    assert_eq!(seen, expected);
}
