// An indexed mesh as CGAL's polygon-soup functions take it: points and one vector of indices per
// polygon. Shared by the comparisons against CGAL and the benchmarks.
#ifndef HALFWING_C_TESTS_CGAL_SOUP_HPP
#define HALFWING_C_TESTS_CGAL_SOUP_HPP

#include <CGAL/Simple_cartesian.h>

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

}  // namespace cgal_soup

#endif
