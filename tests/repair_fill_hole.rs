//! Hole filling: small and huge holes, planar and not, convex and not (L-shape, spiral,
//! saddle), refusals, and every open model of the test data closed without folds.

mod mesh_support;

use std::f64::consts::TAU;
use std::time::{Duration, Instant};

use halfwing::geom::self_intersections;
use halfwing::mesh::{BuildPolicy, FaceId, HalfedgeId, Mesh};
use halfwing::repair::{
    DEGENERATE_RATIO, FOLD_ANGLE_DEGREES, FillError, FillMode, HoleFillOptions, fill_hole,
    fill_hole_with, fill_holes,
};
use halfwing::soup::FaceList;
use mesh_support::{data_dir, load};

/// An open prism: walls joining the polygon `outline` (counter-clockwise seen from +z, heights
/// given per corner) to a copy 1 below. Its top loop is the hole; the bottom loop another.
fn prism(outline: &[[f64; 3]]) -> Mesh {
    prism_and(outline, &[])
}

/// [`prism`] and a triangle apart from it at `extra`'s corners (none when it is empty).
fn prism_and(outline: &[[f64; 3]], extra: &[[f64; 3]]) -> Mesh {
    let n = outline.len() as u32;
    let mut positions = outline.to_vec();
    positions.extend(outline.iter().map(|p| [p[0], p[1], -1.0]));
    let mut indices = Vec::new();
    for i in 0..n {
        let j = (i + 1) % n;
        indices.extend([n + i, n + j, j, n + i, j, i]);
    }
    if !extra.is_empty() {
        indices.extend([2 * n, 2 * n + 1, 2 * n + 2]);
        positions.extend_from_slice(extra);
    }
    Mesh::from_face_list(
        &FaceList::triangles(&positions, &indices),
        BuildPolicy::Strict,
    )
    .unwrap()
    .0
}

/// A boundary half-edge of the top loop (origin 0, target 1).
fn top_hole(mesh: &Mesh) -> HalfedgeId {
    let h = mesh
        .find_halfedge(halfwing::mesh::VertexId(0), halfwing::mesh::VertexId(1))
        .unwrap();
    assert!(mesh.is_boundary_halfedge(h));
    h
}

fn unit_normal(mesh: &Mesh, f: FaceId) -> [f64; 3] {
    let v = halfwing::geom::newell_vector(mesh.face_vertices(f).map(|v| mesh.position(v)));
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    assert!(len > 0.0, "face {f:?} has no area");
    [v[0] / len, v[1] / len, v[2] / len]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Checks the fill is not folded: every new face a proper triangle (twice its area above
/// `DEGENERATE_RATIO` times its longest side squared) turned at most `FOLD_ANGLE_DEGREES` from
/// every face beside it.
fn assert_not_folded(mesh: &Mesh, faces: &[FaceId]) {
    for &f in faces {
        let p: Vec<[f64; 3]> = mesh.face_vertices(f).map(|v| mesh.position(v)).collect();
        assert_eq!(p.len(), 3, "face {f:?} is not a triangle");
        let e = |a: [f64; 3], b: [f64; 3]| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>();
        let longest = e(p[0], p[1]).max(e(p[1], p[2])).max(e(p[2], p[0]));
        let v = halfwing::geom::newell_vector(p.iter().copied());
        let twice_area = dot(v, v).sqrt();
        assert!(
            twice_area > DEGENERATE_RATIO * longest,
            "face {f:?} is degenerate: {p:?}"
        );
    }
    let angle = largest_angle_to_neighbours(mesh, faces);
    assert!(angle <= FOLD_ANGLE_DEGREES, "a new face turns {angle}°");
}

/// The largest angle (degrees) between a new face's normal and a neighbour's.
fn largest_angle_to_neighbours(mesh: &Mesh, faces: &[FaceId]) -> f64 {
    let mut largest: f64 = 0.0;
    for &f in faces {
        let n = unit_normal(mesh, f);
        for g in mesh.face_faces(f) {
            largest = largest.max(
                dot(n, unit_normal(mesh, g))
                    .clamp(-1.0, 1.0)
                    .acos()
                    .to_degrees(),
            );
        }
    }
    largest
}

/// The mesh's faces as triangles (fans), for the self-intersection search.
fn triangles(mesh: &Mesh) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let positions = (0..mesh.n_vertex_slots() as u32)
        .map(|v| {
            let v = halfwing::mesh::VertexId(v);
            if mesh.check_vertex(v).is_ok() {
                mesh.position(v)
            } else {
                [0.0; 3]
            }
        })
        .collect();
    let mut tris = Vec::new();
    for f in 0..mesh.n_face_slots() as u32 {
        let f = FaceId(f);
        if mesh.check_face(f).is_err() {
            continue;
        }
        let c: Vec<u32> = mesh.face_vertices(f).map(|v| v.0).collect();
        for i in 1..c.len() - 1 {
            tris.push([c[0], c[i], c[i + 1]]);
        }
    }
    (positions, tris)
}

/// Fills the top hole of a prism over `outline` and checks: `n − 2` triangles, all facing up
/// within `tilt_degrees` of +z (0 for a planar outline), the mesh valid, no self-intersection.
fn fill_prism_top(outline: &[[f64; 3]], tilt_degrees: f64) {
    let mut mesh = prism(outline);
    let top = top_hole(&mesh);
    let filled = fill_hole(&mut mesh, top).unwrap();
    assert_eq!(filled.edges, outline.len());
    assert_eq!(filled.faces.len(), outline.len() - 2);
    mesh.check().unwrap();
    assert_not_folded(&mesh, &filled.faces);
    for &f in &filled.faces {
        let up = unit_normal(&mesh, f)[2];
        assert!(
            up >= tilt_degrees.to_radians().cos() - 1e-9,
            "face {f:?} tilts: {up}"
        );
    }
    if outline.len() <= 5000 {
        let (p, t) = triangles(&mesh);
        assert_eq!(self_intersections(&p, &t).unwrap(), Vec::<[u32; 2]>::new());
    }
}

fn circle(n: usize, height: impl Fn(f64, f64) -> f64) -> Vec<[f64; 3]> {
    (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            let (x, y) = (a.cos(), a.sin());
            [x, y, height(x, y)]
        })
        .collect()
}

/// An L: the unit square's corners with the top-right quarter cut out, each side split in `m`.
fn l_shape(m: usize) -> Vec<[f64; 3]> {
    let corners = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];
    let mut out = Vec::new();
    for i in 0..6 {
        let (a, b) = (corners[i], corners[(i + 1) % 6]);
        for s in 0..m {
            let t = s as f64 / m as f64;
            out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0.0]);
        }
    }
    out
}

/// A spiral arm of two turns and width 0.3: out along the outer edge, back along the inner.
fn spiral(m: usize) -> Vec<[f64; 3]> {
    let point = |theta: f64, r: f64| [r * theta.cos(), r * theta.sin(), 0.0];
    let mut out = Vec::new();
    for i in 0..m {
        let th = 2.0 * TAU * i as f64 / (m - 1) as f64;
        out.push(point(th, 1.0 + 0.5 * th / TAU + 0.3));
    }
    for i in (0..m).rev() {
        let th = 2.0 * TAU * i as f64 / (m - 1) as f64;
        out.push(point(th, 1.0 + 0.5 * th / TAU));
    }
    out
}

#[test]
fn three_edge_hole_gets_one_triangle() {
    fill_prism_top(&circle(3, |_, _| 0.0), 0.0);
}

#[test]
fn convex_and_nonconvex_planar_holes_are_covered_once() {
    fill_prism_top(&circle(40, |_, _| 0.0), 0.0);
    fill_prism_top(&l_shape(3), 0.0); // 18 corners: exact triangulation
    fill_prism_top(&l_shape(40), 0.0); // 240 corners: projected triangulation
    fill_prism_top(&spiral(30), 0.0); // 60 corners: exact
    fill_prism_top(&spiral(400), 0.0); // 800 corners: projected
}

#[test]
fn saddle_holes_face_up() {
    // z = 0.3 (x² − y²) on the unit circle: not planar, slopes below 35°.
    fill_prism_top(&circle(60, |x, y| 0.3 * (x * x - y * y)), 45.0);
    fill_prism_top(&circle(2000, |x, y| 0.3 * (x * x - y * y)), 45.0);
}

#[test]
fn hundred_thousand_edge_hole() {
    let outline = circle(100_000, |x, y| 0.1 * x * y);
    let start = Instant::now();
    fill_prism_top(&outline, 10.0);
    // Only a guard against quadratic behaviour (which would take minutes), not a benchmark.
    assert!(
        start.elapsed() < Duration::from_secs(60),
        "{:?}",
        start.elapsed()
    );
}

/// Counts of live faces, edges and vertices, and the boundary loops.
fn shape(mesh: &Mesh) -> (usize, usize, usize, usize) {
    (
        mesh.n_faces(),
        mesh.n_edges(),
        mesh.n_vertices(),
        mesh.boundary_loops().len(),
    )
}

#[test]
fn refusals_leave_the_mesh_unchanged() {
    let mut mesh = prism(&circle(8, |_, _| 0.0));
    let before = shape(&mesh);
    let inner = top_hole(&mesh).twin();
    assert!(matches!(
        fill_hole(&mut mesh, inner),
        Err(FillError::NotBoundary)
    ));
    assert!(matches!(
        fill_hole(&mut mesh, HalfedgeId(u32::MAX - 1)),
        Err(FillError::Handle(_))
    ));
    for bad in [f64::NAN, -1.0] {
        let options = HoleFillOptions {
            max_perimeter: bad,
            ..Default::default()
        };
        assert!(matches!(
            fill_holes(&mut mesh, &options),
            Err(FillError::BadOption { .. })
        ));
    }
    assert_eq!(before, shape(&mesh));
}

/// A face not joined to the hole's rim is found by the crossing test: a triangle standing
/// through the middle of the hole refuses every fill, exact or projected, triangulated or refined
/// (one hole alone, or all holes); the same triangle raised above the hole's plane refuses none.
#[test]
fn a_face_apart_from_the_rim_that_crosses_the_fill_refuses_it() {
    let through = [[-0.1, -0.1, -0.5], [0.1, 0.1, -0.5], [0.0, 0.0, 0.5]];
    let above = through.map(|p| [p[0], p[1], p[2] + 0.6]);
    for n in [8, 300] {
        let outline = circle(n, |_, _| 0.0);
        for mode in [FillMode::Triangulate, FillMode::Refine] {
            let mut mesh = prism_and(&outline, &through);
            let before = shape(&mesh);
            let top = top_hole(&mesh);
            let refused = fill_hole_with(&mut mesh, top, mode);
            assert!(
                matches!(refused, Err(FillError::SelfIntersecting)),
                "{n} corners, {mode:?}: {refused:?}"
            );
            assert_eq!(shape(&mesh), before);
            let options = HoleFillOptions {
                max_edges: n,
                max_perimeter: f64::INFINITY,
                mode,
            };
            let report = fill_holes(&mut mesh, &options).unwrap();
            let crossing = report
                .refused
                .iter()
                .filter(|(_, why)| matches!(why, FillError::SelfIntersecting))
                .count();
            assert_eq!(crossing, 1, "{n} corners, {mode:?}: {:?}", report.refused);
            mesh.check().unwrap();

            let mut mesh = prism_and(&outline, &above);
            let top = top_hole(&mesh);
            fill_hole_with(&mut mesh, top, mode).unwrap();
            mesh.check().unwrap();
        }
    }
}

/// A funnel: the walls run from the unit circle at height 0 inwards and down to a circle of
/// radius 0.1 just below, so they face down, under the top hole. Any cap over the top hole
/// folds onto them; it is refused and the mesh left as it was.
#[test]
fn a_fill_that_would_fold_is_refused() {
    for n in [12, 400] {
        let top = circle(n, |_, _| 0.0);
        let mut positions = top.clone();
        positions.extend(top.iter().map(|p| [0.1 * p[0], 0.1 * p[1], -0.05]));
        let n = n as u32;
        let mut indices = Vec::new();
        for i in 0..n {
            let j = (i + 1) % n;
            indices.extend([n + i, n + j, j, n + i, j, i]);
        }
        let mut mesh = Mesh::from_face_list(
            &FaceList::triangles(&positions, &indices),
            BuildPolicy::Strict,
        )
        .unwrap()
        .0;
        let before = shape(&mesh);
        let top = top_hole(&mesh);
        let result = fill_hole(&mut mesh, top);
        assert!(matches!(result, Err(FillError::Folded(_))), "{result:?}");
        assert_eq!(before, shape(&mesh));
        mesh.check().unwrap();
    }
}

#[test]
fn size_limits_choose_the_holes() {
    // Top and bottom loops have 8 edges and a perimeter of 16 sin(π/8) ≈ 6.12.
    let mut mesh = prism(&circle(8, |_, _| 0.0));
    let few_edges = HoleFillOptions {
        max_edges: 7,
        ..Default::default()
    };
    let report = fill_holes(&mut mesh, &few_edges).unwrap();
    assert_eq!((report.filled.len(), report.skipped), (0, 2));
    let short = HoleFillOptions {
        max_perimeter: 6.0,
        ..Default::default()
    };
    assert_eq!(fill_holes(&mut mesh, &short).unwrap().skipped, 2);
    let report = fill_holes(
        &mut mesh,
        &HoleFillOptions {
            max_edges: 8,
            max_perimeter: 6.2,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(report.filled.len(), 2);
    assert_eq!(report.faces_added(), 12);
    assert!(
        report
            .filled
            .iter()
            .all(|h| h.edges == 8 && h.faces.len() == 6)
    );
    assert!(mesh.boundary_loops().is_empty());
    mesh.check().unwrap();
}

#[test]
fn every_open_model_is_closed_without_folds() {
    fill_open_models(false);
}

#[test]
fn every_open_model_is_filled_without_new_self_intersections() {
    fill_open_models(true);
}

/// Every model of the test data's open set that builds: all holes filled but those refused,
/// the mesh valid, closed when none was refused, no fill folded and, when
/// `no_new_intersections`, no self-intersection the mesh did not have before.
fn fill_open_models(no_new_intersections: bool) {
    let mut paths: Vec<_> = std::fs::read_dir(data_dir().join("open"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    paths.sort();
    let mut filled_models = 0;
    for path in paths {
        let soup = load(&path);
        let Ok((mut mesh, _)) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip)
        else {
            continue;
        };
        let loops = mesh.boundary_loops().len();
        if loops == 0 {
            continue;
        }
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let (p, t) = triangles(&mesh);
        let before = self_intersections(&p, &t).unwrap();
        let report = fill_holes(&mut mesh, &HoleFillOptions::default()).unwrap();
        mesh.check().unwrap_or_else(|e| panic!("{name}: {e}"));
        let left = mesh.boundary_loops().len();
        assert_eq!(left, report.refused.len(), "{name}");
        let faces: Vec<FaceId> = report
            .filled
            .iter()
            .flat_map(|h| h.faces.iter().copied())
            .collect();
        assert_not_folded(&mesh, &faces);
        let (p, t) = triangles(&mesh);
        let after = self_intersections(&p, &t).unwrap();
        // Triangles are listed face by face, so the old faces keep their triangle indices.
        let new_pairs: Vec<[u32; 2]> = after
            .iter()
            .copied()
            .filter(|pair| !before.contains(pair))
            .collect();
        for (_, why) in &report.refused {
            eprintln!("{name}: refused: {why}");
        }
        eprintln!(
            "{name}: {loops} holes, {} filled ({} faces), {left} left ({} refused), largest angle {:.1}°, \
             self-intersections {} -> {}",
            report.filled.len(),
            faces.len(),
            report.refused.len(),
            largest_angle_to_neighbours(&mesh, &faces),
            before.len(),
            after.len()
        );
        if no_new_intersections {
            assert!(
                new_pairs.is_empty(),
                "{name}: new self-intersections {new_pairs:?}"
            );
        }
        filled_models += usize::from(!report.filled.is_empty());
    }
    // Flat sheets (a triangle, a square, a plane) are refused: their cap would lie on them,
    // facing the other way, a fold. The teapot's holes lie where its parts already run through
    // each other (453 intersecting pairs before any fill): every fill tried crosses them, and
    // they are refused. The eight other open models are filled.
    assert!(filled_models >= 8, "{filled_models} models filled");
}

/// A flat 4 × 4 grid of unit squares (corners `(i, j, 0)`, vertex `5j + i`) without the squares
/// at (1, 1) and (2, 2), then `extra` triangles (corners appended after the grid's): the build
/// splits vertex 12 at (2, 2), where the two squares meet, into two copies, one per fan, and the
/// two squares make one hole whose boundary passes twice through (2, 2).
fn figure_eight_hole(extra: &[[f64; 3]]) -> Mesh {
    figure_eight_of_blocks(1, extra)
}

/// [`figure_eight_hole`] with every square of the grid cut into `block` × `block` unit squares:
/// a hole of `8 × block` edges through `(2 block, 2 block)` twice.
fn figure_eight_of_blocks(block: u32, extra: &[[f64; 3]]) -> Mesh {
    let side = 4 * block;
    let mut positions: Vec<[f64; 3]> = (0..(side + 1) * (side + 1))
        .map(|k| [f64::from(k % (side + 1)), f64::from(k / (side + 1)), 0.0])
        .collect();
    let mut indices = Vec::new();
    for (i, j) in (0..side).flat_map(|j| (0..side).map(move |i| (i, j))) {
        let square = (i / block, j / block);
        if square != (1, 1) && square != (2, 2) {
            let v = (side + 1) * j + i;
            indices.extend([v, v + 1, v + side + 2, v, v + side + 2, v + side + 1]);
        }
    }
    for corners in extra.chunks(3) {
        indices.extend((0..3).map(|k| (positions.len() + k) as u32));
        positions.extend_from_slice(corners);
    }
    let (mesh, diagnostic) = Mesh::from_face_list(
        &FaceList::triangles(&positions, &indices),
        BuildPolicy::Repair,
    )
    .unwrap();
    assert_eq!(diagnostic.vertex_copies.len(), 1);
    let lengths: Vec<usize> = mesh
        .boundary_loops()
        .iter()
        .map(|&h| mesh.halfedge_loop(h).count())
        .collect();
    assert!(lengths.contains(&(8 * block as usize)), "{lengths:?}");
    mesh
}

/// Holes only up to the figure eight's 8 edges (the grid's outer border has 16).
const INNER_HOLES: HoleFillOptions = HoleFillOptions {
    max_edges: 8,
    max_perimeter: f64::INFINITY,
    mode: FillMode::Triangulate,
};

#[test]
fn each_part_of_a_hole_through_one_point_twice_is_refined_and_faired() {
    for mode in [FillMode::Refine, FillMode::Fair] {
        let mut mesh = figure_eight_of_blocks(3, &[]);
        let options = HoleFillOptions {
            max_edges: 24,
            mode,
            ..HoleFillOptions::default()
        };
        let report = fill_holes(&mut mesh, &options).unwrap();
        assert!(report.refused.is_empty(), "{mode:?}: {:?}", report.refused);
        assert_eq!(report.filled.len(), 2, "{mode:?}");
        assert_eq!(report.welded_vertices.len(), 1, "{mode:?}");
        for hole in &report.filled {
            assert_eq!(hole.edges, 12);
            assert!(
                !hole.vertices.is_empty(),
                "{mode:?}: a 3 × 3 hole is refined"
            );
            assert_eq!(hole.faces.len(), hole.edges - 2 + 2 * hole.vertices.len());
            for &v in &hole.vertices {
                let [x, y, z] = mesh.position(v);
                // Inside one of the two squares, on their plane (fairing a flat rim keeps it).
                let inside = |lo: f64| x > lo && x < lo + 3.0 && y > lo && y < lo + 3.0;
                assert!(inside(3.0) || inside(6.0), "{mode:?}: ({x}, {y})");
                assert!(z.abs() < 1e-9, "{mode:?}: z = {z}");
            }
        }
        mesh.check().unwrap();
        assert_eq!(
            mesh.boundary_loops().len(),
            1,
            "{mode:?}: the outer border is left"
        );
        assert!(mesh.non_manifold_vertices().is_empty());
    }
}

#[test]
fn a_hole_through_one_point_twice_is_filled_as_two() {
    let mut mesh = figure_eight_hole(&[]);
    let vertices = mesh.n_vertices();
    let report = fill_holes(&mut mesh, &INNER_HOLES).unwrap();
    assert_eq!(report.filled.len(), 2);
    assert!(report.filled.iter().all(|h| h.edges == 4));
    assert!(report.refused.is_empty(), "{:?}", report.refused);
    assert_eq!(report.faces_added(), 4);
    assert_eq!(report.welded_vertices.len(), 1);
    let [gone, kept] = report.welded_vertices[0];
    assert_eq!(mesh.position(kept), [2.0, 2.0, 0.0]);
    assert!(mesh.is_vertex_deleted(gone));
    mesh.check().unwrap();
    assert_eq!(mesh.n_vertices(), vertices - 1);
    assert!(mesh.non_manifold_vertices().is_empty());
    assert_eq!(
        mesh.boundary_loops().len(),
        1,
        "only the outer border is left"
    );
    let faces: Vec<FaceId> = report.filled.iter().flat_map(|h| h.faces.clone()).collect();
    assert_not_folded(&mesh, &faces);
}

#[test]
fn a_hole_through_one_point_twice_is_left_whole_when_no_part_fills() {
    // A vertical triangle through both squares: every fill of either part crosses it.
    let blade = [[1.2, 1.2, -1.0], [2.8, 2.8, -1.0], [2.0, 2.0, 1.0]];
    let mut mesh = figure_eight_hole(&blade);
    let before = shape(&mesh);
    let loops = mesh.boundary_loops();
    let report = fill_holes(&mut mesh, &INNER_HOLES).unwrap();
    assert!(report.filled.is_empty());
    assert!(report.welded_vertices.is_empty());
    // Refused once, as one hole (the blade's own border, a flat triangle's, is refused too).
    let crossing: Vec<HalfedgeId> = report
        .refused
        .iter()
        .filter(|(_, why)| matches!(why, FillError::SelfIntersecting))
        .map(|&(h, _)| h)
        .collect();
    assert_eq!(crossing.len(), 1, "{:?}", report.refused);
    assert_eq!(mesh.halfedge_loop(crossing[0]).count(), 8);
    assert_eq!(report.refused.len(), 2);
    let refused: Vec<HalfedgeId> = report.refused.iter().map(|r| r.0).collect();
    assert_eq!(refused, loops[1..], "the outer border is beyond the bounds");
    assert_eq!(shape(&mesh), before);
    assert_eq!(mesh.boundary_loops(), loops);
    mesh.check().unwrap();
}

/// A unit UV sphere of `rings` bands up to latitude +30°, its cap left open: a planar hole of
/// `segments` edges in the plane z = 1/2.
fn capless_sphere(segments: u32, rings: u32) -> Mesh {
    let pi = std::f64::consts::PI;
    let mut positions = vec![[0.0, 0.0, -1.0]];
    for r in 1..=rings {
        let lat = -pi / 2.0 + (pi / 2.0 + pi / 6.0) * f64::from(r) / f64::from(rings);
        for s in 0..segments {
            let lon = TAU * f64::from(s) / f64::from(segments);
            positions.push([lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin()]);
        }
    }
    let at = |r: u32, s: u32| 1 + (r - 1) * segments + s % segments;
    let mut indices = Vec::new();
    for s in 0..segments {
        indices.extend([0, at(1, s + 1), at(1, s)]);
    }
    for r in 1..rings {
        for s in 0..segments {
            let (a, b, c, d) = (at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r + 1, s));
            indices.extend([a, b, c, a, c, d]);
        }
    }
    let list = FaceList::triangles(&positions, &indices);
    Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0
}

#[test]
fn a_planar_round_hole_is_not_filled_by_a_fan() {
    // Every triangulation of a flat hole tilts by nothing: the fan the sweep gives a convex
    // ring would be kept, each of its triangles' boxes holding O(n) of the rim's faces, and the
    // crossing test would cost O(n²). The strip's triangles meet each corner at most 3 times.
    let mut mesh = capless_sphere(400, 6);
    let h = mesh.boundary_loops()[0];
    let hole = fill_hole(&mut mesh, h).unwrap();
    assert_eq!(hole.faces.len(), 398);
    let mut uses = std::collections::HashMap::new();
    for &f in &hole.faces {
        for v in mesh.face_vertices(f) {
            *uses.entry(v).or_insert(0) += 1;
        }
    }
    let most = uses.values().copied().max().unwrap();
    assert!(most <= 3, "a corner in {most} new triangles");
    mesh.check().unwrap();
}
