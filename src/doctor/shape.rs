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
    let mut zero_length_edges: Vec<[u32; 2]> = edges
        .iter()
        .filter(|(ends, _)| at(ends[0]) == at(ends[1]))
        .map(|&(ends, _)| ends)
        .collect();
    zero_length_edges.sort_unstable();
    let mut lengths: Vec<f64> = edges.iter().map(|&(_, length)| length).collect();
    let mut long_edges: Vec<[u32; 2]> = if lengths.is_empty() {
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
    long_edges.sort_unstable();

    let (mut needles, mut caps) = (Vec::new(), Vec::new());
    let needle = Angle::degrees(options.needle_angle_degrees);
    let cap = Angle::degrees(options.cap_angle_degrees);
    for f in 0..surface.n_faces() {
        if let &[a, b, c] = surface.face(f) {
            let [a, b, c] = [a, b, c].map(at);
            let corners = [(a, b, c), (b, c, a), (c, a, b)];
            let sides = corners.map(|(p, q, r)| (difference(q, p), difference(r, p)));
            // A corner with a zero-length side has angle 0: a collapsed triangle is a needle.
            if sides
                .iter()
                .any(|&(u, v)| needle.exceeds(u, v).is_none_or(|wider| !wider))
            {
                needles.push(surface.input_face(f));
            }
            if sides.iter().any(|&(u, v)| cap.exceeds(u, v) == Some(true)) {
                caps.push(surface.input_face(f));
            }
        }
    }

    let fold = Angle::degrees(options.fold_angle_degrees);
    let normals: Vec<[f64; 3]> = (0..surface.n_faces())
        .map(|f| newell_vector(surface.face(f).iter().map(|&v| at(v))))
        .collect();
    let mut folded_edges = Vec::new();
    for (c, &p) in pairing.partner.iter().enumerate() {
        if p == BOUNDARY || p == UNPAIRED || (p as usize) < c {
            continue;
        }
        let (f, g) = (
            surface.face_of_corner(c),
            surface.face_of_corner(p as usize),
        );
        if fold.exceeds(normals[f], normals[g]) == Some(true) {
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

fn difference(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// A threshold angle, compared with the angle between two vectors through cosines: no inverse
/// trigonometry per corner.
#[derive(Clone, Copy)]
struct Angle {
    cosine: f64,
}

impl Angle {
    fn degrees(degrees: f64) -> Self {
        Angle {
            cosine: degrees.to_radians().cos(),
        }
    }

    /// Whether the angle between `u` and `v` is larger than this one; `None` when one of them
    /// is zero or not finite. The vectors are scaled to unit size first, so that neither tiny
    /// nor huge coordinates under- or overflow.
    fn exceeds(self, u: [f64; 3], v: [f64; 3]) -> Option<bool> {
        let unit = |w: [f64; 3]| {
            let length = distance(w, [0.0; 3]);
            (length > 0.0 && length.is_finite()).then(|| w.map(|x| x / length))
        };
        let (u, v) = (unit(u)?, unit(v)?);
        let cosine = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        Some(cosine < self.cosine)
    }
}
