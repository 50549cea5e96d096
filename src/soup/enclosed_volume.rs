//! The volume the faces of a closed component enclose. Orientation repairs flip a component when
//! its volume is negative, so the volume of the flipped component must be exactly the negation
//! of the volume before: otherwise a second run could flip it back. Each face is therefore read
//! the same way whichever of its corners comes first and whichever way it runs, and its fan
//! triangles are summed in that reading; only the sign follows the face's direction.

use super::FaceTable;

/// The volume a component's faces enclose, positive when they run counter-clockwise seen from
/// outside.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct EnclosedVolume {
    /// The volume, which may overflow to infinity or underflow to zero at extreme coordinates.
    pub(crate) volume: f64,
    /// Its sign, -1, 0 or 1, right whatever the coordinates' magnitude.
    pub(crate) sign: f64,
}

/// The volume enclosed by the faces of each component `c < n_components` for which `wanted(c)`
/// holds (zero for the others), `component[f]` being face `f`'s: the sum of the tetrahedra from
/// a corner of the component to each triangle of its faces' fans. The sum is taken relative to
/// that corner and scaled by the component's extent, so that neither cancellation far from the
/// origin nor under- or overflow at extreme coordinates decides its sign. Reversing every face
/// of a component negates its volume exactly.
pub(crate) fn component_volumes(
    table: &FaceTable<'_>,
    component: &[usize],
    n_components: usize,
    wanted: impl Fn(usize) -> bool,
    position: impl Fn(u32) -> [f64; 3],
) -> Vec<EnclosedVolume> {
    let n_faces = table.n_faces();
    let readings: Vec<Option<Reading>> = (0..n_faces)
        .map(|f| {
            if wanted(component[f]) {
                Reading::of(table.face(f))
            } else {
                None
            }
        })
        .collect();
    let mut origin = vec![[f64::NAN; 3]; n_components];
    let mut extent = vec![0.0f64; n_components];
    for f in (0..n_faces).filter(|&f| wanted(component[f])) {
        let c = component[f];
        let face = table.face(f);
        if origin[c][0].is_nan() {
            // The first face's first corner in its reading: the same whichever way it runs.
            let first = readings[f].map_or(face[0], |reading| reading.corner(face, 0));
            origin[c] = position(first);
        }
        for &v in face {
            let p = position(v);
            for k in 0..3 {
                extent[c] = extent[c].max((p[k] - origin[c][k]).abs());
            }
        }
    }
    let mut volume = vec![0.0f64; n_components];
    for (f, reading) in readings.iter().enumerate() {
        let (c, Some(reading)) = (component[f], reading) else {
            continue;
        };
        if extent[c] == 0.0 || !extent[c].is_finite() {
            continue;
        }
        let scaled = |v: u32| {
            let p = position(v);
            std::array::from_fn::<f64, 3, _>(|k| (p[k] - origin[c][k]) / extent[c])
        };
        let face = table.face(f);
        let apex = scaled(reading.corner(face, 0));
        let mut fan = 0.0;
        for j in 1..face.len() - 1 {
            let (b, c) = (reading.corner(face, j), reading.corner(face, j + 1));
            fan += determinant(apex, scaled(b), scaled(c));
        }
        volume[c] += if reading.reversed { -fan } else { fan };
    }
    volume
        .iter()
        .enumerate()
        .map(|(c, &scaled)| EnclosedVolume {
            volume: if scaled == 0.0 {
                0.0
            } else {
                scaled * extent[c] * extent[c] * extent[c] / 6.0
            },
            sign: if scaled == 0.0 { 0.0 } else { scaled.signum() },
        })
        .collect()
}

/// How a face is read for its volume: from the corner and in the direction that give the
/// smallest sequence of vertex ids among all its rotations, forward and reversed. Every rotation
/// and the reversal of a face read the same sequence.
#[derive(Clone, Copy, Debug)]
struct Reading {
    /// The position in the face of the corner read first.
    start: usize,
    /// Whether the face is read against its own direction.
    reversed: bool,
}

impl Reading {
    /// The reading of `face`, or `None` when the face reads the same both ways (it then runs
    /// along each of its edges both ways and encloses nothing).
    fn of(face: &[u32]) -> Option<Reading> {
        let n = face.len();
        if n < 3 {
            return None;
        }
        // Distinct neighbours around a single smallest id settle it without a search.
        let (smallest, _) = face.iter().enumerate().min_by_key(|&(_, &v)| v)?;
        let next = face[(smallest + 1) % n];
        let previous = face[(smallest + n - 1) % n];
        let unique = face.iter().filter(|&&v| v == face[smallest]).count() == 1;
        if unique && next != previous {
            return Some(Reading {
                start: smallest,
                reversed: previous < next,
            });
        }
        let forward = Reading {
            start: least_rotation(n, |i| face[i]),
            reversed: false,
        };
        let backward = Reading {
            start: n - 1 - least_rotation(n, |i| face[n - 1 - i]),
            reversed: true,
        };
        let order = (0..n)
            .map(|j| forward.corner(face, j).cmp(&backward.corner(face, j)))
            .find(|order| order.is_ne())?;
        Some(if order.is_lt() { forward } else { backward })
    }

    /// The `j`-th vertex of `face` in this reading.
    fn corner(self, face: &[u32], j: usize) -> u32 {
        let n = face.len();
        face[if self.reversed {
            (self.start + n - j % n) % n
        } else {
            (self.start + j) % n
        }]
    }
}

/// The start of the lexicographically smallest rotation of the sequence `s(0..n)`, in O(n)
/// (the two-candidate minimum-expression scan).
fn least_rotation(n: usize, s: impl Fn(usize) -> u32) -> usize {
    let (mut i, mut j, mut k) = (0, 1, 0);
    while i < n && j < n && k < n {
        let (a, b) = (s((i + k) % n), s((j + k) % n));
        if a == b {
            k += 1;
            continue;
        }
        if a > b {
            i += k + 1;
        } else {
            j += k + 1;
        }
        if i == j {
            j += 1;
        }
        k = 0;
    }
    i.min(j)
}

/// The determinant of the rows `a`, `b`, `c`: six times the signed volume of the tetrahedron
/// they span with the origin. Swapping `b` and `c` negates it exactly.
fn determinant(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every rotation of `face`, forward and reversed.
    fn rotations(face: &[u32]) -> Vec<Vec<u32>> {
        let mut all = Vec::new();
        for reversed in [false, true] {
            let mut turned = face.to_vec();
            if reversed {
                turned.reverse();
            }
            for _ in 0..face.len() {
                all.push(turned.clone());
                turned.rotate_left(1);
            }
        }
        all
    }

    fn read(face: &[u32]) -> Option<(Vec<u32>, bool)> {
        Reading::of(face).map(|r| {
            let ids = (0..face.len()).map(|j| r.corner(face, j)).collect();
            (ids, r.reversed)
        })
    }

    #[test]
    fn every_rotation_and_the_reversal_read_the_same_ids() {
        for face in [
            &[1, 2, 3, 0][..],
            &[5, 9, 7],
            &[0, 0, 1, 0, 2],
            &[3, 1, 3, 1, 2],
            &[4, 4, 5, 4, 6],
            &[2, 1, 2, 1, 0, 0],
        ] {
            let (ids, _) = read(face).unwrap();
            for (r, turned) in rotations(face).iter().enumerate() {
                let (turned_ids, turned_reversed) = read(turned).unwrap();
                assert_eq!(turned_ids, ids, "{face:?} as {turned:?}");
                // Rotations keep the direction; the second half are reversals.
                let original = read(face).unwrap().1;
                assert_eq!(turned_reversed, original ^ (r >= face.len()), "{turned:?}");
            }
        }
    }

    #[test]
    fn a_face_that_reads_the_same_both_ways_encloses_nothing() {
        assert!(Reading::of(&[0, 1, 0, 1]).is_none());
        assert!(Reading::of(&[7, 7, 7]).is_none());
        assert!(Reading::of(&[0, 1, 2, 1]).is_none());
        assert!(Reading::of(&[4, 4, 4, 5]).is_none());
        assert!(Reading::of(&[0, 1]).is_none());
    }

    #[test]
    fn the_least_rotation_starts_the_smallest_sequence() {
        let s = [3, 1, 2, 1, 2, 1, 1, 4];
        let k = least_rotation(s.len(), |i| s[i]);
        assert_eq!(k, 5);
        assert_eq!(least_rotation(4, |_| 9), 0);
    }
}
