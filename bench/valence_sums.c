/* See valence_sums.h. Compiled as C, as a C program using halfwing would be. */
#include "valence_sums.h"

size_t valence_sum_checked_circulator(const hw_mesh *mesh) {
  const size_t n_vertices = hw_mesh_n_vertex_slots(mesh);
  size_t sum = 0;
  uint32_t v;
  for (v = 0; v < n_vertices; ++v) {
    hw_vertex vertex = {v}, w;
    hw_circulator c;
    if (hw_circ_around_vertex(mesh, vertex, HW_CIRCULATOR_KIND_VERTICES, &c) != HW_OK)
      return (size_t)-1;
    while (hw_circ_next_vertex(&c, &w)) ++sum;
  }
  return sum;
}

size_t valence_sum_inline_circulator(const hw_mesh *mesh) {
  hw_nav nav;
  size_t sum = 0;
  uint32_t v;
  if (hw_mesh_nav(mesh, &nav) != HW_OK) return (size_t)-1;
  for (v = 0; v < nav.n_vertex_slots; ++v) {
    hw_vertex vertex = {v}, w;
    hw_nav_circ c = hw_nav_around_vertex(&nav, vertex);
    while (hw_nav_circ_next_vertex(&c, &w)) ++sum;
  }
  return sum;
}

size_t valence_sum_by_hand(const hw_mesh *mesh) {
  hw_nav nav;
  size_t sum = 0;
  uint32_t v;
  if (hw_mesh_nav(mesh, &nav) != HW_OK) return (size_t)-1;
  for (v = 0; v < nav.n_vertex_slots; ++v) {
    hw_vertex vertex = {v};
    const hw_halfedge start = hw_nav_vertex_halfedge(&nav, vertex);
    hw_halfedge h = start;
    if (start.idx == HW_INVALID_INDEX) continue;
    do {
      ++sum;
      h = hw_nav_twin(&nav, hw_nav_prev(&nav, h));
    } while (h.idx != start.idx);
  }
  return sum;
}
