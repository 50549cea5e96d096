/* The inline navigation of halfwing_nav.h (hw_mesh_nav() and the hw_nav_* functions): on real
 * models (closed, open with boundaries, polygonal) and after edits and a garbage collection,
 * every inline walk yields exactly the sequence the checked circulators (hw_circ_*) yield, and
 * every inline step agrees with the checked navigation (hw_mesh_he_*). */
#include <stdlib.h>

#include "check.h"

/* Two buffers of `capacity` ids: what the checked walk gave and what the inline one gave. */
typedef struct walks {
  uint32_t *checked, *inline_;
  size_t capacity;
} walks;

static walks walks_new(size_t capacity) {
  walks w;
  w.capacity = capacity + 1;
  w.checked = (uint32_t *)malloc(w.capacity * sizeof(uint32_t));
  w.inline_ = (uint32_t *)malloc(w.capacity * sizeof(uint32_t));
  return w;
}

static void walks_free(walks *w) {
  free(w->checked);
  free(w->inline_);
}

/* Reads a checked circulator of `kind` to its end. */
static size_t read_checked(hw_circulator *c, hw_circulator_kind kind, walks *w) {
  size_t n = 0;
  hw_halfedge h;
  hw_vertex v;
  hw_edge e;
  hw_face f;
  for (;;) {
    int more;
    uint32_t id;
    switch (kind) {
      case HW_CIRCULATOR_KIND_VERTICES:
        more = hw_circ_next_vertex(c, &v);
        id = v.idx;
        break;
      case HW_CIRCULATOR_KIND_EDGES:
        more = hw_circ_next_edge(c, &e);
        id = e.idx;
        break;
      case HW_CIRCULATOR_KIND_FACES:
        more = hw_circ_next_face(c, &f);
        id = f.idx;
        break;
      default: more = hw_circ_next_halfedge(c, &h); id = h.idx; break;
    }
    if (!more || n == w->capacity) return n;
    w->checked[n++] = id;
  }
}

/* Reads an inline circulator to its end, yielding what a checked one of `kind` yields. */
static size_t read_inline(hw_nav_circ c, hw_circulator_kind kind, walks *w) {
  size_t n = 0;
  hw_halfedge h;
  hw_vertex v;
  hw_edge e;
  hw_face f;
  for (;;) {
    int more;
    uint32_t id;
    switch (kind) {
      case HW_CIRCULATOR_KIND_INCOMING:
        more = hw_nav_circ_next_incoming(&c, &h);
        id = h.idx;
        break;
      case HW_CIRCULATOR_KIND_VERTICES:
        more = hw_nav_circ_next_vertex(&c, &v);
        id = v.idx;
        break;
      case HW_CIRCULATOR_KIND_EDGES:
        more = hw_nav_circ_next_edge(&c, &e);
        id = e.idx;
        break;
      case HW_CIRCULATOR_KIND_FACES:
        more = hw_nav_circ_next_face(&c, &f);
        id = f.idx;
        break;
      default: more = hw_nav_circ_next_halfedge(&c, &h); id = h.idx; break;
    }
    if (!more || n == w->capacity) return n;
    w->inline_[n++] = id;
  }
}

/* Both walks gave the same ids in the same order; counts the walks compared. */
static size_t walks_compared = 0;
static int same_walk(const walks *w, size_t n_checked, size_t n_inline) {
  size_t i;
  ++walks_compared;
  if (n_checked != n_inline) return 0;
  for (i = 0; i < n_checked; ++i)
    if (w->checked[i] != w->inline_[i]) return 0;
  return 1;
}

/* Every vertex: each kind of walk, the walk from each outgoing half-edge, and the hand-written
 * next/twin loop, against the checked circulators; deleted vertices walk nothing. */
static void vertices_walk_alike(const hw_mesh *mesh, const hw_nav *nav, walks *w) {
  uint32_t v;
  hw_circulator_kind kind;
  for (v = 0; v < nav->n_vertex_slots; ++v) {
    hw_vertex vertex = {v};
    hw_circulator c;
    size_t n_ring, i;
    if (hw_circ_around_vertex(mesh, vertex, HW_CIRCULATOR_KIND_HALFEDGES, &c) != HW_OK) {
      CHECK(hw_nav_vertex_is_deleted(nav, vertex));
      CHECK(read_inline(hw_nav_around_vertex(nav, vertex), HW_CIRCULATOR_KIND_HALFEDGES, w) == 0);
      continue;
    }
    CHECK(!hw_nav_vertex_is_deleted(nav, vertex));
    CHECK(hw_nav_vertex_halfedge(nav, vertex).idx == hw_mesh_vertex_halfedge(mesh, vertex).idx);
    for (kind = HW_CIRCULATOR_KIND_HALFEDGES; kind <= HW_CIRCULATOR_KIND_FACES; ++kind) {
      CHECK(hw_circ_around_vertex(mesh, vertex, kind, &c) == HW_OK);
      n_ring = read_checked(&c, kind, w);
      CHECK(same_walk(w, n_ring, read_inline(hw_nav_around_vertex(nav, vertex), kind, w)));
    }
    /* The next/twin loop of the textbooks, written by hand over the inline steps. */
    CHECK(hw_circ_around_vertex(mesh, vertex, HW_CIRCULATOR_KIND_HALFEDGES, &c) == HW_OK);
    n_ring = read_checked(&c, HW_CIRCULATOR_KIND_HALFEDGES, w);
    {
      hw_halfedge start = hw_nav_vertex_halfedge(nav, vertex), h = start;
      size_t n = 0;
      if (start.idx != HW_INVALID_INDEX) do {
          if (n < w->capacity) w->inline_[n] = h.idx;
          ++n;
          h = hw_nav_twin(nav, hw_nav_prev(nav, h));
        } while (h.idx != start.idx && n <= w->capacity);
      CHECK(same_walk(w, n_ring, n));
    }
    /* From each of its outgoing half-edges: the same ring, rotated to start there. */
    for (i = 0; i < n_ring; ++i) {
      hw_halfedge from = {w->checked[i]};
      size_t k, n = read_inline(hw_nav_around_origin(nav, from), HW_CIRCULATOR_KIND_HALFEDGES, w);
      int rotated = n == n_ring;
      for (k = 0; rotated && k < n; ++k) rotated = w->inline_[k] == w->checked[(i + k) % n_ring];
      CHECK(rotated);
    }
  }
}

/* Every face: each kind of walk against the checked circulators; deleted faces are marked. */
static void faces_walk_alike(const hw_mesh *mesh, const hw_nav *nav, walks *w) {
  uint32_t f;
  hw_circulator_kind kind;
  for (f = 0; f < nav->n_face_slots; ++f) {
    hw_face face = {f};
    hw_circulator c;
    if (hw_circ_around_face(mesh, face, HW_CIRCULATOR_KIND_HALFEDGES, &c) != HW_OK) {
      CHECK(hw_nav_face_is_deleted(nav, face));
      continue;
    }
    CHECK(!hw_nav_face_is_deleted(nav, face));
    CHECK(hw_nav_face_halfedge(nav, face).idx == hw_mesh_face_halfedge(mesh, face).idx);
    for (kind = HW_CIRCULATOR_KIND_HALFEDGES; kind <= HW_CIRCULATOR_KIND_FACES; ++kind) {
      if (kind == HW_CIRCULATOR_KIND_INCOMING) continue; /* a vertex-only kind */
      CHECK(hw_circ_around_face(mesh, face, kind, &c) == HW_OK);
      {
        size_t n = read_checked(&c, kind, w);
        CHECK(same_walk(w, n, read_inline(hw_nav_around_face(nav, face), kind, w)));
      }
    }
  }
}

/* Every live half-edge: each inline step against the checked one, and its loop. */
static void halfedges_step_alike(const hw_mesh *mesh, const hw_nav *nav, walks *w) {
  uint32_t i;
  for (i = 0; i < nav->n_halfedge_slots; ++i) {
    hw_halfedge h = {i};
    hw_edge e = hw_nav_edge(nav, h);
    hw_circulator c;
    if (hw_mesh_edge_halfedge(mesh, e, 0).idx == HW_INVALID_INDEX) {
      CHECK(hw_nav_edge_is_deleted(nav, e));
      continue;
    }
    CHECK(!hw_nav_edge_is_deleted(nav, e));
    CHECK(hw_nav_origin(nav, h).idx == hw_mesh_he_origin(mesh, h).idx);
    CHECK(hw_nav_target(nav, h).idx == hw_mesh_he_target(mesh, h).idx);
    CHECK(hw_nav_twin(nav, h).idx == hw_mesh_he_twin(mesh, h).idx);
    CHECK(hw_nav_next(nav, h).idx == hw_mesh_he_next(mesh, h).idx);
    CHECK(hw_nav_prev(nav, h).idx == hw_mesh_he_prev(mesh, h).idx);
    CHECK(hw_nav_face(nav, h).idx == hw_mesh_he_face(mesh, h).idx);
    CHECK(e.idx == hw_mesh_he_edge(mesh, h).idx);
    CHECK(hw_nav_is_boundary(nav, h) == hw_mesh_he_is_boundary(mesh, h));
    CHECK(hw_circ_along_loop(mesh, h, &c) == HW_OK);
    {
      size_t n = read_checked(&c, HW_CIRCULATOR_KIND_HALFEDGES, w);
      CHECK(
          same_walk(w, n, read_inline(hw_nav_along_loop(nav, h), HW_CIRCULATOR_KIND_HALFEDGES, w)));
    }
  }
}

/* The navigation view of `mesh` describes its slots, and every inline walk and step matches the
 * checked ones. Returns the number of boundary half-edges seen (to prove a model has some). */
static size_t inline_matches_checked(const hw_mesh *mesh) {
  hw_nav nav;
  walks w;
  size_t boundary = 0;
  uint32_t h;
  CHECK(hw_mesh_nav(mesh, &nav) == HW_OK);
  CHECK(nav.n_vertex_slots == hw_mesh_n_vertex_slots(mesh));
  CHECK(nav.n_halfedge_slots == hw_mesh_n_halfedge_slots(mesh));
  CHECK(nav.n_face_slots == hw_mesh_n_face_slots(mesh));
  w = walks_new(nav.n_halfedge_slots);
  vertices_walk_alike(mesh, &nav, &w);
  faces_walk_alike(mesh, &nav, &w);
  halfedges_step_alike(mesh, &nav, &w);
  for (h = 0; h < nav.n_halfedge_slots; ++h) {
    hw_halfedge half = {h};
    boundary += !hw_nav_edge_is_deleted(&nav, hw_nav_edge(&nav, half)) &&
                hw_nav_is_boundary(&nav, half);
  }
  walks_free(&w);
  return boundary;
}

static hw_mesh *read_model(const char *relative) {
  char path[1024];
  hw_mesh *mesh = NULL;
  snprintf(path, sizeof path, "%s/meshes/%s", HALFWING_DATA_DIR, relative);
  CHECK(hw_mesh_read(path, HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  return mesh;
}

static void real_models(void) {
  /* closed, open with holes, polygonal (quads and larger), and a polygonal one with boundary */
  static const char *const closed[] = {"closed/pmp_fandisk.off", "closed/lapy_torus.off"};
  static const char *const open[] = {"open/cgal_elephant-with-holes.off", "open/igl_beetle.off"};
  static const char *const polygonal[] = {"polygonal/igl_horse_quad.obj",
                                          "polygonal/gc_dodecahedron_poly.obj",
                                          "polygonal/igl_cylinder.obj"};
  size_t i;
  for (i = 0; i < sizeof closed / sizeof closed[0]; ++i) {
    hw_mesh *mesh = read_model(closed[i]);
    if (mesh) CHECK(inline_matches_checked(mesh) == 0);
    hw_mesh_free(mesh);
  }
  for (i = 0; i < sizeof open / sizeof open[0]; ++i) {
    hw_mesh *mesh = read_model(open[i]);
    if (mesh) CHECK(inline_matches_checked(mesh) > 0);
    hw_mesh_free(mesh);
  }
  for (i = 0; i < sizeof polygonal / sizeof polygonal[0]; ++i) {
    hw_mesh *mesh = read_model(polygonal[i]);
    if (mesh) inline_matches_checked(mesh);
    hw_mesh_free(mesh);
  }
}

/* Edits leave deleted slots behind: the walks around live elements still match, deleted
 * vertices walk nothing, the marks tell deleted slots; then the same after garbage collection. */
static void after_edits_and_garbage_collection(void) {
  hw_mesh *mesh = read_model("open/cgal_elephant-with-holes.off");
  hw_nav nav;
  uint32_t f, deleted_faces = 0, splits = 0, flips = 0, collapses = 0, n_faces;
  hw_vertex isolated;
  const double xyz[3] = {0.25, 0.5, 0.75};
  if (!mesh) return;
  n_faces = (uint32_t)hw_mesh_n_face_slots(mesh);
  /* Holes: every 37th face, dropping the vertices they isolate. */
  for (f = 0; f < n_faces; f += 37) {
    hw_face face = {f};
    deleted_faces += hw_mesh_delete_face(mesh, face, true) == HW_OK;
  }
  CHECK(deleted_faces > 10);
  /* Splits, flips and collapses spread over the mesh (each refused where it would break it). */
  for (f = 3; f < n_faces; f += 89) {
    hw_face face = {f};
    hw_halfedge h = hw_mesh_face_halfedge(mesh, face);
    if (h.idx != HW_INVALID_INDEX) flips += hw_mesh_flip_edge(mesh, hw_mesh_he_edge(mesh, h)) == HW_OK;
  }
  for (f = 5; f < n_faces; f += 101) {
    hw_face face = {f};
    hw_halfedge h = hw_mesh_face_halfedge(mesh, face);
    hw_vertex made;
    if (h.idx != HW_INVALID_INDEX)
      splits += hw_mesh_split_edge(mesh, hw_mesh_he_edge(mesh, h), xyz, &made) == HW_OK;
  }
  for (f = 11; f < n_faces; f += 173) {
    hw_face face = {f};
    hw_halfedge h = hw_mesh_face_halfedge(mesh, face);
    hw_vertex kept;
    if (h.idx != HW_INVALID_INDEX) collapses += hw_mesh_collapse_halfedge(mesh, h, &kept) == HW_OK;
  }
  printf("edits: %u faces deleted, %u splits, %u flips, %u collapses\n", deleted_faces, splits,
         flips, collapses);
  CHECK(splits > 10 && flips > 5 && collapses > 5);
  CHECK(hw_mesh_add_vertex(mesh, xyz, &isolated) == HW_OK);
  CHECK(hw_mesh_check(mesh) == HW_OK);

  CHECK(hw_mesh_nav(mesh, &nav) == HW_OK);
  CHECK(nav.vertex_deleted != NULL && nav.edge_deleted != NULL && nav.face_deleted != NULL);
  CHECK(hw_nav_vertex_halfedge(&nav, isolated).idx == HW_INVALID_INDEX);
  CHECK(!hw_nav_vertex_is_deleted(&nav, isolated));
  CHECK(inline_matches_checked(mesh) > 0);

  CHECK(hw_mesh_garbage_collect(mesh, NULL) == HW_OK);
  CHECK(hw_mesh_nav(mesh, &nav) == HW_OK);
  CHECK(nav.vertex_deleted == NULL && nav.edge_deleted == NULL && nav.face_deleted == NULL);
  CHECK(nav.n_vertex_slots == hw_mesh_n_vertices(mesh));
  CHECK(nav.n_face_slots == hw_mesh_n_faces(mesh));
  CHECK(inline_matches_checked(mesh) > 0);
  hw_mesh_free(mesh);
}

/* The course notes' loop: the valence sum over every vertex, by hand with the inline steps,
 * equals twice the edge count on a closed mesh. */
static void valence_sum_by_hand(void) {
  hw_mesh *mesh = read_model("closed/lapy_torus.off");
  hw_nav nav;
  size_t sum = 0;
  uint32_t v;
  if (!mesh) return;
  CHECK(hw_mesh_nav(mesh, &nav) == HW_OK);
  for (v = 0; v < nav.n_vertex_slots; ++v) {
    hw_vertex vertex = {v};
    hw_halfedge start = hw_nav_vertex_halfedge(&nav, vertex), h = start;
    if (start.idx == HW_INVALID_INDEX) continue;
    do {
      CHECK(hw_nav_origin(&nav, h).idx == v);
      ++sum;
      h = hw_nav_twin(&nav, hw_nav_prev(&nav, h));
    } while (h.idx != start.idx);
  }
  CHECK(sum == 2 * hw_mesh_n_edges(mesh));
  hw_mesh_free(mesh);
}

static void empty_mesh_and_bad_arguments(void) {
  hw_mesh *mesh = hw_mesh_new();
  hw_nav nav, untouched;
  CHECK(hw_mesh_nav(mesh, &nav) == HW_OK);
  CHECK(nav.n_vertex_slots == 0 && nav.n_halfedge_slots == 0 && nav.n_face_slots == 0);
  CHECK(nav.origin == NULL && nav.next == NULL && nav.prev == NULL && nav.face == NULL);
  CHECK(nav.vertex_halfedge == NULL && nav.face_halfedge == NULL);
  CHECK(nav.vertex_deleted == NULL && nav.edge_deleted == NULL && nav.face_deleted == NULL);
  memset(&untouched, 0xab, sizeof untouched);
  nav = untouched;
  CHECK_STATUS(hw_mesh_nav(NULL, &nav), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK(memcmp(&nav, &untouched, sizeof nav) == 0);
  CHECK_STATUS(hw_mesh_nav(mesh, NULL), HW_ERR_NULL_ARGUMENT, "out");
  hw_mesh_free(mesh);
}

int main(void) {
  real_models();
  after_edits_and_garbage_collection();
  valence_sum_by_hand();
  empty_mesh_and_bad_arguments();
  CHECK(walks_compared > 10000);
  return check_summary("test_nav");
}
