/* The mesh doctor through the C API: a cube is a closed polyhedron; a bow tie, a duplicate face
 * (which also overlaps its original), a copied vertex and a T-junction are each named with their
 * elements; every call's bad
 * arguments are refused without writing outputs. */
#include <math.h>
#include <stdlib.h>

#include "check.h"

/* The cube [-1, 1]^3, six quads facing outward. */
static const double cube_positions[] = {-1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1,
                                        -1, -1, 1,  1, -1, 1,  -1, 1, 1,  1, 1, 1};
static const uint32_t cube_sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t cube_indices[] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                        2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};

static void a_cube_is_a_closed_polyhedron(void) {
  hw_doctor_report *report = NULL;
  hw_doctor_verdict verdict;
  hw_doctor_component component;
  size_t n = 0;
  CHECK(hw_doctor_examine_indexed(cube_positions, 8, cube_sizes, 6, cube_indices, 24, NULL,
                                  &report) == HW_OK);
  CHECK(hw_doctor_report_verdict(report, &verdict) == HW_OK);
  CHECK(verdict.manifold && verdict.closed && verdict.oriented && verdict.closed_polyhedron);
  CHECK(verdict.reason == NULL);
  CHECK(hw_doctor_report_n_components(report, &n) == HW_OK && n == 1);
  CHECK(hw_doctor_report_component(report, 0, &component) == HW_OK);
  CHECK(component.n_faces == 6 && component.n_edges == 12 && component.n_vertices == 8);
  CHECK(component.euler_characteristic == 2 && component.genus == 0);
  CHECK(component.closed && component.manifold && component.orientable);
  CHECK(component.consistently_oriented && component.outward == 1);
  CHECK(component.volume == 8.0 && component.area == 24.0);
  CHECK(component.bounding_box[0] == -1.0 && component.bounding_box[5] == 1.0);
  CHECK(hw_doctor_report_n_boundary_loops(report, &n) == HW_OK && n == 0);
  CHECK(hw_diagnostic_is_clean(hw_doctor_report_diagnostic(report)));
  hw_doctor_report_free(report);

  /* The same through a mesh. */
  {
    hw_mesh *mesh = NULL;
    CHECK(hw_mesh_from_indexed(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                               HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
    CHECK(hw_doctor_examine_mesh(mesh, NULL, &report) == HW_OK);
    CHECK(hw_doctor_report_verdict(report, &verdict) == HW_OK && verdict.closed_polyhedron);
    hw_doctor_report_free(report);
    hw_mesh_free(mesh);
  }
}

/* Two squares side by side whose shared side is split on the right one only (vertex 6 is a
 * T-vertex on edge 1-2), a triangle touching the left square at vertex 0 only, face 5 a copy of
 * that triangle, and vertex 10 a copy of vertex 3's position. */
static const double broken_positions[] = {0, 0, 0, 1, 0, 0, 1, 1,   0, 0,  1,    0,
                                          2, 0, 0, 2, 1, 0, 1, 0.5, 0, -1, 0,    0,
                                          0, -1, 0, 5, 5, 5, 0, 1,  0};
static const uint32_t broken_sizes[] = {4, 3, 3, 3, 3, 3};
static const uint32_t broken_indices[] = {0, 1, 2, 3, 1, 4, 6, 6, 4, 5,
                                          6, 5, 2, 0, 7, 8, 0, 7, 8};

static void defects_are_named(void) {
  hw_doctor_report *report = NULL;
  hw_doctor_verdict verdict;
  const uint32_t *ids = NULL;
  size_t n = 0, per_item = 0, n_fans = 0, n_faces = 0;
  uint32_t vertex = 0, face = 0;
  double perimeter = 0;
  char *text;
  CHECK(hw_doctor_examine_indexed(broken_positions, 11, broken_sizes, 6, broken_indices, 19,
                                  NULL, &report) == HW_OK);
  CHECK(hw_doctor_report_verdict(report, &verdict) == HW_OK);
  CHECK(!verdict.manifold && !verdict.closed && !verdict.closed_polyhedron);
  CHECK(verdict.reason != NULL && strstr(verdict.reason, "manifold") != NULL);

  CHECK(hw_doctor_report_finding(report, HW_DOCTOR_FINDING_T_VERTICES, &ids, &n, &per_item) ==
        HW_OK);
  CHECK(n == 1 && per_item == 4);
  CHECK(ids[0] == 6 && ids[1] == 1 && ids[2] == 2 && ids[3] == 0);
  CHECK(hw_doctor_report_finding(report, HW_DOCTOR_FINDING_DUPLICATE_POSITIONS, &ids, &n,
                                 &per_item) == HW_OK);
  CHECK(n == 1 && per_item == 2 && ids[0] == 10 && ids[1] == 3);
  CHECK(hw_doctor_report_finding(report, HW_DOCTOR_FINDING_DUPLICATE_FACES, &ids, &n, &per_item) ==
        HW_OK);
  CHECK(n == 1 && ids[0] == 5 && ids[1] == 4);
  /* A face on the same three vertices as another overlaps it entirely; the right square's
   * three triangles touch the left square at the T-vertex 6, which is not a vertex of it. */
  CHECK(hw_doctor_report_finding(report, HW_DOCTOR_FINDING_SELF_INTERSECTIONS, &ids, &n,
                                 &per_item) == HW_OK);
  CHECK(n == 4 && per_item == 2);
  CHECK(ids[0] == 0 && ids[1] == 1 && ids[2] == 0 && ids[3] == 2 && ids[4] == 0 && ids[5] == 3);
  CHECK(ids[6] == 4 && ids[7] == 5);
  CHECK(strcmp(hw_doctor_finding_name(HW_DOCTOR_FINDING_SELF_INTERSECTIONS),
               "intersecting face pairs") == 0);
  CHECK(hw_doctor_report_finding(report, HW_DOCTOR_FINDING_NEEDLES, &ids, &n, &per_item) == HW_OK);
  CHECK(n == 0 && ids == NULL && per_item == 1);
  for (hw_doctor_finding kind = HW_DOCTOR_FINDING_FIRST;
       kind < HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT; ++kind) {
    CHECK(hw_doctor_finding_name(kind) != NULL);
    CHECK(hw_doctor_report_finding(report, kind, &ids, &n, &per_item) == HW_OK && per_item >= 1);
  }
  CHECK(hw_doctor_finding_name(HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT) == NULL);
  CHECK(hw_doctor_finding_name(HW_DOCTOR_FINDING_FIRST - 1) == NULL);
  /* A diagnostic list is not a finding: refused, not read as another kind. */
  CHECK_STATUS(
      hw_doctor_report_finding(report, HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL, &ids, &n, &per_item),
      HW_ERR_INVALID_INPUT, "unknown doctor finding");

  /* Vertex 0, where the triangles touch the left square, has two fans; so have vertices 1 and 2,
   * where the right square's triangles meet the left square at a corner only (the crack). */
  CHECK(hw_doctor_report_n_vertex_fans(report, &n) == HW_OK && n == 3);
  CHECK(hw_doctor_report_vertex_fan(report, 0, 1, &vertex, &n_fans, &ids, &n_faces) == HW_OK);
  CHECK(vertex == 0 && n_fans == 2 && n_faces == 2 && ids[0] == 4 && ids[1] == 5);
  CHECK(hw_diagnostic_ids(hw_doctor_report_diagnostic(report),
                          HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES, &ids, &n) == HW_OK);
  CHECK(n == 3 && ids[0] == 0 && ids[1] == 1 && ids[2] == 2);

  /* Boundary loops: the two squares' rim, and the triangle pair's. */
  CHECK(hw_doctor_report_n_boundary_loops(report, &n) == HW_OK && n >= 2);
  CHECK(hw_doctor_report_boundary_loop(report, 0, &ids, &n, &perimeter, &face) == HW_OK);
  CHECK(n >= 3 && perimeter > 0 && face == 0);

  /* Text and JSON, with the copy-into-buffer protocol. */
  CHECK(hw_doctor_report_text(report, NULL, 0, &n) == HW_ERR_BUFFER_TOO_SMALL && n > 1);
  text = (char *)malloc(n);
  CHECK(text != NULL && hw_doctor_report_text(report, text, n, NULL) == HW_OK);
  if (text) {
    CHECK(strstr(text, "T-vertices: v6 on v1-v2") != NULL);
    free(text);
  }
  CHECK(hw_doctor_report_json(report, NULL, 0, &n) == HW_ERR_BUFFER_TOO_SMALL);
  text = (char *)malloc(n);
  CHECK(text != NULL && hw_doctor_report_json(report, text, n, NULL) == HW_OK);
  if (text) {
    CHECK(strstr(text, "\"t_vertices\":[{\"vertex\":6,\"edge\":[1,2],\"face\":0}]") != NULL);
    free(text);
  }
  hw_doctor_report_free(report);
}

static void bad_arguments_are_refused(void) {
  hw_doctor_report *report = NULL, *sentinel = (hw_doctor_report *)(uintptr_t)0x1234;
  hw_doctor_options options = hw_doctor_options_default();
  hw_doctor_verdict verdict;
  hw_doctor_component component;
  const uint32_t *ids = NULL;
  size_t n = 0, per_item = 0;
  uint32_t vertex = 0, face = 0;
  double perimeter = 0;
  CHECK(options.relative_tolerance == 1e-9 && options.long_edge_ratio == 10.0);

  options.cap_angle_degrees = NAN;
  report = sentinel;
  CHECK_STATUS(hw_doctor_examine_indexed(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                         &options, &report),
               HW_ERR_INVALID_INPUT, "cap_angle_degrees");
  CHECK(report == sentinel);
  CHECK_STATUS(hw_doctor_examine_indexed(cube_positions, 8, cube_sizes, 6, cube_indices, 23,
                                         NULL, &report),
               HW_ERR_INVALID_INPUT, "malformed face list");
  CHECK_STATUS(hw_doctor_examine_indexed(NULL, 8, cube_sizes, 6, cube_indices, 24, NULL, &report),
               HW_ERR_NULL_ARGUMENT, "positions");
  CHECK_STATUS(hw_doctor_examine_indexed(cube_positions, 8, cube_sizes, 6, cube_indices, 24,
                                         NULL, NULL),
               HW_ERR_NULL_ARGUMENT, "out_report");
  CHECK_STATUS(hw_doctor_examine_mesh(NULL, NULL, &report), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK(report == sentinel);

  report = NULL;
  CHECK(hw_doctor_examine_indexed(cube_positions, 8, cube_sizes, 6, cube_indices, 24, NULL,
                                  &report) == HW_OK);
  CHECK_STATUS(hw_doctor_report_finding(report, 99u, &ids, &n, &per_item), HW_ERR_INVALID_INPUT,
               "unknown doctor finding 99");
  CHECK_STATUS(hw_doctor_report_finding(NULL, HW_DOCTOR_FINDING_NEEDLES, &ids, &n, &per_item),
               HW_ERR_NULL_ARGUMENT, "report");
  CHECK_STATUS(hw_doctor_report_finding(report, HW_DOCTOR_FINDING_NEEDLES, NULL, &n, &per_item),
               HW_ERR_NULL_ARGUMENT, "out_ids");
  CHECK_STATUS(hw_doctor_report_verdict(NULL, &verdict), HW_ERR_NULL_ARGUMENT, "report");
  CHECK_STATUS(hw_doctor_report_verdict(report, NULL), HW_ERR_NULL_ARGUMENT, "out_verdict");
  CHECK_STATUS(hw_doctor_report_component(report, 1, &component), HW_ERR_INVALID_INPUT,
               "component 1 of 1");
  CHECK_STATUS(hw_doctor_report_n_components(report, NULL), HW_ERR_NULL_ARGUMENT, "out_count");
  CHECK_STATUS(hw_doctor_report_boundary_loop(report, 0, &ids, &n, &perimeter, &face),
               HW_ERR_INVALID_INPUT, "boundary loop 0 of 0");
  CHECK_STATUS(hw_doctor_report_vertex_fan(report, 0, 0, &vertex, &n, &ids, &n), HW_ERR_INVALID_INPUT,
               "non-manifold vertex 0 of 0");
  CHECK_STATUS(hw_doctor_report_n_vertex_fans(NULL, &n), HW_ERR_NULL_ARGUMENT, "report");
  CHECK_STATUS(hw_doctor_report_n_boundary_loops(report, NULL), HW_ERR_NULL_ARGUMENT, "out_count");
  CHECK_STATUS(hw_doctor_report_text(NULL, NULL, 0, &n), HW_ERR_NULL_ARGUMENT, "report");
  CHECK_STATUS(hw_doctor_report_json(NULL, NULL, 0, &n), HW_ERR_NULL_ARGUMENT, "report");
  CHECK(hw_doctor_report_diagnostic(NULL) == NULL);
  hw_doctor_report_free(report);
  hw_doctor_report_free(report);
  CHECK(last_error_contains("already freed"));
  hw_doctor_report_free(NULL);
}

/* Self-intersections on their own: the broken faces above, then a degenerate triangle, which is
 * reported as (f, f); a NaN corner and a bad index are refused with the face named. */
static void self_intersections_alone(void) {
  hw_face_pairs *pairs = NULL;
  const uint32_t *ids = NULL;
  size_t n = 0;
  static const double flat[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0};
  static const uint32_t flat_sizes[] = {3, 3};
  static const uint32_t flat_indices[] = {0, 1, 2, 0, 1, 3};
  double with_nan[12];
  uint32_t out_of_range[6];
  CHECK(hw_self_intersections_indexed(broken_positions, 11, broken_sizes, 6, broken_indices, 19,
                                      &pairs) == HW_OK);
  CHECK(hw_face_pairs_view(pairs, &ids, &n) == HW_OK && n == 4);
  CHECK(ids[0] == 0 && ids[1] == 1 && ids[6] == 4 && ids[7] == 5);
  hw_face_pairs_free(pairs);
  CHECK(hw_self_intersections_indexed(flat, 4, flat_sizes, 2, flat_indices, 6, &pairs) == HW_OK);
  CHECK(hw_face_pairs_view(pairs, &ids, &n) == HW_OK && n == 1 && ids[0] == 0 && ids[1] == 0);
  hw_face_pairs_free(pairs);

  memcpy(with_nan, flat, sizeof flat);
  with_nan[10] = NAN;
  pairs = NULL;
  CHECK_STATUS(hw_self_intersections_indexed(with_nan, 4, flat_sizes, 2, flat_indices, 6, &pairs),
               HW_ERR_INVALID_INPUT, "face 1");
  CHECK(pairs == NULL);
  memcpy(out_of_range, flat_indices, sizeof flat_indices);
  out_of_range[5] = 9;
  CHECK_STATUS(hw_self_intersections_indexed(flat, 4, flat_sizes, 2, out_of_range, 6, &pairs),
               HW_ERR_INVALID_INPUT, "vertex 9");
  CHECK_STATUS(hw_self_intersections_indexed(flat, 4, flat_sizes, 2, flat_indices, 6, NULL),
               HW_ERR_NULL_ARGUMENT, "out_pairs");
  CHECK_STATUS(hw_face_pairs_view(NULL, &ids, &n), HW_ERR_NULL_ARGUMENT, "pairs");
  hw_face_pairs_free(NULL);
}

/* Findings drawn over the broken faces: the intersecting pairs fill their 5 faces; the
 * T-vertex is a point on its edge; the duplicate position a point with an edge to its
 * original; a report of another list is refused. */
static void findings_are_drawable(void) {
  hw_doctor_report *report = NULL;
  hw_render_buffers *buffers = NULL;
  const float *floats = NULL;
  const uint32_t *ids = NULL;
  size_t n = 0;
  float low[3], high[3];
  CHECK(hw_doctor_examine_indexed(broken_positions, 11, broken_sizes, 6, broken_indices, 19,
                                  NULL, &report) == HW_OK);
  CHECK(hw_render_buffers_from_finding(report, HW_DOCTOR_FINDING_SELF_INTERSECTIONS,
                                       broken_positions, 11, broken_sizes, 6, broken_indices, 19,
                                       &buffers) == HW_OK);
  /* Faces 0 (a square: 4 corners, 2 triangles) and 1, 2, 3, 4, 5 (triangles). */
  CHECK(hw_render_buffers_n_vertices(buffers) == 4 + 5 * 3);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_TRIANGLE_FACES, &ids, &n) == HW_OK);
  CHECK(n == 7 && ids[0] == 0 && ids[1] == 0 && ids[2] == 1 && ids[6] == 5);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_POINTS, &floats, &n) == HW_OK && n == 0);
  CHECK(hw_render_buffers_bounds(buffers, low, high) == HW_OK);
  CHECK(low[0] == -1 && low[1] == -1 && high[0] == 2 && high[1] == 1);
  hw_render_buffers_free(buffers);

  CHECK(hw_render_buffers_from_finding(report, HW_DOCTOR_FINDING_T_VERTICES, broken_positions, 11,
                                       broken_sizes, 6, broken_indices, 19, &buffers) == HW_OK);
  CHECK(hw_render_buffers_n_vertices(buffers) == 0);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_POINTS, &floats, &n) == HW_OK && n == 3);
  CHECK(floats[0] == 1 && floats[1] == 0.5f && floats[2] == 0);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_POINT_SOURCES, &ids, &n) == HW_OK);
  CHECK(n == 1 && ids[0] == 0);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_BOUNDARY, &floats, &n) == HW_OK &&
        n == 6);
  CHECK(floats[0] == 1 && floats[1] == 0 && floats[3] == 1 && floats[4] == 1);
  hw_render_buffers_free(buffers);

  CHECK(hw_render_buffers_from_finding(report, HW_DOCTOR_FINDING_DUPLICATE_POSITIONS,
                                       broken_positions, 11, broken_sizes, 6, broken_indices, 19,
                                       &buffers) == HW_OK);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_POINTS, &floats, &n) == HW_OK && n == 3);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_BOUNDARY, &floats, &n) == HW_OK &&
        n == 6);
  hw_render_buffers_free(buffers);

  buffers = NULL;
  CHECK_STATUS(
      hw_render_buffers_from_finding(report, HW_DOCTOR_FINDING_SELF_INTERSECTIONS, cube_positions,
                                     8, cube_sizes, 1, cube_indices, 4, &buffers),
      HW_ERR_INVALID_INPUT, "names face 1, but the face list has 1");
  CHECK_STATUS(
      hw_render_buffers_from_finding(report, HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES, broken_positions,
                                     11, broken_sizes, 6, broken_indices, 19, &buffers),
      HW_ERR_INVALID_INPUT, "unknown doctor finding");
  CHECK_STATUS(hw_render_buffers_from_finding(NULL, HW_DOCTOR_FINDING_NEEDLES, broken_positions, 11,
                                              broken_sizes, 6, broken_indices, 19, &buffers),
               HW_ERR_NULL_ARGUMENT, "report");
  CHECK(buffers == NULL);
  hw_doctor_report_free(report);
}

int main(void) {
  a_cube_is_a_closed_polyhedron();
  findings_are_drawable();
  self_intersections_alone();
  defects_are_named();
  bad_arguments_are_refused();
  return check_summary("test_doctor");
}
