//! The repairs of a soup's topology (`orient_faces`, `repair_non_manifold_edges`,
//! `split_non_manifold_vertices`): constructed cases with the exact elements each must change,
//! bad input (refused, soup unchanged), every test model, and their properties: corner data
//! follows its corner, a second run changes nothing, clean input is left as it is, and after
//! the three no edge or vertex is non-manifold and the result builds into a valid mesh.

mod mesh_support;

use halfwing::mesh::{BuildPolicy, Mesh};
use halfwing::repair::{
    NonManifoldEdges, RepairError, RepairReport, orient_faces, repair_non_manifold_edges,
    split_non_manifold_vertices,
};
use halfwing::soup::{PolygonSoup, diagnose};
use mesh_support::grid;
use mesh_support::soups::{lattice_soup, test_models};
use proptest::prelude::*;

/// The faces of a tetrahedron on `v` (4 vertices), facing outward when `v` is laid out as
/// `tetrahedron_positions` gives.
fn tetrahedron_faces(v: [u32; 4]) -> Vec<u32> {
    vec![
        v[0], v[2], v[1], v[0], v[1], v[3], v[1], v[2], v[3], v[2], v[0], v[3],
    ]
}

/// A soup of `faces` (triangles) on `positions`, each corner's uv its corner index.
fn triangles(positions: Vec<[f64; 3]>, indices: Vec<u32>) -> PolygonSoup {
    PolygonSoup {
        positions,
        face_sizes: vec![3; indices.len() / 3],
        corner_uvs: Some((0..indices.len()).map(|c| [c as f64, 0.0]).collect()),
        indices,
        corner_normals: None,
    }
}

/// Two outward tetrahedra sharing the edge 0–1 (four faces on it).
fn tetrahedra_on_an_edge() -> PolygonSoup {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 1.0, 0.0],
        [0.5, 0.3, 1.0],
        [0.5, -1.0, 0.0],
        [0.5, -0.3, -1.0],
    ];
    let mut indices = tetrahedron_faces([0, 1, 2, 3]);
    indices.extend(tetrahedron_faces([0, 1, 4, 5]));
    triangles(positions, indices)
}

/// Two outward tetrahedra touching at vertex 0.
fn tetrahedra_on_a_vertex() -> PolygonSoup {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [-1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, -1.0],
    ];
    let mut indices = tetrahedron_faces([0, 1, 2, 3]);
    indices.extend(tetrahedron_faces([0, 5, 4, 6]));
    triangles(positions, indices)
}

/// Corners' positions and uvs, face by face: what a repair that only moves corners to copies
/// must keep.
fn corner_data(soup: &PolygonSoup) -> Vec<([f64; 3], [f64; 2])> {
    let uvs = soup.corner_uvs.as_ref().unwrap();
    soup.indices
        .iter()
        .zip(uvs)
        .map(|(&v, &uv)| (soup.positions[v as usize], uv))
        .collect()
}

/// Every face range of a soup.
fn face_ranges(soup: &PolygonSoup) -> Vec<std::ops::Range<usize>> {
    let mut first = 0;
    soup.face_sizes
        .iter()
        .map(|&size| {
            first += size as usize;
            first - size as usize..first
        })
        .collect()
}

/// The three repairs in the order a pipeline runs them, with whether anything changed: orient
/// first (cutting separates faces only an inconsistent edge joins), and again last (removing
/// faces on a non-manifold edge can leave two faces on it that disagree).
fn topology_repairs(soup: &mut PolygonSoup, how: NonManifoldEdges) -> Result<bool, RepairError> {
    let mut changed = !orient_faces(soup)?.is_empty();
    changed |= !repair_non_manifold_edges(soup, how)?.is_empty();
    changed |= !split_non_manifold_vertices(soup)?.is_empty();
    changed |= !orient_faces(soup)?.is_empty();
    Ok(changed)
}

/// A repair of a soup, options fixed.
type SoupRepair = fn(&mut PolygonSoup) -> Result<RepairReport, RepairError>;

/// Each repair run a second time changes nothing.
fn assert_each_settled(soup: &PolygonSoup, how: NonManifoldEdges) {
    let mut again = soup.clone();
    assert!(orient_faces(&mut again).unwrap().is_empty());
    assert!(
        repair_non_manifold_edges(&mut again, how)
            .unwrap()
            .is_empty()
    );
    assert!(split_non_manifold_vertices(&mut again).unwrap().is_empty());
    assert_eq!(&again, soup);
}

fn assert_strict_build(soup: &PolygonSoup) -> Mesh {
    let (mesh, _) = Mesh::from_soup(soup, BuildPolicy::Strict).unwrap();
    mesh.check().unwrap();
    mesh
}

#[test]
fn cutting_two_tetrahedra_on_an_edge_keeps_both_closed() {
    let mut soup = tetrahedra_on_an_edge();
    let before = corner_data(&soup);
    assert_eq!(
        diagnose(&soup.as_face_list())
            .unwrap()
            .non_manifold_edges
            .len(),
        1
    );
    let report = repair_non_manifold_edges(&mut soup, NonManifoldEdges::Cut).unwrap();
    // The second tetrahedron gets copies of both ends of the edge.
    assert_eq!(report.vertex_copies, vec![0, 1]);
    assert_eq!(report.maps.vertices, (0..6).collect::<Vec<_>>());
    assert_eq!(report.maps.faces, (0..8).collect::<Vec<_>>());
    assert!(report.removed_faces.is_empty());
    assert_eq!(soup.positions.len(), 8);
    assert_eq!(corner_data(&soup), before);
    let mesh = assert_strict_build(&soup);
    assert_eq!(mesh.n_vertices(), 8);
    assert!(mesh.boundary_loops().is_empty());
    let settled = soup.clone();
    assert!(
        repair_non_manifold_edges(&mut soup, NonManifoldEdges::Cut)
            .unwrap()
            .is_empty()
    );
    assert_eq!(soup, settled);
}

#[test]
fn removing_faces_keeps_one_face_each_way_on_the_edge() {
    let mut soup = tetrahedra_on_an_edge();
    let report = repair_non_manifold_edges(&mut soup, NonManifoldEdges::RemoveFaces).unwrap();
    // Faces on the edge 0–1: 0 (1→0... as 0,2,1), 1 (0→1), 4 and 5 of the second tetrahedron;
    // the first two claim both directions.
    assert_eq!(report.removed_faces, vec![4, 5]);
    assert_eq!(
        report.maps.faces,
        vec![0, 1, 2, 3, u32::MAX, u32::MAX, 4, 5]
    );
    assert!(report.vertex_copies.is_empty());
    assert_eq!(soup.n_faces(), 6);
    let uvs = soup.corner_uvs.as_ref().unwrap();
    assert_eq!(uvs[12][0], 18.0, "face 6 became face 4 with its uvs");
    assert!(
        diagnose(&soup.as_face_list())
            .unwrap()
            .non_manifold_edges
            .is_empty()
    );
    assert!(
        repair_non_manifold_edges(&mut soup, NonManifoldEdges::RemoveFaces)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn three_triangles_on_an_edge_keep_two_joined() {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 1.0, 0.0],
        [0.5, -1.0, 0.0],
        [0.5, 0.0, 1.0],
    ];
    let mut soup = triangles(positions, vec![0, 1, 2, 1, 0, 3, 0, 1, 4]);
    let report = repair_non_manifold_edges(&mut soup, NonManifoldEdges::Cut).unwrap();
    assert_eq!(report.vertex_copies, vec![0, 1]);
    assert_eq!(&soup.indices[..6], &[0, 1, 2, 1, 0, 3]);
    assert_eq!(&soup.indices[6..], &[5, 6, 4]);
    assert_strict_build(&soup);
}

#[test]
fn splitting_gives_each_fan_a_vertex() {
    let mut soup = tetrahedra_on_a_vertex();
    let before = corner_data(&soup);
    assert_eq!(
        diagnose(&soup.as_face_list())
            .unwrap()
            .non_manifold_vertices,
        vec![0]
    );
    let report = split_non_manifold_vertices(&mut soup).unwrap();
    assert_eq!(report.vertex_copies, vec![0]);
    assert_eq!(report.maps.vertices, (0..7).collect::<Vec<_>>());
    assert_eq!(soup.positions[7], soup.positions[0]);
    assert_eq!(corner_data(&soup), before);
    // The second tetrahedron's corners at 0 moved to the copy; the first kept 0.
    assert!(soup.indices[..12].contains(&0) && !soup.indices[..12].contains(&7));
    assert!(soup.indices[12..].contains(&7) && !soup.indices[12..].contains(&0));
    assert_strict_build(&soup);
    assert!(split_non_manifold_vertices(&mut soup).unwrap().is_empty());

    // A bow tie: two triangles touching at a vertex.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [-1.0, -1.0, 0.0],
    ];
    let mut bow_tie = triangles(positions, vec![0, 1, 2, 0, 3, 4]);
    let report = split_non_manifold_vertices(&mut bow_tie).unwrap();
    assert_eq!(report.vertex_copies, vec![0]);
    assert_eq!(bow_tie.indices, vec![0, 1, 2, 5, 3, 4]);
}

/// Two non-planar quads on the corners of a tetrahedron, each the other reversed: a closed
/// pillow. Read from the same corner, both quads take the same diagonal, so the pillow encloses
/// nothing and is left as given, either way round (a fan from each quad's first corner once
/// took different diagonals, gave it a volume, flipped it, and flipped it back on a second run).
#[test]
fn a_pillow_of_two_bent_quads_encloses_nothing() {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
    ];
    for indices in [vec![1, 2, 3, 0, 2, 1, 0, 3], vec![0, 3, 2, 1, 3, 0, 1, 2]] {
        let mut pillow = PolygonSoup {
            face_sizes: vec![4, 4],
            ..triangles(positions.clone(), indices)
        };
        assert!(orient_faces(&mut pillow).unwrap().is_empty());
    }
}

#[test]
fn orienting_flips_the_minority_and_turns_closed_components_outward() {
    // One face of a tetrahedron reversed: that face is reoriented, uvs reversed with it.
    let mut soup = tetrahedra_on_a_vertex();
    soup.indices[3..6].reverse();
    soup.corner_uvs.as_mut().unwrap()[3..6].reverse();
    let before = corner_data(&soup);
    let report = orient_faces(&mut soup).unwrap();
    assert_eq!(report.reoriented_faces, vec![1]);
    let after = corner_data(&soup);
    let mut reversed = before[3..6].to_vec();
    reversed.reverse();
    assert_eq!(after[3..6], reversed[..]);
    assert_eq!(after[..3], before[..3]);
    assert_eq!(soup.indices[3..6], [0, 1, 3]);

    // A whole tetrahedron inside out: every face of it turns.
    let mut soup = tetrahedra_on_a_vertex();
    for f in 4..8 {
        soup.indices[3 * f..3 * f + 3].reverse();
    }
    let report = orient_faces(&mut soup).unwrap();
    assert_eq!(report.reoriented_faces, vec![4, 5, 6, 7]);
    let mut expected = tetrahedra_on_a_vertex();
    expected.corner_uvs.as_mut().unwrap()[12..]
        .chunks_mut(3)
        .for_each(<[_]>::reverse);
    assert_eq!(soup, expected);
    assert!(orient_faces(&mut soup).unwrap().is_empty());

    // An open grid with every third face reversed: only those turn back.
    let clean = grid(5, 4, false, true);
    let mut soup = clean.clone();
    let ranges = face_ranges(&soup);
    let turned: Vec<u32> = (0..soup.n_faces() as u32).filter(|f| f % 3 == 1).collect();
    for &f in &turned {
        soup.indices[ranges[f as usize].clone()].reverse();
    }
    let report = orient_faces(&mut soup).unwrap();
    assert_eq!(report.reoriented_faces, turned);
    assert_eq!(soup.indices, clean.indices);
}

#[test]
fn a_mobius_band_keeps_one_disagreeing_edge() {
    // A strip of 6 quads whose ends are glued with a half twist.
    let n = 6u32;
    let mut positions = Vec::new();
    for i in 0..n {
        let a = f64::from(i) / f64::from(n) * std::f64::consts::TAU;
        let (half_cos, half_sin) = ((a / 2.0).cos(), (a / 2.0).sin());
        for s in [-0.3, 0.3] {
            positions.push([
                (1.0 + s * half_cos) * a.cos(),
                (1.0 + s * half_cos) * a.sin(),
                s * half_sin,
            ]);
        }
    }
    let mut indices = Vec::new();
    for i in 0..n {
        let (a, b) = (2 * i, 2 * i + 1);
        let (c, d) = if i + 1 == n {
            (1, 0)
        } else {
            (2 * i + 2, 2 * i + 3)
        };
        indices.extend([a, c, d, b]);
    }
    let mut soup = PolygonSoup {
        positions,
        face_sizes: vec![4; n as usize],
        indices,
        ..PolygonSoup::default()
    };
    orient_faces(&mut soup).unwrap();
    let settled = soup.clone();
    assert!(orient_faces(&mut soup).unwrap().is_empty());
    assert_eq!(soup, settled);
    assert_eq!(
        diagnose(&soup.as_face_list())
            .unwrap()
            .inconsistent_edges
            .len(),
        1
    );
}

#[test]
fn bad_input_is_refused_and_left_unchanged() {
    let index_out_of_range = triangles(vec![[0.0; 3]; 3], vec![0, 1, 3]);
    let sizes_disagree = PolygonSoup {
        positions: vec![[0.0; 3]; 3],
        face_sizes: vec![4],
        indices: vec![0, 1, 2],
        ..PolygonSoup::default()
    };
    let mut uvs_disagree = tetrahedra_on_an_edge();
    uvs_disagree.corner_uvs.as_mut().unwrap().pop();
    for bad in [index_out_of_range, sizes_disagree, uvs_disagree] {
        let repairs: [SoupRepair; 4] = [
            orient_faces,
            |s| repair_non_manifold_edges(s, NonManifoldEdges::Cut),
            |s| repair_non_manifold_edges(s, NonManifoldEdges::RemoveFaces),
            split_non_manifold_vertices,
        ];
        for repair in repairs {
            let mut soup = bad.clone();
            assert!(matches!(
                repair(&mut soup),
                Err(RepairError::MalformedList(_) | RepairError::IndexOutOfRange { .. })
            ));
            assert_eq!(soup, bad);
        }
    }
}

#[test]
fn empty_and_all_malformed_soups_change_nothing() {
    let all_malformed = PolygonSoup {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [f64::INFINITY; 3]],
        face_sizes: vec![2, 3, 4],
        indices: vec![0, 1, 0, 0, 1, 2, 2, 2, 2],
        ..PolygonSoup::default()
    };
    for soup in [PolygonSoup::default(), all_malformed] {
        for how in [NonManifoldEdges::Cut, NonManifoldEdges::RemoveFaces] {
            let mut repaired = soup.clone();
            assert!(!topology_repairs(&mut repaired, how).unwrap());
            assert_eq!(repaired, soup);
        }
    }
}

#[test]
fn non_finite_positions_are_carried_along() {
    // Two triangles touching at a vertex with a NaN coordinate: split like any other, and the
    // copy keeps the NaN (builds then leave its faces out).
    let positions = vec![
        [f64::NAN, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [-1.0, -1.0, f64::INFINITY],
    ];
    let mut soup = triangles(positions, vec![0, 1, 2, 0, 3, 4]);
    assert!(orient_faces(&mut soup).unwrap().is_empty());
    let report = split_non_manifold_vertices(&mut soup).unwrap();
    assert_eq!(report.vertex_copies, vec![0]);
    assert!(soup.positions[5][0].is_nan());
}

/// A clean closed model: cutting and splitting change nothing, and orienting turns inward
/// components outward, so that it and the model reversed face by face turn complementary sets
/// of faces (the outward orientation is the only one).
fn assert_clean_closed_model_only_turns_outward(model: &PolygonSoup, name: &str) {
    for how in [NonManifoldEdges::Cut, NonManifoldEdges::RemoveFaces] {
        assert!(
            repair_non_manifold_edges(&mut model.clone(), how)
                .unwrap()
                .is_empty()
        );
    }
    assert!(
        split_non_manifold_vertices(&mut model.clone())
            .unwrap()
            .is_empty()
    );
    let mut oriented = model.clone();
    let turned = orient_faces(&mut oriented).unwrap().reoriented_faces;
    let mut reversed = model.clone();
    for range in face_ranges(model) {
        reversed.indices[range].reverse();
    }
    let turned_back = orient_faces(&mut reversed).unwrap().reoriented_faces;
    let mut both: Vec<u32> = turned.iter().chain(&turned_back).copied().collect();
    both.sort_unstable();
    assert_eq!(
        both,
        (0..model.n_faces() as u32).collect::<Vec<_>>(),
        "{name}"
    );
    assert_eq!(oriented.indices, reversed.indices, "{name}");
}

/// Every test model: the three repairs give a soup without non-manifold edges or vertices
/// that builds (Repair) into a valid mesh; a second run changes nothing; closed clean models
/// are left as they are.
#[test]
fn every_test_model_settles_and_clean_ones_are_untouched() {
    for (group, name, original) in test_models() {
        for how in [NonManifoldEdges::Cut, NonManifoldEdges::RemoveFaces] {
            let mut soup = original.clone();
            let Ok(changed) = topology_repairs(&mut soup, how) else {
                // Out-of-range indices: refused, as documented.
                continue;
            };
            let clean = diagnose(&original.as_face_list()).unwrap();
            if group == "closed"
                && !clean.has_invalid_input()
                && !clean.has_edge_defects()
                && clean.non_manifold_vertices.is_empty()
            {
                assert_clean_closed_model_only_turns_outward(&original, &name);
            } else if !changed {
                assert_eq!(soup, original);
            }
            let found = diagnose(&soup.as_face_list()).unwrap();
            assert!(found.non_manifold_edges.is_empty(), "{name}");
            assert!(found.non_manifold_vertices.is_empty(), "{name}");
            assert_each_settled(&soup, how);
            let settled = soup.clone();
            assert!(
                !topology_repairs(&mut soup, how).unwrap(),
                "{name}: second run"
            );
            assert_eq!(soup, settled);
            if let Ok((mesh, _)) = Mesh::from_soup(&soup, BuildPolicy::Repair) {
                mesh.check().unwrap_or_else(|e| panic!("{name}: {e}"));
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn topology_repairs_settle_and_keep_corner_data(soup in lattice_soup(14), remove in any::<bool>()) {
        let how = if remove { NonManifoldEdges::RemoveFaces } else { NonManifoldEdges::Cut };
        let mut repaired = soup.clone();

        // Orienting reverses whole faces, corner data along.
        let report = orient_faces(&mut repaired).unwrap();
        let (before, after) = (corner_data(&soup), corner_data(&repaired));
        for (f, range) in face_ranges(&soup).into_iter().enumerate() {
            let mut expected = before[range.clone()].to_vec();
            if report.reoriented_faces.binary_search(&(f as u32)).is_ok() {
                expected.reverse();
            }
            prop_assert_eq!(&after[range], &expected[..]);
        }

        // Cutting and splitting move corners to copies at the same position.
        let oriented = corner_data(&repaired);
        let report = repair_non_manifold_edges(&mut repaired, how).unwrap();
        if remove {
            prop_assert_eq!(report.maps.faces.iter().filter(|&&f| f != u32::MAX).count(), repaired.n_faces());
        } else {
            prop_assert_eq!(&corner_data(&repaired), &oriented);
            prop_assert_eq!(repaired.positions.len(), soup.positions.len() + report.vertex_copies.len());
        }
        let cut = corner_data(&repaired);
        let n_vertices = repaired.positions.len();
        let report = split_non_manifold_vertices(&mut repaired).unwrap();
        prop_assert_eq!(&corner_data(&repaired), &cut);
        prop_assert_eq!(repaired.positions.len(), n_vertices + report.vertex_copies.len());

        // Each repair alone: a second run changes nothing.
        let repairs: [&dyn Fn(&mut PolygonSoup) -> RepairReport; 3] = [
            &|s| orient_faces(s).unwrap(),
            &|s| repair_non_manifold_edges(s, how).unwrap(),
            &|s| split_non_manifold_vertices(s).unwrap(),
        ];
        for repair in repairs {
            let mut once = soup.clone();
            repair(&mut once);
            let mut twice = once.clone();
            prop_assert!(repair(&mut twice).is_empty());
            prop_assert_eq!(&twice, &once);
        }

        orient_faces(&mut repaired).unwrap();
        assert_each_settled(&repaired, how);
        let found = diagnose(&repaired.as_face_list()).unwrap();
        prop_assert!(found.non_manifold_edges.is_empty());
        prop_assert!(found.non_manifold_vertices.is_empty());
        let settled = repaired.clone();
        prop_assert!(!topology_repairs(&mut repaired, how).unwrap());
        prop_assert_eq!(&repaired, &settled);
        if let Ok((mesh, _)) = Mesh::from_soup(&repaired, BuildPolicy::Repair) {
            mesh.check().unwrap();
        }
        // With nothing malformed and every edge agreeing, a strict build takes it as it is.
        if !found.has_invalid_input() && !found.has_edge_defects() {
            assert_strict_build(&repaired);
        }
    }
}
