// The OpenMesh side of the comparisons: a double-precision polygon mesh built from the same
// indexed face list halfwing gets, face by face with add_face in input order.
#ifndef HALFWING_C_TESTS_OPENMESH_BUILD_HPP
#define HALFWING_C_TESTS_OPENMESH_BUILD_HPP

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <cstddef>
#include <vector>

#include "models.hpp"

/// Double precision, like halfwing (OpenMesh's default traits store float points and normals).
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

/// Builds an OpenMesh mesh with add_face in input order; returns the faces it refused.
inline std::vector<std::size_t> openmesh_build(const models::Indexed& m, PolyMesh& mesh) {
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    mesh.add_vertex(PolyMesh::Point(m.positions[3 * v], m.positions[3 * v + 1],
                                    m.positions[3 * v + 2]));
  std::vector<std::size_t> refused, offsets;
  std::vector<PolyMesh::VertexHandle> face;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    face.clear();
    bool in_range = true;
    for (uint32_t v : m.face(f, offsets)) {
      in_range = in_range && v < m.n_vertices();
      face.emplace_back(int(v));
    }
    // OpenMesh asserts on faces of fewer than 3 corners: they count as refused.
    if (!in_range || face.size() < 3 || !mesh.add_face(face).is_valid()) refused.push_back(f);
  }
  return refused;
}

#endif
