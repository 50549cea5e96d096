// The C++ wrapper speaks the C vocabulary: the counterparts of the C functions that had none
// (editing, views, one-pass normals, index maps, diagnostic edges, the doctor's vertex fans, the
// winged kernel's bulk calls), the scoped enumerations and their names, and ids usable as keys of
// the standard containers.
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

#include "check.h"
#include "halfwing.hpp"

// Two triangles sharing the diagonal 0-2 of a unit square.
static hw::mesh square() {
  return hw::mesh::from_indexed({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {3, 3}, {0, 1, 2, 0, 2, 3});
}

static bool refused_with(hw::Status status, void (*call)()) {
  try {
    call();
  } catch (const hw::error& e) {
    return e.status() == status;
  }
  return false;
}

static void ids_compare_and_hash() {
  const hw_vertex a{1}, b{2}, a_again{1};
  CHECK(a == a_again && a != b && a < b && !(b < a));
  const std::set<hw_face> faces = {hw_face{3}, hw_face{1}, hw_face{3}};
  CHECK(faces.size() == 2 && faces.begin()->idx == 1);
  std::unordered_set<hw_halfedge> halfedges = {hw_halfedge{5}, hw_halfedge{5}, hw_halfedge{6}};
  CHECK(halfedges.size() == 2 && halfedges.count(hw_halfedge{6}) == 1);
  std::map<hw_edge, int> by_edge = {{hw_edge{2}, 20}, {hw_edge{0}, 0}};
  CHECK(by_edge.begin()->second == 0);
  std::unordered_set<hw_wvertex> wv = {hw_wvertex{0}, hw_wvertex{0}};
  std::unordered_set<hw_wedge> we = {hw_wedge{0}, hw_wedge{1}};
  std::set<hw_wface> wf = {hw_wface{2}, hw_wface{1}};
  CHECK(wv.size() == 1 && we.size() == 2 && wf.begin()->idx == 1);
  CHECK(std::hash<hw_vertex>()(a) == std::hash<hw_vertex>()(a_again));

  // The walks of a real model give each neighbour once: a set of ids sees the same count.
  const hw::mesh m =
      hw::mesh::read(std::string(HALFWING_DATA_DIR) + "/meshes/closed/lapy_icosahedron.off");
  std::unordered_set<hw_vertex> ring;
  for (hw_vertex w : m.vertices_around(hw_vertex{0})) ring.insert(w);
  CHECK(ring.size() == m.valence(hw_vertex{0}) && ring.count(hw_vertex{0}) == 0);
}

static void library_wide_calls() {
  CHECK(hw::version_number() == HW_VERSION_NUMBER);
  CHECK(hw::version_number() == EXPECTED_VERSION_MAJOR * 10000u + EXPECTED_VERSION_MINOR * 100u +
                                    EXPECTED_VERSION_PATCH);
  hw::set_thread_count(1);
  hw::set_thread_count(0);
  CHECK(refused_with(hw::Status::InvalidInput,
                     [] { hw::set_thread_count(HW_MAX_THREAD_COUNT + 1); }));

  CHECK(hw::name(hw::DiagnosticList::IsolatedVertices) == "isolated vertices");
  CHECK(hw::name(hw::DiagnosticEdges::Inconsistent) == "inconsistently oriented edges");
  CHECK(hw::name(hw::DoctorFinding::TVertices) == "T-vertices");
  CHECK(hw::name(hw::Status::OutOfMemory) == hw_status_str(HW_ERR_OUT_OF_MEMORY));
  // The three families have disjoint values: a value of one, cast to another, is unknown there.
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::name(static_cast<hw::DoctorFinding>(hw::to_c(hw::DiagnosticList::SkippedFaces)));
  }));
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::name(static_cast<hw::DiagnosticList>(hw::to_c(hw::DiagnosticEdges::NonManifold)));
  }));
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::name(static_cast<hw::DiagnosticEdges>(hw::to_c(hw::DoctorFinding::Caps)));
  }));
}

static void mesh_editing() {
  hw::mesh m = hw::mesh::from_indexed({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {4}, {0, 1, 2, 3});
  // Split the quad along 0-2: halfedge 3->0 ends at 0, halfedge 1->2 ends at 2.
  hw_halfedge to_0{}, to_2{};
  for (hw_halfedge h : m.halfedges_of(hw_face{0})) {
    if (m.target(h).idx == 0) to_0 = h;
    if (m.target(h).idx == 2) to_2 = h;
  }
  const hw_halfedge diagonal = m.split_face(to_0, to_2);
  CHECK(m.n_faces() == 2 && m.n_edges() == 5);
  CHECK(m.origin(diagonal).idx == 0 && m.target(diagonal).idx == 2);
  CHECK(refused_with(hw::Status::Refused, [] {
    hw::mesh t = hw::mesh::from_indexed({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3}, {0, 1, 2});
    t.split_face(hw_halfedge{0}, t.next(hw_halfedge{0}));  // a side would have 2 corners
  }));
  m.check_invariants();

  m.set_vertex_position(hw_vertex{2}, {2, 2, 0});
  CHECK(m.position(hw_vertex{2})[0] == 2);
  CHECK(m.view_positions()[6] == 2 && m.view_positions().size() == 12);
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::mesh t = square();
    t.set_vertex_position(hw_vertex{0}, {NAN, 0, 0});
  }));

  // Edge halfedges: side 0 is 2e, side 1 is 2e + 1.
  const hw_edge e{1};
  CHECK(m.edge_halfedge(e, 0).idx == 2 && m.edge_halfedge(e, 1).idx == 3);
  CHECK(m.edge(m.edge_halfedge(e, 1)) == e);

  // A hexagon becomes 4 triangles.
  hw::mesh hexagon;
  std::vector<hw_vertex> corners;
  const double sixth_of_a_turn = std::acos(-1.0) / 3;
  for (int i = 0; i < 6; ++i)
    corners.push_back(
        hexagon.add_vertex(std::cos(i * sixth_of_a_turn), std::sin(i * sixth_of_a_turn), 0));
  const hw_face f = hexagon.add_face(corners);
  CHECK(hexagon.triangulate_face(f) == 4 && hexagon.n_faces() == 4);
  for (uint32_t g = 0; g < 4; ++g) CHECK(hexagon.degree(hw_face{g}) == 3);
  hexagon.check_invariants();
}

static void deleting_and_index_maps() {
  hw::mesh m = square();
  hw_edge diagonal{};
  for (uint32_t e = 0; e < m.n_edges(); ++e)
    if (!m.is_boundary(hw_edge{e})) diagonal = hw_edge{e};
  m.delete_edge(diagonal, false);  // takes both faces, keeps the vertices
  CHECK(m.n_faces() == 0 && m.n_vertices() == 4);
  hw::index_maps maps = m.garbage_collect();
  CHECK(maps.view(hw::ElementKind::Vertex).size() == 4 &&
        maps.view(hw::ElementKind::Face).size() == 2);
  CHECK(maps.view(hw::ElementKind::Face)[0] == HW_INVALID_INDEX);
  CHECK(maps.view(hw::ElementKind::Vertex)[3] == 3);

  hw::mesh n = square();
  n.delete_vertex(hw_vertex{1});  // only in the first triangle
  CHECK(n.n_faces() == 1 && n.n_vertices() == 3);
  const hw::index_maps compacted = n.garbage_collect();
  const auto vertices = compacted.view(hw::ElementKind::Vertex);
  CHECK(vertices[0] == 0 && vertices[1] == HW_INVALID_INDEX && vertices[2] == 1 &&
        vertices[3] == 2);
  CHECK(refused_with(hw::Status::InvalidHandle, [] { square().delete_vertex(hw_vertex{9}); }));
}

static bool close(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::fabs(a[i] - b[i]) > 1e-12) return false;
  return true;
}

static void topology_views_and_normals() {
  const hw::mesh m =
      hw::mesh::read(std::string(HALFWING_DATA_DIR) + "/meshes/open/cgal_elephant-with-holes.off");
  CHECK(m.n_boundary_loops() == m.boundary_loops().size() && m.n_boundary_loops() > 0);
  const std::vector<uint32_t> components = m.face_components();
  CHECK(components.size() == m.n_faces());
  CHECK(std::set<uint32_t>(components.begin(), components.end()).size() == m.n_components());

  // The connectivity views hold the arrays the navigation reads.
  const auto next = m.view(hw::MeshArray::HalfedgeNext);
  CHECK(next.size() == m.n_halfedges());
  for (uint32_t h = 0; h < next.size(); h += 97) CHECK(next[h] == m.next(hw_halfedge{h}).idx);

  // One pass gives what the two separate calls give.
  const auto both = m.normals(hw::NormalWeighting::Area);
  CHECK(close(both.faces, m.face_normals()));
  CHECK(close(both.vertices, m.vertex_normals(hw::NormalWeighting::Area)));
}

static void attribute_info() {
  hw::mesh m = square();
  m.add_attribute<float>(hw::ElementKind::Vertex, "uv", 2);
  const auto info = m.attribute_info(hw::ElementKind::Vertex, "uv");
  CHECK(info.first == hw::ScalarType::F32 && info.second == 2);
  CHECK(refused_with(hw::Status::NotFound,
                     [] { square().attribute_info(hw::ElementKind::Face, "none"); }));
}

static void diagnostic_edges_and_vertex_fans() {
  // Three triangles on edge 0-1.
  const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  const hw::diagnostic d = hw::diagnostic::of(positions, {3, 3, 3}, {0, 1, 2, 1, 0, 3, 0, 1, 4});
  CHECK(d.n_edges(hw::DiagnosticEdges::NonManifold) == 1);
  const hw::diagnostic::edge_report edge = d.edge(hw::DiagnosticEdges::NonManifold, 0);
  CHECK(edge.vertices[0] == 0 && edge.vertices[1] == 1);
  CHECK((edge.faces == std::vector<uint32_t>{0, 1, 2}));
  CHECK(hw::diagnostic().n_edges(hw::DiagnosticEdges::NonManifold) == 0);
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::diagnostic::of({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3}, {0, 1, 2})
        .edge(hw::DiagnosticEdges::NonManifold, 0);
  }));

  // Two triangles meeting at their corner 0 only: two fans there.
  const hw::doctor_report report = hw::doctor_report::of(
      {0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0}, {3, 3}, {0, 1, 2, 0, 3, 4});
  CHECK(report.n_vertex_fans() == 1);
  const hw::doctor_report::vertex_fan_view first = report.vertex_fan(0, 0);
  const hw::doctor_report::vertex_fan_view second = report.vertex_fan(0, 1);
  CHECK(first.vertex == 0 && first.n_fans == 2 && second.vertex == 0);
  CHECK((first.faces == std::vector<uint32_t>{0} && second.faces == std::vector<uint32_t>{1}));
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::doctor_report::of({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3}, {0, 1, 2}).vertex_fan(0, 0);
  }));
}

static void winged_bulk_calls() {
  // A tetrahedron with its edges numbered and directed by hand.
  const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::vector<uint32_t> sizes = {3, 3, 3, 3};
  const std::vector<uint32_t> indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  const std::vector<uint32_t> order = {3, 0, 0, 1, 1, 2, 2, 0, 1, 3, 2, 3};
  hw::winged w = hw::winged::from_indexed_ordered(positions, sizes, indices, order);
  w.check_invariants();
  const auto records = w.edge_records();
  CHECK(records.size() == 6);
  for (uint32_t e = 0; e < 6; ++e) {
    CHECK(records[e].start.idx == order[2 * e] && records[e].end.idx == order[2 * e + 1]);
    CHECK(w.edge(hw_wedge{e}).start == records[e].start);
  }
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::winged::from_indexed_ordered({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3}, {0, 1, 2}, {0, 1, 1, 2});
  }));

  const std::vector<double> faces = w.face_normals();
  const std::vector<double> vertices = w.vertex_normals();
  CHECK(faces.size() == 12 && vertices.size() == 12);
  for (uint32_t f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) CHECK(faces[3 * f + k] == w.face_normal(hw_wface{f})[k]);

  w.set_vertex_position(hw_wvertex{3}, {0, 0, 2});
  CHECK(w.position(hw_wvertex{3})[2] == 2);
  CHECK(refused_with(hw::Status::InvalidInput, [] {
    hw::winged t = hw::winged::from_indexed({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3}, {0, 1, 2});
    t.set_vertex_position(hw_wvertex{0}, {INFINITY, 0, 0});
  }));

  // The kill operators' garbage collection gives its maps.
  hw::winged k;
  const auto made = k.mvfs({0, 0, 0});
  const auto edge = k.mev(made.second, made.first, {1, 0, 0});
  k.kev(edge.first, edge.second);
  const hw::index_maps maps = k.garbage_collect();
  CHECK(maps.view(hw::ElementKind::Vertex).size() == 2 &&
        maps.view(hw::ElementKind::Vertex)[1] == HW_INVALID_INDEX);
}

// Each scoped enumeration is its C family: the same values, one family kept from another and from
// plain integers by the compiler, and accepted or returned wherever the wrapper takes or gives one.
static_assert(hw::to_c(hw::NormalWeighting::Angle) == HW_NORMAL_WEIGHTING_ANGLE);
static_assert(hw::to_c(hw::Status::Ok) == HW_OK && hw::to_c(hw::Status::Io) == HW_ERR_IO);
static_assert(hw::to_c(hw::DoctorFinding::SmallComponents) == HW_DOCTOR_FINDING_FIRST);
static_assert(hw::to_c(hw::DiagnosticList::FacesTooSmall) == HW_DIAGNOSTIC_LIST_FIRST);
static_assert(hw::to_c(hw::DiagnosticEdges::NonManifold) == HW_DIAGNOSTIC_EDGES_FIRST);
static_assert(hw::to_c(hw::VoronoiEdgeKind::Line) == HW_VORONOI_EDGE_KIND_LINE);
static_assert(hw::to_c(hw::WCirculatorKind::Faces) == HW_WCIRCULATOR_KIND_FACES);
static_assert(!std::is_convertible_v<hw::DiagnosticList, hw::DoctorFinding>);
static_assert(!std::is_convertible_v<hw_normal_weighting, hw::NormalWeighting>);
static_assert(!std::is_convertible_v<hw::Shading, hw_shading>);

static void scoped_enumerations() {
  // A C value converts explicitly and comes back unchanged.
  CHECK(static_cast<hw::Shading>(HW_SHADING_CREASE) == hw::Shading::Crease);
  CHECK(hw::to_c(static_cast<hw::RenderFloats>(HW_RENDER_FLOATS_WIREFRAME)) ==
        HW_RENDER_FLOATS_WIREFRAME);

  // The wrapper's call with the scoped value is the C call with the C value.
  const hw::mesh m = square();
  std::vector<double> by_c(3 * hw_mesh_n_vertex_slots(m.get()));
  CHECK(hw_mesh_vertex_normals(m.get(), HW_NORMAL_WEIGHTING_ANGLE, by_c.data(), by_c.size() / 3,
                               nullptr) == HW_OK);
  CHECK(m.vertex_normals(hw::NormalWeighting::Angle) == by_c);
  CHECK(m.visit(hw::ElementKind::Face, [](uint32_t) {}) == m.n_faces());

  // Returned values are scoped too.
  const hw::voronoi line({{0, 0}, {1, 0}, {2, 0}});
  CHECK(line.dimension() == hw::SiteDimension::Line);
  bool thrown = false;
  try {
    hw::mesh::read("no such file.obj", hw::BuildPolicy::Skip);
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::Io && hw::name(e.status()) == hw_status_str(HW_ERR_IO);
  }
  CHECK(thrown);

  // A value outside its family, forced in by a cast, is refused by the library as in C.
  CHECK(refused_with(hw::Status::InvalidInput,
                     [] { square().vertex_normals(static_cast<hw::NormalWeighting>(7)); }));
  // Every doctor finding has a name; a C loop over the family reads the same names.
  for (hw_doctor_finding kind = HW_DOCTOR_FINDING_FIRST;
       kind < HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT; ++kind)
    CHECK(hw::name(static_cast<hw::DoctorFinding>(kind)) == hw_doctor_finding_name(kind));
}

int main() {
  ids_compare_and_hash();
  library_wide_calls();
  mesh_editing();
  deleting_and_index_maps();
  topology_views_and_normals();
  attribute_info();
  diagnostic_edges_and_vertex_fans();
  winged_bulk_calls();
  scoped_enumerations();
  return check_summary("test_hpp_vocabulary");
}
