//! Disjoint sets of ids as a forest held in a `parent` array (a root is its own parent), with
//! path halving. Joins put the larger root under the smaller, so every parent is at most its
//! child and each set's root is its smallest id: an ascending pass can then number the sets in
//! place, as the connected components and the Voronoi vertices do.
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
}
