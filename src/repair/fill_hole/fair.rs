//! Fairing a refined fill: the vertices refinement added move to minimise a thin-plate energy,
//! the rim and the mesh around it fixed.
//!
//! The energy is the sum over the patch's vertices (rim included) of their squared
//! Laplace–Beltrami operator, `|U x|²` with `U` the area-scaled cotangent Laplacian of
//! [`super::laplacian`], a rim vertex's row counting the faces around the hole: its minimum
//! continues the surrounding surface smoothly, whatever the sizes of the faces there. The
//! normal equations `(Uᵀ U) δ = −Uᵀ U x` for the added vertices' moves `δ` are symmetric
//! positive definite; they are solved by a sparse Cholesky factorisation in nested-dissection
//! order (the matrix's condition grows as the fourth power of the hole's width in edges, which
//! left plain conjugate gradients thousands of iterations short on holes of a few hundred
//! edges), then refined: each iteration solves with the factor for the residual left, until the
//! residual is [`FAIR_TOLERANCE`] times the first (or at the rounding level of the coordinates),
//! at most [`FAIR_ITERATIONS_MAX`] times. For a fill of `m` added vertices the factor has
//! O(m log m) entries and costs O(m^1.5) operations.

use super::laplacian::{Laplacian, Surround};
use super::refine::Patch;
use crate::OutOfMemory;
use crate::support::allocation::{try_filled, try_vec_with_capacity};
use crate::support::nested_dissection::nested_dissection;
use crate::support::sparse_cholesky::{Cholesky, CholeskyFailure, SymmetricMatrix};

/// Solves with the factor per fairing at most: the first, then refinements of the residual
/// left by rounding in the factor. One or two reach [`FAIR_TOLERANCE`] on a well-shaped fill.
pub const FAIR_ITERATIONS_MAX: usize = 8;

/// The solve stops when the residual of the normal equations is this fraction of the one it
/// started from (or at the rounding level of the coordinates).
pub const FAIR_TOLERANCE: f64 = 1e-9;

/// How far a fairing solve goes: at most `iterations_max` solves with the factor, to a
/// residual `tolerance` times the first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct FairLimits {
    pub(super) iterations_max: usize,
    pub(super) tolerance: f64,
}

impl Default for FairLimits {
    fn default() -> Self {
        FairLimits {
            iterations_max: FAIR_ITERATIONS_MAX,
            tolerance: FAIR_TOLERANCE,
        }
    }
}

/// Why fairing failed; the patch is as refinement left it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum FairFailure {
    /// The residual was still above the tolerance after the last iteration allowed.
    NotConverged(FairProgress),
    /// A position or residual came out NaN or infinite.
    NotFinite(FairProgress),
    /// The factorisation met a pivot that is not positive (rounding on a degenerate patch).
    NotPositiveDefinite,
    /// The factor needs more memory than the system gives.
    OutOfMemory(OutOfMemory),
}

/// How far a solve got: the solves with the factor done, and the residual left over the one it
/// started from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct FairProgress {
    pub(super) iterations: usize,
    pub(super) relative_residual: f64,
}

impl From<OutOfMemory> for FairFailure {
    fn from(refusal: OutOfMemory) -> Self {
        FairFailure::OutOfMemory(refusal)
    }
}

impl From<CholeskyFailure> for FairFailure {
    fn from(failure: CholeskyFailure) -> Self {
        match failure {
            CholeskyFailure::OutOfMemory(refusal) => FairFailure::OutOfMemory(refusal),
            CholeskyFailure::NotPositiveDefinite => FairFailure::NotPositiveDefinite,
        }
    }
}

/// Moves the patch's added vertices to the energy's minimum (see the module docs) within
/// `limits`; returns the progress made (`iterations` 0 when the patch was faired already).
pub(super) fn fair(
    patch: &mut Patch,
    surround: &Surround,
    limits: FairLimits,
) -> Result<FairProgress, FairFailure> {
    let n_rim = patch.n_rim;
    let m = patch.points.len();
    let done = FairProgress {
        iterations: 0,
        relative_residual: 0.0,
    };
    if m == n_rim {
        return Ok(done);
    }
    let laplacian = Laplacian::new(patch, surround);
    // U applied to the patch, then Uᵀ on the added vertices: minus the energy's gradient there.
    let applied: Vec<[f64; 3]> = (0..m).map(|w| laplacian.apply(&patch.points, w)).collect();
    let start: Vec<[f64; 3]> = (n_rim..m)
        .map(|c| {
            let mut sum = [0.0; 3];
            for (w, u) in laplacian.column(c) {
                (0..3).for_each(|k| sum[k] -= u * applied[w][k]);
            }
            sum
        })
        .collect();
    let magnitude = patch
        .points
        .iter()
        .flatten()
        .fold(0.0_f64, |acc, x| acc.max(x.abs()));
    let floor = 64.0 * f64::EPSILON * magnitude.max(f64::MIN_POSITIVE);
    let start_norm = norm(&start);
    let target = (limits.tolerance * start_norm).max(floor * ((3 * (m - n_rim)) as f64).sqrt());
    if !start_norm.is_finite() {
        return Err(FairFailure::NotFinite(FairProgress {
            iterations: 0,
            relative_residual: f64::NAN,
        }));
    }
    if start_norm <= target {
        return Ok(done);
    }
    let mut progress = FairProgress {
        iterations: 0,
        relative_residual: 1.0,
    };
    if limits.iterations_max == 0 {
        return Err(FairFailure::NotConverged(progress));
    }
    let matrix = normal_matrix(n_rim, &laplacian)?;
    let order = nested_dissection(&patch.points[n_rim..], &matrix)?;
    let factor = Cholesky::factor(&matrix, order)?;
    let mut delta = try_filled(m - n_rim, [0.0; 3], "fairing moves")?;
    let mut residual = start.clone();
    let mut correction = try_vec_with_capacity(m - n_rim, "fairing moves")?;
    let mut scratch = Vec::new();
    while progress.iterations < limits.iterations_max {
        correction.clear();
        correction.extend_from_slice(&residual);
        factor.solve(&mut correction, &mut scratch)?;
        for (d, c) in delta.iter_mut().zip(&correction) {
            (0..3).for_each(|k| d[k] += c[k]);
        }
        matrix.multiply(&delta, &mut residual);
        for (r, s) in residual.iter_mut().zip(&start) {
            *r = std::array::from_fn(|k| s[k] - r[k]);
        }
        let left = norm(&residual);
        progress.iterations += 1;
        progress.relative_residual = left / start_norm;
        if !left.is_finite() {
            return Err(FairFailure::NotFinite(progress));
        }
        if left <= target {
            break;
        }
    }
    if progress.relative_residual * start_norm > target {
        return Err(FairFailure::NotConverged(progress));
    }
    let moved: Vec<[f64; 3]> = (n_rim..m)
        .map(|j| std::array::from_fn(|k| patch.points[j][k] + delta[j - n_rim][k]))
        .collect();
    if !moved.iter().flatten().all(|x| x.is_finite()) {
        return Err(FairFailure::NotFinite(progress));
    }
    patch.points[n_rim..].copy_from_slice(&moved);
    Ok(progress)
}

/// The Euclidean norm of three columns together.
fn norm(v: &[[f64; 3]]) -> f64 {
    v.iter().flatten().map(|x| x * x).sum::<f64>().sqrt()
}

/// `Uᵀ U` on the added vertices (row `i` for patch vertex `n_rim + i`): entry `(c, d)` sums
/// `U[w][c] · U[w][d]` over the rows `w` of U.
fn normal_matrix(n_rim: usize, laplacian: &Laplacian) -> Result<SymmetricMatrix, OutOfMemory> {
    let m = laplacian.neighbours.len();
    let n = m - n_rim;
    // At most one entry per (row of U, column pair) met: a bound to allocate once.
    let bound: usize = (n_rim..m)
        .map(|c| {
            laplacian
                .column(c)
                .map(|(w, _)| laplacian.neighbours[w].len() + 1)
                .sum::<usize>()
        })
        .sum();
    let mut matrix = SymmetricMatrix {
        starts: try_vec_with_capacity(n + 1, "fairing rows")?,
        columns: try_vec_with_capacity(bound, "fairing entries")?,
        values: try_vec_with_capacity(bound, "fairing entries")?,
    };
    matrix.starts.push(0);
    let mut sums = try_filled(n, 0.0f64, "fairing rows")?;
    let mut touched = try_filled(n, false, "fairing rows")?;
    for c in n_rim..m {
        let first = matrix.columns.len();
        for (w, uc) in laplacian.column(c) {
            for (d, ud) in laplacian.row(w) {
                if d < n_rim {
                    continue;
                }
                if !touched[d - n_rim] {
                    touched[d - n_rim] = true;
                    matrix.columns.push((d - n_rim) as u32);
                }
                sums[d - n_rim] += uc * ud;
            }
        }
        for &d in &matrix.columns[first..] {
            matrix.values.push(sums[d as usize]);
            sums[d as usize] = 0.0;
            touched[d as usize] = false;
        }
        matrix.starts.push(matrix.columns.len());
    }
    Ok(matrix)
}
