//! Euler operators: building and unbuilding solids, refusals, and random operator sequences.

use halfwing::soup::BuildPolicy;
use halfwing::winged::{EdgeId, FaceId, VertexId, Winged, WingedError};
use proptest::prelude::*;

/// What MEV made (edge, vertex) and what MEF made (edge, face), in order.
type Made = (Vec<(EdgeId, VertexId)>, Vec<(EdgeId, FaceId)>);

/// The cube built operator by operator: MVFS, three MEVs and an MEF for the bottom square,
/// four MEVs up and four MEFs around the top. Returns it with the made elements in order.
fn euler_cube() -> (Winged, Made) {
    let mut w = Winged::new();
    let (v0, f0) = w.mvfs([0.0, 0.0, 0.0]).unwrap();
    let mut made_vertices = Vec::new();
    let mut made_faces = Vec::new();
    let bottom = [[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let mut square = vec![v0];
    for p in bottom {
        let (e, v) = w.mev(f0, *square.last().unwrap(), p).unwrap();
        made_vertices.push((e, v));
        square.push(v);
    }
    made_faces.push(w.mef(f0, square[3], square[0]).unwrap());
    let mut top = Vec::new();
    for &v in &square {
        let p = w.position(v).unwrap();
        let (e, t) = w.mev(f0, v, [p[0], p[1], 1.0]).unwrap();
        made_vertices.push((e, t));
        top.push(t);
    }
    for k in 0..4 {
        made_faces.push(w.mef(f0, top[k], top[(k + 1) % 4]).unwrap());
    }
    (w, (made_vertices, made_faces))
}

/// Six times the signed volume enclosed by the faces (positive when they face outward).
fn six_volume(w: &Winged) -> f64 {
    let mut total = 0.0;
    for f in w.faces() {
        let p: Vec<[f64; 3]> = w
            .face_vertices(f)
            .unwrap()
            .map(|v| w.position(v).unwrap())
            .collect();
        for k in 1..p.len() - 1 {
            let (a, b, c) = (p[0], p[k], p[k + 1]);
            total += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    }
    total
}

#[test]
fn euler_operators_build_a_cube() {
    let (w, _) = euler_cube();
    w.check().unwrap();
    assert_eq!((w.n_vertices(), w.n_edges(), w.n_faces()), (8, 12, 6));
    assert_eq!(w.euler_characteristic(), 2);
    assert!(w.edges().all(|e| !w.is_boundary_edge(e).unwrap()));
    assert!(w.faces().all(|f| w.face_loop(f).unwrap().count() == 4));
    assert!(w.vertices().all(|v| w.valence(v).unwrap() == 3));
    assert!((six_volume(&w).abs() - 6.0).abs() < 1e-12);
    // The face list it describes is a valid closed mesh that rebuilds to the same faces.
    let soup = w.to_soup();
    let rebuilt = Winged::from_soup(&soup, BuildPolicy::Strict).unwrap().0;
    rebuilt.check().unwrap();
    assert_eq!(rebuilt.to_soup(), soup);
}

#[test]
fn kill_operators_take_the_cube_back_to_a_point() {
    let (mut w, (made_vertices, made_faces)) = euler_cube();
    for &(e, f) in made_faces.iter().rev() {
        w.kef(e, f).unwrap();
        w.check().unwrap();
        assert_eq!(w.euler_characteristic(), 2);
    }
    for &(e, v) in made_vertices.iter().rev() {
        w.kev(e, v).unwrap();
        w.check().unwrap();
        assert_eq!(w.euler_characteristic(), 2);
    }
    assert_eq!((w.n_vertices(), w.n_edges(), w.n_faces()), (1, 0, 1));
    let f = w.faces().next().unwrap();
    assert_eq!(w.point_face_vertex(f), Some(VertexId(0)));
    assert_eq!(
        w.face_vertices(f).unwrap().collect::<Vec<_>>(),
        [VertexId(0)]
    );
    w.kvfs(f).unwrap();
    w.check().unwrap();
    assert_eq!((w.n_vertices(), w.n_edges(), w.n_faces()), (0, 0, 0));
}

#[test]
fn mev_then_kev_and_mef_then_kef_restore_the_faces() {
    let (mut w, _) = euler_cube();
    let before = w.to_soup();
    let f = FaceId(0);
    let v = w.face_vertices(f).unwrap().next().unwrap();
    let (e, new_v) = w.mev(f, v, [0.5, 0.5, 0.5]).unwrap();
    assert_eq!(
        w.face_loop(f).unwrap().count(),
        6,
        "a dangling edge is walked both ways"
    );
    w.kev(e, new_v).unwrap();
    w.check().unwrap();
    assert_eq!(w.to_soup(), before);

    let corners: Vec<VertexId> = w.face_vertices(f).unwrap().collect();
    let (e, g) = w.mef(f, corners[0], corners[2]).unwrap();
    assert_eq!(w.face_loop(f).unwrap().count(), 3);
    assert_eq!(w.face_loop(g).unwrap().count(), 3);
    w.kef(e, g).unwrap();
    w.check().unwrap();
    let mut after: Vec<VertexId> = w.face_vertices(f).unwrap().collect();
    let shift = after.iter().position(|&x| x == corners[0]).unwrap();
    after.rotate_left(shift);
    assert_eq!(after, corners);
}

#[test]
fn refused_operators_change_nothing() {
    let (mut w, (made_vertices, made_faces)) = euler_cube();
    let snapshot = w.clone();
    let (bottom_edge, _) = made_vertices[0];
    let f = FaceId(0);
    let far = w
        .vertices()
        .find(|&v| !w.face_vertices(f).unwrap().any(|x| x == v))
        .unwrap();
    let on_f: Vec<VertexId> = w.face_vertices(f).unwrap().collect();
    let first_mef_edge = made_faces[0].0;
    let sides = w.edge_faces(first_mef_edge).unwrap();
    let not_on_edge = w.faces().find(|g| !sides.contains(g)).unwrap();
    let refusals = [
        w.clone().mvfs([f64::NAN, 0.0, 0.0]).map(|_| ()),
        w.clone().mev(f, far, [0.0; 3]).map(|_| ()),
        w.clone().mev(f, on_f[0], [f64::INFINITY; 3]).map(|_| ()),
        w.clone().mev(FaceId(99), on_f[0], [0.0; 3]).map(|_| ()),
        w.clone().mef(f, on_f[0], on_f[0]).map(|_| ()),
        w.clone().mef(f, on_f[0], far).map(|_| ()),
        w.clone().kev(bottom_edge, VertexId(0)),
        w.clone().kev(EdgeId(500), VertexId(0)),
        w.clone().kef(first_mef_edge, not_on_edge),
        w.clone().kvfs(f),
    ];
    for (k, r) in refusals.iter().enumerate() {
        assert!(r.is_err(), "operation {k} must be refused");
    }
    // The same refusals on the real structure leave it untouched.
    assert!(matches!(
        w.mev(f, far, [0.0; 3]),
        Err(WingedError::VertexNotOnFace { .. })
    ));
    assert!(matches!(
        w.mef(f, on_f[1], on_f[1]),
        Err(WingedError::SelfLoop(_))
    ));
    assert!(matches!(
        w.kev(bottom_edge, VertexId(0)),
        Err(WingedError::VertexNotDangling { .. })
    ));
    assert_eq!(w, snapshot);

    // A vertex met twice by a loop is ambiguous for MEV and MEF.
    let (e, tip) = w.mev(f, on_f[0], [0.2, 0.2, 0.0]).unwrap();
    let snapshot = w.clone();
    assert!(matches!(
        w.mev(f, on_f[0], [0.0; 3]),
        Err(WingedError::AmbiguousCorner { .. })
    ));
    assert!(matches!(
        w.mef(f, on_f[0], on_f[2]),
        Err(WingedError::AmbiguousCorner { .. })
    ));
    assert!(matches!(
        w.kef(e, f),
        Err(WingedError::EdgeNotBetweenTwoFaces(_))
    ));
    assert_eq!(w, snapshot);
    // The dangling tip itself can be joined to a corner.
    w.mef(f, tip, on_f[2]).unwrap();
    w.check().unwrap();
}

/// One randomly chosen operator; the selectors pick elements modulo what exists.
#[derive(Clone, Debug)]
enum Op {
    Mvfs,
    Mev {
        face: usize,
        corner: usize,
    },
    Mef {
        face: usize,
        first: usize,
        second: usize,
    },
    Kev {
        edge: usize,
        end: bool,
    },
    Kef {
        edge: usize,
        left: bool,
    },
    Kvfs {
        face: usize,
    },
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        1 => Just(Op::Mvfs),
        6 => (any::<usize>(), any::<usize>()).prop_map(|(face, corner)| Op::Mev { face, corner }),
        5 => (any::<usize>(), any::<usize>(), any::<usize>())
            .prop_map(|(face, first, second)| Op::Mef { face, first, second }),
        3 => (any::<usize>(), any::<bool>()).prop_map(|(edge, end)| Op::Kev { edge, end }),
        3 => (any::<usize>(), any::<bool>()).prop_map(|(edge, left)| Op::Kef { edge, left }),
        1 => any::<usize>().prop_map(|face| Op::Kvfs { face }),
    ]
}

fn pick<T: Copy>(items: &[T], selector: usize) -> Option<T> {
    (!items.is_empty()).then(|| items[selector % items.len()])
}

/// Applies `op`; returns the change in (V, E, F, solids) it made, or `None` if refused.
fn apply(w: &mut Winged, op: &Op, step: usize) -> Option<(i64, i64, i64, i64)> {
    let faces: Vec<FaceId> = w.faces().collect();
    let edges: Vec<EdgeId> = w.edges().collect();
    let p = [step as f64, (step * 7 % 5) as f64, (step * 3 % 11) as f64];
    match *op {
        Op::Mvfs => w.mvfs(p).ok().map(|_| (1, 0, 1, 1)),
        Op::Mev { face, corner } => {
            let f = pick(&faces, face)?;
            let corners: Vec<VertexId> = w.face_vertices(f).unwrap().collect();
            let v = pick(&corners, corner)?;
            w.mev(f, v, p).ok().map(|_| (1, 1, 0, 0))
        }
        Op::Mef {
            face,
            first,
            second,
        } => {
            let f = pick(&faces, face)?;
            let corners: Vec<VertexId> = w.face_vertices(f).unwrap().collect();
            let (a, b) = (pick(&corners, first)?, pick(&corners, second)?);
            w.mef(f, a, b).ok().map(|_| (0, 1, 1, 0))
        }
        Op::Kev { edge, end } => {
            let e = pick(&edges, edge)?;
            let r = *w.edge(e).unwrap();
            w.kev(e, if end { r.end } else { r.start })
                .ok()
                .map(|_| (-1, -1, 0, 0))
        }
        Op::Kef { edge, left } => {
            let e = pick(&edges, edge)?;
            let r = *w.edge(e).unwrap();
            w.kef(e, if left { r.left_face } else { r.right_face })
                .ok()
                .map(|_| (0, -1, -1, 0))
        }
        Op::Kvfs { face } => w.kvfs(pick(&faces, face)?).ok().map(|_| (-1, 0, -1, -1)),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Every operator either applies (changing V, E, F by its own amounts) or refuses and
    /// changes nothing; every invariant holds after each step, and V − E + F = 2 per solid.
    #[test]
    fn random_operator_sequences_keep_every_invariant(ops in proptest::collection::vec(op(), 1..80)) {
        let mut w = Winged::new();
        w.mvfs([0.0; 3]).unwrap();
        let mut solids = 1i64;
        for (step, op) in ops.iter().enumerate() {
            let before = w.clone();
            let counts = |w: &Winged| (i64::from(w.n_vertices()), i64::from(w.n_edges()), i64::from(w.n_faces()));
            let (v0, e0, f0) = counts(&before);
            match apply(&mut w, op, step) {
                Some((dv, de, df, ds)) => {
                    solids += ds;
                    prop_assert_eq!(counts(&w), (v0 + dv, e0 + de, f0 + df), "{:?}", op);
                }
                None => prop_assert_eq!(&w, &before, "refused {:?} changed the structure", op),
            }
            if let Err(e) = w.check() {
                return Err(TestCaseError::fail(format!("after {op:?}: {e}")));
            }
            prop_assert_eq!(w.euler_characteristic(), 2 * solids);
            let ring_total: usize = w.vertices().map(|v| w.valence(v).unwrap()).sum();
            prop_assert_eq!(ring_total, 2 * w.n_edges() as usize);
        }
    }
}

#[test]
fn garbage_collect_compacts_after_kills() {
    let (mut w, (made_vertices, made_faces)) = euler_cube();
    let (e, f) = made_faces[4];
    w.kef(e, f).unwrap();
    let (e, v) = *made_vertices.last().unwrap();
    // The last top vertex is no longer dangling; remove a fresh dangling one instead.
    assert!(w.kev(e, v).is_err());
    let (e, v) = w.mev(FaceId(0), VertexId(0), [0.1, 0.1, 0.0]).unwrap();
    w.kev(e, v).unwrap();
    let before = w.to_soup();
    let map = w.garbage_collect();
    w.check().unwrap();
    assert_eq!(w.n_vertex_slots(), w.n_vertices());
    assert_eq!(w.n_edge_slots(), w.n_edges());
    assert_eq!(w.n_face_slots(), w.n_faces());
    assert_eq!(map.faces[f.index()], FaceId::INVALID.0);
    assert_eq!(map.vertices[v.index()], VertexId::INVALID.0);
    assert!(map.halfedges.is_empty());
    assert_eq!(
        map.edges
            .iter()
            .filter(|&&e| e != EdgeId::INVALID.0)
            .count(),
        w.n_edges() as usize
    );
    assert_eq!(w.to_soup(), before);
}

/// A pillow (two triangles on the same three vertices) and a triangle touching it at vertex 0,
/// built under Skip: the builder splits vertex 0, the triangle's corner becoming vertex 5, so no
/// vertex has edges outside its ring. Then KEF merges the pillow's faces, leaving a loop
/// 0 → 1 → 2 → 1 → 0 in which vertex 0 dangles from edge 0.
fn pillow_beside_a_triangle() -> Winged {
    let p = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
    ];
    let idx = [0, 1, 2, 0, 2, 1, 0, 3, 4];
    let fl = halfwing::soup::FaceList::triangles(&p, &idx);
    let (mut w, d) = Winged::from_face_list(&fl, BuildPolicy::Skip).unwrap();
    assert_eq!(d.non_manifold_vertices, [0]);
    assert_eq!(d.vertex_copies, [0]);
    assert!(w.non_manifold_vertices().is_empty());
    assert_eq!(w.edge(EdgeId(2)).unwrap().start, VertexId(2));
    assert_eq!(w.edge(EdgeId(2)).unwrap().end, VertexId(0));
    w.kef(EdgeId(2), FaceId(0)).unwrap();
    w.check().unwrap();
    w
}

/// Found by a randomized stress harness (seed 5602) when the builder kept a pinched vertex's
/// fans apart: KEV deleted the vertex while the other fan's edges still ended there. The
/// builder now splits such a vertex, so the vertex that dangles in the pillow has no other edge
/// and goes, while the triangle keeps its copy.
#[test]
fn kev_of_a_split_vertex_leaves_its_copy_in_the_other_fan() {
    let mut w = pillow_beside_a_triangle();
    let copy = VertexId(5);
    let triangle_edges = w.valence(copy).unwrap();
    w.kev(EdgeId(0), VertexId(0)).unwrap();
    w.check().unwrap();
    assert!(!w.is_vertex(VertexId(0)));
    assert_eq!(w.valence(copy).unwrap(), triangle_edges);
    // Its dangling neighbour in the pillow goes too, down to a point face.
    w.kev(EdgeId(1), VertexId(2)).unwrap();
    w.check().unwrap();
}
