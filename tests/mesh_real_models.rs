//! Seed 004's loops (sides of a face, star of a vertex, faces around a vertex, adjacent faces,
//! boundary walk), written with the raw navigation exactly as the slides do, on the real models
//! of the shared data set; and the build's counts and diagnostics against the data manifest.

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
        assert_eq!(repaired.n_faces(), soup.n_faces(), "{file}");
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
    // Non-manifold vertices are kept and reported, even under Strict.
    for (file, non_manifold_vertices) in [
        ("broken/gc_hourglass_ico.obj", 1),
        ("broken/c3d_teapot.obj", 38),
    ] {
        let (mesh, diagnostic) = build(file, BuildPolicy::Strict);
        assert_eq!(mesh.check(), Ok(()), "{file}");
        assert_eq!(
            diagnostic.non_manifold_vertices.len(),
            non_manifold_vertices,
            "{file}: {diagnostic}"
        );
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

    let soup = load(&data_dir().join("broken/tm_notenoughindices.obj"));
    let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Repair).unwrap_err();
    assert_eq!(error.diagnostic().faces_too_small.len(), 1);

    let soup = load(&data_dir().join("broken/om_cube-minimal-degenerated.obj"));
    let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().faces_repeated_vertex.len(), 3, "{error}");
    // "2 2 2" collapses to one corner: Skip leaves it out, Repair refuses rather than drop it.
    let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert!(diagnostic.skipped_faces.len() >= 3, "{diagnostic}");
    let error = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Repair).unwrap_err();
    assert!(!error.diagnostic().faces_too_small.is_empty(), "{error}");
}
