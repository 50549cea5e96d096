//! The repairs (`halfwing::repair`): each on constructed cases with the exact elements it must
//! change, on bad input (refused, input unchanged), on every test model, and their properties:
//! a repaired soup builds into a mesh that passes `check()`, a second run changes nothing, clean
//! input is left as it is, and kept corner data follows its corner.

mod mesh_support;

use halfwing::io::read_path;
use halfwing::mesh::{BuildPolicy, HalfedgeId, Mesh};
use halfwing::repair::{
    RepairError, RepairReport, SmallComponents, Tolerance, merge_vertices, remove_duplicate_faces,
    remove_small_components, remove_unreferenced_vertices, stitch_borders,
};
use halfwing::soup::PolygonSoup;
use mesh_support::soups::{lattice_soup, test_models};
use mesh_support::{data_dir, grid};
use proptest::prelude::*;

/// Every corner with a vertex of its own (an unwelded soup), each corner's normal and uv
/// naming its old vertex so that tests can see where corner data went.
fn unwelded(soup: &PolygonSoup) -> PolygonSoup {
    PolygonSoup {
        positions: soup
            .indices
            .iter()
            .map(|&v| soup.positions[v as usize])
            .collect(),
        face_sizes: soup.face_sizes.clone(),
        indices: (0..soup.indices.len() as u32).collect(),
        corner_normals: Some(soup.indices.iter().map(|&v| [v as f64, 0.0, 1.0]).collect()),
        corner_uvs: Some((0..soup.indices.len()).map(|c| [c as f64, 0.5]).collect()),
    }
}

fn boundary_edges(mesh: &Mesh) -> usize {
    (0..mesh.n_halfedge_slots() as u32)
        .map(HalfedgeId)
        .filter(|&h| !mesh.is_halfedge_deleted(h) && mesh.is_boundary_halfedge(h))
        .count()
}

/// Corners' positions, face by face: what a repair that only renumbers must keep.
fn corner_positions(soup: &PolygonSoup) -> Vec<[f64; 3]> {
    soup.indices
        .iter()
        .map(|&v| soup.positions[v as usize])
        .collect()
}

#[test]
fn exact_merge_welds_an_unwelded_grid_and_keeps_corner_data() {
    let welded = grid(4, 3, false, true);
    let mut soup = unwelded(&welded);
    let before = soup.clone();
    let report = merge_vertices(&mut soup, Tolerance::EXACT).unwrap();
    assert_eq!(soup.positions.len(), welded.positions.len());
    assert_eq!(soup.n_faces(), welded.n_faces());
    assert_eq!(
        report.merged_vertices.len(),
        welded.indices.len() - welded.positions.len()
    );
    // Every kept vertex is the lowest corner at its position; the corners keep their positions,
    // normals and uvs.
    assert_eq!(corner_positions(&soup), corner_positions(&before));
    assert_eq!(soup.corner_normals, before.corner_normals);
    assert_eq!(soup.corner_uvs, before.corner_uvs);
    for &[v, kept] in &report.merged_vertices {
        assert!(kept < v);
        assert_eq!(
            before.positions[v as usize],
            before.positions[kept as usize]
        );
        assert_eq!(report.maps.vertices[v as usize], u32::MAX);
    }
    assert!(report.removed_faces.is_empty());
    let (mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    mesh.check().unwrap();
    assert_eq!(boundary_edges(&mesh), 2 * (4 + 3));
    // Idempotent.
    let again = soup.clone();
    assert!(
        merge_vertices(&mut soup, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    assert_eq!(soup, again);
}

#[test]
fn tolerance_merges_near_vertices_into_the_first_and_collapses_faces() {
    // Two triangles sharing an edge whose ends are given twice, 1e-7 apart, and a sliver
    // triangle whose corners all fall within the tolerance.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0 + 1e-7, 0.0, 0.0],
        [1e-7, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [5.0, 5.0, 0.0],
        [5.0, 5.0 + 1e-7, 0.0],
        [5.0 + 1e-7, 5.0, 0.0],
    ];
    let mut soup = PolygonSoup {
        positions,
        face_sizes: vec![3, 3, 3],
        indices: vec![0, 1, 2, 3, 5, 4, 6, 7, 8],
        corner_normals: Some((0..9).map(|c| [c as f64, 0.0, 0.0]).collect()),
        corner_uvs: None,
    };
    let report = merge_vertices(&mut soup, Tolerance::Absolute(1e-6)).unwrap();
    assert_eq!(report.merged_vertices, vec![[3, 1], [4, 2], [7, 6], [8, 6]]);
    assert_eq!(report.removed_faces, vec![2]);
    assert_eq!(report.maps.faces, vec![0, 1, u32::MAX]);
    assert_eq!(
        report.maps.vertices,
        vec![0, 1, 2, u32::MAX, u32::MAX, 3, 4, u32::MAX, u32::MAX]
    );
    assert_eq!(soup.indices, vec![0, 1, 2, 1, 3, 2]);
    // The kept vertices keep their positions; the corners their normals.
    assert_eq!(soup.positions[1], [1.0, 0.0, 0.0]);
    assert_eq!(
        soup.corner_normals.as_ref().unwrap()[3..],
        [[3.0, 0.0, 0.0], [4.0, 0.0, 0.0], [5.0, 0.0, 0.0]]
    );
    // Relative: 1e-7 of a diagonal of about 7 is 7e-7, enough; 1e-8 is not.
    let mut same = soup.clone();
    assert!(
        merge_vertices(&mut same, Tolerance::Relative(1e-7))
            .unwrap()
            .is_empty()
    );
}

#[test]
fn near_merge_is_greedy_not_transitive() {
    // 0 — 1 — 2 spaced 0.6 with tolerance 1: 1 joins 0; 2 is 1.2 from 0, so it stays.
    let mut soup = PolygonSoup {
        positions: vec![[0.0, 0.0, 0.0], [0.6, 0.0, 0.0], [1.2, 0.0, 0.0]],
        ..PolygonSoup::default()
    };
    let report = merge_vertices(&mut soup, Tolerance::Absolute(1.0)).unwrap();
    assert_eq!(report.merged_vertices, vec![[1, 0]]);
    assert_eq!(soup.positions, vec![[0.0, 0.0, 0.0], [1.2, 0.0, 0.0]]);
}

#[test]
fn polygons_drop_repeated_corners_and_collapse_below_three_distinct() {
    // A pentagon whose corners 1 and 2 coincide keeps 4 corners; a quad a b a' b' (a = a',
    // b = b') has 2 distinct corners and goes.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [3.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
        [3.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
    ];
    let mut soup = PolygonSoup {
        positions,
        face_sizes: vec![5, 4],
        indices: vec![0, 1, 2, 3, 4, 5, 6, 7, 8],
        corner_normals: None,
        corner_uvs: Some((0..9).map(|c| [c as f64, 0.0]).collect()),
    };
    let report = merge_vertices(&mut soup, Tolerance::EXACT).unwrap();
    assert_eq!(report.removed_faces, vec![1]);
    assert_eq!(report.removed_corners, 1);
    assert_eq!(soup.face_sizes, vec![4]);
    assert_eq!(soup.indices, vec![0, 1, 2, 3]);
    assert_eq!(
        soup.corner_uvs.unwrap(),
        vec![[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [4.0, 0.0]]
    );
}

#[test]
fn bad_tolerances_are_refused_and_leave_the_soup_unchanged() {
    let original = unwelded(&grid(2, 2, false, true));
    for (tolerance, words) in [
        (Tolerance::Absolute(-1.0), "0 or more"),
        (Tolerance::Absolute(f64::NAN), "NaN"),
        (Tolerance::Absolute(f64::INFINITY), "finite"),
        (Tolerance::Relative(-0.5), "between 0 and 1"),
        (Tolerance::Relative(2.0), "between 0 and 1"),
        (Tolerance::Relative(f64::NAN), "between 0 and 1"),
        (Tolerance::Absolute(1e-300), "2^-48"),
    ] {
        let mut soup = original.clone();
        let error = merge_vertices(&mut soup, tolerance).unwrap_err();
        assert!(matches!(error, RepairError::BadTolerance { .. }));
        assert!(error.to_string().contains(words), "{error}");
        assert_eq!(soup, original);
        let (mut mesh, _) = Mesh::from_soup(&original, BuildPolicy::Strict).unwrap();
        let before = mesh.clone();
        assert!(stitch_borders(&mut mesh, tolerance).is_err());
        assert_eq!(mesh, before);
    }
    // A huge finite tolerance merges everything into one vertex: every face collapses.
    let mut soup = original.clone();
    let report = merge_vertices(&mut soup, Tolerance::Absolute(1e308)).unwrap();
    assert_eq!(soup.positions.len(), 1);
    assert_eq!(soup.n_faces(), 0);
    assert_eq!(report.removed_faces.len(), original.n_faces());
    assert!(soup.corner_uvs.unwrap().is_empty());
}

#[test]
fn malformed_soups_are_refused_unchanged() {
    let mut ragged = grid(1, 1, false, true);
    ragged.indices.pop();
    let mut out_of_range = grid(1, 1, false, true);
    out_of_range.indices[4] = 99;
    let mut short_normals = grid(1, 1, false, true);
    short_normals.corner_normals = Some(vec![[0.0; 3]; 2]);
    for original in [ragged, out_of_range, short_normals] {
        let mut soup = original.clone();
        assert!(merge_vertices(&mut soup, Tolerance::EXACT).is_err());
        assert!(remove_duplicate_faces(&mut soup).is_err());
        assert!(remove_unreferenced_vertices(&mut soup).is_err());
        assert!(remove_small_components(&mut soup, SmallComponents::FaceCount(1)).is_err());
        assert_eq!(soup, original);
    }
    let error = merge_vertices(
        &mut PolygonSoup {
            positions: vec![[0.0; 3]],
            face_sizes: vec![3],
            indices: vec![0, 0, 7],
            ..PolygonSoup::default()
        },
        Tolerance::EXACT,
    )
    .unwrap_err();
    assert_eq!(
        error.to_string(),
        "face 0 names vertex 7, but there are 1 vertices"
    );
}

#[test]
fn empty_input_changes_nothing() {
    let mut soup = PolygonSoup::default();
    for report in [
        merge_vertices(&mut soup, Tolerance::Relative(0.1)).unwrap(),
        remove_duplicate_faces(&mut soup).unwrap(),
        remove_unreferenced_vertices(&mut soup).unwrap(),
        remove_small_components(&mut soup, SmallComponents::RelativeDiameter(0.5)).unwrap(),
    ] {
        assert_eq!(report, RepairReport::default());
    }
    let mut mesh = Mesh::new();
    assert!(
        stitch_borders(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn all_coincident_points_merge_in_linear_time_and_every_face_collapses() {
    // 300 000 vertices at one point, or spread within one tolerance cell: a quadratic merge
    // would not finish (the bound only catches that, it measures nothing).
    let n = 300_000u32;
    for spread in [0.0, 1e-9] {
        let mut soup = PolygonSoup {
            positions: (0..n)
                .map(|i| [spread * f64::from(i % 1000) / 1000.0, 0.0, spread])
                .collect(),
            face_sizes: vec![3; (n / 3) as usize],
            indices: (0..n).collect(),
            ..PolygonSoup::default()
        };
        let start = std::time::Instant::now();
        let report = merge_vertices(&mut soup, Tolerance::Absolute(1e-6)).unwrap();
        assert!(start.elapsed().as_secs() < 60);
        assert_eq!(soup.positions.len(), 1);
        assert_eq!(soup.n_faces(), 0);
        assert_eq!(report.removed_faces.len(), (n / 3) as usize);
    }
}

#[test]
fn duplicate_faces_keep_the_first_in_either_orientation() {
    let mut soup = grid(2, 1, false, true);
    let n = soup.n_faces() as u32;
    // Face 0 again rotated, face 1 again reversed, face 0 a third time.
    let (f0, f1) = (soup.indices[0..3].to_vec(), soup.indices[3..6].to_vec());
    soup.indices.extend([
        f0[1], f0[2], f0[0], f1[2], f1[1], f1[0], f0[0], f0[1], f0[2],
    ]);
    soup.face_sizes.extend([3, 3, 3]);
    let report = remove_duplicate_faces(&mut soup).unwrap();
    assert_eq!(report.duplicate_faces, vec![[n, 0], [n + 1, 1], [n + 2, 0]]);
    assert_eq!(report.removed_faces, vec![n, n + 1, n + 2]);
    assert_eq!(soup, grid(2, 1, false, true));
    assert!(remove_duplicate_faces(&mut soup).unwrap().is_empty());
}

#[test]
fn unreferenced_vertices_go_with_a_map() {
    let mut soup = grid(1, 1, false, false);
    soup.positions.insert(0, [9.0; 3]);
    soup.positions.push([8.0; 3]);
    for v in &mut soup.indices {
        *v += 1;
    }
    let report = remove_unreferenced_vertices(&mut soup).unwrap();
    assert_eq!(report.removed_vertices, vec![0, 5]);
    assert_eq!(report.maps.vertices, vec![u32::MAX, 0, 1, 2, 3, u32::MAX]);
    assert_eq!(soup, grid(1, 1, false, false));
}

#[test]
fn small_components_by_face_count_and_by_diameter() {
    // A 4×4 grid (32 triangles) and a small far triangle of its own, and an unreferenced vertex
    // that must stay.
    let mut soup = grid(4, 4, false, true);
    let base = soup.positions.len() as u32;
    soup.positions.extend([
        [10.0, 0.0, 0.0],
        [10.1, 0.0, 0.0],
        [10.0, 0.1, 0.0],
        [7.0; 3],
    ]);
    soup.indices.extend([base, base + 1, base + 2]);
    soup.face_sizes.push(3);
    for small in [
        SmallComponents::FaceCount(1),
        SmallComponents::RelativeDiameter(0.1),
    ] {
        let mut repaired = soup.clone();
        let report = remove_small_components(&mut repaired, small).unwrap();
        assert_eq!(report.removed_faces, vec![32]);
        assert_eq!(report.removed_vertices, vec![base, base + 1, base + 2]);
        assert_eq!(repaired.positions.len(), base as usize + 1);
        assert!(
            remove_small_components(&mut repaired, small)
                .unwrap()
                .is_empty()
        );
    }
    let mut untouched = soup.clone();
    assert!(
        remove_small_components(&mut untouched, SmallComponents::FaceCount(0))
            .unwrap()
            .is_empty()
    );
    assert!(
        remove_small_components(&mut untouched, SmallComponents::RelativeDiameter(1.5)).is_err()
    );
    assert_eq!(untouched, soup);
}

/// An open grid cut along its middle column into two halves that do not share vertices.
fn cut_grid() -> PolygonSoup {
    let mut soup = grid(4, 3, false, true);
    let n = soup.positions.len() as u32;
    let copies: Vec<[f64; 3]> = soup.positions.clone();
    soup.positions.extend(copies);
    let mut first = 0;
    for &size in &soup.face_sizes {
        let face = first..first + size as usize;
        first = face.end;
        let right = soup.indices[face.clone()]
            .iter()
            .all(|&v| soup.positions[v as usize][0] >= 0.5);
        if right {
            for v in &mut soup.indices[face] {
                *v += n;
            }
        }
    }
    remove_unreferenced_vertices(&mut soup).unwrap();
    soup
}

#[test]
fn stitching_a_cut_grid_closes_the_cut() {
    let soup = cut_grid();
    let (mut mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    mesh.set_corner_uvs(
        &(0..mesh.n_halfedge_slots())
            .map(|h| [h as f64, 0.0])
            .collect::<Vec<_>>(),
    )
    .unwrap();
    assert_eq!(boundary_edges(&mesh), 2 * (4 + 3) + 2 * 3);
    let uvs_of_faces = |mesh: &Mesh| -> Vec<Vec<f64>> {
        (0..mesh.n_faces() as u32)
            .map(|f| {
                let h = mesh.face_halfedges()[f as usize];
                let start = HalfedgeId(h);
                let mut out = vec![];
                let mut h = start;
                loop {
                    out.push(mesh.corner_uvs().unwrap()[h.index()][0]);
                    h = mesh.next(h);
                    if h == start {
                        break;
                    }
                }
                out.sort_by(f64::total_cmp);
                out
            })
            .collect()
    };
    let uvs_before = uvs_of_faces(&mesh);
    let report = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.stitched_halfedges.len(), 3);
    assert_eq!(report.merged_vertices.len(), 4);
    assert_eq!(boundary_edges(&mesh), 2 * (4 + 3));
    assert_eq!(mesh.n_vertices(), 20);
    // Each face kept its corners' data.
    assert_eq!(uvs_of_faces(&mesh), uvs_before);
    // Idempotent.
    let again = mesh.clone();
    assert!(
        stitch_borders(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    assert_eq!(mesh, again);
}

#[test]
fn stitching_within_a_tolerance_and_refusing_three_sheets() {
    let mut soup = cut_grid();
    let n = soup.positions.len();
    for p in &mut soup.positions[n / 2..] {
        p[1] += 1e-9;
    }
    let (mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    let mut exact = mesh.clone();
    assert!(
        stitch_borders(&mut exact, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    let mut near = mesh.clone();
    let report = stitch_borders(&mut near, Tolerance::Absolute(1e-6)).unwrap();
    near.check().unwrap();
    assert_eq!(report.stitched_halfedges.len(), 3);

    // Three triangles on one edge: no pair is unique, nothing is stitched.
    let fan = PolygonSoup {
        positions: vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.5, -1.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.5, 0.0, 1.0],
        ],
        face_sizes: vec![3; 3],
        indices: (0..9).collect(),
        ..PolygonSoup::default()
    };
    let (mut mesh, _) = Mesh::from_soup(&fan, BuildPolicy::Strict).unwrap();
    let before = mesh.clone();
    assert!(
        stitch_borders(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    assert_eq!(mesh, before);
}

#[test]
fn stitching_that_would_double_an_edge_is_left_out() {
    // Two triangles a b c and b' a' c' on the same three points: gluing a b to b' a' would
    // also merge c with c' and give two edges a c; nothing may be stitched.
    let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let soup = PolygonSoup {
        positions: vec![p[0], p[1], p[2], p[1], p[0], p[2]],
        face_sizes: vec![3, 3],
        indices: vec![0, 1, 2, 3, 4, 5],
        ..PolygonSoup::default()
    };
    let (mut mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    let report = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    // The pairs a b / b' a' and the others all lead to a doubled edge or a repeated face
    // vertex somewhere; whatever is stitched must leave a valid mesh.
    assert!(report.stitched_halfedges.len() <= 3);
}

#[test]
fn the_capsule_closes_after_welding_and_stitching() {
    let mut soup = read_path(data_dir().join("broken/tm_capsule.obj")).unwrap();
    let weld = merge_vertices(&mut soup, Tolerance::EXACT).unwrap();
    assert_eq!(weld.merged_vertices.len(), 250);
    remove_unreferenced_vertices(&mut soup).unwrap();
    let (mut mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    let stitch = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(
        boundary_edges(&mesh),
        0,
        "{} stitched",
        stitch.stitched_halfedges.len()
    );

    // Without welding first, stitching alone closes the seam too.
    let soup = read_path(data_dir().join("broken/tm_capsule.obj")).unwrap();
    let (mut mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Skip).unwrap();
    let before = boundary_edges(&mesh);
    let stitch = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert!(boundary_edges(&mesh) < before);
    assert!(!stitch.stitched_halfedges.is_empty());
}

/// Every test model: the repairs in a row give a soup that builds into a valid mesh, run
/// twice they change nothing, and stitching keeps the mesh valid.
#[test]
fn every_test_model_repairs_to_a_valid_mesh() {
    for (_, name, mut soup) in test_models() {
        let steps = |soup: &mut PolygonSoup| -> Result<bool, RepairError> {
            let mut changed = !merge_vertices(soup, Tolerance::EXACT)?.is_empty();
            changed |= !remove_duplicate_faces(soup)?.is_empty();
            changed |= !remove_unreferenced_vertices(soup)?.is_empty();
            Ok(changed)
        };
        if steps(&mut soup).is_err() {
            // Out-of-range indices: refused, as documented.
            continue;
        }
        let settled = soup.clone();
        assert!(!steps(&mut soup).unwrap(), "{name}: second run changed it");
        assert_eq!(soup, settled);
        if let Ok((mut mesh, _)) = Mesh::from_soup(&soup, BuildPolicy::Repair) {
            stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
            mesh.check().unwrap_or_else(|e| panic!("{name}: {e}"));
            let settled = mesh.clone();
            assert!(
                stitch_borders(&mut mesh, Tolerance::EXACT)
                    .unwrap()
                    .is_empty()
            );
            assert_eq!(mesh, settled);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn repairs_are_idempotent_and_keep_corner_data(soup in lattice_soup(30), relative in 0.0..0.6f64) {
        let mut repaired = soup.clone();
        let report = merge_vertices(&mut repaired, Tolerance::Relative(relative)).unwrap();
        // Kept corners keep their uvs; the maps agree with what is left.
        let kept_faces = report.maps.faces.iter().filter(|&&f| f != u32::MAX).count();
        prop_assert_eq!(kept_faces, repaired.n_faces());
        prop_assert_eq!(
            report.maps.vertices.iter().filter(|&&v| v != u32::MAX).count(),
            repaired.positions.len()
        );
        let uvs = repaired.corner_uvs.clone().unwrap();
        prop_assert!(uvs.windows(2).all(|w| w[0][0] < w[1][0]));
        let mut settled = repaired.clone();
        prop_assert!(merge_vertices(&mut settled, Tolerance::Relative(relative)).unwrap().is_empty());
        prop_assert_eq!(&settled, &repaired);
        for _ in 0..2 {
            remove_duplicate_faces(&mut repaired).unwrap();
            remove_unreferenced_vertices(&mut repaired).unwrap();
            remove_small_components(&mut repaired, SmallComponents::FaceCount(1)).unwrap();
        }
        let settled = repaired.clone();
        prop_assert!(remove_duplicate_faces(&mut repaired).unwrap().is_empty());
        prop_assert!(remove_unreferenced_vertices(&mut repaired).unwrap().is_empty());
        prop_assert!(remove_small_components(&mut repaired, SmallComponents::FaceCount(1)).unwrap().is_empty());
        prop_assert_eq!(&repaired, &settled);
        if let Ok((mesh, _)) = Mesh::from_soup(&repaired, BuildPolicy::Repair) {
            mesh.check().unwrap();
        }
    }

    #[test]
    fn stitching_keeps_every_invariant(soup in lattice_soup(30), cut in 0usize..3) {
        // Build with vertex copies so that there are borders to stitch, cut some more by
        // unwelding every `cut`-th face.
        let mut unwelded_soup = soup.clone();
        if cut > 0 {
            let mut first = 0;
            for (f, &size) in soup.face_sizes.iter().enumerate() {
                if f % cut == 0 {
                    for c in first..first + size as usize {
                        unwelded_soup.positions.push(soup.positions[soup.indices[c] as usize]);
                        unwelded_soup.indices[c] = unwelded_soup.positions.len() as u32 - 1;
                    }
                }
                first += size as usize;
            }
        }
        if let Ok((mut mesh, _)) = Mesh::from_soup(&unwelded_soup, BuildPolicy::Repair) {
            let n_faces = mesh.n_faces();
            let report = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
            mesh.check().unwrap();
            prop_assert_eq!(mesh.n_faces(), n_faces);
            prop_assert_eq!(mesh.n_edges() + report.stitched_halfedges.len(), report.maps.edges.len());
            let settled = mesh.clone();
            prop_assert!(stitch_borders(&mut mesh, Tolerance::EXACT).unwrap().is_empty());
            prop_assert_eq!(&mesh, &settled);
        }
    }
}
