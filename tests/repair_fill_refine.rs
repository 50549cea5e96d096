//! Refined and faired hole fills: edge lengths like the boundary's, no folds, a valid closed
//! mesh, interpolated attributes, idempotence, fairing that restores curvature, long holes,
//! and refusals that leave the mesh unchanged.

use std::time::{Duration, Instant};

mod mesh_support;
use mesh_support::largest_turn;

use halfwing::geom::self_intersections;
use halfwing::mesh::{BuildPolicy, ElementKind, FaceId, HalfedgeId, Mesh, VertexId};
use halfwing::repair::{
    FOLD_ANGLE_DEGREES, FillError, FillMode, HoleFillOptions, HoleFillReport, fill_hole_with,
    fill_holes,
};
use halfwing::soup::FaceList;
use halfwing::surfaces::icosphere;

/// A unit icosphere of `level` with the faces whose centroids lie above `height` removed, and
/// a vertex attribute `height` holding each vertex's z.
fn capless_sphere(level: u32, height: f64) -> Mesh {
    let (mut mesh, _) =
        Mesh::from_soup(&icosphere(1.0, level).unwrap(), BuildPolicy::Strict).unwrap();
    let cap: Vec<FaceId> = (0..mesh.n_face_slots() as u32)
        .map(FaceId)
        .filter(|&f| {
            let z: f64 = mesh.face_vertices(f).map(|v| mesh.position(v)[2]).sum();
            z / 3.0 > height
        })
        .collect();
    for f in cap {
        mesh.delete_face(f, true).unwrap();
    }
    mesh.garbage_collect();
    mesh.add_attribute::<f64>(ElementKind::Vertex, "height", 1)
        .unwrap();
    let heights: Vec<f64> = mesh.positions().iter().map(|p| p[2]).collect();
    mesh.attribute_mut::<f64>(ElementKind::Vertex, "height")
        .unwrap()
        .copy_from_slice(&heights);
    mesh
}

fn length(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
}

fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, count) = values.fold((0.0, 0), |(s, c), x| (s + x, c + 1));
    sum / count as f64
}

fn no_self_intersection(mesh: &Mesh) {
    // The fills are on a mesh without deleted elements: ids are indices.
    let triangles: Vec<[u32; 3]> = (0..mesh.n_face_slots() as u32)
        .map(|f| {
            let c: Vec<u32> = mesh.face_vertices(FaceId(f)).map(|v| v.0).collect();
            [c[0], c[1], c[2]]
        })
        .collect();
    assert_eq!(
        self_intersections(mesh.positions(), &triangles).unwrap(),
        Vec::<[u32; 2]>::new()
    );
}

/// The one boundary loop's half-edge and its edges' mean length.
fn the_hole(mesh: &Mesh) -> (HalfedgeId, f64) {
    let loops = mesh.boundary_loops();
    assert_eq!(loops.len(), 1);
    let h = loops[0];
    let lengths = mesh
        .halfedge_loop(h)
        .map(|s| length(mesh.position(mesh.origin(s)), mesh.position(mesh.target(s))));
    (h, mean(lengths))
}

/// Fills the cap above `height` of a capless sphere in `mode` and checks what every refined fill must hold.
fn fill_cap(level: u32, height: f64, mode: FillMode) -> (Mesh, HoleFillReport) {
    let mut mesh = capless_sphere(level, height);
    let (h, boundary_length) = the_hole(&mesh);
    let mut coarse = mesh.clone();
    let coarse_faces = fill_hole_with(&mut coarse, h, FillMode::Triangulate)
        .unwrap()
        .faces;
    let coarse_turn = largest_turn(&coarse, &coarse_faces);
    let (v0, e0, f0) = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
    let report = fill_holes(
        &mut mesh,
        &HoleFillOptions {
            mode,
            ..HoleFillOptions::default()
        },
    )
    .unwrap();
    assert!(report.refused.is_empty(), "{:?}", report.refused);
    let hole = &report.filled[0];
    mesh.check().unwrap();
    assert!(mesh.boundary_loops().is_empty());
    // A disk of `vertices` inside a ring of `edges`: Euler's formula.
    assert_eq!(hole.faces.len(), hole.edges - 2 + 2 * hole.vertices.len());
    assert_eq!(mesh.n_vertices(), v0 + report.vertices_added());
    assert_eq!(mesh.n_faces(), f0 + report.faces_added());
    assert_eq!(
        mesh.n_edges(),
        e0 + hole.edges - 3 + 3 * hole.vertices.len()
    );
    let (v, e, f) = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
    assert_eq!(v as i64 - e as i64 + f as i64, 2, "a sphere again");
    // Refined edges are about the boundary's: Liepa's density keeps them within a factor √2
    // or so of the local scale.
    let mut new_edges = Vec::new();
    for &f in &hole.faces {
        for h in mesh.face_loop(f) {
            new_edges.push(length(
                mesh.position(mesh.origin(h)),
                mesh.position(mesh.target(h)),
            ));
        }
    }
    let new_mean = mean(new_edges.iter().copied());
    assert!(
        (0.6 * boundary_length..=1.6 * boundary_length).contains(&new_mean),
        "new edges {new_mean} against the boundary's {boundary_length}"
    );
    assert!(
        hole.vertices.len() > hole.edges,
        "refinement adds vertices inside"
    );
    // No fold, and not much sharper a turn than the triangulation refined (whose triangles
    // between the rim's zigzag corners stand steep; flips there trade one turn for another).
    let turn = largest_turn(&mesh, &hole.faces);
    assert!(
        turn <= FOLD_ANGLE_DEGREES.min(coarse_turn + 15.0),
        "a new face turns {turn}°, {coarse_turn}° unrefined"
    );
    no_self_intersection(&mesh);
    // Attributes: each new vertex's height the mean of existing ones, so within the rim's.
    let heights = mesh
        .attribute::<f64>(ElementKind::Vertex, "height")
        .unwrap();
    let rim: Vec<f64> = (0..mesh.n_vertex_slots() as u32)
        .map(VertexId)
        .filter(|&v| !hole.vertices.contains(&v))
        .filter(|&v| mesh.position(v)[2] > height - 0.1)
        .map(|v| heights[v.0 as usize])
        .collect();
    let (low, high) = rim
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
    for &v in &hole.vertices {
        let x = heights[v.0 as usize];
        assert!(
            x >= low - 1e-12 && x <= high + 1e-12,
            "height {x} outside {low}..{high}"
        );
    }
    // A second run finds no hole: nothing changes.
    let before = (
        mesh.n_vertices(),
        mesh.n_edges(),
        mesh.n_faces(),
        mesh.positions().to_vec(),
    );
    let again = fill_holes(
        &mut mesh,
        &HoleFillOptions {
            mode,
            ..HoleFillOptions::default()
        },
    )
    .unwrap();
    assert_eq!(again, HoleFillReport::default());
    assert_eq!(
        before,
        (
            mesh.n_vertices(),
            mesh.n_edges(),
            mesh.n_faces(),
            mesh.positions().to_vec()
        )
    );
    (mesh, report)
}

#[test]
fn refined_cap_matches_the_boundary() {
    // Level 4: a hole of fewer than 100 edges (exact triangulation first); level 5: more
    // (projected triangulation first).
    for level in [4, 5] {
        fill_cap(level, 0.6, FillMode::Refine);
    }
}

#[test]
fn faired_cap_bulges_like_the_sphere() {
    // (Level 5 cut at 0.6 has a rim whose projected triangulation stands steep triangles
    // between zigzag corners; fairing folds one of them there and the hole is refused.)
    for (level, height) in [(4, 0.6), (5, 0.8)] {
        let (flat, flat_report) = fill_cap(level, height, FillMode::Refine);
        let (faired, faired_report) = fill_cap(level, height, FillMode::Fair);
        let top = |mesh: &Mesh, report: &HoleFillReport| {
            report.filled[0]
                .vertices
                .iter()
                .map(|&v| mesh.position(v)[2])
                .fold(f64::MIN, f64::max)
        };
        // A refined fill stays in the cut's plane, a faired one rises towards the sphere's top
        // (z = 1) as the surface around it curves.
        let (flat_top, faired_top) = (top(&flat, &flat_report), top(&faired, &faired_report));
        assert!(flat_top < height + 0.1, "{flat_top}");
        let bulge = (faired_top - height) / (1.0 - height);
        assert!(bulge > 0.5 && bulge < 1.5, "{faired_top}");
    }
}

/// An open box of `n` × 1 unit squares' walls around a 1 × `n` rectangle at z = 0: its top
/// loop has `2n + 2` edges, all of length 1, and spans a thin strip.
fn open_strip(n: usize) -> Mesh {
    let mut outline = Vec::with_capacity(2 * n + 2);
    outline.extend((0..=n).map(|i| [i as f64, 0.0, 0.0]));
    outline.extend((0..=n).rev().map(|i| [i as f64, 1.0, 0.0]));
    let m = outline.len() as u32;
    let mut positions = outline.clone();
    positions.extend(outline.iter().map(|p| [p[0], p[1], -1.0]));
    let mut indices = Vec::new();
    for i in 0..m {
        let j = (i + 1) % m;
        indices.extend([m + i, m + j, j, m + i, j, i]);
    }
    Mesh::from_face_list(
        &FaceList::triangles(&positions, &indices),
        BuildPolicy::Strict,
    )
    .unwrap()
    .0
}

#[test]
fn long_thin_hole_refines_in_linear_size() {
    let mut mesh = open_strip(50_000);
    let top = mesh.find_halfedge(VertexId(0), VertexId(1)).unwrap();
    let start = Instant::now();
    let filled = fill_hole_with(&mut mesh, top, FillMode::Fair).unwrap();
    assert_eq!(filled.edges, 100_002);
    // The strip is one edge wide: refinement has little to add.
    assert!(
        filled.vertices.len() <= filled.edges,
        "{}",
        filled.vertices.len()
    );
    mesh.check().unwrap();
    // Only a guard against quadratic behaviour (minutes), not a benchmark.
    assert!(
        start.elapsed() < Duration::from_secs(60),
        "{:?}",
        start.elapsed()
    );
}

#[test]
fn three_edge_hole_stays_one_triangle() {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let indices = [0, 2, 1, 0, 1, 3, 1, 2, 3];
    for mode in [FillMode::Refine, FillMode::Fair] {
        let (mut mesh, _) = Mesh::from_face_list(
            &FaceList::triangles(&positions, &indices),
            BuildPolicy::Strict,
        )
        .unwrap();
        let h = mesh.boundary_loops()[0];
        let filled = fill_hole_with(&mut mesh, h, mode).unwrap();
        assert_eq!((filled.faces.len(), filled.vertices.len()), (1, 0));
        mesh.check().unwrap();
    }
}

#[test]
fn refusals_leave_the_mesh_unchanged() {
    let mut mesh = capless_sphere(3, 0.6);
    let before = (mesh.n_vertices(), mesh.n_faces(), mesh.positions().to_vec());
    let bad = HoleFillOptions {
        max_perimeter: f64::NAN,
        mode: FillMode::Fair,
        ..HoleFillOptions::default()
    };
    assert!(matches!(
        fill_holes(&mut mesh, &bad),
        Err(FillError::BadOption { .. })
    ));
    // A half-edge with a face.
    let inner = mesh.face_halfedge(FaceId(0));
    assert_eq!(
        fill_hole_with(&mut mesh, inner, FillMode::Refine),
        Err(FillError::NotBoundary)
    );
    assert_eq!(
        before,
        (mesh.n_vertices(), mesh.n_faces(), mesh.positions().to_vec())
    );
}
