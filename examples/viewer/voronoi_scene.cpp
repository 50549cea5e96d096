#include "voronoi_scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "gl_program.h"

namespace viewer {

namespace {

// The rectangle the cells are clipped to.
constexpr double width = 16.0, height = 10.0;

// Flat colours per vertex, no lighting: the plane faces the viewer.
const char* const fill_vertex_shader =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 color;\n"
    "uniform mat4 mvp;\n"
    "out vec3 vertex_color;\n"
    "void main() { vertex_color = color; gl_Position = mvp * vec4(position, 1.0); }\n";
const char* const fill_fragment_shader =
    "#version 330 core\n"
    "in vec3 vertex_color;\n"
    "out vec4 color;\n"
    "void main() { color = vec4(vertex_color, 1.0); }\n";

constexpr line_style outline_style{{0.10f, 0.10f, 0.12f}, 1.5f};
constexpr line_style site_style{{0.05f, 0.05f, 0.05f}, 3.0f};

// A colour per site: hues a golden angle apart, so neighbouring indices (and most neighbouring
// cells) differ clearly; light enough for the dark outlines and sites to read on top.
std::array<float, 3> site_color(uint32_t site) {
  const double hue = std::fmod(site * 0.6180339887498949, 1.0) * 6.0;
  const double s = 0.55, v = 0.95, c = v * s;
  const double x = c * (1 - std::fabs(std::fmod(hue, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  const double m = v - c;
  return {float(r + m), float(g + m), float(b + m)};
}

}  // namespace

gpu_colored_surface::gpu_colored_surface(const hw::render_buffers& buffers,
                                         const std::vector<float>& colors) {
  glBindVertexArray(vao_.get());
  upload_attribute(positions_, buffers.floats(hw::RenderFloats::Positions), 0, 3);
  upload_attribute(colors_, hw::values_view<const float>(colors.data(), colors.size()), 1, 3);
  const auto triangles = buffers.indices(hw::RenderIndices::Triangles);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangles_.get());  // recorded in the VAO
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size_bytes()),
               triangles.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  n_indices_ = static_cast<GLsizei>(triangles.size());
}

void gpu_colored_surface::draw() const {
  if (n_indices_ == 0) return;
  glBindVertexArray(vao_.get());
  glDrawElements(GL_TRIANGLES, n_indices_, GL_UNSIGNED_INT, nullptr);
}

voronoi_scene::voronoi_scene(std::size_t n_sites) {
  fill_program_ = gl_program_build(fill_vertex_shader, nullptr, fill_fragment_shader);
  if (fill_program_ == 0) throw std::runtime_error("voronoi scene: the fill shader does not build");
  add_random_sites(n_sites);
  rebuild();
}

voronoi_scene::~voronoi_scene() { glDeleteProgram(fill_program_); }

void voronoi_scene::add_random_sites(std::size_t n) {
  // A 64-bit linear congruential generator (Knuth's MMIX constants), top 53 bits.
  const auto uniform = [this] {
    random_state_ = random_state_ * 6364136223846793005u + 1442695040888963407u;
    return static_cast<double>(random_state_ >> 11) / 9007199254740992.0;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double x = width * uniform();
    sites_.push_back({x, height * uniform()});
  }
}

void voronoi_scene::rebuild() {
  cells_.reset();
  outlines_.reset();
  site_marks_.reset();
  n_cells_ = 0;
  if (sites_.empty()) return;
  const hw::voronoi diagram(sites_);
  const hw::voronoi_cells clipped = diagram.clip({0, 0}, {width, height});
  const hw::render_buffers buffers = hw::render_buffers::cells(clipped);
  // Every vertex takes the colour of the site whose cell it belongs to.
  const auto vertex_sites = buffers.indices(hw::RenderIndices::VertexSources);
  std::vector<float> colors;
  colors.reserve(3 * vertex_sites.size());
  for (uint32_t site : vertex_sites) {
    const auto c = site_color(site);
    colors.insert(colors.end(), c.begin(), c.end());
  }
  cells_ = std::make_unique<gpu_colored_surface>(buffers, colors);
  outlines_ = std::make_unique<gpu_lines>(buffers, hw::RenderFloats::Wireframe);
  for (hw_site site{0}; site.idx < clipped.size(); ++site.idx)
    n_cells_ += !clipped.polygon(site).empty();

  // The sites as small squares: the outlines of a polygon list.
  const double r = 0.05;
  std::vector<double> corners;
  std::vector<uint32_t> sizes(sites_.size(), 4);
  for (const hw::point2& p : sites_) {
    const double square[8] = {p[0] - r, p[1] - r, p[0] + r, p[1] - r,
                              p[0] + r, p[1] + r, p[0] - r, p[1] + r};
    corners.insert(corners.end(), square, square + 8);
  }
  site_marks_ = std::make_unique<gpu_lines>(hw::render_buffers::polygons(corners, 2, sizes),
                                            hw::RenderFloats::Wireframe);
}

void voronoi_scene::view(float aspect, float& half_width, float& half_height) const {
  // The whole rectangle with a 5% margin, whatever the window's shape.
  const float margin = 1.05f;
  if (width / height > aspect) {
    half_width = float(0.5 * width) * margin;
    half_height = half_width / aspect;
  } else {
    half_height = float(0.5 * height) * margin;
    half_width = half_height * aspect;
  }
}

void voronoi_scene::draw(const programs& with) const {
  // A 2D scene: its own orthographic view of the rectangle, not the orbit camera's.
  GLint viewport[4] = {0, 0, 1, 1};
  glGetIntegerv(GL_VIEWPORT, viewport);
  aspect_ = float(viewport[2]) / float(viewport[3] > 0 ? viewport[3] : 1);
  float half_width = 1, half_height = 1;
  view(aspect_, half_width, half_height);
  const float mvp[16] = {1 / half_width, 0, 0, 0,
                         0, 1 / half_height, 0, 0,
                         0, 0, 1, 0,
                         float(-0.5 * width) / half_width, float(-0.5 * height) / half_height, 0, 1};
  glDisable(GL_DEPTH_TEST);  // drawn in order: fills, outlines, sites
  if (cells_) {
    glUseProgram(fill_program_);
    glUniformMatrix4fv(glGetUniformLocation(fill_program_, "mvp"), 1, GL_FALSE, mvp);
    cells_->draw();
  }
  glUseProgram(with.lines);
  glUniformMatrix4fv(glGetUniformLocation(with.lines, "mvp"), 1, GL_FALSE, mvp);
  const auto draw_lines = [&](const line_style& style, const gpu_lines& lines) {
    glUniform3fv(glGetUniformLocation(with.lines, "line_color"), 1, style.color.data());
    glUniform1f(glGetUniformLocation(with.lines, "line_width"), style.width);
    lines.draw();
  };
  if (show_outlines_ && outlines_) draw_lines(outline_style, *outlines_);
  if (show_sites_ && site_marks_) draw_lines(site_style, *site_marks_);
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
}

bool voronoi_scene::on_key(int key) {
  switch (key) {
    case GLFW_KEY_L: {
      // One Lloyd step: every site moves to the centroid of its clipped cell.
      if (sites_.empty()) return false;
      const std::vector<hw::point2> rectangle = {{0, 0}, {width, 0}, {width, height}, {0, height}};
      const hw::lloyd_result step = hw::lloyd(sites_, rectangle, 1);
      sites_ = step.sites;
      last_move_ = step.max_displacement;
      ++lloyd_steps_;
      break;
    }
    case GLFW_KEY_P: add_random_sites(10); break;
    case GLFW_KEY_C:
      sites_.clear();
      lloyd_steps_ = 0;
      last_move_ = 0;
      break;
    case GLFW_KEY_O: show_outlines_ = !show_outlines_; return true;
    case GLFW_KEY_S: show_sites_ = !show_sites_; return true;
    default: return false;
  }
  rebuild();
  return true;
}

bool voronoi_scene::on_click(double x, double y) {
  // (x, y) are fractions of the window, from its top-left corner: back through the view.
  float half_width = 1, half_height = 1;
  view(aspect_, half_width, half_height);
  const double px = 0.5 * width + (2 * x - 1) * half_width;
  const double py = 0.5 * height + (1 - 2 * y) * half_height;
  if (px < 0 || px > width || py < 0 || py > height) return false;
  sites_.push_back({px, py});
  rebuild();
  return true;
}

std::string voronoi_scene::help() const {
  return "  click      add a site\n"
         "  L          one Lloyd step (sites to their cells' centroids)\n"
         "  P          add 10 random sites\n"
         "  C          clear all sites\n"
         "  O / S      cell outlines / sites\n";
}

std::string voronoi_scene::status() const {
  std::ostringstream out;
  out << "voronoi: " << sites_.size() << " sites, " << n_cells_ << " cells in " << width << " x "
      << height << ", " << lloyd_steps_ << " Lloyd steps";
  if (lloyd_steps_ > 0) out << " (last largest move " << last_move_ << ")";
  out << "; outlines " << (show_outlines_ ? "on" : "off") << ", sites "
      << (show_sites_ ? "on" : "off");
  return out.str();
}

std::pair<std::array<float, 3>, std::array<float, 3>> voronoi_scene::bounds() const {
  return {{0, 0, 0}, {float(width), float(height), 0}};
}

}  // namespace viewer
