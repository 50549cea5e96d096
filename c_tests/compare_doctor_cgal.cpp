// The mesh doctor against CGAL 5 Polygon Mesh Processing on every model of tests/data/meshes
// (closed, open, polygonal and broken), the same indexed face list fed to both:
// - is_polygon_soup_a_polygon_mesh against the doctor's manifold and oriented verdicts;
// - where CGAL can build the surface: connected_components, extract_boundary_cycles (count and
//   lengths), and on closed triangle meshes is_outward_oriented and volume;
// - on every triangle mesh CGAL can build, self_intersections (exact predicates): the very same
//   face pairs from hw::self_intersections, and from the doctor, where CGAL's (f, f) for a
//   degenerate face is among the zero-area faces;
// - orient_polygon_soup's duplicated points against the doctor's non-manifold vertex fans, on the
//   models whose only defect is non-manifold vertices.
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "check.h"
#include "halfwing.hpp"
#include "cgal_soup.hpp"
#include "models.hpp"

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

using cgal_soup::Soup;
using cgal_soup::ExactMesh;
using FacePair = std::array<uint32_t, 2>;

// CGAL's self-intersecting face pairs of a triangle soup that is a polygon mesh, sorted, smaller
// face first, without its (f, f) pairs; `degenerate` receives those pairs' faces.
std::vector<FacePair> cgal_self_intersections(const Soup& soup, std::vector<uint32_t>& degenerate) {
  const ExactMesh mesh = cgal_soup::exact_mesh(soup);
  std::vector<std::pair<ExactMesh::Face_index, ExactMesh::Face_index>> found;
  PMP::self_intersections(mesh, std::back_inserter(found));
  std::vector<FacePair> pairs;
  for (const auto& [f, g] : found) {
    const auto a = static_cast<uint32_t>(f.idx()), b = static_cast<uint32_t>(g.idx());
    if (a == b)
      degenerate.push_back(a);
    else
      pairs.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(pairs.begin(), pairs.end());
  std::sort(degenerate.begin(), degenerate.end());
  return pairs;
}

std::vector<FacePair> doctor_self_intersections(const hw::doctor_report& report) {
  const auto found = report.finding(hw::DoctorFinding::SelfIntersections);
  std::vector<FacePair> pairs(found.n_items);
  for (std::size_t i = 0; i < found.n_items; ++i)
    pairs[i] = {found.ids[2 * i], found.ids[2 * i + 1]};
  return pairs;
}

std::vector<uint32_t> ids_of(const hw::doctor_report& report, hw_diagnostic_list list) {
  const uint32_t* ids = nullptr;
  std::size_t n = 0;
  hw::check(hw_diagnostic_ids(report.input_diagnostic(), list, &ids, &n));
  return std::vector<uint32_t>(ids, ids + n);
}

std::vector<std::size_t> cgal_boundary_cycle_lengths(const SurfaceMesh& mesh) {
  std::vector<SurfaceMesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::vector<std::size_t> lengths;
  for (auto h : cycles) lengths.push_back(CGAL::halfedges_around_face(h, mesh).size());
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

std::size_t count_of(const hw::doctor_report& report, hw_diagnostic_list list) {
  return ids_of(report, list).size();
}

std::size_t edge_count_of(const hw::doctor_report& report, hw_diagnostic_edges list) {
  std::size_t n = 0;
  hw::check(hw_diagnostic_n_edges(report.input_diagnostic(), list, &n));
  return n;
}

std::size_t compared_builds = 0, compared_orientations = 0, compared_splits = 0,
            compared_intersections = 0, intersecting_models = 0;

void compare(const std::filesystem::path& path) {
  models::Indexed m;
  try {
    m = models::read(path);
  } catch (const hw::error&) {
    return;  // refused by the reader (an out-of-range index): nothing to give either library
  }
  const hw::doctor_report report = hw::doctor_report::of(m.positions, m.face_sizes, m.indices);
  const hw_doctor_verdict verdict = report.verdict();
  Soup soup = cgal_soup::of(m);
  const bool malformed = count_of(report, HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL) +
                             count_of(report, HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX) >
                         0;
  const bool is_mesh = PMP::is_polygon_soup_a_polygon_mesh(soup.polygons);
  CHECK(is_mesh == (verdict.manifold && verdict.oriented && !malformed));
  if (is_mesh != (verdict.manifold && verdict.oriented && !malformed))
    std::fprintf(stderr, "  %s: CGAL says polygon mesh %d\n", m.name.c_str(), is_mesh);

  const std::vector<hw_doctor_component> components = report.components();
  std::vector<std::size_t> loops;
  for (const auto& loop : report.boundary_loops()) loops.push_back(loop.vertices.size());
  std::sort(loops.begin(), loops.end());

  if (is_mesh) {
    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, sm);
    auto fcc = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc").first;
    CHECK(components.size() == PMP::connected_components(sm, fcc));
    CHECK(loops == cgal_boundary_cycle_lengths(sm));
    ++compared_builds;
    const bool triangles = CGAL::is_triangle_mesh(sm);
    if (triangles && CGAL::is_closed(sm) && components.size() == 1) {
      const bool outward = PMP::is_outward_oriented(sm);
      CHECK(components[0].outward == (outward ? 1 : -1));
      const double volume = PMP::volume(sm);
      CHECK(std::fabs(components[0].volume - volume) <= 1e-9 * std::fabs(volume));
      ++compared_orientations;
    }
    if (triangles) {
      std::vector<uint32_t> degenerate;
      const std::vector<FacePair> cgal = cgal_self_intersections(soup, degenerate);
      const std::vector<FacePair> ours = doctor_self_intersections(report);
      CHECK(ours == cgal);
      if (ours != cgal)
        std::fprintf(stderr, "  %s: %zu intersecting pairs, CGAL %zu\n", m.name.c_str(),
                     ours.size(), cgal.size());
      // CGAL's degenerate faces are exactly collinear corners; the zero-area faces of the
      // diagnostic include those.
      const std::vector<uint32_t> zero_area = ids_of(report, HW_DIAGNOSTIC_LIST_DEGENERATE_FACES);
      CHECK(std::includes(zero_area.begin(), zero_area.end(), degenerate.begin(),
                          degenerate.end()));
      // On their own, with the degenerate faces' (f, f) pairs as CGAL gives them.
      std::vector<FacePair> with_degenerate = cgal;
      for (uint32_t f : degenerate) with_degenerate.push_back({f, f});
      std::sort(with_degenerate.begin(), with_degenerate.end());
      CHECK(hw::self_intersections(m.positions, m.face_sizes, m.indices) == with_degenerate);
      ++compared_intersections;
      intersecting_models += !cgal.empty();
    }
  }

  // Where the only edge defects are none, orient_polygon_soup duplicates one point per extra fan
  // of each non-manifold vertex.
  const std::size_t non_manifold_vertices =
      count_of(report, HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES);
  if (non_manifold_vertices > 0 && !malformed &&
      edge_count_of(report, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD) == 0 &&
      edge_count_of(report, HW_DIAGNOSTIC_EDGES_INCONSISTENT) == 0) {
    std::size_t extra_fans = 0, n = 0;
    hw::check(hw_doctor_report_n_vertex_fans(report.get(), &n));
    for (std::size_t i = 0; i < n; ++i) {
      uint32_t vertex = 0;
      std::size_t n_fans = 0, n_faces = 0;
      const uint32_t* faces = nullptr;
      hw::check(hw_doctor_report_vertex_fan(report.get(), i, 0, &vertex, &n_fans, &faces,
                                            &n_faces));
      extra_fans += n_fans - 1;
    }
    const std::size_t before = soup.points.size();
    PMP::orient_polygon_soup(soup.points, soup.polygons);
    CHECK(soup.points.size() - before == extra_fans);
    ++compared_splits;
  }
  std::printf("  %-42s components=%zu loops=%zu manifold=%d oriented=%d polyhedron=%d\n",
              m.name.c_str(), components.size(), loops.size(), verdict.manifold, verdict.oriented,
              verdict.closed_polyhedron);
}

}  // namespace

int main() {
  for (const char* folder :
       {"meshes/closed", "meshes/open", "meshes/polygonal", "meshes/broken"})
    for (const auto& path : models::files(folder)) compare(path);
  std::printf(
      "compared: %zu builds, %zu orientations and volumes, %zu vertex splits, %zu "
      "self-intersection searches (%zu models intersect)\n",
      compared_builds, compared_orientations, compared_splits, compared_intersections,
      intersecting_models);
  CHECK(compared_builds > 40 && compared_orientations > 10 && compared_splits >= 2);
  CHECK(compared_intersections > 30 && intersecting_models >= 2);
  return check_summary("compare_doctor_cgal");
}
