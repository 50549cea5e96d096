// Side-by-side benchmark: halfwing (through its C API) against OpenMesh and CGAL Surface_mesh, in
// one run, on the same inputs. Prints a table of times and ratios (halfwing / reference) for:
// bulk build, face + vertex normals, a one-ring valence sum over all vertices (checked and inline
// C circulators, C++ ranges, a loop by hand), boundary-loop count, connected components, and heap
// bytes per face.
//
//   bench/run-mesh-compare.sh [model files...]     (builds it in Release and runs it)
//   mesh_compare [--quick] [--warm] [--repeats N] [--only GENERATED-MODEL] [model files...]
//
// Memory conditions are the same for every library and printed in the header: by default "cold"
// (every large allocation is fresh pages from the kernel, so each build pays its page faults, as
// a program building a mesh once does); --warm keeps freed memory in the heap so repeated builds
// reuse faulted-in pages.
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "../c_tests/cgal_soup.hpp"
#include "halfwing.hpp"
#include "models.hpp"
#include "timing.hpp"
#include "valence_sums.h"

namespace {

using bench::best_ms;
using bench::set_memory_policy;

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// OpenMesh's default traits store float points and normals; halfwing and CGAL use double.
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

/// Heap bytes in use (glibc, all arenas, mmapped chunks included).
std::size_t heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

/// Heap bytes a freshly built structure keeps.
template <class Build>
std::size_t bytes_kept(Build build) {
  const std::size_t before = heap_in_use();
  const auto kept = build();
  return heap_in_use() - before;
}

// --- builders ---------------------------------------------------------------------------------

template <class OM>
OM openmesh_build(const bench::IndexedMesh& m) {
  OM mesh;
  mesh.reserve(m.n_vertices(), m.indices.size() / 2 + m.n_vertices() / 8, m.n_faces());
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    mesh.add_vertex(typename OM::Point(m.positions[3 * v], m.positions[3 * v + 1],
                                       m.positions[3 * v + 2]));
  std::vector<typename OM::VertexHandle> face;
  std::size_t corner = 0;
  for (uint32_t size : m.face_sizes) {
    face.clear();
    for (uint32_t i = 0; i < size; ++i) face.emplace_back(int(m.indices[corner + i]));
    mesh.add_face(face);
    corner += size;
  }
  return mesh;
}

/// CGAL's soup input, prepared outside the timed region.
using cgal_soup::Soup;

SurfaceMesh cgal_build_soup(const Soup& soup) {
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  return mesh;
}

SurfaceMesh cgal_build_add_face(const bench::IndexedMesh& m) {
  SurfaceMesh mesh;
  mesh.reserve(m.n_vertices(), m.indices.size() / 2 + m.n_vertices() / 8, m.n_faces());
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    mesh.add_vertex(Kernel::Point_3(m.positions[3 * v], m.positions[3 * v + 1],
                                    m.positions[3 * v + 2]));
  std::vector<SurfaceMesh::Vertex_index> face;
  std::size_t corner = 0;
  for (uint32_t size : m.face_sizes) {
    face.clear();
    for (uint32_t i = 0; i < size; ++i) face.emplace_back(m.indices[corner + i]);
    mesh.add_face(face);
    corner += size;
  }
  return mesh;
}

hw::mesh halfwing_build(const bench::IndexedMesh& m) {
  return hw::mesh::from_indexed(m.positions, m.face_sizes, m.indices);
}

// --- queries ----------------------------------------------------------------------------------

template <class OM>
std::size_t openmesh_valence_sum(const OM& mesh) {
  std::size_t sum = 0;
  for (auto v : mesh.vertices())
    for (auto it = mesh.cvv_iter(v); it.is_valid(); ++it) ++sum;
  return sum;
}

/// Boundary loops the way an OpenMesh user counts them: walk each unvisited boundary half-edge's
/// loop.
template <class OM>
std::size_t openmesh_boundary_loops(const OM& mesh) {
  std::vector<char> seen(mesh.n_halfedges(), 0);
  std::size_t loops = 0;
  for (auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h) || seen[h.idx()]) continue;
    ++loops;
    auto g = h;
    do {
      seen[g.idx()] = 1;
      g = mesh.next_halfedge_handle(g);
    } while (g != h);
  }
  return loops;
}

/// halfwing's one-ring walk as a C++ range-for over the inline navigation (hw::nav_view).
std::size_t halfwing_valence_sum_nav_range(const hw::mesh& mesh) {
  const hw::nav_view nav = mesh.nav();
  std::size_t sum = 0;
  for (uint32_t v = 0; v < nav.n_vertex_slots(); ++v)
    for (hw_vertex w : nav.vertices_around(hw_vertex{v})) {
      (void)w;
      ++sum;
    }
  return sum;
}

/// The same with hw::mesh's own ranges, which check each vertex id before stepping inline.
std::size_t halfwing_valence_sum_mesh_range(const hw::mesh& mesh) {
  std::size_t sum = 0;
  const std::size_t n_vertices = mesh.n_vertices();
  for (uint32_t v = 0; v < n_vertices; ++v)
    for (hw_vertex w : mesh.vertices_around(hw_vertex{v})) {
      (void)w;
      ++sum;
    }
  return sum;
}

// --- the table --------------------------------------------------------------------------------

struct Row {
  std::string model, measure;
  double halfwing, reference;
  std::string reference_name;
  /// The ratio halfwing / reference must not exceed; 0 = no target.
  double target;
};

std::vector<Row> all_rows;

void print_header() {
  std::printf("%-22s %-26s %9s %9s  %-32s %7s %7s\n", "model", "measure", "halfwing",
              "reference", "reference is", "ratio", "target");
}

void print_row(const Row& r) {
  const double ratio = r.halfwing / r.reference;
  char target[16] = "";
  if (r.target > 0)
    std::snprintf(target, sizeof target, "%s%.2f", ratio <= r.target ? "<=" : "MISS>", r.target);
  std::printf("%-22s %-26s %9.2f %9.2f  %-32s %6.2fx %7s\n", r.model.c_str(),
              r.measure.c_str(), r.halfwing, r.reference, r.reference_name.c_str(), ratio, target);
}

/// Warns when two libraries disagree on a count: the timings would compare different work.
void expect_equal(const char* what, std::size_t halfwing, std::size_t reference) {
  if (halfwing != reference)
    std::printf("  !! %s differ: halfwing %zu, reference %zu\n", what, halfwing, reference);
}

template <class OM>
void compare_with(const bench::IndexedMesh& m, int repeats, const char* openmesh_kind) {
  const std::size_t n_faces = m.n_faces();
  std::printf("\n%s: %zu vertices, %zu faces%s\n", m.name.c_str(), m.n_vertices(), n_faces,
              m.all_triangles() ? " (triangles)" : "");
  auto row = [&](const std::string& measure, double hw_value, double reference,
                 const std::string& reference_name, double target = 0) {
    all_rows.push_back({m.name, measure, hw_value, reference, reference_name, target});
    print_row(all_rows.back());
  };
  const std::string om_name = std::string("OpenMesh ") + openmesh_kind;

  // Bulk build: every library builds a fresh structure from the same indexed list.
  // The single-threaded builds take turns; the 2-thread build (a thread count is a pool to start,
  // not part of a build) comes after them.
  const Soup soup = cgal_soup::of(m);
  hw::check(hw_set_thread_count(1));
  const auto [hw_build_1, om_add, cgal_soup_ms, cgal_add] = best_ms(
      repeats, [&] { return halfwing_build(m); }, [&] { return openmesh_build<OM>(m); },
      [&] { return cgal_build_soup(soup); }, [&] { return cgal_build_add_face(m); });
  hw::check(hw_set_thread_count(2));
  const double hw_build_2 = best_ms(repeats, [&] { return halfwing_build(m); })[0];
  hw::check(hw_set_thread_count(1));
  const double fastest = std::min({om_add, cgal_soup_ms, cgal_add});
  row("build 1 thread (ms)", hw_build_1, om_add, om_name + " add_face");
  row("build 1 thread (ms)", hw_build_1, cgal_soup_ms, "CGAL soup_to_polygon_mesh");
  row("build 1 thread (ms)", hw_build_1, cgal_add, "CGAL Surface_mesh add_face");
  row("build 1 thread (ms)", hw_build_1, fastest, "fastest of the three", 0.2);
  row("build 2 threads (ms)", hw_build_2, fastest, "fastest of the three", 0.2);

  // Face + vertex normals (unit face normals summed: OpenMesh's update_normals), into buffers
  // allocated once on both sides.
  OM om = openmesh_build<OM>(m);
  om.request_face_normals();
  om.request_vertex_normals();
  const hw::mesh mesh = halfwing_build(m);
  std::vector<double> face_normals(3 * mesh.n_faces()), vertex_normals(3 * mesh.n_vertices());
  const auto [hw_normals, om_normals] = best_ms(
      repeats,
      [&] {
        hw::check(hw_mesh_normals(mesh.get(), HW_NORMAL_WEIGHTING_UNIFORM, face_normals.data(),
                                  mesh.n_faces(), nullptr, vertex_normals.data(), mesh.n_vertices(),
                                  nullptr));
      },
      [&] { om.update_normals(); });
  double worst_normal_gap = 0;
  for (auto v : om.vertices())
    for (int k = 0; k < 3; ++k)
      worst_normal_gap = std::max(
          worst_normal_gap, std::abs(om.normal(v)[k] - vertex_normals[3 * v.idx() + k]));
  if (worst_normal_gap > 1e-9)
    std::printf("  !! vertex normals differ by up to %g\n", worst_normal_gap);
  row("face+vertex normals (ms)", hw_normals, om_normals, om_name + " update_normals", 0.5);

  // One-ring traversal: the valence sum over all vertices, five ways, against OpenMesh's
  // cvv_iter in the same interleaved rounds.
  std::array<std::size_t, 5> hw_sums{};
  std::size_t om_sum = 0;
  const auto [checked_ms, inline_ms, nav_range_ms, mesh_range_ms, by_hand_ms, om_ring] = best_ms(
      repeats, [&] { hw_sums[0] = valence_sum_checked_circulator(mesh.get()); },
      [&] { hw_sums[1] = valence_sum_inline_circulator(mesh.get()); },
      [&] { hw_sums[2] = halfwing_valence_sum_nav_range(mesh); },
      [&] { hw_sums[3] = halfwing_valence_sum_mesh_range(mesh); },
      [&] { hw_sums[4] = valence_sum_by_hand(mesh.get()); },
      [&] { om_sum = openmesh_valence_sum(om); });
  for (std::size_t sum : hw_sums) expect_equal("valence sums", sum, om_sum);
  const std::string cvv = om_name + " cvv_iter";
  row("ring: C checked circ (ms)", checked_ms, om_ring, cvv);
  row("ring: C inline circ (ms)", inline_ms, om_ring, cvv, 1.0);
  row("ring: C++ nav range (ms)", nav_range_ms, om_ring, cvv, 0.5);
  row("ring: C++ mesh range (ms)", mesh_range_ms, om_ring, cvv);
  row("ring: C by hand (ms)", by_hand_ms, om_ring, cvv, 0.5);

  // Boundary loops.
  std::size_t hw_loops = 0, om_loops = 0, cgal_loops = 0;
  SurfaceMesh sm = cgal_build_soup(soup);
  std::vector<SurfaceMesh::Halfedge_index> cycles;
  const auto [hw_loops_ms, om_loops_ms, cgal_loops_ms] = best_ms(
      repeats, [&] { hw::check(hw_mesh_count_boundary_loops(mesh.get(), &hw_loops)); },
      [&] { om_loops = openmesh_boundary_loops(om); },
      [&] {
        cycles.clear();
        PMP::extract_boundary_cycles(sm, std::back_inserter(cycles));
        cgal_loops = cycles.size();
      });
  expect_equal("boundary loops (OpenMesh)", hw_loops, om_loops);
  expect_equal("boundary loops (CGAL)", hw_loops, cgal_loops);
  row("boundary loops (ms)", hw_loops_ms, om_loops_ms, om_name + " loop walk");
  row("boundary loops (ms)", hw_loops_ms, cgal_loops_ms, "CGAL extract_boundary_cycles");

  // Connected components; CGAL's face property map is allocated outside the timed region.
  std::size_t hw_components = 0, cgal_components = 0;
  auto face_component = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc").first;
  const auto [hw_cc, cgal_cc] = best_ms(
      repeats, [&] { hw::check(hw_mesh_count_components(mesh.get(), &hw_components)); },
      [&] { cgal_components = PMP::connected_components(sm, face_component); });
  sm.remove_property_map(face_component);
  expect_equal("component counts", hw_components, cgal_components);
  row("connected components (ms)", hw_cc, cgal_cc, "CGAL connected_components", 0.5);

  // Heap kept per face: connectivity + double positions (+ each library's bookkeeping).
  const double hw_bytes = double(bytes_kept([&] { return halfwing_build(m); })) / n_faces;
  const double om_bytes = double(bytes_kept([&] { return openmesh_build<OM>(m); })) / n_faces;
  const double cgal_bytes = double(bytes_kept([&] { return cgal_build_soup(soup); })) / n_faces;
  row("heap bytes per face", hw_bytes, om_bytes, om_name);
  row("heap bytes per face", hw_bytes, cgal_bytes, "CGAL Surface_mesh", 1.0);
}

/// TriMesh for triangle models (OpenMesh's faster kernel for them), PolyMesh otherwise.
void compare(const bench::IndexedMesh& m, int repeats) {
  if (m.n_faces() == 0) return;
  try {
    if (m.all_triangles())
      compare_with<TriMesh>(m, repeats, "TriMesh");
    else
      compare_with<PolyMesh>(m, repeats, "PolyMesh");
  } catch (const hw::error& e) {
    std::printf("  skipped: halfwing refuses %s under the strict policy (%s)\n", m.name.c_str(),
                e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, warm = false;
  std::string only;
  int repeats = 5;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--warm") == 0) {
      warm = true;
    } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else if (std::strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else if (argv[i][0] == '-') {
      std::fprintf(stderr, "usage: %s [--quick] [--warm] [--repeats N] [--only torus-tri|torus-quad|grid-tri] "
                   "[model files...]\n",
                   argv[0]);
      return 2;
    } else {
      files.push_back(argv[i]);
    }
  }
  const char* memory = set_memory_policy(warm);
  if (quick) repeats = 1;
  // ~1M faces each (--quick: ~20k, to check that the program works).
  const uint32_t n = quick ? 100 : 708;
  std::printf("halfwing %s vs OpenMesh %d.%d and CGAL %s\n", hw::version().c_str(), OM_GET_VER,
              OM_GET_MAJ, CGAL_VERSION_STR);
  std::printf("times: best of %d runs, in ms; ratio = halfwing / reference (lower is better)\n",
              repeats);
  std::printf("memory: %s\n", memory);
  print_header();
  const uint32_t quad_side = n * 10 / 7;
  if (only.empty() || only == "torus-tri") compare(bench::torus(n, n, true), repeats);
  if (only.empty() || only == "torus-quad")
    compare(bench::torus(quad_side, quad_side, false), repeats);
  if (only.empty() || only == "grid-tri") compare(bench::open_grid(n), repeats);
  for (const std::string& file : files) {
    try {
      compare(bench::read_file(file), repeats);
    } catch (const hw::error& e) {
      std::printf("\n%s: skipped, unreadable (%s)\n", file.c_str(), e.what());
    }
  }

  std::printf("\nsummary\n");
  print_header();
  for (const Row& r : all_rows)
    if (r.target > 0) print_row(r);
  return 0;
}
