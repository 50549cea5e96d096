//! Duplicates: vertices at one position or within a tolerance, faces on one vertex set, and
//! T-vertices (a vertex lying inside a boundary edge: the two sides of a crack that do not
//! share their vertices).

use std::collections::HashMap;

use super::measure::{bounding_box, distance};
use super::point_tree::PointTree;
use crate::soup::{BOUNDARY, EdgePairing, FaceTable};

/// A vertex lying inside a boundary edge it is not an end of, within the tolerance. Laid out as
/// four `u32` (C reads a list of them as one array).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TVertex {
    /// The vertex.
    pub vertex: u32,
    /// The boundary edge's ends, smaller first.
    pub edge: [u32; 2],
    /// The edge's one face.
    pub face: u32,
}

/// The tolerance's absolute distance: `relative` times the diagonal of the bounding box of the
/// vertices the faces of `table` name (0 when there are none, or the box is not finite).
pub(super) fn absolute_tolerance(
    table: &FaceTable<'_>,
    positions: &[[f64; 3]],
    relative: f64,
) -> f64 {
    let named = table
        .corners()
        .iter()
        .filter_map(|&v| positions.get(v as usize));
    let [low, high] = bounding_box(named.copied());
    let diagonal = distance(low, high);
    if diagonal.is_finite() {
        relative * diagonal
    } else {
        0.0
    }
}

/// Vertices that coincide with a lower one.
pub(super) struct Coincident {
    /// `[v, first]`: same position exactly.
    pub(super) exact: Vec<[u32; 2]>,
    /// `[v, first]`: within the tolerance, not at the same position.
    pub(super) within_tolerance: Vec<[u32; 2]>,
}

/// The vertices (all of `positions` with finite coordinates, named by a face or not) at the
/// position of a lower vertex, and those within `tolerance` of one.
///
/// Near duplicates are grouped greedily, as a merge would: vertices are taken in order; one
/// within the tolerance of a group's first vertex joins that group (and is listed with it),
/// else it starts a group. Group leaders are more than the tolerance apart, so a grid of cells
/// the tolerance wide holds a bounded number of them per cell and each vertex is checked against
/// a bounded number: linear time whatever the input's shape.
pub(super) fn coincident_vertices(
    table: &FaceTable<'_>,
    positions: &[[f64; 3]],
    tolerance: f64,
) -> Coincident {
    let finite = |v: usize| positions[v].iter().all(|x| x.is_finite());
    // -0.0 and 0.0 are one position.
    let key = |v: usize| positions[v].map(|x| (x + 0.0).to_bits());
    let mut order: Vec<u32> = (0..positions.len() as u32)
        .filter(|&v| finite(v as usize))
        .collect();
    order.sort_by_key(|&v| (key(v as usize), v));
    let mut exact: Vec<[u32; 2]> = order
        .chunk_by(|&a, &b| key(a as usize) == key(b as usize))
        .flat_map(|group| group[1..].iter().map(move |&v| [v, group[0]]))
        .collect();
    exact.sort_unstable();

    let mut within_tolerance = Vec::new();
    if tolerance > 0.0 {
        let named = table
            .corners()
            .iter()
            .filter_map(|&v| positions.get(v as usize));
        let [low, _] = bounding_box(named.copied().chain(positions.iter().copied()));
        // Cells numbered from the box's corner, so the numbers stay below 1 / tolerance.
        let cell = |p: [f64; 3]| -> [i64; 3] {
            std::array::from_fn(|k| ((p[k] - low[k]) / tolerance).floor().clamp(-1e15, 1e15) as i64)
        };
        let mut leaders: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        for v in (0..positions.len()).filter(|&v| finite(v)) {
            let p = positions[v];
            let home = cell(p);
            let mut joined = None;
            'search: for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        let near = [home[0] + dx, home[1] + dy, home[2] + dz];
                        for &leader in leaders.get(&near).into_iter().flatten() {
                            if distance(p, positions[leader as usize]) <= tolerance {
                                joined = Some(leader);
                                break 'search;
                            }
                        }
                    }
                }
            }
            match joined {
                Some(leader) if positions[leader as usize] != p => {
                    within_tolerance.push([v as u32, leader]);
                }
                Some(_) => {}
                None => leaders.entry(home).or_default().push(v as u32),
            }
        }
    }
    Coincident {
        exact,
        within_tolerance,
    }
}

/// Pairs `[f, first]` of faces of `surface` on the same vertex set as a lower face (input
/// indices, ascending).
pub(super) fn duplicate_faces(surface: &FaceTable<'_>) -> Vec<[u32; 2]> {
    let mut first_with: HashMap<Vec<u32>, u32> = HashMap::new();
    let mut duplicates = Vec::new();
    for f in 0..surface.n_faces() {
        let mut set = surface.face(f).to_vec();
        set.sort_unstable();
        let face = surface.input_face(f);
        let first = *first_with.entry(set).or_insert(face);
        if first != face {
            duplicates.push([face, first]);
        }
    }
    duplicates
}

/// The vertices of boundary edges of `surface` lying within `tolerance` of the inside of
/// another boundary edge (strictly between its ends, at neither end's position). Each edge asks
/// a [`PointTree`] of the boundary vertices for those near it.
pub(super) fn t_vertices(
    surface: &FaceTable<'_>,
    pairing: &EdgePairing,
    positions: &[[f64; 3]],
    tolerance: f64,
) -> Vec<TVertex> {
    let corners = surface.corners();
    let at = |v: u32| positions[v as usize];
    let finite = |v: u32| at(v).iter().all(|x| x.is_finite());
    let edges: Vec<(u32, u32, usize)> = (0..corners.len())
        .filter(|&c| pairing.partner[c] == BOUNDARY)
        .map(|c| (corners[c], corners[surface.next_corner(c)], c))
        .filter(|&(a, b, _)| finite(a) && finite(b))
        .collect();
    let mut boundary_vertices: Vec<u32> = edges.iter().flat_map(|&(a, b, _)| [a, b]).collect();
    boundary_vertices.sort_unstable();
    boundary_vertices.dedup();
    let tree = PointTree::new(boundary_vertices, &at);
    let mut found = Vec::new();
    for &(a, b, c) in &edges {
        let (pa, pb) = (at(a), at(b));
        tree.near_segment(pa, pb, tolerance, |v| {
            let p = at(v);
            if v != a && v != b && p != pa && p != pb && lies_inside_segment(p, pa, pb, tolerance) {
                found.push(TVertex {
                    vertex: v,
                    edge: [a.min(b), a.max(b)],
                    face: surface.input_face(surface.face_of_corner(c)),
                });
            }
        });
    }
    found.sort_unstable_by_key(|t| (t.vertex, t.edge));
    found
}

/// Whether `p` projects strictly between `a` and `b` and lies within `tolerance` of the segment.
fn lies_inside_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    let ab: [f64; 3] = std::array::from_fn(|k| b[k] - a[k]);
    let ap: [f64; 3] = std::array::from_fn(|k| p[k] - a[k]);
    let squared = ab.iter().map(|x| x * x).sum::<f64>();
    if squared == 0.0 || !squared.is_finite() {
        return false;
    }
    let t = ab.iter().zip(&ap).map(|(x, y)| x * y).sum::<f64>() / squared;
    if !(t > 0.0 && t < 1.0) {
        return false;
    }
    let closest: [f64; 3] = std::array::from_fn(|k| a[k] + t * ab[k]);
    distance(p, closest) <= tolerance
}
