/**
 * @file halfwing_nav.h
 * @brief Inline navigation over a half-edge mesh: steps that compile to array reads.
 *
 * halfwing.h includes this header; include halfwing.h. It is written by hand (halfwing.h is
 * generated) and holds only `static inline` functions over ::hw_nav, valid C99 and C++17.
 *
 * The checked navigation (hw_mesh_he_next(), hw_circ_around_vertex(), ...) validates the mesh
 * and every id on every call: the right tool for ids that come from outside. The inline
 * navigation validates once: hw_mesh_nav() fills an ::hw_nav, and the `hw_nav_*` functions then
 * read its arrays directly, so a loop over a whole mesh runs at the speed of hand-written array
 * code:
 * @code
 * hw_nav nav;
 * if (hw_mesh_nav(mesh, &nav) != HW_OK) return;
 * size_t sum = 0;
 * for (uint32_t v = 0; v < nav.n_vertex_slots; ++v) {
 *   hw_vertex vertex = {v};
 *   hw_nav_circ c = hw_nav_around_vertex(&nav, vertex);
 *   hw_vertex w;
 *   while (hw_nav_circ_next_vertex(&c, &w)) sum += 1;   // the valence of v
 * }
 * @endcode
 * or with the half-edges themselves, `next`/`prev`/`twin` by hand:
 * @code
 * hw_halfedge start = hw_nav_vertex_halfedge(&nav, vertex), h = start;
 * if (start.idx != HW_INVALID_INDEX)
 *   do { visit(h); h = hw_nav_twin(&nav, hw_nav_prev(&nav, h)); } while (h.idx != start.idx);
 * @endcode
 *
 * Validity. An ::hw_nav and every circulator started from it are valid until the next call that
 * modifies the mesh (any call taking a non-const `hw_mesh *`) or frees it; get a new one after.
 *
 * Trusted ids. The inline functions do not check their ids: an id must be below the slot count
 * of its kind (::hw_nav's `n_*_slots`) and name a live element (see "Deleted elements").
 * Anything else reads out of bounds or yields meaningless ids. Ids the mesh itself gave since
 * the last modification (from the views, a circulator, a visit) are safe.
 *
 * Orders, the same as the checked circulators (`hw_circ_*`) give:
 * - around a vertex: its outgoing half-edges counter-clockwise seen from outside, starting at
 *   its stored half-edge (hw_nav_vertex_halfedge()); one step is `twin(prev(h))`. Neighbours are
 *   the targets, faces the faces (the outside skipped), edges the edges, incoming half-edges the
 *   twins, all in that order. At a vertex where several fans meet (non-manifold) only the fan of
 *   its stored half-edge is visited.
 * - around a face: its half-edges counter-clockwise seen from outside, starting at
 *   hw_nav_face_halfedge(); one step is `next`. Corners are the origins, adjacent faces the faces
 *   of the twins (boundary sides skipped).
 * - along a loop: `next` from the given half-edge, all the way round (a face's sides, or a
 *   boundary loop, which runs clockwise seen from outside); read as around a face.
 *
 * Boundary vertices. A boundary vertex stores its boundary outgoing half-edge, so its walk
 * starts there and sees the fan whole: a boundary vertex with k neighbours has k outgoing
 * half-edges and k - 1 faces, the first neighbour and the last being its boundary neighbours.
 * hw_nav_is_boundary() tells a boundary half-edge (no face).
 *
 * Deleted elements (until hw_mesh_garbage_collect() removes them). A deleted or isolated vertex
 * stores no half-edge: its walk is empty (where hw_circ_around_vertex() refuses a deleted
 * vertex). The walk around a live vertex, face or loop meets live elements only. A deleted face
 * or half-edge keeps stale links: do not start a walk from one. Loops over every slot skip the
 * deleted ones with hw_nav_vertex_is_deleted(), hw_nav_edge_is_deleted(),
 * hw_nav_face_is_deleted().
 *
 * Walks trust the mesh's structure, which every halfwing call keeps sound; unlike the checked
 * circulators they are not bounded by the half-edge count.
 */
#ifndef HALFWING_NAV_H
#define HALFWING_NAV_H

#include "halfwing.h"

/** @addtogroup nav
 * @{
 */

/** The vertex half-edge `h` leaves. */
static inline hw_vertex hw_nav_origin(const hw_nav *nav, hw_halfedge h) {
  hw_vertex v;
  v.idx = nav->origin[h.idx];
  return v;
}

/** The vertex half-edge `h` points to (the origin of its twin). */
static inline hw_vertex hw_nav_target(const hw_nav *nav, hw_halfedge h) {
  hw_vertex v;
  v.idx = nav->origin[h.idx ^ 1u];
  return v;
}

/** The opposite half-edge of `h`'s edge (`h.idx ^ 1`; needs no array). */
static inline hw_halfedge hw_nav_twin(const hw_nav *nav, hw_halfedge h) {
  (void)nav;
  h.idx ^= 1u;
  return h;
}

/** The next half-edge around `h`'s face or boundary loop. */
static inline hw_halfedge hw_nav_next(const hw_nav *nav, hw_halfedge h) {
  h.idx = nav->next[h.idx];
  return h;
}

/** The previous half-edge around `h`'s face or boundary loop. */
static inline hw_halfedge hw_nav_prev(const hw_nav *nav, hw_halfedge h) {
  h.idx = nav->prev[h.idx];
  return h;
}

/** The face of `h` (invalid id on a boundary). */
static inline hw_face hw_nav_face(const hw_nav *nav, hw_halfedge h) {
  hw_face f;
  f.idx = nav->face[h.idx];
  return f;
}

/** The edge of `h` (`h.idx >> 1`; needs no array). */
static inline hw_edge hw_nav_edge(const hw_nav *nav, hw_halfedge h) {
  hw_edge e;
  (void)nav;
  e.idx = h.idx >> 1;
  return e;
}

/** `true` when `h` lies on a boundary (it has no face). */
static inline bool hw_nav_is_boundary(const hw_nav *nav, hw_halfedge h) {
  return nav->face[h.idx] == HW_INVALID_INDEX;
}

/** The outgoing half-edge `v` stores: the boundary one on a boundary; invalid id when `v` is
 * isolated or deleted. */
static inline hw_halfedge hw_nav_vertex_halfedge(const hw_nav *nav, hw_vertex v) {
  hw_halfedge h;
  h.idx = nav->vertex_halfedge[v.idx];
  return h;
}

/** The half-edge `f` stores (where its walk starts). Stale for a deleted face. */
static inline hw_halfedge hw_nav_face_halfedge(const hw_nav *nav, hw_face f) {
  hw_halfedge h;
  h.idx = nav->face_halfedge[f.idx];
  return h;
}

/** `true` when vertex slot `v` (below `n_vertex_slots`) holds a deleted vertex. */
static inline bool hw_nav_vertex_is_deleted(const hw_nav *nav, hw_vertex v) {
  return nav->vertex_deleted != NULL && nav->vertex_deleted[v.idx];
}

/** `true` when edge slot `e` (below `n_halfedge_slots / 2`) holds a deleted edge. */
static inline bool hw_nav_edge_is_deleted(const hw_nav *nav, hw_edge e) {
  return nav->edge_deleted != NULL && nav->edge_deleted[e.idx];
}

/** `true` when face slot `f` (below `n_face_slots`) holds a deleted face. */
static inline bool hw_nav_face_is_deleted(const hw_nav *nav, hw_face f) {
  return nav->face_deleted != NULL && nav->face_deleted[f.idx];
}

/**
 * An inline circulator, kept on the caller's stack: started by hw_nav_around_vertex(),
 * hw_nav_around_origin(), hw_nav_around_face() or hw_nav_along_loop() and read with any `hw_nav_circ_next_*`. Valid as
 * long as the ::hw_nav it came from. Treat the fields as private.
 */
typedef struct hw_nav_circ {
  /** `prev` around a vertex (then twinned), `next` around a face or along a loop. */
  const uint32_t *step;
  /** The mesh's origin of each half-edge (::hw_nav's `origin`). */
  const uint32_t *origin;
  /** The mesh's face of each half-edge (::hw_nav's `face`). */
  const uint32_t *face;
  /** 1 around a vertex (its half-edges leave the centre), 0 around a face or loop. */
  uint32_t flip;
  /** The half-edge the walk started at; reaching it again ends the walk. */
  uint32_t start;
  /** The half-edge yielded next, or the invalid id once the walk is over. */
  uint32_t current;
} hw_nav_circ;

/** A walk by `next` from live half-edge `h` back to it: a face's sides or a boundary loop. */
static inline hw_nav_circ hw_nav_along_loop(const hw_nav *nav, hw_halfedge h) {
  hw_nav_circ c;
  c.step = nav->next;
  c.origin = nav->origin;
  c.face = nav->face;
  c.flip = 0u;
  c.start = h.idx;
  c.current = h.idx;
  return c;
}

/** A walk around the origin of live half-edge `h`, counter-clockwise from `h` itself (an
 * invalid `h` gives an empty walk). */
static inline hw_nav_circ hw_nav_around_origin(const hw_nav *nav, hw_halfedge h) {
  hw_nav_circ c = hw_nav_along_loop(nav, h);
  c.step = nav->prev;
  c.flip = 1u;
  return c;
}

/** A walk around vertex `v` (see the orders above); empty for an isolated or deleted vertex. */
static inline hw_nav_circ hw_nav_around_vertex(const hw_nav *nav, hw_vertex v) {
  return hw_nav_around_origin(nav, hw_nav_vertex_halfedge(nav, v));
}

/** A walk around live face `f`. */
static inline hw_nav_circ hw_nav_around_face(const hw_nav *nav, hw_face f) {
  return hw_nav_along_loop(nav, hw_nav_face_halfedge(nav, f));
}

/** Next half-edge (outgoing around a vertex, a side around a face or loop): writes it through
 * `out` and returns true, or returns false when the walk is over. */
static inline bool hw_nav_circ_next_halfedge(hw_nav_circ *c, hw_halfedge *out) {
  const uint32_t h = c->current;
  uint32_t following;
  if (h == HW_INVALID_INDEX) return false;
  following = c->step[h] ^ c->flip;
  c->current = following == c->start ? HW_INVALID_INDEX : following;
  out->idx = h;
  return true;
}

/** Next incoming half-edge (the twin of the next half-edge; around a vertex: those arriving). */
static inline bool hw_nav_circ_next_incoming(hw_nav_circ *c, hw_halfedge *out) {
  hw_halfedge h;
  if (!hw_nav_circ_next_halfedge(c, &h)) return false;
  out->idx = h.idx ^ 1u;
  return true;
}

/** Next vertex: a neighbour around a vertex, a corner around a face or loop. */
static inline bool hw_nav_circ_next_vertex(hw_nav_circ *c, hw_vertex *out) {
  hw_halfedge h;
  if (!hw_nav_circ_next_halfedge(c, &h)) return false;
  out->idx = c->origin[h.idx ^ c->flip];
  return true;
}

/** Next edge: at a vertex, or a side of a face or loop. */
static inline bool hw_nav_circ_next_edge(hw_nav_circ *c, hw_edge *out) {
  hw_halfedge h;
  if (!hw_nav_circ_next_halfedge(c, &h)) return false;
  out->idx = h.idx >> 1;
  return true;
}

/** Next face: around a vertex (the outside skipped), or across a side of a face or loop
 * (boundary sides skipped). */
static inline bool hw_nav_circ_next_face(hw_nav_circ *c, hw_face *out) {
  hw_halfedge h;
  while (hw_nav_circ_next_halfedge(c, &h)) {
    const uint32_t f = c->face[h.idx ^ c->flip ^ 1u];
    if (f != HW_INVALID_INDEX) {
      out->idx = f;
      return true;
    }
  }
  return false;
}

/** @} */

#endif /* HALFWING_NAV_H */
