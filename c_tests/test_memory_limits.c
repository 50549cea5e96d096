/* Entry points asked for more memory than the process may have return HW_ERR_OUT_OF_MEMORY (or
 * refuse a count the data does not back) instead of aborting, and the library stays usable.
 * The calls run in a forked child whose address space is limited (setrlimit(RLIMIT_AS)) to what
 * it uses plus HEADROOM; an abort there fails the test through the child's exit status. Input
 * arrays far larger than the limit are a mapping of zero pages made before the limit is set:
 * they cost no memory, and nothing should read them beyond the first few elements. The limit
 * counts what is mapped already (under AddressSanitizer, its shadow), so it is set relative to
 * that. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE 1 /* fork, setrlimit, mmap's MAP_NORESERVE under -std=c11 */
#endif

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"

#define HEADROOM ((size_t)256 << 20)
#define ZEROS_BYTES ((size_t)16 << 30)

static size_t address_space_in_use(void) {
  unsigned long pages = 0;
  FILE *statm = fopen("/proc/self/statm", "r");
  if (statm == NULL) return 0;
  if (fscanf(statm, "%lu", &pages) != 1) pages = 0;
  fclose(statm);
  return (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
}

static void builds_larger_than_memory(const double *zeros) {
  hw_mesh *mesh = NULL;
  hw_winged *winged = NULL;
  hw_doctor_report *report = NULL;
  hw_diagnostic *diagnostic = NULL;
  const uint32_t sizes[1] = {3};
  const uint32_t triangle[3] = {0, 1, 2};
  const size_t n_vertices = 500000000; /* 12 GB of positions, 20 GB to build */

  CHECK_STATUS(hw_surface_grid(1.0, 1.0, 20000, 20000, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_OUT_OF_MEMORY, "cannot allocate 9.6 GB for 400040001 vertices");
  CHECK(mesh == NULL);
  CHECK_STATUS(hw_mesh_from_indexed(zeros, n_vertices, sizes, 1, triangle, 3,
                                    HW_BUILD_POLICY_REPAIR, &mesh, &diagnostic),
               HW_ERR_OUT_OF_MEMORY, "cannot allocate 20.0 GB for 500000000 vertices");
  CHECK(mesh == NULL && diagnostic == NULL);
  CHECK_STATUS(hw_winged_from_indexed(zeros, n_vertices, sizes, 1, triangle, 3,
                                      HW_BUILD_POLICY_STRICT, &winged, NULL),
               HW_ERR_OUT_OF_MEMORY, "cannot allocate");
  CHECK(winged == NULL);
  CHECK_STATUS(hw_doctor_examine_indexed(zeros, n_vertices, sizes, 1, triangle, 3, NULL, &report),
               HW_ERR_OUT_OF_MEMORY, "cannot allocate");
  CHECK(report == NULL);
  CHECK_STATUS(hw_diagnose_indexed(zeros, n_vertices, sizes, 1, triangle, 3, &diagnostic),
               HW_ERR_OUT_OF_MEMORY, "cannot allocate 20.0 GB for 500000000 vertices");
  CHECK(diagnostic == NULL);
}

static void self_intersections_larger_than_memory(const double *zeros) {
  hw_face_pairs *pairs = NULL;
  /* A billion faces of three corners, sizes and indices all 0 (the zero pages): 672 GB to
   * search, refused before the sizes are read. */
  const uint32_t *zero_ids = (const uint32_t *)(const void *)zeros;
  const size_t n_faces = 1000000000;
  CHECK_STATUS(hw_self_intersections_indexed(zeros, 3, zero_ids, n_faces, zero_ids, 3 * n_faces,
                                             &pairs),
               HW_ERR_OUT_OF_MEMORY, "for 3000000000 corners");
  CHECK(pairs == NULL);
}

static void voronoi_larger_than_memory(const double *zeros) {
  const double triangle[6] = {0, 0, 1, 0, 0, 1};
  hw_voronoi *voronoi = NULL;
  size_t needed = 0;
  /* 20M sites (all at the origin: read, they are one site): 6.4 GB to triangulate. */
  CHECK_STATUS(hw_voronoi_build(zeros, 20000000, &voronoi), HW_ERR_OUT_OF_MEMORY,
               "for 20000000 sites");
  CHECK(voronoi == NULL);
  CHECK(hw_voronoi_build(triangle, 3, &voronoi) == HW_OK);
  /* 1.6G labels: the caller's buffer (the zero pages, never written on failure) holds them,
   * the picture the library makes first does not fit. */
  CHECK_STATUS(hw_voronoi_label_image(voronoi, HW_METRIC_EUCLIDEAN, 0, 0, 1, 1, 40000, 40000,
                                      (uint32_t *)(uintptr_t)zeros, ZEROS_BYTES / 4, &needed),
               HW_ERR_OUT_OF_MEMORY, "cannot allocate 6.4 GB for 1600000000 pixels");
  hw_voronoi_free(voronoi);
}

static void lying_header(void) {
  const char *path = TEST_TMP_DIR "/lying_header.off";
  hw_mesh *mesh = NULL;
  FILE *file = fopen(path, "w");
  CHECK(file != NULL);
  if (file == NULL) return;
  /* A billion vertices declared (24 GB), three given. */
  fputs("OFF\n1000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", file);
  fclose(file);
  CHECK_STATUS(hw_mesh_read(path, HW_BUILD_POLICY_STRICT, &mesh, NULL), HW_ERR_PARSE, "vertices");
  CHECK(mesh == NULL);
}

static int child(void) {
  hw_mesh *mesh = NULL;
  struct rlimit limit;
  const double *zeros = (const double *)mmap(NULL, ZEROS_BYTES, PROT_READ,
                                             MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  CHECK(zeros != (const double *)MAP_FAILED);
  if (zeros == (const double *)MAP_FAILED) return check_summary("test_memory_limits (child)");
  limit.rlim_cur = address_space_in_use() + HEADROOM;
  limit.rlim_max = RLIM_INFINITY;
  CHECK(setrlimit(RLIMIT_AS, &limit) == 0);

  builds_larger_than_memory(zeros);
  self_intersections_larger_than_memory(zeros);
  voronoi_larger_than_memory(zeros);
  lying_header();

  /* Still usable under the same limit. */
  CHECK(hw_surface_grid(1.0, 1.0, 8, 8, HW_CELL_FACES_TRIANGLES, &mesh) == HW_OK);
  CHECK(mesh != NULL && hw_mesh_n_faces(mesh) == 128);
  hw_mesh_free(mesh);
  return check_summary("test_memory_limits (child)");
}

int main(void) {
  int status = 0;
  pid_t pid;
  fflush(stdout);
  pid = fork();
  CHECK(pid >= 0);
  if (pid == 0) {
    int failed = child();
    fflush(stdout);
    _exit(failed);
  }
  if (pid > 0) {
    CHECK(waitpid(pid, &status, 0) == pid);
    CHECK(WIFEXITED(status)); /* not killed by an abort */
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  return check_summary("test_memory_limits");
}
