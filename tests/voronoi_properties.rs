//! Property tests: random (and deliberately degenerate) site sets always give an exact Delaunay
//! triangulation, a consistent Voronoi DCEL, and clipped cells that tile the region.

mod voronoi_common;

use halfwing::voronoi::{ClipPolygon, Delaunay, Metric, SiteId, Voronoi};
use proptest::prelude::*;
use voronoi_common::*;

/// Sites from a small integer lattice (many duplicates, collinear and cocircular subsets) or
/// arbitrary floats, mixed.
fn sites() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop_oneof![
        prop::collection::vec(
            (0i32..8, 0i32..8).prop_map(|(x, y)| [x as f64, y as f64]),
            0..60
        ),
        prop::collection::vec(
            (-1e3f64..1e3, -1e3f64..1e3).prop_map(|(x, y)| [x, y]),
            0..120
        ),
        prop::collection::vec(
            (0i32..4, -1e-3f64..1e-3).prop_map(|(x, y)| [x as f64, y]),
            0..40
        ),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn delaunay_is_exact_and_voronoi_tiles_the_clip(pts in sites()) {
        let d = Delaunay::new(&pts).unwrap();
        check_delaunay(&d, true);
        let v = Voronoi::from_delaunay(d);
        check_voronoi(&v);
        check_clipped(&v, &bounding_clip(&pts, 0.25));
        let inner = ClipPolygon::convex(&[[1.0, 1.0], [5.0, 2.0], [6.0, 6.0], [2.0, 5.0]]).unwrap();
        check_clipped(&v, &inner);
    }

    #[test]
    fn nearest_site_is_the_exact_nearest(pts in sites(), q in (-10.0f64..10.0, -10.0f64..10.0)) {
        let d = Delaunay::new(&pts).unwrap();
        let q = [q.0, q.1];
        let expected = (0..pts.len() as u32)
            .filter(|&s| d.representative()[s as usize] == s)
            .min_by(|&a, &b| Metric::Euclidean.compare(q, pts[a as usize], pts[b as usize]).then(a.cmp(&b)));
        prop_assert_eq!(d.nearest_site(q, None).unwrap(), expected.map(SiteId));
    }
}

/// Found by the property test above: the cell of (0, 5) meets the inner region only at its
/// corner (2, 5), which lies on the bisector of (0, 5) and (2, 3): it must be empty.
#[test]
fn a_cell_meeting_the_region_at_a_corner_only_is_empty() {
    let pts = [[2.0, 3.0], [3.0, 7.0], [0.0, 5.0]];
    let v = Voronoi::new(&pts).unwrap();
    check_voronoi(&v);
    check_clipped(&v, &bounding_clip(&pts, 0.25));
    let inner = ClipPolygon::convex(&[[1.0, 1.0], [5.0, 2.0], [6.0, 6.0], [2.0, 5.0]]).unwrap();
    check_clipped(&v, &inner);
}
