//! Badly shaped elements: zero-length edges, needle and cap triangles, faces folded onto their
//! neighbours, and edges much longer than the rest.

use super::DoctorOptions;
use super::measure::distance;
use crate::geom::newell_vector;
use crate::soup::{BOUNDARY, EdgePairing, FaceTable, UNPAIRED};

/// An edge whose two faces fold onto each other. Laid out as four `u32` (C reads a list of them
/// as one array).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FoldedEdge {
    /// The edge's ends, smaller first.
    pub vertices: [u32; 2],
    /// Its two faces, ascending.
    pub faces: [u32; 2],
}

/// The shape findings, as [`super::DoctorReport`] holds them.
pub(super) struct Shapes {
    pub(super) zero_length_edges: Vec<[u32; 2]>,
    pub(super) needles: Vec<u32>,
    pub(super) caps: Vec<u32>,
    pub(super) folded_edges: Vec<FoldedEdge>,
    pub(super) long_edges: Vec<[u32; 2]>,
}

/// The shape findings of `surface` (whose edges `pairing` pairs). Needles and caps are
/// triangles only (a polygon's angles say nothing of its triangles'); folds are judged across
/// two-face edges, between the faces' Newell normals.
pub(super) fn shapes(
    surface: &FaceTable<'_>,
    pairing: &EdgePairing,
    positions: &[[f64; 3]],
    options: &DoctorOptions,
) -> Shapes {
    let corners = surface.corners();
    let at = |v: u32| positions[v as usize];
    // Every edge once: from its lower corner when paired, from each problem once.
    let mut edges: Vec<([u32; 2], f64)> = Vec::new();
    for c in 0..corners.len() {
        let keep = match pairing.partner[c] {
            BOUNDARY => true,
            UNPAIRED => false,
            p => (p as usize) > c,
        };
        if keep {
            let (a, b) = (corners[c], corners[surface.next_corner(c)]);
            edges.push(([a.min(b), a.max(b)], distance(at(a), at(b))));
        }
    }
    for problem in &pairing.problems {
        let [a, b] = problem.vertices;
        edges.push(([a, b], distance(at(a), at(b))));
    }
    edges.sort_unstable_by_key(|&(ends, _)| ends);

    let zero_length_edges = edges
        .iter()
        .filter(|(ends, _)| at(ends[0]) == at(ends[1]))
        .map(|&(ends, _)| ends)
        .collect();
    let mut lengths: Vec<f64> = edges.iter().map(|&(_, length)| length).collect();
    let long_edges = if lengths.is_empty() {
        Vec::new()
    } else {
        let middle = lengths.len() / 2;
        let (_, &mut median, _) = lengths.select_nth_unstable_by(middle, f64::total_cmp);
        edges
            .iter()
            .filter(|&&(_, length)| length > options.long_edge_ratio * median)
            .map(|&(ends, _)| ends)
            .collect()
    };

    let (mut needles, mut caps) = (Vec::new(), Vec::new());
    let needle = options.needle_angle_degrees.to_radians();
    let cap = options.cap_angle_degrees.to_radians();
    for f in 0..surface.n_faces() {
        if let &[a, b, c] = surface.face(f) {
            let angles = triangle_angles(at(a), at(b), at(c));
            let (smallest, largest) = angles
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(s, l), &x| (s.min(x), l.max(x)));
            if smallest < needle {
                needles.push(surface.input_face(f));
            }
            if largest > cap {
                caps.push(surface.input_face(f));
            }
        }
    }

    let fold = options.fold_angle_degrees.to_radians();
    let normal = |f: usize| newell_vector(surface.face(f).iter().map(|&v| at(v)));
    let mut folded_edges = Vec::new();
    for (c, &p) in pairing.partner.iter().enumerate() {
        if p == BOUNDARY || p == UNPAIRED || (p as usize) < c {
            continue;
        }
        let (f, g) = (
            surface.face_of_corner(c),
            surface.face_of_corner(p as usize),
        );
        if angle_between(normal(f), normal(g)).is_some_and(|angle| angle > fold) {
            let (a, b) = (corners[c], corners[surface.next_corner(c)]);
            let (f, g) = (surface.input_face(f), surface.input_face(g));
            folded_edges.push(FoldedEdge {
                vertices: [a.min(b), a.max(b)],
                faces: [f.min(g), f.max(g)],
            });
        }
    }
    folded_edges.sort_unstable_by_key(|edge| edge.vertices);

    needles.sort_unstable();
    caps.sort_unstable();
    Shapes {
        zero_length_edges,
        needles,
        caps,
        folded_edges,
        long_edges,
    }
}

/// The angles (radians) of triangle `a b c` at its three corners; a corner with a zero-length
/// side has angle 0 (a collapsed triangle is a needle).
fn triangle_angles(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    let corner = |p: [f64; 3], q: [f64; 3], r: [f64; 3]| {
        let u = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
        let v = [r[0] - p[0], r[1] - p[1], r[2] - p[2]];
        angle_between(u, v).unwrap_or(0.0)
    };
    [corner(a, b, c), corner(b, c, a), corner(c, a, b)]
}

/// The angle between `u` and `v` (radians, by `atan2` of the cross and dot products of the
/// vectors scaled to unit size, accurate near 0 and π), or `None` when one is zero or not
/// finite.
fn angle_between(u: [f64; 3], v: [f64; 3]) -> Option<f64> {
    let unit = |w: [f64; 3]| {
        let length = distance(w, [0.0; 3]);
        (length > 0.0 && length.is_finite()).then(|| w.map(|x| x / length))
    };
    let (u, v) = (unit(u)?, unit(v)?);
    let cross = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    Some(distance(cross, [0.0; 3]).atan2(dot))
}
