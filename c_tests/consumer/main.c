/* A consumer of the installed halfwing package: builds the tetrahedron of the course notes and
 * checks its counts and the library version. */
#include <stdio.h>

#include <halfwing.h>

int main(void) {
  static const double positions[] = {
      0.5773502691896258, 0.0, 0.0,  -0.2886751345948129, 0.5, 0.0,
      -0.2886751345948129, -0.5, 0.0, 0.0, 0.0, 0.816496580927726};
  static const uint32_t sizes[] = {3, 3, 3, 3};
  static const uint32_t indices[] = {0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 2, 1};
  hw_mesh *mesh = NULL;
  hw_status status;
  hw_nav nav;
  uint32_t v;
  size_t valence_sum = 0;
  int ok;

  if (hw_version_number() != HW_VERSION_NUMBER) {
    fprintf(stderr, "header %d and library %u disagree\n", HW_VERSION_NUMBER, hw_version_number());
    return 1;
  }
  status = hw_mesh_from_indexed(positions, 4, sizes, 4, indices, 12, HW_BUILD_POLICY_STRICT, &mesh,
                                NULL);
  if (status != HW_OK) {
    fprintf(stderr, "hw_mesh_from_indexed: %s\n", hw_status_str(status));
    return 1;
  }
  ok = hw_mesh_n_vertices(mesh) == 4 && hw_mesh_n_faces(mesh) == 4 && hw_mesh_n_edges(mesh) == 6;
  /* The inline navigation comes with the installed headers: every vertex has three neighbours. */
  ok = ok && hw_mesh_nav(mesh, &nav) == HW_OK;
  for (v = 0; ok && v < nav.n_vertex_slots; ++v) {
    hw_vertex vertex = {v}, w;
    hw_nav_circ c = hw_nav_around_vertex(&nav, vertex);
    while (hw_nav_circ_next_vertex(&c, &w)) ++valence_sum;
  }
  ok = ok && valence_sum == 12;
  printf("halfwing %s: V=%zu E=%zu F=%zu\n", hw_version_string(), hw_mesh_n_vertices(mesh),
         hw_mesh_n_edges(mesh), hw_mesh_n_faces(mesh));
  hw_mesh_free(mesh);
  return ok ? 0 : 1;
}
