// An indexed mesh as CGAL's polygon-soup functions take it: points and one vector of indices per
// polygon, and as a surface mesh over exact predicates. Shared by the comparisons against CGAL
// and the benchmarks.
#ifndef HALFWING_C_TESTS_CGAL_SOUP_HPP
#define HALFWING_C_TESTS_CGAL_SOUP_HPP

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

#include "indexed_mesh.hpp"

namespace cgal_soup {

using Point = CGAL::Simple_cartesian<double>::Point_3;

struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

inline Soup of(const indexed::Mesh& m) {
  Soup soup;
  soup.points.reserve(m.n_vertices());
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    soup.points.emplace_back(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  soup.polygons.reserve(m.n_faces());
  std::size_t corner = 0;
  for (uint32_t size : m.face_sizes) {
    soup.polygons.emplace_back(m.indices.begin() + corner, m.indices.begin() + corner + size);
    corner += size;
  }
  return soup;
}

using Exact = CGAL::Exact_predicates_inexact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<Exact::Point_3>;

/// The soup as a surface mesh over exact predicates (what self_intersections needs to decide
/// exactly); empty when the soup is not a polygon mesh.
inline ExactMesh exact_mesh(const Soup& soup) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Exact::Point_3> points;
  points.reserve(soup.points.size());
  for (const auto& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  ExactMesh mesh;
  if (PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    PMP::polygon_soup_to_polygon_mesh(points, soup.polygons, mesh);
  return mesh;
}

}  // namespace cgal_soup

#endif
