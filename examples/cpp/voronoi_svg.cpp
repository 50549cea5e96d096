// voronoi_svg.cpp — the Voronoi diagram of a point set with halfwing.hpp: build it, clip the
// cells to a rectangle, write an SVG, then relax the sites with Lloyd steps (each site moves to
// its cell's centroid) and watch the cells even out; the relaxed diagram is written too.
//
//   voronoi_svg_cpp [out_prefix]     (default "voronoi": writes voronoi.svg and voronoi_lloyd.svg)
//
// The sites are the same 100 generated points as the C example's (fixed seed).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "halfwing.hpp"

namespace {

constexpr double width = 10.0, height = 6.0;

// A 64-bit linear congruential generator (Knuth's MMIX constants): uniform doubles in [0, 1).
struct lcg {
  uint64_t state;
  double next() {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  }
};

// Total area of the cells and the ratio of the largest cell's area to the smallest's.
struct area_stats {
  double total = 0, smallest = 0, largest = 0;
};

area_stats stats(const hw::voronoi_cells& cells) {
  area_stats s;
  s.smallest = width * height;
  for (hw_site site{0}; site.idx < cells.size(); ++site.idx) {
    const double a = cells.area(site);
    if (a == 0) continue;  // a duplicate, or a cell outside the rectangle
    s.total += a;
    s.smallest = std::min(s.smallest, a);
    s.largest = std::max(s.largest, a);
  }
  return s;
}

void report(const char* what, const hw::voronoi_cells& cells) {
  const area_stats s = stats(cells);
  std::printf("%s: total area %.6f, cell areas %.4f .. %.4f (ratio %.2f)\n", what, s.total,
              s.smallest, s.largest, s.largest / s.smallest);
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string prefix = argc > 1 ? argv[1] : "voronoi";
  lcg random{2024};
  std::vector<hw::point2> sites(100);
  for (hw::point2& p : sites) {
    p[0] = width * random.next();
    p[1] = height * random.next();
  }
  const std::vector<hw::point2> rectangle = {{0, 0}, {width, 0}, {width, height}, {0, height}};

  const hw::voronoi diagram(sites);
  const hw::voronoi_cells cells = diagram.clip({0, 0}, {width, height});
  std::printf("%zu sites, %zu cells, %zu Voronoi vertices\n", diagram.n_sites(), cells.size(),
              diagram.n_vertices());
  report("random sites", cells);
  diagram.write_svg(cells, prefix + ".svg");

  // Lloyd relaxation one step at a time: the largest move shrinks as the sites settle.
  std::vector<hw::point2> relaxed = sites;
  for (int step = 1; step <= 5; ++step) {
    const hw::lloyd_result r = hw::lloyd(relaxed, rectangle, 1);
    relaxed = r.sites;
    std::printf("lloyd step %d: largest move %.4f\n", step, r.max_displacement);
  }
  // Then up to 50 more, stopping once no site moves farther than 1e-3.
  const hw::lloyd_result settled = hw::lloyd(relaxed, rectangle, 50, 1e-3);
  relaxed = settled.sites;
  std::printf("then %u more steps, last largest move %.5f\n", settled.iterations,
              settled.max_displacement);

  const hw::voronoi relaxed_diagram(relaxed);
  const hw::voronoi_cells relaxed_cells = relaxed_diagram.clip({0, 0}, {width, height});
  report("after lloyd", relaxed_cells);
  relaxed_diagram.write_svg(relaxed_cells, prefix + "_lloyd.svg");
  std::printf("wrote %s.svg and %s_lloyd.svg\n", prefix.c_str(), prefix.c_str());
  return 0;
} catch (const hw::error& e) {
  std::fprintf(stderr, "voronoi_svg_cpp: %s\n", e.what());
  return 1;
}
