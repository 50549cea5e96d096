// Side-by-side benchmark of halfwing's hole filling against CGAL 5 Polygon Mesh Processing's
// triangulate_hole, in one run, on holes of 1,000 edges (or of each size given): a sphere with
// its cap removed (planar) and a tube whose rim waves up and down (non-planar). Both triangulate
// the hole on its corners only. halfwing: a loop longer than 100 corners is triangulated on its
// best-fit plane in O(n log n), improved by flips, tested for folds and, with exact predicates,
// for crossings with the faces near the hole (found by one scan of the faces' boxes, then a box
// tree over those few). CGAL (defaults): Liepa's minimum-weight dynamic programme restricted to
// the edges of a 3D Delaunay triangulation of the hole's corners, falling back to the full O(n³)
// programme when that finds none. Each run gets a fresh mesh (not timed); rounds alternate
// between the two, best of N; single thread on both sides (RAYON_NUM_THREADS=1 is set by the run
// script; CGAL's is sequential). Then the same holes refined and faired on both sides (see
// compare_faired).
//
//   bench/run-hole-fill-compare.sh [--quick] [--repeats N] [EDGES...]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <iterator>
#include <limits>
#include <vector>

#include "../c_tests/cgal_soup.hpp"
#include "../c_tests/hole_models.hpp"
#include "halfwing.hpp"
#include "options.hpp"
#include "timing.hpp"

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

SurfaceMesh cgal_mesh(const indexed::Mesh& m) {
  const cgal_soup::Soup soup = cgal_soup::of(m);
  std::vector<Kernel::Point_3> points;
  for (const auto& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, soup.polygons, mesh);
  return mesh;
}

// The models have one hole: its first border half-edge.
SurfaceMesh::Halfedge_index first_border(const SurfaceMesh& mesh) {
  for (auto h : mesh.halfedges())
    if (mesh.is_border(h)) return h;
  return SurfaceMesh::Halfedge_index();
}

void compare(const indexed::Mesh& m, int repeats) {
  double ours = std::numeric_limits<double>::infinity(), theirs = ours;
  std::size_t our_faces = 0, their_faces = 0;
  for (int round = 0; round < repeats; ++round) {
    {
      hw::mesh mesh = hw::mesh::from_indexed(m.positions, m.face_sizes, m.indices);
      const hw_halfedge h = mesh.boundary_loops().front();
      const auto start = bench::Clock::now();
      try {
        our_faces = mesh.fill_hole(h);
      } catch (const hw::error& e) {
        std::printf("%-24s halfwing refused: %s\n", m.name.c_str(), e.what());
        return;
      }
      ours = std::min(ours, bench::elapsed_ms(start, bench::Clock::now()));
    }
    {
      SurfaceMesh mesh = cgal_mesh(m);
      const SurfaceMesh::Halfedge_index border = first_border(mesh);
      std::vector<SurfaceMesh::Face_index> faces;
      const auto start = bench::Clock::now();
      PMP::triangulate_hole(mesh, border, std::back_inserter(faces));
      theirs = std::min(theirs, bench::elapsed_ms(start, bench::Clock::now()));
      their_faces = faces.size();
    }
  }
  std::printf("%-24s %8zu %8zu %8zu %12.1f %12.1f %8.2fx\n", m.name.c_str(),
              m.face_sizes.size(), our_faces, their_faces, ours, theirs, ours / theirs);
}

// Refined and faired: halfwing's fill_holes in FillMode::Fair (the one hole) against CGAL's
// triangulate_refine_and_fair_hole (defaults: Eigen's sparse solver); vertices added each side.
void compare_faired(const indexed::Mesh& m, int repeats) {
  double ours = std::numeric_limits<double>::infinity(), theirs = ours;
  std::size_t our_vertices = 0, their_vertices = 0;
  for (int round = 0; round < repeats; ++round) {
    {
      hw::mesh mesh = hw::mesh::from_indexed(m.positions, m.face_sizes, m.indices);
      const std::size_t before = mesh.n_vertices();
      const auto start = bench::Clock::now();
      const auto result = mesh.fill_holes(std::numeric_limits<size_t>::max(), hw::FillMode::Fair);
      if (result.filled != 1) {
        std::printf("%-24s halfwing refused the faired fill\n", (m.name + " fair").c_str());
        return;
      }
      ours = std::min(ours, bench::elapsed_ms(start, bench::Clock::now()));
      our_vertices = mesh.n_vertices() - before;
    }
    {
      SurfaceMesh mesh = cgal_mesh(m);
      const SurfaceMesh::Halfedge_index border = first_border(mesh);
      std::vector<SurfaceMesh::Face_index> faces;
      std::vector<SurfaceMesh::Vertex_index> vertices;
      const auto start = bench::Clock::now();
      const bool faired = std::get<0>(PMP::triangulate_refine_and_fair_hole(
          mesh, border, std::back_inserter(faces), std::back_inserter(vertices)));
      theirs = std::min(theirs, bench::elapsed_ms(start, bench::Clock::now()));
      their_vertices = faired ? vertices.size() : 0;
    }
  }
  std::printf("%-24s %8zu %8zu %8zu %12.1f %12.1f %8.2fx  (vertices added)\n",
              (m.name + " fair").c_str(), m.face_sizes.size(), our_vertices, their_vertices,
              ours, theirs, ours / theirs);
}

}  // namespace

int main(int argc, char** argv) {
  bench::options opts;
  if (!bench::parse_options(argc, argv, opts)) return 2;
  // Positional arguments are hole sizes here (for a growth check), not model files.
  std::vector<uint32_t> sizes;
  for (const std::string& arg : opts.files) {
    char* end = nullptr;
    const unsigned long edges = std::strtoul(arg.c_str(), &end, 10);
    if (end == arg.c_str() || *end != '\0' || edges < 3 || edges > 1000000) {
      std::fprintf(stderr, "hole size %s: expected a number of edges from 3 to 1000000\n",
                   arg.c_str());
      return 2;
    }
    sizes.push_back(static_cast<uint32_t>(edges));
  }
  if (sizes.empty()) sizes.push_back(opts.quick ? 100 : 1000);
  std::printf("halfwing %s fill_hole vs CGAL %s triangulate_hole; memory: %s\n",
              hw::version().c_str(), CGAL_VERSION_STR, bench::set_memory_policy(false));
  std::printf("times: best of %d runs, in ms; ratio = halfwing / CGAL (lower is better)\n",
              opts.repeats);
  std::printf("%-24s %8s %8s %8s %12s %12s %9s\n", "model", "faces", "ours+", "CGAL+",
              "halfwing", "CGAL", "ratio");
  for (const uint32_t edges : sizes) {
    compare(hole_models::capless_sphere(edges, 20), opts.repeats);
    compare(hole_models::wavy_tube(edges, 10), opts.repeats);
    compare_faired(hole_models::capless_sphere(edges, 20), opts.repeats);
    compare_faired(hole_models::wavy_tube(edges, 10), opts.repeats);
  }
  return 0;
}
