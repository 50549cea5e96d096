//! Attributes: per-corner normals and texture coordinates through files, builds and policies;
//! named user columns through every edit and compaction.

mod mesh_support;

use halfwing::io::{read_path, write_path};
use halfwing::mesh::{
    AttributeError, BuildPolicy, EdgeId, ElementKind, FaceId, HalfedgeId, Mesh, ScalarType,
    VertexId,
};
use halfwing::soup::PolygonSoup;
use mesh_support::{data_dir, grid};

#[test]
fn obj_corner_attributes_round_trip_through_the_mesh() {
    let files = [
        "closed/c3d_spot.obj",          // texture coordinates
        "closed/nvdiffrec_bob_tri.obj", // both
        "polygonal/pmp_suzanne.obj",    // normals, polygons
        "polygonal/igl_cylinder.obj",   // both, polygons
    ];
    for file in files {
        let soup = read_path(data_dir().join(file)).unwrap();
        assert!(soup.corner_normals.is_some() || soup.corner_uvs.is_some());
        let (mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Repair).unwrap();
        assert_eq!(mesh.check(), Ok(()));
        let exported = mesh.to_soup();
        assert_eq!(
            exported, soup,
            "{file}: the mesh keeps every corner's values"
        );

        let path = std::env::temp_dir().join(format!(
            "halfwing-attr-{}-{}",
            std::process::id(),
            file.replace('/', "-")
        ));
        write_path(&path, &exported).unwrap();
        let reread = read_path(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(reread, soup, "{file}: written and read back");
    }
}

/// Corner normal `[input corner, input vertex, input face]` of every corner of `soup`.
fn tag_corners(soup: &mut PolygonSoup) {
    let mut tags = Vec::new();
    for (face, &size) in soup.face_sizes.iter().enumerate() {
        for _ in 0..size {
            let corner = tags.len();
            tags.push([corner as f64, soup.indices[corner] as f64, face as f64]);
        }
    }
    soup.corner_normals = Some(tags);
    soup.corner_uvs = Some((0..soup.indices.len()).map(|c| [c as f64, 0.5]).collect());
}

#[test]
fn corners_keep_their_values_when_policies_skip_reorient_and_copy() {
    // Face 0 names vertex 3 twice in a row and once more later; faces 1 and 2 disagree on the
    // direction of edge 0–1; edge 1–2 has three faces (1, 3 and 4).
    let positions: Vec<[f64; 3]> = (0..8).map(|i| [i as f64, (i * i) as f64, 0.0]).collect();
    let mut soup = PolygonSoup {
        positions,
        face_sizes: vec![5, 3, 3, 3, 3],
        indices: vec![3, 3, 5, 6, 3, 0, 1, 2, 0, 1, 7, 2, 1, 4, 2, 1, 5],
        corner_normals: None,
        corner_uvs: None,
    };
    tag_corners(&mut soup);
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (mesh, diagnostic) = Mesh::from_soup(&soup, policy).unwrap();
        assert_eq!(mesh.check(), Ok(()));
        let normals = mesh.corner_normals().unwrap();
        let uvs = mesh.corner_uvs().unwrap();
        let original = |v: VertexId| -> u32 {
            match (v.0 as usize).checked_sub(soup.positions.len()) {
                Some(copy) => diagnostic.vertex_copies[copy],
                None => v.0,
            }
        };
        let kept: Vec<u32> = (0..soup.n_faces() as u32)
            .filter(|f| !diagnostic.skipped_faces.contains(f))
            .collect();
        for f in 0..mesh.n_face_slots() as u32 {
            let mut seen = Vec::new();
            for h in mesh.face_loop(FaceId(f)) {
                let [corner, vertex, face] = normals[h.index()];
                assert_eq!(vertex as u32, original(mesh.origin(h)), "{policy:?}");
                assert_eq!(face as u32, kept[f as usize], "{policy:?}");
                assert_eq!(soup.indices[corner as usize], vertex as u32);
                assert_eq!(uvs[h.index()], [corner, 0.5]);
                seen.push(corner);
            }
            seen.dedup();
            assert_eq!(seen.len(), mesh.face_degree(FaceId(f)), "each corner once");
        }
        if policy == BuildPolicy::Repair {
            assert!(
                !diagnostic.reoriented_faces.is_empty() && !diagnostic.vertex_copies.is_empty()
            );
        } else {
            assert!(!diagnostic.skipped_faces.is_empty());
        }
        for h in 0..mesh.n_halfedge_slots() as u32 {
            if mesh.is_boundary_halfedge(HalfedgeId(h)) {
                assert_eq!(normals[h as usize], [0.0; 3]);
            }
        }
    }
    let mut bad = soup.clone();
    bad.corner_uvs.as_mut().unwrap().pop();
    let error = Mesh::from_soup(&bad, BuildPolicy::Repair).unwrap_err();
    assert!(error.to_string().contains("corner uvs"), "{error}");
}

fn tagged_grid() -> Mesh {
    let mut soup = grid(3, 2, false, true);
    tag_corners(&mut soup);
    let (mut mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    // Each element carries its own id, so tests can tell where values went.
    for kind in [
        ElementKind::Vertex,
        ElementKind::Halfedge,
        ElementKind::Edge,
        ElementKind::Face,
    ] {
        mesh.add_attribute::<u32>(kind, "id", 1).unwrap();
        for (i, value) in mesh
            .attribute_mut::<u32>(kind, "id")
            .unwrap()
            .iter_mut()
            .enumerate()
        {
            *value = i as u32;
        }
    }
    mesh.add_attribute::<f32>(ElementKind::Vertex, "colour", 3)
        .unwrap();
    let positions = mesh.positions().to_vec();
    for (v, colour) in mesh
        .attribute_mut::<f32>(ElementKind::Vertex, "colour")
        .unwrap()
        .chunks_mut(3)
        .enumerate()
    {
        colour.copy_from_slice(&positions[v].map(|x| x as f32));
    }
    mesh
}

fn ids(mesh: &Mesh, kind: ElementKind) -> &[u32] {
    mesh.attribute::<u32>(kind, "id").unwrap()
}

#[test]
fn split_edge_blends_at_the_projected_position_and_keeps_the_ends() {
    let mut mesh = tagged_grid();
    let e = (0..mesh.n_edge_slots() as u32)
        .map(EdgeId)
        .find(|&e| !mesh.is_boundary_edge(e))
        .unwrap();
    let (h0, h1) = (e.halfedge(0), e.halfedge(1));
    let (a, b) = (mesh.origin(h0), mesh.target(h0));
    let (pa, pb) = (mesh.position(a), mesh.position(b));
    let point = [
        0.75 * pa[0] + 0.25 * pb[0],
        0.75 * pa[1] + 0.25 * pb[1],
        0.0,
    ];
    let before = mesh.clone();
    let uv = |m: &Mesh, h: HalfedgeId| m.corner_uvs().unwrap()[h.index()][0];
    let w = mesh.split_edge(e, point).unwrap();
    assert_eq!(mesh.check(), Ok(()));

    let colour = mesh
        .attribute::<f32>(ElementKind::Vertex, "colour")
        .unwrap();
    let expected = point.map(|x| x as f32);
    for k in 0..3 {
        assert!((colour[3 * w.index() + k] - expected[k]).abs() < 1e-6);
    }
    // Integers take the nearer end (a, a quarter of the way).
    assert_eq!(ids(&mesh, ElementKind::Vertex)[w.index()], a.0);
    let n = mesh.next(h0); // the new half-edge w → b beside h0
    assert_eq!(ids(&mesh, ElementKind::Edge)[n.edge().index()], e.0);
    let corner_a = uv(&before, h0);
    let corner_b = uv(&before, before.next(h0));
    assert_eq!(uv(&mesh, h0), corner_a);
    assert_eq!(uv(&mesh, n), 0.75 * corner_a + 0.25 * corner_b);
    // Beside h1 (was b → a, now w → a) the corner at b moved to twin(n).
    assert_eq!(uv(&mesh, n.twin()), uv(&before, h1));
    let normals = mesh.corner_normals().unwrap();
    let length = normals[h1.index()]
        .iter()
        .map(|x| x * x)
        .sum::<f64>()
        .sqrt();
    assert!((length - 1.0).abs() < 1e-12, "blended normals are unit");
}

#[test]
fn face_split_flip_and_triangulate_carry_corners_and_faces() {
    let mut quad = Mesh::new();
    for p in [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ] {
        quad.add_vertex(p).unwrap();
    }
    let f = quad
        .add_face(&[VertexId(0), VertexId(1), VertexId(2), VertexId(3)])
        .unwrap();
    quad.add_attribute::<i32>(ElementKind::Face, "label", 1)
        .unwrap();
    quad.attribute_mut::<i32>(ElementKind::Face, "label")
        .unwrap()[f.index()] = -7;
    let corners: Vec<[f64; 2]> = (0..quad.n_halfedge_slots())
        .map(|h| [quad.origin(HalfedgeId(h as u32)).0 as f64, 0.0])
        .collect();
    quad.set_corner_uvs(&corners).unwrap();
    let faces = quad.triangulate_face(f).unwrap();
    assert_eq!(faces.len(), 2);
    let uvs = quad.corner_uvs().unwrap();
    for &t in &faces {
        assert_eq!(
            quad.attribute::<i32>(ElementKind::Face, "label").unwrap()[t.index()],
            -7
        );
        for h in quad.face_loop(t) {
            assert_eq!(
                uvs[h.index()][0],
                quad.origin(h).0 as f64,
                "corner of its own vertex"
            );
        }
    }
    let diagonal = quad
        .face_loop(faces[1])
        .find(|h| !quad.is_boundary_halfedge(h.twin()));
    quad.flip_edge(diagonal.unwrap().edge()).unwrap();
    assert_eq!(quad.check(), Ok(()));
    let uvs = quad.corner_uvs().unwrap();
    for &t in &faces {
        for h in quad.face_loop(t) {
            assert_eq!(uvs[h.index()][0], quad.origin(h).0 as f64, "after the flip");
        }
    }
}

#[test]
fn collapse_delete_and_compaction_keep_values_with_their_elements() {
    let mut mesh = tagged_grid();
    let h = (0..mesh.n_halfedge_slots() as u32)
        .map(HalfedgeId)
        .find(|&h| mesh.can_collapse_halfedge(h).is_ok())
        .unwrap();
    let (removed, kept) = (mesh.origin(h), mesh.target(h));
    assert_eq!(mesh.collapse_halfedge(h).unwrap(), kept);
    assert_eq!(ids(&mesh, ElementKind::Vertex)[kept.index()], kept.0);
    let normals = mesh.corner_normals().unwrap();
    for f in (0..mesh.n_face_slots() as u32).map(FaceId) {
        if mesh.is_face_deleted(f) {
            continue;
        }
        for g in mesh.face_loop(f) {
            // Corner tags name the vertex the corner had before the collapse.
            let tagged = VertexId(normals[g.index()][1] as u32);
            let moved = mesh.origin(g) == kept && tagged == removed;
            assert!(tagged == mesh.origin(g) || moved, "{g}: {tagged}");
        }
    }
    let live = (0..mesh.n_face_slots() as u32)
        .map(FaceId)
        .find(|&f| !mesh.is_face_deleted(f));
    mesh.delete_face(live.unwrap(), true).unwrap();
    let before = mesh.clone();
    let maps = mesh.garbage_collect();
    assert_eq!(mesh.check(), Ok(()));
    let pairs = [
        (ElementKind::Vertex, &maps.vertices),
        (ElementKind::Halfedge, &maps.halfedges),
        (ElementKind::Edge, &maps.edges),
        (ElementKind::Face, &maps.faces),
    ];
    for (kind, map) in pairs {
        let old = ids(&before, kind);
        let new = ids(&mesh, kind);
        assert_eq!(new.len(), mesh.n_slots(kind));
        for (old_id, &new_id) in map.iter().enumerate() {
            if new_id != u32::MAX {
                assert_eq!(new[new_id as usize], old[old_id], "{kind}");
            }
        }
    }
    let soup = mesh.to_soup();
    let (rebuilt, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
    assert_eq!(rebuilt.to_soup(), soup);
}

#[test]
fn attribute_calls_refuse_bad_names_types_and_counts() {
    let mut mesh = tagged_grid();
    let vertex = ElementKind::Vertex;
    assert!(matches!(
        mesh.add_attribute::<f64>(vertex, "colour", 3),
        Err(AttributeError::NameTaken { .. })
    ));
    assert!(matches!(
        mesh.add_attribute::<f64>(ElementKind::Halfedge, Mesh::CORNER_NORMALS, 3),
        Err(AttributeError::InvalidName { .. })
    ));
    assert!(matches!(
        mesh.add_attribute::<f64>(vertex, "", 1),
        Err(AttributeError::InvalidName { .. })
    ));
    for count in [0, 17] {
        assert_eq!(
            mesh.add_attribute::<u32>(vertex, "n", count),
            Err(AttributeError::InvalidComponents { count })
        );
    }
    assert!(matches!(
        mesh.attribute::<f64>(vertex, "colour"),
        Err(AttributeError::WrongType {
            stored: ScalarType::F32,
            requested: ScalarType::F64,
            ..
        })
    ));
    assert!(matches!(
        mesh.attribute::<f32>(ElementKind::Face, "colour"),
        Err(AttributeError::NotFound { .. })
    ));
    assert!(matches!(
        mesh.set_corner_uvs(&[[0.0; 2]]),
        Err(AttributeError::WrongLength { .. })
    ));
    let names: Vec<&str> = mesh.attribute_names(vertex).collect();
    assert_eq!(names, ["id", "colour"]);
    let info = mesh.attribute_info(vertex, "colour").unwrap();
    assert_eq!((info.scalar, info.components), (ScalarType::F32, 3));
    mesh.remove_attribute(vertex, "id").unwrap();
    mesh.remove_attribute(ElementKind::Halfedge, Mesh::CORNER_UVS)
        .unwrap();
    assert!(mesh.corner_uvs().is_none());
    assert!(mesh.to_soup().corner_uvs.is_none());
    assert!(matches!(
        mesh.remove_attribute(vertex, "id"),
        Err(AttributeError::NotFound { .. })
    ));
    assert_eq!(mesh.check(), Ok(()));
}
