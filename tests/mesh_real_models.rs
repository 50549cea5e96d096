//! Seed 004's loops (sides of a face, star of a vertex, faces around a vertex, adjacent faces,
//! boundary walk), written with the raw navigation exactly as the slides do, on the real models
//! of the test data set; and the build's counts and diagnostics against the data manifest.

mod mesh_support;

use halfwing::mesh::{BuildPolicy, FaceId, Mesh, VertexId};
use mesh_support::{data_dir, load};

fn build(relative: &str, policy: BuildPolicy) -> (Mesh, halfwing::soup::Diagnostic) {
    let soup = load(&data_dir().join(relative));
    Mesh::from_face_list(&soup.as_face_list(), policy).unwrap_or_else(|e| panic!("{relative}: {e}"))
}

/// Seed 004's loops, against the circulators and the manifest's counts.
fn seed_loops_agree(mesh: &Mesh) {
    for f in 0..mesh.n_faces() as u32 {
        // "conta quanti lati ha una faccia": do { lati++; i = next(i) } while (i != start)
        let start = mesh.face_halfedge(FaceId(f));
        let (mut i, mut sides, mut adjacent) = (start, 0, 0);
        loop {
            sides += 1;
            if !mesh.is_boundary_halfedge(mesh.twin(i)) {
                adjacent += 1; // "quante facce adiacenti"
            }
            i = mesh.next(i);
            if i == start {
                break;
            }
        }
        assert_eq!(sides, mesh.face_degree(FaceId(f)));
        assert_eq!(adjacent, mesh.face_faces(FaceId(f)).count());
    }
    for v in 0..mesh.n_vertices() as u32 {
        let v = VertexId(v);
        let start = mesh.vertex_halfedge(v);
        if !start.is_valid() {
            continue;
        }
        // "stella di un vertice": do { i = opp(i); vj = v(i); i = next(i) } while (i != start)
        // walks clockwise; the circulator walks counter-clockwise: same set, reversed order.
        let (mut i, mut star, mut faces) = (start, Vec::new(), Vec::new());
        loop {
            if mesh.face(i).is_valid() {
                faces.push(mesh.face(i));
            }
            i = mesh.twin(i);
            star.push(mesh.origin(i));
            i = mesh.next(i);
            if i == start {
                break;
            }
        }
        let mut ccw: Vec<VertexId> = mesh.vertex_vertices(v).collect();
        assert_eq!(ccw.len(), star.len());
        ccw[1..].reverse();
        assert_eq!(star, ccw, "star of {v:?}");
        let mut ccw_faces: Vec<FaceId> = mesh.vertex_faces(v).collect();
        ccw_faces.sort_unstable();
        faces.sort_unstable();
        assert_eq!(faces, ccw_faces);
    }
}

/// "visita di un bordo": the boundary loops and their total length.
fn boundary_edges(mesh: &Mesh) -> usize {
    mesh.boundary_loops()
        .iter()
        .map(|&start| {
            let (mut i, mut length) = (start, 0);
            loop {
                length += 1;
                i = mesh.next(i);
                if i == start {
                    break length;
                }
            }
        })
        .sum()
}

fn euler(mesh: &Mesh) -> i64 {
    let used = mesh.n_vertices() - mesh.isolated_vertices().len();
    used as i64 - mesh.n_edges() as i64 + mesh.n_faces() as i64
}

#[test]
fn closed_models_build_clean_and_loops_agree() {
    for (file, vertices, faces, euler_characteristic) in [
        ("closed/cgal_tetrahedron.off", 4, 4, 2),
        ("closed/lapy_torus.off", 576, 1152, 0),
        ("closed/cgal_eight.off", 315, 634, -2),
        ("closed/c3d_spot.obj", 2930, 5856, 2),
        ("polygonal/cgal_torus_quad.off", 25, 25, 0),
    ] {
        let (mesh, diagnostic) = build(file, BuildPolicy::Strict);
        assert_eq!(mesh.check(), Ok(()), "{file}");
        assert!(diagnostic.is_clean(), "{file}: {diagnostic}");
        assert_eq!(
            (mesh.n_vertices(), mesh.n_faces()),
            (vertices, faces),
            "{file}"
        );
        assert_eq!(euler(&mesh), euler_characteristic, "{file}");
        assert_eq!(boundary_edges(&mesh), 0, "{file}");
        seed_loops_agree(&mesh);
    }
}

#[test]
fn open_models_have_the_manifest_boundary() {
    for (file, boundary, euler_characteristic) in [
        ("open/igl_planexy.off", 16, 1),
        ("open/lapy_square-mesh.off", 60, 1),
        ("open/pmp_hemisphere.off", 120, 1),
        ("open/cgal_open_cube.off", 4, 1),
        ("open/cgal_elephant-with-holes.off", 1353, -110),
        ("open/cgal_three_peaks.off", 141, 1),
    ] {
        let (mesh, diagnostic) = build(file, BuildPolicy::Strict);
        assert_eq!(mesh.check(), Ok(()), "{file}");
        assert_eq!(boundary_edges(&mesh), boundary, "{file}: {diagnostic}");
        assert_eq!(euler(&mesh), euler_characteristic, "{file}");
        seed_loops_agree(&mesh);
    }
}

#[test]
fn broken_models_are_diagnosed_as_the_manifest_says() {
    // Strict refuses edge defects and names them all.
    for (file, non_manifold_edges, inconsistent_edges) in [
        ("broken/cgal_cubes.off", 1, 0),
        ("broken/gc_fan3.obj", 1, 0),
        ("broken/gc_moebius.obj", 0, 4),
        ("broken/cgal_cube-shuffled.off", 0, 9),
        ("broken/cgal_tet-shuffled.off", 0, 4),
        ("broken/tm_joined_tetrahedra.obj", 3, 0),
        ("broken/igl_truck.obj", 54, 64),
    ] {
        let soup = load(&data_dir().join(file));
        let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
        let diagnostic = error.diagnostic();
        assert_eq!(
            diagnostic.non_manifold_edges.len(),
            non_manifold_edges,
            "{file}: {diagnostic}"
        );
        assert_eq!(
            diagnostic.inconsistent_edges.len(),
            inconsistent_edges,
            "{file}: {diagnostic}"
        );
        // Skip and Repair both give a valid structure; Repair keeps every face.
        let (skipped, skip_diagnostic) =
            Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip).unwrap();
        assert_eq!(skipped.check(), Ok(()), "{file}");
        assert_eq!(
            skipped.n_faces() + skip_diagnostic.skipped_faces.len(),
            soup.n_faces(),
            "{file}"
        );
        let (repaired, repair_diagnostic) =
            Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Repair).unwrap();
        assert_eq!(repaired.check(), Ok(()), "{file}");
        assert_eq!(
            repaired.n_faces() + repair_diagnostic.skipped_faces.len(),
            soup.n_faces(),
            "{file}"
        );
        let repaired_something = !repair_diagnostic.vertex_copies.is_empty()
            || !repair_diagnostic.reoriented_faces.is_empty();
        assert!(repaired_something, "{file}");
        seed_loops_agree(&repaired);
    }
    // Shuffled orientations are repaired by reversing faces alone: closed again, nothing cut.
    for file in [
        "broken/cgal_cube-shuffled.off",
        "broken/cgal_tet-shuffled.off",
    ] {
        let (mesh, diagnostic) = build(file, BuildPolicy::Repair);
        assert!(diagnostic.vertex_copies.is_empty(), "{file}: {diagnostic}");
        assert!(!diagnostic.reoriented_faces.is_empty(), "{file}");
        assert_eq!(boundary_edges(&mesh), 0, "{file}");
        assert_eq!(euler(&mesh), 2, "{file}");
    }
    // A Möbius band cannot be oriented: repair cuts it along one seam.
    let (mesh, diagnostic) = build("broken/gc_moebius.obj", BuildPolicy::Repair);
    assert!(!diagnostic.vertex_copies.is_empty());
    assert_eq!(mesh.check(), Ok(()));
    // Non-manifold vertices are refused by Strict and split by Skip and Repair, one vertex per
    // fan: every vertex query then sees every face at its vertex, and the copies' valences add
    // up to the number of edges the file has at the vertex (the teapot's 38 where two fans touch,
    // the hourglass's apex of two closed cones).
    for (file, non_manifold_vertices) in [
        ("broken/gc_hourglass_ico.obj", 1),
        ("broken/c3d_teapot.obj", 38),
    ] {
        let soup = load(&data_dir().join(file));
        let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
        assert_eq!(
            error.diagnostic().non_manifold_vertices.len(),
            non_manifold_vertices,
            "{file}: {error}"
        );
        for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
            let (mesh, diagnostic) = build(file, policy);
            assert_eq!(mesh.check(), Ok(()), "{file}");
            assert!(mesh.non_manifold_vertices().is_empty(), "{file}");
            let split = &diagnostic.non_manifold_vertices;
            assert_eq!(split.len(), non_manifold_vertices, "{file}: {diagnostic}");
            // Each copy's valence adds to its original's: together, the file's valence.
            let mut total = vec![0; soup.positions.len()];
            for v in 0..mesh.n_vertex_slots() as u32 {
                let original = match (v as usize).checked_sub(soup.positions.len()) {
                    Some(copy) => diagnostic.vertex_copies[copy] as usize,
                    None => v as usize,
                };
                total[original] += mesh.valence(VertexId(v));
            }
            let mut edges: Vec<[u32; 2]> = Vec::new();
            let mut start = 0;
            for &size in &soup.face_sizes {
                let face = &soup.indices[start..start + size as usize];
                start += size as usize;
                for (i, &a) in face.iter().enumerate() {
                    let b = face[(i + 1) % face.len()];
                    edges.push([a.min(b), a.max(b)]);
                }
            }
            edges.sort_unstable();
            edges.dedup();
            for &v in split {
                let in_file = edges.iter().filter(|e| e.contains(&v)).count();
                assert!(in_file > mesh.valence(VertexId(v)), "{file}: vertex {v}");
                assert_eq!(total[v as usize], in_file, "{file}: vertex {v}");
            }
            seed_loops_agree(&mesh);
        }
    }
    let (_, diagnostic) = build("broken/cgal_degtri_sliding.off", BuildPolicy::Strict);
    assert_eq!(diagnostic.degenerate_faces.len(), 4, "{diagnostic}");
    let (mesh, diagnostic) = build("broken/tm_capsule.obj", BuildPolicy::Strict);
    assert_eq!(diagnostic.degenerate_faces.len(), 200, "{diagnostic}");
    assert_eq!(boundary_edges(&mesh), 302);
}

#[test]
fn invalid_faces_in_real_files_are_named() {
    let soup = load(&data_dir().join("broken/tobj_invalid_index.obj"));
    let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().faces_out_of_range.len(), 1);
    let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip).unwrap();
    assert_eq!(mesh.n_faces(), 1);
    assert_eq!(diagnostic.skipped_faces, diagnostic.faces_out_of_range);

    // Repair accepts every file Skip accepts: faces it cannot keep are left out and listed.
    let soup = load(&data_dir().join("broken/tm_notenoughindices.obj"));
    let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().faces_too_small.len(), 1);
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), policy).unwrap();
        assert_eq!(mesh.check(), Ok(()));
        assert_eq!(diagnostic.skipped_faces, diagnostic.faces_too_small);
    }

    let soup = load(&data_dir().join("broken/om_cube-minimal-degenerated.obj"));
    let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().faces_repeated_vertex.len(), 3, "{error}");
    // Skip leaves out every face that repeats a vertex; Repair collapses the repeats and leaves
    // out only the faces left with fewer than 3 corners ("2 2 2").
    let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(diagnostic.skipped_faces, diagnostic.faces_repeated_vertex);
    let (mesh, diagnostic) =
        Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Repair).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert!(!diagnostic.skipped_faces.is_empty(), "{diagnostic}");
    assert!(diagnostic.skipped_faces.len() < 3, "{diagnostic}");
    assert!(
        diagnostic
            .skipped_faces
            .iter()
            .all(|f| diagnostic.faces_repeated_vertex.contains(f))
    );
    assert_eq!(
        mesh.n_faces() + diagnostic.skipped_faces.len(),
        soup.n_faces()
    );
}

/// The diagnosis of a file describes the file: its non-manifold vertices and edges,
/// inconsistently oriented edges and unreferenced vertices are those the data manifest measured
/// on every model (a count the manifest does not give is zero), whatever a policy would do.
#[test]
fn diagnoses_describe_the_input_as_the_manifest_measured() {
    let manifest = std::fs::read_to_string(data_dir().join("../MANIFEST.md")).unwrap();
    let mut checked = 0;
    for section in manifest.split("\n### `").skip(1) {
        let Some(path) = section.split('`').next() else {
            continue;
        };
        let Some(relative) = path.strip_prefix("meshes/") else {
            continue;
        };
        let measured = section
            .lines()
            .find_map(|line| line.strip_prefix("- Measured: "))
            .unwrap_or_else(|| panic!("{path}: no measured line"));
        let count = |what: &str| -> usize {
            measured
                .split("; ")
                .find_map(|item| item.strip_prefix(what)?.strip_prefix('=')?.parse().ok())
                .unwrap_or(0)
        };
        // The library's reader, or for the files it refuses (out-of-range indices) the test
        // loader, which keeps them.
        let file = data_dir().join(relative);
        let soup = halfwing::io::read_path(&file).unwrap_or_else(|_| load(&file));
        let diagnostic = Mesh::diagnose(&soup.as_face_list()).unwrap();
        let found = [
            diagnostic.non_manifold_vertices.len(),
            diagnostic.non_manifold_edges.len(),
            diagnostic.inconsistent_edges.len(),
            diagnostic.isolated_vertices.len(),
        ];
        let expected = [
            count("non-manifold vertices"),
            count("non-manifold edges"),
            count("inconsistently oriented edges"),
            count("unreferenced vertices"),
        ];
        // The manifest counts the edges of faces with fewer than 3 corners or a vertex named
        // twice too; the diagnostic leaves those faces out of the edge and fan analysis (it
        // lists them apart).
        let malformed = diagnostic.faces_too_small.len() + diagnostic.faces_repeated_vertex.len();
        if malformed == 0 {
            assert_eq!(found, expected, "{path}: {diagnostic}");
        } else {
            assert_eq!(found[2..], expected[2..], "{path}: {diagnostic}");
        }
        assert!(diagnostic.skipped_faces.is_empty() && diagnostic.vertex_copies.is_empty());
        checked += 1;
    }
    assert!(checked > 50, "{checked} models");
}
