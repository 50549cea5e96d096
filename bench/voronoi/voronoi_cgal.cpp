// CGAL's side of the Voronoi benchmark (bench/run-voronoi-compare.sh): Delaunay_triangulation_2
// with exact predicates (EPICK), built by range insertion (CGAL's own spatial sort), and that
// triangulation plus a walk of every face of its Voronoi_diagram_2 adaptor, reading each finite
// vertex (CGAL has no clipping: unbounded faces stay open). Inputs are generated exactly as in
// benches/voronoi_compare.rs (same LCG, same seed). Prints `RESULT <input> cgal <stage> <ms>`,
// the best of several runs.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_policies_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_traits_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Voronoi_diagram_2.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "points2d.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Dt = CGAL::Delaunay_triangulation_2<Kernel>;
using Vd = CGAL::Voronoi_diagram_2<Dt, CGAL::Delaunay_triangulation_adaptation_traits_2<Dt>,
                                   CGAL::Delaunay_triangulation_caching_degeneracy_removal_policy_2<Dt>>;

/// Best wall-clock milliseconds of `runs` runs of `work`.
template <class Work>
double best_of(int runs, Work work) {
  double best = 1e300;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    best = std::min(best, elapsed.count());
  }
  return best;
}

/// Every Voronoi face's boundary, reading the finite vertices.
double walk_faces(const Vd& vd) {
  double sum = 0;
  for (auto f = vd.faces_begin(); f != vd.faces_end(); ++f) {
    const Vd::Ccb_halfedge_circulator start = f->ccb();
    Vd::Ccb_halfedge_circulator h = start;
    do {
      if (h->has_source()) sum += h->source()->point().x() + h->source()->point().y();
    } while (++h != start);
  }
  return sum;
}

volatile double sink;

void run(const points2d::PointSet& set, int runs) {
  std::vector<Kernel::Point_2> points;
  points.reserve(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) points.emplace_back(set.xy[2 * i], set.xy[2 * i + 1]);
  const double delaunay = best_of(runs, [&] {
    Dt dt(points.begin(), points.end());
    sink = static_cast<double>(dt.number_of_faces());
  });
  std::printf("RESULT %s cgal delaunay %.1f\n", set.name.c_str(), delaunay);
  std::fflush(stdout);
  const double voronoi = best_of(runs, [&] {
    Dt dt(points.begin(), points.end());
    Vd vd(dt, true);  // swap: the adaptor takes the triangulation without copying it
    sink = walk_faces(vd);
  });
  std::printf("RESULT %s cgal voronoi %.1f\n", set.name.c_str(), voronoi);
  std::fflush(stdout);
}

}  // namespace

/// Runs per measurement for `n_sites` sites: the same rule as benches/voronoi_compare.rs.
int runs_for(std::size_t n_sites) {
  if (n_sites <= 10000) return 201;
  if (n_sites <= 100000) return 31;
  return 3;
}

int main(int argc, char** argv) {
  const char* filter = argc > 1 ? argv[1] : "";
  std::vector<std::pair<points2d::PointSet, int>> inputs;
  for (std::size_t n : {10000u, 100000u, 1000000u}) {
    points2d::PointSet set = points2d::uniform(n, 42);
    inputs.emplace_back(std::move(set), runs_for(n));
  }
  points2d::PointSet grid = points2d::integer_grid(1000);
  grid.name = "grid_1000x1000";
  const std::size_t grid_sites = grid.size();
  inputs.emplace_back(std::move(grid), runs_for(grid_sites));
  for (const auto& [set, runs] : inputs)
    if (set.name.find(filter) != std::string::npos) run(set, runs);
  return 0;
}
