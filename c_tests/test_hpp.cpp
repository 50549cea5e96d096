// The C++ wrapper: RAII ownership and moves, exceptions carrying status and message, range-for
// circulation, reading files, normals and editing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "check.h"
#include "halfwing.hpp"

static void exceptions_carry_status_and_message() {
  bool thrown = false;
  try {
    hw::mesh::from_indexed({}, {3}, {0, 1, 2});
  } catch (const hw::error& e) {
    thrown = true;
    CHECK(e.status() == hw::Status::InvalidInput);
    CHECK(std::string(e.what()).find("out-of-range") != std::string::npos);
  }
  CHECK(thrown);
  thrown = false;
  try {
    hw::mesh::read("no/such/file.off");
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::Io;
  }
  CHECK(thrown);
}

static void ownership_moves() {
  const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  hw::mesh a = hw::mesh::from_indexed(positions, {3}, {0, 1, 2});
  CHECK(a.n_vertices() == 3 && a.n_faces() == 1 && a.n_edges() == 3);
  hw::mesh b = std::move(a);
  CHECK(!a && b && b.n_faces() == 1);
  hw::mesh c;
  c = std::move(b);
  CHECK(c.n_halfedges() == 6);
}

static void circulation_and_normals() {
  const std::string path = std::string(HALFWING_DATA_DIR) + "/meshes/closed/lapy_icosahedron.off";
  hw::diagnostic report;
  hw::mesh m = hw::mesh::read(path, hw::BuildPolicy::Strict, &report);
  CHECK(report && report.is_clean());
  CHECK(report.summary() == "no defects found");
  const hw::diagnostic empty;
  CHECK(!empty && empty.is_clean() && empty.summary().empty() &&
        empty.ids(hw::DiagnosticList::IsolatedVertices).empty());
  m.check_invariants();
  std::size_t ring_total = 0;
  for (uint32_t i = 0; i < m.n_vertices(); ++i) {
    hw_vertex v{i};
    std::set<uint32_t> ring, faces;
    for (hw_vertex w : m.vertices_around(v)) ring.insert(w.idx);
    for (hw_face f : m.faces_around(v)) faces.insert(f.idx);
    for (hw_halfedge h : m.outgoing(v)) CHECK(m.origin(h).idx == i);
    CHECK(ring.size() == 5 && faces.size() == 5 && m.valence(v) == 5);
    ring_total += ring.size();
  }
  CHECK(ring_total == 2 * m.n_edges());
  for (uint32_t f = 0; f < m.n_faces(); ++f) {
    std::size_t sides = 0, across = 0;
    for (hw_vertex v : m.vertices_of(hw_face{f})) {
      (void)v;
      ++sides;
    }
    for (hw_face g : m.faces_across(hw_face{f})) across += g.idx != f;
    CHECK(sides == 3 && across == 3);
  }
  CHECK(m.boundary_loops().empty() && m.count_components() == 1);
  const std::vector<double> normals = m.vertex_normals(hw::NormalWeighting::Angle);
  for (uint32_t i = 0; i < m.n_vertices(); ++i) {
    // An icosahedron centred at the origin (coordinates rounded in the file): the normal points
    // along the position.
    const std::array<double, 3> p = m.position(hw_vertex{i});
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double along = (normals[3 * i] * p[0] + normals[3 * i + 1] * p[1] + normals[3 * i + 2] * p[2]) / r;
    CHECK(along > 0.9999);
  }
}

/// hw::mesh::visit: every live element once, a callable that stops the visit by returning false,
/// and an exception from the callable rethrown to the caller after the visit stopped.
static void visits() {
  const std::string path = std::string(HALFWING_DATA_DIR) + "/meshes/closed/lapy_icosahedron.off";
  hw::mesh m = hw::mesh::read(path);
  std::size_t valence_sum = 0;
  CHECK(m.visit(hw::ElementKind::Vertex,
                [&](uint32_t v) { valence_sum += m.valence(hw_vertex{v}); }) == m.n_vertices());
  CHECK(valence_sum == 2 * m.n_edges());
  std::vector<uint32_t> faces;
  CHECK(m.visit(hw::ElementKind::Face, [&](uint32_t f) {
    faces.push_back(f);
    return faces.size() < 4;
  }) == 4);
  CHECK((faces == std::vector<uint32_t>{0, 1, 2, 3}));
  std::size_t calls = 0;
  bool thrown = false;
  try {
    m.visit(hw::ElementKind::Edge, [&](uint32_t e) {
      ++calls;
      if (e == 2) throw std::runtime_error("edge 2");
    });
  } catch (const std::runtime_error& e) {
    thrown = std::string(e.what()) == "edge 2";
  }
  CHECK(thrown && calls == 3);
  bool refused = false;
  try {
    m.visit(static_cast<hw::ElementKind>(99), [](uint32_t) {});
  } catch (const hw::error& e) {
    refused = e.status() == hw::Status::InvalidInput;
  }
  CHECK(refused);
}

static void editing() {
  hw::mesh m = hw::mesh::from_indexed({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {3, 3},
                                      {0, 1, 2, 0, 2, 3});
  hw_edge diagonal{};
  for (uint32_t e = 0; e < m.n_edges(); ++e)
    if (!m.is_boundary(hw_edge{e})) diagonal = hw_edge{e};
  m.flip_edge(diagonal);
  m.check_invariants();
  bool refused = false;
  try {
    m.flip_edge(hw_edge{0});  // a boundary edge
  } catch (const hw::error& e) {
    refused = e.status() == hw::Status::Refused;
  }
  CHECK(refused);
  const hw_vertex middle = m.split_edge(diagonal, {0.5, 0.5, 0});
  CHECK(m.n_vertices() == 5 && m.valence(middle) == 2);
  m.delete_face(hw_face{0}, true);
  m.garbage_collect();
  CHECK(m.n_faces() == 1);
  m.check_invariants();
}

static void faces_and_attributes() {
  hw::mesh m;
  const hw_vertex a = m.add_vertex(0, 0, 0), b = m.add_vertex(1, 0, 0), c = m.add_vertex(0, 1, 0);
  const hw_face f = m.add_face({a, b, c});
  CHECK(f.idx == 0 && m.n_faces() == 1 && m.n_edges() == 3);
  bool refused = false;
  try {
    m.add_face({a, b, c});
  } catch (const hw::error& e) {
    refused = e.status() == hw::Status::Refused;
  }
  CHECK(refused && m.n_faces() == 1);

  m.add_attribute<float>(hw::ElementKind::Vertex, "colour", 3);
  m.add_attribute<uint32_t>(hw::ElementKind::Face, "group");
  auto colour = m.attribute_data<float>(hw::ElementKind::Vertex, "colour");
  CHECK(colour.size() == 9);
  colour[4] = 2.5f;
  CHECK(m.attribute<float>(hw::ElementKind::Vertex, "colour")[4] == 2.5f);
  CHECK(m.attribute_names(hw::ElementKind::Face) == std::vector<std::string>{"group"});
  bool wrong_type = false;
  try {
    m.attribute<double>(hw::ElementKind::Vertex, "colour");
  } catch (const hw::error& e) {
    wrong_type = e.status() == hw::Status::InvalidInput;
  }
  CHECK(wrong_type);

  std::vector<double> uv(2 * m.n_halfedges(), 0.5);
  m.set_corner_uvs(uv);
  CHECK(m.corner_uvs().size() == uv.size() && m.corner_uvs()[3] == 0.5);
  m.remove_attribute(hw::ElementKind::Halfedge, "hw:corner_uv");
  bool missing = false;
  try {
    m.corner_uvs();
  } catch (const hw::error& e) {
    missing = e.status() == hw::Status::NotFound;
  }
  CHECK(missing);
}

/// hw::winged: a quad built by the Euler operators, walked with range-for, converted to a
/// half-edge mesh and back; refusals throw with HW_ERR_REFUSED and change nothing.
static void winged_kernel() {
  hw::winged w;
  auto [v0, f0] = w.mvfs({0, 0, 0});
  auto [e1, v1] = w.mev(f0, v0, {1, 0, 0});
  auto [e2, v2] = w.mev(f0, v1, {1, 1, 0});
  auto [e3, v3] = w.mev(f0, v2, {0, 1, 0});
  auto [e4, f1] = w.mef(f0, v3, v0);
  CHECK(w.n_vertices() == 4 && w.n_edges() == 4 && w.n_faces() == 2);
  w.check_invariants();
  std::vector<uint32_t> corners;
  for (hw_wvertex v : w.face_vertices(f1)) corners.push_back(v.idx);
  CHECK(corners.size() == 4);
  std::set<uint32_t> around_v0;
  for (hw_wvertex v : w.vertex_vertices(v0)) around_v0.insert(v.idx);
  CHECK((around_v0 == std::set<uint32_t>{v1.idx, v3.idx}));
  std::size_t edges = 0, faces = 0;
  for (hw_wedge e : w.face_edges(f0)) edges += e.idx != HW_INVALID_INDEX;
  for (hw_wface f : w.face_faces(f0)) faces += f.idx == f1.idx;
  CHECK(edges == 4 && faces == 4);
  const hw_wedge_record r = w.edge(e4);
  CHECK(r.start.idx == v3.idx && r.end.idx == v0.idx && r.left_face.idx == f1.idx);
  CHECK(std::fabs(std::fabs(w.face_normal(f1)[2]) - 1) < 1e-12);

  bool refused = false;
  try {
    w.mef(f0, v1, v1);
  } catch (const hw::error& e) {
    refused = e.status() == hw::Status::Refused &&
              std::string(e.what()).find("itself") != std::string::npos;
  }
  CHECK(refused);
  CHECK(w.n_edges() == 4);
  bool invalid = false;
  try {
    w.vertex_edge(hw_wvertex{99});
  } catch (const hw::error& e) {
    invalid = e.status() == hw::Status::InvalidHandle;
  }
  CHECK(invalid);

  hw::mesh m = w.to_mesh();
  CHECK(m.n_faces() == 2 && m.n_halfedges() == 8);
  hw::winged back = hw::winged::from_mesh(m);
  CHECK(back.n_edges() == 4 && back.table(hw::WTable::Edges) == w.table(hw::WTable::Edges));
  const std::string faces_csv =
      w.table(hw::WTable::Faces, hw::WNaming::DirectInverse, hw::TableFormat::Csv);
  CHECK(faces_csv.rfind("Id,Arista\n0,", 0) == 0 && faces_csv.find("\n1,3\n") != std::string::npos);
  hw::winged moved = std::move(back);
  CHECK(!back && moved.n_faces() == 2);
  (void)e1;
  (void)e2;
  (void)e3;
}

static void voronoi_classes() {
  const std::vector<hw::point2> sites = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 2}, {4, 0}};
  const hw::voronoi diagram(sites);
  CHECK(diagram.n_sites() == 6 && diagram.n_unique_sites() == 5);
  CHECK(diagram.dimension() == hw::SiteDimension::Plane && diagram.n_triangles() == 4);
  CHECK(diagram.view(hw::VoronoiArray::Representative)[5] == 1);
  CHECK(diagram.sites().size() == 6 && diagram.vertices().size() == diagram.n_vertices());
  const hw_site corner{0}, centre{4}, duplicate{5};
  CHECK(diagram.nearest_site({1.2, 2.1}) == centre);
  CHECK(diagram.nearest_site({3.9, 0.1}, centre) == hw_site{1});
  // The ids order and hash, so the neighbours go into a set: four distinct corners.
  const std::vector<hw_site> around = diagram.neighbours(centre);
  const std::set<hw_site> distinct(around.begin(), around.end());
  CHECK(around.size() == 4 && distinct.size() == 4 && distinct.count(duplicate) == 0);
  CHECK(std::hash<hw_site>()(centre) == std::hash<uint32_t>()(4));
  const hw_voronoi_halfedge h = diagram.edge_between(corner, centre);
  CHECK(diagram.edge(h).site == corner && diagram.edge(h).opposite_site == centre);
  CHECK(diagram.edge(h).origin != diagram.edge(h).target);
  CHECK(diagram.edge_between(centre, corner) == hw_voronoi_halfedge{h.idx ^ 1u});
  CHECK(diagram.delaunay_mesh().n_faces() == 4);
  const hw::delaunay triangulation(sites);
  CHECK(triangulation.dimension() == hw::SiteDimension::Plane && triangulation.n_triangles() == 4);
  const auto triangles = triangulation.view(hw::VoronoiArray::Triangles);
  const auto dual_triangles = diagram.view(hw::VoronoiArray::Triangles);
  CHECK(std::equal(triangles.begin(), triangles.end(), dual_triangles.begin(), dual_triangles.end()));
  CHECK(triangulation.view(hw::VoronoiArray::Hull).size() == 4);

  const hw::voronoi_cells cells = diagram.clip({-1, -1}, {5, 5});
  double total = 0;
  for (hw_site s{0}; s.idx < cells.size(); ++s.idx) total += cells.area(s);
  CHECK(std::fabs(total - 36) < 1e-12 && cells.polygon(duplicate).empty());
  CHECK(cells.polygon_points(centre).size() == cells.polygon(centre).size());
  const hw::point2 c = cells.centroid(centre);
  CHECK(c[0] > 0 && c[0] < 4 && c[1] > 0 && c[1] < 4);
  CHECK(cells.to_mesh().n_faces() == 5 && cells.face_sites().size() == 5);
  CHECK(cells.face_sites()[4] == centre);
  const hw::render_buffers drawn = hw::render_buffers::cells(cells);
  CHECK(drawn.indices(hw::RenderIndices::TriangleFaces).size() ==
        drawn.indices(hw::RenderIndices::Triangles).size() / 3);
  CHECK(drawn.indices(hw::RenderIndices::WireframeSources).size() ==
        drawn.floats(hw::RenderFloats::Wireframe).size() / 6);
  CHECK(drawn.n_vertices() == drawn.floats(hw::RenderFloats::Positions).size() / 3 &&
        drawn.n_vertices() > 0);
  const hw::voronoi_cells diamond = diagram.clip({{2, -1}, {5, 2}, {2, 5}, {-1, 2}});
  CHECK(diamond.positions().size() >= 4);

  const std::vector<uint32_t> labels =
      diagram.label_image(hw::Metric::Chebyshev, {0, 0}, {4, 4}, 8, 8);
  CHECK(labels.size() == 64 && labels.front() == 3);
  const std::string svg = diagram.svg(cells);
  CHECK(svg.rfind("<svg", 0) == 0 && svg.find('\0') == std::string::npos);
  diagram.write_svg(cells, TEST_TMP_DIR "/voronoi_hpp.svg");

  const hw::lloyd_result relaxed = hw::lloyd(sites, {{0, 0}, {4, 0}, {4, 4}, {0, 4}}, 20, 1e-9);
  CHECK(relaxed.sites.size() == 6 && relaxed.iterations >= 1);

  bool thrown = false;
  try {
    diagram.edge_between(corner, hw_site{2});
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::NotFound;
  }
  CHECK(thrown);
  thrown = false;
  try {
    hw::voronoi({{0, 0}, {NAN, 1}});
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::InvalidInput &&
             std::string(e.what()).find("site 1") != std::string::npos;
  }
  CHECK(thrown);

  // A point file feeds a diagram; a malformed one throws with the file's line.
  const std::vector<hw::point2> read =
      hw::read_points2d(std::string(HALFWING_DATA_DIR) + "/points2d/triangle_dots.node");
  CHECK(read.size() == 100 && read[0][0] == 0.0476694 && read[0][1] == 0.809168);
  CHECK(hw::voronoi(read).n_sites() == read.size());
  thrown = false;
  try {
    hw::read_points2d(std::string(HALFWING_DATA_DIR) + "/meshes/closed/cgal_cube.off");
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::InvalidInput &&
             std::string(e.what()).find("unknown point format") != std::string::npos;
  }
  CHECK(thrown);
}

static void doctor() {
  // A refused build still hands its diagnostic to the caller, then throws.
  hw::diagnostic refused;
  bool thrown = false;
  try {
    hw::mesh::from_indexed({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3, 3}, {0, 1, 2, 0, 1, 2},
                           hw::BuildPolicy::Strict, &refused);
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::NonManifold;
  }
  CHECK(thrown && refused && !refused.is_clean());
  CHECK(refused.summary().find("inconsistently oriented") != std::string::npos);

  // The teapot's pinched vertices, with their fans; the icosahedron is a closed polyhedron.
  const std::string data = std::string(HALFWING_DATA_DIR) + "/meshes/";
  const hw::mesh icosahedron = hw::mesh::read(data + "closed/lapy_icosahedron.off");
  const hw::doctor_report report = icosahedron.examine();
  const hw_doctor_verdict verdict = report.verdict();
  CHECK(verdict.closed_polyhedron && verdict.reason == nullptr);
  const std::vector<hw_doctor_component> components = report.components();
  CHECK(components.size() == 1 && components[0].genus == 0 && components[0].outward == 1);
  CHECK(report.boundary_loops().empty());
  CHECK(report.text().find("a closed polyhedron") != std::string::npos);
  CHECK(report.json().find("\"closed_polyhedron\":true") != std::string::npos);
  CHECK(hw_diagnostic_is_clean(report.input_diagnostic()));

  const hw::doctor_report broken =
      hw::doctor_report::of({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 0}, {3, 3, 3},
                            {0, 1, 2, 0, 2, 3, 1, 4, 2});
  const hw::doctor_report::finding_view duplicates =
      broken.finding(hw::DoctorFinding::DuplicatePositions);
  CHECK(duplicates.n_items == 1 && duplicates.ids_per_item == 2);
  CHECK(duplicates.ids[0] == 4 && duplicates.ids[1] == 2);
  CHECK(broken.boundary_loops().size() == 1 && !broken.verdict().closed);
}

static void repair_pipeline() {
  const hw::soup input =
      hw::soup::read(std::string(HALFWING_DATA_DIR) + "/meshes/broken/cgaltest_nm_edges_simple.off");
  auto repaired = hw::repair_mesh(input);
  const hw::mesh& m = repaired.first;
  CHECK(hw_mesh_check(m.get()) == HW_OK);
  const hw_repair_fate_counts c = repaired.second.counts();
  const std::size_t n_input = input.positions().size() / 3;
  CHECK(c.kept_vertices + c.merged_vertices + c.removed_vertices == n_input);
  CHECK(c.kept_vertices + c.added_vertices == m.n_vertices());
  CHECK(c.kept_faces + c.removed_faces == input.face_sizes().size());
  CHECK(repaired.second.list(hw::FatesList::VertexKinds).size() == n_input);

  // A cap flips with the triangle across its long edge; a T-vertex splits the edge under it.
  hw::mesh cap = hw::mesh::from_indexed({0, 0, 0, 2, 0, 0, 1, 0, 0, 1, -1, 0}, {3, 3},
                                        {0, 1, 2, 1, 0, 3});
  const hw::repair_report flipped = cap.remove_degenerate_faces();
  CHECK(flipped.list(hw::RepairList::FlippedFaces) == std::vector<uint32_t>({0, 1}));
  CHECK(cap.n_faces() == 2 && cap.remove_degenerate_faces().list(hw::RepairList::FlippedFaces).empty());
  hw::mesh crack = hw::mesh::from_indexed(
      {0, 0, 0, 2, 0, 0, 1, -1, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, 3, 0, 0}, {3, 3, 3, 3, 3, 3, 3},
      {0, 2, 1, 0, 3, 4, 3, 1, 4, 2, 0, 5, 5, 0, 4, 1, 2, 6, 4, 1, 6});
  CHECK(crack.remove_t_vertices().list(hw::RepairList::VertexCopies) == std::vector<uint32_t>({3}));
  CHECK(crack.stitch_borders().list(hw::RepairList::StitchedHalfedges).size() == 4);
  CHECK(crack.n_vertices() == 7 && hw_mesh_check(crack.get()) == HW_OK);
  hw_repair_options bad = hw_repair_options_default();
  bad.merge_tolerance = -1;
  bool threw = false;
  try {
    hw::repair_mesh(input, bad);
  } catch (const hw::error& e) {
    threw = e.status() == hw::Status::InvalidInput;
  }
  CHECK(threw);
}

static void version_string() { CHECK(hw::version() == EXPECTED_VERSION_STRING); }

// ---- range-for over the inline navigation -----------------------------------------------------

/// The ids a checked C circulator yields, to its end.
template <class Id>
static std::vector<uint32_t> checked_walk(hw_circulator c, bool (*next)(hw_circulator*, Id*)) {
  std::vector<uint32_t> ids;
  Id id;
  while (next(&c, &id)) ids.push_back(id.idx);
  return ids;
}

/// The ids a range-for over `range` yields.
template <class Range>
static std::vector<uint32_t> range_walk(const Range& range) {
  std::vector<uint32_t> ids;
  for (auto id : range) ids.push_back(id.idx);
  return ids;
}

static hw_circulator around(const hw::mesh& m, hw_vertex v, hw_circulator_kind kind) {
  hw_circulator c;
  hw::check(hw_circ_around_vertex(m.get(), v, kind, &c));
  return c;
}

static hw_circulator around(const hw::mesh& m, hw_face f, hw_circulator_kind kind) {
  hw_circulator c;
  hw::check(hw_circ_around_face(m.get(), f, kind, &c));
  return c;
}

/// Every range of hw::mesh (checked start, inline steps) and of hw::nav_view yields what the
/// checked C circulators yield, and every nav_view step agrees with the checked one. Returns the
/// number of walks compared.
static std::size_t ranges_match_checked(const hw::mesh& m) {
  const hw::nav_view nav = m.nav();
  CHECK(nav.n_vertex_slots() == hw_mesh_n_vertex_slots(m.get()));
  CHECK(nav.n_halfedge_slots() == hw_mesh_n_halfedge_slots(m.get()));
  CHECK(nav.n_face_slots() == hw_mesh_n_face_slots(m.get()));
  CHECK(nav.raw().origin != nullptr || nav.n_halfedge_slots() == 0);
  std::size_t walks = 0;
  auto same = [&](const std::vector<uint32_t>& want, const std::vector<uint32_t>& got) {
    ++walks;
    CHECK(want == got);
  };
  for (uint32_t i = 0; i < nav.n_vertex_slots(); ++i) {
    const hw_vertex v{i};
    if (nav.is_deleted(v)) {
      bool thrown = false;
      try {
        m.vertices_around(v);
      } catch (const hw::error& e) {
        thrown = e.status() == hw::Status::InvalidHandle;
      }
      CHECK(thrown);
      CHECK(range_walk(nav.outgoing(v)).empty());
      continue;
    }
    CHECK(nav.halfedge(v).idx == m.halfedge(v).idx);
    const auto outgoing =
        checked_walk(around(m, v, HW_CIRCULATOR_KIND_HALFEDGES), hw_circ_next_halfedge);
    same(outgoing, range_walk(m.outgoing(v)));
    same(outgoing, range_walk(nav.outgoing(v)));
    const auto incoming =
        checked_walk(around(m, v, HW_CIRCULATOR_KIND_INCOMING), hw_circ_next_halfedge);
    same(incoming, range_walk(m.incoming(v)));
    same(incoming, range_walk(nav.incoming(v)));
    const auto ring = checked_walk(around(m, v, HW_CIRCULATOR_KIND_VERTICES), hw_circ_next_vertex);
    same(ring, range_walk(m.vertices_around(v)));
    same(ring, range_walk(nav.vertices_around(v)));
    const auto edges = checked_walk(around(m, v, HW_CIRCULATOR_KIND_EDGES), hw_circ_next_edge);
    same(edges, range_walk(m.edges_around(v)));
    same(edges, range_walk(nav.edges_around(v)));
    const auto faces = checked_walk(around(m, v, HW_CIRCULATOR_KIND_FACES), hw_circ_next_face);
    same(faces, range_walk(m.faces_around(v)));
    same(faces, range_walk(nav.faces_around(v)));
    if (!outgoing.empty()) {
      // From its second outgoing half-edge: the same ring, rotated by one.
      std::vector<uint32_t> rotated(outgoing.begin() + 1, outgoing.end());
      rotated.push_back(outgoing.front());
      same(rotated, range_walk(nav.around_origin(hw_halfedge{outgoing.size() > 1 ? outgoing[1] : outgoing[0]})));
    }
  }
  for (uint32_t i = 0; i < nav.n_face_slots(); ++i) {
    const hw_face f{i};
    if (nav.is_deleted(f)) continue;
    CHECK(nav.halfedge(f).idx == m.halfedge(f).idx);
    const auto sides =
        checked_walk(around(m, f, HW_CIRCULATOR_KIND_HALFEDGES), hw_circ_next_halfedge);
    same(sides, range_walk(m.halfedges_of(f)));
    same(sides, range_walk(nav.halfedges_of(f)));
    const auto corners =
        checked_walk(around(m, f, HW_CIRCULATOR_KIND_VERTICES), hw_circ_next_vertex);
    same(corners, range_walk(m.vertices_of(f)));
    same(corners, range_walk(nav.vertices_of(f)));
    const auto edges = checked_walk(around(m, f, HW_CIRCULATOR_KIND_EDGES), hw_circ_next_edge);
    same(edges, range_walk(m.edges_of(f)));
    same(edges, range_walk(nav.edges_of(f)));
    const auto across = checked_walk(around(m, f, HW_CIRCULATOR_KIND_FACES), hw_circ_next_face);
    same(across, range_walk(m.faces_across(f)));
    same(across, range_walk(nav.faces_across(f)));
  }
  for (uint32_t i = 0; i < nav.n_halfedge_slots(); ++i) {
    const hw_halfedge h{i};
    if (nav.is_deleted(nav.edge(h))) continue;
    CHECK(nav.origin(h).idx == m.origin(h).idx && nav.target(h).idx == m.target(h).idx);
    CHECK(nav.twin(h).idx == m.twin(h).idx && nav.edge(h).idx == m.edge(h).idx);
    CHECK(nav.next(h).idx == m.next(h).idx && nav.prev(h).idx == m.prev(h).idx);
    CHECK(nav.face(h).idx == m.face(h).idx && nav.is_boundary(h) == m.is_boundary(h));
    hw_circulator c;
    hw::check(hw_circ_along_loop(m.get(), h, &c));
    const auto loop = checked_walk(c, hw_circ_next_halfedge);
    same(loop, range_walk(m.loop(h)));
    same(loop, range_walk(nav.loop(h)));
  }
  return walks;
}

static void ranges_on_real_models() {
  for (const char* model : {"closed/pmp_fandisk.off", "open/cgal_elephant-with-holes.off",
                            "polygonal/igl_horse_quad.obj", "polygonal/igl_cylinder.obj"}) {
    const hw::mesh m = hw::mesh::read(std::string(HALFWING_DATA_DIR) + "/meshes/" + model);
    CHECK(ranges_match_checked(m) > 1000);
  }
  // After deleting faces (their isolated vertices too) and garbage collection.
  hw::mesh m =
      hw::mesh::read(std::string(HALFWING_DATA_DIR) + "/meshes/open/cgal_elephant-with-holes.off");
  const std::size_t n_faces = m.n_faces();
  for (uint32_t f = 0; f < n_faces; f += 23) m.delete_face(hw_face{f}, true);
  CHECK(m.nav().raw().face_deleted != nullptr);
  std::size_t deleted_vertices = 0;
  const hw::nav_view nav = m.nav();
  for (uint32_t v = 0; v < nav.n_vertex_slots(); ++v) deleted_vertices += nav.is_deleted(hw_vertex{v});
  CHECK(deleted_vertices > 0);
  CHECK(ranges_match_checked(m) > 1000);
  m.garbage_collect();
  CHECK(m.nav().raw().face_deleted == nullptr);
  CHECK(ranges_match_checked(m) > 1000);
}

static void hole_filling() {
  // An open box (a unit cube without its top): one 4-edge hole, closed by two triangles.
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  const std::vector<uint32_t> sizes(10, 3);
  const std::vector<uint32_t> ix = {0, 2, 1, 0, 3, 2, 0, 1, 5, 0, 5, 4, 1, 2, 6,
                                    1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  hw::mesh box = hw::mesh::from_indexed(p, sizes, ix);
  const hw::mesh::fill_holes_result result = box.fill_holes();
  CHECK(result.filled == 1 && result.refused == 0 && result.faces_added == 2);
  CHECK(box.n_faces() == 12);
  box.check_invariants();
  // The box is closed now: no half-edge is on a hole.
  bool refused = false;
  try {
    box.fill_hole(hw_halfedge{0});
  } catch (const hw::error& e) {
    refused = e.status() == hw::Status::Refused;
  }
  CHECK(refused && box.n_faces() == 12);
  // Refined: the fill is a disk over the rim's 4 edges, with any vertices it adds inside.
  hw::mesh refined = hw::mesh::from_indexed(p, sizes, ix);
  const hw::mesh::fill_holes_result fine = refined.fill_holes(SIZE_MAX, hw::FillMode::Fair);
  CHECK(fine.filled == 1 && fine.faces_added == 2 + 2 * (refined.n_vertices() - 8));
  CHECK(refined.boundary_loops().empty());
  refined.check_invariants();
  // A flat square: its cap would lie on it facing the other way, a fold, so it is refused.
  hw::mesh square = hw::mesh::from_indexed({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {3, 3},
                                           {0, 1, 2, 0, 2, 3});
  const hw::mesh::fill_holes_result flat = square.fill_holes();
  CHECK(flat.filled == 0 && flat.refused == 1 && square.n_faces() == 2);
}

int main() {
  exceptions_carry_status_and_message();
  ownership_moves();
  circulation_and_normals();
  ranges_on_real_models();
  visits();
  editing();
  hole_filling();
  faces_and_attributes();
  winged_kernel();
  voronoi_classes();
  doctor();
  repair_pipeline();
  version_string();
  return check_summary("test_hpp");
}
