/* The Voronoi C API: construction, views, edges, meshes, clipping, queries, Lloyd, rasters and
 * SVG, on small inputs whose answers are known, plus every bad argument of each call. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* Four corners of a square, one site inside it, and a copy of corner 1. */
static const double five_and_a_copy[] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 2, 4, 0};
enum { N_SITES = 6, DUPLICATE = 5, CENTRE = 4 };

static hw_voronoi *build(const double *xy, size_t n) {
  hw_voronoi *v = NULL;
  CHECK(hw_voronoi_build(xy, n, &v) == HW_OK && v != NULL);
  return v;
}

static double distance(const double *a, const double *b) { return hypot(a[0] - b[0], a[1] - b[1]); }

static void counts_and_views(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES);
  const uint32_t *rep = NULL, *tri = NULL, *twins = NULL, *hull = NULL, *tri_vertex = NULL, *origin = NULL,
                 *next = NULL, *prev = NULL, *site = NULL, *cell = NULL, *vertex_edge = NULL;
  const double *sites = NULL, *vertices = NULL;
  size_t n = 0, n_tri = 0, n_half = 0, n_vert = 0, i;
  uint32_t s;

  CHECK(hw_voronoi_n_sites(v) == N_SITES);
  CHECK(hw_voronoi_n_unique_sites(v) == N_SITES - 1);
  CHECK(hw_voronoi_dimension(v) == HW_SITE_DIMENSION_PLANE);
  /* Five distinct sites, four on the hull: 2n - 2 - h = 4 triangles, 8 edges. */
  CHECK(hw_voronoi_n_triangles(v) == 4);
  CHECK(hw_voronoi_n_halfedges(v) == 16);

  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_REPRESENTATIVE, &rep, &n) == HW_OK && n == N_SITES);
  CHECK(rep[DUPLICATE] == 1 && rep[1] == 1 && rep[CENTRE] == CENTRE);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_TRIANGLES, &tri, &n_tri) == HW_OK && n_tri == 12);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_TRIANGLE_TWINS, &twins, &n) == HW_OK && n == 12);
  /* The four hull edges have no twin; interior ones pair up with opposite directions. */
  for (n = 0, i = 0; i < 12; ++i) {
    if (twins[i] == HW_INVALID_INDEX) {
      n++;
    } else {
      CHECK(twins[twins[i]] == i && tri[twins[i]] == tri[3 * (i / 3) + (i + 1) % 3]);
    }
  }
  CHECK(n == 4);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HULL, &hull, &n) == HW_OK && n == 4);
  for (i = 0; i < 4; ++i) CHECK(hull[i] < 4);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_TRIANGLE_VERTEX, &tri_vertex, &n) == HW_OK && n == 4);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HALFEDGE_ORIGIN, &origin, &n_half) == HW_OK &&
        n_half == 16);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HALFEDGE_NEXT, &next, &n) == HW_OK && n == 16);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HALFEDGE_PREV, &prev, &n) == HW_OK && n == 16);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HALFEDGE_SITE, &site, &n) == HW_OK && n == 16);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_CELL_HALFEDGE, &cell, &n) == HW_OK && n == N_SITES);
  CHECK(cell[DUPLICATE] == HW_INVALID_INDEX);
  CHECK(hw_voronoi_sites(v, &sites, &n) == HW_OK && n == N_SITES && sites[2 * DUPLICATE] == 4);
  CHECK(hw_voronoi_vertices(v, &vertices, &n_vert) == HW_OK && n_vert == hw_voronoi_n_vertices(v));
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_VERTEX_HALFEDGE, &vertex_edge, &n) == HW_OK &&
        n == n_vert);

  /* Every cell walk closes, every half-edge bounds its site's cell, and next/prev agree; every
   * finite half-edge start is equidistant from the sites on both sides. */
  for (s = 0; s < N_SITES - 1; ++s) {
    uint32_t h = cell[s], start = h, steps = 0;
    do {
      CHECK(site[h] == s && prev[next[h]] == h);
      if (origin[h] != HW_INVALID_INDEX) {
        const double *p = vertices + 2 * origin[h];
        CHECK(fabs(distance(p, sites + 2 * site[h]) - distance(p, sites + 2 * site[h ^ 1u])) <
              1e-12);
      }
      h = next[h];
    } while (h != start && ++steps < 16);
    CHECK(h == start);
  }
  /* The vertex of each triangle is its circumcentre. */
  for (i = 0; i < 4; ++i) {
    const double *c = vertices + 2 * tri_vertex[i];
    const double r = distance(c, sites + 2 * tri[3 * i]);
    CHECK(fabs(distance(c, sites + 2 * tri[3 * i + 1]) - r) < 1e-12);
    CHECK(fabs(distance(c, sites + 2 * tri[3 * i + 2]) - r) < 1e-12);
  }
  CHECK(origin[vertex_edge[0]] == 0);

  CHECK_STATUS(hw_voronoi_view(v, 99, &rep, &n), HW_ERR_INVALID_INPUT, "unknown Voronoi array");
  CHECK_STATUS(hw_voronoi_view(v, HW_VORONOI_ARRAY_HULL, NULL, &n), HW_ERR_NULL_ARGUMENT,
               "out_data");
  CHECK_STATUS(hw_voronoi_view(NULL, HW_VORONOI_ARRAY_HULL, &rep, &n), HW_ERR_NULL_ARGUMENT,
               "voronoi");
  CHECK_STATUS(hw_voronoi_sites(v, &sites, NULL), HW_ERR_NULL_ARGUMENT, "out_n_sites");
  CHECK_STATUS(hw_voronoi_vertices(NULL, &vertices, &n), HW_ERR_NULL_ARGUMENT, "voronoi");
  CHECK(hw_voronoi_n_sites(NULL) == 0 && last_error_contains("voronoi"));
  CHECK(hw_voronoi_n_unique_sites(NULL) == 0 && hw_voronoi_n_triangles(NULL) == 0);
  CHECK(hw_voronoi_n_vertices(NULL) == 0 && hw_voronoi_n_halfedges(NULL) == 0);
  CHECK(hw_voronoi_dimension(NULL) == HW_SITE_DIMENSION_EMPTY);
  hw_voronoi_free(v);
}

/* Ids by index: a function, as compound literals are not C++ (this file is also built as C++). */
static hw_site site_at(uint32_t idx) {
  hw_site site = {idx};
  return site;
}

static hw_voronoi_halfedge halfedge_at(uint32_t idx) {
  hw_voronoi_halfedge halfedge = {idx};
  return halfedge;
}

static void edges(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES);
  hw_voronoi_edge e;
  hw_voronoi_halfedge h;
  uint32_t rays = 0, segments = 0;
  for (h.idx = 0; h.idx < hw_voronoi_n_halfedges(v); ++h.idx) {
    CHECK(hw_voronoi_edge_describe(v, h, &e) == HW_OK);
    if (e.kind == HW_VORONOI_EDGE_KIND_SEGMENT) {
      segments++;
      CHECK(e.origin.idx != HW_INVALID_INDEX && e.target.idx != HW_INVALID_INDEX);
      CHECK(e.direction[0] == e.end[0] - e.point[0] && e.direction[1] == e.end[1] - e.point[1]);
    } else {
      rays++;
      CHECK(e.kind == HW_VORONOI_EDGE_KIND_RAY);
      /* A ray is perpendicular to the hull edge joining its two sites. */
      const double *a = five_and_a_copy + 2 * e.site.idx;
      const double *b = five_and_a_copy + 2 * e.opposite_site.idx;
      CHECK(fabs(e.direction[0] * (a[0] - b[0]) + e.direction[1] * (a[1] - b[1])) < 1e-12);
    }
  }
  /* Four interior Delaunay edges give segments, four hull edges rays (both half-edges each). */
  CHECK(segments == 8 && rays == 8);
  CHECK_STATUS(hw_voronoi_edge_describe(v, halfedge_at(16), &e), HW_ERR_INVALID_HANDLE,
               "Voronoi half-edge 16 out of range");
  CHECK_STATUS(hw_voronoi_edge_describe(v, halfedge_at(0), NULL), HW_ERR_NULL_ARGUMENT,
               "out_edge");
  hw_voronoi_free(v);
}

static void queries(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES), *empty = build(NULL, 0);
  const hw_site none = {HW_INVALID_INDEX}, centre = {CENTRE}, duplicate = {DUPLICATE};
  hw_site s = {0}, around[8], around_copy[8];
  hw_voronoi_halfedge h = {0};
  size_t needed = 0, needed_copy = 0;
  hw_voronoi_edge e;

  CHECK(hw_voronoi_nearest_site(v, 3.9, 0.2, none, &s) == HW_OK && s.idx == 1);
  CHECK(hw_voronoi_nearest_site(v, 1.1, 2.1, site_at(0), &s) == HW_OK && s.idx == CENTRE);
  CHECK_STATUS(hw_voronoi_nearest_site(v, NAN, 0, none, &s), HW_ERR_INVALID_INPUT, "non-finite");
  CHECK_STATUS(hw_voronoi_nearest_site(empty, 0, 0, none, &s), HW_ERR_NOT_FOUND, "no sites");
  CHECK_STATUS(hw_voronoi_nearest_site(v, 0, 0, none, NULL), HW_ERR_NULL_ARGUMENT, "out_site");

  CHECK(hw_voronoi_neighbours(v, centre, around, 8, &needed) == HW_OK && needed == 4);
  /* A duplicate answers for its representative. */
  CHECK(hw_voronoi_neighbours(v, site_at(1), around, 8, &needed) == HW_OK);
  CHECK(hw_voronoi_neighbours(v, duplicate, around_copy, 8, &needed_copy) == HW_OK);
  CHECK(needed == needed_copy && memcmp(around, around_copy, needed * sizeof *around) == 0);
  CHECK_STATUS(hw_voronoi_neighbours(v, centre, around, 2, &needed), HW_ERR_BUFFER_TOO_SMALL,
               "4 are needed");
  CHECK(needed == 4);
  CHECK_STATUS(hw_voronoi_neighbours(v, site_at(99), around, 8, &needed), HW_ERR_INVALID_HANDLE,
               "site 99 out of range");

  CHECK(hw_voronoi_edge_between(v, site_at(0), centre, &h) == HW_OK);
  CHECK(hw_voronoi_edge_describe(v, h, &e) == HW_OK && e.site.idx == 0 &&
        e.opposite_site.idx == CENTRE);
  CHECK(hw_voronoi_edge_between(v, centre, duplicate, &h) == HW_OK);
  CHECK(hw_voronoi_edge_describe(v, h, &e) == HW_OK && e.site.idx == CENTRE &&
        e.opposite_site.idx == 1);
  /* Opposite corners are separated by the centre site's cell. */
  CHECK_STATUS(hw_voronoi_edge_between(v, site_at(0), site_at(2), &h), HW_ERR_NOT_FOUND,
               "share no edge");
  CHECK_STATUS(hw_voronoi_edge_between(v, site_at(0), site_at(6), &h), HW_ERR_INVALID_HANDLE,
               "out of range");
  CHECK_STATUS(hw_voronoi_edge_between(v, site_at(0), site_at(1), NULL), HW_ERR_NULL_ARGUMENT,
               "out_halfedge");
  hw_voronoi_free(v);
  hw_voronoi_free(empty);
}

static void meshes(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES);
  hw_voronoi_cells *cells = NULL;
  hw_mesh *mesh = NULL;
  hw_site face_sites[8];
  size_t needed = 0, i;

  CHECK(hw_voronoi_delaunay_mesh(v, &mesh) == HW_OK);
  CHECK(hw_mesh_n_vertices(mesh) == N_SITES && hw_mesh_n_faces(mesh) == 4);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
  mesh = NULL;

  CHECK(hw_voronoi_clip_rect(v, -1, -1, 5, 5, &cells) == HW_OK);
  CHECK(hw_voronoi_cells_mesh(cells, &mesh) == HW_OK);
  CHECK(hw_mesh_n_faces(mesh) == 5 && hw_mesh_check(mesh) == HW_OK);
  /* Neighbouring cells share their edges: one connected disc. */
  CHECK(hw_mesh_n_edges(mesh) + 1 == hw_mesh_n_vertices(mesh) + hw_mesh_n_faces(mesh));
  CHECK(hw_voronoi_cells_face_sites(cells, face_sites, 8, &needed) == HW_OK && needed == 5);
  for (i = 0; i < 5; ++i) CHECK(face_sites[i].idx == i);
  CHECK_STATUS(hw_voronoi_cells_face_sites(cells, face_sites, 4, &needed), HW_ERR_BUFFER_TOO_SMALL,
               "5 are needed");
  needed = 4242;
  face_sites[0].idx = 77;
  CHECK_STATUS(hw_voronoi_cells_face_sites(NULL, face_sites, 8, &needed), HW_ERR_NULL_ARGUMENT,
               "cells");
  CHECK(needed == 4242 && face_sites[0].idx == 77);
  hw_mesh_free(mesh);

  CHECK_STATUS(hw_voronoi_delaunay_mesh(v, NULL), HW_ERR_NULL_ARGUMENT, "out_mesh");
  CHECK_STATUS(hw_voronoi_cells_mesh(NULL, &mesh), HW_ERR_NULL_ARGUMENT, "cells");
  hw_voronoi_cells_free(cells);
  hw_voronoi_free(v);
}

static void clipping(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES);
  hw_voronoi_cells *cells = NULL, *diamond = NULL;
  const double *xy = NULL;
  const uint32_t *polygon = NULL;
  size_t n_positions = 0, len = 0;
  double area = 0, total = 0, centroid[2];
  hw_site s;
  /* Clockwise on purpose: either orientation is accepted. */
  const double diamond_xy[] = {2, -1, -1, 2, 2, 5, 5, 2};
  const double star[] = {0, 0, 4, 0, 1, 1, 0, 4};
  const double collinear[] = {0, 0, 1, 1, 2, 2};
  const double with_nan[] = {0, 0, 1, 0, NAN, 1};

  CHECK(hw_voronoi_clip_rect(v, -1, -1, 5, 5, &cells) == HW_OK);
  CHECK(hw_voronoi_cells_n_cells(cells) == N_SITES);
  CHECK(hw_voronoi_cells_positions(cells, &xy, &n_positions) == HW_OK && n_positions >= 4);
  for (s.idx = 0; s.idx < N_SITES; ++s.idx) {
    size_t k;
    CHECK(hw_voronoi_cells_polygon(cells, s, &polygon, &len) == HW_OK);
    CHECK(hw_voronoi_cells_area_centroid(cells, s, &area, NULL) == HW_OK);
    total += area;
    if (s.idx == DUPLICATE) {
      CHECK(len == 0 && polygon == NULL && area == 0);
      CHECK_STATUS(hw_voronoi_cells_area_centroid(cells, s, NULL, centroid), HW_ERR_NOT_FOUND,
                   "empty");
      continue;
    }
    CHECK(len >= 3 && area > 0);
    CHECK(hw_voronoi_cells_area_centroid(cells, s, NULL, centroid) == HW_OK);
    /* Every site lies in its own (convex) cell: left of every edge. */
    for (k = 0; k < len; ++k) {
      const double *a = xy + 2 * polygon[k], *b = xy + 2 * polygon[(k + 1) % len];
      const double *p = five_and_a_copy + 2 * s.idx;
      CHECK((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) > 0);
    }
  }
  CHECK(fabs(total - 36) < 36e-12);

  CHECK(hw_voronoi_clip_convex(v, diamond_xy, 4, &diamond) == HW_OK);
  for (total = 0, s.idx = 0; s.idx < N_SITES; ++s.idx) {
    CHECK(hw_voronoi_cells_area_centroid(diamond, s, &area, NULL) == HW_OK);
    total += area;
  }
  CHECK(fabs(total - 18) < 18e-12);
  hw_voronoi_cells_free(diamond);
  diamond = NULL;

  CHECK_STATUS(hw_voronoi_clip_rect(v, 0, 0, 0, 1, &diamond), HW_ERR_INVALID_INPUT,
               "zero or negative extent");
  CHECK_STATUS(hw_voronoi_clip_rect(v, 0, 0, INFINITY, 1, &diamond), HW_ERR_INVALID_INPUT,
               "non-finite");
  CHECK_STATUS(hw_voronoi_clip_convex(v, star, 4, &diamond), HW_ERR_INVALID_INPUT, "not convex");
  CHECK_STATUS(hw_voronoi_clip_convex(v, collinear, 3, &diamond), HW_ERR_INVALID_INPUT,
               "zero area");
  CHECK_STATUS(hw_voronoi_clip_convex(v, star, 2, &diamond), HW_ERR_INVALID_INPUT,
               "fewer than three");
  CHECK_STATUS(hw_voronoi_clip_convex(v, with_nan, 3, &diamond), HW_ERR_INVALID_INPUT,
               "non-finite");
  CHECK_STATUS(hw_voronoi_clip_convex(v, NULL, 3, &diamond), HW_ERR_NULL_ARGUMENT, "clip_xy");
  CHECK_STATUS(hw_voronoi_clip_rect(NULL, 0, 0, 1, 1, &diamond), HW_ERR_NULL_ARGUMENT, "voronoi");
  CHECK_STATUS(hw_voronoi_clip_rect(v, 0, 0, 1, 1, NULL), HW_ERR_NULL_ARGUMENT, "out_cells");
  CHECK(diamond == NULL);

  CHECK_STATUS(hw_voronoi_cells_polygon(cells, site_at(N_SITES), &polygon, &len),
               HW_ERR_INVALID_HANDLE, "out of range");
  CHECK_STATUS(hw_voronoi_cells_polygon(cells, site_at(0), NULL, &len), HW_ERR_NULL_ARGUMENT,
               "out_indices");
  CHECK_STATUS(hw_voronoi_cells_area_centroid(cells, site_at(7), &area, NULL),
               HW_ERR_INVALID_HANDLE, "out of range");
  CHECK_STATUS(hw_voronoi_cells_positions(cells, NULL, &len), HW_ERR_NULL_ARGUMENT, "out_xy");
  CHECK(hw_voronoi_cells_n_cells(NULL) == 0 && last_error_contains("cells"));

  hw_voronoi_cells_free(cells);
  hw_voronoi_cells_free(cells);
  CHECK(last_error_contains("already freed"));
  hw_voronoi_cells_free(NULL);
  hw_voronoi_free(v);
}

static void degenerate_inputs(void) {
  const double line[] = {0, 0, 1, 1, 3, 3, 2, 2};
  const double same[] = {1, 1, 1, 1, 1, 1};
  const double grid[] = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1, 0, 2, 1, 2, 2, 2};
  const double huge[] = {1e200, 0, 0, 1e200, -1e200, -1e200, 3e199, 2e199};
  hw_voronoi *v = NULL;
  hw_voronoi_cells *cells = NULL;
  hw_voronoi_edge e;
  const uint32_t *hull = NULL, *vertex_edge = NULL, *next_prev = NULL;
  size_t n = 0;
  double area = 0;
  hw_voronoi_halfedge line_edge;
  hw_site nearest;
  uint32_t h, u;

  v = build(NULL, 0);
  CHECK(hw_voronoi_dimension(v) == HW_SITE_DIMENSION_EMPTY && hw_voronoi_n_halfedges(v) == 0);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HULL, &hull, &n) == HW_OK && n == 0 && hull == NULL);
  hw_voronoi_free(v);

  v = build(same, 3);
  CHECK(hw_voronoi_dimension(v) == HW_SITE_DIMENSION_POINT && hw_voronoi_n_unique_sites(v) == 1);
  CHECK(hw_voronoi_clip_rect(v, 0, 0, 2, 3, &cells) == HW_OK);
  CHECK(hw_voronoi_cells_area_centroid(cells, site_at(0), &area, NULL) == HW_OK && area == 6);
  hw_voronoi_cells_free(cells);
  hw_voronoi_free(v);

  v = build(line, 4);
  CHECK(hw_voronoi_dimension(v) == HW_SITE_DIMENSION_LINE && hw_voronoi_n_triangles(v) == 0);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HULL, &hull, &n) == HW_OK && n == 4);
  CHECK(hull[0] == 0 && hull[1] == 1 && hull[2] == 3 && hull[3] == 2);
  CHECK(hw_voronoi_n_halfedges(v) == 6);
  for (line_edge.idx = 0; line_edge.idx < 6; ++line_edge.idx)
    CHECK(hw_voronoi_edge_describe(v, line_edge, &e) == HW_OK &&
          e.kind == HW_VORONOI_EDGE_KIND_LINE);
  hw_voronoi_free(v);

  /* 3 × 3 grid: each unit square's four corners are cocircular, so its centre is one Voronoi
   * vertex of degree 4 and no edge has zero length. */
  v = build(grid, 9);
  CHECK(hw_voronoi_n_vertices(v) == 4 && hw_voronoi_n_halfedges(v) == 2 * 12);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_VERTEX_HALFEDGE, &vertex_edge, &n) == HW_OK);
  CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_HALFEDGE_PREV, &next_prev, &n) == HW_OK);
  for (u = 0; u < 4; ++u) {
    uint32_t start = vertex_edge[u], degree = 0;
    h = start;
    do {
      degree++;
      h = next_prev[h] ^ 1u;
    } while (h != start && degree < 10);
    CHECK(degree == 4);
  }
  hw_voronoi_free(v);

  /* Magnitudes near both ends of the double range: exact predicates still find the three
   * triangles, and the circumcentres are equidistant from their corners. */
  for (u = 0; u < 2; ++u) {
    double scaled[8];
    const double *vertices = NULL;
    const uint32_t *tri = NULL, *tri_vertex = NULL;
    size_t k;
    for (k = 0; k < 8; ++k) scaled[k] = u == 0 ? huge[k] : huge[k] * 1e-250 * 1e-250; /* 1e-300 */
    v = build(scaled, 4);
    CHECK(hw_voronoi_n_triangles(v) == 3);
    CHECK(hw_voronoi_vertices(v, &vertices, &n) == HW_OK && n == 3);
    CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_TRIANGLES, &tri, &n) == HW_OK);
    CHECK(hw_voronoi_view(v, HW_VORONOI_ARRAY_TRIANGLE_VERTEX, &tri_vertex, &n) == HW_OK);
    for (k = 0; k < 3; ++k) {
      const double *c = vertices + 2 * tri_vertex[k];
      const double r = distance(c, scaled + 2 * tri[3 * k]);
      CHECK(fabs(distance(c, scaled + 2 * tri[3 * k + 1]) - r) <= 1e-12 * r);
      CHECK(fabs(distance(c, scaled + 2 * tri[3 * k + 2]) - r) <= 1e-12 * r);
    }
    CHECK(hw_voronoi_nearest_site(v, scaled[6], scaled[7], site_at(HW_INVALID_INDEX), &nearest) ==
          HW_OK);
    CHECK(nearest.idx == 3);
    hw_voronoi_free(v);
  }
}

static void bad_construction(void) {
  const double with_nan[] = {0, 0, 1, 0, 0, NAN};
  const double with_inf[] = {0, 0, INFINITY, 0};
  hw_voronoi *v = NULL;
  CHECK_STATUS(hw_voronoi_build(with_nan, 3, &v), HW_ERR_INVALID_INPUT, "site 2");
  CHECK_STATUS(hw_voronoi_build(with_inf, 2, &v), HW_ERR_INVALID_INPUT, "site 1");
  CHECK_STATUS(hw_voronoi_build(NULL, 3, &v), HW_ERR_NULL_ARGUMENT, "xy");
  CHECK_STATUS(hw_voronoi_build(with_nan, 1, NULL), HW_ERR_NULL_ARGUMENT, "out_voronoi");
  CHECK(v == NULL);
  v = build(with_nan, 2);
  hw_voronoi_free(v);
  hw_voronoi_free(v);
  CHECK(last_error_contains("already freed"));
  hw_voronoi_free(NULL);
}

/* The triangulation alone: the same triangles, twins, hull and representatives as the diagram's,
 * on the square with a centre and a copy, on collinear sites, and on a random cloud. */
static void delaunay_alone(void) {
  static const double collinear[] = {0, 0, 2, 2, 1, 1, 2, 2};
  const hw_voronoi_array arrays[] = {HW_VORONOI_ARRAY_REPRESENTATIVE, HW_VORONOI_ARRAY_TRIANGLES,
                                     HW_VORONOI_ARRAY_TRIANGLE_TWINS, HW_VORONOI_ARRAY_HULL};
  double cloud[2 * 500];
  const struct {
    const double *xy;
    size_t n;
    hw_site_dimension dimension;
  } inputs[] = {{five_and_a_copy, N_SITES, HW_SITE_DIMENSION_PLANE},
                {collinear, 4, HW_SITE_DIMENSION_LINE},
                {cloud, 500, HW_SITE_DIMENSION_PLANE},
                {NULL, 0, HW_SITE_DIMENSION_EMPTY}};
  const uint32_t *data = NULL, *expected = NULL;
  size_t i, k, n = 0, n_expected = 0;
  uint32_t state = 12345;
  hw_delaunay *d = NULL;

  for (i = 0; i < 2 * 500; ++i) {
    state = state * 1664525u + 1013904223u;
    cloud[i] = (double)(state >> 8) / (double)(1u << 24);
  }
  for (i = 0; i < sizeof inputs / sizeof inputs[0]; ++i) {
    hw_voronoi *v = build(inputs[i].xy, inputs[i].n);
    CHECK(hw_delaunay_build(inputs[i].xy, inputs[i].n, &d) == HW_OK && d != NULL);
    CHECK(hw_delaunay_dimension(d) == inputs[i].dimension);
    CHECK(hw_delaunay_n_triangles(d) == hw_voronoi_n_triangles(v));
    for (k = 0; k < sizeof arrays / sizeof arrays[0]; ++k) {
      CHECK(hw_delaunay_view(d, arrays[k], &data, &n) == HW_OK);
      CHECK(hw_voronoi_view(v, arrays[k], &expected, &n_expected) == HW_OK && n == n_expected);
      CHECK(n == 0 || memcmp(data, expected, n * sizeof *data) == 0);
    }
    hw_delaunay_free(d);
    hw_voronoi_free(v);
  }
  /* The square: four triangles, the hull's four edges without a twin. */
  CHECK(hw_delaunay_build(five_and_a_copy, N_SITES, &d) == HW_OK);
  CHECK(hw_delaunay_n_triangles(d) == 4);
  CHECK(hw_delaunay_view(d, HW_VORONOI_ARRAY_TRIANGLE_TWINS, &data, &n) == HW_OK && n == 12);
  for (n = 0, i = 0; i < 12; ++i) n += data[i] == HW_INVALID_INDEX;
  CHECK(n == 4);
  /* The Voronoi diagram's arrays are not the triangulation's. */
  CHECK_STATUS(hw_delaunay_view(d, HW_VORONOI_ARRAY_HALFEDGE_NEXT, &data, &n), HW_ERR_INVALID_INPUT,
               "not an array of the Delaunay triangulation");
  CHECK_STATUS(hw_delaunay_view(NULL, HW_VORONOI_ARRAY_TRIANGLES, &data, &n), HW_ERR_NULL_ARGUMENT,
               "delaunay");
  CHECK_STATUS(hw_delaunay_view(d, HW_VORONOI_ARRAY_TRIANGLES, NULL, &n), HW_ERR_NULL_ARGUMENT,
               "out_data");
  hw_delaunay_free(d);
  hw_delaunay_free(d);
  CHECK(last_error_contains("already freed"));
  hw_delaunay_free(NULL);
  CHECK(hw_delaunay_n_triangles(NULL) == 0 && last_error_contains("delaunay"));
  CHECK(hw_delaunay_dimension(NULL) == HW_SITE_DIMENSION_EMPTY);
  d = NULL;
  CHECK_STATUS(hw_delaunay_build(five_and_a_copy + 1, 3, NULL), HW_ERR_NULL_ARGUMENT,
               "out_delaunay");
  {
    const double with_nan[] = {0, 0, 1, 0, 0, NAN};
    CHECK_STATUS(hw_delaunay_build(with_nan, 3, &d), HW_ERR_INVALID_INPUT, "site 2");
    CHECK_STATUS(hw_delaunay_build(NULL, 3, &d), HW_ERR_NULL_ARGUMENT, "xy");
  }
  CHECK(d == NULL);
}

static void lloyd(void) {
  const double rect[] = {0, 0, 4, 0, 4, 4, 0, 4};
  const double not_convex[] = {0, 0, 4, 0, 1, 1, 0, 4};
  double xy[2 * N_SITES], out[2 * N_SITES], with_nan[2 * N_SITES], moved = -1;
  uint32_t iterations = 0, i;
  memcpy(xy, five_and_a_copy, sizeof xy);

  CHECK(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 50, 1e-9, out, &iterations, &moved) == HW_OK);
  CHECK(iterations >= 1 && iterations <= 50 && moved >= 0);
  for (i = 0; i < 2 * N_SITES; ++i) CHECK(out[i] >= 0 && out[i] <= 4);
  /* In place: the output may be the input array; the result is the same. */
  CHECK(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 50, 1e-9, xy, NULL, NULL) == HW_OK);
  CHECK(memcmp(xy, out, sizeof xy) == 0);
  /* Zero iterations change nothing. */
  CHECK(hw_voronoi_lloyd(five_and_a_copy, N_SITES, rect, 4, 0, 0, out, &iterations, NULL) == HW_OK);
  CHECK(iterations == 0 && memcmp(out, five_and_a_copy, sizeof out) == 0);

  /* Each bad argument is named for what it is; the outputs stay untouched. */
  memcpy(out, xy, sizeof out);
  iterations = 77;
  CHECK_STATUS(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 5, -1, out, &iterations, NULL),
               HW_ERR_INVALID_INPUT, "tolerance -1 is not a finite distance of at least 0");
  CHECK_STATUS(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 5, NAN, out, &iterations, NULL),
               HW_ERR_INVALID_INPUT, "tolerance NaN");
  CHECK_STATUS(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 5, INFINITY, out, &iterations, NULL),
               HW_ERR_INVALID_INPUT, "tolerance inf");
  memcpy(with_nan, xy, sizeof with_nan);
  with_nan[2 * 3] = NAN;
  /* Also with no iteration to run, a NaN site is refused rather than copied out. */
  CHECK_STATUS(hw_voronoi_lloyd(with_nan, N_SITES, rect, 4, 0, 0, out, &iterations, NULL),
               HW_ERR_INVALID_INPUT, "site 3 has a non-finite coordinate");
  CHECK(iterations == 77 && memcmp(out, xy, sizeof out) == 0);
  {
    /* A misaligned output array is refused like a misaligned input one. */
    double storage[2 * N_SITES + 1];
    double *misaligned = (double *)(void *)((unsigned char *)storage + 1);
    memset(storage, 0, sizeof storage);
    CHECK_STATUS(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 5, 0, misaligned, &iterations, NULL),
                 HW_ERR_INVALID_INPUT, "argument `out_xy` is misaligned");
    CHECK(iterations == 77);
    for (i = 0; i < 2 * N_SITES + 1; ++i) CHECK(storage[i] == 0);
  }
  CHECK_STATUS(hw_voronoi_lloyd(xy, N_SITES, not_convex, 4, 5, 0, out, NULL, NULL),
               HW_ERR_INVALID_INPUT, "not convex");
  CHECK_STATUS(hw_voronoi_lloyd(xy, N_SITES, rect, 4, 5, 0, NULL, NULL, NULL),
               HW_ERR_NULL_ARGUMENT, "out_xy");
  CHECK_STATUS(hw_voronoi_lloyd(NULL, N_SITES, rect, 4, 5, 0, out, NULL, NULL),
               HW_ERR_NULL_ARGUMENT, "xy");
}

static void label_images(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES);
  uint32_t labels[16 * 16], small[4];
  size_t needed = 0, i;
  hw_metric m;
  for (m = HW_METRIC_EUCLIDEAN; m <= HW_METRIC_CHEBYSHEV; ++m) {
    CHECK(hw_voronoi_label_image(v, m, 0, 0, 4, 4, 16, 16, labels, 256, &needed) == HW_OK);
    CHECK(needed == 256);
    for (i = 0; i < 256; ++i) CHECK(labels[i] < DUPLICATE);
    /* Row 0 is the top: its first pixel is nearest to corner 3 (0, 4), the bottom-right one
     * to corner 1 (never to its duplicate). */
    CHECK(labels[0] == 3 && labels[255] == 1);
  }
  CHECK_STATUS(hw_voronoi_label_image(v, HW_METRIC_MANHATTAN, 0, 0, 4, 4, 16, 16, small, 4, &needed),
               HW_ERR_BUFFER_TOO_SMALL, "256 are needed");
  CHECK(needed == 256);
  small[0] = small[3] = 77;
  needed = 4242;
  CHECK_STATUS(hw_voronoi_label_image(v, 7, 0, 0, 4, 4, 2, 2, small, 4, &needed),
               HW_ERR_INVALID_INPUT, "unknown metric 7");
  CHECK_STATUS(hw_voronoi_label_image(NULL, HW_METRIC_EUCLIDEAN, 0, 0, 4, 4, 2, 2, small, 4,
                                      &needed),
               HW_ERR_NULL_ARGUMENT, "voronoi");
  CHECK(small[0] == 77 && small[3] == 77 && needed == 4242);
  CHECK_STATUS(hw_voronoi_label_image(v, HW_METRIC_EUCLIDEAN, 0, 0, 4, 4, 0, 2, small, 4, NULL),
               HW_ERR_INVALID_INPUT, "raster size");
  CHECK_STATUS(hw_voronoi_label_image(v, HW_METRIC_EUCLIDEAN, NAN, 0, 4, 4, 2, 2, small, 4, NULL),
               HW_ERR_INVALID_INPUT, "non-finite");
  {
    /* A misaligned output array is refused before any work; the needed size still comes back. */
    uint64_t storage[3] = {0, 0, 0};
    uint32_t *misaligned = (uint32_t *)(void *)((unsigned char *)storage + 1);
    needed = 0;
    CHECK_STATUS(hw_voronoi_label_image(v, HW_METRIC_EUCLIDEAN, 0, 0, 4, 4, 2, 2, misaligned, 4,
                                        &needed),
                 HW_ERR_INVALID_INPUT, "argument `out_labels` is misaligned");
    CHECK(needed == 4 && storage[0] == 0 && storage[1] == 0 && storage[2] == 0);
  }
  hw_voronoi_free(v);
}

static void svg(void) {
  hw_voronoi *v = build(five_and_a_copy, N_SITES), *other = build(five_and_a_copy, 3);
  hw_voronoi_cells *cells = NULL;
  hw_svg_options options = hw_svg_options_default();
  size_t needed = 0;
  char *text = NULL, tiny[8];
  const char *path = TEST_TMP_DIR "/voronoi_api.svg";
  FILE *file = NULL;

  CHECK(options.width_px > 0 && options.fill_cells && options.sites && !options.delaunay_edges);
  CHECK(hw_voronoi_clip_rect(v, -1, -1, 5, 5, &cells) == HW_OK);
  CHECK_STATUS(hw_voronoi_svg(v, cells, NULL, NULL, 0, &needed), HW_ERR_BUFFER_TOO_SMALL,
               "are needed");
  CHECK(needed > 100);
  text = (char *)malloc(needed);
  CHECK(hw_voronoi_svg(v, cells, NULL, text, needed, &needed) == HW_OK);
  CHECK(strncmp(text, "<svg", 4) == 0 && strstr(text, "<polygon") != NULL);
  CHECK(strstr(text, "<line") == NULL);
  free(text);
  options.delaunay_edges = true;
  CHECK(hw_voronoi_svg(v, cells, &options, NULL, 0, &needed) == HW_ERR_BUFFER_TOO_SMALL);
  text = (char *)malloc(needed);
  CHECK(hw_voronoi_svg(v, cells, &options, text, needed, NULL) == HW_OK);
  CHECK(strstr(text, "<line") != NULL);
  free(text);
  CHECK_STATUS(hw_voronoi_svg(v, cells, NULL, tiny, sizeof tiny, NULL), HW_ERR_BUFFER_TOO_SMALL,
               "bytes");

  CHECK(hw_voronoi_svg_write(v, cells, &options, path) == HW_OK);
  file = fopen(path, "r");
  CHECK(file != NULL);
  if (file) {
    char head[5] = {0};
    CHECK(fread(head, 1, 4, file) == 4 && strcmp(head, "<svg") == 0);
    fclose(file);
  }
  CHECK_STATUS(hw_voronoi_svg_write(v, cells, NULL, TEST_TMP_DIR "/no/such/dir/x.svg"), HW_ERR_IO,
               "cannot write");
  CHECK_STATUS(hw_voronoi_svg_write(v, cells, NULL, NULL), HW_ERR_NULL_ARGUMENT, "path");
  CHECK_STATUS(hw_voronoi_svg_write(other, cells, NULL, path), HW_ERR_INVALID_INPUT,
               "not clipped from this diagram");
  options.width_px = 0;
  CHECK_STATUS(hw_voronoi_svg(v, cells, &options, tiny, sizeof tiny, NULL), HW_ERR_INVALID_INPUT,
               "positive number of pixels");
  CHECK_STATUS(hw_voronoi_svg(v, NULL, NULL, tiny, sizeof tiny, NULL), HW_ERR_NULL_ARGUMENT,
               "cells");
  hw_voronoi_cells_free(cells);
  hw_voronoi_free(other);
  hw_voronoi_free(v);
}

/* A point file read through the library's reader feeds a diagram; a malformed one is refused
 * with the file and the line named. */
static void point_files(void) {
  char path[1024];
  hw_points2d *points = NULL;
  hw_voronoi *v = NULL;
  const double *xy = NULL;
  size_t n = 0;
  FILE *file;
  snprintf(path, sizeof path, "%s/points2d/cgal_points.xy", HALFWING_DATA_DIR);
  CHECK(hw_points2d_read(path, &points) == HW_OK);
  CHECK(hw_points2d_view(points, &xy, &n) == HW_OK);
  CHECK(n > 3 && xy != NULL);
  CHECK(hw_voronoi_build(xy, n, &v) == HW_OK);
  CHECK(hw_voronoi_n_sites(v) == n);
  hw_voronoi_free(v);
  CHECK_STATUS(hw_points2d_view(points, NULL, &n), HW_ERR_NULL_ARGUMENT, "out_xy");
  CHECK_STATUS(hw_points2d_view(NULL, &xy, &n), HW_ERR_NULL_ARGUMENT, "points");
  hw_points2d_free(points);
  hw_points2d_free(NULL);

  points = NULL;
  snprintf(path, sizeof path, "%s/bad_points.txt", TEST_TMP_DIR);
  file = fopen(path, "w");
  CHECK(file != NULL);
  if (file) {
    fputs("3\n0 1\n2 oops\n", file);
    fclose(file);
  }
  CHECK_STATUS(hw_points2d_read(path, &points), HW_ERR_PARSE, "line 3");
  CHECK(last_error_contains("bad_points.txt") && last_error_contains("`oops` is not a number"));
  CHECK_STATUS(hw_points2d_read("points.csv", &points), HW_ERR_INVALID_INPUT, "unknown point format");
  CHECK_STATUS(hw_points2d_read("/nonexistent/points.xy", &points), HW_ERR_IO, "cannot read");
  CHECK_STATUS(hw_points2d_read(NULL, &points), HW_ERR_NULL_ARGUMENT, "path");
  CHECK_STATUS(hw_points2d_read(path, NULL), HW_ERR_NULL_ARGUMENT, "out_points");
  CHECK(points == NULL);
}

int main(void) {
  counts_and_views();
  edges();
  queries();
  meshes();
  clipping();
  degenerate_inputs();
  bad_construction();
  delaunay_alone();
  lloyd();
  label_images();
  svg();
  point_files();
  return check_summary("test_voronoi_api");
}
