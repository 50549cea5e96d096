/* hw_mesh creation, counts and release through the C API, with every bad argument. */
#include <math.h>
#include <stdint.h>

#include "check.h"

/* The tetrahedron of the course notes (seed 000, "Winged Edges"). */
static const double tet_positions[] = {
    0.5773502691896258, 0.0, 0.0,  -0.2886751345948129, 0.5, 0.0,
    -0.2886751345948129, -0.5, 0.0, 0.0, 0.0, 0.816496580927726};
static const uint32_t tet_sizes[] = {3, 3, 3, 3};
static const uint32_t tet_indices[] = {0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 2, 1};

static hw_mesh *build_tetrahedron(void) {
  hw_mesh *mesh = NULL;
  CHECK(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 12,
                             HW_BUILD_POLICY_STRICT, &mesh, NULL) == HW_OK);
  return mesh;
}

static void tetrahedron_counts(void) {
  hw_mesh *mesh = build_tetrahedron();
  CHECK(mesh != NULL);
  CHECK(hw_mesh_n_vertices(mesh) == 4);
  CHECK(hw_mesh_n_edges(mesh) == 6);
  CHECK(hw_mesh_n_halfedges(mesh) == 12);
  CHECK(hw_mesh_n_faces(mesh) == 4);
  hw_mesh_free(mesh);
}

static void empty_mesh(void) {
  hw_mesh *mesh = hw_mesh_new();
  hw_mesh *built = NULL;
  CHECK(mesh != NULL);
  CHECK(hw_mesh_n_vertices(mesh) == 0 && hw_mesh_n_faces(mesh) == 0);
  {
    /* Empty views are NULL with length 0, as the header documents. */
    const double *xyz = (const double *)&mesh;
    const uint32_t *origins = (const uint32_t *)&mesh;
    size_t n = 7;
    CHECK(hw_mesh_view_positions(mesh, &xyz, &n) == HW_OK && xyz == NULL && n == 0);
    n = 7;
    CHECK(hw_mesh_view(mesh, HW_MESH_ARRAY_HALFEDGE_ORIGIN, &origins, &n) == HW_OK &&
          origins == NULL && n == 0);
  }
  hw_mesh_free(mesh);
  /* An empty face list is an empty mesh, not an error; NULL arrays are fine with zero counts. */
  CHECK(hw_mesh_from_indexed(NULL, 0, NULL, 0, NULL, 0, HW_BUILD_POLICY_STRICT, &built, NULL) ==
        HW_OK);
  CHECK(built != NULL && hw_mesh_n_faces(built) == 0);
  hw_mesh_free(built);
}

/* A failed call leaves *out_mesh as it was. */
#define SENTINEL ((hw_mesh *)(uintptr_t)0x1234)

static void null_arguments(void) {
  hw_mesh *mesh = SENTINEL;
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 12,
                                    HW_BUILD_POLICY_STRICT, NULL, NULL),
               HW_ERR_NULL_ARGUMENT, "out_mesh");
  CHECK_STATUS(hw_mesh_from_indexed(NULL, 4, tet_sizes, 4, tet_indices, 12, HW_BUILD_POLICY_STRICT,
                                    &mesh, NULL),
               HW_ERR_NULL_ARGUMENT, "positions");
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, NULL, 4, tet_indices, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_NULL_ARGUMENT, "face_sizes");
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, NULL, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_NULL_ARGUMENT, "indices");
  CHECK(mesh == SENTINEL);
  CHECK(hw_mesh_n_vertices(NULL) == 0);
  CHECK(last_error_contains("mesh"));
  CHECK(hw_mesh_n_faces(NULL) == 0);
  CHECK(hw_mesh_n_edges(NULL) == 0);
  CHECK(hw_mesh_n_halfedges(NULL) == 0);
  hw_mesh_free(NULL); /* a no-op */
}

static void malformed_face_data(void) {
  hw_mesh *mesh = SENTINEL;
  static const uint32_t out_of_range[] = {0, 1, 3, 1, 2, 7, 0, 3, 2, 0, 2, 1};
  static const uint32_t repeated[] = {0, 1, 1, 1, 2, 3, 0, 3, 2, 0, 2, 1};
  static const uint32_t short_sizes[] = {3, 3, 2, 4};
  double nan_positions[12];
  memcpy(nan_positions, tet_positions, sizeof nan_positions);
  nan_positions[4] = nan("");

  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, out_of_range, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "out-of-range vertex indices: f1");
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, repeated, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "repeated vertex: f0");
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, short_sizes, 4, tet_indices, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "fewer than 3 corners: f2");
  CHECK_STATUS(hw_mesh_from_indexed(nan_positions, 4, tet_sizes, 4, tet_indices, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "coordinates: v1");
  /* Sizes that do not add up to the number of indices. */
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 11,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "11");
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, 4, tet_sizes, 4, tet_indices, 12, 99u, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "policy");
  CHECK_STATUS(hw_mesh_from_indexed(tet_positions, SIZE_MAX, tet_sizes, 4, tet_indices, 12,
                                    HW_BUILD_POLICY_STRICT, &mesh, NULL),
               HW_ERR_INVALID_INPUT, "n_vertices");
  CHECK(mesh == SENTINEL);
}

static void non_manifold_edge_policies(void) {
  /* Three triangles on the edge 0-1. */
  static const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  static const uint32_t sizes[] = {3, 3, 3};
  static const uint32_t indices[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  hw_mesh *mesh = SENTINEL;
  CHECK_STATUS(
      hw_mesh_from_indexed(positions, 5, sizes, 3, indices, 9, HW_BUILD_POLICY_STRICT, &mesh, NULL),
      HW_ERR_NON_MANIFOLD, "non-manifold");
  CHECK(mesh == SENTINEL);
  mesh = NULL;
  CHECK(hw_mesh_from_indexed(positions, 5, sizes, 3, indices, 9, HW_BUILD_POLICY_SKIP, &mesh,
                             NULL) == HW_OK);
  CHECK(mesh != NULL && hw_mesh_n_faces(mesh) == 2);
  hw_mesh_free(mesh);
  mesh = NULL;
  CHECK(hw_mesh_from_indexed(positions, 5, sizes, 3, indices, 9, HW_BUILD_POLICY_REPAIR, &mesh,
                             NULL) == HW_OK);
  CHECK(mesh != NULL && hw_mesh_n_faces(mesh) == 3);
  hw_mesh_free(mesh);
}

static void double_free_is_refused(void) {
  hw_mesh *mesh = build_tetrahedron();
  hw_mesh *others[8];
  size_t i;
  hw_mesh_free(mesh);
  hw_mesh_free(mesh); /* detected: not a live mesh any more */
  CHECK(last_error_contains("already freed"));
  /* New meshes never take the freed one's address, so freeing the stale pointer again is still
   * refused and leaves them alone (before, the allocator gave the address to the next mesh and
   * the stale free released that mesh). */
  for (i = 0; i < 8; ++i) {
    others[i] = build_tetrahedron();
    CHECK(others[i] != mesh);
  }
  hw_mesh_free(mesh);
  CHECK(last_error_contains("already freed"));
  for (i = 0; i < 8; ++i) {
    CHECK(hw_mesh_n_faces(others[i]) == 4 && hw_mesh_check(others[i]) == HW_OK);
    hw_mesh_free(others[i]);
  }
}

int main(void) {
  tetrahedron_counts();
  empty_mesh();
  null_arguments();
  malformed_face_data();
  non_manifold_edge_policies();
  double_free_is_refused();
  return check_summary("test_mesh_api");
}
