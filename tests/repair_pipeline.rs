//! The repair pipeline (`halfwing::repair::repair_mesh`): on every broken and open test model it
//! gives a mesh that passes `check()`, survives a write and a strict re-read, is manifold,
//! oriented and outward, closed wherever the input allows, and accounts for every input vertex
//! and face.

mod mesh_support;

use halfwing::doctor::{DoctorOptions, DoctorReport};
use halfwing::io::MeshFormat;
use halfwing::io::{read_bytes, read_path, write_obj};
use halfwing::mesh::{BuildPolicy, Mesh};
use halfwing::repair::{
    FaceFate, RepairError, RepairFates, RepairOptions, SmallComponents, Tolerance, VertexFate,
    repair_mesh,
};
use halfwing::soup::PolygonSoup;
use mesh_support::{data_dir, grid};

/// Broken models whose repair keeps a boundary, and why (the pipeline fills no hole).
const STAYS_OPEN: &[(&str, &str)] = &[
    ("c3d_teapot.obj", "the teapot's surface has openings"),
    ("cgal_degtri_sliding.off", "an open patch"),
    (
        "cgal_non_manifold_face_graph.off",
        "cutting its non-manifold edges leaves borders",
    ),
    (
        "cgal_tetra_intersected_by_triangle.off",
        "the lone triangle is an open component",
    ),
    ("cgaltest_caps_and_needles.off", "an open patch"),
    ("cgaltest_degtri_four.off", "an open patch"),
    (
        "cgaltest_nm_edges_simple.off",
        "cutting its non-manifold edges leaves borders",
    ),
    (
        "cgaltest_non_manifold_vertex.off",
        "open sheets meeting at a vertex",
    ),
    ("cgaltest_overlapping_triangles.off", "open triangles"),
    (
        "cgaltest_three_triangles_sharing_a_vertex.off",
        "open triangles",
    ),
    ("gc_fan3.obj", "an open fan"),
    ("gc_moebius.obj", "a Moebius strip has a border"),
    ("igl_truck.obj", "open parts"),
    (
        "tm_joined_tetrahedra.obj",
        "cutting the shared non-manifold edges leaves borders",
    ),
    (
        "tm_notenoughindices.obj",
        "the faces with too few corners leave a hole",
    ),
];

/// The fates sum to the input, name output elements that exist, and output elements are each
/// named once (by a kept input element or an added one).
fn check_accounting(input: &PolygonSoup, mesh: &Mesh, fates: &RepairFates) {
    let counts = fates.counts();
    assert_eq!(fates.vertices.len(), input.positions.len());
    assert_eq!(fates.faces.len(), input.n_faces());
    assert_eq!(
        counts.kept_vertices + counts.merged_vertices + counts.removed_vertices,
        input.positions.len()
    );
    assert_eq!(
        counts.kept_vertices + counts.added_vertices,
        mesh.n_vertices()
    );
    assert_eq!(counts.kept_faces + counts.removed_faces, input.n_faces());
    assert_eq!(counts.kept_faces + counts.added_faces, mesh.n_faces());
    let mut named = vec![0u32; mesh.n_vertices()];
    for fate in &fates.vertices {
        match *fate {
            VertexFate::Kept(v) => named[v as usize] += 1,
            VertexFate::Merged { into } => assert!((into as usize) < mesh.n_vertices()),
            VertexFate::Removed(_) => {}
        }
    }
    for &[v, source] in &fates.added_vertices {
        named[v as usize] += 1;
        assert!((source as usize) < input.positions.len());
    }
    assert!(
        named.iter().all(|&n| n == 1),
        "every output vertex named once"
    );
    let mut faces = vec![0u32; mesh.n_faces()];
    for fate in &fates.faces {
        if let FaceFate::Kept { face, .. } = *fate {
            faces[face as usize] += 1;
        }
    }
    for &f in &fates.added_faces {
        faces[f as usize] += 1;
    }
    assert!(
        faces.iter().all(|&n| n == 1),
        "every output face named once"
    );
}

/// A unit cube of quads without its top: one hole of four edges.
fn open_box() -> PolygonSoup {
    let positions: Vec<[f64; 3]> = (0..8)
        .map(|i| [f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)])
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [0, 1, 5, 4],
        [1, 3, 7, 5],
        [3, 2, 6, 7],
        [2, 0, 4, 6],
    ];
    PolygonSoup {
        positions,
        face_sizes: vec![4; quads.len()],
        indices: quads.iter().flatten().copied().collect(),
        corner_normals: None,
        corner_uvs: None,
    }
}

#[test]
fn holes_are_filled_only_when_asked_and_the_new_faces_are_accounted_for() {
    let soup = open_box();
    let (mesh, fates) = repair_mesh(&soup, &RepairOptions::default()).unwrap();
    check_accounting(&soup, &mesh, &fates);
    assert_eq!(mesh.boundary_loops().len(), 1, "left open by default");
    assert_eq!((fates.filled_holes, fates.added_faces.len()), (0, 0));

    let too_small = RepairOptions::default().fill_holes_up_to(3);
    let (mesh, fates) = repair_mesh(&soup, &too_small).unwrap();
    assert_eq!(
        mesh.boundary_loops().len(),
        1,
        "a hole of 4 edges is beyond 3"
    );
    assert_eq!(fates.filled_holes, 0);

    let options = RepairOptions::default().fill_holes_up_to(4);
    let report = repair_and_check("open box", &soup, &options);
    assert!(report.is_closed());
    let (mesh, fates) = repair_mesh(&soup, &options).unwrap();
    assert_eq!((fates.filled_holes, fates.refused_holes), (1, 0));
    assert_eq!(fates.added_faces.len(), 2);
    assert_eq!(fates.counts().added_faces, 2);
    assert_eq!(mesh.n_faces(), 7);
    assert!(mesh.boundary_loops().is_empty());
}

#[test]
fn an_open_model_comes_out_closed_when_holes_are_filled() {
    let path = data_dir().join("open").join("pmp_hemisphere.off");
    let soup = read_path(&path).unwrap();
    let options = RepairOptions::default().fill_holes_up_to(usize::MAX);
    let report = repair_and_check("pmp_hemisphere.off", &soup, &options);
    assert!(report.is_closed());
    let (mesh, fates) = repair_mesh(&soup, &options).unwrap();
    assert_eq!(fates.filled_holes, 1);
    assert_eq!(
        fates.counts().kept_faces + fates.added_faces.len(),
        mesh.n_faces()
    );
}

fn doctor(soup: &PolygonSoup) -> DoctorReport {
    halfwing::doctor::examine(&soup.as_face_list(), &DoctorOptions::default()).unwrap()
}

/// Repairs `input` and checks everything but closedness; gives the output's doctor report.
fn repair_and_check(name: &str, input: &PolygonSoup, options: &RepairOptions) -> DoctorReport {
    let (mesh, fates) = repair_mesh(input, options).unwrap_or_else(|e| panic!("{name}: {e}"));
    mesh.check().unwrap_or_else(|e| panic!("{name}: {e}"));
    check_accounting(input, &mesh, &fates);
    let soup = mesh.to_soup();
    let mut bytes = Vec::new();
    write_obj(&mut bytes, &soup).unwrap();
    let reread = read_bytes(MeshFormat::Obj, &bytes).unwrap();
    let (again, _) = Mesh::from_soup(&reread, BuildPolicy::Strict)
        .unwrap_or_else(|e| panic!("{name}: strict re-read: {e}"));
    again.check().unwrap();
    assert_eq!(again.n_faces(), mesh.n_faces(), "{name}");
    let report = doctor(&soup);
    assert!(report.is_manifold(), "{name}: manifold");
    assert!(report.is_oriented(), "{name}: oriented");
    let inward = report
        .components
        .iter()
        .any(|c| c.closed && c.outward == Some(false));
    assert!(!inward, "{name}: a closed component faces inward");
    report
}

fn models(dir: &str) -> Vec<(String, PolygonSoup)> {
    let dir = data_dir().join(dir);
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    paths.sort();
    paths
        .into_iter()
        .filter_map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            // Files the readers refuse have no face list to repair (tests/io_data.rs).
            read_path(&p).ok().map(|soup| (name, soup))
        })
        .collect()
}

#[test]
fn every_broken_model_repairs_to_a_clean_closed_mesh_where_it_can() {
    let models = models("broken");
    assert!(models.len() >= 20, "{} broken models read", models.len());
    let mut open = Vec::new();
    for (name, soup) in &models {
        let report = repair_and_check(name, soup, &RepairOptions::default());
        if !report.is_closed() {
            open.push(name.as_str());
        }
    }
    let expected: Vec<&str> = STAYS_OPEN.iter().map(|(n, _)| *n).collect();
    assert_eq!(open, expected, "broken models that stay open");
}

#[test]
fn every_open_model_repairs_to_a_clean_mesh_with_its_holes() {
    for (name, soup) in &models("open") {
        let before = doctor(soup);
        let report = repair_and_check(name, soup, &RepairOptions::default());
        // Nothing fills holes: the boundary stays, but stitching never opens new ones.
        assert!(
            report.boundary_loops.len() <= before.boundary_loops.len().max(1),
            "{name}"
        );
    }
}

#[test]
fn an_unwelded_closed_grid_welds_into_one_closed_mesh() {
    let closed = grid(6, 5, true, true);
    let unwelded = PolygonSoup {
        positions: closed
            .indices
            .iter()
            .map(|&v| closed.positions[v as usize])
            .collect(),
        face_sizes: closed.face_sizes.clone(),
        indices: (0..closed.indices.len() as u32).collect(),
        corner_normals: None,
        corner_uvs: None,
    };
    let (mesh, fates) = repair_mesh(&unwelded, &RepairOptions::default()).unwrap();
    check_accounting(&unwelded, &mesh, &fates);
    assert_eq!(mesh.n_vertices(), closed.positions.len());
    assert_eq!(
        fates.counts().merged_vertices,
        unwelded.positions.len() - closed.positions.len()
    );
    assert!(doctor(&mesh.to_soup()).is_closed());
}

#[test]
fn duplicates_name_the_face_they_duplicate_and_small_components_go_when_asked() {
    let mut soup = grid(3, 3, false, true);
    let first = soup.indices[..3].to_vec();
    soup.face_sizes.push(3);
    soup.indices.extend([first[2], first[1], first[0]]);
    let n = soup.positions.len() as u32;
    soup.positions
        .extend([[10.0, 0.0, 0.0], [11.0, 0.0, 0.0], [10.0, 1.0, 0.0]]);
    soup.face_sizes.push(3);
    soup.indices.extend([n, n + 1, n + 2]);
    let options = RepairOptions {
        small_components: Some(SmallComponents::FaceCount(1)),
        ..RepairOptions::default()
    };
    let (mesh, fates) = repair_mesh(&soup, &options).unwrap();
    check_accounting(&soup, &mesh, &fates);
    let last = soup.n_faces() - 1;
    assert_eq!(
        fates.faces[last - 1],
        FaceFate::Removed(halfwing::repair::Removal::Duplicate { of: 0 })
    );
    assert_eq!(
        fates.faces[last],
        FaceFate::Removed(halfwing::repair::Removal::SmallComponent)
    );
    for v in n..n + 3 {
        assert_eq!(
            fates.vertices[v as usize],
            VertexFate::Removed(halfwing::repair::Removal::SmallComponent)
        );
    }
}

#[test]
fn bad_options_and_malformed_lists_are_refused() {
    let soup = grid(2, 2, false, true);
    let bad = RepairOptions {
        merge_tolerance: Tolerance::Absolute(f64::NAN),
        ..RepairOptions::default()
    };
    assert!(matches!(
        repair_mesh(&soup, &bad),
        Err(RepairError::BadTolerance { .. })
    ));
    let mut broken = soup.clone();
    broken.indices.push(0);
    assert!(matches!(
        repair_mesh(&broken, &RepairOptions::default()),
        Err(RepairError::MalformedList(_))
    ));
    let mut out_of_range = soup;
    out_of_range.indices[0] = 999;
    assert!(matches!(
        repair_mesh(&out_of_range, &RepairOptions::default()),
        Err(RepairError::IndexOutOfRange { .. })
    ));
}
