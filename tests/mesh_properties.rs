//! Property tests: random meshes keep every invariant, have the expected Euler characteristic,
//! and rebuild identically from their own face list; random soups never break a build.

mod mesh_support;

use halfwing::mesh::{BuildPolicy, FaceId, Mesh};
use halfwing::soup::{FaceList, PolygonSoup};
use mesh_support::grid;
use proptest::prelude::*;

fn euler(mesh: &Mesh) -> i64 {
    mesh.n_vertices() as i64 - mesh.n_edges() as i64 + mesh.n_faces() as i64
}

fn rebuilds_identically(mesh: &Mesh) {
    let soup = mesh.to_soup();
    let (rebuilt, _) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap();
    assert_eq!(&rebuilt, mesh);
}

/// The number of fans of faces around `v` in `soup` (faces joined through shared edges at `v`),
/// counted the slow way: an independent check of the builder's.
fn mesh_fans_of(soup: &PolygonSoup, v: u32) -> usize {
    let mut faces: Vec<&[u32]> = Vec::new();
    let mut start = 0;
    for &size in &soup.face_sizes {
        let face = &soup.indices[start..start + size as usize];
        start += size as usize;
        if face.contains(&v) {
            faces.push(face);
        }
    }
    let mut fan: Vec<usize> = (0..faces.len()).collect();
    let neighbours = |face: &[u32]| {
        let i = face.iter().position(|&w| w == v).unwrap();
        [
            face[(i + 1) % face.len()],
            face[(i + face.len() - 1) % face.len()],
        ]
    };
    for _ in 0..faces.len() {
        for a in 0..faces.len() {
            for b in 0..faces.len() {
                if neighbours(faces[a])
                    .iter()
                    .any(|w| neighbours(faces[b]).contains(w))
                {
                    let low = fan[a].min(fan[b]);
                    fan[a] = low;
                    fan[b] = low;
                }
            }
        }
    }
    fan.sort_unstable();
    fan.dedup();
    fan.len()
}

/// The soup without the faces whose bit is clear in `keep` (cycled).
fn subset(soup: &PolygonSoup, keep: &[bool]) -> PolygonSoup {
    let mut out = PolygonSoup {
        positions: soup.positions.clone(),
        ..PolygonSoup::default()
    };
    let mut start = 0;
    for (f, &size) in soup.face_sizes.iter().enumerate() {
        let end = start + size as usize;
        if keep[f % keep.len()] {
            out.face_sizes.push(size);
            out.indices.extend_from_slice(&soup.indices[start..end]);
        }
        start = end;
    }
    out
}

proptest! {
    #[test]
    fn grids_keep_invariants_and_euler(columns in 3u32..12, rows in 3u32..12, closed: bool, triangles: bool) {
        let soup = grid(columns, rows, closed, triangles);
        let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap();
        prop_assert!(diagnostic.is_clean(), "{}", diagnostic);
        prop_assert_eq!(mesh.check(), Ok(()));
        prop_assert_eq!(euler(&mesh), if closed { 0 } else { 1 });
        prop_assert_eq!(mesh.boundary_loops().len(), if closed { 0 } else { 1 });
        let corners: usize = (0..mesh.n_faces() as u32).map(|f| mesh.face_degree(FaceId(f))).sum();
        prop_assert_eq!(corners, soup.indices.len());
        rebuilds_identically(&mesh);
    }

    #[test]
    fn grids_with_random_holes_keep_invariants(
        columns in 3u32..9, rows in 3u32..9, closed: bool, keep in prop::collection::vec(any::<bool>(), 1..40),
    ) {
        // Removing faces makes holes, pinched (non-manifold) vertices and isolated vertices:
        // Skip splits the pinched ones, one vertex per fan.
        let soup = subset(&grid(columns, rows, closed, true), &keep);
        let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip).unwrap();
        prop_assert_eq!(mesh.check(), Ok(()));
        prop_assert!(diagnostic.skipped_faces.is_empty());
        prop_assert!(mesh.non_manifold_vertices().is_empty());
        prop_assert_eq!(&diagnostic.vertex_copies, &diagnostic.non_manifold_vertices.iter().flat_map(|&v| {
            let fans = mesh_fans_of(&soup, v);
            std::iter::repeat_n(v, fans - 1)
        }).collect::<Vec<_>>());
        prop_assert_eq!(diagnostic.isolated_vertices.len(), mesh.isolated_vertices().len());
        let boundary: usize = mesh.boundary_loops().iter().map(|&h| mesh.halfedge_loop(h).count()).sum();
        let boundary_halfedges = (0..mesh.n_halfedge_slots() as u32)
            .filter(|&h| mesh.is_boundary_halfedge(halfwing::mesh::HalfedgeId(h)))
            .count();
        prop_assert_eq!(boundary, boundary_halfedges);
        rebuilds_identically(&mesh);
    }

    #[test]
    fn random_soups_never_break_a_build(
        n_vertices in 1usize..10,
        faces in prop::collection::vec(prop::collection::vec(0u32..11, 1..6), 0..14),
    ) {
        let positions: Vec<[f64; 3]> =
            (0..n_vertices).map(|i| [(i as f64).cos(), (i as f64).sin(), (i * i) as f64 * 0.1]).collect();
        let sizes: Vec<u32> = faces.iter().map(|f| f.len() as u32).collect();
        let indices: Vec<u32> = faces.concat();
        let list = FaceList::polygons(&positions, &sizes, &indices);
        for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
            match Mesh::from_face_list(&list, policy) {
                Ok((mesh, diagnostic)) => {
                    prop_assert_eq!(mesh.check(), Ok(()));
                    prop_assert_eq!(mesh.n_vertices(), n_vertices + diagnostic.vertex_copies.len());
                    prop_assert!(mesh.non_manifold_vertices().is_empty());
                    prop_assert_eq!(mesh.n_faces() + diagnostic.skipped_faces.len(), faces.len());
                    if policy == BuildPolicy::Strict {
                        prop_assert!(!diagnostic.has_invalid_input() && !diagnostic.has_edge_defects());
                        prop_assert!(diagnostic.non_manifold_vertices.is_empty());
                    }
                    // Repair leaves out only the faces no structure can hold.
                    if policy == BuildPolicy::Repair {
                        let mut unkeepable: Vec<u32> = diagnostic.faces_too_small.iter()
                            .chain(&diagnostic.faces_out_of_range).copied().collect();
                        unkeepable.sort_unstable();
                        unkeepable.dedup();
                        let collapsed = diagnostic.skipped_faces.iter().filter(|f| unkeepable.binary_search(f).is_err());
                        for &f in collapsed {
                            prop_assert!(diagnostic.faces_repeated_vertex.contains(&f));
                        }
                    }
                    rebuilds_identically(&mesh);
                }
                Err(error) => {
                    prop_assert!(policy == BuildPolicy::Strict, "only Strict refuses: {}", error);
                    let diagnostic = error.diagnostic();
                    prop_assert!(diagnostic.has_invalid_input() || diagnostic.has_edge_defects()
                        || !diagnostic.non_manifold_vertices.is_empty());
                }
            }
        }
    }
}
