// halfwing's Delaunay triangulation and Voronoi diagram against CGAL 5
// (Delaunay_triangulation_2 with exact predicates + the Voronoi_diagram_2 adaptor with degeneracy
// removal) on the point sets of tests/data/points2d and on generated ones:
//  - the same set of Delaunay edges, on inputs without four cocircular sites (decided with CGAL's
//    exact in-circle test);
//  - every Voronoi vertex within 1e-9 (relative) of the exactly constructed circumcentre;
//  - the same cell adjacency (Voronoi edges of non-zero length), on every input.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_policies_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_traits_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Voronoi_diagram_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "check.h"
#include "halfwing.hpp"
#include "points2d.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
using Dt = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Vd = CGAL::Voronoi_diagram_2<Dt, CGAL::Delaunay_triangulation_adaptation_traits_2<Dt>,
                                   CGAL::Delaunay_triangulation_caching_degeneracy_removal_policy_2<Dt>>;
using Edge = std::pair<uint32_t, uint32_t>;

Edge undirected(uint32_t a, uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

/// CGAL's triangulation of the sites, each vertex carrying the halfwing representative of the
/// input index it was inserted with (CGAL keeps one copy of duplicates, not always the first).
Dt cgal_triangulation(const points2d::PointSet& set, const hw::values_view<const uint32_t>& rep) {
  std::vector<std::pair<Kernel::Point_2, uint32_t>> points;
  for (uint32_t i = 0; i < set.size(); ++i)
    points.emplace_back(Kernel::Point_2(set.xy[2 * i], set.xy[2 * i + 1]), rep[i]);
  return Dt(points.begin(), points.end());
}

/// Is there a finite edge whose two triangles share their circumcircle (four cocircular sites)?
bool has_cocircular_quadruple(const Dt& dt) {
  if (dt.dimension() < 2) return false;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Dt::Face_handle f = e->first, g = f->neighbor(e->second);
    if (dt.is_infinite(f) || dt.is_infinite(g)) continue;
    const Dt::Vertex_handle opposite = g->vertex(g->index(f));
    if (dt.side_of_oriented_circle(f, opposite->point(), false) == CGAL::ON_ORIENTED_BOUNDARY)
      return true;
  }
  return false;
}

struct Halfwing {
  std::set<Edge> delaunay_edges, cell_adjacency;
  /// Directed Delaunay edge (a, b) → the Voronoi vertex of the triangle on its left.
  std::map<Edge, uint32_t> vertex_left_of;
};

Halfwing halfwing_structures(const hw::voronoi& v) {
  Halfwing out;
  const auto tri = v.view(hw::VoronoiArray::Triangles),
             tri_vertex = v.view(hw::VoronoiArray::TriangleVertex);
  for (std::size_t e = 0; e < tri.size(); ++e) {
    const uint32_t a = tri[e], b = tri[3 * (e / 3) + (e + 1) % 3];
    out.delaunay_edges.insert(undirected(a, b));
    out.vertex_left_of[{a, b}] = tri_vertex[e / 3];
  }
  if (v.dimension() == hw::SiteDimension::Line) {
    const auto chain = v.view(hw::VoronoiArray::Hull);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k)
      out.delaunay_edges.insert(undirected(chain[k], chain[k + 1]));
  }
  const auto site = v.view(hw::VoronoiArray::HalfedgeSite);
  for (std::size_t h = 0; h < site.size(); h += 2)
    out.cell_adjacency.insert(undirected(site[h], site[h + 1]));
  return out;
}

/// The circumcentre of a finite face, constructed exactly and rounded to doubles.
std::pair<double, double> rounded_circumcentre(Dt::Face_handle f) {
  auto exact = [&](int k) {
    const Kernel::Point_2& p = f->vertex(k)->point();
    return ExactKernel::Point_2(p.x(), p.y());
  };
  const ExactKernel::Point_2 centre = CGAL::circumcenter(exact(0), exact(1), exact(2));
  // Force the exact value: to_double of a lazy number may only round its interval.
  return {CGAL::to_double(CGAL::exact(centre.x())), CGAL::to_double(CGAL::exact(centre.y()))};
}

/// Largest coordinate magnitude of the sites: the scale of "relative" for vertex positions.
double site_scale(const points2d::PointSet& set) {
  double scale = 0;
  for (double c : set.xy) scale = std::max(scale, std::fabs(c));
  return scale;
}

void compare(const points2d::PointSet& set) {
  const std::vector<hw::point2> sites = [&] {
    std::vector<hw::point2> p;
    for (std::size_t i = 0; i < set.size(); ++i) p.push_back({set.xy[2 * i], set.xy[2 * i + 1]});
    return p;
  }();
  const hw::voronoi v(sites);
  const Dt dt = cgal_triangulation(set, v.view(hw::VoronoiArray::Representative));
  const Halfwing ours = halfwing_structures(v);
  const bool cocircular = has_cocircular_quadruple(dt);
  int failures_before = check_failed;

  CHECK(dt.number_of_vertices() == v.n_unique_sites());
  std::set<Edge> cgal_edges;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Dt::Face_handle f = e->first;
    cgal_edges.insert(undirected(f->vertex(Dt::cw(e->second))->info(),
                                 f->vertex(Dt::ccw(e->second))->info()));
  }
  if (!cocircular) {
    CHECK(cgal_edges == ours.delaunay_edges);
    CHECK(dt.number_of_faces() == v.n_triangles());
  }

  // Cell adjacency: the Voronoi diagram with zero-length edges removed, on every input. halfwing
  // also merges the ends of an edge when they land on the same double point (so that no edge has
  // zero length in its floating-point output); such an edge may exist in CGAL's diagram, but
  // only if it is shorter than the accuracy of the vertices themselves.
  const Vd vd(dt);
  const double scale = site_scale(set);
  std::set<Edge> cgal_adjacency;
  std::size_t merged_by_rounding = 0;
  for (auto h = vd.halfedges_begin(); h != vd.halfedges_end(); ++h) {
    const Edge sites =
        undirected(h->face()->dual()->info(), h->twin()->face()->dual()->info());
    if (!cgal_adjacency.insert(sites).second || ours.cell_adjacency.count(sites)) continue;
    ++merged_by_rounding;
    CHECK(h->has_source() && h->has_target());
    if (!(h->has_source() && h->has_target())) continue;
    const auto [sx, sy] = rounded_circumcentre(h->source()->dual());
    const auto [tx, ty] = rounded_circumcentre(h->target()->dual());
    CHECK(std::hypot(sx - tx, sy - ty) <= 1e-9 * std::max({scale, std::fabs(sx), std::fabs(sy)}));
  }
  std::size_t only_ours = 0;
  for (const Edge& e : ours.cell_adjacency) only_ours += cgal_adjacency.count(e) == 0;
  CHECK(only_ours == 0);
  if (dt.dimension() == 2) {
    CHECK(v.n_vertices() <= vd.number_of_vertices());
    if (merged_by_rounding == 0) CHECK(vd.number_of_vertices() == v.n_vertices());
  }

  // Voronoi vertices: CGAL's face → the exactly constructed circumcentre; halfwing's vertex is
  // the one left of any of the face's edges that halfwing also has.
  const auto vertices = v.vertices();
  std::size_t matched = 0, faces = 0;
  double worst = 0;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    ++faces;
    const auto [cx, cy] = rounded_circumcentre(f);
    for (int k = 0; k < 3; ++k) {
      const auto found = ours.vertex_left_of.find(
          {f->vertex(Dt::ccw(k))->info(), f->vertex(Dt::cw(k))->info()});
      if (found == ours.vertex_left_of.end()) continue;
      const hw::point2 p = vertices[found->second];
      const double error =
          std::hypot(p[0] - cx, p[1] - cy) / std::max({scale, std::fabs(cx), std::fabs(cy)});
      if (error > 1e-9)
        std::printf("  vertex %u at (%.17g, %.17g), exact (%.17g, %.17g), sites %u %u %u\n",
                    found->second, p[0], p[1], cx, cy, f->vertex(0)->info(), f->vertex(1)->info(),
                    f->vertex(2)->info());
      worst = std::max(worst, error);
      ++matched;
      break;
    }
  }
  CHECK(worst <= 1e-9);
  // Without cocircular sites every face has its three edges in halfwing too.
  if (!cocircular) CHECK(matched == faces);
  std::printf("%-28s %6zu sites %6zu unique %6zu triangles %6zu vertices %s %zu rounding "
              "merges, worst vertex %.1e %s\n",
              set.name.c_str(), set.size(), v.n_unique_sites(), v.n_triangles(), v.n_vertices(),
              cocircular ? "cocircular" : "          ", merged_by_rounding, worst,
              check_failed == failures_before ? "ok" : "MISMATCH");
}

}  // namespace

int main() {
  std::vector<points2d::PointSet> sets = points2d::read_folder(HALFWING_DATA_DIR "/points2d");
  sets.push_back(points2d::uniform(20000, 7));
  sets.push_back(points2d::integer_grid(60));
  {
    // Points on a circle rounded to doubles (nearly cocircular) plus its centre.
    points2d::PointSet circle{"circle_1000", {0.0, 0.0}};
    for (int i = 0; i < 1000; ++i) {
      circle.xy.push_back(std::cos(2 * std::acos(-1.0) * i / 1000));
      circle.xy.push_back(std::sin(2 * std::acos(-1.0) * i / 1000));
    }
    sets.push_back(circle);
  }
  {
    // Small random integers: many duplicates and exactly cocircular quadruples.
    points2d::PointSet small{"random_integers_0_20", {}};
    points2d::Lcg random(11);
    for (int i = 0; i < 2000; ++i) small.xy.push_back(std::floor(random.next() * 21));
    sets.push_back(small);
  }
  {
    points2d::PointSet line{"collinear_200", {}};
    for (int i = 0; i < 200; ++i) {
      line.xy.push_back(0.5 * ((i * 37) % 200));
      line.xy.push_back(0.25 * ((i * 37) % 200) - 3);
    }
    sets.push_back(line);
  }
  {
    // Magnitudes near both ends of the double range.
    points2d::PointSet tiny = points2d::uniform(500, 3), huge = points2d::uniform(500, 5);
    tiny.name = "uniform_500_times_1e-300";
    huge.name = "uniform_500_times_1e+200";
    for (double& c : tiny.xy) c *= 1e-300;
    for (double& c : huge.xy) c *= 1e200;
    sets.push_back(tiny);
    sets.push_back(huge);
  }
  for (const points2d::PointSet& set : sets) compare(set);
  return check_summary("compare_voronoi_cgal");
}
