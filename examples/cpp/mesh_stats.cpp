// mesh_stats.cpp — the C example mesh_stats.c with the C++ wrapper halfwing.hpp: RAII owners
// (no free calls), exceptions instead of status checks, and range-for circulation.
//
//   mesh_stats_cpp [model.obj|.off|.ply]   (default: the bundled examples/data/hole_capsule.off)
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

#include "halfwing.hpp"

#ifndef HALFWING_EXAMPLE_MODEL
#define HALFWING_EXAMPLE_MODEL "hole_capsule.off"
#endif

int main(int argc, char** argv) try {
  const std::string path = argc > 1 ? argv[1] : HALFWING_EXAMPLE_MODEL;
  hw::diagnostic report;
  const hw::mesh mesh = hw::mesh::read(path, hw::BuildPolicy::Repair, &report);

  const std::size_t v = mesh.n_vertices(), e = mesh.n_edges(), f = mesh.n_faces();
  std::printf("%s\nV = %zu, E = %zu, F = %zu, half-edges = %zu\n", path.c_str(), v, e, f,
              mesh.n_halfedges());
  std::printf("Euler characteristic V - E + F = %ld\n", long(v) - long(e) + long(f));

  // A boundary loop is a half-edge loop like a face's: mesh.loop(h) walks it by next().
  const auto loops = mesh.boundary_loops();
  std::printf("boundary loops: %zu\n", loops.size());
  for (std::size_t i = 0; i < loops.size(); ++i) {
    std::size_t length = 0;
    for (hw_halfedge h : mesh.loop(loops[i])) length += mesh.is_boundary(h) ? 1 : 0;
    std::printf("  loop %zu: starts at half-edge %u, %zu edges\n", i, loops[i].idx, length);
  }
  std::printf("components: %zu\n", mesh.count_components());

  // The one-ring of vertex 0, counter-clockwise: its neighbours and the faces between them.
  const hw_vertex first{0};
  std::printf("vertex 0 neighbours:");
  for (hw_vertex w : mesh.vertices_around(first)) std::printf(" %u", w.idx);
  std::printf("\nvertex 0 faces:");
  for (hw_face face : mesh.faces_around(first)) std::printf(" %u", face.idx);
  std::printf("\n");

  uint32_t min_valence = UINT32_MAX, max_valence = 0;
  for (uint32_t i = 0; i < v; ++i) {
    min_valence = std::min(min_valence, mesh.valence(hw_vertex{i}));
    max_valence = std::max(max_valence, mesh.valence(hw_vertex{i}));
  }
  std::printf("valence: min %u, max %u\n", min_valence, max_valence);
  mesh.check_invariants();  // throws hw::error if the structure were broken
  std::printf("invariants: ok\n");
  std::printf("diagnostic: %s\n", report.is_clean() ? "clean" : report.summary().c_str());

  const auto face_normals = mesh.face_normals();
  const auto vertex_normals = mesh.vertex_normals(hw::NormalWeighting::Angle);
  for (std::size_t i = 0; i < 3 && 3 * i < face_normals.size(); ++i)
    std::printf("face %zu normal: (%.4f, %.4f, %.4f)\n", i, face_normals[3 * i],
                face_normals[3 * i + 1], face_normals[3 * i + 2]);
  for (std::size_t i = 0; i < 3 && 3 * i < vertex_normals.size(); ++i)
    std::printf("vertex %zu normal (angle-weighted): (%.4f, %.4f, %.4f)\n", i,
                vertex_normals[3 * i], vertex_normals[3 * i + 1], vertex_normals[3 * i + 2]);
  return 0;
} catch (const std::exception& failure) {
  std::fprintf(stderr, "mesh_stats_cpp: %s\n", failure.what());
  return 1;
}
