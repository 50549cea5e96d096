// Side-by-side benchmark of the mesh doctor against the CGAL Polygon Mesh Processing calls that
// compute the same findings, in one run, on the same indexed face lists:
// is_polygon_soup_a_polygon_mesh, polygon_soup_to_polygon_mesh, connected_components,
// extract_boundary_cycles, degenerate_faces, self_intersections (exact predicates, on triangle
// meshes), and for closed meshes is_outward_oriented and volume. The doctor computes more (near
// duplicates, T-vertices, needles and caps, folds, long edges, genus, witnesses): CGAL's sum is
// a lower bound of what the same report would cost with it. Then self-intersections alone:
// hw::self_intersections against PMP::self_intersections (sequential; this Debian CGAL has no
// TBB). halfwing runs with 1 thread and with 2.
//
//   bench/run-doctor-compare.sh [--quick] [--repeats N] [model files...]
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <string>
#include <vector>

#include "../c_tests/cgal_soup.hpp"
#include "halfwing.hpp"
#include "models.hpp"
#include "options.hpp"
#include "timing.hpp"

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

using cgal_soup::Soup;
using cgal_soup::ExactMesh;

std::size_t cgal_self_intersections(const ExactMesh& mesh) {
  if (mesh.is_empty() || !CGAL::is_triangle_mesh(mesh)) return 0;
  std::vector<std::pair<ExactMesh::Face_index, ExactMesh::Face_index>> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  return pairs.size();
}

/// CGAL's calls for the doctor's findings that it has, on the soup as given. Returns a checksum
/// so that nothing is optimised away.
std::size_t cgal_findings(const Soup& soup, const ExactMesh& exact) {
  std::size_t sum = PMP::is_polygon_soup_a_polygon_mesh(soup.polygons) ? 1 : 0;
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  auto component = mesh.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc").first;
  sum += PMP::connected_components(mesh, component);
  std::vector<SurfaceMesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  sum += cycles.size();
  std::vector<SurfaceMesh::Face_index> degenerate;
  PMP::degenerate_faces(mesh, std::back_inserter(degenerate));
  sum += degenerate.size();
  if (CGAL::is_closed(mesh) && CGAL::is_triangle_mesh(mesh)) {
    sum += PMP::is_outward_oriented(mesh) ? 1 : 0;
    sum += PMP::volume(mesh) > 0 ? 1 : 0;
  }
  return sum + cgal_self_intersections(exact);
}

std::size_t halfwing_findings(const bench::IndexedMesh& m) {
  const hw::doctor_report report = hw::doctor_report::of(m.positions, m.face_sizes, m.indices);
  return report.components().size() + report.boundary_loops().size();
}

std::size_t halfwing_self_intersections(const bench::IndexedMesh& m) {
  return hw::self_intersections(m.positions, m.face_sizes, m.indices).size();
}

void print_row(const char* what, const bench::IndexedMesh& m, double one_thread,
               double two_threads, double cgal) {
  std::printf("%-9s %-26s %9zu %12.2f %12.2f %12.2f %8.2fx %8.2fx\n", what, m.name.c_str(),
              m.n_faces(), one_thread, two_threads, cgal, one_thread / cgal, two_threads / cgal);
}

void compare(const bench::IndexedMesh& m, int repeats) {
  const Soup soup = cgal_soup::of(m);
  // Built outside the timed calls, like the doctor's input arrays.
  const ExactMesh exact = cgal_soup::exact_mesh(soup);
  hw::check(hw_set_thread_count(1));
  const auto [one_thread, cgal] = bench::best_ms(
      repeats, [&] { return halfwing_findings(m); }, [&] { return cgal_findings(soup, exact); });
  const auto [intersections_one_thread, cgal_intersections] = bench::best_ms(
      repeats, [&] { return halfwing_self_intersections(m); },
      [&] { return cgal_self_intersections(exact); });
  hw::check(hw_set_thread_count(2));
  const double two_threads = bench::best_ms(repeats, [&] { return halfwing_findings(m); })[0];
  const double intersections_two_threads =
      bench::best_ms(repeats, [&] { return halfwing_self_intersections(m); })[0];
  print_row("doctor", m, one_thread, two_threads, cgal);
  if (CGAL::is_triangle_mesh(exact) && !exact.is_empty())
    print_row("self-int.", m, intersections_one_thread, intersections_two_threads,
              cgal_intersections);
}

}  // namespace

int main(int argc, char** argv) {
  bench::options opts;
  if (!bench::parse_options(argc, argv, opts)) return 2;
  std::printf("halfwing %s doctor vs CGAL %s PMP; memory: %s\n", hw::version().c_str(),
              CGAL_VERSION_STR, bench::set_memory_policy(false));
  std::printf("times: best of %d runs, in ms; ratio = halfwing / CGAL (lower is better)\n",
              opts.repeats);
  std::printf("%-9s %-26s %9s %12s %12s %12s %9s %9s\n", "what", "model", "faces", "halfwing 1T",
              "halfwing 2T", "CGAL 1T", "1T ratio", "2T ratio");
  bench::compare_models(opts, compare);
  return 0;
}
