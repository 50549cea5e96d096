// Test models for the comparisons against OpenMesh and CGAL: every mesh file of a folder of the
// test data (tests/data), read once through halfwing's own reader so that all three libraries get
// the same indexed face list.
#ifndef HALFWING_C_TESTS_MODELS_HPP
#define HALFWING_C_TESTS_MODELS_HPP

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "indexed_mesh.hpp"

namespace models {

using Indexed = indexed::Mesh;

/// Reads a file with hw_soup_read(), named folder/file; throws hw::error when it cannot be read.
inline Indexed read(const std::filesystem::path& path) {
  return indexed::read(path.string(),
                       path.parent_path().filename().string() + "/" + path.filename().string());
}

/// The mesh files of `folder` (relative to the test data folder), sorted by name.
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
