// The C++ wrapper of render buffers and surface generators: RAII, views, exceptions.
#include <cmath>
#include <string>
#include <vector>

#include "check.h"
#include "halfwing.hpp"

static void generated_meshes_render() {
  hw::mesh torus = hw::surface::torus(2.0, 0.5, 16, 8);
  CHECK(torus.n_faces() == 16 * 8);
  hw_render_options options = hw_render_options_default();
  options.interleaved = true;
  hw::render_buffers buffers(torus, options);
  CHECK(buffers.stride() == 6);
  CHECK(buffers.indices(hw::RenderIndices::Triangles).size() == 3 * 2 * 16 * 8);
  CHECK(buffers.floats(hw::RenderFloats::Interleaved).size() == 6 * buffers.n_vertices());
  CHECK(buffers.floats(hw::RenderFloats::Interleaved).size_bytes() ==
        sizeof(float) * 6 * buffers.n_vertices());
  CHECK(buffers.floats(hw::RenderFloats::Boundary).empty());
  // Every triangle index names a vertex.
  bool in_range = true;
  for (uint32_t v : buffers.indices(hw::RenderIndices::Triangles))
    in_range = in_range && v < buffers.n_vertices();
  CHECK(in_range);
  auto box = buffers.bounds();
  CHECK(std::fabs(box.second[0] - 2.5f) < 1e-5f && std::fabs(box.first[2] + 0.5f) < 1e-5f);

  hw::mesh disc = hw::surface::revolution({{0, 0, 0}, {1, 0, 0}}, false, {0, 0, 0}, {0, 0, 1}, 12);
  hw::render_buffers disc_buffers(disc);
  CHECK(disc_buffers.floats(hw::RenderFloats::Boundary).size() == 12 * 6);

  hw::mesh band = hw::surface::ruled({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}, false, 2);
  CHECK(band.n_faces() == 2);
  hw::mesh tube = hw::surface::sweep({{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}, true, {0, 0, 1}, 1);
  CHECK(tube.n_faces() == 3);
  CHECK(hw::surface::tetrahedron().n_vertices() == 4);
  CHECK(hw::surface::icosphere(1.0, 1).n_faces() == 80);
  CHECK(hw::surface::grid(1.0, 1.0, 2, 2).n_faces() == 4);
}

static void polygons_and_errors() {
  hw::render_buffers cells = hw::render_buffers::polygons({0, 0, 1, 0, 1, 1, 0, 1}, 2, {4});
  CHECK(cells.n_vertices() == 4 && cells.indices(hw::RenderIndices::Triangles).size() == 6);
  CHECK(cells.floats(hw::RenderFloats::Wireframe).size() == 4 * 6);
  bool thrown = false;
  try {
    hw::surface::cube(-1.0);
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::InvalidInput &&
             std::string(e.what()).find("side") != std::string::npos;
  }
  CHECK(thrown);
  thrown = false;
  try {
    hw::render_buffers::polygons({0, 0, 1}, 2, {1});
  } catch (const hw::error& e) {
    thrown = e.status() == hw::Status::InvalidInput;
  }
  CHECK(thrown);
  thrown = false;
  try {
    hw_render_options options = hw_render_options_default();
    options.shading = HW_SHADING_CREASE;
    options.crease_angle = -1;
    hw::render_buffers bad(hw::surface::cube(), options);
  } catch (const hw::error& e) {
    thrown = std::string(e.what()).find("crease angle") != std::string::npos;
  }
  CHECK(thrown);
}

int main() {
  generated_meshes_render();
  polygons_and_errors();
  return check_summary("test_render_hpp");
}
