/* mesh_stats.c — load a model and print what the half-edge structure knows about it: counts,
 * Euler characteristic, boundary loops (walked the way the course notes write it), components,
 * valences, the build diagnostic, and a few normals.
 *
 *   mesh_stats [model.obj|.off|.ply]     (default: the bundled examples/data/hole_capsule.off)
 */
#include <stdio.h>
#include <stdlib.h>

#include "halfwing.h"

#ifndef HALFWING_EXAMPLE_MODEL
#define HALFWING_EXAMPLE_MODEL "hole_capsule.off"
#endif

/* Prints the failed call's status and message and returns 1, for `return fail(...)`. */
static int fail(const char *what, hw_status status) {
    char message[512];
    if (hw_last_error_message(message, sizeof message, NULL) != HW_OK) message[0] = '\0';
    fprintf(stderr, "mesh_stats: %s: %s (%s)\n", what, hw_status_str(status), message);
    return 1;
}

/* The length of the boundary loop through `start`: next() until back at the start, the seeds'
 * `do { ... h = next(h); } while (h != start);` word for word. */
static size_t loop_length(const hw_mesh *mesh, hw_halfedge start) {
    size_t length = 0;
    hw_halfedge h = start;
    do {
        ++length;
        h = hw_mesh_he_next(mesh, h);
    } while (h.idx != start.idx && h.idx != HW_INVALID_INDEX);
    return length;
}

static void print_loops(const hw_mesh *mesh) {
    size_t n_loops = 0;
    hw_halfedge *loops;
    hw_mesh_boundary_loops(mesh, NULL, 0, &n_loops); /* no buffer: asks for the count only */
    if (n_loops == 0) {
        printf("boundary loops: 0 (closed)\n");
        return;
    }
    loops = malloc(n_loops * sizeof *loops);
    if (loops == NULL || hw_mesh_boundary_loops(mesh, loops, n_loops, NULL) != HW_OK) {
        free(loops);
        return;
    }
    printf("boundary loops: %zu\n", n_loops);
    for (size_t i = 0; i < n_loops; ++i)
        printf("  loop %zu: starts at half-edge %u, %zu edges\n", i, loops[i].idx, loop_length(mesh, loops[i]));
    free(loops);
}

static void print_valences(const hw_mesh *mesh) {
    uint32_t min = UINT32_MAX, max = 0;
    size_t total = 0,
           n = hw_mesh_n_vertex_slots(mesh); /* ids run 0 .. slots-1 */
    for (uint32_t v = 0; v < n; ++v) {
        hw_vertex vertex = {v};
        uint32_t valence = hw_mesh_vertex_valence(mesh, vertex);
        min = valence < min ? valence : min;
        max = valence > max ? valence : max;
        total += valence;
    }
    if (n > 0) printf("valence: min %u, max %u, mean %.2f\n", min, max, (double)total / (double)n);
}

/* The normals of the first few faces and vertices (arrays are indexed by element id). */
static int print_normals(const hw_mesh *mesh) {
  size_t n_faces = hw_mesh_n_face_slots(mesh),
         n_vertices = hw_mesh_n_vertex_slots(mesh);
  double *faces = malloc(3 * n_faces * sizeof *faces),
         *vertices = malloc(3 * n_vertices * sizeof *vertices);
  hw_status status = faces && vertices ? hw_mesh_normals(mesh, HW_NORMAL_WEIGHTING_ANGLE, faces,
                                                         n_faces, NULL, vertices, n_vertices, NULL)
                                       : HW_ERR_INVALID_INPUT;
  if (status == HW_OK) {
    for (size_t f = 0; f < 3 && f < n_faces; ++f)
      printf("face %zu normal: (%.4f, %.4f, %.4f)\n", f, faces[3 * f], faces[3 * f + 1],
             faces[3 * f + 2]);
    for (size_t v = 0; v < 3 && v < n_vertices; ++v)
      printf("vertex %zu normal (angle-weighted): (%.4f, %.4f, %.4f)\n", v, vertices[3 * v],
             vertices[3 * v + 1], vertices[3 * v + 2]);
    }
    free(faces);
    free(vertices);
    return status == HW_OK ? 0 : fail("normals", status);
}

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : HALFWING_EXAMPLE_MODEL;
    hw_mesh *mesh = NULL;
    hw_diagnostic *diagnostic = NULL;
    size_t components = 0, summary_size = 0;
    char *summary;

    /* REPAIR keeps every face of a broken file (and the diagnostic says what it changed). */
    hw_status status = hw_mesh_read(path, HW_BUILD_POLICY_REPAIR, &mesh, &diagnostic);
    if (status != HW_OK) return fail(path, status);

    size_t v = hw_mesh_n_vertices(mesh), e = hw_mesh_n_edges(mesh), f = hw_mesh_n_faces(mesh);
    printf("%s\n", path);
    printf("V = %zu, E = %zu, F = %zu, half-edges = %zu\n", v, e, f, hw_mesh_n_halfedges(mesh));
    printf("Euler characteristic V - E + F = %ld\n", (long)v - (long)e + (long)f);
    print_loops(mesh);
    if (hw_mesh_n_components(mesh, &components) == HW_OK) printf("components: %zu\n", components);
    print_valences(mesh);
    printf("invariants: %s\n", hw_mesh_check(mesh) == HW_OK ? "ok" : "BROKEN");

    /* The diagnostic as text: ask for the size, then copy. */
    hw_diagnostic_summary(diagnostic, NULL, 0, &summary_size);
    summary = malloc(summary_size);
    if (summary && hw_diagnostic_summary(diagnostic, summary, summary_size, NULL) == HW_OK)
        printf("diagnostic: %s\n", hw_diagnostic_is_clean(diagnostic) ? "clean" : summary);
    free(summary);

    int rc = print_normals(mesh);
    hw_diagnostic_free(diagnostic);
    hw_mesh_free(mesh);
    return rc;
}
