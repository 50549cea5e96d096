/* Normals, editing operators, deletion and compaction, slot counts and thread count through the
 * C API, with the refusals and bad arguments of each. */
#include <math.h>

#include "check.h"

/* A unit cube of six quads, counter-clockwise seen from outside. */
static const double cube_positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                        0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t cube_sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t cube_faces[] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                      1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};

static hw_mesh *cube(void) {
  hw_mesh *mesh = NULL;
  CHECK(hw_mesh_from_indexed(cube_positions, 8, cube_sizes, 6, cube_faces, 24,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  return mesh;
}

static double length3(const double *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

static void normals(void) {
  hw_mesh *mesh = cube();
  double faces[6 * 3], vertices[8 * 3], corners[24 * 3], small[3];
  size_t needed = 0, f, v, h;
  hw_normal_weighting w;

  CHECK(hw_mesh_face_normals(mesh, faces, 6, &needed) == HW_OK && needed == 6);
  for (f = 0; f < 6; ++f) {
    /* Outward: along the direction from the cube's centre to the face's first corner. */
    const double *p = cube_positions + 3 * cube_faces[4 * f];
    const double outward = faces[3 * f] * (p[0] - 0.5) + faces[3 * f + 1] * (p[1] - 0.5) +
                           faces[3 * f + 2] * (p[2] - 0.5);
    CHECK(fabs(length3(faces + 3 * f) - 1) < 1e-12 && outward > 0);
  }
  for (w = HW_NORMAL_WEIGHTING_UNIFORM; w <= HW_NORMAL_WEIGHTING_ANGLE; ++w) {
    CHECK(hw_mesh_vertex_normals(mesh, w, vertices, 8, NULL) == HW_OK);
    /* A cube corner's normal points along the diagonal, whatever the weighting. */
    for (v = 0; v < 8; ++v) {
      const double *p = cube_positions + 3 * v;
      const double c = 1 / sqrt(3.0);
      CHECK(fabs(vertices[3 * v] - (p[0] - 0.5) * 2 * c) < 1e-12);
      CHECK(fabs(vertices[3 * v + 2] - (p[2] - 0.5) * 2 * c) < 1e-12);
    }
  }
  CHECK(hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_UNIFORM, faces, 6, NULL, vertices, 8, NULL) ==
        HW_OK);
  /* Crease angle 0: every corner takes its face's normal (flat shading). */
  CHECK(hw_mesh_corner_normals(mesh, 0.0, corners, 24, &needed) == HW_OK && needed == 24);
  for (h = 0; h < 24; ++h) {
    hw_halfedge he = {(uint32_t)h};
    hw_face face = hw_mesh_he_face(mesh, he);
    if (face.idx == HW_INVALID_INDEX) continue;
    CHECK(fabs(corners[3 * h] - faces[3 * face.idx]) < 1e-12 &&
          fabs(corners[3 * h + 1] - faces[3 * face.idx + 1]) < 1e-12 &&
          fabs(corners[3 * h + 2] - faces[3 * face.idx + 2]) < 1e-12);
  }
  /* Smooth (crease angle pi): the angle-weighted vertex normal. */
  CHECK(hw_mesh_corner_normals(mesh, 3.2, corners, 24, NULL) == HW_OK);
  CHECK(hw_mesh_vertex_normals(mesh, HW_NORMAL_WEIGHTING_ANGLE, vertices, 8, NULL) == HW_OK);
  for (h = 0; h < 24; ++h) {
    hw_halfedge he = {(uint32_t)h};
    hw_vertex origin = hw_mesh_he_origin(mesh, he);
    CHECK(fabs(corners[3 * h] - vertices[3 * origin.idx]) < 1e-12);
  }

  CHECK_STATUS(hw_mesh_face_normals(mesh, small, 1, &needed), HW_ERR_BUFFER_TOO_SMALL,
               "6 are needed");
  CHECK(needed == 6);
  CHECK_STATUS(hw_mesh_face_normals(mesh, NULL, 0, &needed), HW_ERR_BUFFER_TOO_SMALL, "needed");
  {
    /* Misaligned output arrays are refused, naming the argument; nothing is written. */
    double storage[3 * 24 + 1];
    double *misaligned = (double *)(void *)((unsigned char *)storage + 1);
    size_t face_needed = 0, vertex_needed = 0;
    memset(storage, 0, sizeof storage);
    CHECK_STATUS(hw_mesh_face_normals(mesh, misaligned, 6, &needed), HW_ERR_INVALID_INPUT,
                 "argument `out_normals` is misaligned");
    CHECK_STATUS(hw_mesh_corner_normals(mesh, 0.0, misaligned, 24, &needed),
                 HW_ERR_INVALID_INPUT, "argument `out_normals` is misaligned");
    CHECK_STATUS(hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_UNIFORM, faces, 6, &face_needed,
                                 misaligned, 8, &vertex_needed),
                 HW_ERR_INVALID_INPUT, "argument `out_vertex_normals` is misaligned");
    CHECK(face_needed == 6 && vertex_needed == 8);
    for (h = 0; h < 3 * 24 + 1; ++h) CHECK(storage[h] == 0);
  }
  CHECK_STATUS(hw_mesh_vertex_normals(mesh, 9u, vertices, 8, NULL), HW_ERR_INVALID_INPUT,
               "weighting 9");
  CHECK_STATUS(hw_mesh_vertex_normals(NULL, HW_NORMAL_WEIGHTING_UNIFORM, vertices, 8, NULL),
               HW_ERR_NULL_ARGUMENT, "mesh");
  {
    /* Too small: both needed sizes come back, whichever array is short, and neither array is
     * written. */
    size_t face_needed = 0, vertex_needed = 0;
    memset(faces, 0, sizeof faces);
    memset(vertices, 0, sizeof vertices);
    CHECK_STATUS(hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_UNIFORM, faces, 6, &face_needed,
                                 vertices, 7, &vertex_needed),
                 HW_ERR_BUFFER_TOO_SMALL, "8 are needed");
    CHECK(face_needed == 6 && vertex_needed == 8);
    face_needed = vertex_needed = 0;
    CHECK_STATUS(hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_UNIFORM, faces, 5, &face_needed,
                                 vertices, 8, &vertex_needed),
                 HW_ERR_BUFFER_TOO_SMALL, "6 are needed");
    CHECK(face_needed == 6 && vertex_needed == 8);
    face_needed = vertex_needed = 0;
    CHECK(hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_UNIFORM, NULL, 0, &face_needed, NULL, 0,
                          &vertex_needed) == HW_ERR_BUFFER_TOO_SMALL);
    CHECK(face_needed == 6 && vertex_needed == 8);
    for (f = 0; f < 18; ++f) CHECK(faces[f] == 0);
    for (v = 0; v < 24; ++v) CHECK(vertices[v] == 0);
  }
  CHECK_STATUS(hw_mesh_corner_normals(mesh, -1.0, corners, 24, NULL), HW_ERR_INVALID_INPUT,
               "crease");
  CHECK(hw_mesh_n_halfedge_slots(mesh) == 24);
  CHECK(hw_mesh_n_edge_slots(mesh) == 12);
  hw_mesh_free(mesh);
}

static void editing(void) {
  hw_mesh *mesh = cube();
  hw_index_maps *maps = NULL;
  hw_vertex v;
  hw_halfedge h0, h1, made;
  hw_face top = {1}, deleted = {0};
  hw_edge e0 = {0}, diagonal = {12};
  hw_vertex missing = {999};
  const uint32_t *map = NULL;
  size_t n_tri = 0, len = 0;
  const double middle[3] = {0.5, 0.5, 1.0}, far[3] = {9, 9, 9};
  double nan_point[3] = {0, 0, 0};
  nan_point[1] = nan("");

  /* Flip needs two triangles: refused on the quad cube, nothing changes. */
  CHECK_STATUS(hw_mesh_flip_edge(mesh, e0), HW_ERR_REFUSED, "flip");
  CHECK(hw_mesh_n_edges(mesh) == 12 && hw_mesh_check(mesh) == HW_OK);

  /* Triangulate the top quad, then flip its diagonal. */
  CHECK(hw_mesh_triangulate_face(mesh, top, &n_tri) == HW_OK && n_tri == 2);
  CHECK(hw_mesh_n_faces(mesh) == 7 && hw_mesh_n_edges(mesh) == 13);
  CHECK(hw_mesh_edge_is_boundary(mesh, diagonal) == false);
  CHECK(hw_mesh_flip_edge(mesh, diagonal) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 7 && hw_mesh_check(mesh) == HW_OK);

  /* Split an edge at a new vertex, then split a face through it. */
  CHECK(hw_mesh_split_edge(mesh, e0, middle, &v) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 9 && hw_mesh_check(mesh) == HW_OK);
  CHECK_STATUS(hw_mesh_split_edge(mesh, e0, nan_point, &v), HW_ERR_INVALID_INPUT, "not finite");
  h0 = hw_mesh_vertex_halfedge(mesh, v);
  h1 = hw_mesh_he_next(mesh, hw_mesh_he_next(mesh, h0));
  h0 = hw_mesh_he_prev(mesh, h0);
  CHECK(hw_mesh_split_face(mesh, h0, h1, &made) == HW_OK);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  CHECK_STATUS(hw_mesh_split_face(mesh, h0, h0, &made), HW_ERR_REFUSED, "split");


  /* Add an isolated vertex; delete a face; compact. */
  CHECK(hw_mesh_add_vertex(mesh, far, &v) == HW_OK);
  CHECK(hw_mesh_vertex_halfedge(mesh, v).idx == HW_INVALID_INDEX);
  CHECK_STATUS(hw_mesh_add_vertex(mesh, nan_point, &v), HW_ERR_INVALID_INPUT, "not finite");
  CHECK(hw_mesh_delete_face(mesh, deleted, false) == HW_OK);
  CHECK_STATUS(hw_mesh_delete_face(mesh, deleted, false), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK(hw_mesh_face_halfedge(mesh, deleted).idx == HW_INVALID_INDEX);
  CHECK(last_error_contains("face 0 is deleted"));
  CHECK(hw_mesh_garbage_collect(mesh, &maps) == HW_OK);
  CHECK(hw_index_maps_view(maps, HW_ELEMENT_KIND_FACE, &map, &len) == HW_OK);
  CHECK(len >= 1 && map[0] == HW_INVALID_INDEX);
  CHECK(hw_mesh_n_face_slots(mesh) == hw_mesh_n_faces(mesh));
  CHECK_STATUS(hw_index_maps_view(maps, 8u, &map, &len), HW_ERR_INVALID_INPUT, "kind 8");
  {
    /* NULL maps or outputs: refused, nothing written. */
    const uint32_t *unset = NULL;
    size_t unset_len = 4242;
    CHECK_STATUS(hw_index_maps_view(NULL, HW_ELEMENT_KIND_FACE, &unset, &unset_len),
                 HW_ERR_NULL_ARGUMENT, "maps");
    CHECK_STATUS(hw_index_maps_view(maps, HW_ELEMENT_KIND_FACE, NULL, &unset_len),
                 HW_ERR_NULL_ARGUMENT, "out_map");
    CHECK_STATUS(hw_index_maps_view(maps, HW_ELEMENT_KIND_FACE, &unset, NULL), HW_ERR_NULL_ARGUMENT,
                 "out_len");
    CHECK(unset == NULL && unset_len == 4242);
  }
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_index_maps_free(maps);
  hw_index_maps_free(maps);
  CHECK(last_error_contains("already freed"));
  CHECK(hw_mesh_garbage_collect(mesh, NULL) == HW_OK);

  CHECK_STATUS(hw_mesh_flip_edge(NULL, e0), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_delete_vertex(mesh, missing), HW_ERR_INVALID_HANDLE, "999");
  CHECK_STATUS(hw_mesh_split_edge(mesh, e0, middle, NULL), HW_ERR_NULL_ARGUMENT, "out_vertex");
  hw_mesh_free(mesh);
}

/* Edge collapse on triangles: the link condition refuses on a tetrahedron (it would fold the
 * solid flat), and an interior edge of the seed 000 fan collapses to one vertex fewer. */
static void collapse(void) {
  static const double tet_positions[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  static const uint32_t tet_sizes[] = {3, 3, 3, 3};
  static const uint32_t tet_faces[] = {0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0};
  static const double fan_positions[] = {1, 4, 0, 3, 4, 0, 0, 2, 0, 2, 2, 0,
                                         4, 2, 0, 1, 0, 0, 3, 0, 0};
  static const uint32_t fan_sizes[] = {3, 3, 3, 3, 3, 3};
  static const uint32_t fan_faces[] = {0, 2, 3, 0, 3, 1, 1, 3, 4, 2, 5, 3, 3, 5, 6, 3, 6, 4};
  hw_mesh *mesh = NULL;
  hw_halfedge h = {0};
  hw_vertex kept, target, inner = {3};
  hw_circulator c;
  CHECK(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, tet_faces, 12, HW_BUILD_POLICY_STRICT,
                             &mesh, NULL) == HW_OK);
  CHECK_STATUS(hw_mesh_collapse_halfedge(mesh, h, &kept), HW_ERR_REFUSED, "collapse");
  CHECK(hw_mesh_n_faces(mesh) == 4 && hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);

  CHECK(hw_mesh_from_indexed(fan_positions, 7, fan_sizes, 6, fan_faces, 18, HW_BUILD_POLICY_STRICT,
                             &mesh, NULL) == HW_OK);
  /* The inner vertex v4 (index 3) merges into one of its boundary neighbours. */
  CHECK(hw_circ_around_vertex(mesh, inner, HW_CIRCULATOR_KIND_HALFEDGES, &c) == HW_OK);
  CHECK(hw_circ_next_halfedge(&c, &h));
  target = hw_mesh_he_target(mesh, h);
  CHECK(hw_mesh_collapse_halfedge(mesh, h, &kept) == HW_OK);
  CHECK(kept.idx == target.idx);
  CHECK(hw_mesh_n_vertices(mesh) == 6 && hw_mesh_n_faces(mesh) == 4);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_mesh_garbage_collect(mesh, NULL) == HW_OK && hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
}

/* Every id-taking call on elements that are deleted (marked, not yet compacted) refuses them
 * with HW_ERR_INVALID_HANDLE naming the deletion, leaves its outputs and the mesh untouched; a
 * NULL output of an edit is refused before the mesh changes. */
static void deleted_elements_and_null_outputs(void) {
  hw_mesh *mesh = cube();
  const hw_vertex v0 = {0}, live_v = {6};
  const hw_face f0 = {0}, top = {1}; /* the top face keeps clear of v0 */
  const double point[3] = {0.5, 0.5, 0.5};
  hw_halfedge h, h_live;
  hw_edge e;
  hw_circulator c, c_before;
  hw_vertex out_v = {4242};
  hw_face out_f = {4242};
  hw_halfedge out_h = {4242};
  double xyz[3] = {7, 7, 7};
  size_t n_out = 4242, n_v, n_f, n_e;
  h = hw_mesh_vertex_halfedge(mesh, v0);
  e.idx = h.idx >> 1;
  h_live = hw_mesh_face_halfedge(mesh, top);
  CHECK(hw_mesh_delete_vertex(mesh, v0) == HW_OK);
  n_v = hw_mesh_n_vertices(mesh);
  n_f = hw_mesh_n_faces(mesh);
  n_e = hw_mesh_n_edges(mesh);
  CHECK(n_v == 7 && n_f == 3);

  /* Navigation: an invalid id, false or 0, and the message. */
  CHECK(hw_mesh_he_origin(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(hw_mesh_he_target(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(hw_mesh_he_next(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(hw_mesh_he_prev(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(hw_mesh_he_twin(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(hw_mesh_he_face(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(hw_mesh_he_edge(mesh, h).idx == HW_INVALID_INDEX && last_error_contains("deleted"));
  CHECK(!hw_mesh_he_is_boundary(mesh, h) && last_error_contains("deleted"));
  CHECK(hw_mesh_edge_halfedge(mesh, e, 0).idx == HW_INVALID_INDEX &&
        last_error_contains("deleted"));
  CHECK(!hw_mesh_edge_is_boundary(mesh, e) && last_error_contains("deleted"));
  CHECK(hw_mesh_vertex_halfedge(mesh, v0).idx == HW_INVALID_INDEX &&
        last_error_contains("vertex 0 is deleted"));
  CHECK(!hw_mesh_vertex_is_boundary(mesh, v0) && last_error_contains("deleted"));
  CHECK(hw_mesh_vertex_valence(mesh, v0) == 0 && last_error_contains("deleted"));
  CHECK(hw_mesh_face_degree(mesh, f0) == 0 && last_error_contains("face 0 is deleted"));
  CHECK(!hw_mesh_face_is_boundary(mesh, f0) && last_error_contains("deleted"));

  /* Status calls: refused, outputs untouched. */
  CHECK_STATUS(hw_mesh_vertex_position(mesh, v0, xyz), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK(xyz[0] == 7 && xyz[1] == 7 && xyz[2] == 7);
  CHECK_STATUS(hw_mesh_set_vertex_position(mesh, v0, point), HW_ERR_INVALID_HANDLE, "deleted");
  memset(&c, 0xA5, sizeof c);
  c_before = c;
  CHECK_STATUS(hw_circ_around_vertex(mesh, v0, HW_CIRCULATOR_KIND_VERTICES, &c),
               HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_circ_around_face(mesh, f0, HW_CIRCULATOR_KIND_VERTICES, &c),
               HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_circ_along_loop(mesh, h, &c), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK(memcmp(&c, &c_before, sizeof c) == 0);

  /* Edits: refused, outputs and mesh untouched. */
  CHECK_STATUS(hw_mesh_split_edge(mesh, e, point, &out_v), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_flip_edge(mesh, e), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_collapse_halfedge(mesh, h, &out_v), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_split_face(mesh, h, h_live, &out_h), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_triangulate_face(mesh, f0, &n_out), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_delete_edge(mesh, e, true), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_delete_face(mesh, f0, true), HW_ERR_INVALID_HANDLE, "deleted");
  CHECK_STATUS(hw_mesh_delete_vertex(mesh, v0), HW_ERR_INVALID_HANDLE, "deleted");
  {
    const hw_vertex corners[3] = {{0}, {1}, {2}};
    CHECK_STATUS(hw_mesh_add_face(mesh, corners, 3, &out_f), HW_ERR_INVALID_HANDLE,
                 "vertex 0 is deleted");
  }
  CHECK(out_v.idx == 4242 && out_f.idx == 4242 && out_h.idx == 4242 && n_out == 4242);

  /* NULL outputs (and inputs) of edits, on live elements: refused before anything changes. */
  CHECK_STATUS(hw_mesh_add_vertex(mesh, point, NULL), HW_ERR_NULL_ARGUMENT, "out_vertex");
  CHECK_STATUS(hw_mesh_add_vertex(mesh, NULL, &out_v), HW_ERR_NULL_ARGUMENT, "xyz");
  CHECK_STATUS(hw_mesh_add_vertex(NULL, point, &out_v), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_split_edge(mesh, hw_mesh_he_edge(mesh, h_live), NULL, &out_v),
               HW_ERR_NULL_ARGUMENT, "xyz");
  CHECK_STATUS(hw_mesh_collapse_halfedge(mesh, h_live, NULL), HW_ERR_NULL_ARGUMENT,
               "out_vertex");
  out_h = hw_mesh_he_next(mesh, hw_mesh_he_next(mesh, h_live));
  CHECK_STATUS(hw_mesh_split_face(mesh, h_live, out_h, NULL), HW_ERR_NULL_ARGUMENT,
               "out_halfedge");
  out_h.idx = 4242;
  {
    const hw_vertex corners[3] = {{4}, {5}, {6}};
    CHECK_STATUS(hw_mesh_add_face(mesh, corners, 3, NULL), HW_ERR_NULL_ARGUMENT, "out_face");
  }
  CHECK_STATUS(hw_mesh_set_vertex_position(mesh, live_v, NULL), HW_ERR_NULL_ARGUMENT, "xyz");
  CHECK_STATUS(hw_mesh_set_vertex_position(NULL, live_v, point), HW_ERR_NULL_ARGUMENT, "mesh");
  {
    /* A misaligned point is refused like every other misaligned pointer, naming it. */
    double storage[4] = {0.5, 0.5, 0.5, 0.5};
    const double *misaligned = (const double *)(const void *)((const unsigned char *)storage + 1);
    CHECK_STATUS(hw_mesh_add_vertex(mesh, misaligned, &out_v), HW_ERR_INVALID_INPUT,
                 "argument `xyz` is misaligned");
    CHECK_STATUS(hw_mesh_set_vertex_position(mesh, live_v, misaligned), HW_ERR_INVALID_INPUT,
                 "argument `xyz` is misaligned");
    CHECK_STATUS(hw_mesh_split_edge(mesh, hw_mesh_he_edge(mesh, h_live), misaligned, &out_v),
                 HW_ERR_INVALID_INPUT, "argument `xyz` is misaligned");
  }
  CHECK_STATUS(hw_mesh_vertex_position(mesh, live_v, NULL), HW_ERR_NULL_ARGUMENT, "out_xyz");
  CHECK_STATUS(hw_mesh_triangulate_face(NULL, f0, &n_out), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_garbage_collect(NULL, NULL), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK(out_v.idx == 4242 && out_f.idx == 4242 && out_h.idx == 4242 && n_out == 4242);
  CHECK(hw_mesh_n_vertices(mesh) == n_v && hw_mesh_n_faces(mesh) == n_f &&
        hw_mesh_n_edges(mesh) == n_e);
  CHECK(hw_mesh_vertex_position(mesh, live_v, xyz) == HW_OK && xyz[0] == 1 && xyz[2] == 1);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
}

static void thread_count(void) {
  hw_mesh *mesh = NULL;
  CHECK(hw_set_thread_count(1) == HW_OK);
  mesh = cube();
  hw_mesh_free(mesh);
  CHECK(hw_set_thread_count(2) == HW_OK);
  mesh = cube();
  hw_mesh_free(mesh);
  CHECK(hw_set_thread_count(0) == HW_OK);
  /* Above the documented maximum: refused, naming the count and the maximum; the library goes
   * on working with the setting it had. */
  CHECK(HW_MAX_THREAD_COUNT >= 64);
  CHECK_STATUS(hw_set_thread_count(HW_MAX_THREAD_COUNT + 1), HW_ERR_INVALID_INPUT,
               "is above the maximum");
  CHECK_STATUS(hw_set_thread_count(SIZE_MAX), HW_ERR_INVALID_INPUT, "thread count");
  CHECK(last_error_contains("18446744073709551615") || last_error_contains("4294967295"));
  mesh = cube();
  CHECK(hw_mesh_n_faces(mesh) == 6);
  hw_mesh_free(mesh);
}

/* A quad 0-1-2-3 (corners from `start` on) closed into a pillow by triangles 0-2-1 and 0-3-2:
 * its diagonal 0-2 is an edge already. */
static hw_mesh *pillow(uint32_t start) {
  static const double positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint32_t sizes[] = {4, 3, 3};
  uint32_t faces[] = {0, 0, 0, 0, 0, 2, 1, 0, 3, 2};
  uint32_t k;
  hw_mesh *mesh = NULL;
  for (k = 0; k < 4; ++k) faces[k] = (start + k) % 4;
  CHECK(hw_mesh_from_indexed(positions, 4, sizes, 3, faces, 10, HW_BUILD_POLICY_STRICT, &mesh,
                             NULL) == HW_OK);
  return mesh;
}

/* The half-edge of face `f` into vertex `v`. */
static hw_halfedge into_vertex(const hw_mesh *mesh, hw_face f, uint32_t v) {
  hw_halfedge h = hw_mesh_face_halfedge(mesh, f);
  while (hw_mesh_he_target(mesh, h).idx != v) h = hw_mesh_he_next(mesh, h);
  return h;
}

/* Before: hw_mesh_triangulate_face refused the quad from 2 of its 4 start corners (its
 * triangulation's diagonal was the edge 0-2), hw_mesh_split_face joined the two corners of one
 * vertex (an edge from a vertex to itself) and triangulating that face did too. */
static void existing_edges_and_repeated_corners(void) {
  hw_face quad = {0};
  hw_halfedge h0, h1, made;
  size_t n_tri = 0;
  uint32_t start;
  hw_winged *winged = hw_winged_new();
  hw_wvertex v0, v1, v2;
  hw_wface point_face;
  hw_wedge edge;
  hw_mesh *struts = NULL;
  const double origin[3] = {0, 0, 0}, east[3] = {1, 0, 0}, north_east[3] = {1, 1, 0};

  for (start = 0; start < 4; ++start) {
    hw_mesh *mesh = pillow(start);
    CHECK(hw_mesh_triangulate_face(mesh, quad, &n_tri) == HW_OK && n_tri == 2);
    CHECK(hw_mesh_n_edges(mesh) == 6 && hw_mesh_check(mesh) == HW_OK);
    hw_mesh_free(mesh);
  }
  {
    hw_mesh *mesh = pillow(0);
    h0 = into_vertex(mesh, quad, 0);
    h1 = into_vertex(mesh, quad, 2);
    CHECK_STATUS(hw_mesh_split_face(mesh, h0, h1, &made), HW_ERR_REFUSED, "already joined");
    CHECK(hw_mesh_n_edges(mesh) == 5 && hw_mesh_check(mesh) == HW_OK);
    hw_mesh_free(mesh);
  }

  /* A path of two struts v0-v1-v2: its face's loop v0 v1 v2 v1 visits v1 twice. */
  CHECK(hw_winged_mvfs(winged, origin, &v0, &point_face) == HW_OK);
  CHECK(hw_winged_mev(winged, point_face, v0, east, &edge, &v1) == HW_OK);
  CHECK(hw_winged_mev(winged, point_face, v1, north_east, &edge, &v2) == HW_OK);
  CHECK(hw_winged_to_mesh(winged, &struts) == HW_OK);
  h0 = into_vertex(struts, quad, v1.idx);
  h1 = hw_mesh_he_next(struts, hw_mesh_he_next(struts, h0));
  CHECK(hw_mesh_he_target(struts, h1).idx == v1.idx);
  CHECK_STATUS(hw_mesh_split_face(struts, h0, h1, &made), HW_ERR_REFUSED, "one vertex");
  CHECK(hw_mesh_n_edges(struts) == 2);
  CHECK(hw_mesh_triangulate_face(struts, quad, &n_tri) == HW_OK && n_tri == 2);
  CHECK(hw_mesh_n_edges(struts) == 3 && hw_mesh_check(struts) == HW_OK);
  hw_mesh_free(struts);
  hw_winged_free(winged);
}

int main(void) {
  normals();
  editing();
  existing_edges_and_repeated_corners();
  collapse();
  deleted_elements_and_null_outputs();
  thread_count();
  return check_summary("test_editing");
}
