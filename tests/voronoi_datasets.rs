//! The shared 2D point sets (`data/points2d/`): exact Delaunay, equidistant Voronoi vertices,
//! clipped cells that tile their bounding box, and the counts MANIFEST.md states.

mod test_data;
mod voronoi_common;

use halfwing::voronoi::{Delaunay, Dimension, Voronoi};
use std::path::PathBuf;
use voronoi_common::*;

fn data_dir() -> PathBuf {
    test_data::root().join("points2d")
}

/// (file, number of points, exact duplicates) as MANIFEST.md lists them.
const SETS: &[(&str, usize, usize)] = &[
    ("delaunator_ukraine.json", 874, 7),
    ("delaunator_robustness1.json", 79, 0),
    ("delaunator_robustness2.json", 1000, 32),
    ("delaunator_issue13.json", 17, 0),
    ("delaunator_issue43.json", 5, 0),
    ("delaunator-rs_grid.json", 32, 2),
    ("delaunator-rs_issue24.json", 4, 0),
    ("triangle_dots.node", 100, 0),
    ("triangle_spiral.node", 15, 0),
    ("triangle_greenland.node", 33343, 0),
    ("triangle_A.poly", 29, 0),
    ("triangle_la.poly", 141, 0),
    ("boostpoly_primary_005.txt", 10, 0),
    ("boostpoly_primary_016.txt", 100, 0),
    ("boostpoly_random_005.txt", 100, 0),
    ("voronoice_degenerated1.json", 15, 0),
    ("voronoice_degenerated2.json", 11, 0),
    ("voronoice_degenerated3.json", 10, 0),
    ("voronoice_degenerated7.json", 4, 0),
    ("cgal_voronoi.cin", 4, 0),
    ("cgal_points.xy", 5, 0),
    ("cgal_blob00.xy", 320, 0),
    ("cgal_skyline_noisy00.xy", 430, 0),
    ("cgal_ch_graham_anderson.cin", 500, 0),
    ("cgal_hierarchy.cin", 500, 0),
    ("cgaltest_layers.xy", 502, 0),
];

#[test]
fn every_point_set_triangulates_exactly_and_tiles_its_box() {
    let dir = data_dir();
    if !dir.exists() {
        eprintln!("skipping: {} not found (set HALFWING_DATA)", dir.display());
        return;
    }
    for &(file, count, duplicates) in SETS {
        let points = read_points(&dir.join(file));
        assert_eq!(points.len(), count, "{file}");
        let d = Delaunay::new(&points).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(d.duplicates().count(), duplicates, "{file}");
        check_delaunay(&d, points.len() <= 1000);
        let v = Voronoi::from_delaunay(d);
        check_voronoi(&v);
        check_clipped(&v, &bounding_clip(&points, 0.1));
        eprintln!(
            "{file}: {} triangles, {} Voronoi vertices",
            v.delaunay().n_triangles(),
            v.n_vertices()
        );
    }
}

#[test]
fn collinear_file_gives_a_chain() {
    let dir = data_dir();
    if !dir.exists() {
        return;
    }
    let d = Delaunay::new(&read_points(&dir.join("boostpoly_primary_005.txt"))).unwrap();
    assert_eq!(d.dimension(), Dimension::Line);
    assert_eq!(d.edges().len(), 9);
}

#[test]
fn cocircular_fixture_gives_one_vertex() {
    let dir = data_dir();
    if !dir.exists() {
        return;
    }
    // 17 points "at radius 3" from their centroid: cocircular only up to rounding, so the exact
    // diagram may split the centre; every vertex must still be equidistant from its sites.
    let v = Voronoi::new(&read_points(&dir.join("delaunator_issue13.json"))).unwrap();
    check_voronoi(&v);
    let cgal = Voronoi::new(&read_points(&dir.join("cgal_voronoi.cin"))).unwrap();
    // (0,0) (1,1) (0,2) (1,0): not cocircular; two triangles, two vertices.
    assert_eq!(cgal.n_vertices(), 2);
}
