/* voronoi_svg.c — the Voronoi diagram of a point set from C: build it, clip every cell to a
 * rectangle, add up the cell areas (they tile the rectangle), write an SVG drawing and read it
 * back.
 *
 *   voronoi_svg [out.svg]     (default: voronoi.svg in the current directory)
 *
 * The sites are generated: 100 points from a fixed-seed generator (the same picture every run),
 * plus one exact copy of site 0 to show how duplicates are handled (merged: no cell of their own).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "halfwing.h"

#define N_RANDOM 100
#define N_SITES (N_RANDOM + 1)
#define WIDTH 10.0
#define HEIGHT 6.0

/* Prints the failed call's status and message and returns 1, for `return fail(...)`. */
static int fail(const char *what, hw_status status) {
    char message[512];
    if (hw_last_error_message(message, sizeof message, NULL) != HW_OK) message[0] = '\0';
    fprintf(stderr, "voronoi_svg: %s: %s (%s)\n", what, hw_status_str(status), message);
    return 1;
}

/* A 64-bit linear congruential generator (Knuth's MMIX constants): a uniform double in [0, 1). */
static double next_uniform(uint64_t *state) {
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (double)(*state >> 11) / 9007199254740992.0; /* top 53 bits / 2^53 */
}

/* Counts the occurrences of `needle` in the file at `path` (-1 if it cannot be read). */
static long count_in_file(const char *path, const char *needle) {
    char chunk[4096 + 64];
    size_t keep = 0, n, len = strlen(needle);
    long count = 0;
    FILE *file = fopen(path, "rb");
    if (!file) return -1;
    /* Read in chunks, keeping the last len - 1 bytes so a needle across chunks is still found. */
    while ((n = fread(chunk + keep, 1, 4096, file)) > 0) {
        size_t total = keep + n, i;
        for (i = 0; i + len <= total; ++i)
            if (memcmp(chunk + i, needle, len) == 0) ++count;
        keep = total < len - 1 ? total : len - 1;
        memmove(chunk, chunk + total - keep, keep);
    }
    fclose(file);
    return count;
}

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : "voronoi.svg";
    double xy[2 * N_SITES];
    uint64_t state = 2024;
    hw_voronoi *voronoi = NULL;
    hw_voronoi_cells *cells = NULL;
    hw_svg_options options = hw_svg_options_default();
    hw_status status;
    double total_area = 0, largest_area = 0;
    hw_site largest = {0}, site;
    size_t non_empty = 0;
    long polygons;
    int i;

    for (i = 0; i < N_RANDOM; ++i) {
        xy[2 * i] = WIDTH * next_uniform(&state);
        xy[2 * i + 1] = HEIGHT * next_uniform(&state);
    }
    xy[2 * N_RANDOM] = xy[0]; /* the duplicate */
    xy[2 * N_RANDOM + 1] = xy[1];

    /* The diagram: a Delaunay triangulation with exact predicates, and its dual. */
    status = hw_voronoi_build(xy, N_SITES, &voronoi);
    if (status != HW_OK) return fail("hw_voronoi_build", status);
    printf("%zu sites (%zu distinct), %zu Delaunay triangles, %zu Voronoi vertices\n",
           hw_voronoi_n_sites(voronoi), hw_voronoi_n_unique_sites(voronoi),
           hw_voronoi_n_triangles(voronoi), hw_voronoi_n_vertices(voronoi));

    /* Every cell clipped to the rectangle, as a counter-clockwise polygon indexed by site. */
    status = hw_voronoi_clip_rect(voronoi, 0, 0, WIDTH, HEIGHT, &cells);
    if (status != HW_OK) {
        hw_voronoi_free(voronoi);
        return fail("hw_voronoi_clip_rect", status);
    }
    for (site.idx = 0; site.idx < hw_voronoi_cells_n_cells(cells); ++site.idx) {
        double area = 0;
        status = hw_voronoi_cells_area_centroid(cells, site, &area, NULL);
        if (status != HW_OK) break;
        if (area > 0) ++non_empty;
        if (area > largest_area) {
            largest_area = area;
            largest = site;
        }
        total_area += area;
    }
    if (status == HW_OK) {
        printf("%zu non-empty cells of %zu (the duplicate has none)\n", non_empty,
               hw_voronoi_cells_n_cells(cells));
        printf("total area %.6f (rectangle %.0f x %.0f: %.6f)\n", total_area, WIDTH, HEIGHT,
               WIDTH * HEIGHT);
        printf("largest cell: site %u, area %.4f\n", largest.idx, largest_area);

        /* The drawing: filled cells, sites as dots, 600 pixels wide. */
        options.width_px = 600;
        options.sites = true;
        status = hw_voronoi_svg_write(voronoi, cells, &options, path);
    }
    hw_voronoi_cells_free(cells);
    hw_voronoi_free(voronoi);
    if (status != HW_OK) return fail("cells or SVG", status);

    polygons = count_in_file(path, "<polygon");
    printf("wrote %s: %ld cell polygons, %ld site dots\n", path, polygons,
           count_in_file(path, "<circle"));
    return polygons == (long)non_empty ? 0 : 1;
}
