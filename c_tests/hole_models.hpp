// Meshes with one large hole, for the hole-filling comparison against CGAL and its benchmark: a
// sphere with its top cap removed (a planar circular hole) and a tube closed at the bottom whose
// top rim waves up and down (a non-planar hole), each with `segments` boundary edges; and the
// halfwing mesh's triangles and fold and area measures shared by both programs.
#ifndef HALFWING_C_TESTS_HOLE_MODELS_HPP
#define HALFWING_C_TESTS_HOLE_MODELS_HPP

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "halfwing.hpp"
#include "indexed_mesh.hpp"

namespace hole_models {

/// A unit UV sphere of `rings` bands from the south pole up to latitude +30°, the cap above
/// left open: one hole of `segments` edges in the plane z = 1/2.
inline indexed::Mesh capless_sphere(uint32_t segments, uint32_t rings) {
  indexed::Mesh m;
  const double pi = std::acos(-1.0);
  // Assigned, not inserted: GCC 12 warns falsely on inserting a list into an empty vector.
  m.positions = {0.0, 0.0, -1.0};
  for (uint32_t r = 1; r <= rings; ++r) {
    const double lat = -pi / 2 + (pi / 2 + pi / 6) * r / rings;
    for (uint32_t s = 0; s < segments; ++s) {
      const double lon = 2 * pi * s / segments;
      m.positions.insert(m.positions.end(),
                         {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
    }
  }
  auto at = [&](uint32_t r, uint32_t s) { return 1 + (r - 1) * segments + s % segments; };
  for (uint32_t s = 0; s < segments; ++s) {
    m.face_sizes.push_back(3);
    m.indices.insert(m.indices.end(), {0, at(1, s + 1), at(1, s)});
  }
  for (uint32_t r = 1; r < rings; ++r)
    for (uint32_t s = 0; s < segments; ++s) {
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      m.indices.insert(m.indices.end(), {at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r, s),
                                         at(r + 1, s + 1), at(r + 1, s)});
    }
  m.name = "capless-sphere-" + std::to_string(segments);
  return m;
}

/// A tube of radius 1 and `rows` bands from z = −1 up to a rim at z = 0.1 sin(5θ), closed at
/// the bottom by a fan: one non-planar hole of `segments` edges.
inline indexed::Mesh wavy_tube(uint32_t segments, uint32_t rows) {
  indexed::Mesh m;
  const double pi = std::acos(-1.0);
  // Assigned, not inserted: GCC 12 warns falsely on inserting a list into an empty vector.
  m.positions = {0.0, 0.0, -1.0};
  for (uint32_t r = 0; r <= rows; ++r)
    for (uint32_t s = 0; s < segments; ++s) {
      const double t = 2 * pi * s / segments;
      const double top = 0.1 * std::sin(5 * t);
      m.positions.insert(m.positions.end(),
                         {std::cos(t), std::sin(t), -1.0 + (top + 1.0) * r / rows});
    }
  auto at = [&](uint32_t r, uint32_t s) { return 1 + r * segments + s % segments; };
  for (uint32_t s = 0; s < segments; ++s) {
    m.face_sizes.push_back(3);
    m.indices.insert(m.indices.end(), {0, at(0, s + 1), at(0, s)});
  }
  for (uint32_t r = 0; r < rows; ++r)
    for (uint32_t s = 0; s < segments; ++s) {
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      m.indices.insert(m.indices.end(), {at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r, s),
                                         at(r + 1, s + 1), at(r + 1, s)});
    }
  m.name = "wavy-tube-" + std::to_string(segments);
  return m;
}

using Triangle = std::array<std::array<double, 3>, 3>;

/// The triangles of faces `first..` of a mesh without deleted slots (new faces are appended).
inline std::vector<Triangle> triangles_from(const hw::mesh& mesh, std::size_t first) {
  std::vector<Triangle> out;
  for (std::size_t f = first; f < mesh.n_faces(); ++f) {
    Triangle t{};
    std::size_t k = 0;
    for (hw_vertex v : mesh.vertices_of(hw_face{static_cast<uint32_t>(f)}))
      if (k < 3) t[k++] = mesh.position(v);
    out.push_back(t);
  }
  return out;
}

inline std::array<double, 3> normal_of(const Triangle& t) {
  const double u[3] = {t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
  const double v[3] = {t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

inline double area_of(const std::vector<Triangle>& triangles) {
  double area = 0;
  for (const Triangle& t : triangles) {
    const auto n = normal_of(t);
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

}  // namespace hole_models

#endif
