/* Diagnostics through the C API: what a bulk build reports on broken input under each policy,
 * the analysis without a build, the views and summary with their bad arguments; plus the calls
 * no other test reaches (edge circulation, face components, deleting an edge, writing a file). */
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* Three triangles on the edge 0-1 (non-manifold), a fourth face with a repeated vertex and a
 * NaN-free isolated vertex 6. */
static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 2, 2, 2, 5, 5, 5};
static const uint32_t sizes[] = {3, 3, 3, 3};
static const uint32_t indices[] = {0, 1, 2, 1, 0, 3, 0, 1, 4, 2, 5, 2};

static void diagnose_without_building(void) {
  hw_diagnostic *d = NULL;
  const uint32_t *ids = NULL, *faces = NULL;
  size_t n = 0, n_faces = 0, needed = 0;
  uint32_t ends[2] = {0, 0};
  char *text;
  CHECK(hw_diagnose_indexed(positions, 7, sizes, 4, indices, 12, &d) == HW_OK);
  CHECK(!hw_diagnostic_is_clean(d));
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 3);
  /* The findings describe the input, not a build: only vertex 6 is in no face (vertex 5 is in
   * the malformed face), and nothing was left out. */
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 6);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_SKIPPED_FACES, &ids, &n) == HW_OK);
  CHECK(n == 0);
  CHECK(hw_diagnostic_n_edges(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, &n) == HW_OK && n == 1);
  CHECK(hw_diagnostic_edge(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 0, ends, &faces, &n_faces) ==
        HW_OK);
  CHECK(ends[0] == 0 && ends[1] == 1 && n_faces == 3);
  CHECK(faces[0] == 0 && faces[1] == 1 && faces[2] == 2);
  CHECK(hw_diagnostic_n_edges(d, HW_DIAGNOSTIC_EDGES_INCONSISTENT, &n) == HW_OK);

  /* The summary, with the copy-into-buffer protocol. */
  CHECK(hw_diagnostic_summary(d, NULL, 0, &needed) == HW_ERR_BUFFER_TOO_SMALL && needed > 1);
  text = (char *)malloc(needed);
  CHECK(text != NULL && hw_diagnostic_summary(d, text, needed, NULL) == HW_OK);
  if (text) {
    CHECK(strstr(text, "non-manifold edge (3+ faces)") != NULL);
    CHECK(strstr(text, "(v0-v1 in faces f0 f1 f2)") != NULL);
    CHECK(strstr(text, "repeated vertex: f3") != NULL);
    free(text);
  }

  /* Bad arguments. */
  CHECK_STATUS(hw_diagnostic_ids(d, 99u, &ids, &n), HW_ERR_INVALID_INPUT, "list 99");
  CHECK_STATUS(hw_diagnostic_ids(NULL, HW_DIAGNOSTIC_LIST_SKIPPED_FACES, &ids, &n),
               HW_ERR_NULL_ARGUMENT, "diagnostic");
  CHECK_STATUS(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_SKIPPED_FACES, NULL, &n),
               HW_ERR_NULL_ARGUMENT, "out_ids");
  CHECK_STATUS(hw_diagnostic_edge(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 5, ends, &faces, &n_faces),
               HW_ERR_INVALID_INPUT, "edge 5");
  CHECK_STATUS(hw_diagnostic_edge(d, 7u, 0, ends, &faces, &n_faces), HW_ERR_INVALID_INPUT,
               "edge list 7");
  {
    /* NULL for the diagnostic or any output, or an index just past the list: refused, and no
     * output is written. */
    static const uint32_t sentinel_faces[1] = {0};
    ends[0] = ends[1] = 77;
    faces = sentinel_faces;
    n_faces = 77;
    CHECK_STATUS(
        hw_diagnostic_edge(NULL, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 0, ends, &faces, &n_faces),
        HW_ERR_NULL_ARGUMENT, "diagnostic");
    CHECK_STATUS(hw_diagnostic_edge(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 0, NULL, &faces, &n_faces),
                 HW_ERR_NULL_ARGUMENT, "out_vertices");
    CHECK_STATUS(hw_diagnostic_edge(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 0, ends, NULL, &n_faces),
                 HW_ERR_NULL_ARGUMENT, "out_faces");
    CHECK_STATUS(hw_diagnostic_edge(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 0, ends, &faces, NULL),
                 HW_ERR_NULL_ARGUMENT, "out_n_faces");
    CHECK_STATUS(hw_diagnostic_edge(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, 1, ends, &faces, &n_faces),
                 HW_ERR_INVALID_INPUT, "edge 1 of a list of 1");
    CHECK(ends[0] == 77 && ends[1] == 77 && faces == sentinel_faces && n_faces == 77);
  }
  CHECK_STATUS(hw_diagnostic_n_edges(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, NULL),
               HW_ERR_NULL_ARGUMENT, "out_count");
  CHECK_STATUS(hw_diagnostic_summary(NULL, NULL, 0, NULL), HW_ERR_NULL_ARGUMENT, "diagnostic");
  CHECK(!hw_diagnostic_is_clean(NULL));
  CHECK_STATUS(hw_diagnose_indexed(NULL, 7, sizes, 4, indices, 12, &d), HW_ERR_NULL_ARGUMENT,
               "positions");
  CHECK_STATUS(hw_diagnose_indexed(positions, 7, sizes, 4, indices, 12, NULL),
               HW_ERR_NULL_ARGUMENT, "out_diagnostic");
  hw_diagnostic_free(d);
  hw_diagnostic_free(d);
  CHECK(last_error_contains("already freed"));
  hw_diagnostic_free(NULL);
}

static void policies_report_what_they_did(void) {
  hw_mesh *mesh = NULL;
  hw_diagnostic *d = NULL;
  const uint32_t *ids = NULL;
  size_t n = 0;
  /* Skip: the malformed face and the third face on the edge go; the diagnostic says which. */
  CHECK(hw_mesh_from_indexed(positions, 7, sizes, 4, indices, 12, HW_BUILD_POLICY_SKIP, &mesh,
                             &d) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 2);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_SKIPPED_FACES, &ids, &n) == HW_OK);
  CHECK(n == 2 && ids[0] == 2 && ids[1] == 3);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_diagnostic_free(d);
  hw_mesh_free(mesh);
  /* Repair keeps every face it can: the face whose corners collapse below three is left out
   * and listed, the three faces on the edge are kept by copying the edge's vertices. */
  mesh = NULL;
  d = NULL;
  CHECK(hw_mesh_from_indexed(positions, 7, sizes, 4, indices, 12, HW_BUILD_POLICY_REPAIR, &mesh,
                             &d) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 3 && hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_SKIPPED_FACES, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 3);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_REORIENTED_FACES, &ids, &n) == HW_OK);
  hw_diagnostic_free(d);
  hw_mesh_free(mesh);
  /* Strict refuses, and still hands out the refusal's diagnostic. */
  mesh = NULL;
  d = NULL;
  CHECK_STATUS(
      hw_mesh_from_indexed(positions, 7, sizes, 4, indices, 12, HW_BUILD_POLICY_STRICT, &mesh, &d),
      HW_ERR_INVALID_INPUT, "repeated vertex");
  CHECK(mesh == NULL && d != NULL);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 3);
  CHECK(hw_diagnostic_n_edges(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, &n) == HW_OK && n == 1);
  hw_diagnostic_free(d);
  /* A cube with five of six faces flipped comes back whole and facing outward. */
  {
    static const double cube[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    static const uint32_t quads[] = {4, 4, 4, 4, 4, 4};
    /* Outward: bottom 0 3 2 1, top 4 5 6 7, front 0 1 5 4, right 1 2 6 5, back 2 3 7 6,
     * left 3 0 4 7; all but the bottom given reversed. */
    static const uint32_t corners[] = {0, 3, 2, 1, 7, 6, 5, 4, 4, 5, 1, 0,
                                       5, 6, 2, 1, 6, 7, 3, 2, 7, 4, 0, 3};
    double normals[18], volume = 0;
    CHECK(hw_mesh_from_indexed(cube, 8, quads, 6, corners, 24, HW_BUILD_POLICY_REPAIR, &mesh, &d) ==
          HW_OK);
    CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_REORIENTED_FACES, &ids, &n) == HW_OK);
    CHECK(n == 5 && ids[0] == 1 && ids[4] == 5);
    CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_VERTEX_COPIES, &ids, &n) == HW_OK && n == 0);
    CHECK(hw_mesh_face_normals(mesh, normals, 6, NULL) == HW_OK);
    for (uint32_t f = 0; f < 6; ++f) {
      hw_face face = {f};
      hw_vertex corner = hw_mesh_he_origin(mesh, hw_mesh_face_halfedge(mesh, face));
      double p[3];
      const double *normal = normals + 3 * f;
      double outward;
      CHECK(hw_mesh_vertex_position(mesh, corner, p) == HW_OK);
      /* Outward normals point away from the cube's centre (0.5, 0.5, 0.5). */
      outward = normal[0] * (p[0] - 0.5) + normal[1] * (p[1] - 0.5) + normal[2] * (p[2] - 0.5);
      CHECK(outward > 0);
      volume += outward;
    }
    CHECK(volume > 0);
    hw_diagnostic_free(d);
    hw_mesh_free(mesh);
  }
  /* Without the malformed face, Repair keeps all three faces by copying the edge's vertices. */
  CHECK(hw_mesh_from_indexed(positions, 7, sizes, 3, indices, 9, HW_BUILD_POLICY_REPAIR, &mesh,
                             &d) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 3 && hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_diagnostic_ids(d, HW_DIAGNOSTIC_LIST_VERTEX_COPIES, &ids, &n) == HW_OK && n >= 1);
  CHECK(hw_mesh_n_vertices(mesh) == 7 + n);
  hw_diagnostic_free(d);
  hw_mesh_free(mesh);
}

static void remaining_calls(void) {
  /* Two quads side by side. */
  static const double quad_positions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  static const uint32_t quad_sizes[] = {4, 4};
  static const uint32_t quad_indices[] = {0, 1, 4, 3, 1, 2, 5, 4};
  hw_mesh *mesh = NULL, *again = NULL;
  hw_circulator c;
  hw_edge e, middle = {0};
  hw_face f0 = {0}, bad_face = {9};
  hw_vertex v1 = {1};
  uint32_t components[2];
  size_t n = 0, count = 0;
  char path[512];
  CHECK(hw_mesh_from_indexed(quad_positions, 6, quad_sizes, 2, quad_indices, 8,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  CHECK(hw_circ_around_vertex(mesh, v1, HW_CIRCULATOR_KIND_EDGES, &c) == HW_OK);
  while (hw_circ_next_edge(&c, &e)) {
    if (!hw_mesh_edge_is_boundary(mesh, e)) middle = e;
    ++count;
  }
  CHECK(count == 3);
  CHECK(hw_mesh_face_is_boundary(mesh, f0));
  CHECK(!hw_mesh_face_is_boundary(mesh, bad_face) && last_error_contains("face id 9"));
  CHECK(hw_mesh_face_components(mesh, components, 2, &n) == HW_OK && n == 2);
  CHECK(components[0] == 0 && components[1] == 0);
  CHECK_STATUS(hw_mesh_face_components(mesh, components, 1, &n), HW_ERR_BUFFER_TOO_SMALL,
               "2 are needed");
  {
    /* A misaligned output array is refused like a misaligned input one; the needed size still
     * comes back and the memory is untouched. */
    uint64_t storage[2] = {0, 0};
    uint32_t *misaligned = (uint32_t *)(void *)((unsigned char *)storage + 1);
    n = 0;
    CHECK_STATUS(hw_mesh_face_components(mesh, misaligned, 2, &n), HW_ERR_INVALID_INPUT,
                 "argument `out_components` is misaligned");
    CHECK(n == 2 && storage[0] == 0 && storage[1] == 0);
  }

  /* Write, read back, same counts. */
  snprintf(path, sizeof path, "%s/halfwing_test_diagnostics.off", TEST_TMP_DIR);
  CHECK(hw_mesh_write(mesh, path) == HW_OK);
  CHECK(hw_mesh_read(path, HW_BUILD_POLICY_STRICT, &again, NULL) == HW_OK);
  CHECK(again != NULL && hw_mesh_n_faces(again) == 2 && hw_mesh_n_vertices(again) == 6);
  hw_mesh_free(again);
  CHECK_STATUS(hw_mesh_write(mesh, NULL), HW_ERR_NULL_ARGUMENT, "path");
  CHECK_STATUS(hw_mesh_write(mesh, "/nonexistent/dir/x.off"), HW_ERR_IO, "cannot create");

  /* Deleting the shared edge takes both faces with it. */
  CHECK(hw_mesh_delete_edge(mesh, middle, true) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 0 && hw_mesh_check(mesh) == HW_OK);
  CHECK_STATUS(hw_mesh_delete_edge(mesh, middle, true), HW_ERR_INVALID_HANDLE, "deleted");
  hw_mesh_free(mesh);
}

/* A million copies of one triangle put a million faces on each of its three edges: the summary
 * and the build's error message name the first few and count the rest, within
 * HW_MAX_MESSAGE_SIZE. */
static void long_lists_are_counted_not_listed(void) {
  enum { N_FACES = 1000000 };
  static const double triangle[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  uint32_t *copy_sizes = (uint32_t *)malloc(N_FACES * sizeof(uint32_t));
  uint32_t *copy_indices = (uint32_t *)malloc(3 * N_FACES * sizeof(uint32_t));
  static char text[HW_MAX_MESSAGE_SIZE];
  hw_diagnostic *d = NULL;
  hw_mesh *mesh = NULL;
  size_t i, needed = 0;
  CHECK(copy_sizes != NULL && copy_indices != NULL);
  if (copy_sizes == NULL || copy_indices == NULL) {
    free(copy_sizes);
    free(copy_indices);
    return;
  }
  for (i = 0; i < N_FACES; ++i) {
    copy_sizes[i] = 3;
    copy_indices[3 * i] = 0;
    copy_indices[3 * i + 1] = 1;
    copy_indices[3 * i + 2] = 2;
  }
  CHECK(hw_diagnose_indexed(triangle, 3, copy_sizes, N_FACES, copy_indices, 3 * N_FACES, &d) ==
        HW_OK);
  CHECK(hw_diagnostic_summary(d, text, sizeof text, &needed) == HW_OK);
  CHECK(needed <= HW_MAX_MESSAGE_SIZE);
  CHECK(strstr(text, "(v0-v1 in faces f0 f1 f2 f3 f4 f5 f6 f7 … and 999992 more)") != NULL);
  hw_diagnostic_free(d);

  CHECK(hw_mesh_from_indexed(triangle, 3, copy_sizes, N_FACES, copy_indices, 3 * N_FACES,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_ERR_NON_MANIFOLD);
  CHECK(mesh == NULL);
  CHECK(hw_last_error_message(text, sizeof text, &needed) == HW_OK);
  CHECK(needed <= HW_MAX_MESSAGE_SIZE);
  CHECK(strstr(text, "not an oriented manifold") != NULL);
  CHECK(strstr(text, "f7 … and 999992 more)") != NULL);
  free(copy_sizes);
  free(copy_indices);
}

/* A face count of 2^32 - 1 is refused before anything proportional to it is allocated: it took
 * a 16 GiB allocation (81 s) before, and aborted under a 4 GiB limit. The sizes array is never
 * read past the refusal. */
static void huge_counts_are_refused_before_allocating(void) {
  hw_mesh *mesh = NULL;
  hw_diagnostic *diagnostic = NULL;
  CHECK_STATUS(hw_mesh_from_indexed(positions, 7, sizes, 0xFFFFFFFFu, indices, 12,
                                    HW_BUILD_POLICY_SKIP, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "4294967295 faces");
  CHECK(mesh == NULL);
  /* The diagnosis describes a list malformed as a whole by its summary alone. */
  CHECK(hw_diagnose_indexed(positions, 7, sizes, 0xFFFFFFFFu, indices, 12, &diagnostic) == HW_OK);
  {
    char text[256];
    size_t needed = 0;
    CHECK(hw_diagnostic_summary(diagnostic, text, sizeof text, &needed) == HW_OK);
    CHECK(strstr(text, "4294967295 faces exceed the 32-bit index range") != NULL);
  }
  hw_diagnostic_free(diagnostic);
}

/* Every list kind has a name; the id lists, the edge lists and the doctor's findings are three
 * separate ranges of values, so a value of the wrong family is refused, never read as another
 * list. */
static void list_kinds_are_named_and_kept_apart(void) {
  hw_diagnostic *d = NULL;
  const uint32_t *ids = NULL;
  size_t n = 0;
  uint32_t list, other;
  CHECK(hw_diagnose_indexed(positions, 7, sizes, 4, indices, 12, &d) == HW_OK);
  for (list = HW_DIAGNOSTIC_LIST_FIRST; list < HW_DIAGNOSTIC_LIST_FIRST + HW_DIAGNOSTIC_LIST_COUNT;
       ++list) {
    CHECK(hw_diagnostic_list_name(list) != NULL);
    CHECK(hw_diagnostic_edges_name(list) == NULL && hw_doctor_finding_name(list) == NULL);
    CHECK(hw_diagnostic_ids(d, list, &ids, &n) == HW_OK);
    for (other = list + 1; other < HW_DIAGNOSTIC_LIST_FIRST + HW_DIAGNOSTIC_LIST_COUNT; ++other)
      CHECK(strcmp(hw_diagnostic_list_name(list), hw_diagnostic_list_name(other)) != 0);
  }
  for (list = HW_DIAGNOSTIC_EDGES_FIRST;
       list < HW_DIAGNOSTIC_EDGES_FIRST + HW_DIAGNOSTIC_EDGES_COUNT; ++list) {
    CHECK(hw_diagnostic_edges_name(list) != NULL);
    CHECK(hw_diagnostic_list_name(list) == NULL && hw_doctor_finding_name(list) == NULL);
    CHECK(hw_diagnostic_n_edges(d, list, &n) == HW_OK);
  }
  CHECK(strcmp(hw_diagnostic_list_name(HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES),
               "isolated vertices") == 0);
  CHECK(strcmp(hw_diagnostic_edges_name(HW_DIAGNOSTIC_EDGES_NON_MANIFOLD),
               "non-manifold edges (3+ faces)") == 0);
  CHECK(hw_diagnostic_list_name(HW_DIAGNOSTIC_LIST_FIRST + HW_DIAGNOSTIC_LIST_COUNT) == NULL);
  CHECK(hw_diagnostic_edges_name(HW_DIAGNOSTIC_EDGES_FIRST + HW_DIAGNOSTIC_EDGES_COUNT) == NULL);
  CHECK_STATUS(hw_diagnostic_ids(d, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, &ids, &n),
               HW_ERR_INVALID_INPUT, "unknown diagnostic list");
  CHECK_STATUS(hw_diagnostic_n_edges(d, HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL, &n),
               HW_ERR_INVALID_INPUT, "unknown diagnostic edge list");
  CHECK_STATUS(hw_diagnostic_ids(d, HW_DOCTOR_FINDING_NEEDLES, &ids, &n), HW_ERR_INVALID_INPUT,
               "unknown diagnostic list");
  hw_diagnostic_free(d);
}

int main(void) {
  list_kinds_are_named_and_kept_apart();
  huge_counts_are_refused_before_allocating();
  diagnose_without_building();
  policies_report_what_they_did();
  remaining_calls();
  long_lists_are_counted_not_listed();
  return check_summary("test_diagnostics");
}
