//! Holes whose boundary passes more than once through one point: at a vertex with two boundary
//! fans, or at two copies of one vertex (as splitting a non-manifold vertex leaves them). No
//! triangulation on such a loop's corners is free of a fold or a touching, so the loop is split
//! there into simple loops that are filled one by one, the copies welded into one vertex.

use std::collections::HashMap;

use super::crossings::Surroundings;
use crate::mesh::{HalfedgeId, Mesh, Pinch, VertexId};
use crate::support::id_set::IdSet;

/// The loops a hole's boundary was split into, and the pinches that split it.
pub(super) struct SplitLoop {
    /// One boundary half-edge of each loop: the hole's own when it was not split, else the last
    /// one holds the hole's last side.
    pub(super) loops: Vec<HalfedgeId>,
    /// The pinches, in the order made.
    pub(super) pinches: Vec<Pinch>,
}

/// Splits the boundary loop through `h` wherever it returns to a point it has passed (exactly
/// the same position) into simple loops meeting there. Walking the loop with a stack of the
/// points passed, a point met again closes the loop of the corners stacked since, which is split
/// off ([`Mesh::pinch_boundary_loop`]). Two copies are welded only when each has a single fan
/// and they have no neighbour in common (the weld must not double an edge); elsewhere the loop
/// is left as it is. `several_fans` marks the vertices with more than one fan, found on first
/// use. O(n) expected for a loop of `n` corners, plus O(size of the mesh) once.
pub(super) fn split_at_pinches(
    mesh: &mut Mesh,
    h: HalfedgeId,
    surroundings: &mut Surroundings,
    several_fans: &mut Option<IdSet>,
) -> SplitLoop {
    let sides: Vec<HalfedgeId> = mesh.halfedge_loop(h).collect();
    let n = sides.len();
    let key =
        |mesh: &Mesh, s: HalfedgeId| mesh.position(mesh.origin(s)).map(|x| (x + 0.0).to_bits());
    let mut passed: HashMap<[u64; 3], usize> = HashMap::with_capacity(n);
    let mut stack: Vec<usize> = Vec::with_capacity(n);
    let mut split = SplitLoop {
        loops: Vec::new(),
        pinches: Vec::new(),
    };
    for k in 0..n {
        let point = key(mesh, sides[k]);
        let Some(&m) = passed.get(&point) else {
            passed.insert(point, k);
            stack.push(k);
            continue;
        };
        let (first, second) = (sides[(m + n - 1) % n], sides[k - 1]);
        let fans = several_fans.get_or_insert_with(|| {
            let mut set = IdSet::new(mesh.n_vertex_slots());
            for v in mesh.non_manifold_vertices() {
                set.insert(v.0);
            }
            set
        });
        if !may_pinch(mesh, fans, first, second) {
            continue;
        }
        let (v, w) = (mesh.target(first), mesh.target(second));
        let pinch = mesh.pinch_boundary_loop(first, second);
        if w != v {
            fans.insert(v.0);
            surroundings.weld(w.0, Some(v.0));
        }
        split.pinches.push(pinch);
        split.loops.push(second);
        while let Some(&top) = stack.last().filter(|&&top| top > m) {
            passed.remove(&key(mesh, sides[top]));
            stack.pop();
        }
    }
    // Every part split off holds a side before the last one.
    split.loops.push(if split.pinches.is_empty() {
        h
    } else {
        sides[n - 1]
    });
    split
}

/// Whether the loop may be pinched at the targets `v` of `first` and `w` of `second` (one
/// position): the same vertex, or two with one fan each and no neighbour in common.
fn may_pinch(mesh: &Mesh, several_fans: &IdSet, first: HalfedgeId, second: HalfedgeId) -> bool {
    let (v, w) = (mesh.target(first), mesh.target(second));
    if v == w {
        return true;
    }
    if several_fans.contains(v.0) || several_fans.contains(w.0) {
        return false;
    }
    let mut neighbours: Vec<VertexId> = mesh.vertex_vertices(v).collect();
    neighbours.sort_unstable();
    !mesh
        .vertex_vertices(w)
        .any(|x| x == v || neighbours.binary_search(&x).is_ok())
}

/// Undoes, last first, each pinch of `split` both of whose loops are still open (nothing was
/// filled beside it), and returns the vertices welded by the pinches kept, as `[gone, kept]`.
pub(super) fn undo_open_pinches(
    mesh: &mut Mesh,
    split: SplitLoop,
    surroundings: &mut Surroundings,
) -> Vec<[VertexId; 2]> {
    let mut welded = Vec::new();
    for pinch in split.pinches.into_iter().rev() {
        let [first, second] = pinch.boundary_halfedges();
        let kept = mesh.target(first);
        if mesh.is_boundary_halfedge(first) && mesh.is_boundary_halfedge(second) {
            if let Some(w) = pinch.welded_vertex() {
                surroundings.weld(w.0, None);
            }
            mesh.unpinch_boundary_loop(pinch);
        } else if let Some(w) = pinch.welded_vertex() {
            welded.push([w, kept]);
        }
    }
    welded
}

#[cfg(test)]
mod tests {
    use super::super::{HoleFillOptions, fill_holes};
    use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};
    use crate::soup::{BuildPolicy, FaceList};

    /// A flat 4 × 4 grid of unit squares (vertex `5j + i` at `(i, j, 0)`) with the squares at
    /// (1, 1) and (2, 2) deleted: two holes of 4 edges that both pass through vertex 12.
    fn grid_with_two_holes_at_a_vertex() -> Mesh {
        let positions: Vec<[f64; 3]> = (0..25)
            .map(|k| [f64::from(k % 5), f64::from(k / 5), 0.0])
            .collect();
        let indices: Vec<u32> = (0..16u32)
            .flat_map(|s| {
                let v = 5 * (s / 4) + s % 4;
                [v, v + 1, v + 6, v, v + 6, v + 5]
            })
            .collect();
        let list = FaceList::triangles(&positions, &indices);
        let (mut mesh, _) = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap();
        for square in [5, 10] {
            for f in [2 * square, 2 * square + 1] {
                mesh.delete_face(FaceId(f), false).unwrap();
            }
        }
        mesh
    }

    #[test]
    fn a_hole_through_one_vertex_twice_is_filled_as_two() {
        let mut mesh = grid_with_two_holes_at_a_vertex();
        let v = VertexId(12);
        let into: Vec<HalfedgeId> = mesh
            .incoming_halfedges(v)
            .filter(|&h| mesh.is_boundary_halfedge(h))
            .collect();
        assert_eq!(into.len(), 2);
        // Joined into one loop through vertex 12 twice (what pinching two loops undoes).
        mesh.pinch_boundary_loop(into[0], into[1]);
        let corners: Vec<VertexId> = mesh
            .halfedge_loop(into[0])
            .map(|h| mesh.origin(h))
            .collect();
        assert_eq!(corners.len(), 8);
        assert_eq!(corners.iter().filter(|&&c| c == v).count(), 2);
        mesh.check().unwrap();

        let options = HoleFillOptions {
            max_edges: 8,
            ..HoleFillOptions::default()
        };
        let report = fill_holes(&mut mesh, &options).unwrap();
        assert_eq!(report.filled.len(), 2);
        assert!(report.refused.is_empty(), "{:?}", report.refused);
        assert!(report.welded_vertices.is_empty());
        assert_eq!(report.faces_added(), 4);
        mesh.check().unwrap();
        assert_eq!(
            mesh.boundary_loops().len(),
            1,
            "only the outer border is left"
        );
        assert!(mesh.non_manifold_vertices().is_empty());
    }
}
