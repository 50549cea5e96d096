/* Callbacks through the C API: hw_mesh_visit over every live element of a kind, hw_circ_visit
 * over a circulator, both checked against what the counts, the circulators and a real model
 * say, and every bad argument. */
#include <stdlib.h>

#include "check.h"

/* The visitor's state: the ids seen, a stop after `limit` calls, and the mesh it reads. */
typedef struct {
  const hw_mesh *mesh;
  uint32_t *ids;
  size_t n, capacity, limit;
  size_t valence_sum;
  int increasing;
} seen_ids;

static bool record_id(uint32_t idx, void *userdata) {
  seen_ids *seen = (seen_ids *)userdata;
  if (seen->n > 0 && idx <= seen->ids[seen->n - 1]) seen->increasing = 0;
  if (seen->n < seen->capacity) seen->ids[seen->n] = idx;
  seen->n++;
  return seen->n < seen->limit;
}

/* Reads the mesh from inside the visit: the call holds nothing that forbids it. */
static bool add_valence(uint32_t idx, void *userdata) {
  seen_ids *seen = (seen_ids *)userdata;
  hw_vertex v = {idx};
  seen->valence_sum += hw_mesh_vertex_valence(seen->mesh, v);
  return record_id(idx, userdata);
}

static bool stop_at_once(uint32_t idx, void *userdata) {
  (void)idx;
  (void)userdata;
  return false;
}

static bool never_called(uint32_t idx, void *userdata) {
  (void)idx;
  *(int *)userdata = 1;
  return true;
}

static seen_ids fresh(const hw_mesh *mesh, uint32_t *ids, size_t capacity, size_t limit) {
  seen_ids seen;
  seen.mesh = mesh;
  seen.ids = ids;
  seen.n = 0;
  seen.capacity = capacity;
  seen.limit = limit;
  seen.valence_sum = 0;
  seen.increasing = 1;
  return seen;
}

/* Every kind on a real model: one call per live element, in increasing id order; a visitor that
 * reads the mesh (valences sum to twice the edge count); a visit stopped early. */
static void every_live_element(void) {
  hw_mesh *mesh = NULL;
  const size_t capacity = 1u << 20;
  uint32_t *ids = (uint32_t *)malloc(capacity * sizeof *ids);
  size_t visited = 0;
  seen_ids seen;
  hw_element_kind kinds[4] = {HW_ELEMENT_KIND_VERTEX, HW_ELEMENT_KIND_HALFEDGE,
                              HW_ELEMENT_KIND_EDGE, HW_ELEMENT_KIND_FACE};
  size_t n_slots[4];
  int k;
  CHECK(ids != NULL);
  CHECK(hw_mesh_read(HALFWING_DATA_DIR "/meshes/open/cgal_elephant-with-holes.off",
                     HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  if (mesh == NULL || ids == NULL) {
    free(ids);
    return;
  }
  n_slots[0] = hw_mesh_n_vertex_slots(mesh);
  n_slots[1] = hw_mesh_n_halfedge_slots(mesh);
  n_slots[2] = hw_mesh_n_edge_slots(mesh);
  n_slots[3] = hw_mesh_n_face_slots(mesh);
  for (k = 0; k < 4; ++k) {
    size_t expected = n_slots[k];
    seen = fresh(mesh, ids, capacity, (size_t)-1);
    CHECK(hw_mesh_visit(mesh, kinds[k], record_id, &seen, &visited) == HW_OK);
    CHECK(visited == expected && seen.n == expected && seen.increasing);
    CHECK(expected > 0 && ids[0] == 0 && ids[expected - 1] == expected - 1);
  }

  seen = fresh(mesh, ids, capacity, (size_t)-1);
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_VERTEX, add_valence, &seen, NULL) == HW_OK);
  CHECK(seen.n == hw_mesh_n_vertices(mesh));
  CHECK(seen.valence_sum == 2 * hw_mesh_n_edges(mesh));

  seen = fresh(mesh, ids, capacity, 3);
  visited = 0;
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_FACE, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == 3 && seen.n == 3 && ids[0] == 0 && ids[1] == 1 && ids[2] == 2);

  hw_mesh_free(mesh);
  free(ids);
}

/* Deleted elements are skipped, before and after garbage collection. */
static void deleted_elements_are_skipped(void) {
  /* Two triangles sharing the edge 1-2. */
  static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  static const uint32_t sizes[] = {3, 3};
  static const uint32_t corners[] = {0, 1, 2, 2, 1, 3};
  hw_mesh *mesh = NULL;
  hw_face first = {0};
  uint32_t ids[8];
  size_t visited = 0;
  seen_ids seen;
  CHECK(hw_mesh_from_indexed(positions, 4, sizes, 2, corners, 6, HW_BUILD_POLICY_STRICT, &mesh,
                             NULL) == HW_OK);
  CHECK(hw_mesh_delete_face(mesh, first, true) == HW_OK);
  seen = fresh(mesh, ids, 8, (size_t)-1);
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_FACE, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == 1 && ids[0] == 1);
  seen = fresh(mesh, ids, 8, (size_t)-1);
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_VERTEX, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == hw_mesh_n_vertices(mesh) && visited == 3 && seen.increasing);
  CHECK(ids[0] != 0 && ids[1] != 0 && ids[2] != 0); /* vertex 0 went with its only face */
  seen = fresh(mesh, ids, 8, (size_t)-1);
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_EDGE, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == hw_mesh_n_edges(mesh) && visited == 3);

  CHECK(hw_mesh_garbage_collect(mesh, NULL) == HW_OK);
  seen = fresh(mesh, ids, 8, (size_t)-1);
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_FACE, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == 1 && ids[0] == 0);
  hw_mesh_free(mesh);

  mesh = hw_mesh_new();
  visited = 7;
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_VERTEX, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == 0); /* an empty mesh makes no call */
  hw_mesh_free(mesh);
}

/* A circulator's visit yields what its hw_circ_next_* loop yields, and a stopped visit leaves the
 * circulator at the next element. */
static void circulator_visits(void) {
  hw_mesh *mesh = NULL;
  hw_circulator c;
  hw_vertex v = {0}, w;
  hw_face f;
  uint32_t by_loop[64], by_visit[64];
  size_t n_loop = 0, visited = 0;
  seen_ids seen;
  CHECK(hw_mesh_read(HALFWING_DATA_DIR "/meshes/closed/cgal_elephant.off", HW_BUILD_POLICY_STRICT,
                     &mesh, NULL) == HW_OK);
  if (mesh == NULL) return;
  CHECK(hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK);
  while (n_loop < 64 && hw_circ_next_vertex(&c, &w)) by_loop[n_loop++] = w.idx;
  CHECK(n_loop >= 3 && n_loop == hw_mesh_vertex_valence(mesh, v));

  CHECK(hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK);
  seen = fresh(mesh, by_visit, 64, (size_t)-1);
  CHECK(hw_circ_visit(&c, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == n_loop && memcmp(by_loop, by_visit, n_loop * sizeof *by_loop) == 0);
  CHECK(!hw_circ_next_vertex(&c, &w)); /* drained */

  CHECK(hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK);
  seen = fresh(mesh, by_visit, 64, 2);
  CHECK(hw_circ_visit(&c, record_id, &seen, &visited) == HW_OK);
  CHECK(visited == 2 && hw_circ_next_vertex(&c, &w) && w.idx == by_loop[2]);

  /* Faces around a face: a kind whose walk skips steps (none here: the model is closed). */
  f.idx = 0;
  CHECK(hw_circ_around_face(mesh, f, HW_CIRCULATOR_KIND_FACES, &c) == HW_OK);
  seen = fresh(mesh, by_visit, 64, (size_t)-1);
  CHECK(hw_circ_visit(&c, record_id, &seen, NULL) == HW_OK);
  CHECK(seen.n == hw_mesh_face_degree(mesh, f));
  hw_mesh_free(mesh);
}

/* Bad arguments: a status and a message naming the argument, no call made, output untouched. */
static void bad_arguments(void) {
  hw_mesh *mesh = NULL;
  hw_circulator c;
  hw_vertex v = {0};
  int called = 0;
  size_t visited = 42;
  static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  static const uint32_t sizes[] = {3};
  static const uint32_t corners[] = {0, 1, 2};
  CHECK(hw_mesh_from_indexed(positions, 3, sizes, 1, corners, 3, HW_BUILD_POLICY_STRICT, &mesh,
                             NULL) == HW_OK);

  CHECK_STATUS(hw_mesh_visit(NULL, HW_ELEMENT_KIND_FACE, never_called, &called, &visited),
               HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_visit(mesh, HW_ELEMENT_KIND_FACE, NULL, &called, &visited),
               HW_ERR_NULL_ARGUMENT, "visit");
  CHECK_STATUS(hw_mesh_visit(mesh, 99, never_called, &called, &visited), HW_ERR_INVALID_INPUT,
               "kind 99");
  CHECK(called == 0 && visited == 42);

  CHECK(hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_EDGES, &c) == HW_OK);
  CHECK_STATUS(hw_circ_visit(NULL, never_called, &called, &visited), HW_ERR_NULL_ARGUMENT,
               "circulator");
  CHECK_STATUS(hw_circ_visit(&c, NULL, &called, &visited), HW_ERR_NULL_ARGUMENT, "visit");
  CHECK(called == 0 && visited == 42);

  /* A NULL count is allowed, and userdata is the caller's business (NULL here). */
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_FACE, stop_at_once, NULL, NULL) == HW_OK);
  visited = 0;
  CHECK(hw_mesh_visit(mesh, HW_ELEMENT_KIND_VERTEX, stop_at_once, NULL, &visited) == HW_OK);
  CHECK(visited == 1);
  hw_mesh_free(mesh);
}

int main(void) {
  every_live_element();
  deleted_elements_are_skipped();
  circulator_visits();
  bad_arguments();
  return check_summary("test_visit");
}
