//! Boundary loops (holes) and the fans of faces around non-manifold vertices.

use std::collections::HashMap;

use super::measure::distance;
use crate::soup::{BOUNDARY, EdgePairing, FaceTable, Fans};

/// A closed chain of boundary edges (edges with one face): a hole, or the rim of an open
/// surface.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BoundaryLoop {
    /// The loop's vertices in order, each joined by a boundary edge to the next (and the last to
    /// the first). The loop runs clockwise seen from outside, as the faces' missing neighbours
    /// would walk it. A vertex where several fans touch may appear more than once.
    pub vertices: Vec<u32>,
    /// The sum of its edges' lengths.
    pub perimeter: f64,
    /// An input face along the loop.
    pub face: u32,
}

/// The fans of faces around one non-manifold vertex: faces are in one fan when they are joined
/// through edges at the vertex.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VertexFans {
    /// The vertex.
    pub vertex: u32,
    /// The input faces of each fan, ascending; fans in order of their lowest face.
    pub fans: Vec<Vec<u32>>,
}

/// The boundary loops of `surface` (whose edges `pairing` pairs) and the table face along each,
/// and the fans of each of `non_manifold` (ascending).
///
/// At each vertex a loop goes on along another boundary edge of the same fan, so it never jumps
/// between the fans of a non-manifold vertex. Edges are linked without regard to their direction,
/// so a loop also runs on across the seam of a non-orientable surface (a Möbius strip has one).
/// Where a fan has more than two boundary edges (faces joined only through a non-manifold edge),
/// they are linked in corner order.
pub(super) fn loops_and_fans(
    surface: &FaceTable<'_>,
    pairing: &EdgePairing,
    positions: &[[f64; 3]],
    non_manifold: &[u32],
) -> (Vec<(BoundaryLoop, usize)>, Vec<VertexFans>) {
    let corners = surface.corners();
    // Boundary edge c: the face edge of corner c, with no face across.
    let boundary: Vec<u32> = (0..corners.len() as u32)
        .filter(|&c| pairing.partner[c as usize] == BOUNDARY)
        .collect();
    if boundary.is_empty() && non_manifold.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let mut fans = Fans::through_shared_edges(surface, pairing);
    let ends = |c: u32| {
        let next = surface.next_corner(c as usize) as u32;
        [(corners[c as usize], c), (corners[next as usize], next)]
    };
    let mut at_fan: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
    for &c in &boundary {
        for (vertex, corner) in ends(c) {
            at_fan
                .entry((vertex, fans.root(corner)))
                .or_default()
                .push(c);
        }
    }
    let mut visited = vec![false; corners.len()];
    let mut loops = Vec::new();
    for &start in &boundary {
        if visited[start as usize] {
            continue;
        }
        visited[start as usize] = true;
        // The first edge is walked against its face (b → a), as the hole's own half-edges run.
        let [(a, a_corner), (b, _)] = ends(start);
        let mut vertices = vec![b];
        let mut perimeter = distance(positions[a as usize], positions[b as usize]);
        let (mut here, mut here_corner) = (a, a_corner);
        loop {
            let slot = &at_fan[&(here, fans.root(here_corner))];
            let Some(&next) = slot.iter().find(|&&e| !visited[e as usize]) else {
                break;
            };
            visited[next as usize] = true;
            vertices.push(here);
            let [(p, p_corner), (q, q_corner)] = ends(next);
            let (far, far_corner) = if p == here {
                (q, q_corner)
            } else {
                (p, p_corner)
            };
            perimeter += distance(positions[here as usize], positions[far as usize]);
            (here, here_corner) = (far, far_corner);
        }
        let face = surface.face_of_corner(start as usize);
        let found = BoundaryLoop {
            vertices,
            perimeter,
            face: surface.input_face(face),
        };
        loops.push((found, face));
    }

    let mut fans_of: HashMap<u32, Vec<(u32, u32)>> =
        non_manifold.iter().map(|&v| (v, Vec::new())).collect();
    for (c, v) in corners.iter().enumerate() {
        if let Some(at) = fans_of.get_mut(v) {
            let face = surface.input_face(surface.face_of_corner(c));
            at.push((fans.root(c as u32), face));
        }
    }
    let vertex_fans = non_manifold
        .iter()
        .map(|&vertex| {
            let mut by_fan = fans_of.remove(&vertex).unwrap_or_default();
            by_fan.sort_unstable();
            let mut fans: Vec<Vec<u32>> = by_fan
                .chunk_by(|a, b| a.0 == b.0)
                .map(|fan| fan.iter().map(|&(_, face)| face).collect())
                .collect();
            for fan in &mut fans {
                fan.sort_unstable();
                fan.dedup();
            }
            fans.sort_unstable();
            VertexFans { vertex, fans }
        })
        .collect();
    (loops, vertex_fans)
}
