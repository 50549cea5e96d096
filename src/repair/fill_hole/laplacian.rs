//! The cotangent Laplacian over a refined patch and the faces around its hole, the operator
//! fairing minimises.
//!
//! Row `w` is the discrete Laplace–Beltrami operator at vertex `w`, `(1 / A_w) Σ_j c_wj (x_j −
//! x_w)` with `c_wj` half the sum of the cotangents of the angles facing edge `w j` and `A_w`
//! a third of the area of the triangles at `w`, scaled by `√A_w` so that the sum of the rows'
//! squares is the thin-plate energy `Σ A_w |Δx_w|²`. Unlike uniform weights it depends on the
//! surface only, not on how it is sampled: a fill refined finely against long faces around the
//! hole (a tube of tall quads split in two) still continues their tangent plane, where uniform
//! weights would pull the fill's first ring as far out as the long edges reach, a ridge that
//! refinement then splits again and again. The weights are taken from the geometry before the
//! move (the operator is linear in the moves), the faces around the hole from the mesh (a
//! polygon by the triangle at the rim corner), and the patch's from its triangles.

use super::geometry::{cross, dot, norm, sub, triangle_area};
use super::refine::Patch;
use crate::mesh::{Mesh, VertexId};

/// The largest cotangent weight a triangle gives (an angle of about 0.06°): a sliver beside
/// the hole would otherwise give an infinite one.
const COTANGENT_MAX: f64 = 1e3;

/// The faces around a hole's rim, as fairing needs them: per rim corner, what its Laplacian row
/// takes from the mesh.
#[derive(Clone, Debug)]
pub(super) struct Surround {
    /// `Σ c_wj x_j` over the corner's mesh neighbours other than its two rim neighbours.
    outer_sums: Vec<[f64; 3]>,
    /// `Σ c_wj` over the same neighbours.
    outer_weights: Vec<f64>,
    /// The weights the mesh's faces give the rim edges to the next and the previous corner.
    rim_weights: Vec<[f64; 2]>,
    /// A third of the area of the mesh's faces at the corner.
    areas: Vec<f64>,
}

impl Surround {
    /// The faces of `mesh` around the rim `corners` (in loop order).
    pub(super) fn of(mesh: &Mesh, corners: &[VertexId]) -> Surround {
        let n = corners.len();
        let mut surround = Surround {
            outer_sums: Vec::with_capacity(n),
            outer_weights: Vec::with_capacity(n),
            rim_weights: Vec::with_capacity(n),
            areas: Vec::with_capacity(n),
        };
        let mut edges: Vec<(VertexId, f64)> = Vec::new();
        for (i, &v) in corners.iter().enumerate() {
            let (next, previous) = (corners[(i + 1) % n], corners[(i + n - 1) % n]);
            let at = mesh.position(v);
            let mut area = 0.0;
            edges.clear();
            for out in mesh.outgoing_halfedges(v) {
                if mesh.is_boundary_halfedge(out) {
                    continue;
                }
                // The face's triangle at v: p → v → q.
                let q = mesh.target(out);
                let p = mesh.origin(mesh.prev(out));
                let (pp, qp) = (mesh.position(p), mesh.position(q));
                edges.push((q, 0.5 * cotangent(pp, at, qp)));
                edges.push((p, 0.5 * cotangent(qp, at, pp)));
                area += triangle_area(pp, at, qp) / 3.0;
            }
            // One weight per edge, whatever the vertex's degree: O(d log d).
            edges.sort_unstable_by_key(|&(w, _)| w.0);
            let (mut sum, mut weight, mut rim) = ([0.0; 3], 0.0, [0.0; 2]);
            for &(w, c) in &edges {
                if w == next {
                    rim[0] += c;
                } else if w == previous {
                    rim[1] += c;
                } else {
                    let p = mesh.position(w);
                    (0..3).for_each(|k| sum[k] += c * p[k]);
                    weight += c;
                }
            }
            surround.outer_sums.push(sum);
            surround.outer_weights.push(weight);
            surround.rim_weights.push(rim);
            surround.areas.push(area);
        }
        surround
    }
}

/// The cotangent of the angle at `apex` of the triangle `apex p q`, at most [`COTANGENT_MAX`]
/// in magnitude; 0 when a side at the apex has no length.
fn cotangent(apex: [f64; 3], p: [f64; 3], q: [f64; 3]) -> f64 {
    let (u, v) = (sub(p, apex), sub(q, apex));
    let (cos, sin) = (dot(u, v), norm(cross(u, v)));
    if cos == 0.0 && sin == 0.0 || !(cos.is_finite() && sin.is_finite()) {
        0.0
    } else if sin * COTANGENT_MAX > cos.abs() {
        cos / sin
    } else {
        COTANGENT_MAX.copysign(cos)
    }
}

/// The rows of the scaled Laplacian `U` over a patch (see the module docs): row `w` is
/// `scales[w] · (outer[w] + Σ_j weights[w][j] x_j − totals[w] x_w)`, its neighbours in the
/// patch sorted.
#[derive(Clone, Debug)]
pub(super) struct Laplacian {
    /// Each vertex's neighbours in the patch.
    pub(super) neighbours: Vec<Vec<u32>>,
    /// The weight of the edge to each neighbour (the same from both ends but along the rim).
    weights: Vec<Vec<f64>>,
    /// `Σ_j weights[w][j]` with the rim corners' weights from the mesh.
    totals: Vec<f64>,
    /// The rim corners' `Σ c_wj x_j` over their neighbours in the mesh; zero elsewhere.
    outer: Vec<[f64; 3]>,
    /// `1 / √A_w`.
    scales: Vec<f64>,
}

impl Laplacian {
    /// The Laplacian of `patch` at its current positions, the rim's rows completed by `surround`.
    pub(super) fn new(patch: &Patch, surround: &Surround) -> Laplacian {
        let m = patch.points.len();
        let n_rim = patch.n_rim;
        let neighbours = patch.neighbours();
        let mut weights: Vec<Vec<f64>> = neighbours.iter().map(|l| vec![0.0; l.len()]).collect();
        let mut areas = vec![0.0; m];
        let add = |weights: &mut Vec<Vec<f64>>, a: u32, b: u32, c: f64| {
            for (from, to) in [(a, b), (b, a)] {
                let row = &neighbours[from as usize];
                if let Ok(k) = row.binary_search(&to) {
                    weights[from as usize][k] += c;
                }
            }
        };
        for &[a, b, c] in &patch.triangles {
            let [pa, pb, pc] = [a, b, c].map(|v| patch.points[v as usize]);
            add(&mut weights, b, c, 0.5 * cotangent(pa, pb, pc));
            add(&mut weights, c, a, 0.5 * cotangent(pb, pc, pa));
            add(&mut weights, a, b, 0.5 * cotangent(pc, pa, pb));
            let third = triangle_area(pa, pb, pc) / 3.0;
            [a, b, c].iter().for_each(|&v| areas[v as usize] += third);
        }
        let mut outer = vec![[0.0; 3]; m];
        let mut totals: Vec<f64> = weights.iter().map(|row| row.iter().sum()).collect();
        for i in 0..n_rim {
            let next = ((i + 1) % n_rim) as u32;
            let previous = ((i + n_rim - 1) % n_rim) as u32;
            for (to, c) in [next, previous].into_iter().zip(surround.rim_weights[i]) {
                if let Ok(k) = neighbours[i].binary_search(&to) {
                    weights[i][k] += c;
                    totals[i] += c;
                }
            }
            outer[i] = surround.outer_sums[i];
            totals[i] += surround.outer_weights[i];
            areas[i] += surround.areas[i];
        }
        // A vertex among degenerate triangles only: the mean area keeps its row finite.
        let mean = areas.iter().sum::<f64>() / m.max(1) as f64;
        let floor = (mean * 1e-12).max(f64::MIN_POSITIVE);
        let scales = areas.iter().map(|&a| 1.0 / a.max(floor).sqrt()).collect();
        Laplacian {
            neighbours,
            weights,
            totals,
            outer,
            scales,
        }
    }

    /// Row `w` of `U` applied to `points`.
    pub(super) fn apply(&self, points: &[[f64; 3]], w: usize) -> [f64; 3] {
        let mut sum = self.outer[w];
        for (&j, &c) in self.neighbours[w].iter().zip(&self.weights[w]) {
            (0..3).for_each(|k| sum[k] += c * points[j as usize][k]);
        }
        std::array::from_fn(|k| self.scales[w] * (sum[k] - self.totals[w] * points[w][k]))
    }

    /// The entries of column `c` of `U`: `(w, U[w][c])` for `c` itself and each neighbour `w`.
    /// For an added vertex `c` only: its edges' weights come from the patch's triangles, the same
    /// from both ends, where a rim corner's edges along the rim also count the mesh's faces.
    pub(super) fn column(&self, c: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let diagonal = (c, -self.scales[c] * self.totals[c]);
        let others = self.neighbours[c]
            .iter()
            .zip(&self.weights[c])
            .map(|(&w, &weight)| (w as usize, self.scales[w as usize] * weight));
        std::iter::once(diagonal).chain(others)
    }

    /// The entries of row `w` of `U`: `(j, U[w][j])` for `w` itself and each neighbour `j`.
    pub(super) fn row(&self, w: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let scale = self.scales[w];
        let diagonal = (w, -scale * self.totals[w]);
        let others = self.neighbours[w]
            .iter()
            .zip(&self.weights[w])
            .map(move |(&j, &weight)| (j as usize, scale * weight));
        std::iter::once(diagonal).chain(others)
    }
}
