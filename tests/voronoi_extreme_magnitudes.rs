//! Sites and clip regions whose magnitudes push products of coordinates out of the range of
//! doubles: answers stay exact (nearest sites) and cells still tile their region.

mod voronoi_common;

use halfwing::voronoi::{ClipPolygon, SiteId, Voronoi};
use voronoi_common::*;

/// Every site's nearest site is itself (or the first site at the same position).
fn assert_each_site_nearest_to_itself(v: &Voronoi) {
    let d = v.delaunay();
    for (i, &p) in d.sites().iter().enumerate() {
        let nearest = v.nearest_site(p, None).unwrap().unwrap();
        assert_eq!(
            nearest,
            SiteId(d.representative()[i]),
            "site {i} at {p:?}: nearest is {nearest} at {:?}",
            d.sites()[nearest.index()]
        );
    }
}

/// The diagram of `sites`, and its cells clipped to the rectangle from `min` to `max` checked
/// (`check_clipped`).
fn checked_in_rectangle(
    sites: &[[f64; 2]],
    min: [f64; 2],
    max: [f64; 2],
) -> (Voronoi, ClipPolygon) {
    let clip = ClipPolygon::rectangle(min, max).unwrap();
    let v = Voronoi::new(sites).unwrap();
    check_clipped(&v, &clip);
    (v, clip)
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
    assert_eq!(
        v.nearest_site([1e-300, 1e-300], None).unwrap(),
        Some(SiteId(2))
    );
    assert_eq!(v.nearest_site([0.0, 0.0], None).unwrap(), Some(SiteId(0)));
    assert_eq!(
        v.nearest_site([4e-300, -1e-300], None).unwrap(),
        Some(SiteId(2))
    );
    assert_eq!(
        v.nearest_site([-1e-300, 0.0], None).unwrap(),
        Some(SiteId(0))
    );
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
        for site in (0..sites.len() as u32).map(SiteId) {
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
        assert!(
            cells.cell(SiteId(0)).unwrap().len() >= 3,
            "box {min:?}: empty cell"
        );
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
    for site in (0..2).map(SiteId) {
        assert_eq!(cells.cell(site).unwrap().len(), 4, "{site}");
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

/// Far from the origin a region one ulp wide holds few representable points: a side crossing it
/// is placed from the sites in a frame local to the region, not from a bisector midpoint rounded
/// a half ulp away (which put it 0.4 off along the region's other axis).
#[test]
fn sides_crossing_a_box_one_ulp_wide_far_out_are_where_the_sites_put_them() {
    let x = 1e15_f64 + 50.0;
    let ulp = x.next_up() - x;
    assert_eq!(ulp, 0.125);
    // The bisector of `a` and `b` is 0.125 (x - 0.0625) + (5 / 128) (y - 5 / 256) = 0 around `a`:
    // it meets x = 0 at y = 0.21953125 and x = 0.125 at y = -0.18046875 (all exact in doubles).
    let a = [x, 0.0];
    let b = [x + ulp, 5.0 / 128.0];
    let sites = [a, b, [x, 100.0]];
    let v = Voronoi::new(&sites).unwrap();
    let clip = ClipPolygon::rectangle([x, -1.0], [x + ulp, 1.0]).unwrap();
    check_clipped(&v, &clip);
    let cells = v.clip(&clip);
    let cell = cells.cell_polygon(SiteId(0)).unwrap();
    let on = |edge: f64| -> Vec<f64> {
        cell.iter()
            .filter(|p| p[0] == edge && p[1].abs() < 1.0)
            .map(|p| p[1])
            .collect()
    };
    // Within a few ulps of the exact heights (the positions are rounded from the local frame).
    for (edge, exact) in [(x, 0.21953125), (x + ulp, -0.18046875)] {
        let heights = on(edge);
        assert_eq!(heights.len(), 1, "one crossing at x = {edge} in {cell:?}");
        assert!(
            (heights[0] - exact).abs() <= 1e-12,
            "{heights:?} vs {exact} in {cell:?}"
        );
    }
}

/// A region two units wide and one ulp tall at 1e15 + 50: the sites a ulp above and below a site
/// on its edge split a column between them, with Voronoi vertices half an ulp off the
/// representable heights. Rounded there, vertices of neighbouring triangles merged and the cell
/// of the site on the edge vanished.
#[test]
fn a_site_on_the_edge_of_a_region_one_ulp_tall_far_out_keeps_its_cell() {
    let (x, y) = (1e15 + 49.125, 553.5217878740434_f64);
    let u = y.next_up() - y;
    let at = |dx: f64, dy: f64| [x + dx, y + dy * u];
    let sites = [
        at(0.0, 0.0),
        at(0.0, 1.0),
        at(0.0, -1.0),
        at(-0.25, 5.0),
        at(0.375, -4.0),
        at(0.375, 3.0),
        at(2.0, 0.0),
        at(-0.5, -3.0),
    ];
    let v = Voronoi::new(&sites).unwrap();
    let clip = ClipPolygon::rectangle(at(0.0, 0.0), at(2.0, 1.0)).unwrap();
    check_clipped(&v, &clip);
    assert!(v.clip(&clip).cell(SiteId(0)).unwrap().len() >= 3);
}

/// The bisector of a site at the region's corner and one 1e-135 from it, nearly collinear with
/// the others (so the edge between them ends at far Voronoi vertices), cuts a triangle 1e-135
/// wide off the corner: both crossings rounded to the same point along the edge, which was
/// dropped as missing the region.
#[test]
fn a_bisector_passing_a_corner_by_less_than_an_ulp_keeps_its_cell() {
    let sites = [
        [0.0, 0.0],
        [1.1999999999999996e-135, 7.999999999999997e-136],
        [3.0, 2.0],
        [-3.0, -2.0],
        [42.0, 28.0],
    ];
    let (v, clip) = checked_in_rectangle(&sites, [0.0, 0.0], [42.0, 28.0]);
    assert!(v.clip(&clip).cell(SiteId(0)).unwrap().len() >= 3);
}

/// A region 2 wide and 2e-252 tall: the bisector `x = 1.5` crosses its bottom and top at
/// parameters along the edge equal in doubles (they differ by 2e-252 of 0.5), and the cell of
/// the site at the corner `(2, 0)`, a quarter of the region, came out empty.
#[test]
fn an_edge_crossing_a_region_flatter_than_an_ulp_is_kept() {
    let sites = [[2.0, 0.0], [1.0, 0.0], [2.0, 1.0], [1.0, 1.0], [3.0, 0.0]];
    let (v, clip) = checked_in_rectangle(&sites, [1e-252, 0.0], [2.0, 2e-252]);
    assert!(v.clip(&clip).cell(SiteId(0)).unwrap().len() >= 3);
}

#[test]
fn circumcentres_beyond_the_range_of_doubles_are_infinite_with_their_sign() {
    // Sites on the line y = -3x but for the rounding of the tiny one (from a stress case): the
    // triangles are 1e-143 in area, their exact circumcentres near (-5e386, -2e386) and beyond.
    let tiny = [
        f64::from_bits(899_270_040_106_987_691),
        f64::from_bits(10_129_759_947_744_597_121),
    ];
    let far = [
        f64::from_bits(6_417_922_035_339_371_486),
        f64::from_bits(15_648_195_754_803_410_381),
    ];
    let one_triangle = vec![tiny, far, [20.0, -60.0]];
    // Two adjacent triangles whose centres both round to (-inf, -inf): one vertex, as for any
    // centres rounding to one point.
    let two_triangles = vec![tiny, far, [20.0, -60.0], [2.0 * far[0], 2.0 * far[1]]];
    for sites in [one_triangle, two_triangles] {
        let v = Voronoi::new(&sites).unwrap();
        assert_eq!(v.vertices(), [[f64::NEG_INFINITY; 2]]);
        check_voronoi(&v);
        check_clipped(&v, &bounding_clip(&sites, 0.1));
        check_clipped(
            &v,
            &ClipPolygon::rectangle([-100.0, -100.0], [100.0, 100.0]).unwrap(),
        );
        assert_each_site_nearest_to_itself(&v);
    }
}

/// A region from a site to one 1e40 away: the cells near the first site's corner are a few
/// tenths wide, 1e-40 of the region. Their edges run from Voronoi vertices beside the corner to
/// far ones, and were parametrised from the far end, where a parameter's rounding is 1e24 long:
/// the cell of the corner's site came out empty. Clipped from the near end and placed from the
/// nearer corner of the side, it is its triangle.
#[test]
fn cells_at_the_corner_of_a_region_far_larger_than_them_keep_their_shape() {
    let corner = [0.6654262839801495, 0.722164734606788];
    let far = [4.46772356960677e39, 5.298486514846041e39];
    let sites = [
        [0.39060108195688203, 0.27955996206734735],
        [0.8722834087571435, 0.8781683733940039],
        [0.44677235696067696, 0.529848651484604],
        [0.7900238710381996, 0.10550059640556819],
        corner,
        [0.5825742508067545, 0.11474956691296534],
        far,
    ];
    let clip = ClipPolygon::rectangle(corner, far).unwrap();
    let v = Voronoi::new(&sites).unwrap();
    check_clipped(&v, &clip);
    // The corner's cell is cut off by its bisector with site 1 alone: a right triangle whose
    // legs run along the two sides to where that bisector crosses them.
    let [p, q] = [corner, sites[1]];
    let squared = |a: [f64; 2]| a[0] * a[0] + a[1] * a[1];
    let crossing = |k: usize| {
        let l = 1 - k;
        (squared(q) - squared(p) - 2.0 * (q[l] - p[l]) * p[l]) / (2.0 * (q[k] - p[k]))
    };
    let legs = [crossing(0) - corner[0], crossing(1) - corner[1]];
    let area = v.clip(&clip).cell_area(SiteId(4)).unwrap();
    assert!(
        (area - 0.5 * legs[0] * legs[1]).abs() <= 1e-12,
        "{area} vs {legs:?}"
    );
}

/// Sites on the line y = -3x, one of them 1e45 out, in a region from (-7, -2.7e26) to
/// (9e25, 21): the cells that matter lie within 30 of the corner (-7, 21), 1e-25 of the region.
/// Their edges end at Voronoi vertices far beyond it, and a crossing computed along such an edge
/// was off by 3e10 (the ulp of its far end), on the wrong side of the corner: a cell that meets
/// the region only at the corner walked the whole boundary. Crossings are now placed from the
/// sites, and the sides an edge crosses are decided exactly where rounding chose them.
#[test]
fn cells_beside_the_near_corner_of_a_huge_region_are_placed_from_their_sites() {
    let sites = [
        [-12.0, 36.0],
        [-18.0, 54.0],
        [-2.0, 6.0],
        [7.000000000000001e44, -2.1000000000000003e45],
    ];
    let (v, clip) = checked_in_rectangle(&sites, [-7.0, -2.7000000000000004e26], [9e25, 21.0]);
    // The bisector of the first and third sites passes exactly through the corner (-7, 21).
    assert!(v.clip(&clip).cell(SiteId(0)).unwrap().is_empty());
}

/// A box 5 ulps wide and 6 tall at 1e15 + 50, whose right side the bisector of the two sites
/// beside it runs along, inside by 1e-23: the cell of the site to the right is that sliver.
/// Its crossings with the bottom and the top were taken from a point of the edge rounded in
/// the box's frame, where the bisector lies on the side: both came out at the bottom corner,
/// and the sliver lost its top. Placed from the sites, they lie at either end of the side.
#[test]
fn a_bisector_along_a_side_of_a_box_a_few_ulps_wide_keeps_its_sliver() {
    let sites = [
        [1000000000000050.0, -922.8153790296379],
        [1000000000000050.3, -922.8153790296402],
        [1000000000000050.6, -922.815379029639],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000049.5, -922.8153790296402],
        [1000000000000050.1, -922.8153790296395],
    );
}

/// Sites at 2e-59 and 1e-287 beside the corner (0, 0) of a 1 × 2 box: the Voronoi edge of the
/// first and the site at (0, 2) crosses the left side 2.5e-59 before its vertex inside, half a
/// unit along the edge, so the crossing's parameter rounds onto the vertex's. The piece from
/// the crossing to the vertex was dropped, and with it a quarter of that site's cell. The
/// crossing, placed from the sites where the edge puts it, keeps the piece.
#[test]
fn an_edge_crossing_a_side_just_before_its_vertex_inside_is_kept() {
    let sites = [
        [2e-59, 1e-59],
        [0.0, 9.999999999999996e-288],
        [0.0, 0.0],
        [0.0, 2.0],
    ];
    checked_in_rectangle(&sites, [0.0, 0.0], [1.0, 2.0]);
}

/// Sites on the line y = -1.5x at 1e45, 1e-259 and 32, and a box a few ulps wide around the
/// tiny one: the circumcentre lies beyond the range of doubles, and moving it into the box's
/// local frame divided infinity by infinity. Its direction is kept instead.
#[test]
fn a_vertex_beyond_doubles_keeps_its_direction_in_a_local_frame() {
    let sites = [
        [2.6000000000000004e45, -3.9000000000000006e45],
        [9.999999999999996e-260, -1.4999999999999995e-259],
        [-32.0, 48.0],
    ];
    let clip = ClipPolygon::rectangle(
        [9.999999999999993e-260, -1.4999999999999998e-259],
        [9.999999999999999e-260, -1.499999999999999e-259],
    )
    .unwrap();
    let v = Voronoi::new(&sites).unwrap();
    let cells = v.clip(&clip);
    assert!(cells.positions().iter().flatten().all(|x| x.is_finite()));
    // The whole box is nearest to the site inside it.
    assert_eq!(cells.cell(SiteId(1)).unwrap().len(), 4);
}

/// Three sites on a vertical line an ulp or two apart at 1e15 + 49.5, a fourth a quarter to
/// their right, and a region from 1e15 + 50.6 to 1e53: the fourth site's cell holds all of it.
/// The two circumcentres round to one Voronoi vertex, which merges away the edge between the
/// middle site and the fourth. The middle site's cell, rebuilt from
/// its exact polygon, was cut only by the sites across its remaining sides and came out as a
/// strip across the whole region. The sites across edges merged away bound it too.
#[test]
fn a_cell_rebuilt_exactly_is_cut_by_the_sites_across_merged_edges() {
    let sites = [
        [1000000000000049.5, -86.56064164729837],
        [1000000000000049.5, -86.56064164729838],
        [1000000000000049.5, -86.5606416472984],
        [1000000000000049.8, -86.56064164729844],
    ];
    let (v, clip) = checked_in_rectangle(
        &sites,
        [1000000000000050.6, -8.656064164729844e39],
        [1.0000000000000504e53, -86.56064164729833],
    );
    let cells = v.clip(&clip);
    for site in 0..3 {
        assert!(cells.cell(SiteId(site)).unwrap().is_empty(), "site {site}");
    }
    // Rebuilt from its exact polygon, the whole region keeps its own corners.
    assert_eq!(cells.cell_polygon(SiteId(3)).unwrap(), clip.vertices());
}

/// Four sites a quarter apart at 1e15 + 49 in a region from there to 1e88: one Voronoi vertex,
/// at 7e10, rounds onto the region's left side, 1.5e-65 of its length before the bottom
/// corner, so its parameter rounds to the corner's. It was put on the corner, and the cell
/// between it and the corner went round the whole region (the areas summed to twice the
/// region's). It keeps its offset from the corner.
#[test]
fn a_vertex_just_before_the_end_of_a_long_side_is_not_moved_onto_the_corner() {
    let sites = [
        [1000000000000048.9, 487.74455113359664],
        [1000000000000049.1, 487.744551133596],
        [1000000000000049.1, 487.7445511335953],
        [1000000000000049.4, 487.74455113359625],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000049.1, 487.7445511335957],
        [1.000000000000049e88, 4.877445511335963e75],
    );
}

/// Three sites an ulp apart at 1e15 + 49.4 in a box 23 ulps wide and 11 tall: the cell on the
/// right meets its neighbours at x = 1e15 + 49.4375, between two doubles. Its corners round to
/// either side of that, so the cell comes out with a reflex corner an ulp deep, and the
/// extension of a side there passes beside its own site. The site still lies in its cell.
#[test]
fn a_cell_with_a_corner_rounded_reflex_holds_its_site() {
    let sites = [
        [1000000000000049.4, -598.8040313554328],
        [1000000000000049.4, -598.8040313554326],
        [1000000000000049.5, -598.8040313554328],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000048.6, -598.8040313554336],
        [1000000000000051.5, -598.8040313554324],
    );
}

/// Three sites at 1e15 + 51 and a box 7 ulps wide and 6 tall beside them, whose right side the
/// Voronoi vertex lies on exactly (placed in the box's local frame). The edge between the two
/// sites to the right leaves the box at once from that vertex: its crossing with the side is
/// the vertex itself. It was kept as a piece from the vertex to that crossing, and the cell
/// beside it went round the whole box (the areas summed to twice the box's).
#[test]
fn an_edge_leaving_at_once_from_a_vertex_on_the_boundary_has_no_piece() {
    let sites = [
        [1000000000000051.4, 944.403761974561],
        [1000000000000051.4, 944.4037619745623],
        [1000000000000050.6, 944.4037619745606],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000050.1, 944.4037619745613],
        [1000000000000051.0, 944.403761974562],
    );
}

/// Two sites 1e-286 apart near 1e-271 and one at 1e15: their circumcentre lies at
/// (3.6e15, 8.0e27), but the fast formula, on differences scaled into the subnormals, put it
/// at infinity.
#[test]
fn a_centre_of_sites_1e_minus_286_apart_beside_one_at_1e15_is_finite() {
    let sites = [
        [1.0000000000000491e-271, -3.924186530907457e-284],
        [1.000000000000048e-271, -3.924186530907452e-284],
        [1000000000000049.8, -392.4186530907462],
    ];
    let v = Voronoi::new(&sites).unwrap();
    check_voronoi(&v);
    let [x, y] = v.vertices()[0];
    assert!((x - 3.647977311966128e15).abs() <= 1e-9 * x, "x = {x:e}");
    assert!((y - 8.021986944739589e27).abs() <= 1e-9 * y, "y = {y:e}");
}

/// A region 4 wide and 2e-86 tall along the x axis. The Voronoi vertex (3, 0) of (2, 0), (4, 0)
/// and (3, 1) lies on its bottom side, and the edges from it cross the region to its top in
/// 2e-86, a parameter that rounds onto the vertex's. Such an edge was dropped like one leaving
/// at once through the side its vertex lies on, and the cell of (2, 0) walked round the region
/// the wrong way. It reaches the opposite side, and keeps its piece.
#[test]
fn an_edge_crossing_a_flat_region_to_a_vertex_on_its_other_side_is_kept() {
    let sites = [
        [3.0, 2.0],
        [4.0, 2.0],
        [2.0, 0.0],
        [3.0, 1.0],
        [0.0, 3.0],
        [1.0, 1.0],
        [4.0, 0.0],
    ];
    let (v, clip) = checked_in_rectangle(&sites, [2e-86, 0.0], [4.0, 2e-86]);
    let cells = v.clip(&clip);
    let area = |site: u32| cells.cell_area(SiteId(site)).unwrap();
    // (1, 1) holds x < 1, (2, 0) 1 < x < 3 and (4, 0) x > 3; (3, 1) a triangle 4e-86 wide.
    let height = 2e-86;
    for (site, width) in [(5, 1.0), (2, 2.0), (6, 1.0)] {
        let expected = width * height;
        assert!(
            (area(site) - expected).abs() <= 1e-9 * expected,
            "cell {site}"
        );
    }
    assert!(!cells.cell(SiteId(3)).unwrap().is_empty());
}

/// Sites near 1 beside one at (2.9e28, 5.2e28), and a region from one of them to 7.9e143. The
/// bisector of (0.13, 0.90) and (0.39, 0.88) runs from a Voronoi vertex at 3e28 with a slope of
/// 15, and leaves the region by its left side at y = 9; from the vertex, rounded to ulps of
/// 3e28, it seemed to leave by the bottom, and the cell of (0.39, 0.88) went round the whole
/// region. It leaves by the side it crosses exactly.
#[test]
fn a_steep_edge_from_a_far_vertex_leaves_by_the_side_it_crosses_exactly() {
    let sites = [
        [0.9860278425343197, 0.7369339860406604],
        [0.7942519096707895, 0.54344487021357],
        [0.13044504911924937, 0.8990791036405866],
        [0.38508462327067194, 0.8824461812645711],
        [2.8897113354128375e28, 5.239935461917e28],
    ];
    checked_in_rectangle(
        &sites,
        [0.7942519096707895, 0.54344487021357],
        [7.942519096707896e143, 5.434448702135702e143],
    );
}

/// A box 7 ulps wide and 7 tall at 1e15 + 51. The bisector of the sites a quarter to either
/// side of its right side runs along that side, 1e-25 inside it, and the edge from its Voronoi
/// vertex on the side missed the box within rounding: the sliver between the two, the cell of
/// the site to the right, kept only the three positions of its other edge, on the side, and
/// lost its top. A cell whose positions lie in a line beside such an edge is rebuilt from its
/// exact polygon.
#[test]
fn a_sliver_beside_an_edge_that_missed_within_rounding_is_rebuilt_exactly() {
    let sites = [
        [1000000000000051.4, -839.1401399746389],
        [1000000000000051.1, -839.1401399746392],
        [1000000000000051.4, -839.1401399746375],
        [1000000000000051.1, -839.1401399746368],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000050.4, -839.1401399746381],
        [1000000000000051.3, -839.1401399746373],
    );
}

/// Sites an ulp or two apart at 1e15 + 48.5, above and to the left of a region that reaches
/// 1e62. The Voronoi edge between two of them is 1e-12 long, outside the region, but its ends,
/// rounded to ulps of 1e15, took it across the region's corner: its crossings, placed from the
/// sites where its bisector crosses the sides, gave a piece from the left side to the bottom
/// 1e37 away, and the areas summed to twice the region's. A crossing is kept only where it lies
/// on the edge, which is decided exactly.
#[test]
fn an_edge_crossing_a_corner_only_once_its_ends_are_rounded_has_no_piece() {
    let sites = [
        [1000000000000048.3, -928.6921875644529],
        [1000000000000048.6, -928.6921875644535],
        [1000000000000048.6, -928.6921875644518],
        [1000000000000048.6, -928.6921875644533],
        [1000000000000049.5, -928.6921875644531],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000049.8, -9.286921875644536e49],
        [1.0000000000000496e62, -928.6921875644538],
    );
}

/// A region 7 subnormals wide around the site (0, 0), whose cell holds all of it. In the
/// region's local frame the sites (2, 3) and (3, 2) lie 1e300 out, and the ray between them,
/// moved along their bisector rounded to ulps of 1e300, crossed the region: the cell of (0, 0)
/// came out empty. The ray's crossings lie beyond its vertex, nearer to (0, 0).
#[test]
fn a_ray_whose_line_crosses_a_subnormal_region_beyond_its_vertex_misses_it() {
    let sites = [
        [0.0, 3e-251],
        [3e-9, 0.0],
        [0.0, 0.0],
        [2.0, 3.0],
        [3.0, 2.0],
    ];
    let clip = ClipPolygon::rectangle([-2e-323, -5e-324], [1.5e-323, 5e-324]).unwrap();
    let cells = Voronoi::new(&sites).unwrap().clip(&clip);
    for site in 0..sites.len() as u32 {
        let cell = cells.cell_polygon(SiteId(site)).unwrap();
        if site == 2 {
            let mut corners = cell.clone();
            corners.sort_by(|p, q| p.partial_cmp(q).unwrap());
            let mut region = clip.vertices().to_vec();
            region.sort_by(|p, q| p.partial_cmp(q).unwrap());
            assert_eq!(corners, region, "the cell of (0, 0) is the region");
        } else {
            assert!(cell.is_empty(), "site {site}: {cell:?}");
        }
    }
}

/// A box 23 ulps wide and 2 tall at 1e15 + 50, narrower than the rounding of its own corners:
/// every cell's area there lies within rounding. The bisector of two sites crosses it half way
/// between two doubles, and a cell beside an edge that missed the box was rebuilt from its
/// exact polygon, its crossings rounded the other way from the shared ones: the two cells
/// overlapped by an ulp. Only a cell whose corners lie exactly in a line is rebuilt so.
#[test]
fn cells_in_a_box_narrower_than_rounding_share_their_crossings() {
    let sites = [
        [1000000000000049.5, -4.81294127104001],
        [1000000000000049.4, -4.812941271040022],
        [1000000000000049.5, -4.812941271040022],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000048.6, -4.812941271040014],
        [1000000000000051.5, -4.812941271040012],
    );
}

#[test]
fn a_vertex_rounded_out_of_a_region_at_1e97_is_placed_on_its_side() {
    // Sites from 1 to 6 beside one at 4e97: the Voronoi vertex at (2e97, 4e96) lies on or
    // inside the region's top side exactly, and rounds an ulp above it. The areas came to 1.5
    // times the region's.
    let sites = [
        [6.0, 1.0],
        [4.000000000000001e97, 0.0],
        [5.0, 6.0],
        [2.0, 6.0],
    ];
    checked_in_rectangle(
        &sites,
        [-4.000000000000001e96, -4.000000000000001e96],
        [4.400000000000001e97, 4.000000000000001e96],
    );
}

#[test]
fn a_sliver_along_a_side_within_1e_minus_12_of_parallel_is_kept() {
    // A box 7 ulps wide at 1e15 + 50, and the bisector of sites 0 and 1 running along its right
    // side, 1e-25 inside it: site 0's part is a sliver. In the local frame the bisector, moved
    // from a vertex 2.5e12 out and rounded to ulps of 3.5, seemed to leave the box by that side
    // before it entered by the top, 8e-5 of its length away: it was taken for a miss by far
    // more than rounding, and site 0 had no cell.
    let sites = [
        [1000000000000051.4, 489.7919087613411],
        [1000000000000050.6, 489.79190876134055],
        [1000000000000049.4, 489.7919087613401],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000050.1, 489.791908761341],
        [1000000000000051.0, 489.79190876134135],
    );
}

#[test]
fn a_bisector_crossing_just_beyond_a_corner_enters_by_the_other_side() {
    // Three collinear sites near 1, in a region reaching 6.6e64: the bisector y = x - 2 meets
    // the left side's line 2 below the bottom-left corner, at -6e63, and enters by the bottom.
    // Its parameter along the left side rounded onto that corner, the bisector was taken to
    // enter there, and the middle strip walked round the whole region.
    let sites = [[2.0, 1.0], [1.0, 2.0], [3.0, 0.0]];
    checked_in_rectangle(
        &sites,
        [-6.000000000000001e63, -6.000000000000001e63],
        [1.6000000000000004e64, 6.600000000000001e64],
    );
}

#[test]
fn a_ray_along_a_side_from_a_vertex_rounded_onto_it_is_kept() {
    // A box 5 ulps wide at 1e15 + 50.75, its left side half way between site 1 and the other
    // three. The Voronoi vertex of sites 0, 1 and 2 lies 2e-26 inside that side and rounds onto
    // it; the ray of sites 1 and 2 runs down the side from it, inside by less, and leaves the
    // box 7e-15 above the bottom. The ray was dropped as leaving through the vertex's own side
    // at once, and site 1's sliver along the side lost all but its tip.
    let sites = [
        [1000000000000050.9, 95.77401993858466],
        [1000000000000050.6, 95.77401993858452],
        [1000000000000050.9, 95.77401993858444],
        [1000000000000050.9, 95.7740199385847],
    ];
    checked_in_rectangle(
        &sites,
        [1000000000000050.8, 95.77401993858447],
        [1000000000000051.4, 95.77401993858456],
    );
}
