// Side-by-side benchmark of halfwing's whole repair pipeline (hw::repair_mesh) against the sum of
// the CGAL Polygon Mesh Processing calls that do the same steps, in one run, single thread on
// both sides. Inputs: a generated ~1M-triangle torus written with every corner on a vertex of its
// own (3M vertices: a triangle soup), and each model file named as it is and unwelded the same
// way. Each run gets a fresh copy of its input (the copy is not timed); rounds alternate between
// the two, best of N; the CGAL column is the sum of its steps' times in its best run.
//
// The steps, halfwing's (default options, T-vertex splitting off) and CGAL's:
//   merge exact duplicate vertices, drop collapsed corners and faces, remove duplicate faces and
//     unreferenced vertices        repair_polygon_soup
//   split non-manifold vertices and edges, orient consistently
//                                  orient_polygon_soup, polygon_soup_to_polygon_mesh
//   turn closed components outward orient (triangle meshes)
//   mend exactly degenerate triangles
//                                  remove_degenerate_faces (triangle meshes)
//   stitch exactly coincident borders
//                                  stitch_borders, duplicate_non_manifold_vertices
//   remove unreferenced vertices   remove_isolated_vertices
// Holes are filled on neither side. CGAL has no exact T-vertex splitting (its border snapping is
// tolerance-based and experimental), so halfwing's is switched off.
//
//   bench/run-repair-mesh-compare.sh [--quick] [--repeats N] [model files...]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Surface_mesh.h>

#include <array>
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
using Kernel = cgal_soup::Exact;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

Soup exact_soup(const bench::IndexedMesh& m) {
  const cgal_soup::Soup plain = cgal_soup::of(m);
  Soup soup;
  soup.points.reserve(plain.points.size());
  for (const auto& p : plain.points) soup.points.emplace_back(p.x(), p.y(), p.z());
  soup.polygons = plain.polygons;
  return soup;
}

constexpr std::size_t kSteps = 6;
const char* const kStepNames[kSteps] = {"soup", "orient+build", "outward", "degenerate",
                                        "stitch", "isolated"};

struct CgalRun {
  std::array<double, kSteps> ms{};
  std::size_t vertices = 0, faces = 0;
  double total() const {
    double sum = 0;
    for (double t : ms) sum += t;
    return sum;
  }
};

/// CGAL's pipeline on `soup` (changed), each step timed on its own.
CgalRun cgal_pipeline(Soup& soup) {
  CgalRun run;
  auto timed = [&](std::size_t step, auto work) {
    const auto start = bench::Clock::now();
    work();
    run.ms[step] = bench::elapsed_ms(start, bench::Clock::now());
  };
  Mesh mesh;
  timed(0, [&] { PMP::repair_polygon_soup(soup.points, soup.polygons); });
  timed(1, [&] {
    PMP::orient_polygon_soup(soup.points, soup.polygons);
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  });
  // orient and remove_degenerate_faces take triangle meshes only.
  const bool triangles = CGAL::is_triangle_mesh(mesh);
  timed(2, [&] {
    if (triangles) PMP::orient(mesh);
  });
  timed(3, [&] {
    if (triangles) PMP::remove_degenerate_faces(mesh);
  });
  timed(4, [&] {
    PMP::stitch_borders(mesh);
    PMP::duplicate_non_manifold_vertices(mesh);
  });
  timed(5, [&] { PMP::remove_isolated_vertices(mesh); });
  run.vertices = mesh.number_of_vertices();
  run.faces = mesh.number_of_faces();
  return run;
}

void compare(const bench::IndexedMesh& m, int repeats) {
  const hw::soup input = hw::soup::from_indexed(m.positions, m.face_sizes, m.indices);
  const Soup cgal_input = exact_soup(m);
  hw_repair_options options = hw_repair_options_default();
  options.remove_t_vertices = false;
  double ours = std::numeric_limits<double>::infinity();
  CgalRun theirs;
  theirs.ms.fill(std::numeric_limits<double>::infinity());
  std::size_t our_vertices = 0, our_faces = 0;
  for (int round = 0; round < repeats; ++round) {
    {
      const auto start = bench::Clock::now();
      auto repaired = hw::repair_mesh(input, options);
      ours = std::min(ours, bench::elapsed_ms(start, bench::Clock::now()));
      our_vertices = repaired.first.n_vertices();
      our_faces = repaired.first.n_faces();
    }
    {
      Soup soup = cgal_input;
      const CgalRun run = cgal_pipeline(soup);
      if (run.total() < theirs.total()) theirs = run;
    }
  }
  const bool same = our_vertices == theirs.vertices && our_faces == theirs.faces;
  std::printf("%-34s %8zu %8zu %8zu %10.1f %10.1f %7.2fx %s\n", m.name.c_str(), m.n_faces(),
              our_vertices, our_faces, ours, theirs.total(), ours / theirs.total(),
              same ? "" : ("(CGAL: " + std::to_string(theirs.vertices) + " vertices, " +
                           std::to_string(theirs.faces) + " faces)")
                              .c_str());
  std::printf("%-34s", "  CGAL steps (ms):");
  for (std::size_t s = 0; s < kSteps; ++s) std::printf(" %s %.1f", kStepNames[s], theirs.ms[s]);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  bench::options opts;
  if (!bench::parse_options(argc, argv, opts)) return 2;
  hw::set_thread_count(1);
  std::printf("halfwing %s repair_mesh vs the CGAL %s PMP repair calls, 1 thread; memory: %s\n",
              hw::version().c_str(), CGAL_VERSION_STR, bench::set_memory_policy(false));
  std::printf("times: best of %d runs, in ms; ratio = halfwing / CGAL sum (lower is better)\n",
              opts.repeats);
  std::printf("%-34s %8s %8s %8s %10s %10s %8s\n", "model", "faces in", "vertices", "faces",
              "halfwing", "CGAL sum", "ratio");
  const uint32_t n = opts.quick ? 100 : 708;
  compare(bench::unwelded(bench::torus(n, n, true)), opts.repeats);
  for (const std::string& file : opts.files) {
    const bench::IndexedMesh model = bench::read_file(file);
    compare(model, opts.repeats);
    compare(bench::unwelded(model), opts.repeats);
  }
  return 0;
}
