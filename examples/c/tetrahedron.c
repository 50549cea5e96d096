/* Builds the tetrahedron of the course notes ("Alas y celdas", seed 000) through the C API and
 * prints its counts and Euler characteristic.
 *
 *   V0 = ( sqrt(3)/3,    0, 0)          F0 = {0, 1, 3}
 *   V1 = (-sqrt(3)/6,  1/2, 0)          F1 = {1, 2, 3}
 *   V2 = (-sqrt(3)/6, -1/2, 0)          F2 = {0, 3, 2}
 *   V3 = ( 0,            0, sqrt(6)/3)  F3 = {0, 2, 1}
 */
#include <math.h>
#include <stdio.h>

#include <halfwing.h>

/* Prints the failed call, its status and the library's detailed message. */
static int fail(const char *what, hw_status status) {
  char message[512];
  hw_last_error_message(message, sizeof message, NULL);
  fprintf(stderr, "%s failed: %s: %s\n", what, hw_status_str(status), message);
  return 1;
}

int main(void) {
  const double s3 = sqrt(3.0), s6 = sqrt(6.0);
  const double positions[] = {
      s3 / 3, 0.0, 0.0,       /* V0 */
      -s3 / 6, 0.5, 0.0,      /* V1 */
      -s3 / 6, -0.5, 0.0,     /* V2 */
      0.0, 0.0, s6 / 3,       /* V3 */
  };
  const uint32_t face_sizes[] = {3, 3, 3, 3};
  const uint32_t indices[] = {0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 2, 1};
  hw_mesh *mesh = NULL;
  size_t v, e, f;

  hw_status status = hw_mesh_from_indexed(positions, 4, face_sizes, 4, indices, 12,
                                          HW_BUILD_POLICY_STRICT, &mesh, NULL);
  if (status != HW_OK) return fail("hw_mesh_from_indexed", status);

  v = hw_mesh_n_vertices(mesh);
  e = hw_mesh_n_edges(mesh);
  f = hw_mesh_n_faces(mesh);
  printf("halfwing %s: the seed tetrahedron\n", hw_version_string());
  printf("V = %zu, E = %zu, F = %zu, V - E + F = %ld\n", v, e, f, (long)v - (long)e + (long)f);
  printf("half-edges: %zu\n", hw_mesh_n_halfedges(mesh));

  hw_mesh_free(mesh);
  return 0;
}
