/* Navigation, circulators, views and topology through the C API: the seed 000 half-edge table,
 * and the seed 004 loops written as the course notes write them, checked on real models against
 * what the indexed face list itself says. */
#include <stdlib.h>

#include "check.h"

/* ---- seed 000: the 7-vertex, 6-face half-edge table ("Half Edges") ---------------------------
 * Faces read off the table's next/origin columns (v1..v7 numbered 0..6 here):
 * f0 = e0 e1 e2 = v1 v3 v4, f1 = v1 v4 v2, f2 = v2 v4 v5, f3 = v3 v6 v4, f4 = v4 v6 v7,
 * f5 = v4 v7 v5; the boundary loop e18 e19 e20 e23 e22 e21 leaves v3 v1 v2 v5 v7 v6. */
static const double seed_positions[] = {1, 4, 0, 3, 4, 0, 0, 2, 0, 2, 2, 0,
                                        4, 2, 0, 1, 0, 0, 3, 0, 0};
static const uint32_t seed_sizes[] = {3, 3, 3, 3, 3, 3};
static const uint32_t seed_faces[] = {0, 2, 3, 0, 3, 1, 1, 3, 4, 2, 5, 3, 3, 5, 6, 3, 6, 4};
static const uint32_t seed_boundary[] = {2, 0, 1, 4, 6, 5};

/* Is `got` (n items) a rotation of `want`? */
static int same_cycle(const uint32_t *got, const uint32_t *want, size_t n) {
  size_t shift, i;
  for (shift = 0; shift < n; ++shift) {
    for (i = 0; i < n && got[(i + shift) % n] == want[i]; ++i) {
    }
    if (i == n) return 1;
  }
  return n == 0;
}

static void seed_half_edge_table(void) {
  hw_mesh *mesh = NULL;
  hw_halfedge loops[4], h, start;
  hw_circulator c;
  hw_vertex v;
  uint32_t cycle[8];
  size_t n = 0, needed = 0, f;
  CHECK(hw_mesh_from_indexed(seed_positions, 7, seed_sizes, 6, seed_faces, 18,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 7 && hw_mesh_n_faces(mesh) == 6);
  CHECK(hw_mesh_n_halfedges(mesh) == 24); /* 18 inside + 6 on the boundary, as in the table */
  CHECK(hw_mesh_check(mesh) == HW_OK);

  /* Every face loop is the face as given, up to its starting corner. */
  for (f = 0; f < 6; ++f) {
    hw_face face = {(uint32_t)f};
    n = 0;
    CHECK(hw_circ_around_face(mesh, face, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK);
    while (n < 8 && hw_circ_next_vertex(&c, &v)) cycle[n++] = v.idx;
    CHECK(n == 3 && same_cycle(cycle, seed_faces + 3 * f, 3));
  }

  /* One boundary loop of six half-edges, leaving v3 v1 v2 v5 v7 v6 in that cyclic order. */
  CHECK(hw_mesh_boundary_loops(mesh, loops, 4, &needed) == HW_OK);
  CHECK(needed == 1);
  start = h = loops[0];
  n = 0;
  do {
    CHECK(hw_mesh_he_is_boundary(mesh, h));
    CHECK(hw_mesh_he_face(mesh, h).idx == HW_INVALID_INDEX);
    if (n < 8) cycle[n] = hw_mesh_he_origin(mesh, h).idx;
    ++n;
    h = hw_mesh_he_next(mesh, h);
  } while (h.idx != start.idx && n < 50);
  CHECK(n == 6 && same_cycle(cycle, seed_boundary, 6));

  /* Twins, next/prev and edges, for every half-edge. */
  for (h.idx = 0; h.idx < 24; ++h.idx) {
    hw_halfedge t = hw_mesh_he_twin(mesh, h);
    CHECK(t.idx == (h.idx ^ 1u));
    CHECK(hw_mesh_he_origin(mesh, t).idx == hw_mesh_he_target(mesh, h).idx);
    CHECK(hw_mesh_he_prev(mesh, hw_mesh_he_next(mesh, h)).idx == h.idx);
    CHECK(hw_mesh_he_edge(mesh, h).idx == h.idx >> 1);
  }
  /* v4 (index 3) is the inner vertex of all six faces. */
  v.idx = 3;
  CHECK(hw_mesh_vertex_valence(mesh, v) == 6);
  CHECK(!hw_mesh_vertex_is_boundary(mesh, v));
  v.idx = 0;
  CHECK(hw_mesh_vertex_valence(mesh, v) == 3 && hw_mesh_vertex_is_boundary(mesh, v));
  hw_mesh_free(mesh);
}

/* ---- seed 004: the loops of the course notes, on real models ---------------------------------- */

/* "conta quanti lati ha una faccia" */
static uint32_t count_sides(const hw_mesh *mesh, hw_halfedge i) {
  hw_halfedge start = i;
  uint32_t sides = 0;
  do {
    sides++;
    i = hw_mesh_he_next(mesh, i);
  } while (i.idx != start.idx);
  return sides;
}

/* "scansione di vertici attorno ad un vertice": marks every vertex of the star of origin(i). */
static uint32_t mark_star(const hw_mesh *mesh, hw_halfedge i, unsigned char *marks) {
  hw_halfedge start = i;
  uint32_t count = 0;
  do {
    i = hw_mesh_he_twin(mesh, i);
    marks[hw_mesh_he_origin(mesh, i).idx] = 1;
    count++;
    i = hw_mesh_he_next(mesh, i);
  } while (i.idx != start.idx);
  return count;
}

/* "contare le facce adiacenti da una faccia" */
static uint32_t count_adjacent_faces(const hw_mesh *mesh, hw_halfedge i) {
  hw_halfedge start = i;
  uint32_t faces = 0;
  do {
    hw_halfedge j = hw_mesh_he_twin(mesh, i);
    if (hw_mesh_he_face(mesh, j).idx != HW_INVALID_INDEX) faces++;
    i = hw_mesh_he_next(mesh, i);
  } while (i.idx != start.idx);
  return faces;
}

static void seed_loops_on(const char *relative) {
  char path[1024];
  hw_soup *soup = NULL;
  hw_mesh *mesh = NULL;
  const double *xyz;
  const uint32_t *sizes, *corners;
  size_t n_vertices, n_faces, n_corners, f, v, corner = 0, boundary_halfedges = 0, loops = 0;
  size_t walked = 0, h;
  unsigned char *star, *truth;

  snprintf(path, sizeof path, "%s/%s", HALFWING_DATA_DIR, relative);
  CHECK(hw_soup_read(path, &soup) == HW_OK);
  CHECK(hw_soup_view(soup, &xyz, &n_vertices, &sizes, &n_faces, &corners, &n_corners) == HW_OK);
  CHECK(hw_mesh_from_indexed(xyz, n_vertices, sizes, n_faces, corners, n_corners,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  if (mesh == NULL) {
    fprintf(stderr, "  %s did not build\n", relative);
    hw_soup_free(soup);
    return;
  }
  star = (unsigned char *)calloc(n_vertices, 1);
  truth = (unsigned char *)calloc(n_vertices, 1);

  for (f = 0; f < n_faces; ++f) {
    hw_face face = {(uint32_t)f};
    hw_halfedge i = hw_mesh_face_halfedge(mesh, face);
    uint32_t adjacent = count_adjacent_faces(mesh, i), expected_adjacent = 0;
    hw_circulator c;
    hw_face g;
    CHECK(count_sides(mesh, i) == sizes[f]);
    CHECK(hw_mesh_face_degree(mesh, face) == sizes[f]);
    CHECK(hw_circ_around_face(mesh, face, HW_CIRCULATOR_KIND_FACES, &c) == HW_OK);
    while (hw_circ_next_face(&c, &g)) expected_adjacent++;
    CHECK(adjacent == expected_adjacent);
  }

  /* The star of every vertex is the set of vertices it shares a face side with. */
  for (v = 0; v < n_vertices; ++v) {
    hw_vertex vertex = {(uint32_t)v};
    hw_halfedge i = hw_mesh_vertex_halfedge(mesh, vertex);
    size_t k, mismatches = 0;
    if (i.idx == HW_INVALID_INDEX) continue; /* isolated */
    memset(star, 0, n_vertices);
    memset(truth, 0, n_vertices);
    CHECK(mark_star(mesh, i, star) == hw_mesh_vertex_valence(mesh, vertex));
    for (corner = 0, f = 0; f < n_faces; corner += sizes[f], ++f)
      for (k = 0; k < sizes[f]; ++k)
        if (corners[corner + k] == v) {
          truth[corners[corner + (k + 1) % sizes[f]]] = 1;
          truth[corners[corner + (k + sizes[f] - 1) % sizes[f]]] = 1;
        }
    for (k = 0; k < n_vertices; ++k) mismatches += star[k] != truth[k];
    CHECK(mismatches == 0);
  }

  /* "visita di un bordo": the loops cover every boundary half-edge exactly once. */
  for (h = 0; h < hw_mesh_n_halfedges(mesh); ++h) {
    hw_halfedge he = {(uint32_t)h};
    boundary_halfedges += hw_mesh_he_is_boundary(mesh, he);
  }
  CHECK(hw_mesh_n_boundary_loops(mesh, &loops) == HW_OK);
  if (loops > 0) {
    hw_halfedge *starts = (hw_halfedge *)malloc(loops * sizeof *starts);
    size_t l;
    CHECK(hw_mesh_boundary_loops(mesh, starts, loops, NULL) == HW_OK);
    for (l = 0; l < loops; ++l) {
      hw_circulator c;
      hw_halfedge he;
      CHECK(hw_circ_along_loop(mesh, starts[l], &c) == HW_OK);
      while (hw_circ_next_halfedge(&c, &he)) {
        CHECK(hw_mesh_he_is_boundary(mesh, he));
        walked++;
      }
    }
    free(starts);
  }
  CHECK(walked == boundary_halfedges);
  printf("  %s: V=%zu F=%zu boundary loops=%zu\n", relative, n_vertices, n_faces, loops);

  free(star);
  free(truth);
  hw_mesh_free(mesh);
  hw_soup_free(soup);
}

/* ---- views: a one-ring walk over the raw arrays equals the circulator's -------------------- */
static void views_walk_like_circulators(void) {
  char path[1024];
  hw_mesh *mesh = NULL;
  const uint32_t *prev, *vertex_halfedge;
  const double *xyz;
  size_t n_halfedges, n_vertices, n_positions, v, from_views = 0, from_circulators = 0;
  snprintf(path, sizeof path, "%s/meshes/open/cgal_elephant-with-holes.off", HALFWING_DATA_DIR);
  CHECK(hw_mesh_read(path, HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_view(mesh, HW_MESH_ARRAY_HALFEDGE_PREV, &prev, &n_halfedges) == HW_OK);
  CHECK(hw_mesh_view(mesh, HW_MESH_ARRAY_VERTEX_HALFEDGE, &vertex_halfedge, &n_vertices) == HW_OK);
  CHECK(hw_mesh_view_positions(mesh, &xyz, &n_positions) == HW_OK);
  CHECK(n_halfedges == hw_mesh_n_halfedges(mesh) && n_vertices == n_positions);
  for (v = 0; v < n_vertices; ++v) {
    uint32_t h = vertex_halfedge[v], start = h;
    hw_circulator c;
    hw_halfedge out;
    hw_vertex vertex = {(uint32_t)v};
    if (h != HW_INVALID_INDEX) do {
        from_views++;
        h = prev[h] ^ 1u;
      } while (h != start);
    CHECK(hw_circ_around_vertex(mesh, vertex, HW_CIRCULATOR_KIND_HALFEDGES, &c) == HW_OK);
    while (hw_circ_next_halfedge(&c, &out)) from_circulators++;
  }
  CHECK(from_views == from_circulators && from_views == n_halfedges);
  hw_mesh_free(mesh);
}

/* ---- bad arguments ------------------------------------------------------------------------- */
static void bad_arguments(void) {
  hw_mesh *mesh = NULL;
  hw_halfedge bad = {99}, invalid = {HW_INVALID_INDEX};
  hw_vertex v = {0}, bad_vertex = {7};
  hw_face bad_face = {6};
  hw_edge bad_edge = {12}, edge0 = {0};
  hw_face face0 = {0};
  hw_circulator c;
  hw_vertex out_vertex;
  hw_face out_face;
  const uint32_t *data = NULL;
  size_t len = 0, count = 0;
  double xyz[3];
  const double nan_xyz[3] = {0.0, 0.0, 0.0 / 0.0 * 0.0};
  CHECK(hw_mesh_from_indexed(seed_positions, 7, seed_sizes, 6, seed_faces, 18,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_he_next(mesh, bad).idx == HW_INVALID_INDEX);
  CHECK(last_error_contains("half-edge id 99 is out of range"));
  CHECK(hw_mesh_he_origin(mesh, invalid).idx == HW_INVALID_INDEX);
  CHECK(hw_mesh_he_twin(NULL, invalid).idx == HW_INVALID_INDEX);
  CHECK(last_error_contains("mesh"));
  CHECK(hw_mesh_vertex_halfedge(mesh, bad_vertex).idx == HW_INVALID_INDEX);
  CHECK(hw_mesh_face_halfedge(mesh, bad_face).idx == HW_INVALID_INDEX);
  CHECK(hw_mesh_edge_halfedge(mesh, bad_edge, 0).idx == HW_INVALID_INDEX);
  CHECK(hw_mesh_edge_halfedge(mesh, edge0, 2).idx == HW_INVALID_INDEX);
  CHECK(last_error_contains("side 2"));
  CHECK(!hw_mesh_he_is_boundary(mesh, bad) && !hw_mesh_vertex_is_boundary(mesh, bad_vertex));
  CHECK(hw_mesh_vertex_valence(mesh, bad_vertex) == 0 && hw_mesh_face_degree(mesh, bad_face) == 0);

  CHECK_STATUS(hw_circ_around_vertex(mesh, bad_vertex, HW_CIRCULATOR_KIND_VERTICES, &c),
               HW_ERR_INVALID_HANDLE, "vertex id 7");
  CHECK_STATUS(hw_circ_around_vertex(mesh, v, 77u, &c), HW_ERR_INVALID_INPUT, "kind 77");
  CHECK_STATUS(hw_circ_around_face(mesh, face0, HW_CIRCULATOR_KIND_INCOMING, &c),
               HW_ERR_INVALID_INPUT, "does not apply");
  CHECK_STATUS(hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_VERTICES, NULL),
               HW_ERR_NULL_ARGUMENT, "out");
  CHECK(hw_circ_around_vertex(mesh, v, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK);
  CHECK(!hw_circ_next_face(&c, &out_face)); /* wrong kind */
  CHECK(last_error_contains("read as kind"));
  CHECK(!hw_circ_next_vertex(NULL, &out_vertex));
  CHECK(!hw_circ_next_vertex(&c, NULL));
  /* A forged circulator state ends the walk instead of reading out of bounds. */
  c.current = 123456u;
  CHECK(!hw_circ_next_vertex(&c, &out_vertex));

  CHECK_STATUS(hw_mesh_view(mesh, 42u, &data, &len), HW_ERR_INVALID_INPUT, "array 42");
  CHECK_STATUS(hw_mesh_view(mesh, HW_MESH_ARRAY_HALFEDGE_NEXT, NULL, &len), HW_ERR_NULL_ARGUMENT,
               "out_data");
  CHECK_STATUS(hw_mesh_n_boundary_loops(NULL, &count), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_boundary_loops(mesh, NULL, 0, &count), HW_ERR_BUFFER_TOO_SMALL, "needed");
  CHECK(count == 1);
  CHECK_STATUS(hw_mesh_vertex_position(mesh, bad_vertex, xyz), HW_ERR_INVALID_HANDLE, "vertex");
  CHECK_STATUS(hw_mesh_set_vertex_position(mesh, v, nan_xyz), HW_ERR_INVALID_INPUT,
               "not finite");
  CHECK(hw_mesh_vertex_position(mesh, v, xyz) == HW_OK && xyz[0] == 1 && xyz[1] == 4);
  CHECK_STATUS(hw_mesh_check(NULL), HW_ERR_NULL_ARGUMENT, "mesh");
  hw_mesh_free(mesh);
}

/* NULL meshes, circulators and outputs of the circulator calls: refused, nothing written, the
 * circulator not advanced. */
static void circulator_bad_arguments(void) {
  hw_mesh *mesh = NULL;
  hw_face face0 = {0};
  hw_halfedge h0 = {0}, out_h = {4242};
  hw_edge out_e = {4242};
  hw_face out_f = {4242};
  hw_circulator c, before, by_edge, by_face, by_halfedge;
  CHECK(hw_mesh_from_indexed(seed_positions, 7, seed_sizes, 6, seed_faces, 18,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  memset(&c, 0xab, sizeof c);
  before = c;
  CHECK_STATUS(hw_circ_along_loop(NULL, h0, &c), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_circ_along_loop(mesh, h0, NULL), HW_ERR_NULL_ARGUMENT, "out");
  CHECK_STATUS(hw_circ_around_face(NULL, face0, HW_CIRCULATOR_KIND_VERTICES, &c),
               HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_circ_around_face(mesh, face0, HW_CIRCULATOR_KIND_VERTICES, NULL),
               HW_ERR_NULL_ARGUMENT, "out");
  CHECK(memcmp(&c, &before, sizeof c) == 0);

  CHECK(hw_circ_around_face(mesh, face0, HW_CIRCULATOR_KIND_EDGES, &by_edge) == HW_OK);
  CHECK(hw_circ_around_face(mesh, face0, HW_CIRCULATOR_KIND_FACES, &by_face) == HW_OK);
  CHECK(hw_circ_around_face(mesh, face0, HW_CIRCULATOR_KIND_HALFEDGES, &by_halfedge) == HW_OK);
  CHECK(!hw_circ_next_edge(NULL, &out_e) && last_error_contains("circulator"));
  CHECK(!hw_circ_next_face(NULL, &out_f) && last_error_contains("circulator"));
  CHECK(!hw_circ_next_halfedge(NULL, &out_h) && last_error_contains("circulator"));
  CHECK(out_e.idx == 4242 && out_f.idx == 4242 && out_h.idx == 4242);
  before = by_edge;
  CHECK(!hw_circ_next_edge(&by_edge, NULL) && last_error_contains("`out`"));
  CHECK(memcmp(&by_edge, &before, sizeof by_edge) == 0);
  before = by_face;
  CHECK(!hw_circ_next_face(&by_face, NULL) && last_error_contains("`out`"));
  CHECK(memcmp(&by_face, &before, sizeof by_face) == 0);
  before = by_halfedge;
  CHECK(!hw_circ_next_halfedge(&by_halfedge, NULL) && last_error_contains("`out`"));
  CHECK(memcmp(&by_halfedge, &before, sizeof by_halfedge) == 0);
  /* Still usable from the start: the refusals did not advance them. */
  CHECK(hw_circ_next_edge(&by_edge, &out_e) && out_e.idx != 4242);
  CHECK(hw_circ_next_halfedge(&by_halfedge, &out_h) && out_h.idx != 4242);
  hw_mesh_free(mesh);
}

/* NULL meshes, unknown kinds and short or NULL outputs of the whole-mesh queries. */
static void whole_mesh_query_bad_arguments(void) {
  hw_mesh *mesh = NULL;
  uint32_t components[8] = {77, 77, 77, 77, 77, 77, 77, 77};
  hw_halfedge loops[2] = {{4242}, {4242}};
  double normals[3 * 24];
  const double *xyz = NULL;
  size_t needed = 4242, count = 4242, face_needed = 4242, vertex_needed = 4242, corner_slots, i;
  CHECK(hw_mesh_from_indexed(seed_positions, 7, seed_sizes, 6, seed_faces, 18,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  memset(normals, 0, sizeof normals);
  CHECK_STATUS(hw_mesh_boundary_loops(NULL, loops, 2, &needed), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK(loops[0].idx == 4242 && needed == 4242);
  CHECK_STATUS(hw_mesh_n_components(NULL, &count), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_n_components(mesh, NULL), HW_ERR_NULL_ARGUMENT, "out_count");
  CHECK(count == 4242);
  CHECK_STATUS(hw_mesh_face_components(NULL, components, 8, &needed), HW_ERR_NULL_ARGUMENT,
               "mesh");
  CHECK(components[0] == 77 && needed == 4242);
  CHECK(hw_mesh_n_vertex_slots(NULL) == 0 && last_error_contains("mesh"));
  CHECK(hw_mesh_n_halfedge_slots(NULL) == 0 && hw_mesh_n_edge_slots(NULL) == 0 &&
        hw_mesh_n_face_slots(NULL) == 0 && last_error_contains("mesh"));
  CHECK_STATUS(hw_mesh_view_positions(NULL, &xyz, &count), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_view_positions(mesh, NULL, &count), HW_ERR_NULL_ARGUMENT, "out_xyz");
  CHECK_STATUS(hw_mesh_view_positions(mesh, &xyz, NULL), HW_ERR_NULL_ARGUMENT,
               "out_n_vertices");
  CHECK(xyz == NULL && count == 4242);

  CHECK_STATUS(hw_mesh_face_normals(NULL, normals, 6, &needed), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_normals(NULL, HW_NORMAL_WEIGHTING_UNIFORM, normals, 6, &face_needed,
                               normals + 18, 7, &vertex_needed),
               HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_normals(mesh, 5u, normals, 6, &face_needed, normals + 18, 7,
                               &vertex_needed),
               HW_ERR_INVALID_INPUT, "unknown normal weighting 5");
  CHECK(needed == 4242 && face_needed == 4242 && vertex_needed == 4242);
  /* Too small: the needed sizes come back, the arrays stay untouched. */
  CHECK_STATUS(hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_UNIFORM, normals, 6, &face_needed,
                               normals + 18, 6, &vertex_needed),
               HW_ERR_BUFFER_TOO_SMALL, "7 are needed");
  CHECK(face_needed == 6 && vertex_needed == 7);
  corner_slots = hw_mesh_n_halfedge_slots(mesh);
  CHECK(corner_slots == 24);
  CHECK_STATUS(hw_mesh_corner_normals(mesh, 0.5, normals, corner_slots - 1, &needed),
               HW_ERR_BUFFER_TOO_SMALL, "24 are needed");
  CHECK(needed == corner_slots);
  for (i = 0; i < 3 * 24; ++i) CHECK(normals[i] == 0);
  hw_mesh_free(mesh);
}

static void bad_files(void) {
  hw_soup *soup = NULL;
  hw_mesh *mesh = NULL;
  char path[1024];
  CHECK_STATUS(hw_soup_read(NULL, &soup), HW_ERR_NULL_ARGUMENT, "path");
  CHECK_STATUS(hw_soup_read("/nonexistent/file.off", &soup), HW_ERR_IO,
               "cannot open '/nonexistent/file.off'");
  CHECK_STATUS(hw_soup_read("model.xyz", &soup), HW_ERR_INVALID_INPUT, "xyz");
  snprintf(path, sizeof path, "%s/meshes/broken/tobj_invalid_index.obj", HALFWING_DATA_DIR);
  CHECK_STATUS(hw_mesh_read(path, HW_BUILD_POLICY_STRICT, &mesh, NULL), HW_ERR_PARSE, "line 12");
  CHECK(soup == NULL && mesh == NULL);
  hw_soup_free(NULL);

  /* NULL for each pointer of the file calls; a bad policy; a soup freed twice. */
  snprintf(path, sizeof path, "%s/meshes/closed/lapy_torus.off", HALFWING_DATA_DIR);
  CHECK_STATUS(hw_soup_read(path, NULL), HW_ERR_NULL_ARGUMENT, "out_soup");
  CHECK_STATUS(hw_mesh_read(NULL, HW_BUILD_POLICY_STRICT, &mesh, NULL), HW_ERR_NULL_ARGUMENT,
               "path");
  CHECK_STATUS(hw_mesh_read(path, HW_BUILD_POLICY_STRICT, NULL, NULL), HW_ERR_NULL_ARGUMENT,
               "out_mesh");
  CHECK_STATUS(hw_mesh_read(path, 7u, &mesh, NULL), HW_ERR_INVALID_INPUT, "policy 7");
  CHECK(mesh == NULL);
  CHECK(hw_soup_read(path, &soup) == HW_OK);
  {
    const double *xyz = NULL;
    size_t n_vertices = 4242, n_faces = 0;
    CHECK_STATUS(hw_soup_view(NULL, &xyz, &n_vertices, NULL, NULL, NULL, NULL),
                 HW_ERR_NULL_ARGUMENT, "soup");
    CHECK(xyz == NULL && n_vertices == 4242);
    /* Every output is optional; a count alone is given without its array. */
    CHECK(hw_soup_view(soup, NULL, NULL, NULL, NULL, NULL, NULL) == HW_OK);
    CHECK(hw_soup_view(soup, NULL, &n_vertices, NULL, &n_faces, NULL, NULL) == HW_OK);
    CHECK(n_vertices > 0 && n_faces > 0);
  }
  hw_soup_free(soup);
  hw_soup_free(soup);
  CHECK(last_error_contains("already freed"));
}

int main(void) {
  seed_half_edge_table();
  seed_loops_on("meshes/closed/lapy_torus.off");
  seed_loops_on("meshes/closed/cgal_eight.off");
  seed_loops_on("meshes/open/cgal_elephant-with-holes.off");
  seed_loops_on("meshes/open/igl_beetle.off");
  seed_loops_on("meshes/polygonal/pmp_fandisk_quads.off");
  seed_loops_on("meshes/polygonal/cgal_double-torus-example.off");
  views_walk_like_circulators();
  bad_arguments();
  circulator_bad_arguments();
  whole_mesh_query_bad_arguments();
  bad_files();
  return check_summary("test_navigation");
}
