//! Duplicates: vertices at one position or within a tolerance, faces on one vertex set, and
//! T-vertices (a vertex lying inside a boundary edge: the two sides of a crack that do not
//! share their vertices).

use super::measure::{bounding_box, distance};
use super::point_tree::PointTree;
use crate::soup::{BOUNDARY, EdgePairing, FaceTable};
use crate::support::prefetch::prefetch;
use crate::support::radix_sort::radix_sort_by_high_word;

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

/// The width of the near-duplicate grid's cells, in tolerances: wider cells mean fewer
/// neighbouring cells to look into, each holding a few more group leaders.
const CELLS_PER_TOLERANCE: f64 = 4.0;

/// Vertices that coincide with a lower one.
pub(crate) struct Coincident {
    /// `[v, first]`: same position exactly.
    pub(crate) exact: Vec<[u32; 2]>,
    /// `[v, first]`: within the tolerance, not at the same position.
    pub(crate) within_tolerance: Vec<[u32; 2]>,
}

/// The vertices (all of `positions` with finite coordinates) at the
/// position of a lower vertex, and those within `tolerance` of one.
///
/// Near duplicates are grouped greedily, as a merge would: vertices are taken in order; one
/// within the tolerance of a group's first vertex joins that group (and is listed with it),
/// else it starts a group. Group leaders are more than the tolerance apart, so a grid of cells
/// the tolerance wide holds a bounded number of them per cell and each vertex is checked against
/// a bounded number: linear time whatever the input's shape.
pub(crate) fn coincident_vertices(positions: &[[f64; 3]], tolerance: f64) -> Coincident {
    let finite = |v: usize| positions[v].iter().all(|x| x.is_finite());
    let first = lowest_at_each_position(positions);
    let exact: Vec<[u32; 2]> = (0..positions.len() as u32)
        .filter(|&v| first[v as usize] < v)
        .map(|v| [v, first[v as usize]])
        .collect();

    let mut within_tolerance = Vec::new();
    if tolerance > 0.0 {
        let [low, _] = bounding_box(positions.iter().copied());
        // Cells CELLS_PER_TOLERANCE tolerances wide, numbered from the box's corner (so the
        // numbers stay below a few times 1 / tolerance); a vertex looks into a neighbouring cell
        // only along the axes where it lies within the tolerance of its cell's side.
        let size = CELLS_PER_TOLERANCE * tolerance;
        let scaled =
            |v: usize| -> [f64; 3] { std::array::from_fn(|k| (positions[v][k] - low[k]) / size) };
        let cell_of = |v: usize| scaled(v).map(|x| x.floor().clamp(-1e15, 1e15) as i64);
        // The occupied cells, sorted, and each cell's group leaders as a list threaded through
        // `next_leader` (no map keyed by input-chosen values, no allocation per cell).
        let mut cells: Vec<[i64; 3]> = (0..positions.len())
            .filter(|&v| finite(v))
            .map(cell_of)
            .collect();
        cells.sort_unstable();
        cells.dedup();
        const NONE: u32 = u32::MAX;
        let mut first_leader = vec![NONE; cells.len()];
        let mut next_leader = vec![NONE; positions.len()];
        for v in (0..positions.len()).filter(|&v| finite(v)) {
            let p = positions[v];
            let inside = scaled(v);
            let home = cell_of(v);
            let reach = |k: usize| {
                let inside = inside[k] - inside[k].floor();
                let low = if inside * CELLS_PER_TOLERANCE <= 1.0 {
                    -1
                } else {
                    0
                };
                let high = if (1.0 - inside) * CELLS_PER_TOLERANCE <= 1.0 {
                    1
                } else {
                    0
                };
                low..=high
            };
            let mut joined = None;
            'search: for dx in reach(0) {
                for dy in reach(1) {
                    for dz in reach(2) {
                        let near = [home[0] + dx, home[1] + dy, home[2] + dz];
                        let Ok(cell) = cells.binary_search(&near) else {
                            continue;
                        };
                        let mut leader = first_leader[cell];
                        while leader != NONE {
                            if distance(p, positions[leader as usize]) <= tolerance {
                                joined = Some(leader);
                                break 'search;
                            }
                            leader = next_leader[leader as usize];
                        }
                    }
                }
            }
            match joined {
                Some(leader) if positions[leader as usize] != p => {
                    within_tolerance.push([v as u32, leader]);
                }
                Some(_) => {}
                None => {
                    let cell = cells.binary_search(&home).unwrap_or_default();
                    next_leader[v] = first_leader[cell];
                    first_leader[cell] = v as u32;
                }
            }
        }
    }
    Coincident {
        exact,
        within_tolerance,
    }
}

/// For every vertex with finite coordinates, the lowest vertex at exactly its position (itself
/// when it is the lowest; −0 and 0 are one coordinate); `u32::MAX` for the others.
///
/// Vertices are sorted by a 32-bit mix of their coordinates' bits, packed with their index in
/// one `u64` (a linear radix sort); only vertices whose mixes collide are compared coordinate by
/// coordinate, sorted by their full positions when several collide, so inputs made to collide
/// cost a sort, never a quadratic search.
pub(crate) fn lowest_at_each_position(positions: &[[f64; 3]]) -> Vec<u32> {
    let bits = |v: usize| positions[v].map(|x| (x + 0.0).to_bits());
    let mix = |[x, y, z]: [u64; 3]| {
        let h = x.wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ y.wrapping_mul(0xC2B2_AE3D_27D4_EB4F).rotate_left(21)
            ^ z.wrapping_mul(0x1656_67B1_9E37_79F9).rotate_left(42);
        (h ^ (h >> 32)) >> 32
    };
    let mut keyed: Vec<u64> = (0..positions.len())
        .filter(|&v| positions[v].iter().all(|x| x.is_finite()))
        .map(|v| (mix(bits(v)) << 32) | v as u64)
        .collect();
    radix_sort_by_high_word(&mut keyed);
    let mut first = vec![u32::MAX; positions.len()];
    let mut run: Vec<u32> = Vec::new();
    // Positions are read in the mixes' order, far apart in memory: each is asked for a run or
    // so ahead of its use.
    const AHEAD: usize = 16;
    let mut start = 0;
    while start < keyed.len() {
        let mix_here = keyed[start] >> 32;
        let end = start
            + keyed[start..]
                .iter()
                .take_while(|&&k| k >> 32 == mix_here)
                .count();
        for &k in keyed.iter().skip(end + AHEAD).take(end - start) {
            prefetch(&positions[k as u32 as usize]);
        }
        let same_mix = &keyed[start..end];
        start = end;
        if let &[only] = same_mix {
            first[only as u32 as usize] = only as u32;
            continue;
        }
        // Ascending ids: usually copies of one position, whose lowest is the first; else a
        // stable sort by position keeps each position's lowest first.
        run.clear();
        run.extend(same_mix.iter().map(|&k| k as u32));
        let lowest = bits(run[0] as usize);
        if run.iter().all(|&v| bits(v as usize) == lowest) {
            for &v in &run {
                first[v as usize] = run[0];
            }
            continue;
        }
        run.sort_by_key(|&v| bits(v as usize));
        for group in run.chunk_by(|&a, &b| bits(a as usize) == bits(b as usize)) {
            for &v in group {
                first[v as usize] = group[0];
            }
        }
    }
    first
}

/// Pairs `[f, first]` of faces of `surface` on the same vertex set as a lower face (input
/// indices, ascending). Faces are sorted by their sorted vertex sets: triangles and quads by a
/// fixed-size key, larger polygons by their whole sets (no hashing of input-chosen keys, no
/// allocation per face of the usual meshes).
pub(crate) fn duplicate_faces(surface: &FaceTable<'_>) -> Vec<[u32; 2]> {
    let mut small: Vec<([u32; 4], u32)> = Vec::with_capacity(surface.n_faces());
    let mut large: Vec<(Vec<u32>, u32)> = Vec::new();
    for f in 0..surface.n_faces() {
        let face = surface.face(f);
        let input = surface.input_face(f);
        if face.len() <= 4 {
            let mut key = [u32::MAX; 4];
            key[..face.len()].copy_from_slice(face);
            key.sort_unstable();
            small.push((key, input));
        } else {
            let mut key = face.to_vec();
            key.sort_unstable();
            large.push((key, input));
        }
    }
    small.sort_unstable();
    large.sort_unstable();
    let mut duplicates: Vec<[u32; 2]> = runs_of_equal_keys(&small)
        .chain(runs_of_equal_keys(&large))
        .collect();
    duplicates.sort_unstable();
    duplicates
}

/// `[face, first]` for every face of a run of equal keys but the run's first (lowest) face.
fn runs_of_equal_keys<K: PartialEq>(sorted: &[(K, u32)]) -> impl Iterator<Item = [u32; 2]> + '_ {
    sorted
        .chunk_by(|a, b| a.0 == b.0)
        .flat_map(|run| run[1..].iter().map(move |&(_, face)| [face, run[0].1]))
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
pub(crate) fn lies_inside_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
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
