//! The order in which a patch's triangles join the mesh: peeled from the rim inwards, each one
//! taking one side of the hole that is still open and either a vertex not yet in the mesh or
//! one of the two open sides beside it, so that what stays open is always one simple loop and
//! every [`Mesh::add_face`](crate::mesh::Mesh::add_face) is the plain case of extending a
//! boundary. A triangulated disk can always be peeled so (it can be shelled), and the queue
//! visits each triangle O(1) times: O(m) expected for m triangles.

use std::collections::HashMap;

use crate::mesh::INVALID_INDEX;

/// The triangles' indices in peeling order, or `None` when the triangles do not form a disk
/// on the ring `0..n_rim` (they are then not added).
pub(super) fn peeling_order(
    n_rim: usize,
    n_points: usize,
    triangles: &[[u32; 3]],
) -> Option<Vec<usize>> {
    let mut holding: HashMap<(u32, u32), usize> = HashMap::with_capacity(3 * triangles.len());
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            holding.insert((tri[k], tri[(k + 1) % 3]), t);
        }
    }
    // The open loop, as next/previous corners (INVALID_INDEX: not on it).
    let mut next = vec![INVALID_INDEX; n_points];
    let mut prev = vec![INVALID_INDEX; n_points];
    let mut placed = vec![false; n_points];
    for i in 0..n_rim {
        next[i] = ((i + 1) % n_rim) as u32;
        prev[(i + 1) % n_rim] = i as u32;
        placed[i] = true;
    }
    let mut added = vec![false; triangles.len()];
    let mut order = Vec::with_capacity(triangles.len());
    let mut queue: Vec<usize> = (0..n_rim)
        .filter_map(|i| holding.get(&(i as u32, ((i + 1) % n_rim) as u32)).copied())
        .collect();
    while let Some(t) = queue.pop() {
        if added[t] {
            continue;
        }
        let tri = triangles[t];
        // A rotation a b c whose side a → b is open and whose c fits.
        let fitting = (0..3)
            .map(|r| [tri[r], tri[(r + 1) % 3], tri[(r + 2) % 3]])
            .find(|&[a, b, c]| {
                next[a as usize] == b
                    && (!placed[c as usize] || next[b as usize] == c || prev[a as usize] == c)
            });
        let Some([a, b, c]) = fitting else {
            continue;
        };
        added[t] = true;
        order.push(t);
        let closes_after = next[b as usize] == c;
        let closes_before = prev[a as usize] == c;
        match (closes_after, closes_before) {
            (true, true) => {
                for v in [a, b, c] {
                    next[v as usize] = INVALID_INDEX;
                    prev[v as usize] = INVALID_INDEX;
                }
            }
            (true, false) => {
                // The open loop now runs a → c.
                next[a as usize] = c;
                prev[c as usize] = a;
                next[b as usize] = INVALID_INDEX;
                prev[b as usize] = INVALID_INDEX;
            }
            (false, true) => {
                // The open loop now runs c → b.
                next[c as usize] = b;
                prev[b as usize] = c;
                next[a as usize] = INVALID_INDEX;
                prev[a as usize] = INVALID_INDEX;
            }
            (false, false) => {
                placed[c as usize] = true;
                next[a as usize] = c;
                prev[c as usize] = a;
                next[c as usize] = b;
                prev[b as usize] = c;
            }
        }
        // The triangles on the open sides at the corners that changed: a triangle waiting for
        // its third corner to come beside it is among them when it does.
        for v in [a, b, c] {
            let v = v as usize;
            if next[v] != INVALID_INDEX {
                let around = [(v as u32, next[v]), (prev[v], v as u32)];
                queue.extend(around.iter().filter_map(|e| holding.get(e)).copied());
            }
        }
    }
    (order.len() == triangles.len()).then_some(order)
}
