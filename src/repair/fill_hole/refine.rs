//! Refining a fill (Liepa 2003): triangles much larger than the edges around them are split at
//! their centroid, then edges are flipped towards a Delaunay-like patch, until no triangle is
//! split, so that the new triangles' edges match the lengths of the mesh's edges at the rim.
//!
//! Each corner has a *scale*: a rim corner the mean length of the mesh's edges at it (Liepa's
//! σ, see [`rim_scale`]), a new vertex the mean scale of the triangle it split; no scale is
//! below [`SCALE_FLOOR`] times the rim's mean boundary edge. A triangle is split when, for each
//! of its corners, [`DENSITY`] times the distance from its centroid to the corner exceeds both the
//! corner's scale and the centroid's. An interior edge is flipped when the two angles facing
//! it sum to more than π, unless the other diagonal is an edge already (here or in the mesh)
//! or a new triangle would be degenerate or turned against the two it replaces.

use std::collections::{HashMap, VecDeque};

use super::folds::is_degenerate;
use super::geometry::{dot, norm, sub, triangle_normal};
use crate::mesh::{JoinedCorners, Mesh, VertexId};

/// Liepa's density factor √2: a triangle is split while its centroid is farther than 1/√2 of
/// the local scale from each corner.
pub const DENSITY: f64 = std::f64::consts::SQRT_2;

/// Split-and-flip rounds at most. Each round splits every triangle too large, so the number of
/// triangles grows geometrically and a fill reaches its density in about log₃ of its final
/// triangle count rounds; the cap bounds the work whatever the input.
pub const REFINE_ROUNDS_MAX: usize = 48;

/// No corner's scale is below this fraction of the rim's mean boundary edge, so that the fill
/// has at most about the hole's area over (this × the mean boundary edge)² triangles, whatever
/// the edges of the mesh around it.
pub const SCALE_FLOOR: f64 = 0.25;

/// Passes of refinement and fairing at most: fairing a fill bends it out of the plane it was
/// refined in, stretching its triangles, which the next pass splits; a few passes leave the
/// triangles within a small factor of the density.
pub const REFINE_PASSES_MAX: usize = 3;

/// Flips tried per edge in one round at most; keeps a round linear even where flips on a
/// non-planar patch would cycle.
const FLIPS_PER_EDGE: usize = 4;

/// A rim corner's scale: the mean length of the mesh's edges at `v` (boundary edges and the
/// edges into the surface around the hole), so that the fill's triangles continue the size of
/// the faces around it rather than that of the rim's edges alone.
pub(super) fn rim_scale(mesh: &Mesh, v: VertexId) -> f64 {
    let at = mesh.position(v);
    let (mut sum, mut count) = (0.0, 0usize);
    for out in mesh.outgoing_halfedges(v) {
        sum += norm(sub(mesh.position(mesh.target(out)), at));
        count += 1;
    }
    if count == 0 { 0.0 } else { sum / count as f64 }
}

/// A triangulated patch over a hole: the rim's corners (`0..n_rim`, in loop order) and the
/// vertices refinement added, with its triangles in the loop's winding.
#[derive(Clone, Debug)]
pub(super) struct Patch {
    pub(super) n_rim: usize,
    pub(super) points: Vec<[f64; 3]>,
    /// The three vertices whose centroid each added vertex was created at (patch indices).
    pub(super) parents: Vec<[u32; 3]>,
    pub(super) triangles: Vec<[u32; 3]>,
    scales: Vec<f64>,
    /// The triangle holding each directed edge.
    edges: HashMap<(u32, u32), u32>,
}

impl Patch {
    /// The patch of the coarse fill `triangles` over the ring `points`, whose corners have the
    /// scales `scales` (see [`rim_scale`]).
    pub(super) fn new(
        points: &[[f64; 3]],
        triangles: Vec<[u32; 3]>,
        mut scales: Vec<f64>,
    ) -> Patch {
        let n = points.len();
        debug_assert_eq!(scales.len(), n);
        // A floor on the scales: a corner whose edges have (nearly) no length would otherwise
        // have splits go on towards zero size.
        let perimeter: f64 = (0..n)
            .map(|i| norm(sub(points[(i + 1) % n], points[i])))
            .sum();
        let floor = SCALE_FLOOR * perimeter / n.max(1) as f64;
        scales.iter_mut().for_each(|s| *s = s.max(floor));
        let mut edges = HashMap::with_capacity(3 * triangles.len());
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                edges.insert((tri[k], tri[(k + 1) % 3]), t as u32);
            }
        }
        Patch {
            n_rim: n,
            points: points.to_vec(),
            parents: Vec::new(),
            triangles,
            scales,
            edges,
        }
    }

    /// Vertices the patch adds (beyond the rim's corners).
    pub(super) fn n_added(&self) -> usize {
        self.points.len() - self.n_rim
    }

    /// Splits and flips until no triangle is split (at most [`REFINE_ROUNDS_MAX`] rounds in
    /// all), then calls `after_refining` on the patch (fairing moves the new vertices there);
    /// when that stretched triangles enough to split again, refines and calls it again, at most
    /// [`REFINE_PASSES_MAX`] times. Stops at the first call that fails, with its error. O(m log m)
    /// for a result of m triangles, besides the calls.
    pub(super) fn refine<E>(
        &mut self,
        joined: &JoinedCorners,
        mut after_refining: impl FnMut(&mut Patch) -> Result<(), E>,
    ) -> Result<(), E> {
        let mut rounds = 0;
        for _ in 0..REFINE_PASSES_MAX {
            let mut split = false;
            while rounds < REFINE_ROUNDS_MAX && self.split_large_triangles() {
                self.relax(joined);
                rounds += 1;
                split = true;
            }
            if !split {
                break;
            }
            after_refining(self)?;
        }
        Ok(())
    }

    /// Splits every triangle the density test marks at its centroid, but for those whose
    /// centroid lies within the density's reach of a vertex this round added already (see
    /// [`RoundVertices`]); whether any was split.
    fn split_large_triangles(&mut self) -> bool {
        let count = self.triangles.len();
        let mut split = false;
        let mean_rim_scale =
            self.scales[..self.n_rim].iter().sum::<f64>() / self.n_rim.max(1) as f64;
        let mut added = RoundVertices::new(mean_rim_scale / DENSITY);
        for t in 0..count {
            let tri = self.triangles[t];
            let corners = tri.map(|v| self.points[v as usize]);
            let centroid: [f64; 3] =
                std::array::from_fn(|k| (corners[0][k] + corners[1][k] + corners[2][k]) / 3.0);
            let scale = tri.iter().map(|&v| self.scales[v as usize]).sum::<f64>() / 3.0;
            let too_large = (0..3).all(|k| {
                let reach = DENSITY * norm(sub(centroid, corners[k]));
                reach > scale && reach > self.scales[tri[k] as usize]
            });
            if too_large
                && centroid.iter().all(|c| c.is_finite())
                && !added.near(&self.points, centroid, scale / DENSITY)
            {
                added.insert(self.points.len() as u32, centroid);
                self.split(t, centroid, scale);
                split = true;
            }
        }
        split
    }

    /// Splits triangle `t` at a new vertex at `position` into three.
    fn split(&mut self, t: usize, position: [f64; 3], scale: f64) {
        let [a, b, c] = self.triangles[t];
        let w = self.points.len() as u32;
        self.points.push(position);
        self.scales.push(scale);
        self.parents.push([a, b, c]);
        let (t1, t2) = (self.triangles.len() as u32, self.triangles.len() as u32 + 1);
        self.triangles[t] = [a, b, w];
        self.triangles.push([b, c, w]);
        self.triangles.push([c, a, w]);
        for (edge, tri) in [
            ((b, w), t as u32),
            ((w, a), t as u32),
            ((b, c), t1),
            ((c, w), t1),
            ((w, b), t1),
            ((c, a), t2),
            ((a, w), t2),
            ((w, c), t2),
        ] {
            self.edges.insert(edge, tri);
        }
    }

    /// Flips interior edges that are not locally Delaunay (see the module docs), each edge at
    /// most [`FLIPS_PER_EDGE`] times over the pass.
    fn relax(&mut self, joined: &JoinedCorners) {
        let mut interior: Vec<(u32, u32)> = self
            .edges
            .keys()
            .copied()
            .filter(|&(a, b)| a < b && self.edges.contains_key(&(b, a)))
            .collect();
        // Sorted: the hash map's order would make the result differ from run to run.
        interior.sort_unstable();
        let mut queue = VecDeque::from(interior);
        let mut budget = FLIPS_PER_EDGE * queue.len();
        while let Some((a, b)) = queue.pop_front() {
            if budget == 0 {
                break;
            }
            let Some(flipped) = self.flip_if_better(a, b, joined) else {
                continue;
            };
            budget -= 1;
            queue.extend(flipped);
        }
    }

    /// Flips edge `a b` when the test of the module docs asks for it; returns the four edges
    /// around the new diagonal to test again.
    fn flip_if_better(
        &mut self,
        a: u32,
        b: u32,
        joined: &JoinedCorners,
    ) -> Option<[(u32, u32); 4]> {
        let (&t, &s) = (self.edges.get(&(a, b))?, self.edges.get(&(b, a))?);
        let c = third(self.triangles[t as usize], a, b);
        let d = third(self.triangles[s as usize], b, a);
        if c == d || self.edges.contains_key(&(c, d)) || self.edges.contains_key(&(d, c)) {
            return None;
        }
        let n_rim = self.n_rim as u32;
        if c < n_rim && d < n_rim && !joined.may_join(c, d) {
            return None;
        }
        let p = |v: u32| self.points[v as usize];
        let opposite = angle_at(p(c), p(a), p(b)) + angle_at(p(d), p(b), p(a));
        if opposite <= std::f64::consts::PI + 1e-12 {
            return None;
        }
        let old = [
            triangle_normal(p(a), p(b), p(c)).0,
            triangle_normal(p(b), p(a), p(d)).0,
        ];
        let new = [[a, d, c], [d, b, c]];
        for tri in new {
            let [x, y, z] = tri.map(p);
            let normal = triangle_normal(x, y, z).0;
            if is_degenerate(x, y, z) || old.iter().any(|&o| dot(normal, o) <= 0.0) {
                return None;
            }
        }
        self.edges.remove(&(a, b));
        self.edges.remove(&(b, a));
        self.triangles[t as usize] = new[0];
        self.triangles[s as usize] = new[1];
        for (edge, tri) in [
            ((a, d), t),
            ((d, c), t),
            ((c, a), t),
            ((d, b), s),
            ((b, c), s),
            ((c, d), s),
        ] {
            self.edges.insert(edge, tri);
        }
        Some([(a, d), (d, b), (b, c), (c, a)])
    }

    /// The patch's neighbours of every vertex (each undirected edge once per end).
    pub(super) fn neighbours(&self) -> Vec<Vec<u32>> {
        let mut neighbours = vec![Vec::new(); self.points.len()];
        for &(u, v) in self.edges.keys() {
            // Each undirected edge once: from its interior half, or its only (rim) half.
            if u < v || !self.edges.contains_key(&(v, u)) {
                neighbours[u as usize].push(v);
                neighbours[v as usize].push(u);
            }
        }
        for list in &mut neighbours {
            list.sort_unstable();
        }
        neighbours
    }
}

/// The vertices one round of splits added, in a grid of cubes: a round splits every large
/// triangle at once, and the centroids of neighbouring slivers (a coarse fill's fan from a far
/// corner to short rim edges) lie far closer to each other than to any corner. Splitting both
/// would leave clusters of vertices that no flip separates (a third of a 1,000-edge fill's
/// edges were under a fifth of its scale); the second waits for the next round, after flips.
struct RoundVertices {
    cell: f64,
    cells: HashMap<[i64; 3], Vec<u32>>,
}

impl RoundVertices {
    fn new(cell: f64) -> RoundVertices {
        RoundVertices {
            cell,
            cells: HashMap::new(),
        }
    }

    fn key(&self, p: [f64; 3]) -> [i64; 3] {
        // Saturating: a position beyond the grid's range shares the last cell.
        p.map(|x| (x / self.cell).floor() as i64)
    }

    /// Whether a vertex of this round lies closer to `p` than `reach` (at most a cell, so that
    /// the search stays in the 27 cells around `p`).
    fn near(&self, points: &[[f64; 3]], p: [f64; 3], reach: f64) -> bool {
        if !(self.cell > 0.0 && self.cell.is_finite()) {
            return false;
        }
        let reach = reach.min(self.cell);
        let [x, y, z] = self.key(p);
        (-1..=1).any(|i| {
            (-1..=1).any(|j| {
                (-1..=1).any(|k| {
                    let key = [
                        x.saturating_add(i),
                        y.saturating_add(j),
                        z.saturating_add(k),
                    ];
                    self.cells.get(&key).is_some_and(|vs| {
                        vs.iter().any(|&v| norm(sub(points[v as usize], p)) < reach)
                    })
                })
            })
        })
    }

    fn insert(&mut self, v: u32, p: [f64; 3]) {
        if self.cell > 0.0 && self.cell.is_finite() {
            self.cells.entry(self.key(p)).or_default().push(v);
        }
    }
}

/// The corner of `tri` that is neither `a` nor `b`.
fn third(tri: [u32; 3], a: u32, b: u32) -> u32 {
    tri.into_iter()
        .find(|&v| v != a && v != b)
        .expect("a triangle has three distinct corners")
}

/// The angle at `apex` between the directions to `p` and `q`.
fn angle_at(apex: [f64; 3], p: [f64; 3], q: [f64; 3]) -> f64 {
    let (u, v) = (sub(p, apex), sub(q, apex));
    let (nu, nv) = (norm(u), norm(v));
    if nu == 0.0 || nv == 0.0 {
        return 0.0;
    }
    (dot(u, v) / (nu * nv)).clamp(-1.0, 1.0).acos()
}
