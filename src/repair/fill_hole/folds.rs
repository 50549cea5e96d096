//! When a fill is folded: the test every triangulation of a hole passes before it is cut into
//! the mesh, so that no fill folds whichever method chose its triangles.

use std::collections::HashMap;

use super::geometry::{angle_between, triangle_normal};

/// Largest angle, in degrees, between the normal of a new triangle and that of a face beside
/// it (another new triangle, or the face across the hole's rim). Beyond it the two faces fold
/// onto each other (a dihedral angle below 30°).
pub const FOLD_ANGLE_DEGREES: f64 = 150.0;

/// A new triangle is degenerate when twice its area is at most this fraction of its longest
/// side squared: its height is below 10⁻¹⁰ of its length.
pub const DEGENERATE_RATIO: f64 = 1e-10;

/// Why a triangulation of a hole folds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Fold {
    /// The triangle at this index has (next to) no area.
    Degenerate(usize),
    /// The triangle at this index turns by this angle (degrees) from a face beside it.
    Folded(usize, f64),
}

/// Whether `a b c` is degenerate: twice its area at most [`DEGENERATE_RATIO`] times its longest
/// side squared, or no finite normal.
pub(super) fn is_degenerate(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> bool {
    let (normal, area) = triangle_normal(a, b, c);
    let longest = [(a, b), (b, c), (c, a)]
        .iter()
        .map(|(p, q)| (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>())
        .fold(0.0, f64::max);
    normal == [0.0; 3] || 2.0 * area <= DEGENERATE_RATIO * longest
}

/// The first fold of `triangles` (corner indices into `points`: the hole's ring of corners in
/// order, then any vertices added inside), or `None`. `rim_normals[i]` is the unit normal of
/// the face across the side from corner `i` to `i + 1`, zero when it has none; there is one per
/// corner of the ring. O(n) expected.
pub(super) fn first_fold(
    points: &[[f64; 3]],
    rim_normals: &[[f64; 3]],
    triangles: &[[u32; 3]],
) -> Option<Fold> {
    let n = rim_normals.len() as u32;
    let mut normals = Vec::with_capacity(triangles.len());
    for (t, tri) in triangles.iter().enumerate() {
        let [a, b, c] = tri.map(|k| points[k as usize]);
        if is_degenerate(a, b, c) {
            return Some(Fold::Degenerate(t));
        }
        normals.push(triangle_normal(a, b, c).0);
    }
    let bound = FOLD_ANGLE_DEGREES.to_radians();
    let mut across: HashMap<(u32, u32), usize> = HashMap::with_capacity(triangles.len() * 3);
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (u, v) = (tri[k], tri[(k + 1) % 3]);
            let neighbour = if u < n && v == (u + 1) % n {
                rim_normals[u as usize]
            } else if let Some(&s) = across.get(&(v, u)) {
                normals[s]
            } else {
                across.insert((u, v), t);
                continue;
            };
            if neighbour == [0.0; 3] {
                continue;
            }
            let angle = angle_between(normals[t], neighbour);
            if angle > bound {
                return Some(Fold::Folded(t, angle.to_degrees()));
            }
        }
    }
    None
}
