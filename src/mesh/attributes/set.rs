//! The named columns of one element kind, and the four sets a mesh carries.

use super::column::Column;
use crate::mesh::ElementKind;

/// The columns of one element kind, in the order they were added.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct AttributeSet {
    pub(crate) columns: Vec<Column>,
}

impl AttributeSet {
    pub(crate) fn find(&self, name: &str) -> Option<&Column> {
        self.columns.iter().find(|c| c.name == name)
    }

    pub(crate) fn find_mut(&mut self, name: &str) -> Option<&mut Column> {
        self.columns.iter_mut().find(|c| c.name == name)
    }

    /// Applies `op` to every column (a no-op, and free, when there are none).
    pub(crate) fn each(&mut self, mut op: impl FnMut(&mut Column)) {
        self.columns.iter_mut().for_each(&mut op);
    }

    pub(crate) fn resize(&mut self, n_elements: usize) {
        self.each(|c| c.resize(n_elements));
    }

    pub(crate) fn copy(&mut self, from: usize, to: usize) {
        self.each(|c| c.copy(from, to));
    }

    pub(crate) fn blend(&mut self, a: usize, b: usize, t: f64, to: usize) {
        self.each(|c| c.blend(a, b, t, to));
    }

    pub(crate) fn reset(&mut self, i: usize) {
        self.each(|c| c.reset(i));
    }

    pub(crate) fn compact(&mut self, map: &[u32]) {
        self.each(|c| c.compact(map));
    }

    /// `true` when every column has `components` values for each of `n_elements` elements.
    pub(crate) fn fits(&self, n_elements: usize) -> bool {
        self.columns
            .iter()
            .all(|c| c.len() == n_elements * c.components)
    }
}

/// Every attribute of a mesh, by element kind. Corner attributes are half-edge columns: the
/// corner of vertex `v` in face `f` is the half-edge of `f` that leaves `v`.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Attributes {
    pub(crate) vertex: AttributeSet,
    pub(crate) halfedge: AttributeSet,
    pub(crate) edge: AttributeSet,
    pub(crate) face: AttributeSet,
}

impl Attributes {
    pub(crate) fn of(&self, kind: ElementKind) -> &AttributeSet {
        match kind {
            ElementKind::Vertex => &self.vertex,
            ElementKind::Halfedge => &self.halfedge,
            ElementKind::Edge => &self.edge,
            ElementKind::Face => &self.face,
        }
    }

    /// `true` when every column fits its kind's element count (`capacities` by kind: vertex,
    /// half-edge, edge, face).
    pub(crate) fn fit(&self, capacities: [usize; 4]) -> bool {
        [&self.vertex, &self.halfedge, &self.edge, &self.face]
            .iter()
            .zip(capacities)
            .all(|(set, n)| set.fits(n))
    }

    pub(crate) fn of_mut(&mut self, kind: ElementKind) -> &mut AttributeSet {
        match kind {
            ElementKind::Vertex => &mut self.vertex,
            ElementKind::Halfedge => &mut self.halfedge,
            ElementKind::Edge => &mut self.edge,
            ElementKind::Face => &mut self.face,
        }
    }
}
