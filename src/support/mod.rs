//! Building blocks that know nothing about meshes, shared by the kernels, the soup tools and the
//! Voronoi diagram: fallible allocation, sorting and ordering of ids, sets and disjoint sets of
//! ids, scans and walks over large arrays, and the wording of counts in messages.

pub(crate) mod allocation;
pub(crate) mod counted;
pub(crate) mod cycles;
pub(crate) mod disjoint_sets;
pub(crate) mod id_set;
pub(crate) mod ids;
pub(crate) mod index_maps;
pub(crate) mod large_arrays;
pub(crate) mod nested_dissection;
pub(crate) mod order;
pub(crate) mod prefetch;
pub(crate) mod radix_sort;
pub(crate) mod rare_hits;
pub(crate) mod sparse_cholesky;
#[cfg(test)]
pub(crate) mod test_random;
