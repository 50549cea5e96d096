// Side-by-side benchmark of halfwing's exact vertex merge against CGAL Polygon Mesh Processing's
// merge_duplicate_points_in_polygon_soup, in one run, on the same unwelded soups: a generated
// ~1M-triangle torus written with every corner on a vertex of its own (3M vertices), and real
// models unwelded the same way. Each run gets a fresh copy of its input (the copy is not timed:
// both merges change their input in place); rounds alternate between the two, best of N.
//
//   bench/run-repair-compare.sh [--quick] [--repeats N] [model files...]
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "../c_tests/cgal_soup.hpp"
#include "halfwing.hpp"
#include "models.hpp"
#include "options.hpp"
#include "timing.hpp"

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal_soup::Soup;

void compare(const bench::IndexedMesh& welded, int repeats) {
  const bench::IndexedMesh m = bench::unwelded(welded);
  double ours = std::numeric_limits<double>::infinity(), theirs = ours;
  std::size_t our_left = 0, their_left = 0;
  for (int round = 0; round < repeats; ++round) {
    {
      hw::soup soup = hw::soup::from_indexed(m.positions, m.face_sizes, m.indices);
      const auto start = bench::Clock::now();
      const hw::repair_report report = soup.merge_vertices();
      ours = std::min(ours, bench::elapsed_ms(start, bench::Clock::now()));
      our_left = m.n_vertices() - report.list(hw::RepairList::MergedVertices).size() / 2;
    }
    {
      Soup soup = cgal_soup::of(m);
      const auto start = bench::Clock::now();
      PMP::merge_duplicate_points_in_polygon_soup(soup.points, soup.polygons);
      theirs = std::min(theirs, bench::elapsed_ms(start, bench::Clock::now()));
      their_left = soup.points.size();
    }
  }
  std::printf("%-30s %9zu %9zu %12.1f %12.1f %8.2fx %s\n", m.name.c_str(), m.n_vertices(),
              our_left, ours, theirs, ours / theirs,
              our_left == their_left ? "" : "(vertex counts differ!)");
}

}  // namespace

int main(int argc, char** argv) {
  bench::options opts;
  if (!bench::parse_options(argc, argv, opts)) return 2;
  std::printf("halfwing %s merge_vertices vs CGAL %s merge_duplicate_points_in_polygon_soup; "
              "memory: %s\n",
              hw::version().c_str(), CGAL_VERSION_STR, bench::set_memory_policy(false));
  std::printf("times: best of %d runs, in ms; ratio = halfwing / CGAL (lower is better)\n",
              opts.repeats);
  std::printf("%-30s %9s %9s %12s %12s %9s\n", "model", "vertices", "left", "halfwing", "CGAL",
              "ratio");
  bench::compare_models(opts, compare);
  return 0;
}
