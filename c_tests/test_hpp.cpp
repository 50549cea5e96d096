// The C++ wrapper: RAII ownership, moves, and exceptions carrying status and message.
#include <cstdio>
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
    CHECK(e.status() == HW_ERR_INVALID_INPUT);
    CHECK(std::string(e.what()).find("out of range") != std::string::npos ||
          std::string(e.what()).find("vertex") != std::string::npos);
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

static void faces_and_attributes() {
  hw::mesh m;
  const hw_vertex a = m.add_vertex(0, 0, 0), b = m.add_vertex(1, 0, 0), c = m.add_vertex(0, 1, 0);
  const hw_face f = m.add_face({a, b, c});
  CHECK(f.idx == 0 && m.n_faces() == 1 && m.n_edges() == 3);
  bool refused = false;
  try {
    m.add_face({a, b, c});
  } catch (const hw::error& e) {
    refused = e.status() == HW_ERR_REFUSED;
  }
  CHECK(refused && m.n_faces() == 1);

  m.add_attribute<float>(HW_ELEMENT_VERTEX, "colour", 3);
  m.add_attribute<uint32_t>(HW_ELEMENT_FACE, "group");
  auto colour = m.attribute_data<float>(HW_ELEMENT_VERTEX, "colour");
  CHECK(colour.size() == 9);
  colour[4] = 2.5f;
  CHECK(m.attribute<float>(HW_ELEMENT_VERTEX, "colour")[4] == 2.5f);
  CHECK(m.attribute_names(HW_ELEMENT_FACE) == std::vector<std::string>{"group"});
  bool wrong_type = false;
  try {
    m.attribute<double>(HW_ELEMENT_VERTEX, "colour");
  } catch (const hw::error& e) {
    wrong_type = e.status() == HW_ERR_INVALID_INPUT;
  }
  CHECK(wrong_type);

  std::vector<double> uv(2 * m.n_halfedges(), 0.5);
  m.set_corner_uvs(uv);
  CHECK(m.corner_uvs().size() == uv.size() && m.corner_uvs()[3] == 0.5);
  m.remove_attribute(HW_ELEMENT_HALFEDGE, "hw:corner_uv");
  bool missing = false;
  try {
    m.corner_uvs();
  } catch (const hw::error& e) {
    missing = e.status() == HW_ERR_NOT_FOUND;
  }
  CHECK(missing);
}

static void version_string() { CHECK(hw::version() == EXPECTED_VERSION_STRING); }

int main() {
  exceptions_carry_status_and_message();
  ownership_moves();
  faces_and_attributes();
  version_string();
  return check_summary("test_hpp");
}
