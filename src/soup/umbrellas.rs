//! The repair step that cuts a face list along its problem edges and gives every fan of faces
//! ("umbrella") around an endpoint of those edges a vertex of its own, as CGAL's polygon-soup
//! orientation does. Two closed cubes sharing an edge become two closed cubes; three triangles on
//! one edge become three separate triangles; what stays connected through manifold edges stays
//! connected.

use std::collections::HashMap;

use super::pairing::{BOUNDARY, EdgePairing, UNPAIRED};
use super::resolve::VertexCopies;
use super::{BuildError, FaceTable};
use crate::disjoint_sets;

/// Disjoint sets of corners (see [`disjoint_sets`]).
struct Fans {
    parent: Vec<u32>,
}

impl Fans {
    fn root(&mut self, c: u32) -> u32 {
        disjoint_sets::root(&mut self.parent, 0, c)
    }

    fn join(&mut self, a: u32, b: u32) {
        disjoint_sets::join(&mut self.parent, 0, a, b);
    }
}

/// Splits the umbrellas at the endpoints of `pairing`'s problem edges: corners at one vertex
/// belong to one umbrella when they are linked through paired (manifold) edges. On a problem edge,
/// faces that already share their umbrellas at both ends stay together (they will pair again);
/// faces that would be left alone are matched two by two in input order, one of each direction,
/// so that a lone pair keeps its edge (a "book" of three triangles keeps two joined). The umbrella
/// holding a vertex's first corner keeps the vertex, every other umbrella gets a copy. Returns
/// whether any corner changed vertex (then pair again).
pub(super) fn split_umbrellas(
    table: &mut FaceTable<'_>,
    pairing: &EdgePairing,
    copies: &mut VertexCopies,
) -> Result<bool, BuildError> {
    let n_corners = table.n_corners();
    let mut fans = Fans {
        parent: (0..n_corners as u32).collect(),
    };
    for (c, &p) in pairing.partner.iter().enumerate() {
        if p != BOUNDARY && p != UNPAIRED {
            // Corner c leaves a towards b; its partner p leaves b towards a, so the corner after
            // p in p's face sits at a, in the fan next to c's.
            fans.join(c as u32, table.next_corner(p as usize) as u32);
        }
    }
    join_lone_faces(table, pairing, &mut fans);
    let mut corners_at: HashMap<u32, Vec<u32>> = pairing
        .problems
        .iter()
        .flat_map(|problem| problem.vertices)
        .map(|v| (v, Vec::new()))
        .collect();
    for (c, v) in table.corners().iter().enumerate() {
        if let Some(at) = corners_at.get_mut(v) {
            at.push(c as u32);
        }
    }
    let mut vertices: Vec<u32> = corners_at.keys().copied().collect();
    vertices.sort_unstable();
    let mut changed = false;
    for vertex in vertices {
        // Umbrellas in the order of their first corner: the first keeps the vertex.
        let mut umbrella_vertex: Vec<(u32, u32)> = Vec::new();
        for &c in &corners_at[&vertex] {
            let root = fans.root(c);
            let assigned = match umbrella_vertex.iter().find(|(r, _)| *r == root) {
                Some(&(_, assigned)) => assigned,
                None => {
                    let assigned = if umbrella_vertex.is_empty() {
                        vertex
                    } else {
                        copies.copy(vertex)?
                    };
                    umbrella_vertex.push((root, assigned));
                    assigned
                }
            };
            if assigned != vertex {
                table.corners_mut()[c as usize] = assigned;
                changed = true;
            }
        }
    }
    Ok(changed)
}

/// On each problem edge, the corners whose faces share their umbrellas at both ends with no other
/// face of the edge are "lone": the split would leave their face with nothing across the edge.
/// Lone corners are matched in input order, one running each way, and joined as if paired.
fn join_lone_faces(table: &FaceTable<'_>, pairing: &EdgePairing, fans: &mut Fans) {
    let corners = table.corners();
    for problem in &pairing.problems {
        let ends = |fans: &mut Fans, c: u32| {
            let next = table.next_corner(c as usize) as u32;
            (fans.root(c), fans.root(next))
        };
        let keys: Vec<(u32, u32)> = problem.corners.iter().map(|&c| ends(fans, c)).collect();
        let lone: Vec<u32> = problem
            .corners
            .iter()
            .zip(&keys)
            .filter(|&(_, key)| keys.iter().filter(|other| *other == key).count() == 1)
            .map(|(&c, _)| c)
            .collect();
        let forward = |c: &&u32| corners[**c as usize] == problem.vertices[0];
        let (ahead, back): (Vec<&u32>, Vec<&u32>) = lone.iter().partition(forward);
        for (&a, &b) in ahead.iter().zip(&back) {
            // a runs v0 → v1, b runs v1 → v0: joined like a paired edge.
            fans.join(*a, table.next_corner(*b as usize) as u32);
            fans.join(table.next_corner(*a as usize) as u32, *b);
        }
    }
}
