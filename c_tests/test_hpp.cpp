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

static void version_string() { CHECK(hw::version() == EXPECTED_VERSION_STRING); }

int main() {
  exceptions_carry_status_and_message();
  ownership_moves();
  version_string();
  return check_summary("test_hpp");
}
