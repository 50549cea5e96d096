// Benchmark inputs: large indexed meshes generated deterministically on the fly (never committed),
// and real models read through halfwing's own reader.
#ifndef HALFWING_BENCH_MODELS_HPP
#define HALFWING_BENCH_MODELS_HPP

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../c_tests/indexed_mesh.hpp"

namespace bench {

using IndexedMesh = indexed::Mesh;

/// A torus of `rings x segments` quads, each split into two triangles when `triangles`:
/// closed, genus 1.
inline IndexedMesh torus(uint32_t rings, uint32_t segments, bool triangles) {
  IndexedMesh m;
  m.name = triangles ? "torus-tri" : "torus-quad";
  const double pi = 3.14159265358979323846, big = 1.0, small = 0.35;
  m.positions.reserve(3 * std::size_t(rings) * segments);
  for (uint32_t i = 0; i < rings; ++i) {
    const double u = 2 * pi * i / rings;
    for (uint32_t j = 0; j < segments; ++j) {
      const double v = 2 * pi * j / segments;
      m.positions.insert(m.positions.end(), {(big + small * std::cos(v)) * std::cos(u),
                                             (big + small * std::cos(v)) * std::sin(u),
                                             small * std::sin(v)});
    }
  }
  auto at = [&](uint32_t i, uint32_t j) { return (i % rings) * segments + (j % segments); };
  for (uint32_t i = 0; i < rings; ++i) {
    for (uint32_t j = 0; j < segments; ++j) {
      // (i, j) -> (i + 1, j) -> (i + 1, j + 1) -> (i, j + 1) runs counter-clockwise seen from
      // outside: u (around the axis) x v (around the tube) points out of the tube.
      const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (triangles) {
        m.face_sizes.insert(m.face_sizes.end(), {3, 3});
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
      } else {
        m.face_sizes.push_back(4);
        m.indices.insert(m.indices.end(), {a, b, c, d});
      }
    }
  }
  return m;
}

/// An open `n x n` grid of quads split into triangles, gently curved: one boundary loop.
inline IndexedMesh open_grid(uint32_t n) {
  IndexedMesh m;
  m.name = "grid-tri";
  for (uint32_t i = 0; i <= n; ++i)
    for (uint32_t j = 0; j <= n; ++j) {
      const double x = double(i) / n, y = double(j) / n;
      m.positions.insert(m.positions.end(), {x, y, 0.1 * std::sin(6 * x) * std::cos(5 * y)});
    }
  auto at = [&](uint32_t i, uint32_t j) { return i * (n + 1) + j; };
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = 0; j < n; ++j) {
      const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  return m;
}

/// `m` with every corner on a vertex of its own (a triangle soup), named `<name>-unwelded`.
inline IndexedMesh unwelded(const IndexedMesh& m) {
  IndexedMesh out;
  out.name = m.name + "-unwelded";
  out.face_sizes = m.face_sizes;
  out.positions.reserve(3 * m.indices.size());
  out.indices.reserve(m.indices.size());
  for (uint32_t v : m.indices) {
    out.indices.push_back(static_cast<uint32_t>(out.positions.size() / 3));
    out.positions.insert(out.positions.end(), m.positions.begin() + 3 * v,
                         m.positions.begin() + 3 * v + 3);
  }
  return out;
}

/// A model file (OBJ, OFF, PLY) read with hw_soup_read(), named by its file name.
inline IndexedMesh read_file(const std::string& path) {
  return indexed::read(path, path.substr(path.find_last_of('/') + 1));
}

}  // namespace bench

#endif
