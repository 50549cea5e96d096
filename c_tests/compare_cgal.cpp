// halfwing against CGAL 5 Surface_mesh on the real models of tests/data, the same indexed face
// list fed to both (through PMP::polygon_soup_to_polygon_mesh): vertex/edge/face counts, boundary
// cycles and their lengths, the valence histogram and the connected components.
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <map>
#include <vector>

#include "check.h"
#include "models.hpp"

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh cgal_build(const models::Indexed& m) {
  std::vector<Kernel::Point_3> points;
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    points.emplace_back(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::size_t> offsets;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const indexed::Corners face = m.face(f, offsets);
    polygons.emplace_back(face.begin(), face.end());
  }
  SurfaceMesh mesh;
  CHECK(PMP::is_polygon_soup_a_polygon_mesh(polygons));
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

std::vector<std::size_t> cgal_boundary_cycle_lengths(const SurfaceMesh& mesh) {
  std::vector<SurfaceMesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::vector<std::size_t> lengths;
  for (auto h : cycles) {
    std::size_t length = 0;
    for (auto g : CGAL::halfedges_around_face(h, mesh)) {
      (void)g;
      ++length;
    }
    lengths.push_back(length);
  }
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

std::vector<std::size_t> halfwing_boundary_loop_lengths(const hw::mesh& mesh) {
  std::size_t n = 0;
  hw_mesh_boundary_loops(mesh.get(), nullptr, 0, &n);
  std::vector<hw_halfedge> starts(n);
  hw::check(hw_mesh_boundary_loops(mesh.get(), starts.data(), starts.size(), &n));
  std::vector<std::size_t> lengths;
  for (hw_halfedge start : starts) {
    hw_circulator c;
    hw_halfedge h;
    std::size_t length = 0;
    hw::check(hw_circ_along_loop(mesh.get(), start, &c));
    while (hw_circ_next_halfedge(&c, &h)) ++length;
    lengths.push_back(length);
  }
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

void compare(const std::filesystem::path& path) {
  const models::Indexed m = models::read(path);
  const SurfaceMesh sm = cgal_build(m);
  const hw::mesh mesh = hw::mesh::from_indexed(m.positions, m.face_sizes, m.indices);

  // Unreferenced points stay isolated vertices in halfwing; compare the vertices faces use.
  std::map<uint32_t, std::size_t> hw_valences, cgal_valences;
  std::size_t hw_used_vertices = 0;
  for (uint32_t v = 0; v < mesh.n_vertices(); ++v) {
    const uint32_t valence = hw_mesh_vertex_valence(mesh.get(), hw_vertex{v});
    if (valence == 0) continue;
    ++hw_used_vertices;
    ++hw_valences[valence];
  }
  std::size_t cgal_used_vertices = 0;
  for (auto v : sm.vertices()) {
    if (sm.is_isolated(v)) continue;
    ++cgal_used_vertices;
    ++cgal_valences[uint32_t(CGAL::degree(v, sm))];
  }
  CHECK(hw_used_vertices == cgal_used_vertices);
  CHECK(mesh.n_edges() == sm.number_of_edges());
  CHECK(mesh.n_faces() == sm.number_of_faces());
  CHECK(hw_valences == cgal_valences);

  const std::vector<std::size_t> loops = halfwing_boundary_loop_lengths(mesh);
  CHECK(loops == cgal_boundary_cycle_lengths(sm));

  std::size_t components = 0;
  hw::check(hw_mesh_count_components(mesh.get(), &components));
  SurfaceMesh copy = sm;
  auto fcc = copy.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc").first;
  const std::size_t cgal_components = PMP::connected_components(copy, fcc);
  CHECK(components == cgal_components);

  std::printf("  %-42s V=%zu E=%zu F=%zu loops=%zu components=%zu valences=%zu kinds\n",
              m.name.c_str(), hw_used_vertices, mesh.n_edges(), mesh.n_faces(), loops.size(),
              components, hw_valences.size());
}

}  // namespace

int main() {
  for (const char* folder : {"meshes/closed", "meshes/open", "meshes/polygonal"})
    for (const auto& path : models::files(folder)) compare(path);
  return check_summary("compare_cgal");
}
