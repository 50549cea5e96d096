//! Faces of a parametric lattice: the shared core of the swept, ruled, revolved, toroidal and grid
//! surfaces. A generator lays out one vertex id per lattice node (several nodes may share an id:
//! poles, welded seams), and this module turns every lattice cell into a face, dropping the
//! repeated corners that shared ids create so that no face is degenerate.

use super::builder::SoupBuilder;

/// How the cells of a lattice become faces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CellFaces {
    /// One quadrilateral per cell (a triangle where a pole collapses one side).
    #[default]
    Quads,
    /// Two triangles per cell, split along the diagonal from the cell's first corner.
    Triangles,
}

/// A lattice of vertex ids, `columns` nodes along u by `rows` nodes along v, row after row.
/// A wrapped direction joins its last node back to its first.
pub(crate) struct Lattice<'a> {
    pub(crate) ids: &'a [u32],
    pub(crate) columns: usize,
    pub(crate) rows: usize,
    pub(crate) wrap_u: bool,
    pub(crate) wrap_v: bool,
}

/// A cell whose corners collapse to fewer than three distinct vertices, by lattice coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct CollapsedCell {
    pub(crate) u: usize,
    pub(crate) v: usize,
}

impl Lattice<'_> {
    /// Number of cells along u.
    pub(crate) fn cells_u(&self) -> usize {
        if self.wrap_u {
            self.columns
        } else {
            self.columns.saturating_sub(1)
        }
    }

    /// Number of cells along v.
    pub(crate) fn cells_v(&self) -> usize {
        if self.wrap_v {
            self.rows
        } else {
            self.rows.saturating_sub(1)
        }
    }

    fn id(&self, u: usize, v: usize) -> u32 {
        self.ids[(v % self.rows) * self.columns + (u % self.columns)]
    }

    /// Emits every cell as faces. Corners go (u,v), (u+1,v), (u+1,v+1), (u,v+1), so a face's
    /// normal points along ∂S/∂u × ∂S/∂v: generators pick u and v so that this is "outside".
    pub(crate) fn push_faces(
        &self,
        out: &mut SoupBuilder,
        kind: CellFaces,
    ) -> Result<(), CollapsedCell> {
        for v in 0..self.cells_v() {
            for u in 0..self.cells_u() {
                let quad = [
                    self.id(u, v),
                    self.id(u + 1, v),
                    self.id(u + 1, v + 1),
                    self.id(u, v + 1),
                ];
                let corners = distinct_cycle(quad);
                match (corners.as_slice(), kind) {
                    ([a, b, c, d], CellFaces::Triangles) => {
                        out.face(&[*a, *b, *c]);
                        out.face(&[*a, *c, *d]);
                    }
                    ([_, _, _, _] | [_, _, _], _) => out.face(&corners),
                    _ => return Err(CollapsedCell { u, v }),
                }
            }
        }
        Ok(())
    }
}

/// Removes cyclically repeated neighbours; returns an empty list when a non-adjacent repeat
/// remains (the cell would be a pinched, non-simple polygon).
fn distinct_cycle(quad: [u32; 4]) -> Vec<u32> {
    let mut corners: Vec<u32> = Vec::with_capacity(4);
    for (i, &id) in quad.iter().enumerate() {
        if id != quad[(i + 3) % 4] {
            corners.push(id);
        }
    }
    if corners.is_empty() {
        return corners;
    }
    let mut sorted = corners.clone();
    sorted.sort_unstable();
    sorted.dedup();
    if sorted.len() != corners.len() {
        corners.clear();
    }
    corners
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distinct_cycle_drops_pole_repeats_and_rejects_pinches() {
        assert_eq!(distinct_cycle([1, 2, 3, 4]), vec![1, 2, 3, 4]);
        assert_eq!(distinct_cycle([7, 7, 3, 4]), vec![7, 3, 4]);
        assert_eq!(distinct_cycle([3, 7, 4, 3]), vec![7, 4, 3]);
        assert_eq!(distinct_cycle([1, 2, 1, 3]), Vec::<u32>::new());
        assert_eq!(distinct_cycle([5, 5, 5, 5]), Vec::<u32>::new());
        assert_eq!(distinct_cycle([5, 5, 6, 6]).len(), 2);
    }
}
