//! Cutting a ring of corners `0..n` along diagonals into pieces, each a sub-ring in the same
//! cyclic order. Only a set of diagonals that do not cross (as chords of the ring) cuts a
//! polygon into pieces, so diagonals that cross one kept earlier, repeat one, or are sides of the
//! ring are left out: whatever the diagonals, every piece has at least 3 corners and the pieces
//! of an `n`-corner ring hold `n − 2` triangles between them. O(n + d log d) for `d` diagonals.

use std::ops::Range;

/// Scratch buffers and the result of [`Pieces::cut`].
#[derive(Debug, Default)]
pub(super) struct Pieces {
    /// The corners of every piece, piece after piece, each in increasing order (the ring's
    /// cyclic order, read from its lowest corner).
    pub(super) corners: Vec<u32>,
    /// Each piece's range in `corners`.
    pub(super) ranges: Vec<Range<usize>>,
    /// Kept diagonals as `(low, high)`, sorted by `low`, then by `high` decreasing.
    chords: Vec<(u32, u32)>,
    /// The pieces still open during the walk: their corners so far, and their last corner.
    open: Vec<(Vec<u32>, u32)>,
    spare: Vec<Vec<u32>>,
}

impl Pieces {
    /// Cuts the ring `0..n` (n ≥ 3) along `diagonals`, kept as described in the module docs.
    pub(super) fn cut(&mut self, n: u32, diagonals: &[(u32, u32)]) {
        self.keep_non_crossing(n, diagonals);
        self.corners.clear();
        self.ranges.clear();
        // Walk the corners in order. The innermost open piece takes each corner; a diagonal
        // (a, b) opens a piece at a that closes at b, where its parent takes b too.
        let root = self.spare.pop().unwrap_or_default();
        self.open.push((root, n - 1));
        let mut chord = 0;
        for corner in 0..n {
            self.innermost().push(corner);
            while self.open.len() > 1 && self.open.last().is_some_and(|p| p.1 == corner) {
                let (piece, _) = self.open.pop().expect("checked above");
                self.emit(piece);
                self.innermost().push(corner);
            }
            while let Some(&(low, high)) = self.chords.get(chord) {
                if low != corner {
                    break;
                }
                let mut piece = self.spare.pop().unwrap_or_default();
                piece.push(corner);
                self.open.push((piece, high));
                chord += 1;
            }
        }
        let (root, _) = self.open.pop().expect("the root piece");
        debug_assert!(self.open.is_empty());
        self.emit(root);
    }

    fn innermost(&mut self) -> &mut Vec<u32> {
        &mut self.open.last_mut().expect("the root piece is open").0
    }

    fn emit(&mut self, mut piece: Vec<u32>) {
        let start = self.corners.len();
        self.corners.extend_from_slice(&piece);
        self.ranges.push(start..self.corners.len());
        piece.clear();
        self.spare.push(piece);
    }

    /// Sorts the diagonals as chords `(low, high)` and keeps those that cross no chord kept
    /// before them and are neither sides of the ring nor repeats.
    fn keep_non_crossing(&mut self, n: u32, diagonals: &[(u32, u32)]) {
        self.chords.clear();
        self.chords.extend(
            diagonals
                .iter()
                .map(|&(a, b)| (a.min(b), a.max(b)))
                .filter(|&(low, high)| high < n && high - low >= 2 && !(low == 0 && high == n - 1)),
        );
        self.chords
            .sort_unstable_by(|a, b| a.0.cmp(&b.0).then(b.1.cmp(&a.1)));
        // The kept chords that contain the current one's low end, innermost last: a new chord
        // must end within the innermost one, or it crosses it.
        let mut containing: Vec<(u32, u32)> = Vec::new();
        self.chords.retain(|&(low, high)| {
            while containing.last().is_some_and(|&(_, end)| end <= low) {
                containing.pop();
            }
            let keep = match containing.last() {
                Some(&inner) => inner != (low, high) && high <= inner.1,
                None => true,
            };
            if keep {
                containing.push((low, high));
            }
            keep
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pieces_of(n: u32, diagonals: &[(u32, u32)]) -> Vec<Vec<u32>> {
        let mut pieces = Pieces::default();
        pieces.cut(n, diagonals);
        let mut out: Vec<Vec<u32>> = pieces
            .ranges
            .iter()
            .map(|r| pieces.corners[r.clone()].to_vec())
            .collect();
        out.sort();
        out
    }

    #[test]
    fn nested_and_side_by_side_diagonals_cut_pieces() {
        assert_eq!(
            pieces_of(8, &[(2, 6), (0, 2), (3, 6), (6, 0)]),
            vec![
                vec![0, 1, 2],
                vec![0, 2, 6],
                vec![0, 6, 7],
                vec![2, 3, 6],
                vec![3, 4, 5, 6]
            ]
        );
    }

    #[test]
    fn crossing_repeated_and_side_diagonals_are_left_out() {
        // (1, 4) crosses (0, 2), which comes first in sorted order and is kept; (3, 4) and
        // (5, 0) are sides, (2, 0) repeats (0, 2), and 9 is no corner.
        let pieces = pieces_of(6, &[(1, 4), (0, 2), (3, 4), (5, 0), (2, 0), (9, 1)]);
        assert_eq!(pieces, vec![vec![0, 1, 2], vec![0, 2, 3, 4, 5]]);
        let total: usize = pieces.iter().map(|p| p.len() - 2).sum();
        assert_eq!(total, 4);
    }
}
