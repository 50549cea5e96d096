/* Render buffers and surface generators through the C API: the arrays a GL program uploads, every
 * shading and layout, polygon lists, Voronoi cells, and the refusal of every bad argument. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define MESH_SENTINEL ((hw_mesh *)(uintptr_t)0x1234)
#define BUFFERS_SENTINEL ((hw_render_buffers *)(uintptr_t)0x5678)

static hw_mesh *unit_cube(void) {
  hw_mesh *mesh = NULL;
  CHECK(hw_surface_cube(1.0, &mesh) == HW_OK);
  return mesh;
}

static hw_render_buffers *build(const hw_mesh *mesh, const hw_render_options *options) {
  hw_render_buffers *buffers = NULL;
  CHECK(hw_render_buffers_build(mesh, NULL, options, &buffers) == HW_OK);
  return buffers;
}

static size_t float_count(const hw_render_buffers *buffers, hw_render_floats which) {
  const float *data = NULL;
  size_t n = SIZE_MAX;
  CHECK(hw_render_buffers_floats(buffers, which, &data, &n) == HW_OK);
  CHECK((n == 0) == (data == NULL));
  return n;
}

static size_t index_count(const hw_render_buffers *buffers, hw_render_indices which) {
  const uint32_t *data = NULL;
  size_t n = SIZE_MAX;
  CHECK(hw_render_buffers_indices(buffers, which, &data, &n) == HW_OK);
  return n;
}

static void shading_modes_split_vertices(void) {
  hw_mesh *mesh = unit_cube();
  hw_render_options options = hw_render_options_default();
  hw_render_buffers *buffers;

  CHECK(options.shading == HW_SHADING_CORNER_NORMALS && options.corner_normals == NULL);
  buffers = build(mesh, NULL); /* NULL options: the defaults (no corner normals: smooth) */
  CHECK(hw_render_buffers_n_vertices(buffers) == 8);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_POSITIONS) == 24);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_NORMALS) == 24);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_UVS) == 0);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_INTERLEAVED) == 0);
  CHECK(hw_render_buffers_stride(buffers) == 0);
  CHECK(index_count(buffers, HW_RENDER_INDICES_TRIANGLES) == 36);
  CHECK(index_count(buffers, HW_RENDER_INDICES_TRIANGLE_FACES) == 12);
  CHECK(index_count(buffers, HW_RENDER_INDICES_VERTEX_SOURCES) == 8);
  /* Lines: 12 edges, no boundary, no diagnostic given; glyphs for 8 vertices and 6 faces. */
  CHECK(float_count(buffers, HW_RENDER_FLOATS_WIREFRAME) == 12 * 6);
  CHECK(index_count(buffers, HW_RENDER_INDICES_WIREFRAME_SOURCES) == 12);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_BOUNDARY) == 0);
  CHECK(index_count(buffers, HW_RENDER_INDICES_BOUNDARY_SOURCES) == 0);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_NON_MANIFOLD) == 0);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_VERTEX_NORMALS) == 8 * 6);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_FACE_NORMALS) == 6 * 6);
  hw_render_buffers_free(buffers);

  options.shading = HW_SHADING_FLAT;
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_n_vertices(buffers) == 24);
  hw_render_buffers_free(buffers);

  options.shading = HW_SHADING_CREASE;
  options.crease_angle = 0.5; /* the cube's 90 degree edges are sharper */
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_n_vertices(buffers) == 24);
  hw_render_buffers_free(buffers);
  options.crease_angle = 3.2;
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_n_vertices(buffers) == 8);
  hw_render_buffers_free(buffers);
  hw_mesh_free(mesh);
}

static void interleaved_layout_with_corner_attributes(void) {
  hw_mesh *mesh = unit_cube();
  hw_render_options options = hw_render_options_default();
  size_t slots = hw_mesh_n_halfedge_slots(mesh), h;
  double normals[24 * 3], uvs[24 * 2];
  const float *data = NULL;
  size_t n = 0, r;
  hw_render_buffers *buffers;

  CHECK(slots == 24);
  /* One normal for all corners and a uv per face: the cube splits along every face border. */
  for (h = 0; h < slots; ++h) {
    hw_halfedge he = {(uint32_t)h};
    normals[3 * h] = 0, normals[3 * h + 1] = 0, normals[3 * h + 2] = 1;
    uvs[2 * h] = (double)hw_mesh_he_face(mesh, he).idx, uvs[2 * h + 1] = 0.25;
  }
  options.interleaved = true;
  options.corner_normals = normals;
  options.corner_uvs = uvs;
  options.n_corners = slots;
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_stride(buffers) == 8);
  CHECK(hw_render_buffers_n_vertices(buffers) == 24);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_POSITIONS) == 0);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_INTERLEAVED, &data, &n) == HW_OK &&
        n == 24 * 8);
  for (r = 0; data != NULL && r < 24; ++r) {
    CHECK(data[8 * r + 5] == 1.0f && data[8 * r + 7] == 0.25f);
    CHECK(fabsf(data[8 * r]) == 0.5f); /* the unit cube spans -0.5 .. 0.5 */
  }
  hw_render_buffers_free(buffers);
  hw_mesh_free(mesh);
}

/* The mesh's own corner normals and uvs (a file's vn/vt) are honoured by default; an explicit
 * flat, smooth or crease shading computes its normals instead. */
static void mesh_corner_attributes_are_honoured(void) {
  hw_mesh *mesh = unit_cube();
  hw_render_options options = hw_render_options_default();
  double normals[24 * 3], uvs[24 * 2];
  const float *data = NULL;
  size_t h, n = 0;
  hw_render_buffers *buffers;
  for (h = 0; h < 24; ++h) {
    normals[3 * h] = 1, normals[3 * h + 1] = 0, normals[3 * h + 2] = 0;
    uvs[2 * h] = 0.5, uvs[2 * h + 1] = 0.75;
  }
  CHECK(hw_mesh_corner_normals_set(mesh, normals, 24) == HW_OK);
  CHECK(hw_mesh_corner_uvs_set(mesh, uvs, 24) == HW_OK);
  CHECK(options.mesh_corner_normals && options.mesh_corner_uvs);

  /* One normal and one uv for every corner: a vertex per mesh vertex, all facing +x. */
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_n_vertices(buffers) == 8);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_NORMALS, &data, &n) == HW_OK && n == 24);
  CHECK(data != NULL && data[0] == 1.0f && data[1] == 0.0f && data[23] == 0.0f);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_UVS, &data, &n) == HW_OK && n == 16);
  CHECK(data != NULL && data[0] == 0.5f && data[15] == 0.75f);
  hw_render_buffers_free(buffers);

  /* An explicit shading wins over the mesh's normals: flat gives 24 vertices along the axes. */
  options.shading = HW_SHADING_FLAT;
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_n_vertices(buffers) == 24);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_NORMALS, &data, &n) == HW_OK && n == 72);
  for (h = 0; data != NULL && h < 24; ++h)
    CHECK(fabsf(data[3 * h]) + fabsf(data[3 * h + 1]) + fabsf(data[3 * h + 2]) == 1.0f);
  hw_render_buffers_free(buffers);

  /* Declined: the shading's normals (flat: 24 vertices) and no uvs. */
  options.mesh_corner_normals = false;
  options.mesh_corner_uvs = false;
  options.shading = HW_SHADING_FLAT;
  buffers = build(mesh, &options);
  CHECK(hw_render_buffers_n_vertices(buffers) == 24);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_UVS) == 0);
  hw_render_buffers_free(buffers);
  hw_mesh_free(mesh);
}

/* The normals of a build as a malloc'd copy (*n floats). */
static float *normals_of(const hw_mesh *mesh, hw_shading shading, size_t *n) {
  hw_render_options options = hw_render_options_default();
  hw_render_buffers *buffers;
  const float *data = NULL;
  float *copy = NULL;
  options.shading = shading;
  buffers = build(mesh, &options);
  *n = 0;
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_NORMALS, &data, n) == HW_OK && *n > 0);
  copy = (float *)malloc(*n * sizeof *copy);
  if (copy != NULL && data != NULL) memcpy(copy, data, *n * sizeof *copy);
  hw_render_buffers_free(buffers);
  return copy;
}

/* A real OBJ with its own normals (vn): the default shading shows the file's normals, and each
 * explicit shading wins over them, so the four give four different normal buffers. */
static void explicit_shadings_win_over_a_files_normals(void) {
  static const hw_shading shadings[] = {HW_SHADING_CORNER_NORMALS, HW_SHADING_FLAT,
                                        HW_SHADING_SMOOTH, HW_SHADING_CREASE};
  hw_mesh *mesh = NULL;
  float *normals[4];
  size_t n[4], i, j;
  const double *file_normals = NULL;
  size_t n_file_normals = 0;
  CHECK(hw_mesh_read(HALFWING_DATA_DIR "/meshes/polygonal/pmp_suzanne.obj", HW_BUILD_POLICY_REPAIR,
                     &mesh, NULL) == HW_OK);
  CHECK(hw_mesh_corner_normals_view(mesh, &file_normals, &n_file_normals) == HW_OK);
  CHECK(file_normals != NULL &&
        n_file_normals == hw_mesh_n_halfedge_slots(mesh));
  for (i = 0; i < 4; ++i) normals[i] = normals_of(mesh, shadings[i], &n[i]);
  for (i = 0; i < 4; ++i)
    for (j = i + 1; j < 4; ++j)
      CHECK(normals[i] != NULL && normals[j] != NULL &&
            (n[i] != n[j] || memcmp(normals[i], normals[j], n[i] * sizeof(float)) != 0));
  for (i = 0; i < 4; ++i) free(normals[i]);
  hw_mesh_free(mesh);
}

static void boundary_bounds_and_non_manifold_edges(void) {
  /* A 2 x 1 grid of quads: 8 boundary edges around 7 edges inside and out. */
  hw_mesh *mesh = NULL;
  hw_render_buffers *buffers;
  float lo[3], hi[3];
  CHECK(hw_surface_grid(2.0, 1.0, 2, 1, HW_CELL_FACES_QUADS, &mesh) == HW_OK);
  buffers = build(mesh, NULL);
  CHECK(index_count(buffers, HW_RENDER_INDICES_TRIANGLES) == 12);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_BOUNDARY) == 6 * 6);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_WIREFRAME) == 7 * 6);
  CHECK(hw_render_buffers_bounds(buffers, lo, hi) == HW_OK);
  CHECK(lo[0] == -1.0f && hi[0] == 1.0f && lo[1] == -0.5f && hi[1] == 0.5f && hi[2] == 0.0f);
  hw_render_buffers_free(buffers);
  hw_mesh_free(mesh);

  {
    /* Three triangles on the edge 0-1, repaired: the diagnostic reports the edge. */
    static const double positions[] = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0};
    static const uint32_t sizes[] = {3, 3, 3};
    static const uint32_t indices[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    hw_diagnostic *diagnostic = NULL;
    const float *line = NULL;
    size_t n = 0;
    CHECK(hw_mesh_from_indexed(positions, 5, sizes, 3, indices, 9, HW_BUILD_POLICY_REPAIR, &mesh,
                               &diagnostic) == HW_OK);
    CHECK(hw_render_buffers_build(mesh, diagnostic, NULL, &buffers) == HW_OK);
    CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_NON_MANIFOLD, &line, &n) == HW_OK &&
          n == 6);
    CHECK(line != NULL && line[2] == 0.0f && line[5] == 1.0f);
    hw_render_buffers_free(buffers);
    hw_diagnostic_free(diagnostic);
    hw_mesh_free(mesh);
  }
}

static void polygon_lists(void) {
  /* A square and a triangle in the plane, then the same in 3D. */
  static const double planar[] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 2, 0, 1, 1};
  static const double spatial[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 2, 0, 0, 1, 1, 0};
  static const uint32_t sizes[] = {4, 3};
  static const uint32_t bad_sizes[] = {4, 4};
  hw_render_buffers *buffers = BUFFERS_SENTINEL;
  const uint32_t *polygon_of = NULL;
  const float *normals = NULL;
  size_t n = 0;
  CHECK(hw_render_buffers_from_polygons(planar, 2, 7, sizes, 2, &buffers) == HW_OK);
  CHECK(hw_render_buffers_n_vertices(buffers) == 7);
  CHECK(index_count(buffers, HW_RENDER_INDICES_TRIANGLES) == 9);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_WIREFRAME) == 7 * 6);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_VERTEX_SOURCES, &polygon_of, &n) ==
        HW_OK);
  CHECK(n == 7 && polygon_of[3] == 0 && polygon_of[4] == 1);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_NORMALS, &normals, &n) == HW_OK &&
        n == 21);
  CHECK(normals[2] == 1.0f && normals[20] == 1.0f);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_BOUNDARY) == 0);
  hw_render_buffers_free(buffers);
  CHECK(hw_render_buffers_from_polygons(spatial, 3, 7, sizes, 2, &buffers) == HW_OK);
  CHECK(index_count(buffers, HW_RENDER_INDICES_TRIANGLE_FACES) == 3);
  hw_render_buffers_free(buffers);

  buffers = BUFFERS_SENTINEL;
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 2, 7, bad_sizes, 2, &buffers),
               HW_ERR_INVALID_INPUT, "8 corners");
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 4, 7, sizes, 2, &buffers),
               HW_ERR_INVALID_INPUT, "dimension");
  CHECK_STATUS(hw_render_buffers_from_polygons(NULL, 2, 7, sizes, 2, &buffers),
               HW_ERR_NULL_ARGUMENT, "corners");
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 2, 7, NULL, 2, &buffers),
               HW_ERR_NULL_ARGUMENT, "sizes");
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 2, 7, sizes, 2, NULL),
               HW_ERR_NULL_ARGUMENT, "out_buffers");
  CHECK(buffers == BUFFERS_SENTINEL);
}

/* Polygons that cannot be filled and corners that are not points are refused, naming the
 * polygon and the corner; nothing is handed out. */
static void polygon_lists_refuse_bad_polygons(void) {
  static const double planar[] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 2, 0, 1, 1};
  static const double spatial[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 2, 0, 0, 1, 1, 0};
  static const uint32_t point_then_rest[] = {1, 6};
  static const uint32_t segment_then_rest[] = {2, 5};
  static const uint32_t empty_then_all[] = {0, 7};
  static const uint32_t square_and_triangle[] = {4, 3};
  double with_nan[14], with_infinity[21];
  hw_render_buffers *buffers = BUFFERS_SENTINEL;
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 2, 7, point_then_rest, 2, &buffers),
               HW_ERR_INVALID_INPUT, "polygon 0 has 1 corners");
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 2, 7, segment_then_rest, 2, &buffers),
               HW_ERR_INVALID_INPUT, "polygon 0 has 2 corners");
  CHECK_STATUS(hw_render_buffers_from_polygons(planar, 2, 7, empty_then_all, 2, &buffers),
               HW_ERR_INVALID_INPUT, "polygon 0 has 0 corners");
  memcpy(with_nan, planar, sizeof with_nan);
  with_nan[2 * 5 + 1] = NAN; /* corner 1 of the triangle */
  CHECK_STATUS(hw_render_buffers_from_polygons(with_nan, 2, 7, square_and_triangle, 2, &buffers),
               HW_ERR_INVALID_INPUT, "polygon 1 corner 1");
  memcpy(with_infinity, spatial, sizeof with_infinity);
  with_infinity[3 * 2 + 2] = INFINITY; /* z of corner 2 of the square */
  CHECK_STATUS(hw_render_buffers_from_polygons(with_infinity, 3, 7, square_and_triangle, 2, &buffers),
               HW_ERR_INVALID_INPUT, "polygon 0 corner 2");
  CHECK(buffers == BUFFERS_SENTINEL);
}

/* Four sites, one per quadrant of [-2, 2]^2, and a duplicate of the first: four square cells
 * whose triangles, vertices and outline segments all name their site; the duplicate draws
 * nothing. */
static void voronoi_cell_buffers(void) {
  static const double sites[] = {-1, -1, 1, -1, 1, 1, -1, 1, -1, -1};
  hw_voronoi *v = NULL;
  hw_voronoi_cells *cells = NULL;
  hw_render_buffers *buffers = NULL;
  const float *xyz = NULL, *normals = NULL;
  const uint32_t *triangles = NULL, *triangle_sites = NULL, *vertex_sites = NULL;
  const uint32_t *segment_sites = NULL;
  size_t n_xyz = 0, n_normals = 0, n_triangles = 0, n_triangle_sites = 0, n_vertex_sites = 0;
  size_t n_segment_sites = 0, t, k;
  double area = 0;
  CHECK(hw_voronoi_build(sites, 5, &v) == HW_OK);
  CHECK(hw_voronoi_clip_rect(v, -2, -2, 2, 2, &cells) == HW_OK);
  hw_voronoi_free(v); /* the cells own their data, the buffers theirs */
  CHECK(hw_render_buffers_from_voronoi_cells(cells, &buffers) == HW_OK && buffers != NULL);
  hw_voronoi_cells_free(cells);

  CHECK(hw_render_buffers_n_vertices(buffers) == 16);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_POSITIONS, &xyz, &n_xyz) == HW_OK);
  CHECK(hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_NORMALS, &normals, &n_normals) == HW_OK);
  CHECK(n_xyz == 16 * 3 && n_normals == 16 * 3);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_TRIANGLES, &triangles, &n_triangles) ==
        HW_OK);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_TRIANGLE_FACES, &triangle_sites,
                                  &n_triangle_sites) == HW_OK);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_VERTEX_SOURCES, &vertex_sites,
                                  &n_vertex_sites) == HW_OK);
  CHECK(hw_render_buffers_indices(buffers, HW_RENDER_INDICES_WIREFRAME_SOURCES, &segment_sites,
                                  &n_segment_sites) == HW_OK);
  CHECK(n_triangles == 8 * 3 && n_triangle_sites == 8 && n_vertex_sites == 16);
  CHECK(float_count(buffers, HW_RENDER_FLOATS_WIREFRAME) == 16 * 6 && n_segment_sites == 16);
  for (k = 0; k < 16; ++k) {
    CHECK(xyz[3 * k + 2] == 0.0f && normals[3 * k + 2] == 1.0f);
    CHECK(vertex_sites[k] < 4 && segment_sites[k] < 4);
  }
  for (t = 0; t < 8; ++t) {
    const float *a = xyz + 3 * triangles[3 * t], *b = xyz + 3 * triangles[3 * t + 1];
    const float *c = xyz + 3 * triangles[3 * t + 2];
    const double signed_area =
        0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    CHECK(signed_area > 0); /* counter-clockwise */
    area += signed_area;
    /* every corner of the triangle belongs to its site's cell, which lies in its quadrant */
    CHECK(triangle_sites[t] < 4);
    for (k = 0; k < 3; ++k) {
      const uint32_t corner = triangles[3 * t + k];
      const double sx = sites[2 * triangle_sites[t]], sy = sites[2 * triangle_sites[t] + 1];
      CHECK(vertex_sites[corner] == triangle_sites[t]);
      CHECK(xyz[3 * corner] * sx >= 0 && xyz[3 * corner + 1] * sy >= 0);
    }
  }
  CHECK(fabs(area - 16) < 1e-5);
  hw_render_buffers_free(buffers);
}

static void bad_voronoi_cell_arguments(void) {
  static const double sites[] = {0, 0, 1, 0, 0, 1};
  hw_voronoi *v = NULL;
  hw_voronoi_cells *cells = NULL;
  hw_render_buffers *buffers = BUFFERS_SENTINEL;
  CHECK(hw_voronoi_build(sites, 3, &v) == HW_OK);
  CHECK(hw_voronoi_clip_rect(v, -1, -1, 2, 2, &cells) == HW_OK);
  CHECK_STATUS(hw_render_buffers_from_voronoi_cells(NULL, &buffers), HW_ERR_NULL_ARGUMENT,
               "cells");
  CHECK_STATUS(hw_render_buffers_from_voronoi_cells(cells, NULL), HW_ERR_NULL_ARGUMENT,
               "out_buffers");
  CHECK_STATUS(hw_render_buffers_from_voronoi_cells(NULL, NULL), HW_ERR_NULL_ARGUMENT, "");
  CHECK(buffers == BUFFERS_SENTINEL); /* outputs only on success */
  hw_voronoi_cells_free(cells);
  hw_voronoi_free(v);
}

static void bad_render_arguments(void) {
  hw_mesh *mesh = unit_cube();
  hw_render_buffers *buffers = BUFFERS_SENTINEL, *good = build(mesh, NULL);
  hw_render_options options = hw_render_options_default();
  const float *floats = NULL;
  const uint32_t *indices = NULL;
  double normals[3 * 4] = {0};
  size_t n = 0;
  float lo[3], hi[3];

  CHECK_STATUS(hw_render_buffers_build(NULL, NULL, NULL, &buffers), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, NULL, NULL), HW_ERR_NULL_ARGUMENT, "out_buffers");
  options.shading = 7;
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "shading");
  options = hw_render_options_default();
  options.weighting = 9;
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "weighting");
  options = hw_render_options_default();
  options.shading = HW_SHADING_CREASE;
  options.crease_angle = -1.0;
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "crease");
  options.crease_angle = nan("");
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "crease");
  options = hw_render_options_default();
  options.normal_length = -2.0;
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "glyph");
  options = hw_render_options_default();
  options.corner_normals = normals;
  options.n_corners = 4; /* the cube has 24 half-edge slots */
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "24 half-edge slots");
  options.corner_normals = NULL;
  options.corner_uvs = normals;
  CHECK_STATUS(hw_render_buffers_build(mesh, NULL, &options, &buffers), HW_ERR_INVALID_INPUT, "uvs");
  CHECK(buffers == BUFFERS_SENTINEL);

  CHECK_STATUS(hw_render_buffers_floats(NULL, HW_RENDER_FLOATS_POSITIONS, &floats, &n),
               HW_ERR_NULL_ARGUMENT, "buffers");
  CHECK_STATUS(hw_render_buffers_floats(good, 99, &floats, &n), HW_ERR_INVALID_INPUT, "99");
  CHECK_STATUS(hw_render_buffers_floats(good, HW_RENDER_FLOATS_POSITIONS, NULL, &n),
               HW_ERR_NULL_ARGUMENT, "out_data");
  CHECK_STATUS(hw_render_buffers_floats(good, HW_RENDER_FLOATS_POSITIONS, &floats, NULL),
               HW_ERR_NULL_ARGUMENT, "out_len");
  CHECK_STATUS(hw_render_buffers_indices(NULL, HW_RENDER_INDICES_TRIANGLES, &indices, &n),
               HW_ERR_NULL_ARGUMENT, "buffers");
  CHECK_STATUS(hw_render_buffers_indices(good, 99, &indices, &n), HW_ERR_INVALID_INPUT, "99");
  CHECK_STATUS(hw_render_buffers_indices(good, HW_RENDER_INDICES_TRIANGLES, NULL, &n),
               HW_ERR_NULL_ARGUMENT, "out_data");
  CHECK_STATUS(hw_render_buffers_indices(good, HW_RENDER_INDICES_TRIANGLES, &indices, NULL),
               HW_ERR_NULL_ARGUMENT, "out_len");
  CHECK(hw_render_buffers_n_vertices(NULL) == 0 && last_error_contains("buffers"));
  CHECK(hw_render_buffers_stride(NULL) == 0 && last_error_contains("buffers"));
  CHECK_STATUS(hw_render_buffers_bounds(NULL, lo, hi), HW_ERR_NULL_ARGUMENT, "buffers");
  /* Both outputs are required (NULL does not mean "skip"), and a refusal writes neither. */
  lo[0] = hi[0] = -7.0f;
  CHECK_STATUS(hw_render_buffers_bounds(good, NULL, hi), HW_ERR_NULL_ARGUMENT, "out_min");
  CHECK_STATUS(hw_render_buffers_bounds(good, lo, NULL), HW_ERR_NULL_ARGUMENT, "out_max");
  CHECK(lo[0] == -7.0f && hi[0] == -7.0f);

  hw_render_buffers_free(NULL); /* a no-op */
  hw_render_buffers_free(good);
  hw_render_buffers_free(good); /* refused, not freed twice */
  CHECK(last_error_contains("already freed"));
  hw_mesh_free(mesh);
}

/* Euler characteristic V - E + F and the number of boundary loops of a generated mesh. */
static void check_topology(hw_mesh *mesh, long euler, size_t loops) {
  size_t n_loops = SIZE_MAX;
  CHECK(mesh != NULL && mesh != MESH_SENTINEL);
  CHECK((long)hw_mesh_n_vertices(mesh) - (long)hw_mesh_n_edges(mesh) + (long)hw_mesh_n_faces(mesh) == euler);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  CHECK(hw_mesh_n_boundary_loops(mesh, &n_loops) == HW_OK && n_loops == loops);
  hw_mesh_free(mesh);
}

static void generators(void) {
  static const double square[] = {1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0};
  static const double lifted[] = {1, 0, 1, 0, 1, 1, -1, 0, 1, 0, -1, 1};
  static const double half_circle[] = {0, 0, -1, 1, 0, 0, 0, 0, 1}; /* pole to pole */
  static const double up[] = {0, 0, 1}, origin[] = {0, 0, 0};
  hw_mesh *mesh = NULL;

  CHECK(hw_surface_tetrahedron(&mesh) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 4 && hw_mesh_n_faces(mesh) == 4);
  check_topology(mesh, 2, 0);
  CHECK(hw_surface_cube(2.0, &mesh) == HW_OK);
  check_topology(mesh, 2, 0);
  CHECK(hw_surface_icosphere(1.0, 2, &mesh) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 20 * 16);
  check_topology(mesh, 2, 0);
  CHECK(hw_surface_torus(2.0, 0.5, 12, 8, HW_CELL_FACES_TRIANGLES, &mesh) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 2 * 12 * 8);
  check_topology(mesh, 0, 0);
  CHECK(hw_surface_grid(1.0, 1.0, 3, 2, HW_CELL_FACES_QUADS, &mesh) == HW_OK);
  check_topology(mesh, 1, 1);
  CHECK(hw_surface_sweep(square, 4, true, up, 2, HW_CELL_FACES_QUADS, &mesh) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 8);
  check_topology(mesh, 0, 2);
  CHECK(hw_surface_revolution(half_circle, 3, false, origin, up, true, 0.0, 6, HW_CAPS_NONE,
                              HW_CELL_FACES_QUADS, &mesh) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == 2 + 6);
  check_topology(mesh, 2, 0);
  CHECK(hw_surface_revolution(square, 2, false, origin, up, false, 1.5, 4, HW_CAPS_NONE,
                              HW_CELL_FACES_TRIANGLES, &mesh) == HW_OK);
  check_topology(mesh, 1, 1);
  CHECK(hw_surface_ruled(square, lifted, 4, true, 1, HW_CELL_FACES_QUADS, &mesh) == HW_OK);
  check_topology(mesh, 0, 2);
}

static void bad_generator_parameters(void) {
  static const double line[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  static const double nan_line[] = {0, 0, 0, 1, NAN, 0};
  static const double up[] = {0, 0, 1}, zero[] = {0, 0, 0}, along_x[] = {1, 0, 0};
  hw_mesh *mesh = MESH_SENTINEL;

  CHECK_STATUS(hw_surface_tetrahedron(NULL), HW_ERR_NULL_ARGUMENT, "out_mesh");
  CHECK_STATUS(hw_surface_cube(-1.0, &mesh), HW_ERR_INVALID_INPUT, "side");
  CHECK_STATUS(hw_surface_cube(nan(""), &mesh), HW_ERR_INVALID_INPUT, "side");
  CHECK_STATUS(hw_surface_cube(1.0, NULL), HW_ERR_NULL_ARGUMENT, "out_mesh");
  CHECK_STATUS(hw_surface_icosphere(0.0, 1, &mesh), HW_ERR_INVALID_INPUT, "radius");
  CHECK_STATUS(hw_surface_icosphere(1.0, 99, &mesh), HW_ERR_INVALID_INPUT, "level");
  CHECK_STATUS(hw_surface_torus(1.0, 2.0, 8, 8, HW_CELL_FACES_QUADS, &mesh), HW_ERR_INVALID_INPUT,
               "minor radius");
  CHECK_STATUS(hw_surface_torus(2.0, 1.0, 2, 8, HW_CELL_FACES_QUADS, &mesh), HW_ERR_INVALID_INPUT,
               "major_steps");
  CHECK_STATUS(hw_surface_torus(2.0, 1.0, 8, 8, 5, &mesh), HW_ERR_INVALID_INPUT, "cell faces");
  CHECK_STATUS(hw_surface_grid(1.0, 1.0, 0, 1, HW_CELL_FACES_QUADS, &mesh), HW_ERR_INVALID_INPUT,
               "cells_x");
  CHECK_STATUS(hw_surface_grid(1.0, -1.0, 1, 1, HW_CELL_FACES_QUADS, &mesh), HW_ERR_INVALID_INPUT,
               "height");
  CHECK_STATUS(hw_surface_sweep(NULL, 3, false, up, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_NULL_ARGUMENT, "profile");
  CHECK_STATUS(hw_surface_sweep(line, 3, false, NULL, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_NULL_ARGUMENT, "direction");
  CHECK_STATUS(hw_surface_sweep(line, 3, false, zero, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "zero length");
  CHECK_STATUS(hw_surface_sweep(line, 3, false, along_x, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "parallel");
  CHECK_STATUS(hw_surface_sweep(line, 1, false, up, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "at least 2");
  CHECK_STATUS(hw_surface_sweep(nan_line, 2, false, up, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "non-finite");
  CHECK_STATUS(hw_surface_sweep(line, 3, false, up, 0, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "steps");
  CHECK_STATUS(hw_surface_sweep(line, 3, false, up, 1, HW_CELL_FACES_QUADS, NULL),
               HW_ERR_NULL_ARGUMENT, "out_mesh");
  CHECK_STATUS(hw_surface_revolution(line, 3, false, zero, along_x, true, 0.0, 8, HW_CAPS_NONE,
                                     HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "lies on the axis");
  CHECK_STATUS(hw_surface_revolution(line, 3, false, zero, up, false, 7.0, 8, HW_CAPS_NONE,
                                     HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "outside (0, 2");
  CHECK_STATUS(hw_surface_revolution(line, 3, false, zero, up, true, 0.0, 2, HW_CAPS_NONE,
                                     HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "steps");
  CHECK_STATUS(
      hw_surface_revolution(line, 3, false, zero, up, true, 0.0, 8, 9, HW_CELL_FACES_QUADS, &mesh),
      HW_ERR_INVALID_INPUT, "caps");
  CHECK_STATUS(hw_surface_revolution(line, 3, false, NULL, up, true, 0.0, 8, HW_CAPS_NONE,
                                     HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_NULL_ARGUMENT, "axis_origin");
  CHECK_STATUS(hw_surface_revolution(line, 3, false, zero, NULL, true, 0.0, 8, HW_CAPS_NONE,
                                     HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_NULL_ARGUMENT, "axis_direction");
  CHECK_STATUS(hw_surface_ruled(line, NULL, 3, false, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_NULL_ARGUMENT, "second");
  CHECK_STATUS(hw_surface_ruled(line, line, 3, false, 1, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "collapses");
  CHECK_STATUS(hw_surface_ruled(line, line, 3, false, 0, HW_CELL_FACES_QUADS, &mesh),
               HW_ERR_INVALID_INPUT, "steps");
  CHECK(mesh == MESH_SENTINEL);
}

int main(void) {
  shading_modes_split_vertices();
  interleaved_layout_with_corner_attributes();
  mesh_corner_attributes_are_honoured();
  explicit_shadings_win_over_a_files_normals();
  boundary_bounds_and_non_manifold_edges();
  polygon_lists();
  polygon_lists_refuse_bad_polygons();
  bad_render_arguments();
  voronoi_cell_buffers();
  bad_voronoi_cell_arguments();
  generators();
  bad_generator_parameters();
  return check_summary("test_render");
}
