// halfwing's winged-edge kernel against OpenMesh 9's circulators on the manifold models of
// the test data (closed, open, polygonal), the same indexed face list fed to both: every face's
// vertex loop (same cyclic order, whatever corner each starts at), every vertex's ring of
// neighbours (same set and same counter-clockwise cyclic order), the faces around every vertex
// and the faces adjacent to every face (same multisets). Face and vertex ids agree because both
// keep the input's numbering when nothing is refused. (Isolated vertices are checked on halfwing's
// side only: OpenMesh 9's counter-clockwise circulators walk garbage around them.)
#include <algorithm>
#include <cstdio>
#include <vector>

#include "check.h"
#include "models.hpp"
#include "openmesh_build.hpp"

namespace {

/// Whether `a` is a rotation of `b` (same cyclic sequence).
bool same_cycle(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  const auto start = std::find(b.begin(), b.end(), a[0]);
  if (start == b.end()) return false;
  std::vector<uint32_t> rotated(start, b.end());
  rotated.insert(rotated.end(), b.begin(), start);
  return rotated == a;
}

std::vector<uint32_t> sorted(std::vector<uint32_t> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

template <class Range>
std::vector<uint32_t> ids_of(const Range& range) {
  std::vector<uint32_t> ids;
  for (auto id : range) ids.push_back(id.idx);
  return ids;
}

template <class Range>
std::vector<uint32_t> openmesh_ids(const Range& range) {
  std::vector<uint32_t> ids;
  for (auto handle : range) ids.push_back(uint32_t(handle.idx()));
  return ids;
}

/// The winged structure of a model; false when halfwing refuses it or finds a vertex where
/// several fans touch (not a manifold model).
bool build_manifold(const models::Indexed& m, hw::winged& out) {
  hw::diagnostic report;
  try {
    out = hw::winged::from_indexed(m.positions, m.face_sizes, m.indices, hw::BuildPolicy::Strict,
                                   &report);
  } catch (const hw::error&) {
    return false;
  }
  return report.ids(hw::DiagnosticList::NonManifoldVertices).empty();
}

/// Compares one model; returns false when it is not a manifold model (skipped).
bool compare(const models::Indexed& m) {
  hw::winged w;
  if (!build_manifold(m, w)) return false;
  PolyMesh om;
  const std::vector<std::size_t> refused = openmesh_build(m, om);
  CHECK(refused.empty());
  if (!refused.empty()) return true;
  CHECK(w.n_vertices() == om.n_vertices() && w.n_edges() == om.n_edges() &&
        w.n_faces() == om.n_faces());
  w.check_invariants();

  std::size_t bad_loops = 0, bad_rings = 0, bad_vertex_faces = 0, bad_adjacency = 0;
  std::size_t isolated = 0;
  for (auto f : om.faces()) {
    const hw_wface wf{uint32_t(f.idx())};
    if (!same_cycle(ids_of(w.face_vertices(wf)), openmesh_ids(om.fv_ccw_range(f)))) ++bad_loops;
    if (sorted(ids_of(w.face_faces(wf))) != sorted(openmesh_ids(om.ff_range(f)))) ++bad_adjacency;
  }
  for (auto v : om.vertices()) {
    const hw_wvertex wv{uint32_t(v.idx())};
    const std::vector<uint32_t> ring = ids_of(w.vertex_vertices(wv));
    if (om.is_isolated(v)) {
      // OpenMesh's counter-clockwise circulators do not check for an isolated vertex's missing
      // half-edge and walk from an unrelated one, so only halfwing's side is checked here.
      ++isolated;
      if (!ring.empty()) ++bad_rings;
      continue;
    }
    if (!same_cycle(ring, openmesh_ids(om.vv_ccw_range(v)))) ++bad_rings;
    if (sorted(ids_of(w.vertex_faces(wv))) != sorted(openmesh_ids(om.vf_range(v))))
      ++bad_vertex_faces;
  }
  CHECK(bad_loops == 0);
  CHECK(bad_rings == 0);
  CHECK(bad_vertex_faces == 0);
  CHECK(bad_adjacency == 0);
  if (isolated != 0) std::printf("%s: %zu isolated vertices\n", m.name.c_str(), isolated);
  if (bad_loops + bad_rings + bad_vertex_faces + bad_adjacency != 0)
    std::fprintf(stderr, "%s: %zu face loops, %zu vertex rings, %zu vertex faces, %zu adjacencies differ\n",
                 m.name.c_str(), bad_loops, bad_rings, bad_vertex_faces, bad_adjacency);
  return true;
}

}  // namespace

int main() {
  omerr().disable();  // add_face's complaints are expected on nothing here, but stay quiet
  std::size_t compared = 0, skipped = 0;
  for (const char* folder : {"meshes/closed", "meshes/open", "meshes/polygonal"}) {
    for (const auto& path : models::files(folder)) {
      models::Indexed m;
      try {
        m = models::read(path);
      } catch (const hw::error&) {
        ++skipped;  // the readers have their own tests
        continue;
      }
      if (compare(m)) {
        ++compared;
      } else {
        ++skipped;
        std::printf("skipped (not manifold): %s\n", m.name.c_str());
      }
    }
  }
  std::printf("compared %zu manifold models, skipped %zu\n", compared, skipped);
  CHECK(compared >= 30);
  return check_summary("compare_winged_openmesh");
}
