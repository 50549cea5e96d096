//! Old-to-new id maps: what a compaction returns, so that ids held from before can be followed.

use super::ids::INVALID_INDEX;

/// Old-to-new id maps of a compaction or a renumbering repair: `vertices[old] = new`, with
/// `INVALID_INDEX` (`u32::MAX`) for an element that is gone; live elements keep their relative
/// order. [`Mesh::garbage_collect`](crate::mesh::Mesh::garbage_collect) and
/// [`Winged::garbage_collect`](crate::winged::Winged::garbage_collect) return one (a winged
/// structure has no half-edges: its half-edge map is empty), and so do the repairs.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct IndexMaps {
    /// Vertex map.
    pub vertices: Vec<u32>,
    /// Half-edge map (twins stay paired: `new(h ^ 1) = new(h) ^ 1`).
    pub halfedges: Vec<u32>,
    /// Edge map.
    pub edges: Vec<u32>,
    /// Face map.
    pub faces: Vec<u32>,
}

/// New index of every slot below `len`, `INVALID_INDEX` where `deleted` (slots past its end are
/// live); lengths below `u32::MAX` hold because the arrays were built with 32-bit ids.
pub(crate) fn compaction_map(len: usize, deleted: &[bool]) -> Vec<u32> {
    let mut next = 0u32;
    (0..len)
        .map(|i| {
            if deleted.get(i).copied().unwrap_or(false) {
                INVALID_INDEX
            } else {
                next += 1;
                next - 1
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn live_slots_are_numbered_in_order() {
        assert_eq!(
            compaction_map(5, &[false, true, false, true]),
            vec![0, INVALID_INDEX, 1, INVALID_INDEX, 2]
        );
        assert_eq!(compaction_map(2, &[]), vec![0, 1]);
    }
}
