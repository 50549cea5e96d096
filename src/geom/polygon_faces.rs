//! The polygon mesh the normal passes read: positions, live faces, each face's corners in loop
//! order and the faces at a vertex. Both kernels give it (the half-edge mesh beside its normals,
//! the winged structure beside its own), so one set of passes computes their normals, with the
//! same arithmetic over the same corners.

/// A polygon mesh as the normal passes read it. Faces and vertices are numbered by slot; a
/// face's corners run in loop order (counter-clockwise seen from outside) from its first corner,
/// the one its stored half-edge or edge leaves, so two kernels holding the same faces give the
/// same corners in the same order, and so the same normals bit for bit.
pub(crate) trait PolygonFaces: Sync {
    /// The vertex positions, indexed by vertex slot.
    fn positions(&self) -> &[[f64; 3]];

    /// Number of face slots (live and deleted).
    fn face_slot_count(&self) -> usize;

    /// Whether face slot `f` holds a live face.
    fn is_live_face(&self, f: u32) -> bool;

    /// The live faces, in increasing id order.
    fn live_faces(&self) -> impl Iterator<Item = u32> + '_;

    /// The corner vertices of live face `f`, in loop order from its first corner (none for a
    /// face without edges).
    fn corners(&self, f: u32) -> impl Iterator<Item = u32> + Clone + '_;

    /// The corners of live face `f` (as [`PolygonFaces::corners`] gives them) as a fixed-size
    /// list, when the kernel reads a triangle or a quad faster than it walks a face; by default
    /// never. Either way the same arithmetic follows.
    #[inline(always)]
    fn small_face(&self, _f: u32) -> SmallFace {
        SmallFace::Larger
    }

    /// The live faces with a corner at vertex `v`, in every fan of it (a non-manifold vertex
    /// has several), in any order, a face possibly more than once.
    fn faces_at(&self, v: u32) -> Vec<u32>;
}

/// The corner vertices of a triangle or a quad: these make up nearly every real mesh, and
/// fixed-size lists cost half the time of a walk through the face iterators (face normals of a
/// 1M-triangle grid: 8.6 against 18.4 ms).
pub(crate) enum SmallFace {
    Triangle([u32; 3]),
    Quad([u32; 4]),
    /// Five corners or more, or a face the kernel does not read this way: walk it.
    Larger,
}

impl SmallFace {
    /// The face whose half-edge is `h0` in a half-edge mesh's arrays (`next`, `prev`, `origin`
    /// indexed by half-edge), with its corners in loop order from `origin(h0)`; `Larger` too
    /// when `h0` or `next(h0)` is no half-edge, for the bounded walk to judge.
    #[inline(always)]
    pub(crate) fn of_halfedge(next: &[u32], prev: &[u32], origin: &[u32], h0: u32) -> SmallFace {
        // The last corner comes from `prev`, loaded beside `next(h0)` rather than after it:
        // a triangle's corners then wait on one load each, not on a chain of two.
        let (Some(&h1), Some(&last)) = (next.get(h0 as usize), prev.get(h0 as usize)) else {
            return SmallFace::Larger;
        };
        let Some(&h2) = next.get(h1 as usize) else {
            return SmallFace::Larger;
        };
        if h2 == last {
            SmallFace::Triangle(gather(origin, [h0, h1, last]))
        } else if next.get(h2 as usize) == Some(&last) {
            SmallFace::Quad(gather(origin, [h0, h1, h2, last]))
        } else {
            SmallFace::Larger
        }
    }
}

/// `array[i]` for each of `indices`. A plain loop rather than `indices.map(..)`, whose inner
/// `try_map` call LLVM leaves out of line once the caller grows (30 % more instructions for the
/// vertex normals when it did).
#[inline(always)]
pub(crate) fn gather<T: Copy + Default, const N: usize>(array: &[T], indices: [u32; N]) -> [T; N] {
    let mut gathered = [T::default(); N];
    for (slot, &i) in gathered.iter_mut().zip(&indices) {
        *slot = array[i as usize];
    }
    gathered
}
