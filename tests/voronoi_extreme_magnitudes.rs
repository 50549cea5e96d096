//! Sites and clip regions whose magnitudes push products of coordinates out of the range of
//! doubles: answers stay exact (nearest sites) and cells still tile their region.

mod voronoi_common;

use halfwing::voronoi::{ClipPolygon, Voronoi};
use voronoi_common::*;

/// Every site's nearest site is itself (or the first site at the same position).
fn assert_each_site_nearest_to_itself(v: &Voronoi) {
    let d = v.delaunay();
    for (i, &p) in d.sites().iter().enumerate() {
        let nearest = v.nearest_site(p, None).unwrap().unwrap();
        assert_eq!(
            nearest,
            d.representative()[i],
            "site {i} at {p:?}: nearest is {nearest} at {:?}",
            d.sites()[nearest as usize]
        );
    }
}

#[test]
fn one_far_site_among_unit_square_sites() {
    // Squared distances between the unit-square sites, in the frame that brings 1e154 near 1,
    // are near 1e-308: they underflowed and the descent stopped at the wrong sites.
    let mut sites = uniform(98, 154);
    sites.push([1e154, 0.5]);
    let v = Voronoi::new(&sites).unwrap();
    check_delaunay(v.delaunay(), true);
    assert_each_site_nearest_to_itself(&v);
    check_clipped(&v, &ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap());
    check_clipped(&v, &bounding_clip(&sites, 0.1));
}

#[test]
fn a_site_at_1e_minus_300_beside_unit_sites() {
    let sites = [[0.0, 0.0], [1.0, 1.0], [1e-300, 1e-300]];
    let v = Voronoi::new(&sites).unwrap();
    assert_eq!(v.nearest_site([1e-300, 1e-300], None).unwrap(), Some(2));
    assert_eq!(v.nearest_site([0.0, 0.0], None).unwrap(), Some(0));
    assert_eq!(v.nearest_site([4e-300, -1e-300], None).unwrap(), Some(2));
    assert_eq!(v.nearest_site([-1e-300, 0.0], None).unwrap(), Some(0));
    assert_each_site_nearest_to_itself(&v);
}

#[test]
fn sites_spread_over_every_magnitude() {
    let mut sites = Vec::new();
    for e in (-300..=300).step_by(37) {
        let s = 10f64.powi(e);
        sites.extend([[s, 0.0], [0.0, s], [-s, 1.5 * s], [s, -s]]);
    }
    let v = Voronoi::new(&sites).unwrap();
    check_delaunay(v.delaunay(), true);
    assert_each_site_nearest_to_itself(&v);
}

#[test]
fn regions_whose_area_under_or_overflows_are_accepted() {
    for scale in [1e-300, 1e-170, 1e170, 1e300] {
        let clip = ClipPolygon::rectangle([-scale, -scale], [40.0 * scale, 40.0 * scale])
            .unwrap_or_else(|e| panic!("box at {scale:e}: {e}"));
        let sites: Vec<[f64; 2]> = uniform(60, 7)
            .into_iter()
            .map(|p| [p[0] * 39.0 * scale, p[1] * 39.0 * scale])
            .collect();
        let v = Voronoi::new(&sites).unwrap();
        assert_each_site_nearest_to_itself(&v);
        let cells = v.clip(&clip);
        assert_eq!(cells.n_cells(), sites.len());
        for site in 0..sites.len() as u32 {
            let poly = cells.cell_polygon(site).unwrap();
            assert!(
                poly.len() >= 3,
                "site {site} at {scale:e} has an empty cell"
            );
            assert!(
                poly.iter().flatten().all(|x| x.is_finite()),
                "site {site} at {scale:e}: {poly:?}"
            );
        }
    }
}

#[test]
fn boxes_a_few_ulps_wide_along_one_axis_are_accepted() {
    // Widths of subnormal size beside a height of 1: a shared power of two for both axes lost
    // the width, and the box was refused as having zero area.
    for (min, max) in [
        ([-5e-324, -9.000000000000005], [5e-324, -8.999999999999995]),
        (
            [35.99999999999999, -1.5e-323],
            [36.00000000000003, 1.5e-323],
        ),
        ([-5e-324, 0.9999999999999999], [5e-324, 1.0000000000000002]),
    ] {
        let clip = ClipPolygon::rectangle(min, max)
            .unwrap_or_else(|e| panic!("box {min:?} to {max:?}: {e}"));
        let centre = [0.5 * min[0] + 0.5 * max[0], 0.5 * min[1] + 0.5 * max[1]];
        let sites = [
            centre,
            [centre[0] + 1.0, centre[1]],
            [centre[0], centre[1] - 1.0],
        ];
        let v = Voronoi::new(&sites).unwrap();
        let cells = v.clip(&clip);
        assert!(cells.cell(0).unwrap().len() >= 3, "box {min:?}: empty cell");
        assert!(cells.positions().iter().flatten().all(|x| x.is_finite()));
    }
}

#[test]
fn lines_between_tiny_sites_cross_huge_regions_at_finite_points() {
    // The bisector of two sites 2.5e-299 apart has a direction of that size: its rate along
    // the edges of a region 1e301 wide underflowed and its crossings came out infinite or NaN.
    let sites = [[2.5e-299, 0.0], [0.0, 0.0]];
    let v = Voronoi::new(&sites).unwrap();
    let clip = ClipPolygon::rectangle([-1e300, -1e300], [4e301, 4e301]).unwrap();
    let cells = v.clip(&clip);
    assert!(
        cells.positions().iter().flatten().all(|x| x.is_finite()),
        "{:?}",
        cells.positions()
    );
    for site in 0..2 {
        assert_eq!(cells.cell(site).unwrap().len(), 4, "site {site}");
    }
    assert_each_site_nearest_to_itself(&v);
}

#[test]
fn circumcentres_of_triangles_spanning_every_magnitude_are_finite() {
    // Sites near 1e-299 beside one at 1e301: no power of two keeps both in the floating-point
    // circumcentre, whose products under- and overflowed into a NaN vertex.
    for sites in [
        vec![[1e301, 1e301], [2.5e-299, 0.0], [0.0, 0.0]],
        vec![
            [1.7e-99, 3.1e-99],
            [3.1e-99, 3.1e-99],
            [5e100, 0.0],
            [8e100, 3e100],
        ],
    ] {
        let v = Voronoi::new(&sites).unwrap();
        check_voronoi(&v);
        assert!(
            v.vertices().iter().flatten().all(|x| x.is_finite()),
            "{:?}",
            v.vertices()
        );
        assert_each_site_nearest_to_itself(&v);
    }
}
