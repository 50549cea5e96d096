// The repairs against CGAL 5 Polygon Mesh Processing on every model of the test data
// (tests/data/meshes),
// the same indexed face list fed to both (through hw::soup, so the C++ wrapper is exercised):
// - merge_duplicate_points_in_polygon_soup: the same number of points left as
//   hw::soup::merge_vertices() with tolerance 0, and the same polygons once CGAL's polygons with
//   fewer than 3 distinct corners are dropped (halfwing removes those as collapsed);
// - merge_duplicate_polygons_in_polygon_soup after that: the same number of polygons left as
//   remove_duplicate_faces();
// - remove_isolated_points_in_polygon_soup: the same number of points left as
//   remove_unreferenced_vertices();
// - stitch_borders on every model both build as a polygon mesh, as it is and with every face
//   given vertices of its own: the same number of boundary half-edges after, where the welded
//   surface is one halfwing's kernel can hold. Where welding makes an edge of more than two
//   faces, or collapses a face, CGAL still pairs the half-edges (two edges between the same
//   vertices, edges from a vertex to itself) and halfwing leaves them open (its meshes have
//   neither): those models are listed with both counts, not compared.
// - duplicate_non_manifold_vertices: on every model once oriented and cut along its non-manifold
//   edges (hw::soup::orient_faces(), repair_non_manifold_edges()), as a surface mesh with its
//   non-manifold vertices as they are (built from the soup split by halfwing, the copies then
//   merged back into their originals, which CGAL's halfedge structure can hold): the same number
//   of new vertices as split_non_manifold_vertices(), where the split soup is one CGAL builds.
// - orient_to_bound_a_volume: on every closed triangle model both build, as it is and with
//   every face reversed: the same faces reversed as orient_faces(). Where they differ the model
//   is listed with both counts (CGAL turns a closed component nested in another inward, to bound
//   the volume between; halfwing turns every closed component outward, as its builds do). In the
//   test data that is only broken/cgal_spheres_intersecting.off: two spheres that cross, which
//   CGAL takes as one inside the other and turns inward (its input should not self-intersect).
// - remove_degenerate_faces on every triangle model both build as a mesh: the triangles whose
//   corners lie on one line (counted with exact predicates) before, the same count on both
//   sides, and after: halfwing leaves none, so never more than CGAL. Models with any are listed
//   with both counts and both face counts.
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "cgal_soup.hpp"
#include "check.h"
#include "halfwing.hpp"
#include "models.hpp"

namespace {

using cgal_soup::Soup;
using SurfaceMesh = CGAL::Surface_mesh<cgal_soup::Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

std::size_t compared_soups = 0, compared_stitches = 0, models_stitched = 0;
std::size_t compared_splits = 0, models_split = 0, compared_orientations = 0, models_turned = 0;
std::size_t compared_degenerate = 0, models_degenerate = 0;

std::size_t distinct_corners(std::vector<std::size_t> polygon) {
  std::sort(polygon.begin(), polygon.end());
  return static_cast<std::size_t>(std::unique(polygon.begin(), polygon.end()) - polygon.begin());
}

std::size_t cgal_boundary_halfedges(const SurfaceMesh& mesh) {
  std::size_t n = 0;
  for (auto h : mesh.halfedges()) n += mesh.is_border(h);
  return n;
}

// A mesh fresh from a build or a stitch has no deleted slot.
std::size_t our_boundary_halfedges(const hw::mesh& mesh) {
  std::size_t n = 0;
  for (std::size_t h = 0; h < hw_mesh_n_halfedge_slots(mesh.get()); ++h)
    n += hw_mesh_he_is_boundary(mesh.get(), hw_halfedge{static_cast<uint32_t>(h)});
  return n;
}

/// The list with every face on vertices of its own.
indexed::Mesh unwelded(const indexed::Mesh& m) {
  indexed::Mesh out;
  out.name = m.name + " (unwelded)";
  out.face_sizes = m.face_sizes;
  for (uint32_t v : m.indices) {
    out.indices.push_back(static_cast<uint32_t>(out.positions.size() / 3));
    out.positions.insert(out.positions.end(), m.positions.begin() + 3 * v,
                         m.positions.begin() + 3 * v + 3);
  }
  return out;
}

/// Stitches the list as both libraries build it, when both can; compares boundary half-edges
/// when `comparable`.
void compare_stitch(const indexed::Mesh& m, bool comparable) {
  Soup soup = cgal_soup::of(m);
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) return;
  hw::mesh ours;
  try {
    ours = hw::mesh::from_indexed(m.positions, m.face_sizes, m.indices, hw::BuildPolicy::Strict);
  } catch (const hw::error&) {
    return;  // non-finite coordinates, degenerate corners: not a mesh for halfwing
  }
  SurfaceMesh theirs;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, theirs);
  const std::size_t before = our_boundary_halfedges(ours);
  CHECK(before == cgal_boundary_halfedges(theirs));
  PMP::stitch_borders(theirs);
  const hw::repair_report report = ours.stitch_borders();
  CHECK(hw_mesh_check(ours.get()) == HW_OK);
  const std::size_t after = our_boundary_halfedges(ours), cgal_after = cgal_boundary_halfedges(theirs);
  CHECK(report.list(hw::RepairList::StitchedHalfedges).size() == before - after);
  if (!comparable) {
    std::printf("  %-42s not compared: %zu boundary half-edges after stitching, CGAL %zu\n",
                m.name.c_str(), after, cgal_after);
    return;
  }
  CHECK(after == cgal_after);
  if (after != cgal_after)
    std::fprintf(stderr, "  %s: %zu boundary half-edges after stitching, CGAL %zu\n",
                 m.name.c_str(), after, cgal_after);
  ++compared_stitches;
  models_stitched += after < before;
}

/// The triangles whose corners lie on one line, decided with exact predicates.
std::size_t degenerate_triangles(const cgal_soup::ExactMesh& mesh) {
  std::size_t n = 0;
  for (auto f : mesh.faces()) {
    std::vector<cgal_soup::Exact::Point_3> p;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
    n += p.size() == 3 && CGAL::collinear(p[0], p[1], p[2]);
  }
  return n;
}

/// The same for a halfwing mesh (compacted: faces 0 to n - 1).
std::size_t degenerate_triangles(const hw::mesh& mesh) {
  const auto positions = mesh.view_positions();
  std::size_t n = 0;
  for (uint32_t f = 0; f < mesh.n_faces(); ++f) {
    std::vector<cgal_soup::Exact::Point_3> p;
    for (hw_vertex v : mesh.vertices_of(hw_face{f}))
      p.emplace_back(positions[3 * v.idx], positions[3 * v.idx + 1], positions[3 * v.idx + 2]);
    n += p.size() == 3 && CGAL::collinear(p[0], p[1], p[2]);
  }
  return n;
}

/// Removes the degenerate triangles of a triangle model with both libraries, when both build it.
void compare_degenerate(const indexed::Mesh& m) {
  if (!std::all_of(m.face_sizes.begin(), m.face_sizes.end(), [](uint32_t s) { return s == 3; }))
    return;
  cgal_soup::ExactMesh theirs = cgal_soup::exact_mesh(cgal_soup::of(m));
  if (theirs.is_empty()) return;
  hw::mesh ours;
  try {
    ours = hw::mesh::from_indexed(m.positions, m.face_sizes, m.indices, hw::BuildPolicy::Strict);
  } catch (const hw::error&) {
    return;
  }
  const std::size_t before = degenerate_triangles(theirs);
  CHECK(before == degenerate_triangles(ours));
  PMP::remove_degenerate_faces(theirs);
  const hw::repair_report report = ours.remove_degenerate_faces();
  CHECK(hw_mesh_check(ours.get()) == HW_OK);
  const std::size_t after = degenerate_triangles(ours), cgal_after = degenerate_triangles(theirs);
  CHECK(after == 0 && after <= cgal_after);
  if (before > 0)
    std::printf("  %-42s %zu degenerate triangles; after: halfwing %zu (%zu faces, %zu flips), "
                "CGAL %zu (%zu faces)\n",
                m.name.c_str(), before, after, ours.n_faces(),
                report.list(hw::RepairList::FlippedFaces).size() / 2, cgal_after,
                static_cast<std::size_t>(theirs.number_of_faces()));
  ++compared_degenerate;
  models_degenerate += before > 0;
}

/// The soup's faces as CGAL polygons.
Soup cgal_of(const hw::soup& soup) {
  return cgal_soup::of(indexed::Mesh{"", soup.positions(), soup.face_sizes(), soup.indices()});
}

/// Splits the non-manifold vertices of the model, oriented and cut, with both libraries.
void compare_split(const indexed::Mesh& m) {
  hw::soup ours = hw::soup::from_indexed(m.positions, m.face_sizes, m.indices);
  ours.orient_faces();
  ours.repair_non_manifold_edges(hw::NonManifoldEdges::Cut);
  const std::size_t n_before = ours.positions().size() / 3;
  const hw::repair_report split = ours.split_non_manifold_vertices();
  const std::vector<uint32_t> copies = split.list(hw::RepairList::VertexCopies);
  CHECK(ours.positions().size() / 3 == n_before + copies.size());
  Soup soup = cgal_of(ours);
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) return;
  SurfaceMesh theirs;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, theirs);
  // The builder keeps the points' order: vertex i is point i. Merge every copy back.
  for (auto h : theirs.halfedges()) {
    const std::size_t v = theirs.target(h).idx();
    if (v >= n_before) theirs.set_target(h, SurfaceMesh::Vertex_index(copies[v - n_before]));
  }
  for (std::size_t copy = 0; copy < copies.size(); ++copy) {
    const SurfaceMesh::Vertex_index v(copies[copy]), c(static_cast<uint32_t>(n_before + copy));
    // The original keeps one of its fans' half-edges (any: each names one fan).
    if (theirs.is_isolated(v)) theirs.set_halfedge(v, theirs.halfedge(c));
    theirs.remove_vertex(c);
  }
  const std::size_t cgal_new = PMP::duplicate_non_manifold_vertices(theirs);
  CHECK(cgal_new == copies.size());
  if (cgal_new != copies.size())
    std::fprintf(stderr, "  %s: %zu vertex copies, CGAL %zu\n", m.name.c_str(), copies.size(),
                 cgal_new);
  ++compared_splits;
  models_split += !copies.empty();
}

/// Orients the closed model with both libraries, as it is and inside out.
void compare_orientation(const indexed::Mesh& m) {
  for (bool inside_out : {false, true}) {
    indexed::Mesh turned = m;
    turned.name = m.name + (inside_out ? " (inside out)" : "");
    if (inside_out) {
      std::size_t corner = 0;
      for (uint32_t size : turned.face_sizes) {
        std::reverse(turned.indices.begin() + corner, turned.indices.begin() + corner + size);
        corner += size;
      }
    }
    Soup soup = cgal_soup::of(turned);
    if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) return;
    SurfaceMesh theirs;
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, theirs);
    // CGAL orients closed triangle meshes only.
    if (!CGAL::is_closed(theirs) || !CGAL::is_triangle_mesh(theirs)) return;
    PMP::orient_to_bound_a_volume(theirs);
    std::vector<uint32_t> cgal_turned;
    // Faces keep their order in the builder (face f is polygon f), vertices theirs; a face is
    // reversed when the corner after its first polygon corner is another.
    for (auto f : theirs.faces()) {
      std::vector<uint32_t> cycle;
      for (auto h : CGAL::halfedges_around_face(theirs.halfedge(f), theirs))
        cycle.push_back(theirs.target(h).idx());
      std::vector<std::size_t> before = soup.polygons[f.idx()];
      const auto at = std::find(cycle.begin(), cycle.end(), static_cast<uint32_t>(before[0]));
      const uint32_t after_first = at + 1 == cycle.end() ? cycle[0] : *(at + 1);
      if (after_first != before[1]) cgal_turned.push_back(f.idx());
    }
    hw::soup ours = hw::soup::from_indexed(turned.positions, turned.face_sizes, turned.indices);
    const std::vector<uint32_t> our_turned =
        ours.orient_faces().list(hw::RepairList::ReorientedFaces);
    if (our_turned != cgal_turned) {
      std::printf("  %-42s differs: %zu faces reversed, CGAL %zu\n",
                  turned.name.c_str(), our_turned.size(), cgal_turned.size());
      continue;
    }
    ++compared_orientations;
    models_turned += !our_turned.empty();
  }
}

void compare(const std::filesystem::path& path) {
  const indexed::Mesh m = models::read(path);
  hw::soup ours = hw::soup::from_indexed(m.positions, m.face_sizes, m.indices);
  Soup theirs = cgal_soup::of(m);
  const bool in_range = std::all_of(m.indices.begin(), m.indices.end(),
                                    [&](uint32_t v) { return v < m.n_vertices(); });
  if (!in_range) {
    // halfwing refuses what CGAL would read out of bounds.
    CHECK_STATUS(hw_soup_merge_vertices(ours.get(), 0.0, false, nullptr), HW_ERR_INVALID_INPUT,
                 "names vertex");
    return;
  }

  const hw::repair_report merged = ours.merge_vertices();
  PMP::merge_duplicate_points_in_polygon_soup(theirs.points, theirs.polygons);
  CHECK(ours.positions().size() / 3 == theirs.points.size());
  theirs.polygons.erase(std::remove_if(theirs.polygons.begin(), theirs.polygons.end(),
                                       [](const std::vector<std::size_t>& p) {
                                         return distinct_corners(p) < 3;
                                       }),
                        theirs.polygons.end());
  // Faces malformed in the input (fewer than 3 distinct corners) that no merge touched stay in
  // halfwing's list; count the faces with 3 corners or more.
  std::vector<std::size_t> offsets;
  const indexed::Mesh after{"", ours.positions(), ours.face_sizes(), ours.indices()};
  std::size_t proper = 0;
  for (std::size_t f = 0; f < after.n_faces(); ++f) {
    const indexed::Corners face = after.face(f, offsets);
    proper += distinct_corners(std::vector<std::size_t>(face.begin(), face.end())) >= 3;
  }
  CHECK(proper == theirs.polygons.size());

  ours.remove_duplicate_faces();
  PMP::merge_duplicate_polygons_in_polygon_soup(theirs.points, theirs.polygons);
  const std::size_t our_faces = ours.face_sizes().size() - (after.n_faces() - proper);
  CHECK(our_faces == theirs.polygons.size());
  if (our_faces != theirs.polygons.size())
    std::fprintf(stderr, "  %s: %zu faces after removing duplicates, CGAL %zu\n",
                 m.name.c_str(), our_faces, theirs.polygons.size());

  ours.remove_unreferenced_vertices();
  // CGAL's points no polygon names now include those only malformed faces named, which
  // halfwing keeps: compare on the points the proper faces name.
  const std::vector<uint32_t> indices = ours.indices();
  std::vector<bool> named(ours.positions().size() / 3, false);
  std::size_t corner = 0;
  for (uint32_t size : ours.face_sizes()) {
    std::vector<std::size_t> face(indices.begin() + corner, indices.begin() + corner + size);
    if (distinct_corners(face) >= 3)
      for (std::size_t v : face) named[v] = true;
    corner += size;
  }
  PMP::remove_isolated_points_in_polygon_soup(theirs.points, theirs.polygons);
  CHECK(static_cast<std::size_t>(std::count(named.begin(), named.end(), true)) ==
        theirs.points.size());
  std::printf("  %-42s merged %zu vertices, %zu faces left, %zu points left\n", m.name.c_str(),
              merged.list(hw::RepairList::MergedVertices).size() / 2, our_faces,
              theirs.points.size());
  ++compared_soups;

  // Whether the welded surface fits a half-edge mesh: no collapsed face, no edge of 3 faces.
  const hw::diagnostic welded = hw::diagnostic::of(after.positions, after.face_sizes, after.indices);
  std::size_t non_manifold_edges = 0;
  hw::check(hw_diagnostic_count_edges(welded.get(), HW_DIAGNOSTIC_EDGES_NON_MANIFOLD,
                                     &non_manifold_edges));
  const bool comparable = merged.list(hw::RepairList::RemovedFaces).empty() &&
                          proper == after.n_faces() && non_manifold_edges == 0;
  compare_stitch(m, comparable);
  if (m.n_faces() <= 20000) compare_stitch(unwelded(m), comparable);
  compare_split(m);
  compare_orientation(m);
  compare_degenerate(m);
}

}  // namespace

int main() {
  for (const char* folder :
       {"meshes/closed", "meshes/open", "meshes/polygonal", "meshes/broken"})
    for (const auto& path : models::files(folder)) {
      try {
        compare(path);
      } catch (const hw::error& e) {
        std::printf("  %-42s not read: %s\n", path.filename().string().c_str(), e.what());
      }
    }
  std::printf("compared: %zu soups, %zu stitches (%zu stitched something)\n", compared_soups,
              compared_stitches, models_stitched);
  std::printf("compared: %zu vertex splits (%zu split something), %zu orientations (%zu turned "
              "faces)\n",
              compared_splits, models_split, compared_orientations, models_turned);
  std::printf("compared: %zu degenerate-face removals (%zu had degenerate triangles)\n",
              compared_degenerate, models_degenerate);
  CHECK(compared_soups > 50 && compared_stitches > 50 && models_stitched > 20);
  CHECK(compared_degenerate > 20 && models_degenerate > 0);
  CHECK(compared_splits > 50 && models_split > 0 && compared_orientations > 20 &&
        models_turned > 10);
  return check_summary("compare_repair_cgal");
}
