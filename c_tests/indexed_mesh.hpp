// An indexed polygon list read through halfwing's own reader: the form in which the comparison
// tests (c_tests/models.hpp) and the side-by-side benchmark (bench/models.hpp) hand the same
// faces to OpenMesh, CGAL and halfwing.
#ifndef HALFWING_C_TESTS_INDEXED_MESH_HPP
#define HALFWING_C_TESTS_INDEXED_MESH_HPP

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "halfwing.hpp"

namespace indexed {

/// The corners of one face: a view into the mesh's indices (no copy, so no allocation for
/// GCC 12 to misjudge as freeing a pointer inside a block).
struct Corners {
  const uint32_t* first;
  const uint32_t* last;
  const uint32_t* begin() const { return first; }
  const uint32_t* end() const { return last; }
  std::size_t size() const { return std::size_t(last - first); }
  uint32_t operator[](std::size_t i) const { return first[i]; }
};

/// x, y, z per vertex; corners per face; vertex index per corner.
struct Mesh {
  std::string name;
  std::vector<double> positions;
  std::vector<uint32_t> face_sizes;
  std::vector<uint32_t> indices;
  std::size_t n_vertices() const { return positions.size() / 3; }
  std::size_t n_faces() const { return face_sizes.size(); }
  bool all_triangles() const {
    for (uint32_t size : face_sizes)
      if (size != 3) return false;
    return true;
  }
  /// The corners of face f (`offsets` caches the face starts between calls).
  Corners face(std::size_t f, std::vector<std::size_t>& offsets) const {
    if (offsets.empty()) {
      offsets.push_back(0);
      for (uint32_t size : face_sizes) offsets.push_back(offsets.back() + size);
    }
    return {indices.data() + offsets[f], indices.data() + offsets[f + 1]};
  }
};

/// Reads a mesh file (OBJ, OFF, PLY) with hw_soup_read(); throws hw::error when it cannot be
/// read.
inline Mesh read(const std::string& path, std::string name) {
  hw_soup* soup = nullptr;
  hw::check(hw_soup_read(path.c_str(), &soup));
  const double* xyz = nullptr;
  const uint32_t *sizes = nullptr, *corners = nullptr;
  std::size_t n_vertices = 0, n_faces = 0, n_indices = 0;
  const hw_status status =
      hw_soup_view(soup, &xyz, &n_vertices, &sizes, &n_faces, &corners, &n_indices);
  Mesh m;
  m.name = std::move(name);
  if (status == HW_OK) {
    m.positions.assign(xyz, xyz + 3 * n_vertices);
    m.face_sizes.assign(sizes, sizes + n_faces);
    m.indices.assign(corners, corners + n_indices);
  }
  hw_soup_free(soup);
  hw::check(status);
  return m;
}

}  // namespace indexed

#endif
