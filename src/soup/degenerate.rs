//! Zero-area faces, which every builder reports: checked during its face walk, or in a pass of
//! their own (beside the walk when a second thread is free, before it when the vertex order does
//! not follow the faces; see `soup::front`). The check also learns whether every corner's
//! coordinates are finite, from the sizes it measures the areas against, so that builders need
//! no pass of their own over the positions of input without NaN.

use super::FaceTable;
use crate::geom::{
    is_clearly_not_degenerate_triangle, is_degenerate_quad, is_degenerate_triangle,
    polygon_area_test, quad_squared_perimeter, triangle_squared_size,
};

/// The degenerate faces of a table as input face indices, ascending, found in face order.
pub(crate) struct DegenerateFaces<'p> {
    positions: &'p [[f64; 3]],
    faces: Vec<u32>,
    /// The sum of the squared sizes the checked faces' areas were judged against: finite only
    /// when every coordinate of their corners is (see `geom::triangle_squared_size`).
    squared_sizes: f64,
}

impl<'p> DegenerateFaces<'p> {
    /// None found yet, for the faces of a table whose vertices are at `positions`.
    pub(crate) fn new(positions: &'p [[f64; 3]]) -> Self {
        DegenerateFaces {
            positions,
            faces: Vec::new(),
            squared_sizes: 0.0,
        }
    }

    /// Checks table face `f`, whose vertices are `corners` (faces are checked in order).
    #[inline(always)]
    pub(crate) fn check(&mut self, table: &FaceTable<'_>, f: usize, corners: &[u32]) {
        let positions = self.positions;
        self.record(table, f, area_test(corners, |v| positions[v as usize]));
    }

    /// [`DegenerateFaces::check`] for a walk that has checked the face's vertices already: no
    /// bounds check per corner in the build's busiest loop (1M-triangle open grid 34.1–37.2 →
    /// 33.3–34.7 ms, the torus 31.9–34.0 → 32.0–33.2, one thread, five rounds taking turns).
    ///
    /// # Safety
    /// Every one of `corners` is below [`DegenerateFaces::n_positions`].
    #[inline(always)]
    pub(crate) unsafe fn check_in_range(
        &mut self,
        table: &FaceTable<'_>,
        f: usize,
        corners: &[u32],
    ) {
        let positions = self.positions;
        // SAFETY: as the caller promises.
        let position = |v: u32| unsafe { *positions.get_unchecked(v as usize) };
        self.record(table, f, area_test(corners, position));
    }

    /// The number of positions the faces' vertices index.
    pub(crate) fn n_positions(&self) -> usize {
        self.positions.len()
    }

    /// Takes the test of table face `f` into the findings.
    #[inline(always)]
    fn record(&mut self, table: &FaceTable<'_>, f: usize, (degenerate, squared_size): (bool, f64)) {
        self.squared_sizes += squared_size;
        if degenerate {
            self.faces.push(table.input_face(f));
        }
    }

    /// The degenerate faces of all of `table`. Triangle and quad tables are tested a block of
    /// faces at a time (see [`DegenerateFaces::check_uniform`]).
    pub(crate) fn of_table(table: &FaceTable<'_>, positions: &'p [[f64; 3]]) -> Self {
        let mut found = DegenerateFaces::new(positions);
        match table.uniform_size() {
            Some(3) => found.check_uniform(table, |[a, b, c]| {
                (
                    is_clearly_not_degenerate_triangle(a, b, c),
                    triangle_squared_size(a, b, c),
                )
            }),
            Some(4) => found.check_uniform(table, |[a, b, c, d]| {
                (
                    !is_degenerate_quad(a, b, c, d),
                    quad_squared_perimeter(a, b, c, d),
                )
            }),
            _ => {
                for (f, corners) in table.faces().enumerate() {
                    found.check(table, f, corners);
                }
            }
        }
        found
    }

    /// Checks every face of `table`, all of which have `N` corners. A block of faces has its
    /// positions gathered coordinate by coordinate, so `clearly_not_degenerate` (branch-free,
    /// giving its verdict and the face's squared size) runs on all of them in vector registers;
    /// only blocks where it clears some face not are checked face by face. (A pass over the
    /// 1M-triangle torus: 4.0 ms, against 5.4 face by face.)
    fn check_uniform<const N: usize>(
        &mut self,
        table: &FaceTable<'_>,
        clearly_not_degenerate: impl Fn([[f64; 3]; N]) -> (bool, f64),
    ) {
        const BLOCK: usize = 8;
        let blocks = table.corners().chunks_exact(N * BLOCK);
        let n_blocked = blocks.len() * BLOCK;
        let mut squared_sizes = [0.0; BLOCK];
        for (b, block) in blocks.enumerate() {
            // coordinates[k][j][i]: coordinate k of corner j of the block's face i.
            let mut coordinates = [[[0.0; BLOCK]; N]; 3];
            for (i, face) in block.chunks_exact(N).enumerate() {
                for (j, &v) in face.iter().enumerate() {
                    let point = self.positions[v as usize];
                    for k in 0..3 {
                        coordinates[k][j][i] = point[k];
                    }
                }
            }
            let mut cleared = [false; BLOCK];
            for i in 0..BLOCK {
                let (clear, squared_size) = clearly_not_degenerate(std::array::from_fn(|j| {
                    std::array::from_fn(|k| coordinates[k][j][i])
                }));
                cleared[i] = clear;
                squared_sizes[i] += squared_size;
            }
            if cleared.contains(&false) {
                for (i, face) in block.chunks_exact(N).enumerate() {
                    if !cleared[i] && area_test(face, |v| self.positions[v as usize]).0 {
                        self.faces.push(table.input_face(b * BLOCK + i));
                    }
                }
            }
        }
        self.squared_sizes += squared_sizes.iter().sum::<f64>();
        let rest = table.corners()[n_blocked * N..].chunks_exact(N);
        for (i, face) in rest.enumerate() {
            self.check(table, n_blocked + i, face);
        }
    }

    /// Are the coordinates of every corner checked so far finite? (Only `true` is sure: squared
    /// sizes that overflow give `false` too.)
    pub(crate) fn corners_finite(&self) -> bool {
        self.squared_sizes.is_finite()
    }

    /// The faces found.
    pub(crate) fn into_faces(self) -> Vec<u32> {
        self.faces
    }
}

/// Whether the face with corners `face` has negligible area (see
/// [`crate::geom::is_degenerate_polygon`]; non-finite positions are not degenerate but
/// non-finite, reported apart), and the squared size it was judged against; triangles and quads
/// unrolled. `position(v)` is vertex `v`'s position.
#[inline(always)]
fn area_test(face: &[u32], position: impl Fn(u32) -> [f64; 3]) -> (bool, f64) {
    match *face {
        [a, b, c] => {
            let [a, b, c] = [a, b, c].map(position);
            (
                is_degenerate_triangle(a, b, c),
                triangle_squared_size(a, b, c),
            )
        }
        [a, b, c, d] => {
            let [a, b, c, d] = [a, b, c, d].map(position);
            (
                is_degenerate_quad(a, b, c, d),
                quad_squared_perimeter(a, b, c, d),
            )
        }
        ref face => polygon_area_test(face.iter().map(|&v| position(v))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::FaceList;

    /// Block by block or face by face, the same faces are found: triangles and quads, flat,
    /// collapsed, needles and slivers at rounding level, in blocks and in the rest after them.
    #[test]
    fn blocks_find_the_faces_found_one_by_one() {
        let mut positions = Vec::new();
        for i in 0..60 {
            let x = f64::from(i);
            positions.push([x, 0.0, 0.0]);
            positions.push([x, 1.0, 0.5 * x]);
        }
        positions[21] = positions[20];
        positions[33] = [16.0, 1e-17, 0.0];
        positions[45] = [22.5, 0.0, 0.0];
        let (mut triangles, mut quads) = (Vec::new(), Vec::new());
        for i in 0..59u32 {
            let (a, b, c, d) = (2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1);
            triangles.extend([a, b, c, a, c, d, a, b, 2 * (i / 2)]);
            quads.extend([a, b, c, d, a, b, (2 * i + 4) % 120, 2 * (i / 2)]);
        }
        for (size, indices) in [(3, &triangles), (4, &quads)] {
            let sizes = vec![size; indices.len() / size as usize];
            let table = FaceTable::new(&FaceList::polygons(&positions, &sizes, indices)).unwrap();
            assert_eq!(table.uniform_size(), Some(size as usize));
            let mut one_by_one = DegenerateFaces::new(&positions);
            for (f, corners) in table.faces().enumerate() {
                one_by_one.check(&table, f, corners);
            }
            let one_by_one = one_by_one.into_faces();
            assert!(one_by_one.len() > 10, "{one_by_one:?}");
            assert!(one_by_one.len() < table.n_faces(), "{one_by_one:?}");
            assert_eq!(
                DegenerateFaces::of_table(&table, &positions).into_faces(),
                one_by_one
            );
        }
    }
}
