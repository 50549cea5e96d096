// 2D point sets of tests/data/points2d (formats described in its MANIFEST.md) and generated
// ones, for the Voronoi comparisons. Each reader keeps the points in file order, duplicates
// included, so that site indices mean the same thing to every library.
#ifndef HALFWING_C_TESTS_POINTS2D_HPP
#define HALFWING_C_TESTS_POINTS2D_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace points2d {

struct PointSet {
  std::string name;
  std::vector<double> xy;  // x, y per point
  std::size_t size() const { return xy.size() / 2; }
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// JSON arrays of [x, y] pairs (delaunator, voronoice): every number in order, paired.
inline std::vector<double> numbers_in_json(const std::string& text) {
  std::vector<double> out;
  const char* p = text.c_str();
  while (*p) {
    if (*p == '-' || *p == '+' || *p == '.' || (*p >= '0' && *p <= '9')) {
      char* end = nullptr;
      out.push_back(std::strtod(p, &end));
      p = end;
    } else {
      ++p;
    }
  }
  return out;
}

/// Lines whose first two fields are x and y (.xy, .cin; weights and other columns ignored).
inline std::vector<double> first_two_columns(const std::string& text) {
  std::vector<double> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    double x, y;
    if (fields >> x >> y) {
      out.push_back(x);
      out.push_back(y);
    }
  }
  return out;
}

/// Triangle's .node and .poly: a header "count dimension attributes markers", then one line per
/// vertex "index x y [attributes] [marker]"; '#' starts a comment. The segments of a .poly
/// follow the vertices and are not needed.
inline std::vector<double> triangle_nodes(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  std::vector<std::vector<double>> records;
  std::size_t count = 0;
  while (std::getline(lines, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream fields(line);
    std::vector<double> record;
    double value;
    while (fields >> value) record.push_back(value);
    if (record.empty()) continue;
    if (count == 0) {
      count = static_cast<std::size_t>(record[0]);
      continue;
    }
    records.push_back(record);
    if (records.size() == count) break;
  }
  std::vector<double> out;
  for (const std::vector<double>& r : records) {
    out.push_back(r.at(1));
    out.push_back(r.at(2));
  }
  return out;
}

/// Boost.Polygon inputs: a point count, the points, then a segment count and segments.
inline std::vector<double> counted_points(const std::string& text) {
  std::istringstream in(text);
  std::size_t count = 0;
  in >> count;
  std::vector<double> out(2 * count);
  for (double& value : out)
    if (!(in >> value)) throw std::runtime_error("truncated point list");
  return out;
}

/// Reads one file of tests/data/points2d by its extension.
inline PointSet read(const std::filesystem::path& path) {
  const std::string text = read_text(path), ext = path.extension().string();
  PointSet set{path.filename().string(), {}};
  if (ext == ".json")
    set.xy = numbers_in_json(text);
  else if (ext == ".node" || ext == ".poly")
    set.xy = triangle_nodes(text);
  else if (ext == ".txt")
    set.xy = counted_points(text);
  else
    set.xy = first_two_columns(text);
  if (set.xy.size() % 2 != 0) throw std::runtime_error(set.name + ": odd number of coordinates");
  return set;
}

/// Every point set of `folder`, sorted by name.
inline std::vector<PointSet> read_folder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() != ".md") paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());
  std::vector<PointSet> sets;
  for (const auto& path : paths) sets.push_back(read(path));
  return sets;
}

/// A 64-bit LCG: the same sequence on every platform, no library needed.
class Lcg {
 public:
  explicit Lcg(uint64_t seed) : state_(seed) {}
  /// Uniform in [0, 1).
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state_ >> 11) / static_cast<double>(1ULL << 53);
  }

 private:
  uint64_t state_;
};

inline PointSet uniform(std::size_t n, uint64_t seed) {
  PointSet set{"uniform_" + std::to_string(n), {}};
  Lcg random(seed);
  for (std::size_t i = 0; i < 2 * n; ++i) set.xy.push_back(random.next());
  return set;
}

inline PointSet integer_grid(std::size_t side) {
  PointSet set{"grid_" + std::to_string(side) + "x" + std::to_string(side), {}};
  for (std::size_t i = 0; i < side * side; ++i) {
    set.xy.push_back(static_cast<double>(i % side));
    set.xy.push_back(static_cast<double>(i / side));
  }
  return set;
}

}  // namespace points2d

#endif
