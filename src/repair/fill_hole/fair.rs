//! Fairing a refined fill: the vertices refinement added move to minimise a thin-plate energy,
//! the rim and the mesh around it fixed.
//!
//! The energy is the sum over the patch's vertices (rim included) of the squared uniform
//! Laplacian `U x_v = mean of v's neighbours − x_v`, a rim vertex's neighbours counting those
//! in the mesh around the hole: its minimum continues the surrounding surface smoothly
//! (bilaplacian fairing with uniform weights, which refinement's even triangles suit). The
//! normal equations `(Uᵀ U) x = …` over the added vertices are symmetric positive definite and
//! solved by conjugate gradients, matrix-free, up to [`FAIR_ITERATIONS_MAX`] iterations and a
//! residual [`FAIR_TOLERANCE`] times the initial one.

use super::refine::Patch;

/// Conjugate-gradient iterations per solve at most. Refinement fairs after every round, each
/// solve starting from the last one's vertices (new ones at their triangle's centroid), so the
/// error left is mostly between neighbours, which few iterations remove.
pub const FAIR_ITERATIONS_MAX: usize = 2000;

/// The solve stops when the energy's gradient is this fraction of the gradient it started
/// from (or at the rounding level of the coordinates).
pub const FAIR_TOLERANCE: f64 = 1e-9;

/// The mesh around a hole's rim: for each rim corner, the sum of the positions of its mesh
/// neighbours other than its two rim neighbours, and their number.
#[derive(Clone, Debug)]
pub(super) struct Surround {
    pub(super) sums: Vec<[f64; 3]>,
    pub(super) counts: Vec<usize>,
}

/// Why fairing failed; the patch is as refinement left it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum FairFailure {
    /// The solve did not reach the tolerance within the iteration cap.
    NotConverged,
    /// A position came out NaN or infinite.
    NotFinite,
}

/// Moves the patch's added vertices to the energy's minimum (see the module docs).
pub(super) fn fair(patch: &mut Patch, surround: &Surround) -> Result<(), FairFailure> {
    let n_rim = patch.n_rim;
    let m = patch.points.len();
    if m == n_rim {
        return Ok(());
    }
    let neighbours = patch.neighbours();
    let degrees: Vec<f64> = (0..m)
        .map(|v| {
            let outer = if v < n_rim { surround.counts[v] } else { 0 };
            (neighbours[v].len() + outer) as f64
        })
        .collect();
    // U applied to `x`, the rim's outer neighbours at their positions when `with_outer`.
    let laplacian = |x: &[[f64; 3]], with_outer: bool| -> Vec<[f64; 3]> {
        (0..m)
            .map(|v| {
                let mut sum = if with_outer && v < n_rim {
                    surround.sums[v]
                } else {
                    [0.0; 3]
                };
                for &j in &neighbours[v] {
                    for k in 0..3 {
                        sum[k] += x[j as usize][k];
                    }
                }
                std::array::from_fn(|k| sum[k] / degrees[v] - x[v][k])
            })
            .collect()
    };
    // Uᵀ applied to `q`, on the added vertices (zero on the rim).
    let transposed = |q: &[[f64; 3]]| -> Vec<[f64; 3]> {
        (0..m)
            .map(|j| {
                if j < n_rim {
                    return [0.0; 3];
                }
                let mut sum = [0.0; 3];
                for &v in &neighbours[j] {
                    for k in 0..3 {
                        sum[k] += q[v as usize][k] / degrees[v as usize];
                    }
                }
                std::array::from_fn(|k| sum[k] - q[j][k])
            })
            .collect()
    };
    let normal_matrix = |p: &[[f64; 3]]| transposed(&laplacian(p, false));
    // Solve (UᵀU) δ = −Uᵀ U x for each coordinate, in lockstep.
    let gradient = transposed(&laplacian(&patch.points, true));
    let mut residual: Vec<[f64; 3]> = gradient.iter().map(|g| g.map(|x| -x)).collect();
    let mut direction = residual.clone();
    let mut delta = vec![[0.0; 3]; m];
    let magnitude = patch
        .points
        .iter()
        .flatten()
        .fold(0.0_f64, |acc, x| acc.max(x.abs()));
    let floor = 64.0 * f64::EPSILON * magnitude.max(f64::MIN_POSITIVE);
    let squared = |v: &[[f64; 3]]| -> [f64; 3] {
        let mut s = [0.0; 3];
        for x in v {
            for k in 0..3 {
                s[k] += x[k] * x[k];
            }
        }
        s
    };
    let start = squared(&residual);
    let target: [f64; 3] = std::array::from_fn(|k| {
        (FAIR_TOLERANCE * FAIR_TOLERANCE * start[k]).max(floor * floor * (m - n_rim) as f64)
    });
    let mut current = start;
    let mut converged = (0..3).all(|k| current[k] <= target[k]);
    for _ in 0..FAIR_ITERATIONS_MAX {
        if converged {
            break;
        }
        let product = normal_matrix(&direction);
        let mut curvature = [0.0; 3];
        for (p, q) in direction.iter().zip(&product) {
            for k in 0..3 {
                curvature[k] += p[k] * q[k];
            }
        }
        let step: [f64; 3] = std::array::from_fn(|k| {
            if current[k] <= target[k] || curvature[k] <= 0.0 {
                0.0
            } else {
                current[k] / curvature[k]
            }
        });
        for j in n_rim..m {
            for k in 0..3 {
                delta[j][k] += step[k] * direction[j][k];
                residual[j][k] -= step[k] * product[j][k];
            }
        }
        let next = squared(&residual);
        for j in n_rim..m {
            for k in 0..3 {
                let ratio = if current[k] > 0.0 {
                    next[k] / current[k]
                } else {
                    0.0
                };
                direction[j][k] = residual[j][k] + ratio * direction[j][k];
            }
        }
        if next.iter().any(|x| !x.is_finite()) {
            return Err(FairFailure::NotFinite);
        }
        current = next;
        converged = (0..3).all(|k| current[k] <= target[k]);
    }
    if !converged {
        return Err(FairFailure::NotConverged);
    }
    let moved: Vec<[f64; 3]> = (n_rim..m)
        .map(|j| std::array::from_fn(|k| patch.points[j][k] + delta[j][k]))
        .collect();
    if !moved.iter().flatten().all(|x| x.is_finite()) {
        return Err(FairFailure::NotFinite);
    }
    patch.points[n_rim..].copy_from_slice(&moved);
    Ok(())
}
