//! Fans of faces around each vertex ("umbrellas"), as disjoint sets of corners, and the repairs
//! that give fans a vertex of their own.
//!
//! Two corners at one vertex belong to one fan when their faces share an edge at that vertex.
//! A vertex with several fans (two cones touching at their tips) is a non-manifold vertex: the
//! builders never leave one in a structure, because a vertex's circulation would see one fan
//! only; they split it, one vertex per fan. Repair also cuts a face list along its problem edges
//! and splits the umbrellas around their endpoints, as CGAL's polygon-soup orientation does: two
//! closed cubes sharing an edge become two closed cubes; three triangles on one edge become
//! three separate triangles; what stays connected through manifold edges stays connected.

use std::collections::HashMap;

use super::pairing::{BOUNDARY, EdgePairing, UNPAIRED};
use super::resolve::VertexCopies;
use super::{BuildError, FaceTable};
use crate::support::disjoint_sets;

/// Disjoint sets of corners (see [`disjoint_sets`]): each set is the fan of faces around the
/// corners' vertex.
pub(crate) struct Fans {
    parent: Vec<u32>,
}

impl Fans {
    /// Every corner a fan of its own.
    fn unjoined(n_corners: usize) -> Self {
        Fans {
            parent: (0..n_corners as u32).collect(),
        }
    }

    /// The fans of the input's definition: corners joined through every edge their faces
    /// share, paired or not (three faces on one edge are one fan at each of its ends).
    pub(crate) fn through_shared_edges(table: &FaceTable<'_>, pairing: &EdgePairing) -> Self {
        let mut fans = Fans::through_paired_edges(table, pairing);
        for problem in &pairing.problems {
            // A corner on the edge sits at one end; the corner after it, at the other.
            let mut first_at = [u32::MAX; 2];
            for &c in &problem.corners {
                let next = table.next_corner(c as usize) as u32;
                let at_first_vertex = table.corners()[c as usize] == problem.vertices[0];
                let ends = if at_first_vertex {
                    [c, next]
                } else {
                    [next, c]
                };
                for (end, corner) in ends.into_iter().enumerate() {
                    if first_at[end] == u32::MAX {
                        first_at[end] = corner;
                    } else {
                        fans.join(first_at[end], corner);
                    }
                }
            }
        }
        fans
    }

    /// Corners joined through paired (manifold, consistently oriented) edges only.
    fn through_paired_edges(table: &FaceTable<'_>, pairing: &EdgePairing) -> Self {
        let mut fans = Fans::unjoined(table.n_corners());
        for (c, &p) in pairing.partner.iter().enumerate() {
            if p != BOUNDARY && p != UNPAIRED {
                // Corner c leaves a towards b; its partner p leaves b towards a, so the corner
                // after p in p's face sits at a, in the fan next to c's.
                fans.join(c as u32, table.next_corner(p as usize) as u32);
            }
        }
        fans
    }

    /// The fan of corner `c`, named by one of its corners.
    pub(crate) fn root(&mut self, c: u32) -> u32 {
        disjoint_sets::root(&mut self.parent, 0, c)
    }

    fn join(&mut self, a: u32, b: u32) {
        disjoint_sets::join(&mut self.parent, 0, a, b);
    }

    /// The vertices of `table` (below `n_vertices`) with more than one fan, ascending.
    pub(super) fn non_manifold_vertices(
        &mut self,
        table: &FaceTable<'_>,
        n_vertices: usize,
    ) -> Vec<u32> {
        let mut first_fan = vec![u32::MAX; n_vertices];
        let mut several = vec![false; n_vertices];
        for (c, &v) in table.corners().iter().enumerate() {
            let fan = self.root(c as u32);
            let first = &mut first_fan[v as usize];
            if *first == u32::MAX {
                *first = fan;
            } else if *first != fan {
                several[v as usize] = true;
            }
        }
        (0..n_vertices as u32)
            .filter(|&v| several[v as usize])
            .collect()
    }

    /// Gives every fan at each of `vertices` (ascending) but the first a copy of the vertex:
    /// vertex by vertex, fans in the order of their first corner (the first keeps the vertex).
    /// Returns whether any corner changed vertex.
    fn give_copies(
        &mut self,
        table: &mut FaceTable<'_>,
        vertices: &[u32],
        copies: &mut VertexCopies,
    ) -> Result<bool, BuildError> {
        if vertices.is_empty() {
            return Ok(false);
        }
        let mut at: Vec<(u32, u32)> = table
            .corners()
            .iter()
            .enumerate()
            .filter(|&(_, v)| vertices.binary_search(v).is_ok())
            .map(|(c, &v)| (v, c as u32))
            .collect();
        at.sort_unstable();
        let mut changed = false;
        for corners in at.chunk_by(|a, b| a.0 == b.0) {
            let vertex = corners[0].0;
            let first_fan = self.root(corners[0].1);
            // Fans are keyed by their root corner, unique to the fan.
            let mut fan_vertex: HashMap<u32, u32> = HashMap::new();
            for &(_, c) in corners {
                let fan = self.root(c);
                if fan == first_fan {
                    continue;
                }
                let assigned = match fan_vertex.get(&fan) {
                    Some(&assigned) => assigned,
                    None => {
                        let assigned = copies.copy(vertex)?;
                        fan_vertex.insert(fan, assigned);
                        assigned
                    }
                };
                table.corners_mut()[c as usize] = assigned;
                changed = true;
            }
        }
        Ok(changed)
    }
}

/// Gives every fan of each non-manifold vertex of `table` but the first a vertex of its own
/// (`pairing` is `table`'s, with no problem edge left). Returns the split input vertices,
/// ascending (their copies are in `copies`).
pub(crate) fn split_non_manifold_vertices(
    table: &mut FaceTable<'_>,
    pairing: &EdgePairing,
    copies: &mut VertexCopies,
) -> Result<Vec<u32>, BuildError> {
    let mut fans = Fans::through_shared_edges(table, pairing);
    let split = fans.non_manifold_vertices(table, copies.n_vertices());
    fans.give_copies(table, &split, copies)?;
    Ok(split)
}

/// Splits the umbrellas at the endpoints of `pairing`'s problem edges: corners at one vertex
/// belong to one umbrella when they are linked through paired (manifold) edges. On a problem edge,
/// faces that already share their umbrellas at both ends stay together (they will pair again);
/// faces that would be left alone are matched two by two in input order, one of each direction,
/// so that a lone pair keeps its edge (a "book" of three triangles keeps two joined). The umbrella
/// holding a vertex's first corner keeps the vertex, every other umbrella gets a copy. Returns
/// whether any corner changed vertex (then pair again).
pub(crate) fn split_umbrellas(
    table: &mut FaceTable<'_>,
    pairing: &EdgePairing,
    copies: &mut VertexCopies,
) -> Result<bool, BuildError> {
    let mut fans = Fans::through_paired_edges(table, pairing);
    join_lone_faces(table, pairing, &mut fans);
    let mut vertices: Vec<u32> = pairing
        .problems
        .iter()
        .flat_map(|problem| problem.vertices)
        .collect();
    vertices.sort_unstable();
    vertices.dedup();
    fans.give_copies(table, &vertices, copies)
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
        // Counted by sorting, so an edge of k faces costs k log k, not k².
        let mut sorted = keys.clone();
        sorted.sort_unstable();
        let shared = |key: &(u32, u32)| {
            let start = sorted.partition_point(|k| k < key);
            sorted.get(start + 1) == Some(key)
        };
        let lone: Vec<u32> = problem
            .corners
            .iter()
            .zip(&keys)
            .filter(|&(_, key)| !shared(key))
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
