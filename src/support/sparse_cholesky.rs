//! Sparse Cholesky factorisation `P A Pᵀ = L Lᵀ` of a symmetric positive definite matrix, for
//! solves with three right-hand sides at once (the coordinates of points).
//!
//! Up-looking, one row of `L` at a time: the row's pattern is the set of nodes reached from the
//! matrix row's entries up the elimination tree, so the work is the sum over `L`'s columns of
//! their counts squared and the memory that of `L`. Both depend on the elimination order `P`,
//! which the caller gives (see [`super::nested_dissection`]).

use super::allocation::{OutOfMemory, try_filled, try_vec_with_capacity};

const NONE: u32 = u32::MAX;

/// A symmetric matrix stored by rows, each row holding its entries of both triangles.
#[derive(Clone, Debug, Default)]
pub(crate) struct SymmetricMatrix {
    /// Row `i`'s entries are `columns[starts[i]..starts[i + 1]]` (and `values` there).
    pub(crate) starts: Vec<usize>,
    pub(crate) columns: Vec<u32>,
    pub(crate) values: Vec<f64>,
}

impl SymmetricMatrix {
    /// Rows (and columns).
    pub(crate) fn n(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    fn row(&self, i: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let range = self.starts[i]..self.starts[i + 1];
        self.columns[range.clone()]
            .iter()
            .zip(&self.values[range])
            .map(|(&j, &a)| (j as usize, a))
    }

    /// `self × x` into `out`, three columns at once.
    pub(crate) fn multiply(&self, x: &[[f64; 3]], out: &mut [[f64; 3]]) {
        for (i, out) in out.iter_mut().enumerate() {
            let mut sum = [0.0; 3];
            for (j, a) in self.row(i) {
                (0..3).for_each(|k| sum[k] += a * x[j][k]);
            }
            *out = sum;
        }
    }
}

/// Why a matrix has no factor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum CholeskyFailure {
    /// The factor needs more memory than the system gives.
    OutOfMemory(OutOfMemory),
    /// A pivot came out zero, negative or not finite: the matrix is not (numerically) positive
    /// definite.
    NotPositiveDefinite,
}

impl From<OutOfMemory> for CholeskyFailure {
    fn from(refusal: OutOfMemory) -> Self {
        CholeskyFailure::OutOfMemory(refusal)
    }
}

/// The factor `L` of `P A Pᵀ`, column by column, each column's diagonal first.
#[derive(Clone, Debug)]
pub(crate) struct Cholesky {
    /// `order[k]`: the row of the matrix eliminated `k`-th.
    order: Vec<u32>,
    starts: Vec<usize>,
    rows: Vec<u32>,
    values: Vec<f64>,
}

/// The elimination tree of `P A Pᵀ` and the pattern walks over it.
struct Tree<'a> {
    matrix: &'a SymmetricMatrix,
    order: &'a [u32],
    /// `position[i]`: where row `i` of the matrix is eliminated.
    position: Vec<u32>,
    parent: Vec<u32>,
    mark: Vec<u32>,
    /// Row `k`'s pattern in `stack[top..]`, descendants before ancestors.
    stack: Vec<u32>,
}

impl<'a> Tree<'a> {
    fn new(matrix: &'a SymmetricMatrix, order: &'a [u32]) -> Result<Self, OutOfMemory> {
        let n = matrix.n();
        let mut position = try_filled(n, 0u32, "elimination positions")?;
        for (k, &i) in order.iter().enumerate() {
            position[i as usize] = k as u32;
        }
        let mut tree = Tree {
            matrix,
            order,
            position,
            parent: try_filled(n, NONE, "elimination tree nodes")?,
            mark: try_filled(n, NONE, "elimination tree marks")?,
            stack: try_filled(n, 0u32, "elimination tree nodes")?,
        };
        // Liu's algorithm, the ancestors' path compressed in `mark`.
        for k in 0..n {
            let row = tree.order[k] as usize;
            for e in matrix.starts[row]..matrix.starts[row + 1] {
                let q = tree.position[matrix.columns[e] as usize];
                if q >= k as u32 {
                    continue;
                }
                let mut i = q;
                while i != NONE && i < k as u32 {
                    let next = tree.mark[i as usize];
                    tree.mark[i as usize] = k as u32;
                    if next == NONE {
                        tree.parent[i as usize] = k as u32;
                    }
                    i = next;
                }
            }
        }
        tree.mark.fill(NONE);
        Ok(tree)
    }

    /// Puts row `k`'s pattern in `stack[top..]` and returns `top`.
    fn reach(&mut self, k: usize) -> usize {
        let n = self.stack.len();
        let mut top = n;
        self.mark[k] = k as u32;
        let starts = self.matrix.starts[self.order[k] as usize];
        let ends = self.matrix.starts[self.order[k] as usize + 1];
        for e in starts..ends {
            let q = self.position[self.matrix.columns[e] as usize];
            if q >= k as u32 {
                continue;
            }
            // The path from q up to a marked node, written below the paths found before.
            let mut length = 0;
            let mut i = q;
            while self.mark[i as usize] != k as u32 {
                self.stack[length] = i;
                length += 1;
                self.mark[i as usize] = k as u32;
                i = self.parent[i as usize];
            }
            while length > 0 {
                top -= 1;
                length -= 1;
                self.stack[top] = self.stack[length];
            }
        }
        top
    }
}

impl Cholesky {
    /// Factors `matrix` eliminated in `order` (a permutation of its rows). O(|L|) memory and
    /// O(Σ column count²) time.
    pub(crate) fn factor(
        matrix: &SymmetricMatrix,
        order: Vec<u32>,
    ) -> Result<Self, CholeskyFailure> {
        let n = matrix.n();
        debug_assert_eq!(order.len(), n);
        let mut tree = Tree::new(matrix, &order)?;
        // Column counts: row k adds an entry to each column of its pattern.
        let mut counts = try_filled(n, 1usize, "factor columns")?;
        for k in 0..n {
            let top = tree.reach(k);
            for &i in &tree.stack[top..] {
                counts[i as usize] += 1;
            }
        }
        let mut starts = try_vec_with_capacity(n + 1, "factor columns")?;
        starts.push(0);
        for &count in &counts {
            starts.push(starts.last().copied().unwrap_or(0) + count);
        }
        let total = starts[n];
        let mut rows = try_filled(total, 0u32, "factor entries")?;
        let mut values = try_filled(total, 0.0f64, "factor entries")?;
        let mut next = starts[..n].to_vec();
        let mut x = try_filled(n, 0.0f64, "factor rows")?;
        tree.mark.fill(NONE);
        for k in 0..n {
            let top = tree.reach(k);
            for (j, a) in matrix.row(order[k] as usize) {
                let q = tree.position[j] as usize;
                if q <= k {
                    x[q] += a;
                }
            }
            let mut diagonal = x[k];
            x[k] = 0.0;
            for &i in &tree.stack[top..] {
                let i = i as usize;
                let l = x[i] / values[starts[i]];
                x[i] = 0.0;
                for e in starts[i] + 1..next[i] {
                    x[rows[e] as usize] -= values[e] * l;
                }
                diagonal -= l * l;
                rows[next[i]] = k as u32;
                values[next[i]] = l;
                next[i] += 1;
            }
            if !(diagonal > 0.0 && diagonal.is_finite()) {
                return Err(CholeskyFailure::NotPositiveDefinite);
            }
            rows[next[k]] = k as u32;
            values[next[k]] = diagonal.sqrt();
            next[k] += 1;
        }
        Ok(Cholesky {
            order,
            starts,
            rows,
            values,
        })
    }

    /// Entries of the factor.
    #[cfg(test)]
    pub(crate) fn entries(&self) -> usize {
        self.rows.len()
    }

    /// Solves `A x = b` in place (`b` in, `x` out), using `scratch` (any length; resized).
    pub(crate) fn solve(
        &self,
        b: &mut [[f64; 3]],
        scratch: &mut Vec<[f64; 3]>,
    ) -> Result<(), OutOfMemory> {
        let n = self.order.len();
        scratch.clear();
        super::allocation::try_reserve(scratch, n, "solve entries")?;
        scratch.extend(self.order.iter().map(|&i| b[i as usize]));
        let y = scratch;
        for j in 0..n {
            let diagonal = self.values[self.starts[j]];
            let yj = y[j].map(|v| v / diagonal);
            y[j] = yj;
            for e in self.starts[j] + 1..self.starts[j + 1] {
                let (r, l) = (self.rows[e] as usize, self.values[e]);
                (0..3).for_each(|k| y[r][k] -= l * yj[k]);
            }
        }
        for j in (0..n).rev() {
            let mut yj = y[j];
            for e in self.starts[j] + 1..self.starts[j + 1] {
                let (r, l) = (self.rows[e] as usize, self.values[e]);
                (0..3).for_each(|k| yj[k] -= l * y[r][k]);
            }
            let diagonal = self.values[self.starts[j]];
            y[j] = yj.map(|v| v / diagonal);
        }
        for (k, &i) in self.order.iter().enumerate() {
            b[i as usize] = y[k];
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The path graph's Laplacian plus the identity, `n` rows.
    fn path_matrix(n: usize) -> SymmetricMatrix {
        let mut m = SymmetricMatrix {
            starts: vec![0],
            ..SymmetricMatrix::default()
        };
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                m.columns.push(j as u32);
                let neighbours = usize::from(i > 0) + usize::from(i + 1 < n);
                m.values.push(if i == j {
                    1.0 + neighbours as f64
                } else {
                    -1.0
                });
            }
            m.starts.push(m.columns.len());
        }
        m
    }

    #[test]
    fn solves_in_any_order() {
        let n = 50;
        let m = path_matrix(n);
        let x: Vec<[f64; 3]> = (0..n)
            .map(|i| [i as f64, (i * i) as f64 * 0.01, -1.0])
            .collect();
        let mut b = vec![[0.0; 3]; n];
        m.multiply(&x, &mut b);
        // Natural order (no fill), reversed, and interleaved (fill).
        let orders: [Vec<u32>; 3] = [
            (0..n as u32).collect(),
            (0..n as u32).rev().collect(),
            (0..n as u32)
                .step_by(2)
                .chain((1..n as u32).step_by(2))
                .collect(),
        ];
        for order in orders {
            let factor = Cholesky::factor(&m, order).unwrap();
            assert!(factor.entries() >= 2 * n - 1);
            let mut solved = b.clone();
            factor.solve(&mut solved, &mut Vec::new()).unwrap();
            for (s, e) in solved.iter().zip(&x) {
                for k in 0..3 {
                    assert!((s[k] - e[k]).abs() < 1e-9, "{s:?} {e:?}");
                }
            }
        }
    }

    #[test]
    fn refuses_an_indefinite_matrix() {
        let mut m = path_matrix(4);
        // Row 2's diagonal −1: the matrix has a negative eigenvalue.
        let at = m.starts[2] + 1;
        m.values[at] = -1.0;
        assert_eq!(
            Cholesky::factor(&m, vec![0, 1, 2, 3]).unwrap_err(),
            CholeskyFailure::NotPositiveDefinite
        );
    }
}
