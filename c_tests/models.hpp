// Test models for the comparisons against OpenMesh and CGAL: every mesh file of a folder of
// ../shared/data, read once through halfwing's own reader so that all three libraries get the
// same indexed face list.
#ifndef HALFWING_C_TESTS_MODELS_HPP
#define HALFWING_C_TESTS_MODELS_HPP

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "halfwing.hpp"

namespace models {

struct Indexed {
  std::string name;
  std::vector<double> positions;
  std::vector<uint32_t> face_sizes;
  std::vector<uint32_t> indices;
  std::size_t n_vertices() const { return positions.size() / 3; }
  std::size_t n_faces() const { return face_sizes.size(); }
  /// The corners of face f.
  std::vector<uint32_t> face(std::size_t f, std::vector<std::size_t>& offsets) const {
    if (offsets.empty()) {
      offsets.push_back(0);
      for (uint32_t size : face_sizes) offsets.push_back(offsets.back() + size);
    }
    return {indices.begin() + offsets[f], indices.begin() + offsets[f + 1]};
  }
};

/// Reads a file with hw_soup_read(); throws hw::error when it cannot be read.
inline Indexed read(const std::filesystem::path& path) {
  hw_soup* soup = nullptr;
  hw::check(hw_soup_read(path.c_str(), &soup));
  const double* xyz = nullptr;
  const uint32_t *sizes = nullptr, *corners = nullptr;
  std::size_t n_vertices = 0, n_faces = 0, n_indices = 0;
  const hw_status status =
      hw_soup_view(soup, &xyz, &n_vertices, &sizes, &n_faces, &corners, &n_indices);
  Indexed m;
  m.name = path.parent_path().filename().string() + "/" + path.filename().string();
  if (status == HW_OK) {
    m.positions.assign(xyz, xyz + 3 * n_vertices);
    m.face_sizes.assign(sizes, sizes + n_faces);
    m.indices.assign(corners, corners + n_indices);
  }
  hw_soup_free(soup);
  hw::check(status);
  return m;
}

/// The mesh files of `folder` (relative to the shared data folder), sorted by name.
inline std::vector<std::filesystem::path> files(const std::string& folder) {
  std::vector<std::filesystem::path> paths;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(HALFWING_DATA_DIR) / folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".off" || ext == ".obj" || ext == ".ply") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace models

#endif
