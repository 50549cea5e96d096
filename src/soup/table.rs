//! A face list checked and laid out for the builders: face offsets, corners, and the map back to
//! input face indices.

use std::borrow::Cow;
use std::ops::Range;

use super::{FaceList, FaceSizes, ListProblem};
use crate::support::order::mostly_nearby;
use crate::support::rare_hits::rare_hits_by_runs;

/// Largest number of corners a table may hold: every corner may need two half-edges and
/// half-edge ids must stay below `u32::MAX`.
pub const MAX_CORNERS: u64 = (u32::MAX as u64 - 1) / 2;

/// Largest number of vertices (ids must stay below `u32::MAX`).
pub const MAX_VERTICES: u64 = u32::MAX as u64 - 1;

/// Faces as ranges of one corner array, in the input's (counter-clockwise) order. Borrowed from
/// the input when nothing had to change; a uniform face size needs no offset array at all.
#[derive(Clone, Debug)]
pub struct FaceTable<'a> {
    layout: Layout,
    corners: Cow<'a, [u32]>,
    /// Table face → input face; `None` means the identity.
    input_faces: Option<Vec<u32>>,
}

/// Where each face's corners start.
#[derive(Clone, Debug)]
enum Layout {
    /// Face `f` has corners `f * size .. (f + 1) * size` (`size > 0`).
    Uniform { size: u32, n_faces: usize },
    /// Face `f` has corners `offsets[f]..offsets[f + 1]`.
    Offsets(Vec<u32>),
}

impl<'a> FaceTable<'a> {
    /// Lays out a face list, checking only list-level consistency and the 32-bit limits
    /// (face-level defects are found by [`FaceTable::face_defects`]).
    pub fn new(list: &FaceList<'a>) -> Result<Self, ListProblem> {
        let n_corners = list.indices.len() as u64;
        if n_corners > MAX_CORNERS {
            return Err(ListProblem::TooManyElements {
                what: "corners",
                count: n_corners,
            });
        }
        let layout = match list.sizes {
            FaceSizes::Uniform(size) => {
                if size == 0 || !n_corners.is_multiple_of(u64::from(size)) {
                    if n_corners == 0 {
                        Layout::Offsets(Vec::from([0]))
                    } else {
                        return Err(ListProblem::RaggedUniform {
                            size,
                            indices: n_corners,
                        });
                    }
                } else {
                    Layout::Uniform {
                        size,
                        n_faces: (n_corners / u64::from(size)) as usize,
                    }
                }
            }
            // Per-face sizes that are all equal (a triangle or quad mesh through the C API)
            // need no offset array either: face ranges become arithmetic.
            FaceSizes::PerFace(&[size, ref rest @ ..])
                if size > 0
                    && u64::from(size) * (rest.len() as u64 + 1) == n_corners
                    && all_equal_to(rest, size) =>
            {
                Layout::Uniform {
                    size,
                    n_faces: rest.len() + 1,
                }
            }
            FaceSizes::PerFace(sizes) => {
                // Refused before the offsets are allocated: 2^32 - 1 faces would take 16 GiB.
                if sizes.len() as u64 >= u64::from(u32::MAX) {
                    return Err(ListProblem::TooManyElements {
                        what: "faces",
                        count: sizes.len() as u64,
                    });
                }
                let mut offsets = Vec::with_capacity(sizes.len() + 1);
                let mut total: u64 = 0;
                offsets.push(0);
                for &size in sizes {
                    total += u64::from(size);
                    if total > n_corners {
                        return Err(ListProblem::CornerCountMismatch {
                            expected: sizes.iter().map(|&s| u64::from(s)).sum(),
                            actual: n_corners,
                        });
                    }
                    // n_corners < 2^31, so every offset fits in u32.
                    offsets.push(total as u32);
                }
                if total != n_corners {
                    return Err(ListProblem::CornerCountMismatch {
                        expected: total,
                        actual: n_corners,
                    });
                }
                Layout::Offsets(offsets)
            }
        };
        let table = FaceTable {
            layout,
            corners: Cow::Borrowed(list.indices),
            input_faces: None,
        };
        let n_faces = table.n_faces() as u64;
        if n_faces >= u64::from(u32::MAX) {
            return Err(ListProblem::TooManyElements {
                what: "faces",
                count: n_faces,
            });
        }
        Ok(table)
    }

    /// A table from owned parts. `offsets` starts at 0, ends at `corners.len()` and never
    /// decreases; `input_faces`, when given, has one entry per face.
    pub(crate) fn from_parts(
        offsets: Vec<u32>,
        corners: Vec<u32>,
        input_faces: Option<Vec<u32>>,
    ) -> Self {
        debug_assert_eq!(offsets.last().map(|&o| o as usize), Some(corners.len()));
        FaceTable {
            layout: Layout::Offsets(offsets),
            corners: Cow::Owned(corners),
            input_faces,
        }
    }

    /// Number of faces.
    #[inline]
    pub fn n_faces(&self) -> usize {
        match &self.layout {
            Layout::Uniform { n_faces, .. } => *n_faces,
            Layout::Offsets(offsets) => offsets.len() - 1,
        }
    }

    /// Number of corners (sum of face sizes).
    #[inline]
    pub fn n_corners(&self) -> usize {
        self.corners.len()
    }

    /// Vertex index of every corner.
    #[inline]
    pub fn corners(&self) -> &[u32] {
        &self.corners
    }

    /// The number of corners of every face, when all faces have the same.
    #[inline]
    pub(crate) fn uniform_size(&self) -> Option<usize> {
        match &self.layout {
            Layout::Uniform { size, .. } => Some(*size as usize),
            Layout::Offsets(_) => None,
        }
    }

    /// The corner range of face `f`.
    #[inline]
    pub fn face_range(&self, f: usize) -> Range<usize> {
        match &self.layout {
            Layout::Uniform { size, .. } => f * *size as usize..(f + 1) * *size as usize,
            Layout::Offsets(offsets) => offsets[f] as usize..offsets[f + 1] as usize,
        }
    }

    /// The vertex indices of face `f`.
    #[inline]
    pub fn face(&self, f: usize) -> &[u32] {
        &self.corners[self.face_range(f)]
    }

    /// Do consecutive faces mostly start near each other in vertex order (generated grids and
    /// tori, meshes written in a cache-friendly order)? Then a walk over the faces touches
    /// vertex data almost sequentially; otherwise (scanned models, whose vertex order is not the
    /// faces') nearly every corner waits on memory. Judged by [`mostly_nearby`] on the faces'
    /// first vertices: a pair of faces jumps when those are more than a few hundred ids apart
    /// (their vertex data no longer near in memory). Faces without corners count as jumps: the
    /// table need not be well formed.
    pub(crate) fn vertices_follow_faces(&self) -> bool {
        const NEARBY_VERTICES: u32 = 256;
        mostly_nearby(self.n_faces(), NEARBY_VERTICES, |f| {
            self.face(f).first().copied()
        })
    }

    /// The vertex indices of every face, in order: the builders' walks go through here, and a
    /// uniform face size walks the corner array in fixed steps (no offsets, no bounds checks).
    #[inline]
    pub fn faces(&self) -> Faces<'_> {
        self.faces_in(0..self.n_faces())
    }

    /// Calls `visit(f, corners)` for every face `f` in order, stopping at the first `None` (and
    /// giving it). Triangle and quad tables are walked as arrays of that size, so a `visit` that
    /// matches on the face's size (and is inlined: callers mark it `#[inline(always)]`, as it is
    /// compiled three times) is compiled for that size alone, with no per-face dispatch. For
    /// the bucket count and the build's walk, against [`FaceTable::faces`] (cold memory, one
    /// thread, best of 60 or 30 builds, four rounds taking turns): 1M-triangle torus
    /// 31.9-32.8 → 30.5-31.1 ms, 1M-quad torus 43.5-47.4 → 42.0-43.0 ms).
    #[inline(always)]
    pub(crate) fn try_for_each_face(
        &self,
        mut visit: impl FnMut(usize, &[u32]) -> Option<()>,
    ) -> Option<()> {
        /// `visit` over `corners` taken `N` at a time.
        #[inline(always)]
        fn in_steps<const N: usize>(
            corners: &[u32],
            mut visit: impl FnMut(usize, &[u32]) -> Option<()>,
        ) -> Option<()> {
            let faces = corners.as_chunks::<N>().0.iter();
            faces.enumerate().try_for_each(|(f, face)| visit(f, face))
        }
        match self.uniform_size() {
            Some(3) => in_steps::<3>(&self.corners, visit),
            Some(4) => in_steps::<4>(&self.corners, visit),
            _ => self
                .faces()
                .enumerate()
                .try_for_each(|(f, face)| visit(f, face)),
        }
    }

    /// The vertex indices of faces `range` (within `0..n_faces`), in order, as
    /// [`FaceTable::faces`].
    #[inline]
    pub fn faces_in(&self, range: Range<usize>) -> Faces<'_> {
        match &self.layout {
            Layout::Uniform { size, .. } => {
                let size = *size as usize;
                Faces::Uniform(
                    self.corners[range.start * size..range.end * size].chunks_exact(size),
                )
            }
            Layout::Offsets(offsets) => Faces::Offsets {
                corners: &self.corners,
                offsets: offsets[range.start..range.end + 1].windows(2),
            },
        }
    }

    /// The input face index of table face `f`.
    #[inline]
    pub fn input_face(&self, f: usize) -> u32 {
        match &self.input_faces {
            Some(map) => map[f],
            None => f as u32,
        }
    }

    /// The face holding corner `c < n_corners` (a division for uniform sizes, else a binary
    /// search: meant for the rare repair paths).
    pub fn face_of_corner(&self, c: usize) -> usize {
        match &self.layout {
            Layout::Uniform { size, .. } => c / *size as usize,
            Layout::Offsets(offsets) => offsets.partition_point(|&o| o as usize <= c) - 1,
        }
    }

    /// The corner after `c` in its face (cyclically).
    pub fn next_corner(&self, c: usize) -> usize {
        let range = self.face_range(self.face_of_corner(c));
        if c + 1 == range.end {
            range.start
        } else {
            c + 1
        }
    }

    /// Mutable corners (copies borrowed input first).
    pub(crate) fn corners_mut(&mut self) -> &mut [u32] {
        self.corners.to_mut()
    }

    /// The table face → input face map, materialised.
    pub fn input_faces(&self) -> Vec<u32> {
        (0..self.n_faces()).map(|f| self.input_face(f)).collect()
    }

    /// Calls `visit(face, corner, next_corner)` for every corner in face order, `next_corner`
    /// being the following corner of the same face (cyclically): corner `c`'s directed edge runs
    /// from `corners[c]` to `corners[next_corner]`.
    #[inline]
    pub fn for_each_corner_edge(&self, mut visit: impl FnMut(usize, usize, usize)) {
        // Triangle lists (the usual input) get a loop with the face size known at compile time:
        // every pairing pass runs through here.
        if let Layout::Uniform { size: 3, n_faces } = self.layout {
            for f in 0..n_faces {
                let first = 3 * f;
                visit(f, first, first + 1);
                visit(f, first + 1, first + 2);
                visit(f, first + 2, first);
            }
            return;
        }
        for f in 0..self.n_faces() {
            let range = self.face_range(f);
            if range.is_empty() {
                continue;
            }
            let last = range.end - 1;
            for c in range.start..last {
                visit(f, c, c + 1);
            }
            visit(f, last, range.start);
        }
    }

    /// The table without the faces where `keep` is `false` (indexed by table face).
    pub fn retain(&self, keep: &[bool]) -> FaceTable<'static> {
        let mut offsets = Vec::with_capacity(self.n_faces() + 1);
        let mut corners = Vec::with_capacity(self.n_corners());
        let mut input_faces = Vec::with_capacity(self.n_faces());
        offsets.push(0);
        for f in (0..self.n_faces()).filter(|&f| keep[f]) {
            corners.extend_from_slice(self.face(f));
            offsets.push(corners.len() as u32);
            input_faces.push(self.input_face(f));
        }
        FaceTable::from_parts(offsets, corners, Some(input_faces))
    }

    /// Finds face-level defects: faces with fewer than 3 corners, with an index `>= n_vertices`,
    /// or naming a vertex twice. Each list holds input face indices, ascending. Large tables are
    /// checked in parallel chunks (feature `parallel`).
    pub fn face_defects(&self, n_vertices: usize) -> FaceDefects {
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            const CHUNK: usize = 1 << 16;
            if self.n_faces() > CHUNK {
                let chunks: Vec<FaceDefects> = (0..self.n_faces().div_ceil(CHUNK))
                    .into_par_iter()
                    .map(|chunk| {
                        self.face_defects_in(
                            chunk * CHUNK..self.n_faces().min((chunk + 1) * CHUNK),
                            n_vertices,
                        )
                    })
                    .collect();
                let mut defects = FaceDefects::default();
                for chunk in chunks {
                    defects.too_small.extend(chunk.too_small);
                    defects.out_of_range.extend(chunk.out_of_range);
                    defects.repeated_vertex.extend(chunk.repeated_vertex);
                }
                return defects;
            }
        }
        self.face_defects_in(0..self.n_faces(), n_vertices)
    }

    fn face_defects_in(&self, faces: Range<usize>, n_vertices: usize) -> FaceDefects {
        let mut defects = FaceDefects::default();
        let mut scratch = Vec::new();
        for f in faces {
            let face = self.face(f);
            if is_well_formed(face, n_vertices, &mut scratch) {
                continue;
            }
            let input = self.input_face(f);
            if face.len() < 3 {
                defects.too_small.push(input);
            }
            if face.iter().any(|&v| v as usize >= n_vertices) {
                defects.out_of_range.push(input);
            }
            if has_repeated_vertex(face, &mut scratch) {
                defects.repeated_vertex.push(input);
            }
        }
        defects
    }
}

/// The faces of a table in order, as slices of its corner array (see [`FaceTable::faces`]).
pub enum Faces<'t> {
    /// Every face has the same size.
    Uniform(std::slice::ChunksExact<'t, u32>),
    /// Faces between consecutive offsets.
    Offsets {
        corners: &'t [u32],
        offsets: std::slice::Windows<'t, u32>,
    },
}

impl<'t> Iterator for Faces<'t> {
    type Item = &'t [u32];

    #[inline]
    fn next(&mut self) -> Option<&'t [u32]> {
        match self {
            Faces::Uniform(chunks) => chunks.next(),
            Faces::Offsets { corners, offsets } => offsets
                .next()
                .map(|range| &corners[range[0] as usize..range[1] as usize]),
        }
    }

    #[inline]
    fn size_hint(&self) -> (usize, Option<usize>) {
        match self {
            Faces::Uniform(chunks) => chunks.size_hint(),
            Faces::Offsets { offsets, .. } => offsets.size_hint(),
        }
    }
}

/// Face-level defects of a table, as input face indices.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FaceDefects {
    /// Faces with fewer than 3 corners.
    pub too_small: Vec<u32>,
    /// Faces with an index beyond the positions.
    pub out_of_range: Vec<u32>,
    /// Faces naming one vertex twice.
    pub repeated_vertex: Vec<u32>,
}

impl FaceDefects {
    /// `true` when no face has a defect.
    pub fn is_empty(&self) -> bool {
        self.too_small.is_empty() && self.out_of_range.is_empty() && self.repeated_vertex.is_empty()
    }
}

/// The directed edges of a face's loop, `(corner vertex, next corner vertex)`, last to first
/// included.
#[inline]
pub(crate) fn face_edges(face: &[u32]) -> impl Iterator<Item = (u32, u32)> + '_ {
    let following = face.iter().skip(1).chain(face.first());
    face.iter().copied().zip(following.copied())
}

/// `true` when `face` has at least 3 corners, all below `n_vertices` and all different (the
/// common triangles and quads decided without a loop).
#[inline]
pub(crate) fn is_well_formed(face: &[u32], n_vertices: usize, scratch: &mut Vec<u32>) -> bool {
    match *face {
        [a, b, c] => (a.max(b).max(c) as usize) < n_vertices && a != b && b != c && a != c,
        [a, b, c, d] => {
            (a.max(b).max(c).max(d) as usize) < n_vertices
                && a != b
                && a != c
                && a != d
                && b != c
                && b != d
                && c != d
        }
        _ => {
            face.len() >= 3
                && face.iter().all(|&v| (v as usize) < n_vertices)
                && !has_repeated_vertex(face, scratch)
        }
    }
}

/// Is every one of `sizes` equal to `size`? Tested a run at a time without branches, so the
/// test runs packed (size by size, stopping at the first other one, it took about 0.7 ms of a
/// 1M-quad torus build, by its profile; the build was about 1 ms faster so).
fn all_equal_to(sizes: &[u32], size: u32) -> bool {
    sizes
        .chunks(1024)
        .all(|run| run.iter().fold(0, |differ, &s| differ | (s ^ size)) == 0)
}

/// Quadratic scan for the small faces that dominate real meshes, a sort for big polygons.
pub(crate) fn has_repeated_vertex(face: &[u32], scratch: &mut Vec<u32>) -> bool {
    const QUADRATIC_LIMIT: usize = 12;
    if face.len() <= QUADRATIC_LIMIT {
        face.iter()
            .enumerate()
            .any(|(i, v)| face[i + 1..].contains(v))
    } else {
        scratch.clear();
        scratch.extend_from_slice(face);
        scratch.sort_unstable();
        scratch.windows(2).any(|w| w[0] == w[1])
    }
}

/// Vertices with a NaN or infinite coordinate, ascending.
pub fn non_finite_vertices(positions: &[[f64; 3]]) -> Vec<u32> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        const PART: usize = 1 << 16;
        if positions.len() > PART {
            return positions
                .par_chunks(PART)
                .enumerate()
                .flat_map_iter(|(i, part)| non_finite_in(i * PART, part))
                .collect();
        }
    }
    non_finite_in(0, positions)
}

/// [`non_finite_vertices`] of the vertices `first..` at `positions`, by runs
/// ([`rare_hits_by_runs`]): a run's coordinates are tested as one flat array of bits, which packs
/// into vector registers (the 1M-triangle torus's 500k vertices, warm, best of 10: 1.56 ms tested
/// point by point, 1.35 ms so).
fn non_finite_in(first: usize, positions: &[[f64; 3]]) -> Vec<u32> {
    // 1 for a non-finite coordinate, else 0: the masked exponent xor `EXPONENT` is 0 only then,
    // and only 0 wraps below zero (the others are below 2^63), setting the top bit.
    let non_finite_bit = |x: &f64| ((x.to_bits() & EXPONENT) ^ EXPONENT).wrapping_sub(1) >> 63;
    rare_hits_by_runs(
        positions,
        first,
        |run| {
            run.as_flattened()
                .iter()
                .fold(0, |any, x| any | non_finite_bit(x))
                != 0
        },
        is_non_finite,
    )
}

/// The vertices of `candidates` (ascending) with a NaN or infinite coordinate at `positions`:
/// [`non_finite_vertices`] for builders that know only those few vertices can have one.
pub(crate) fn non_finite_among(positions: &[[f64; 3]], candidates: &[u32]) -> Vec<u32> {
    (candidates.iter().copied())
        .filter(|&v| is_non_finite(&positions[v as usize]))
        .collect()
}

/// All exponent bits set in a coordinate: infinite or NaN.
const EXPONENT: u64 = 0x7ff0_0000_0000_0000;

/// Has `point` a NaN or infinite coordinate? (A test without branches, unlike `is_finite`'s.)
fn is_non_finite(point: &[f64; 3]) -> bool {
    point.iter().any(|x| x.to_bits() & EXPONENT == EXPONENT)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_follow_sizes() {
        let positions = [[0.0; 3]; 5];
        let sizes = [3, 4];
        let indices = [0, 1, 2, 0, 2, 3, 4];
        let table = FaceTable::new(&FaceList::polygons(&positions, &sizes, &indices)).unwrap();
        assert_eq!((table.face_range(0), table.face_range(1)), (0..3, 3..7));
        assert_eq!(table.face_of_corner(5), 1);
        let uniform = FaceTable::new(&FaceList::triangles(&positions, &indices[..6])).unwrap();
        assert_eq!(
            (
                uniform.n_faces(),
                uniform.face_range(1),
                uniform.face_of_corner(4)
            ),
            (2, 3..6, 1)
        );
        assert_eq!(table.face(1), &[0, 2, 3, 4]);
        let mut edges = Vec::new();
        table.for_each_corner_edge(|f, c, n| edges.push((f, c, n)));
        assert_eq!(edges[2], (0, 2, 0));
        assert_eq!(edges[6], (1, 6, 3));
    }

    #[test]
    fn list_level_problems_are_refused() {
        let positions = [[0.0; 3]; 3];
        let indices = [0, 1, 2, 0];
        let err = FaceTable::new(&FaceList::triangles(&positions, &indices)).unwrap_err();
        assert_eq!(
            err,
            ListProblem::RaggedUniform {
                size: 3,
                indices: 4
            }
        );
        let huge = [u32::MAX, u32::MAX, 7];
        let err = FaceTable::new(&FaceList::polygons(&positions, &huge, &indices)).unwrap_err();
        assert_eq!(
            err,
            ListProblem::CornerCountMismatch {
                expected: 2 * u64::from(u32::MAX) + 7,
                actual: 4
            }
        );
        let zero = FaceList {
            positions: &positions,
            sizes: FaceSizes::Uniform(0),
            indices: &indices,
        };
        assert!(FaceTable::new(&zero).is_err());
    }

    #[test]
    fn face_defects_are_found() {
        let sizes = [2, 3, 3, 13];
        let mut indices = vec![0, 1, 0, 1, 99, 0, 1, 0];
        indices.extend(0..12);
        indices.push(5);
        let positions = [[0.0; 3]; 12];
        let table = FaceTable::new(&FaceList::polygons(&positions, &sizes, &indices)).unwrap();
        let defects = table.face_defects(positions.len());
        assert_eq!(defects.too_small, vec![0]);
        assert_eq!(defects.out_of_range, vec![1]);
        assert_eq!(defects.repeated_vertex, vec![2, 3]);
    }

    #[test]
    fn defects_of_large_tables_come_back_in_order() {
        let n_faces = 150_000u32;
        let mut indices: Vec<u32> = (0..n_faces)
            .flat_map(|f| [0, f % 7 + 1, f % 7 + 2])
            .collect();
        for &bad in &[3u32, 65_536, 149_999] {
            indices[3 * bad as usize + 1] = 0;
        }
        let positions = vec![[0.0; 3]; 9];
        let table = FaceTable::new(&FaceList::triangles(&positions, &indices)).unwrap();
        let defects = table.face_defects(positions.len());
        assert_eq!(defects.repeated_vertex, vec![3, 65_536, 149_999]);
        assert!(defects.too_small.is_empty() && defects.out_of_range.is_empty());
    }

    #[test]
    fn non_finite_coordinates_are_found() {
        let positions = [[0.0; 3], [f64::NAN, 0.0, 0.0], [0.0, f64::INFINITY, 0.0]];
        assert_eq!(non_finite_vertices(&positions), vec![1, 2]);
        // Across runs and parallel parts, in order; huge and subnormal values are finite.
        let mut many = vec![[f64::MAX, -f64::MIN_POSITIVE * 0.5, 1.0]; 200_000];
        let bad: [u32; 7] = [0, 255, 256, 65_535, 65_536, 131_073, 199_999];
        for (k, &v) in bad.iter().enumerate() {
            many[v as usize][k % 3] = [f64::NAN, f64::NEG_INFINITY, f64::INFINITY][k % 3];
        }
        assert_eq!(non_finite_vertices(&many), bad);
    }
}
