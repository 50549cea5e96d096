/* The repairs through the C API: each with its report (lists and maps as zero-copy views),
 * refusals that leave the input unchanged and write no output, and stitching a mesh. */
#include <math.h>
#include <stdlib.h>

#include "check.h"

/* Two triangles sharing an edge, the edge's ends given twice (vertices 3 and 4 repeat 1 and
 * 2), an unreferenced vertex 5 and a duplicate of the first triangle, rotated. */
static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 9, 9, 9, 1, 1, 0};
static const uint32_t sizes[] = {3, 3, 3};
static const uint32_t indices[] = {0, 1, 2, 3, 6, 4, 1, 2, 0};

static hw_soup *make_soup(void) {
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(positions, 7, sizes, 3, indices, 9, &soup) == HW_OK);
  return soup;
}

static size_t list_len(const hw_repair_report *report, hw_repair_list list, const uint32_t **ids) {
  size_t n = 0;
  CHECK(hw_repair_report_list(report, list, ids, &n) == HW_OK);
  return n;
}

static void merge_vertices(void) {
  hw_soup *soup = make_soup();
  hw_repair_report *report = NULL;
  CHECK(hw_soup_merge_vertices(soup, 0.0, false, &report) == HW_OK);
  const uint32_t *ids = NULL;
  CHECK(list_len(report, HW_REPAIR_LIST_MERGED_VERTICES, &ids) == 4);
  CHECK(ids[0] == 3 && ids[1] == 1 && ids[2] == 4 && ids[3] == 2);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_VERTICES, &ids) == 2);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_FACES, &ids) == 0 && ids == NULL);
  const hw_index_maps *maps = NULL;
  size_t removed_corners = 99;
  CHECK(hw_repair_report_maps(report, &maps, &removed_corners) == HW_OK);
  CHECK(removed_corners == 0);
  const uint32_t *map = NULL;
  size_t n = 0;
  CHECK(hw_index_maps_view(maps, HW_ELEMENT_KIND_VERTEX, &map, &n) == HW_OK);
  CHECK(n == 7 && map[3] == HW_INVALID_INDEX && map[5] == 3 && map[6] == 4);
  /* The maps belong to the report: freeing them is refused. */
  hw_index_maps_free((hw_index_maps *)maps);
  CHECK(last_error_contains("hw_index_maps"));
  hw_repair_report_free(report);

  const uint32_t *corners = NULL;
  size_t n_vertices = 0, n_corners = 0;
  CHECK(hw_soup_view(soup, NULL, &n_vertices, NULL, NULL, &corners, &n_corners) == HW_OK);
  CHECK(n_vertices == 5 && n_corners == 9);
  CHECK(corners[3] == 1 && corners[4] == 4 && corners[5] == 2);

  /* Then the duplicate face and the unreferenced vertex. */
  CHECK(hw_soup_remove_duplicate_faces(soup, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_DUPLICATE_FACES, &ids) == 2 && ids[0] == 2 && ids[1] == 0);
  hw_repair_report_free(report);
  CHECK(hw_soup_remove_unreferenced_vertices(soup, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_VERTICES, &ids) == 1 && ids[0] == 3);
  hw_repair_report_free(report);
  /* A report is optional. */
  CHECK(hw_soup_remove_unreferenced_vertices(soup, NULL) == HW_OK);
  hw_soup_free(soup);
}

static void refusals_change_nothing(void) {
  hw_soup *soup = make_soup();
  hw_repair_report *report = (hw_repair_report *)&report; /* must stay as it is */
  hw_repair_report *const untouched = report;
  CHECK_STATUS(hw_soup_merge_vertices(soup, -1.0, false, &report), HW_ERR_INVALID_INPUT,
               "0 or more");
  CHECK_STATUS(hw_soup_merge_vertices(soup, NAN, false, &report), HW_ERR_INVALID_INPUT, "NaN");
  CHECK_STATUS(hw_soup_merge_vertices(soup, INFINITY, false, &report), HW_ERR_INVALID_INPUT,
               "finite");
  CHECK_STATUS(hw_soup_merge_vertices(soup, 2.0, true, &report), HW_ERR_INVALID_INPUT,
               "between 0 and 1");
  CHECK_STATUS(
      hw_soup_remove_small_components(soup, HW_SMALL_COMPONENTS_BY_FACE_COUNT, 1.5, &report),
      HW_ERR_INVALID_INPUT, "whole number");
  CHECK_STATUS(hw_soup_remove_small_components(soup, 7, 1.0, &report), HW_ERR_INVALID_INPUT,
               "rule");
  CHECK_STATUS(hw_soup_remove_small_components(soup, HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER, -0.5,
                                               &report),
               HW_ERR_INVALID_INPUT, "between 0 and 1");
  CHECK(report == untouched);
  size_t n_vertices = 0;
  CHECK(hw_soup_view(soup, NULL, &n_vertices, NULL, NULL, NULL, NULL) == HW_OK);
  CHECK(n_vertices == 7);
  CHECK_STATUS(hw_soup_merge_vertices(NULL, 0.0, false, NULL), HW_ERR_NULL_ARGUMENT, "soup");
  CHECK_STATUS(hw_repair_report_list(NULL, HW_REPAIR_LIST_REMOVED_FACES, NULL, NULL),
               HW_ERR_NULL_ARGUMENT, "");
  CHECK_STATUS(hw_repair_report_maps(NULL, NULL, NULL), HW_ERR_NULL_ARGUMENT, "out_maps");
  hw_soup_free(soup);

  /* An index out of range: refused by name. */
  const uint32_t bad[] = {0, 1, 9};
  CHECK(hw_soup_from_indexed(positions, 7, sizes, 1, bad, 3, &soup) == HW_OK);
  CHECK_STATUS(hw_soup_remove_duplicate_faces(soup, NULL), HW_ERR_INVALID_INPUT,
               "face 0 names vertex 9");
  hw_soup_free(soup);
  CHECK_STATUS(hw_soup_from_indexed(NULL, 3, sizes, 1, indices, 3, &soup), HW_ERR_NULL_ARGUMENT,
               "positions");
}

static void small_components(void) {
  /* The two triangles and a far small one. */
  const double p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 5, 5, 5, 5.01, 5, 5, 5, 5.01, 5};
  const uint32_t s[] = {3, 3, 3};
  const uint32_t ix[] = {0, 1, 2, 1, 3, 2, 4, 5, 6};
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(p, 7, s, 3, ix, 9, &soup) == HW_OK);
  hw_repair_report *report = NULL;
  CHECK(hw_soup_remove_small_components(soup, HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER, 0.1,
                                        &report) == HW_OK);
  const uint32_t *ids = NULL;
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_FACES, &ids) == 1 && ids[0] == 2);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_VERTICES, &ids) == 3 && ids[0] == 4);
  hw_repair_report_free(report);
  CHECK(hw_soup_remove_small_components(soup, HW_SMALL_COMPONENTS_BY_FACE_COUNT, 1.0, &report) ==
        HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_FACES, &ids) == 0);
  hw_repair_report_free(report);
  hw_soup_free(soup);
}

static void stitch_borders(void) {
  /* Two triangles on the same square, unwelded: stitching glues their diagonal. */
  const double p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint32_t s[] = {3, 3};
  const uint32_t ix[] = {0, 1, 2, 3, 4, 5};
  hw_mesh *mesh = NULL;
  CHECK(hw_mesh_from_indexed(p, 6, s, 2, ix, 6, HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_n_edges(mesh) == 6);
  hw_repair_report *report = NULL;
  CHECK_STATUS(hw_mesh_stitch_borders(mesh, -1.0, false, &report), HW_ERR_INVALID_INPUT,
               "0 or more");
  CHECK(report == NULL && hw_mesh_n_edges(mesh) == 6);
  CHECK(hw_mesh_stitch_borders(mesh, 0.0, false, &report) == HW_OK);
  const uint32_t *ids = NULL;
  CHECK(list_len(report, HW_REPAIR_LIST_STITCHED_HALFEDGES, &ids) == 2);
  CHECK(list_len(report, HW_REPAIR_LIST_MERGED_VERTICES, &ids) == 4);
  const hw_index_maps *maps = NULL;
  CHECK(hw_repair_report_maps(report, &maps, NULL) == HW_OK);
  const uint32_t *map = NULL;
  size_t n = 0;
  CHECK(hw_index_maps_view(maps, HW_ELEMENT_KIND_EDGE, &map, &n) == HW_OK && n == 6);
  CHECK_STATUS(hw_repair_report_list(report, 42, &ids, &n), HW_ERR_INVALID_INPUT, "42");
  hw_repair_report_free(report);
  CHECK(hw_mesh_n_edges(mesh) == 5 && hw_mesh_n_vertices(mesh) == 4);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
}

/* A disk with a crack: triangle 0 2 1 below the edge 0-1; above it two triangles meeting at 3,
 * the middle of 0-1 (a T-vertex), and at 4; triangles at 5 and 6 join the sides. */
static const double crack[] = {0, 0, 0, 2, 0, 0, 1, -1, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, 3, 0, 0};
static const uint32_t crack_sizes[] = {3, 3, 3, 3, 3, 3, 3};
static const uint32_t crack_indices[] = {0, 2, 1, 0, 3, 4, 3, 1, 4, 2, 0,
                                         5, 5, 0, 4, 1, 2, 6, 4, 1, 6};

static void degenerate_faces_and_t_vertices(void) {
  const double p[] = {0, 0, 0, 2, 0, 0, 1, 0, 0, 1, -1, 0};
  const uint32_t s[] = {3, 3};
  const uint32_t ix[] = {0, 1, 2, 1, 0, 3};
  hw_mesh *mesh = NULL;
  CHECK(hw_mesh_from_indexed(p, 4, s, 2, ix, 6, HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  hw_repair_report *report = NULL;
  CHECK_STATUS(hw_mesh_remove_degenerate_faces(mesh, -1.0, false, &report), HW_ERR_INVALID_INPUT,
               "0 or more");
  CHECK_STATUS(hw_mesh_remove_degenerate_faces(mesh, NAN, false, &report), HW_ERR_INVALID_INPUT,
               "NaN");
  CHECK_STATUS(hw_mesh_remove_degenerate_faces(mesh, 2.0, true, &report), HW_ERR_INVALID_INPUT,
               "between 0 and 1");
  CHECK(report == NULL);
  /* The cap 0 1 2 flips with 1 0 3 across its long edge: 3 2 0 and 2 3 1, both kept. */
  CHECK(hw_mesh_remove_degenerate_faces(mesh, 0.0, false, &report) == HW_OK);
  const uint32_t *ids = NULL;
  CHECK(list_len(report, HW_REPAIR_LIST_FLIPPED_FACES, &ids) == 2 && ids[0] == 0 && ids[1] == 1);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_FACES, &ids) == 0);
  hw_repair_report_free(report);
  CHECK(hw_mesh_n_faces(mesh) == 2 && hw_mesh_check(mesh) == HW_OK);
  /* A second run changes nothing. */
  CHECK(hw_mesh_remove_degenerate_faces(mesh, 0.0, false, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_FLIPPED_FACES, &ids) == 0);
  hw_repair_report_free(report);
  hw_mesh_free(mesh);

  /* The T-vertex 3 splits the edge 0-1 under it; stitching then closes the crack. */
  report = NULL;
  CHECK(hw_mesh_from_indexed(crack, 7, crack_sizes, 7, crack_indices, 21, HW_BUILD_POLICY_STRICT, &mesh,
                             NULL) == HW_OK);
  CHECK_STATUS(hw_mesh_remove_t_vertices(mesh, INFINITY, false, &report), HW_ERR_INVALID_INPUT,
               "finite");
  CHECK(report == NULL && hw_mesh_n_vertices(mesh) == 7);
  CHECK(hw_mesh_remove_t_vertices(mesh, 0.0, false, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_VERTEX_COPIES, &ids) == 1 && ids[0] == 3);
  hw_repair_report_free(report);
  CHECK(hw_mesh_n_vertices(mesh) == 8 && hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_mesh_stitch_borders(mesh, 0.0, false, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_STITCHED_HALFEDGES, &ids) == 4);
  CHECK(list_len(report, HW_REPAIR_LIST_MERGED_VERTICES, &ids) == 2 && ids[0] == 7 && ids[1] == 3);
  hw_repair_report_free(report);
  CHECK(hw_mesh_n_vertices(mesh) == 7 && hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_mesh_remove_t_vertices(mesh, 1e-3, true, NULL) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 7);
  hw_mesh_free(mesh);
}

/* Two outward tetrahedra sharing the edge 0-1 (four faces on it). */
static const double tetrahedra[] = {0,   0,   0, 1,   0,    0, 0.5, 1,    0,
                                    0.5, 0.3, 1, 0.5, -1.0, 0, 0.5, -0.3, -1};
static const uint32_t tetrahedra_sizes[] = {3, 3, 3, 3, 3, 3, 3, 3};
static const uint32_t tetrahedra_indices[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3,
                                              0, 4, 1, 0, 1, 5, 1, 4, 5, 4, 0, 5};

static hw_soup *make_tetrahedra(void) {
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(tetrahedra, 6, tetrahedra_sizes, 8, tetrahedra_indices, 24, &soup) ==
        HW_OK);
  return soup;
}

static void topology(void) {
  /* Cutting: the second tetrahedron gets copies of 0 and 1; both stay closed. */
  hw_soup *soup = make_tetrahedra();
  hw_repair_report *report = NULL;
  CHECK(hw_soup_repair_non_manifold_edges(soup, HW_NON_MANIFOLD_EDGES_CUT, &report) == HW_OK);
  const uint32_t *ids = NULL;
  CHECK(list_len(report, HW_REPAIR_LIST_VERTEX_COPIES, &ids) == 2 && ids[0] == 0 && ids[1] == 1);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_FACES, &ids) == 0);
  hw_repair_report_free(report);
  const double *xyz = NULL;
  const uint32_t *corners = NULL;
  size_t n_vertices = 0, n_corners = 0;
  CHECK(hw_soup_view(soup, &xyz, &n_vertices, NULL, NULL, &corners, &n_corners) == HW_OK);
  CHECK(n_vertices == 8 && n_corners == 24 && xyz[3 * 7] == 1.0);
  CHECK(corners[12] == 6 && corners[13] == 4 && corners[14] == 7);
  /* Nothing non-manifold is left: a second run and splitting vertices change nothing. */
  CHECK(hw_soup_repair_non_manifold_edges(soup, HW_NON_MANIFOLD_EDGES_CUT, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_VERTEX_COPIES, &ids) == 0);
  hw_repair_report_free(report);
  CHECK(hw_soup_split_non_manifold_vertices(soup, NULL) == HW_OK);
  CHECK(hw_soup_view(soup, NULL, &n_vertices, NULL, NULL, NULL, NULL) == HW_OK && n_vertices == 8);
  hw_soup_free(soup);

  /* Removing faces: the first face each way on the edge stays. */
  soup = make_tetrahedra();
  CHECK(hw_soup_repair_non_manifold_edges(soup, HW_NON_MANIFOLD_EDGES_REMOVE_FACES, &report) ==
        HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_REMOVED_FACES, &ids) == 2 && ids[0] == 4 && ids[1] == 5);
  hw_repair_report_free(report);
  /* The two tetrahedra still touch at vertices 0 and 1: one fan each for the second. */
  CHECK(hw_soup_split_non_manifold_vertices(soup, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_VERTEX_COPIES, &ids) == 2 && ids[0] == 0 && ids[1] == 1);
  hw_repair_report_free(report);
  CHECK_STATUS(hw_soup_repair_non_manifold_edges(soup, 9, &report), HW_ERR_INVALID_INPUT,
               "unknown non-manifold edge repair 9");
  hw_soup_free(soup);

  /* Orienting: one face reversed turns back. The tetrahedron inside out is not closed while
   * four faces share its edge 0-1; once cut, it is, and turns outward. */
  uint32_t turned[24];
  for (size_t c = 0; c < 24; c++) {
    turned[c] = tetrahedra_indices[c];
  }
  turned[3] = 3;
  turned[5] = 0;
  for (size_t f = 4; f < 8; f++) {
    uint32_t first = turned[3 * f];
    turned[3 * f] = turned[3 * f + 2];
    turned[3 * f + 2] = first;
  }
  CHECK(hw_soup_from_indexed(tetrahedra, 6, tetrahedra_sizes, 8, turned, 24, &soup) == HW_OK);
  CHECK(hw_soup_orient_faces(soup, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_REORIENTED_FACES, &ids) == 1 && ids[0] == 1);
  hw_repair_report_free(report);
  CHECK(hw_soup_repair_non_manifold_edges(soup, HW_NON_MANIFOLD_EDGES_CUT, NULL) == HW_OK);
  CHECK(hw_soup_orient_faces(soup, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_REORIENTED_FACES, &ids) == 4);
  CHECK(ids[0] == 4 && ids[3] == 7);
  hw_repair_report_free(report);
  CHECK(hw_soup_view(soup, NULL, NULL, NULL, NULL, &corners, &n_corners) == HW_OK);
  for (size_t c = 0; c < 12; c++) {
    CHECK(corners[c] == tetrahedra_indices[c]);
  }
  CHECK(hw_soup_orient_faces(soup, &report) == HW_OK);
  CHECK(list_len(report, HW_REPAIR_LIST_REORIENTED_FACES, &ids) == 0);
  hw_repair_report_free(report);
  CHECK_STATUS(hw_soup_orient_faces(NULL, NULL), HW_ERR_NULL_ARGUMENT, "soup");
  hw_soup_free(soup);

  /* A malformed soup is refused by every one. */
  const uint32_t bad[] = {0, 1, 9};
  CHECK(hw_soup_from_indexed(positions, 7, sizes, 1, bad, 3, &soup) == HW_OK);
  CHECK_STATUS(hw_soup_orient_faces(soup, NULL), HW_ERR_INVALID_INPUT, "face 0 names vertex 9");
  CHECK_STATUS(hw_soup_split_non_manifold_vertices(soup, NULL), HW_ERR_INVALID_INPUT,
               "face 0 names vertex 9");
  CHECK_STATUS(hw_soup_repair_non_manifold_edges(soup, HW_NON_MANIFOLD_EDGES_CUT, NULL),
               HW_ERR_INVALID_INPUT, "face 0 names vertex 9");
  hw_soup_free(soup);
}

static void fill_holes(void) {
  /* An open box: a unit cube without its top, two triangles a side; the top is a 4-edge hole. */
  const double p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  const uint32_t s[] = {3, 3, 3, 3, 3, 3, 3, 3, 3, 3};
  const uint32_t ix[] = {0, 2, 1, 0, 3, 2, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5,
                         2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  hw_mesh *mesh = NULL;
  CHECK(hw_mesh_from_indexed(p, 8, s, 10, ix, 30, HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  hw_halfedge hole;
  size_t n = 0;
  CHECK(hw_mesh_boundary_loops(mesh, &hole, 1, &n) == HW_OK && n == 1);
  size_t faces = 0;
  /* The half-edge across the rim has a face: refused, nothing changed. */
  CHECK_STATUS(hw_mesh_fill_hole(mesh, hw_mesh_he_twin(mesh, hole), &faces), HW_ERR_REFUSED,
               "boundary");
  CHECK(faces == 0 && hw_mesh_n_faces(mesh) == 10);
  CHECK(hw_mesh_fill_hole(mesh, hole, &faces) == HW_OK && faces == 2);
  CHECK(hw_mesh_n_faces(mesh) == 12 && hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_mesh_count_boundary_loops(mesh, &n) == HW_OK && n == 0);
  hw_mesh_free(mesh);

  CHECK(hw_mesh_from_indexed(p, 8, s, 10, ix, 30, HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  hw_fill_hole_options options = hw_fill_hole_options_default();
  options.max_perimeter = -1.0;
  CHECK_STATUS(hw_mesh_fill_holes(mesh, &options, NULL, NULL, NULL), HW_ERR_INVALID_INPUT,
               "max_perimeter");
  options = hw_fill_hole_options_default();
  options.mode = 3;
  CHECK_STATUS(hw_mesh_fill_holes(mesh, &options, NULL, NULL, NULL), HW_ERR_INVALID_INPUT,
               "fill mode");
  CHECK(hw_mesh_n_faces(mesh) == 10);
  options = hw_fill_hole_options_default();
  options.max_edges = 3;
  size_t filled = 9, refused = 9;
  CHECK(hw_mesh_fill_holes(mesh, &options, &filled, &refused, &faces) == HW_OK);
  CHECK(filled == 0 && refused == 0 && faces == 0 && hw_mesh_n_faces(mesh) == 10);
  CHECK(hw_mesh_fill_holes(mesh, NULL, &filled, &refused, &faces) == HW_OK);
  CHECK(filled == 1 && refused == 0 && faces == 2 && hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
}

int main(void) {
  merge_vertices();
  refusals_change_nothing();
  small_components();
  stitch_borders();
  degenerate_faces_and_t_vertices();
  topology();
  fill_holes();
  return check_summary("test_repair");
}
