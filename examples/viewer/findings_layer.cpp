#include "findings_layer.hpp"

#include <cmath>
#include <sstream>

namespace viewer {

namespace {

/// The key, colour and colour name of each finding kind, in ::hw_doctor_finding order.
struct kind_style {
  int key;
  char key_name;
  line_style style;
  const char* color_name;
};

constexpr std::array<kind_style, HW_DOCTOR_FINDING_COUNT> kind_styles{{
    {GLFW_KEY_C, 'C', {{1.0f, 0.5f, 0.0f}, 2.0f}, "orange"},       // small components
    {GLFW_KEY_O, 'O', {{1.0f, 0.0f, 0.0f}, 4.0f}, "red"},          // orientation witness
    {GLFW_KEY_Z, 'Z', {{1.0f, 1.0f, 0.0f}, 3.0f}, "yellow"},       // zero-length edges
    {GLFW_KEY_E, 'E', {{0.6f, 0.0f, 1.0f}, 3.0f}, "violet"},       // needles
    {GLFW_KEY_A, 'A', {{0.0f, 0.4f, 1.0f}, 3.0f}, "blue"},         // caps
    {GLFW_KEY_K, 'K', {{1.0f, 0.3f, 0.6f}, 4.0f}, "pink"},         // folded edges
    {GLFW_KEY_X, 'X', {{0.5f, 0.3f, 0.0f}, 3.0f}, "brown"},        // long edges
    {GLFW_KEY_P, 'P', {{1.0f, 1.0f, 1.0f}, 3.0f}, "white"},        // duplicate positions
    {GLFW_KEY_U, 'U', {{0.7f, 0.7f, 0.7f}, 3.0f}, "grey"},         // near duplicates
    {GLFW_KEY_D, 'D', {{0.0f, 0.5f, 0.0f}, 4.0f}, "dark green"},   // duplicate faces
    {GLFW_KEY_T, 'T', {{0.0f, 0.0f, 0.5f}, 4.0f}, "navy"},         // T-vertices
    {GLFW_KEY_I, 'I', {{1.0f, 0.0f, 0.0f}, 2.5f}, "red"},          // self-intersections
}};

}  // namespace

face_list face_list::read(const std::string& path) {
  hw_soup* raw = nullptr;
  hw::check(hw_soup_read(path.c_str(), &raw));
  const hw::detail::owned<hw_soup, hw_soup_free> soup(raw);
  const double* positions = nullptr;
  const uint32_t *sizes = nullptr, *indices = nullptr;
  std::size_t n_vertices = 0, n_faces = 0, n_indices = 0;
  hw::check(hw_soup_view(soup.get(), &positions, &n_vertices, &sizes, &n_faces, &indices,
                         &n_indices));
  face_list list;
  list.positions.assign(positions, positions + 3 * n_vertices);
  list.face_sizes.assign(sizes, sizes + n_faces);
  list.indices.assign(indices, indices + n_indices);
  return list;
}

face_list face_list::of(const hw::mesh& mesh) {
  face_list list;
  const hw::values_view<const double> positions = mesh.view_positions();
  list.positions.assign(positions.begin(), positions.end());
  for (uint32_t f = 0; f < mesh.n_faces(); ++f) {
    uint32_t size = 0;
    for (hw_vertex v : mesh.vertices_of(hw_face{f})) {
      list.indices.push_back(v.idx);
      ++size;
    }
    list.face_sizes.push_back(size);
  }
  return list;
}

namespace {

/// Three axis-aligned segments of length `size` through each point: a cross the line program
/// can draw, so vertices need no program of their own.
std::vector<float> crosses(const hw::values_view<const float>& points, float size) {
  std::vector<float> segments;
  segments.reserve(points.size() * 6);
  for (std::size_t p = 0; p + 2 < points.size(); p += 3) {
    for (int axis = 0; axis < 3; ++axis) {
      for (float side : {-0.5f, 0.5f}) {
        for (int k = 0; k < 3; ++k) segments.push_back(points[p + k] + (k == axis ? side * size : 0));
      }
    }
  }
  return segments;
}

void draw_lines(GLuint program, const line_style& style, const gpu_lines* lines) {
  if (lines == nullptr || lines->n_segments() == 0) return;
  glUniform3fv(glGetUniformLocation(program, "line_color"), 1, style.color.data());
  glUniform1f(glGetUniformLocation(program, "line_width"), style.width);
  lines->draw();
}

}  // namespace

findings_layer::findings_layer(const face_list& list) {
  report_ = hw::doctor_report::of(list.positions, list.face_sizes, list.indices);
  // Crosses a hundredth of the model's size.
  float size = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    double low = INFINITY, high = -INFINITY;
    for (std::size_t p = k; p < list.positions.size(); p += 3) {
      if (!std::isfinite(list.positions[p])) continue;
      low = std::fmin(low, list.positions[p]);
      high = std::fmax(high, list.positions[p]);
    }
    if (high > low) size = std::fmax(size, static_cast<float>(high - low) / 100);
  }
  for (hw_doctor_finding kind = HW_DOCTOR_FINDING_FIRST;
       kind < HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT; ++kind) {
    kind_layer layer;
    layer.kind = kind;
    const auto finding = static_cast<hw::DoctorFinding>(kind);
    layer.n_items = report_.finding(finding).n_items;
    if (layer.n_items > 0) {
      const auto buffers = hw::render_buffers::finding(report_, finding, list.positions,
                                                       list.face_sizes, list.indices);
      layer.outlines = std::make_unique<gpu_lines>(buffers, hw::RenderFloats::Wireframe);
      layer.lines = std::make_unique<gpu_lines>(buffers, hw::RenderFloats::Boundary);
      const std::vector<float> marks = crosses(buffers.floats(hw::RenderFloats::Points), size);
      layer.crosses = std::make_unique<gpu_lines>(hw::values_view<const float>(marks.data(), marks.size()));
    }
    kinds_.push_back(std::move(layer));
  }
}

void findings_layer::draw(GLuint line_program) const {
  for (const kind_layer& layer : kinds_) {
    if (!layer.shown) continue;
    const line_style& style = kind_styles[layer.kind - HW_DOCTOR_FINDING_FIRST].style;
    draw_lines(line_program, style, layer.outlines.get());
    draw_lines(line_program, style, layer.lines.get());
    draw_lines(line_program, style, layer.crosses.get());
  }
}

bool findings_layer::on_key(int key) {
  for (kind_layer& layer : kinds_) {
    if (kind_styles[layer.kind - HW_DOCTOR_FINDING_FIRST].key == key) {
      layer.shown = !layer.shown;
      return true;
    }
  }
  return false;
}

std::string findings_layer::help() const {
  std::ostringstream out;
  for (const kind_layer& layer : kinds_) {
    const kind_style& style = kind_styles[layer.kind - HW_DOCTOR_FINDING_FIRST];
    out << "  " << style.key_name << "          " << hw_doctor_finding_name(layer.kind) << " ("
        << style.color_name << "; " << layer.n_items << (layer.shown ? ", shown" : ", hidden")
        << ")\n";
  }
  return out.str();
}

std::string findings_layer::summary() const {
  const hw_doctor_verdict verdict = report_.verdict();
  std::ostringstream out;
  out << "doctor: " << (verdict.closed_polyhedron ? "a closed polyhedron" : verdict.reason);
  for (const kind_layer& layer : kinds_)
    if (layer.n_items > 0) out << "; " << layer.n_items << " " << hw_doctor_finding_name(layer.kind);
  return out.str();
}

}  // namespace viewer
