//! Golden test: the 7-vertex half-edge table of seed `000_505984156c1d03bf.txt`.
//!
//! The faces are derived from the table itself (each face's loop by `Next` from its half-edge);
//! the built mesh must then show the table's topology. Half-edge ids differ, so the comparison
//! goes through the map seed half-edge → built half-edge with the same origin and target.

use halfwing::mesh::{BuildPolicy, FaceId, HalfedgeId, Mesh, VertexId};
use halfwing::soup::FaceList;

const NONE: u32 = u32::MAX;

/// The seed's half-edge table, 0-based (`v1` → 0): origin, twin, face (NONE = ∅), next, prev.
const HALFEDGES: [[u32; 5]; 24] = [
    [0, 18, 0, 1, 2],
    [2, 11, 0, 2, 0],
    [3, 3, 0, 0, 1],
    [0, 2, 1, 4, 5],
    [3, 6, 1, 5, 3],
    [1, 19, 1, 3, 4],
    [1, 4, 2, 7, 8],
    [3, 17, 2, 8, 6],
    [4, 20, 2, 6, 7],
    [2, 21, 3, 10, 11],
    [5, 12, 3, 11, 9],
    [3, 1, 3, 9, 10],
    [3, 10, 4, 13, 14],
    [5, 22, 4, 14, 12],
    [6, 15, 4, 12, 13],
    [3, 14, 5, 16, 17],
    [6, 23, 5, 17, 15],
    [4, 7, 5, 15, 16],
    [2, 0, NONE, 19, 21],
    [0, 5, NONE, 20, 18],
    [1, 8, NONE, 23, 19],
    [5, 9, NONE, 18, 22],
    [6, 13, NONE, 21, 23],
    [4, 16, NONE, 22, 20],
];

/// The seed's vertex coordinates.
const POSITIONS: [[f64; 3]; 7] = [
    [1.0, 4.0, 0.0],
    [3.0, 4.0, 0.0],
    [0.0, 2.0, 0.0],
    [2.0, 2.0, 0.0],
    [4.0, 2.0, 0.0],
    [1.0, 0.0, 0.0],
    [3.0, 0.0, 0.0],
];

/// The seed's face table: face → half-edge.
const FACE_HALFEDGE: [u32; 6] = [0, 3, 6, 9, 12, 15];

fn seed_faces() -> (Vec<u32>, Vec<u32>) {
    let (mut sizes, mut indices) = (Vec::new(), Vec::new());
    for &start in &FACE_HALFEDGE {
        let mut e = start;
        let mut size = 0;
        loop {
            indices.push(HALFEDGES[e as usize][0]);
            size += 1;
            e = HALFEDGES[e as usize][3];
            if e == start {
                break;
            }
        }
        sizes.push(size);
    }
    (sizes, indices)
}

fn build_seed() -> Mesh {
    let (sizes, indices) = seed_faces();
    let (mesh, diagnostic) = Mesh::from_face_list(
        &FaceList::polygons(&POSITIONS, &sizes, &indices),
        BuildPolicy::Strict,
    )
    .unwrap();
    assert!(diagnostic.is_clean(), "{diagnostic}");
    mesh
}

#[test]
fn seed_table_counts() {
    let mesh = build_seed();
    assert_eq!(mesh.n_vertices(), 7);
    assert_eq!(mesh.n_faces(), 6);
    assert_eq!(mesh.n_halfedges(), 24);
    assert_eq!(mesh.n_edges(), 12);
    let boundary = (0..24)
        .filter(|&h| mesh.is_boundary_halfedge(HalfedgeId(h)))
        .count();
    assert_eq!(boundary, 6);
    assert_eq!(mesh.check(), Ok(()));
}

#[test]
fn seed_table_topology_matches_through_the_halfedge_map() {
    let mesh = build_seed();
    let target = |e: usize| HALFEDGES[HALFEDGES[e][1] as usize][0];
    let map: Vec<HalfedgeId> = (0..24)
        .map(|e| {
            let (from, to) = (VertexId(HALFEDGES[e][0]), VertexId(target(e)));
            (0..mesh.n_halfedge_slots() as u32)
                .map(HalfedgeId)
                .find(|&h| mesh.origin(h) == from && mesh.target(h) == to)
                .unwrap_or_else(|| panic!("no half-edge {from:?}→{to:?}"))
        })
        .collect();
    for (e, &[origin, twin, face, next, prev]) in HALFEDGES.iter().enumerate() {
        let h = map[e];
        assert_eq!(mesh.origin(h), VertexId(origin), "origin of e{e}");
        assert_eq!(mesh.twin(h), map[twin as usize], "twin of e{e}");
        assert_eq!(mesh.face(h), FaceId(face), "face of e{e}");
        assert_eq!(mesh.next(h), map[next as usize], "next of e{e}");
        assert_eq!(mesh.prev(h), map[prev as usize], "prev of e{e}");
    }
    // Face loops: each face's loop is the seed's loop, starting anywhere.
    for (f, &start) in FACE_HALFEDGE.iter().enumerate() {
        let built: Vec<HalfedgeId> = mesh.face_loop(FaceId(f as u32)).collect();
        assert_eq!(built.len(), 3);
        assert!(built.contains(&map[start as usize]));
    }
    // One boundary loop of six: e18 → e19 → e20 → e23 → e22 → e21.
    let loops = mesh.boundary_loops();
    assert_eq!(loops.len(), 1);
    let start = map[18];
    let walked: Vec<HalfedgeId> = mesh.halfedge_loop(start).collect();
    let expected: Vec<HalfedgeId> = [18, 19, 20, 23, 22, 21].iter().map(|&e| map[e]).collect();
    assert_eq!(walked, expected);
}

#[test]
fn seed_vertices_store_their_boundary_halfedge() {
    let mesh = build_seed();
    for v in 0..7 {
        let v = VertexId(v);
        let h = mesh.vertex_halfedge(v);
        assert_eq!(mesh.origin(h), v);
        // v4 (index 3) is the only interior vertex.
        assert_eq!(mesh.is_boundary_halfedge(h), v != VertexId(3), "{v:?}");
        assert_eq!(mesh.is_boundary_vertex(v), v != VertexId(3));
    }
    assert_eq!(mesh.valence(VertexId(3)), 6);
    // Counter-clockwise around v4 from e15's twin side: neighbours in CCW order about (2, 2).
    let ring: Vec<VertexId> = mesh.vertex_vertices(VertexId(3)).collect();
    let angle = |v: VertexId| {
        let p = POSITIONS[v.index()];
        (p[1] - 2.0).atan2(p[0] - 2.0)
    };
    let turns = (0..ring.len())
        .map(|i| {
            (angle(ring[(i + 1) % ring.len()]) - angle(ring[i])).rem_euclid(std::f64::consts::TAU)
        })
        .sum::<f64>();
    assert!(
        (turns - std::f64::consts::TAU).abs() < 1e-9,
        "ring is not one CCW turn: {ring:?}"
    );
}
