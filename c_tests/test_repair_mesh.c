/* The repair pipeline through the C API: hw_repair_mesh() on a constructed soup with every fate
 * checked, on a model of the test data with the fates summing to the input, and its refusals
 * (nothing written). */
#include <math.h>
#include <stdio.h>

#include "check.h"

/* Two triangles sharing an edge whose ends are given twice (vertices 3 and 4 repeat 1 and 2), an
 * unreferenced vertex 5 and a duplicate of the first triangle, rotated. */
static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 9, 9, 9, 1, 1, 0};
static const uint32_t sizes[] = {3, 3, 3};
static const uint32_t indices[] = {0, 1, 2, 3, 6, 4, 1, 2, 0};

static size_t fates_list(const hw_repair_fates *fates, hw_fates_list list, const uint32_t **ids) {
  size_t n = 0;
  CHECK(hw_repair_fates_list(fates, list, ids, &n) == HW_OK);
  return n;
}

static void every_fate_of_a_small_soup(void) {
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(positions, 7, sizes, 3, indices, 9, &soup) == HW_OK);
  hw_repair_options options = hw_repair_options_default();
  hw_mesh *mesh = NULL;
  hw_repair_fates *fates = NULL;
  CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 4 && hw_mesh_n_faces(mesh) == 2);

  const uint32_t *kinds = NULL, *ids = NULL;
  CHECK(fates_list(fates, HW_FATES_LIST_VERTEX_KINDS, &kinds) == 7);
  CHECK(fates_list(fates, HW_FATES_LIST_VERTEX_IDS, &ids) == 7);
  const uint32_t want_vertex_kinds[] = {HW_FATE_KEPT,   HW_FATE_KEPT,         HW_FATE_KEPT,
                                        HW_FATE_MERGED, HW_FATE_MERGED,       HW_FATE_UNREFERENCED,
                                        HW_FATE_KEPT};
  const uint32_t want_vertex_ids[] = {0, 1, 2, 1, 2, HW_INVALID_INDEX, 3};
  for (int v = 0; v < 7; v++) {
    CHECK(kinds[v] == want_vertex_kinds[v] && ids[v] == want_vertex_ids[v]);
  }
  CHECK(fates_list(fates, HW_FATES_LIST_FACE_KINDS, &kinds) == 3);
  CHECK(fates_list(fates, HW_FATES_LIST_FACE_IDS, &ids) == 3);
  CHECK(kinds[0] == HW_FATE_KEPT && ids[0] == 0 && kinds[1] == HW_FATE_KEPT && ids[1] == 1);
  CHECK(kinds[2] == HW_FATE_DUPLICATE && ids[2] == 0);
  CHECK(fates_list(fates, HW_FATES_LIST_ADDED_VERTICES, &ids) == 0 && ids == NULL);

  hw_repair_fate_counts counts;
  CHECK(hw_repair_fates_counts(fates, &counts) == HW_OK);
  CHECK(counts.kept_vertices == 4 && counts.merged_vertices == 2 && counts.removed_vertices == 1);
  CHECK(counts.added_vertices == 0 && counts.kept_faces == 2 && counts.removed_faces == 1);
  CHECK(counts.reversed_faces == 0 && counts.stitched_edges == 0);
  hw_repair_fates_free(fates);
  hw_mesh_free(mesh);

  /* The fates are optional; the soup is unchanged, so a second run gives the same mesh. */
  CHECK(hw_repair_mesh(soup, &options, &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 4 && hw_mesh_n_faces(mesh) == 2);
  hw_mesh_free(mesh);
  hw_soup_free(soup);
}

static void a_model_accounts_for_every_element(void) {
  char path[1024];
  snprintf(path, sizeof path, "%s/meshes/broken/cgal_cubes.off", HALFWING_DATA_DIR);
  hw_soup *soup = NULL;
  CHECK(hw_soup_read(path, &soup) == HW_OK);
  size_t n_vertices = 0, n_corners = 0;
  const uint32_t *corners = NULL;
  CHECK(hw_soup_view(soup, NULL, &n_vertices, NULL, NULL, &corners, &n_corners) == HW_OK);
  hw_repair_options options = hw_repair_options_default();
  options.remove_small_components = true;
  options.small_rule = HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER;
  options.small_value = 0.01;
  hw_mesh *mesh = NULL;
  hw_repair_fates *fates = NULL;
  CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_repair_fate_counts c;
  CHECK(hw_repair_fates_counts(fates, &c) == HW_OK);
  CHECK(c.kept_vertices + c.merged_vertices + c.removed_vertices == n_vertices);
  CHECK(c.kept_vertices + c.added_vertices == hw_mesh_n_vertices(mesh));
  CHECK(c.kept_faces + c.removed_faces == n_corners / 3);
  CHECK(c.kept_faces == hw_mesh_n_faces(mesh));
  /* Two cubes sharing an edge: cutting the edge gives each its own copies of its two ends. */
  CHECK(c.added_vertices == 2);
  const uint32_t *pairs = NULL;
  CHECK(fates_list(fates, HW_FATES_LIST_ADDED_VERTICES, &pairs) == 4);
  CHECK(pairs[0] == 14 && pairs[2] == 15 && pairs[1] < 14 && pairs[3] < 14);
  hw_repair_fates_free(fates);
  hw_mesh_free(mesh);
  hw_soup_free(soup);
}

static void refusals_write_nothing(void) {
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(positions, 7, sizes, 3, indices, 9, &soup) == HW_OK);
  hw_mesh *mesh = (hw_mesh *)&mesh; /* must stay as it is */
  hw_mesh *const untouched = mesh;
  hw_repair_options options = hw_repair_options_default();
  options.merge_tolerance = NAN;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "NaN");
  options = hw_repair_options_default();
  options.stitch_tolerance = 2.0;
  options.stitch_relative = true;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT,
               "between 0 and 1");
  options = hw_repair_options_default();
  options.remove_small_components = true;
  options.small_rule = 9;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "rule");
  options.small_rule = HW_SMALL_COMPONENTS_BY_FACE_COUNT;
  options.small_value = 0.5;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "whole number");
  CHECK(mesh == untouched);
  options = hw_repair_options_default();
  CHECK_STATUS(hw_repair_mesh(NULL, &options, &mesh, NULL), HW_ERR_NULL_ARGUMENT, "soup");
  CHECK_STATUS(hw_repair_mesh(soup, NULL, &mesh, NULL), HW_ERR_NULL_ARGUMENT, "options");
  CHECK_STATUS(hw_repair_mesh(soup, &options, NULL, NULL), HW_ERR_NULL_ARGUMENT, "out_mesh");
  CHECK(mesh == untouched);

  /* An index naming no vertex. */
  static const uint32_t bad[] = {0, 1, 7};
  hw_soup *broken = NULL;
  CHECK(hw_soup_from_indexed(positions, 7, sizes, 1, bad, 3, &broken) == HW_OK);
  CHECK_STATUS(hw_repair_mesh(broken, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "vertex 7");
  CHECK(mesh == untouched);
  hw_soup_free(broken);

  hw_repair_fates *fates = NULL;
  CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
  const uint32_t *ids = NULL;
  size_t n = 0;
  CHECK_STATUS(hw_repair_fates_list(fates, 99, &ids, &n), HW_ERR_INVALID_INPUT, "fates list");
  CHECK_STATUS(hw_repair_fates_counts(fates, NULL), HW_ERR_NULL_ARGUMENT, "out_counts");
  hw_repair_fates_free(fates);
  hw_repair_fates_free(NULL);
  hw_mesh_free(mesh);
  hw_soup_free(soup);
}

/* A disk with a crack 0-1-3 (3 a T-vertex in the middle of 0-1), as in test_repair.c. */
static void t_vertices_and_degenerate_faces(void) {
  static const double crack[] = {0, 0, 0, 2, 0,  0, 1, -1, 0, 1, 0,
                                 0, 1, 1, 0, -1, 0, 0, 3,  0, 0};
  static const uint32_t crack_sizes[] = {3, 3, 3, 3, 3, 3, 3};
  static const uint32_t crack_indices[] = {0, 2, 1, 0, 3, 4, 3, 1, 4, 2, 0,
                                           5, 5, 0, 4, 1, 2, 6, 4, 1, 6};
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(crack, 7, crack_sizes, 7, crack_indices, 21, &soup) == HW_OK);
  hw_repair_options options = hw_repair_options_default();
  CHECK(options.remove_degenerate_faces && options.remove_t_vertices);
  hw_mesh *mesh = NULL;
  hw_repair_fates *fates = NULL;
  CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
  hw_repair_fate_counts counts;
  CHECK(hw_repair_fates_counts(fates, &counts) == HW_OK);
  CHECK(counts.split_edges == 1 && counts.stitched_edges == 2 && counts.added_vertices == 0);
  CHECK(counts.flipped_edges == 0 && hw_mesh_n_vertices(mesh) == 7);
  hw_repair_fates_free(fates);
  hw_mesh_free(mesh);
  /* Turned off: the crack stays open. */
  options.remove_t_vertices = false;
  CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
  CHECK(hw_repair_fates_counts(fates, &counts) == HW_OK);
  CHECK(counts.split_edges == 0 && counts.stitched_edges == 0);
  hw_repair_fates_free(fates);
  hw_mesh_free(mesh);
  options = hw_repair_options_default();
  options.t_vertex_tolerance = -1;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "0 or more");
  options = hw_repair_options_default();
  options.degenerate_tolerance = NAN;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "NaN");
  hw_soup_free(soup);

  /* An octahedron whose vertex 6 sits 1e-9 from vertex 0 and takes its place in two faces;
   * the slivers 0 3 6 and 0 6 1 close the gap. Within a tolerance of 1e-6 they are degenerate
   * and collapse with the short edge 0-6, which merges 6 into 0. */
  static const double sliver[] = {0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0,
                                  0, 0, -1, 0, 1e-9, 1};
  static const uint32_t sliver_sizes[] = {3, 3, 3, 3, 3, 3, 3, 3, 3, 3};
  static const uint32_t sliver_indices[] = {0, 1, 2, 0, 2, 3, 6, 3, 4, 6, 4, 1, 0, 3,
                                            6, 0, 6, 1, 5, 2, 1, 5, 3, 2, 5, 4, 3, 5,
                                            1, 4};
  CHECK(hw_soup_from_indexed(sliver, 7, sliver_sizes, 10, sliver_indices, 30, &soup) == HW_OK);
  options = hw_repair_options_default();
  CHECK(hw_repair_mesh(soup, &options, &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 10);
  hw_mesh_free(mesh);
  options.degenerate_tolerance = 1e-6;
  CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
  CHECK(hw_mesh_check(mesh) == HW_OK && hw_mesh_n_faces(mesh) == 8);
  CHECK(hw_repair_fates_counts(fates, &counts) == HW_OK);
  CHECK(counts.merged_vertices == 1 && counts.removed_faces == 2);
  const uint32_t *kinds = NULL;
  const uint32_t *ids = NULL;
  CHECK(fates_list(fates, HW_FATES_LIST_FACE_KINDS, &kinds) == 10);
  CHECK(kinds[4] == HW_FATE_DEGENERATE && kinds[5] == HW_FATE_DEGENERATE);
  CHECK(fates_list(fates, HW_FATES_LIST_VERTEX_KINDS, &kinds) == 7);
  CHECK(fates_list(fates, HW_FATES_LIST_VERTEX_IDS, &ids) == 7);
  CHECK(kinds[6] == HW_FATE_MERGED && ids[6] == 0);
  hw_repair_fates_free(fates);
  hw_mesh_free(mesh);
  hw_soup_free(soup);
}

/* A tube of 12 sides and 3 bands closed at the bottom by a fan, open at the top: one hole of 12
 * edges, wider than its edges are long, which a refined fill fills with vertices inside. */
static hw_soup *open_tube(void) {
  double p[3 * (1 + 4 * 12)];
  uint32_t face_sizes[12 + 2 * 3 * 12], corners[3 * (12 + 2 * 3 * 12)];
  p[0] = 0, p[1] = 0, p[2] = 0;
  for (uint32_t r = 0; r < 4; ++r)
    for (uint32_t s = 0; s < 12; ++s) {
      double *q = p + 3 * (1 + r * 12 + s);
      q[0] = cos(6.283185307179586 * s / 12), q[1] = sin(6.283185307179586 * s / 12);
      q[2] = 0.5 * r;
    }
  size_t f = 0, c = 0;
#define AT(r, s) (1 + (r) * 12 + (s) % 12)
  for (uint32_t s = 0; s < 12; ++s) {
    face_sizes[f++] = 3;
    corners[c++] = 0, corners[c++] = AT(0, s + 1), corners[c++] = AT(0, s);
  }
  for (uint32_t r = 0; r < 3; ++r)
    for (uint32_t s = 0; s < 12; ++s) {
      face_sizes[f++] = 3, face_sizes[f++] = 3;
      corners[c++] = AT(r, s), corners[c++] = AT(r, s + 1), corners[c++] = AT(r + 1, s + 1);
      corners[c++] = AT(r, s), corners[c++] = AT(r + 1, s + 1), corners[c++] = AT(r + 1, s);
    }
#undef AT
  hw_soup *soup = NULL;
  CHECK(hw_soup_from_indexed(p, 1 + 4 * 12, face_sizes, f, corners, c, &soup) == HW_OK);
  return soup;
}

/* Hole filling in the pipeline: every added face and vertex is in the counts and lists, the
 * output closed; a refined fill adds vertices, a triangulated one none; a bad mode is refused. */
static void filled_holes_are_accounted_for(void) {
  hw_soup *soup = open_tube();
  const hw_fill_mode modes[] = {HW_FILL_MODE_TRIANGULATE, HW_FILL_MODE_REFINE, HW_FILL_MODE_FAIR};
  for (size_t i = 0; i < 3; ++i) {
    hw_repair_options options = hw_repair_options_default();
    options.fill_holes = true;
    options.fill_max_edges = 12;
    options.fill_mode = modes[i];
    hw_mesh *mesh = NULL;
    hw_repair_fates *fates = NULL;
    CHECK(hw_repair_mesh(soup, &options, &mesh, &fates) == HW_OK);
    hw_repair_fate_counts c;
    CHECK(hw_repair_fates_counts(fates, &c) == HW_OK);
    CHECK(c.filled_holes == 1 && c.refused_holes == 0);
    CHECK(c.kept_vertices + c.added_vertices == hw_mesh_n_vertices(mesh));
    CHECK(c.kept_faces + c.added_faces == hw_mesh_n_faces(mesh));
    /* The fill is a disk inside the 12-edge rim. */
    CHECK(c.added_faces == 10 + 2 * c.added_vertices);
    CHECK(modes[i] == HW_FILL_MODE_TRIANGULATE ? c.added_vertices == 0 : c.added_vertices > 0);
    const uint32_t *ids = NULL;
    CHECK(fates_list(fates, HW_FATES_LIST_ADDED_FACES, &ids) == c.added_faces);
    CHECK(fates_list(fates, HW_FATES_LIST_ADDED_VERTICES, &ids) == 2 * c.added_vertices);
    size_t loops = 1;
    CHECK(hw_mesh_boundary_loops(mesh, NULL, 0, &loops) == HW_OK && loops == 0);
    CHECK(hw_mesh_check(mesh) == HW_OK);
    hw_repair_fates_free(fates);
    hw_mesh_free(mesh);
  }
  hw_repair_options options = hw_repair_options_default();
  options.fill_holes = true;
  options.fill_mode = 7;
  hw_mesh *mesh = NULL;
  CHECK_STATUS(hw_repair_mesh(soup, &options, &mesh, NULL), HW_ERR_INVALID_INPUT, "fill mode");
  CHECK(mesh == NULL);
  hw_soup_free(soup);
}

int main(void) {
  every_fate_of_a_small_soup();
  filled_holes_are_accounted_for();
  t_vertices_and_degenerate_faces();
  a_model_accounts_for_every_element();
  refusals_write_nothing();
  return check_summary("test_repair_mesh");
}
