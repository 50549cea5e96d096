//! Disjoint sets of ids as a forest held in a `parent` array (a root is its own parent), with
//! path halving. Joins put the larger root under the smaller, so every parent is at most its
//! child and each set's root is its smallest id: an ascending pass can then number the sets in
//! place ([`number_sets`]), as the connected components and the Voronoi vertices do.
//!
//! `parent` may hold only the part of the forest for ids `first..first + parent.len()` (the
//! Voronoi vertices join runs of triangles in parallel, each in its own part); whole forests pass
//! `first = 0`.

/// The root of `x`'s set, halving the path on the way (each visited id skips to its
/// grandparent).
#[inline]
pub(crate) fn root(parent: &mut [u32], first: u32, mut x: u32) -> u32 {
    loop {
        let up = parent[(x - first) as usize];
        if up == x {
            return x;
        }
        let grandparent = parent[(up - first) as usize];
        parent[(x - first) as usize] = grandparent;
        x = grandparent;
    }
}

/// Joins the sets of `a` and `b` under the smaller of their roots.
#[inline]
pub(crate) fn join(parent: &mut [u32], first: u32, a: u32, b: u32) {
    let (ra, rb) = (root(parent, first, a), root(parent, first, b));
    if ra != rb {
        parent[(ra.max(rb) - first) as usize] = ra.min(rb);
    }
}

/// Turns a whole forest (ids `0..parent.len()`) into set numbers in place: roots are numbered
/// `0, 1, ...` in ascending order and every other id gets its root's number; returns the number
/// of sets. Relies on every parent being at most its child (as [`join`] keeps them), so an
/// ascending pass finds each parent already numbered. Ids for which `skipped` holds get
/// `u32::MAX` and no number; they must be roots of their own (never joined).
///
/// `visit(x, slot)` is called for each other id, `slot` being the number `x` gets if it is a root:
/// copying `x`'s data to `slot` compacts per-set data in place (`slot <= x`, and a non-root's copy
/// is overwritten by the next root's or falls beyond the count). Branch-free apart from `skipped`:
/// on grids roots and the rest alternate.
#[inline]
pub(crate) fn number_sets(
    parent: &mut [u32],
    skipped: impl Fn(usize) -> bool,
    mut visit: impl FnMut(usize, usize),
) -> usize {
    let mut count = 0;
    for x in 0..parent.len() {
        if skipped(x) {
            parent[x] = u32::MAX;
            continue;
        }
        let up = parent[x] as usize;
        let is_root = up == x;
        let parents_number = parent[up];
        visit(x, count);
        parent[x] = if is_root {
            count as u32
        } else {
            parents_number
        };
        count += usize::from(is_root);
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_are_the_smallest_ids_in_whole_and_partial_forests() {
        let mut whole: Vec<u32> = (0..6).collect();
        join(&mut whole, 0, 4, 2);
        join(&mut whole, 0, 5, 4);
        join(&mut whole, 0, 2, 2);
        assert_eq!(
            (0..6).map(|x| root(&mut whole, 0, x)).collect::<Vec<_>>(),
            [0, 1, 2, 3, 2, 2]
        );
        assert!(whole.iter().enumerate().all(|(x, &p)| p as usize <= x));
        // Ids 10..14 only.
        let mut part: Vec<u32> = (10..14).collect();
        join(&mut part, 10, 13, 11);
        join(&mut part, 10, 12, 13);
        assert_eq!(
            (10..14).map(|x| root(&mut part, 10, x)).collect::<Vec<_>>(),
            [10, 11, 11, 11]
        );
    }

    #[test]
    fn sets_are_numbered_by_their_smallest_id_and_per_set_data_compacts() {
        let mut parent: Vec<u32> = (0..7).collect();
        join(&mut parent, 0, 4, 1);
        join(&mut parent, 0, 6, 4);
        join(&mut parent, 0, 5, 2);
        let mut data = [10, 11, 12, 13, 14, 15, 16];
        let count = number_sets(&mut parent, |x| x == 3, |x, slot| data[slot] = data[x]);
        assert_eq!(count, 3);
        assert_eq!(parent, [0, 1, 2, u32::MAX, 1, 2, 1]);
        assert_eq!(data[..count], [10, 11, 12]);
    }
}
