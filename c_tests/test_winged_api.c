/* hw_winged through the C API: the seed 000 cube table, walks, normals, conversions, the Euler
 * operators building a cube and refusing bad operations, and every bad argument. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

/* Seed 000_505984156c1d03bf.txt, "Winged Edges": the cube. Faces F1..F6 (0-based vertices) start
 * at their ESTART edge; the seed's hand-made edge numbering is passed as the edge order. The seed
 * gives no coordinates; these put every face counter-clockwise seen from outside. */
static const double cube_positions[] = {0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0,
                                        0, 1, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1};
static const uint32_t cube_sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t cube_indices[] = {0, 1, 2, 3, 4, 5, 6, 7, 2, 7, 6, 3,
                                        0, 5, 4, 1, 0, 3, 6, 5, 4, 7, 2, 1};
static const uint32_t cube_edge_order[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6,
                                           6, 7, 7, 4, 0, 5, 4, 1, 2, 7, 6, 3};

/* The seed's Edge-Edge relation, as printed on the slide. */
static const char *const cube_edge_table =
    "EDGE,VSTART,VEND,EPCW,ENCW,EPCCW,ENCCW,FCW,FCCW\n"
    "E1,V1,V2,E4,E2,E10,E9,F1,F4\n"
    "E2,V2,V3,E1,E3,E11,E10,F1,F6\n"
    "E3,V3,V4,E2,E4,E12,E11,F1,F3\n"
    "E4,V4,V1,E3,E1,E9,E12,F1,F5\n"
    "E5,V5,V6,E8,E6,E9,E10,F2,F4\n"
    "E6,V6,V7,E5,E7,E12,E9,F2,F5\n"
    "E7,V7,V8,E6,E8,E11,E12,F2,F3\n"
    "E8,V8,V5,E7,E5,E10,E11,F2,F6\n"
    "E9,V1,V6,E1,E5,E6,E4,F4,F5\n"
    "E10,V5,V2,E5,E1,E2,E8,F4,F6\n"
    "E11,V3,V8,E3,E7,E8,E2,F3,F6\n"
    "E12,V7,V4,E7,E3,E4,E6,F3,F5\n";

/* The seed's Face-Edge table (FACE, ESTART) in CSV. */
static const char *const cube_face_table =
    "FACE,ESTART\nF1,E1\nF2,E5\nF3,E11\nF4,E9\nF5,E4\nF6,E8\n";

static hw_winged *seed_cube(void) {
  hw_winged *w = NULL;
  CHECK(hw_winged_from_indexed_ordered(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                       cube_edge_order, 12, &w) == HW_OK);
  return w;
}

/* The table as a heap string, through the size-query protocol. */
static char *table(const hw_winged *w, hw_wtable which, hw_wnaming naming,
                   hw_table_format format) {
  size_t needed = 0;
  char *text;
  CHECK(hw_winged_table(w, which, naming, format, NULL, 0, &needed) == HW_ERR_BUFFER_TOO_SMALL);
  CHECK(needed > 1);
  text = (char *)malloc(needed);
  CHECK(hw_winged_table(w, which, naming, format, text, needed, NULL) == HW_OK);
  return text;
}

static void seed_cube_tables(void) {
  hw_winged *w = seed_cube();
  char* edges = table(w, HW_WTABLE_EDGES, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_CSV);
  char* faces = table(w, HW_WTABLE_FACES, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_CSV);
  char* granada = table(w, HW_WTABLE_EDGES, HW_WNAMING_DIRECT_INVERSE, HW_TABLE_FORMAT_TEXT);
  char* all = table(w, HW_WTABLE_ALL, HW_WNAMING_LEFT_RIGHT, HW_TABLE_FORMAT_MARKDOWN);
  printf("%s", edges);
  CHECK(strcmp(edges, cube_edge_table) == 0);
  CHECK(strcmp(faces, cube_face_table) == 0);
  CHECK(strncmp(granada, "Id  Vi  Vf  Cd  Ci  Ada  Ads  Aia  Ais\n", 39) == 0);
  CHECK(strstr(all, "| vertex | x | y | z | edge |") != NULL);
  CHECK(strstr(all, "edge_right_ccw") != NULL);
  CHECK(hw_winged_n_vertices(w) == 8 && hw_winged_n_edges(w) == 12 && hw_winged_n_faces(w) == 6);
  CHECK(hw_winged_check(w) == HW_OK);
  free(edges);
  free(faces);
  free(granada);
  free(all);
  hw_winged_free(w);
}

static void records_and_views(void) {
  hw_winged *w = seed_cube();
  hw_wedge_record r;
  const hw_wedge_record *view = NULL;
  size_t n = 0;
  hw_wedge e8 = {8};
  /* E9 of the slide (id 8): V1 -> V6, EPCW E1, ENCW E5, EPCCW E6, ENCCW E4, FCW F4, FCCW F5. */
  CHECK(hw_winged_edge(w, e8, &r) == HW_OK);
  CHECK(r.start.idx == 0 && r.end.idx == 5);
  CHECK(r.left_prev.idx == 0 && r.left_next.idx == 4);
  CHECK(r.right_prev.idx == 5 && r.right_next.idx == 3);
  CHECK(r.left_face.idx == 3 && r.right_face.idx == 4);
  CHECK(hw_winged_edge_records(w, &view, &n) == HW_OK);
  CHECK(n == 12 && view != NULL && memcmp(&view[8], &r, sizeof r) == 0);
  {
    hw_wvertex v2 = {2};
    hw_wface f2 = {2};
    hw_wedge bad_edge = {12};
    double p[3];
    CHECK(hw_winged_vertex_edge(w, v2).idx == 2);
    CHECK(hw_winged_face_edge(w, f2).idx == 10);
    CHECK(hw_winged_vertex_position(w, v2, p) == HW_OK && p[0] == 1 && p[1] == 1 && p[2] == 0);
    CHECK(hw_winged_is_vertex(w, v2) && !hw_winged_is_edge(w, bad_edge) && hw_winged_is_face(w, f2));
    CHECK(hw_winged_n_vertex_slots(w) == 8 && hw_winged_n_edge_slots(w) == 12 &&
          hw_winged_n_face_slots(w) == 6);
  }
  hw_winged_free(w);
}

static void walks(void) {
  hw_winged *w = seed_cube();
  hw_wcirculator c;
  hw_wvertex v;
  hw_wedge e;
  hw_wface f;
  hw_wface f3 = {2};
  hw_wvertex v1 = {0};
  uint32_t got[8];
  size_t n = 0;
  /* F3 = V3 V8 V7 V4, from its ESTART E11 (V3 -> V8). */
  CHECK(hw_wcirc_around_face(w, f3, HW_WCIRCULATOR_KIND_VERTICES, &c) == HW_OK);
  while (hw_wcirc_next_vertex(&c, &v) && n < 8) got[n++] = v.idx;
  CHECK(n == 4 && got[0] == 2 && got[1] == 7 && got[2] == 6 && got[3] == 3);
  n = 0;
  CHECK(hw_wcirc_around_face(w, f3, HW_WCIRCULATOR_KIND_EDGES, &c) == HW_OK);
  while (hw_wcirc_next_edge(&c, &e) && n < 8) got[n++] = e.idx;
  CHECK(n == 4 && got[0] == 10 && got[1] == 6 && got[2] == 11 && got[3] == 2);
  n = 0;
  CHECK(hw_wcirc_around_face(w, f3, HW_WCIRCULATOR_KIND_FACES, &c) == HW_OK);
  while (hw_wcirc_next_face(&c, &f) && n < 8) got[n++] = f.idx;
  CHECK(n == 4); /* F3 touches the four side faces: F6, F2, F5, F1 */
  CHECK(got[0] == 5 && got[1] == 1 && got[2] == 4 && got[3] == 0);
  /* V1 has the three neighbours V2, V4, V6 and the three faces F1, F4, F5. */
  n = 0;
  CHECK(hw_wcirc_around_vertex(w, v1, HW_WCIRCULATOR_KIND_VERTICES, &c) == HW_OK);
  while (hw_wcirc_next_vertex(&c, &v) && n < 8) got[n++] = v.idx;
  CHECK(n == 3 && got[0] + got[1] + got[2] == 1 + 3 + 5);
  n = 0;
  CHECK(hw_wcirc_around_vertex(w, v1, HW_WCIRCULATOR_KIND_FACES, &c) == HW_OK);
  while (hw_wcirc_next_face(&c, &f) && n < 8) got[n++] = f.idx;
  CHECK(n == 3 && got[0] + got[1] + got[2] == 0 + 3 + 4);
  n = 0;
  CHECK(hw_wcirc_around_vertex(w, v1, HW_WCIRCULATOR_KIND_EDGES, &c) == HW_OK);
  while (hw_wcirc_next_edge(&c, &e) && n < 8) got[n++] = e.idx;
  CHECK(n == 3 && got[0] == 0); /* from its stored edge E1 */
  /* A finished walk stays finished. */
  CHECK(!hw_wcirc_next_edge(&c, &e));

  /* Bad arguments. */
  CHECK_STATUS(hw_wcirc_around_face(w, f3, 7, &c), HW_ERR_INVALID_INPUT, "kind 7");
  CHECK_STATUS(hw_wcirc_around_face(NULL, f3, HW_WCIRCULATOR_KIND_EDGES, &c), HW_ERR_NULL_ARGUMENT,
               "winged");
  CHECK_STATUS(hw_wcirc_around_face(w, f3, HW_WCIRCULATOR_KIND_EDGES, NULL), HW_ERR_NULL_ARGUMENT,
               "out");
  {
    hw_wface missing = {6};
    hw_wvertex nowhere = {HW_INVALID_INDEX};
    /* Messages name elements as C sees them ("face 6"), not as Rust debug output. */
    CHECK_STATUS(hw_wcirc_around_face(w, missing, HW_WCIRCULATOR_KIND_EDGES, &c),
                 HW_ERR_INVALID_HANDLE, "face 6 does not exist");
    CHECK_STATUS(hw_wcirc_around_vertex(w, nowhere, HW_WCIRCULATOR_KIND_EDGES, &c),
                 HW_ERR_INVALID_HANDLE, "vertex 4294967295 (the invalid id) does not exist");
  }
  CHECK(hw_wcirc_around_face(w, f3, HW_WCIRCULATOR_KIND_EDGES, &c) == HW_OK);
  CHECK(!hw_wcirc_next_vertex(&c, &v));
  CHECK(last_error_contains("read as kind"));
  CHECK(!hw_wcirc_next_edge(NULL, &e));
  CHECK(last_error_contains("circulator"));
  CHECK(!hw_wcirc_next_edge(&c, NULL));
  CHECK(last_error_contains("out"));
  hw_winged_free(w);
}

static int near(double a, double b) { return fabs(a - b) < 1e-12; }

static void normals(void) {
  hw_winged *w = seed_cube();
  hw_wface f1 = {0};
  hw_wvertex v1 = {0};
  double n[3];
  double all[18], vertex_normals[24];
  size_t needed = 0;
  const double third = 1.0 / sqrt(3.0);
  CHECK(hw_winged_face_normal(w, f1, n) == HW_OK);
  CHECK(near(n[0], 0) && near(n[1], 0) && near(n[2], -1));
  CHECK(hw_winged_vertex_normal(w, v1, n) == HW_OK);
  CHECK(near(n[0], -third) && near(n[1], -third) && near(n[2], -third));
  CHECK_STATUS(hw_winged_face_normals(w, all, 1, &needed), HW_ERR_BUFFER_TOO_SMALL,
               "6 are needed");
  CHECK(needed == 6);
  CHECK(hw_winged_face_normals(w, all, 6, NULL) == HW_OK);
  CHECK(near(all[2], -1) && near(all[5], 1));
  CHECK(hw_winged_vertex_normals(w, NULL, 0, &needed) == HW_ERR_BUFFER_TOO_SMALL);
  CHECK(needed == 8);
  CHECK(hw_winged_vertex_normals(w, vertex_normals, 8, NULL) == HW_OK);
  CHECK(near(vertex_normals[3 * v1.idx], -third) && near(vertex_normals[3 * v1.idx + 1], -third) &&
        near(vertex_normals[3 * v1.idx + 2], -third));
  CHECK_STATUS(hw_winged_face_normal(w, f1, NULL), HW_ERR_NULL_ARGUMENT, "out_normal");
  CHECK_STATUS(hw_winged_vertex_normal(w, v1, NULL), HW_ERR_NULL_ARGUMENT, "out_normal");
  CHECK_STATUS(hw_winged_vertex_normal(NULL, v1, n), HW_ERR_NULL_ARGUMENT, "winged");
  {
    hw_wface missing = {40};
    CHECK_STATUS(hw_winged_face_normal(w, missing, n), HW_ERR_INVALID_HANDLE,
                 "face 40 does not exist");
  }
  hw_winged_free(w);
}

/* The tetrahedron of seed 000, as in test_mesh_api.c. */
static const double tet_positions[] = {
    0.5773502691896258, 0.0, 0.0,  -0.2886751345948129, 0.5, 0.0,
    -0.2886751345948129, -0.5, 0.0, 0.0, 0.0, 0.816496580927726};
static const uint32_t tet_sizes[] = {3, 3, 3, 3};
static const uint32_t tet_indices[] = {0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 2, 1};

static void conversions(void) {
  hw_mesh *mesh = NULL;
  hw_mesh *back = NULL;
  hw_winged *w = NULL;
  hw_circulator c;
  hw_vertex v;
  uint32_t corners[12];
  size_t n = 0;
  uint32_t f;
  CHECK(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 12,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  CHECK(hw_winged_from_mesh(mesh, &w) == HW_OK);
  CHECK(hw_winged_n_edges(w) == 6 && hw_winged_check(w) == HW_OK);
  CHECK(hw_winged_to_mesh(w, &back) == HW_OK);
  CHECK(hw_mesh_n_halfedges(back) == 12 && hw_mesh_check(back) == HW_OK);
  /* Every face comes back with its corners in the input order. */
  for (f = 0; f < 4; f++) {
    hw_face face;
    face.idx = f;
    CHECK(hw_circ_around_face(back, face, HW_CIRCULATOR_KIND_VERTICES, &c) == HW_OK);
    while (hw_circ_next_vertex(&c, &v) && n < 12) corners[n++] = v.idx;
  }
  CHECK(n == 12 && memcmp(corners, tet_indices, sizeof corners) == 0);

  CHECK_STATUS(hw_winged_from_mesh(NULL, &w), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_winged_from_mesh(mesh, NULL), HW_ERR_NULL_ARGUMENT, "out_winged");
  CHECK_STATUS(hw_winged_to_mesh(NULL, &back), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_to_mesh(w, NULL), HW_ERR_NULL_ARGUMENT, "out_mesh");
  hw_mesh_free(back);
  hw_mesh_free(mesh);
  hw_winged_free(w);
}

/* A failed call leaves *out_winged as it was. */
#define SENTINEL ((hw_winged *)(uintptr_t)0x1234)

static void bad_face_lists(void) {
  hw_winged *w = SENTINEL;
  hw_diagnostic *d = NULL;
  static const uint32_t out_of_range[] = {0, 1, 3, 1, 2, 7, 0, 3, 2, 0, 2, 1};
  /* Faces 0 and 2 both walk 0 -> 1; face 3 walks it backward. */
  static const uint32_t flipped[] = {0, 1, 3, 1, 2, 3, 0, 1, 2, 0, 2, 1};
  static const uint32_t bad_order[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6,
                                       6, 7, 7, 4, 0, 5, 4, 1, 2, 7, 6, 2};
  const uint32_t *ids = NULL;
  size_t n = 0;

  /* A refusal hands out its diagnostic (and no structure). */
  CHECK_STATUS(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, out_of_range, 12,
                                      HW_BUILD_POLICY_STRICT, &w, &d),
               HW_ERR_INVALID_INPUT, "out-of-range vertex indices: f1");
  CHECK(w == SENTINEL && d != NULL);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_FACES_OUT_OF_RANGE, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 1);
  hw_diagnostic_free(d);
  d = NULL;
  CHECK_STATUS(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, flipped, 12,
                                      HW_BUILD_POLICY_STRICT, &w, &d),
               HW_ERR_NON_MANIFOLD, "not an oriented manifold");
  CHECK(w == SENTINEL && d != NULL);
  CHECK(hw_diagnostic_n_edges(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, &n) == HW_OK && n == 2);
  hw_diagnostic_free(d);
  d = NULL;
  CHECK_STATUS(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 12, 9, &w, &d),
               HW_ERR_INVALID_INPUT, "unknown build policy 9");
  CHECK_STATUS(hw_winged_from_indexed(NULL, 4, tet_sizes, 4, tet_indices, 12,
                                      HW_BUILD_POLICY_STRICT, &w, &d),
               HW_ERR_NULL_ARGUMENT, "positions");
  CHECK_STATUS(hw_winged_from_indexed(tet_positions, 4, NULL, 4, tet_indices, 12,
                                      HW_BUILD_POLICY_STRICT, &w, &d),
               HW_ERR_NULL_ARGUMENT, "face_sizes");
  CHECK_STATUS(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, NULL, 12,
                                      HW_BUILD_POLICY_STRICT, &w, &d),
               HW_ERR_NULL_ARGUMENT, "indices");
  CHECK_STATUS(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 12,
                                      HW_BUILD_POLICY_STRICT, NULL, &d),
               HW_ERR_NULL_ARGUMENT, "out_winged");
  CHECK(w == SENTINEL && d == NULL);

  /* Skip leaves out the face that cannot be placed and says which. */
  w = NULL;
  CHECK(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, flipped, 12, HW_BUILD_POLICY_SKIP,
                               &w, &d) == HW_OK);
  CHECK(hw_winged_n_faces(w) == 3 && hw_winged_check(w) == HW_OK);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_SKIPPED_FACES, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 2);
  hw_diagnostic_free(d);
  hw_winged_free(w);
  /* Repair keeps every face. */
  w = NULL;
  CHECK(hw_winged_from_indexed(tet_positions, 4, tet_sizes, 4, flipped, 12, HW_BUILD_POLICY_REPAIR,
                               &w, NULL) == HW_OK);
  CHECK(hw_winged_n_faces(w) == 4 && hw_winged_check(w) == HW_OK);
  hw_winged_free(w);

  /* The hand-made numbering must list the faces' edges. */
  w = SENTINEL;
  CHECK_STATUS(hw_winged_from_indexed_ordered(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                              bad_order, 12, &w),
               HW_ERR_INVALID_INPUT, "(6, 2) is not an edge");
  CHECK_STATUS(hw_winged_from_indexed_ordered(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                              cube_edge_order, 11, &w),
               HW_ERR_INVALID_INPUT, "11 edges listed");
  CHECK_STATUS(hw_winged_from_indexed_ordered(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                              NULL, 12, &w),
               HW_ERR_NULL_ARGUMENT, "edge_order");
  CHECK_STATUS(hw_winged_from_indexed_ordered(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                              cube_edge_order, 12, NULL),
               HW_ERR_NULL_ARGUMENT, "out_winged");
  CHECK(w == SENTINEL);
}

static void euler_cube(void) {
  hw_winged *w = hw_winged_new();
  const double bottom[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  hw_wvertex square[4], top[4];
  hw_wface f0, made_face;
  hw_wedge made_edge;
  hw_mesh *mesh = NULL;
  int k;
  CHECK(w != NULL && hw_winged_n_vertices(w) == 0);
  CHECK(hw_winged_mvfs(w, bottom[0], &square[0], &f0) == HW_OK);
  /* A point face has no half-edge counterpart. */
  CHECK_STATUS(hw_winged_to_mesh(w, &mesh), HW_ERR_REFUSED, "point face");
  for (k = 1; k < 4; k++)
    CHECK(hw_winged_mev(w, f0, square[k - 1], bottom[k], &made_edge, &square[k]) == HW_OK);
  CHECK(hw_winged_mef(w, f0, square[3], square[0], &made_edge, &made_face) == HW_OK);
  for (k = 0; k < 4; k++) {
    double up[3];
    memcpy(up, bottom[k], sizeof up);
    up[2] = 1;
    CHECK(hw_winged_mev(w, f0, square[k], up, &made_edge, &top[k]) == HW_OK);
  }
  for (k = 0; k < 4; k++)
    CHECK(hw_winged_mef(w, f0, top[k], top[(k + 1) % 4], &made_edge, &made_face) == HW_OK);
  CHECK(hw_winged_n_vertices(w) == 8 && hw_winged_n_edges(w) == 12 && hw_winged_n_faces(w) == 6);
  CHECK(hw_winged_check(w) == HW_OK);
  CHECK(hw_winged_to_mesh(w, &mesh) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 6 && hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);

  {
    /* Refusals change nothing: the tables print the same before and after. */
    char* before = table(w, HW_WTABLE_ALL, HW_WNAMING_DIRECT_INVERSE, HW_TABLE_FORMAT_CSV);
    char *after;
    const double nowhere[3] = {NAN, 0, 0};
    const double origin[3] = {0, 0, 0};
    hw_wvertex v_out = {HW_INVALID_INDEX};
    hw_wface f_out = {HW_INVALID_INDEX};
    hw_wedge e_out = {HW_INVALID_INDEX};
    hw_wedge bottom_edge = {0};
    hw_wedge missing_edge = {500};
    hw_wface missing_face = {99};
    hw_wvertex on_f0[8], far = {HW_INVALID_INDEX}, v;
    hw_wcirculator c;
    size_t n_on = 0;
    uint32_t id;
    CHECK(hw_wcirc_around_face(w, f0, HW_WCIRCULATOR_KIND_VERTICES, &c) == HW_OK);
    while (hw_wcirc_next_vertex(&c, &v) && n_on < 8) on_f0[n_on++] = v;
    CHECK(n_on == 4);
    for (id = 0; id < 8 && far.idx == HW_INVALID_INDEX; id++) {
      size_t i;
      int on = 0;
      for (i = 0; i < n_on; i++) on |= on_f0[i].idx == id;
      if (!on) far.idx = id;
    }
    CHECK_STATUS(hw_winged_mvfs(w, nowhere, &v_out, &f_out), HW_ERR_INVALID_INPUT, "not finite");
    CHECK_STATUS(hw_winged_mev(w, f0, far, origin, &e_out, &v_out), HW_ERR_REFUSED,
                 "is not on the loop");
    CHECK_STATUS(hw_winged_mev(w, missing_face, square[0], origin, &e_out, &v_out),
                 HW_ERR_INVALID_HANDLE, "face 99 does not exist");
    CHECK_STATUS(hw_winged_mef(w, f0, on_f0[1], on_f0[1], &e_out, &f_out), HW_ERR_REFUSED,
                 "to itself");
    CHECK_STATUS(hw_winged_mef(w, f0, on_f0[0], far, &e_out, &f_out), HW_ERR_REFUSED,
                 "is not on the loop");
    CHECK_STATUS(hw_winged_kev(w, bottom_edge, square[0]), HW_ERR_REFUSED, "has other edges");
    CHECK_STATUS(hw_winged_kev(w, missing_edge, square[0]), HW_ERR_INVALID_HANDLE,
                 "edge 500 does not exist");
    CHECK_STATUS(hw_winged_kvfs(w, f0), HW_ERR_REFUSED, "only a point face");
    CHECK_STATUS(hw_winged_kef(w, missing_edge, f0), HW_ERR_INVALID_HANDLE,
                 "edge 500 does not exist");
    CHECK(v_out.idx == HW_INVALID_INDEX && f_out.idx == HW_INVALID_INDEX &&
          e_out.idx == HW_INVALID_INDEX);
    after = table(w, HW_WTABLE_ALL, HW_WNAMING_DIRECT_INVERSE, HW_TABLE_FORMAT_CSV);
    CHECK(strcmp(before, after) == 0);
    free(before);
    free(after);
  }

  /* Killing the last face's edge merges two faces; the count follows Euler's formula. */
  CHECK(hw_winged_kef(w, made_edge, made_face) == HW_OK);
  CHECK(hw_winged_n_faces(w) == 5 && hw_winged_n_edges(w) == 11);
  CHECK(hw_winged_n_edge_slots(w) == 12);
  {
    hw_index_maps *maps = NULL;
    const uint32_t *edge_map = NULL;
    size_t n_map = 0;
    hw_wvertex first = {0};
    const double moved[3] = {0.25, 0.25, 0.25}, nowhere[3] = {0.0, 1.0 / 0.0 * 0.0, 0.0};
    double at[3];
    CHECK(hw_winged_garbage_collect(w, &maps) == HW_OK);
    CHECK(hw_index_maps_view(maps, HW_ELEMENT_KIND_EDGE, &edge_map, &n_map) == HW_OK);
    /* The killed edge maps to nothing; the other eleven keep their order. */
    CHECK(n_map == 12 && edge_map[made_edge.idx] == HW_INVALID_INDEX);
    hw_index_maps_free(maps);
    CHECK(hw_winged_set_vertex_position(w, first, moved) == HW_OK);
    CHECK(hw_winged_vertex_position(w, first, at) == HW_OK && at[0] == 0.25 && at[2] == 0.25);
    CHECK_STATUS(hw_winged_set_vertex_position(w, first, nowhere), HW_ERR_INVALID_INPUT, "not finite");
    CHECK_STATUS(hw_winged_set_vertex_position(NULL, first, moved), HW_ERR_NULL_ARGUMENT, "winged");
  }
  CHECK(hw_winged_n_edge_slots(w) == 11 && hw_winged_check(w) == HW_OK);
  hw_winged_free(w);
}

static void null_and_freed_handles(void) {
  hw_wvertex v = {0};
  hw_wedge e = {0};
  hw_wface f = {0};
  hw_wedge_record r;
  const hw_wedge_record *view;
  size_t n;
  double p[3];
  char buf[8];
  hw_winged *w;
  hw_wface made_face;
  hw_wvertex made_vertex;
  hw_wedge made_edge;
  CHECK(hw_winged_n_vertices(NULL) == 0 && last_error_contains("winged"));
  CHECK(hw_winged_n_edges(NULL) == 0 && hw_winged_n_faces(NULL) == 0);
  CHECK(hw_winged_n_vertex_slots(NULL) == 0 && hw_winged_n_edge_slots(NULL) == 0 &&
        hw_winged_n_face_slots(NULL) == 0);
  CHECK(!hw_winged_is_vertex(NULL, v) && !hw_winged_is_edge(NULL, e) &&
        !hw_winged_is_face(NULL, f));
  CHECK(hw_winged_vertex_edge(NULL, v).idx == HW_INVALID_INDEX);
  CHECK(hw_winged_face_edge(NULL, f).idx == HW_INVALID_INDEX && last_error_contains("winged"));
  CHECK_STATUS(hw_winged_edge(NULL, e, &r), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_edge_records(NULL, &view, &n), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_vertex_position(NULL, v, p), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_face_normals(NULL, p, 1, NULL), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_vertex_normals(NULL, p, 1, NULL), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_check(NULL), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(
      hw_winged_table(NULL, HW_WTABLE_ALL, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_TEXT, buf, 8, NULL),
      HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_mvfs(NULL, p, &made_vertex, &made_face), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_mev(NULL, f, v, p, &made_edge, &made_vertex), HW_ERR_NULL_ARGUMENT,
               "winged");
  CHECK_STATUS(hw_winged_mef(NULL, f, v, v, &made_edge, &made_face), HW_ERR_NULL_ARGUMENT,
               "winged");
  CHECK_STATUS(hw_winged_kev(NULL, e, v), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_kef(NULL, e, f), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_kvfs(NULL, f), HW_ERR_NULL_ARGUMENT, "winged");
  CHECK_STATUS(hw_winged_garbage_collect(NULL, NULL), HW_ERR_NULL_ARGUMENT, "winged");

  w = seed_cube();
  CHECK_STATUS(hw_winged_edge(w, e, NULL), HW_ERR_NULL_ARGUMENT, "out_record");
  CHECK_STATUS(hw_winged_edge_records(w, NULL, &n), HW_ERR_NULL_ARGUMENT, "out_records");
  CHECK_STATUS(hw_winged_edge_records(w, &view, NULL), HW_ERR_NULL_ARGUMENT, "out_len");
  CHECK_STATUS(hw_winged_vertex_position(w, v, NULL), HW_ERR_NULL_ARGUMENT, "out_xyz");
  CHECK_STATUS(hw_winged_mvfs(w, NULL, &made_vertex, &made_face), HW_ERR_NULL_ARGUMENT,
               "position");
  CHECK_STATUS(hw_winged_mvfs(w, p, NULL, &made_face), HW_ERR_NULL_ARGUMENT, "out_vertex");
  CHECK_STATUS(hw_winged_mvfs(w, p, &made_vertex, NULL), HW_ERR_NULL_ARGUMENT, "out_face");
  CHECK_STATUS(hw_winged_mev(w, f, v, p, NULL, &made_vertex), HW_ERR_NULL_ARGUMENT, "out_edge");
  CHECK_STATUS(hw_winged_mef(w, f, v, v, &made_edge, NULL), HW_ERR_NULL_ARGUMENT, "out_face");
  {
    hw_wedge missing_edge = {12};
    hw_wvertex missing_vertex = {8};
    CHECK_STATUS(hw_winged_edge(w, missing_edge, &r), HW_ERR_INVALID_HANDLE,
                 "edge 12 does not exist");
    CHECK_STATUS(hw_winged_vertex_position(w, missing_vertex, p), HW_ERR_INVALID_HANDLE,
                 "vertex 8 does not exist");
    CHECK(hw_winged_vertex_edge(w, missing_vertex).idx == HW_INVALID_INDEX);
    CHECK(last_error_contains("does not exist"));
  }
  /* Tables: unknown enum values, a buffer too small (nothing written, size reported). */
  CHECK_STATUS(hw_winged_table(w, 4, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_TEXT, buf, 8, NULL),
               HW_ERR_INVALID_INPUT, "unknown table 4");
  CHECK_STATUS(hw_winged_table(w, HW_WTABLE_ALL, 3, HW_TABLE_FORMAT_TEXT, buf, 8, NULL),
               HW_ERR_INVALID_INPUT, "unknown naming 3");
  CHECK_STATUS(hw_winged_table(w, HW_WTABLE_ALL, HW_WNAMING_CW_CCW, 3, buf, 8, NULL),
               HW_ERR_INVALID_INPUT, "unknown table format 3");
  memset(buf, 'x', sizeof buf);
  n = 0;
  CHECK_STATUS(
      hw_winged_table(w, HW_WTABLE_FACES, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_CSV, buf, 8, &n),
      HW_ERR_BUFFER_TOO_SMALL, "are needed");
  CHECK(n == strlen(cube_face_table) + 1 && buf[0] == 'x');

  /* Freeing twice is detected and refused; NULL is a no-op. */
  hw_winged_free(NULL);
  hw_winged_free(w);
  hw_winged_free(w);
  CHECK(last_error_contains("already freed"));
}

/* Ids killed by the Euler operators (deleted, not yet collected) are refused like ids out of
 * range: HW_ERR_INVALID_HANDLE (or an invalid id / false), outputs untouched. */
static void killed_ids(void) {
  hw_winged *w = hw_winged_new();
  const double p0[3] = {0, 0, 0}, p1[3] = {1, 0, 0};
  hw_wvertex v0, v1, out_v = {4242};
  hw_wface f0, out_f = {4242};
  hw_wedge e1, out_e = {4242};
  hw_wedge_record r;
  hw_wcirculator c, c_before;
  double xyz[3] = {7, 7, 7};
  CHECK(w != NULL);
  CHECK(hw_winged_mvfs(w, p0, &v0, &f0) == HW_OK);
  CHECK(hw_winged_mev(w, f0, v0, p1, &e1, &v1) == HW_OK);
  CHECK(hw_winged_kev(w, e1, v1) == HW_OK); /* v1 and e1 are dead, their slots remain */
  CHECK(hw_winged_n_vertex_slots(w) == 2 && hw_winged_n_edge_slots(w) == 1);
  CHECK(!hw_winged_is_vertex(w, v1) && !hw_winged_is_edge(w, e1));
  memset(&r, 0xA5, sizeof r);
  memset(&c, 0xA5, sizeof c);
  c_before = c;
  CHECK_STATUS(hw_winged_edge(w, e1, &r), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK(r.start.idx == 0xA5A5A5A5u);
  CHECK_STATUS(hw_winged_vertex_position(w, v1, xyz), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK_STATUS(hw_winged_vertex_normal(w, v1, xyz), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK(xyz[0] == 7 && xyz[1] == 7 && xyz[2] == 7);
  CHECK_STATUS(hw_winged_set_vertex_position(w, v1, p0), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK(hw_winged_vertex_edge(w, v1).idx == HW_INVALID_INDEX);
  CHECK(last_error_contains("does not exist"));
  CHECK_STATUS(hw_wcirc_around_vertex(w, v1, HW_WCIRCULATOR_KIND_EDGES, &c), HW_ERR_INVALID_HANDLE,
               "does not exist");
  CHECK_STATUS(hw_winged_kev(w, e1, v1), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK_STATUS(hw_winged_kef(w, e1, f0), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK_STATUS(hw_winged_mev(w, f0, v1, p1, &out_e, &out_v), HW_ERR_INVALID_HANDLE,
               "does not exist");
  CHECK_STATUS(hw_winged_mef(w, f0, v0, v1, &out_e, &out_f), HW_ERR_INVALID_HANDLE,
               "does not exist");
  /* The point face and its vertex go too: the face is dead. */
  CHECK(hw_winged_kvfs(w, f0) == HW_OK);
  CHECK(!hw_winged_is_face(w, f0) && hw_winged_n_faces(w) == 0);
  CHECK_STATUS(hw_winged_kvfs(w, f0), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK_STATUS(hw_winged_face_normal(w, f0, xyz), HW_ERR_INVALID_HANDLE, "does not exist");
  CHECK(hw_winged_face_edge(w, f0).idx == HW_INVALID_INDEX);
  CHECK(last_error_contains("does not exist"));
  CHECK_STATUS(hw_wcirc_around_face(w, f0, HW_WCIRCULATOR_KIND_EDGES, &c), HW_ERR_INVALID_HANDLE,
               "does not exist");
  CHECK_STATUS(hw_winged_mev(w, f0, v0, p1, &out_e, &out_v), HW_ERR_INVALID_HANDLE,
               "does not exist");
  CHECK(memcmp(&c, &c_before, sizeof c) == 0);
  CHECK(xyz[0] == 7 && out_v.idx == 4242 && out_f.idx == 4242 && out_e.idx == 4242);
  CHECK(hw_winged_check(w) == HW_OK);
  hw_winged_free(w);
}

int main(void) {
  seed_cube_tables();
  records_and_views();
  walks();
  normals();
  conversions();
  bad_face_lists();
  euler_cube();
  null_and_freed_handles();
  killed_ids();
  return check_summary("test_winged_api");
}
