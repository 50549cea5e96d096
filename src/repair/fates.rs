//! What became of every input vertex and face through a sequence of repairs.

use crate::mesh::INVALID_INDEX;

/// What became of one input vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VertexFate {
    /// It is output vertex `.0`.
    Kept(u32),
    /// It was merged into output vertex `into` (its faces now name that vertex).
    Merged {
        /// The output vertex.
        into: u32,
    },
    /// It is not in the output.
    Removed(Removal),
}

/// What became of one input face.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaceFate {
    /// It is output face `face`; `reversed` when its corners run the other way round.
    Kept {
        /// The output face.
        face: u32,
        /// Whether it was reversed (to agree with its neighbours or to face outward).
        reversed: bool,
    },
    /// It is not in the output.
    Removed(Removal),
}

/// Why an element was removed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Removal {
    /// A face left with fewer than 3 distinct corners when its vertices were merged.
    Collapsed,
    /// A face with the same vertices as input face `of`, which was kept in its place.
    Duplicate {
        /// The input face kept in its place.
        of: u32,
    },
    /// A face the repairing build could not keep (see
    /// [`BuildPolicy::Repair`](crate::soup::BuildPolicy::Repair)), or a vertex with a NaN or
    /// infinite coordinate.
    Unbuildable,
    /// A triangle whose corners lie on one line (see
    /// [`remove_degenerate_faces`](super::remove_degenerate_faces)), removed or collapsed with
    /// its short edge; or a vertex merged away by such a collapse that nothing followed.
    Degenerate,
    /// In a component removed as small.
    SmallComponent,
    /// A vertex no kept face names.
    Unreferenced,
}

/// One element tracked through the steps: where it is now and whether it was merged.
#[derive(Clone, Copy, Debug)]
struct Tracked {
    /// Its id in the current structure (the id of the element it was merged into, when merged);
    /// `INVALID_INDEX` once removed.
    current: u32,
    merged: bool,
    reversed: bool,
    removal: Option<Removal>,
}

impl Tracked {
    fn at(current: u32) -> Self {
        Tracked {
            current,
            merged: false,
            reversed: false,
            removal: None,
        }
    }
}

/// The fates of the input elements and of the elements added on the way, updated step by step
/// from each step's old-to-new maps.
#[derive(Clone, Debug)]
pub(super) struct Ledger {
    n_input_vertices: usize,
    n_input_faces: usize,
    /// Input vertices, then added ones.
    vertices: Vec<Tracked>,
    /// The input vertex each added vertex copies (`INVALID_INDEX` for a new position).
    copies: Vec<u32>,
    /// Input faces, then added ones.
    faces: Vec<Tracked>,
}

impl Ledger {
    pub(super) fn new(n_vertices: usize, n_faces: usize) -> Self {
        Ledger {
            n_input_vertices: n_vertices,
            n_input_faces: n_faces,
            vertices: (0..n_vertices as u32).map(Tracked::at).collect(),
            copies: Vec::new(),
            faces: (0..n_faces as u32).map(Tracked::at).collect(),
        }
    }

    /// Applies a step's vertex map (old to new, `INVALID_INDEX` for gone): a gone vertex listed
    /// in `merged` (`[gone, kept]`, old ids) follows the vertex it went into, any other is
    /// removed for `why`.
    pub(super) fn map_vertices(&mut self, map: &[u32], merged: &[[u32; 2]], why: Removal) {
        let mut into = vec![INVALID_INDEX; map.len()];
        for &[gone, kept] in merged {
            into[gone as usize] = kept;
        }
        for t in self.vertices.iter_mut().filter(|t| t.removal.is_none()) {
            let old = t.current as usize;
            let new = map[old];
            if new != INVALID_INDEX {
                t.current = new;
            } else if into[old] != INVALID_INDEX {
                t.merged = true;
                t.current = map[into[old] as usize];
            } else {
                t.current = INVALID_INDEX;
                t.removal = Some(why);
            }
        }
    }

    /// Applies a step's report: its vertex and face maps, merged vertices following the vertex
    /// they went into, other gone elements removed for `why`.
    pub(super) fn apply(&mut self, report: &super::RepairReport, why: Removal) {
        self.map_vertices(&report.maps.vertices, &report.merged_vertices, why);
        self.map_faces(&report.maps.faces, |_| why);
    }

    /// Applies a step's face map; gone faces are removed for `why(old id)`.
    pub(super) fn map_faces(&mut self, map: &[u32], why: impl Fn(u32) -> Removal) {
        for t in self.faces.iter_mut().filter(|t| t.removal.is_none()) {
            let new = map[t.current as usize];
            if new == INVALID_INDEX {
                t.removal = Some(why(t.current));
            }
            t.current = new;
        }
    }

    /// Removes the vertices now at the given ids, for `why`, leaving the ids of the others.
    pub(super) fn remove_vertices(&mut self, ids: &[u32], why: Removal) {
        let mut gone = vec![false; self.vertices.len() + ids.len()];
        for &v in ids {
            if let Some(slot) = gone.get_mut(v as usize) {
                *slot = true;
            }
        }
        for t in self.vertices.iter_mut().filter(|t| t.removal.is_none()) {
            if gone.get(t.current as usize).copied().unwrap_or(false) {
                t.removal = Some(why);
                t.current = INVALID_INDEX;
            }
        }
    }

    /// Records vertices added at ids `first..`, each copying the vertex now at its `sources`
    /// entry.
    pub(super) fn add_vertices(&mut self, first: u32, sources: &[u32]) {
        let mut input_at = vec![INVALID_INDEX; first as usize];
        for (i, t) in self.vertices.iter().enumerate() {
            if t.removal.is_none() && !t.merged && (t.current as usize) < input_at.len() {
                input_at[t.current as usize] = self.input_of(i);
            }
        }
        for (k, &source) in sources.iter().enumerate() {
            let input = input_at
                .get(source as usize)
                .copied()
                .unwrap_or(INVALID_INDEX);
            self.vertices.push(Tracked::at(first + k as u32));
            self.copies.push(input);
        }
    }

    /// Records faces added at the given ids.
    pub(super) fn add_faces(&mut self, ids: &[u32]) {
        self.faces.extend(ids.iter().map(|&f| Tracked::at(f)));
    }

    /// The output ids of the added faces that are in the output, sorted.
    pub(super) fn added_faces(&self) -> Vec<u32> {
        let mut added: Vec<u32> = self.faces[self.n_input_faces..]
            .iter()
            .filter(|t| t.removal.is_none())
            .map(|t| t.current)
            .collect();
        added.sort_unstable();
        added
    }

    /// Flips the orientation of the faces now at the given ids.
    pub(super) fn reverse_faces(&mut self, ids: &[u32]) {
        let mut flip = vec![false; self.faces.len()];
        for &f in ids {
            if let Some(slot) = flip.get_mut(f as usize) {
                *slot = true;
            }
        }
        for t in self.faces.iter_mut().filter(|t| t.removal.is_none()) {
            if flip.get(t.current as usize).copied().unwrap_or(false) {
                t.reversed = !t.reversed;
            }
        }
    }

    /// The input face now at each id (`INVALID_INDEX` for an added face), for `n_faces` ids.
    pub(super) fn input_faces(&self, n_faces: usize) -> Vec<u32> {
        let mut input = vec![INVALID_INDEX; n_faces];
        for (i, t) in self.faces[..self.n_input_faces].iter().enumerate() {
            if t.removal.is_none() && (t.current as usize) < n_faces {
                input[t.current as usize] = i as u32;
            }
        }
        input
    }

    /// The input vertex a tracked vertex is, or copies.
    fn input_of(&self, tracked: usize) -> u32 {
        if tracked < self.n_input_vertices {
            tracked as u32
        } else {
            self.copies[tracked - self.n_input_vertices]
        }
    }

    pub(super) fn vertex_fates(&self) -> Vec<VertexFate> {
        self.vertices[..self.n_input_vertices]
            .iter()
            .map(|t| match (t.removal, t.merged) {
                (Some(why), _) => VertexFate::Removed(why),
                (None, true) => VertexFate::Merged { into: t.current },
                (None, false) => VertexFate::Kept(t.current),
            })
            .collect()
    }

    pub(super) fn face_fates(&self) -> Vec<FaceFate> {
        self.faces[..self.n_input_faces]
            .iter()
            .map(|t| match t.removal {
                Some(why) => FaceFate::Removed(why),
                None => FaceFate::Kept {
                    face: t.current,
                    reversed: t.reversed,
                },
            })
            .collect()
    }

    /// Pairs `[output vertex, input vertex it copies]` of the added vertices that are in the
    /// output, by output id.
    pub(super) fn added_vertices(&self) -> Vec<[u32; 2]> {
        let mut added: Vec<[u32; 2]> = self.vertices[self.n_input_vertices..]
            .iter()
            .zip(&self.copies)
            .filter(|(t, _)| t.removal.is_none() && !t.merged)
            .map(|(t, &source)| [t.current, source])
            .collect();
        added.sort_unstable();
        added
    }
}
