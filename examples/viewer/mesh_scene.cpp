#include "mesh_scene.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace viewer {

namespace {

constexpr double degrees = 3.14159265358979323846 / 180.0;

const char* shading_name(hw_shading shading) {
  switch (shading) {
    case HW_SHADING_FLAT: return "flat";
    case HW_SHADING_SMOOTH: return "smooth";
    case HW_SHADING_CORNER_NORMALS: return "file normals";
    default: return "crease";
  }
}

const char* weighting_name(hw_normal_weighting weighting) {
  switch (weighting) {
    case HW_NORMAL_WEIGHTING_UNIFORM:
      return "uniform";
    case HW_NORMAL_WEIGHTING_AREA:
      return "area";
    default: return "angle";
  }
}

void draw_lines(GLuint program, const line_style& style, const gpu_lines& lines) {
  glUniform3fv(glGetUniformLocation(program, "line_color"), 1, style.color.data());
  glUniform1f(glGetUniformLocation(program, "line_width"), style.width);
  lines.draw();
}

}  // namespace

mesh_scene::mesh_scene(const std::string& path)
    : path_(path),
      mesh_(hw::mesh::read(path, hw::BuildPolicy::Repair, &report_)),
      findings_(face_list::read(path)) {
  options_.shading = HW_SHADING_CREASE;
  rebuild();
}

void mesh_scene::rebuild() {
  // The repaired mesh has no non-manifold edge: the file's diagnostic does not apply to it.
  buffers_ = std::make_unique<hw::render_buffers>(shown_mesh(), options_,
                                                  show_repaired_ ? nullptr : &report_);
  surface_ = std::make_unique<gpu_surface>(*buffers_);
  wireframe_ = std::make_unique<gpu_lines>(*buffers_, hw::RenderFloats::Wireframe);
  boundary_ = std::make_unique<gpu_lines>(*buffers_, hw::RenderFloats::Boundary);
  non_manifold_ = std::make_unique<gpu_lines>(*buffers_, hw::RenderFloats::NonManifold);
  vertex_normals_ = std::make_unique<gpu_lines>(*buffers_, hw::RenderFloats::VertexNormals);
  face_normals_ = std::make_unique<gpu_lines>(*buffers_, hw::RenderFloats::FaceNormals);
}

void mesh_scene::draw(const programs& with) const {
  // Push the fill back a little so the lines on top are not lost to depth fighting.
  glUseProgram(with.surface);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  surface_->draw();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glUseProgram(with.lines);
  if (show_wireframe_) draw_lines(with.lines, styles::wireframe, *wireframe_);
  if (show_vertex_normals_) draw_lines(with.lines, styles::vertex_normals, *vertex_normals_);
  if (show_face_normals_) draw_lines(with.lines, styles::face_normals, *face_normals_);
  // Highlights last, and LEQUAL so they win depth ties against the wireframe on the same edges.
  glDepthFunc(GL_LEQUAL);
  if (show_boundary_) draw_lines(with.lines, styles::boundary, *boundary_);
  if (show_non_manifold_) draw_lines(with.lines, styles::non_manifold, *non_manifold_);
  shown_findings().draw(with.lines);
  glDepthFunc(GL_LESS);
  glBindVertexArray(0);
}

bool mesh_scene::on_key(int key) {
  switch (key) {
    case GLFW_KEY_1: options_.shading = HW_SHADING_FLAT; break;
    case GLFW_KEY_2: options_.shading = HW_SHADING_SMOOTH; break;
    case GLFW_KEY_3: options_.shading = HW_SHADING_CREASE; break;
    case GLFW_KEY_4: options_.shading = HW_SHADING_CORNER_NORMALS; break;
    case GLFW_KEY_G: options_.weighting = (options_.weighting + 1) % 3; break;
    case GLFW_KEY_LEFT_BRACKET:
      options_.crease_angle = std::fmax(options_.crease_angle - 5 * degrees, 0.0);
      break;
    case GLFW_KEY_RIGHT_BRACKET:
      options_.crease_angle = std::fmin(options_.crease_angle + 5 * degrees, 180 * degrees);
      break;
    case GLFW_KEY_W: show_wireframe_ = !show_wireframe_; return true;
    case GLFW_KEY_B: show_boundary_ = !show_boundary_; return true;
    case GLFW_KEY_M: show_non_manifold_ = !show_non_manifold_; return true;
    case GLFW_KEY_N: show_vertex_normals_ = !show_vertex_normals_; return true;
    case GLFW_KEY_F: show_face_normals_ = !show_face_normals_; return true;
    case GLFW_KEY_J: toggle_repaired(); break;
    default: {
      // A finding kind stays shown or hidden in both meshes.
      const bool known = findings_.on_key(key);
      if (repaired_findings_) repaired_findings_->on_key(key);
      return known;
    }
  }
  rebuild();  // the shading changed: new normals, maybe new vertex splits
  return true;
}

std::string mesh_scene::help() const {
  return "  1 / 2 / 3 / 4  shading: flat / smooth / crease angle / the file's normals\n"
         "  [ / ]      crease angle -5 / +5 degrees\n"
         "  G          vertex-normal weighting: uniform / area / angle\n"
         "  W          wireframe\n"
         "  B          boundary loops (magenta)\n"
         "  M          non-manifold edges from the diagnostic (cyan)\n"
         "  N / F      vertex / face normal glyphs (green / yellow)\n"
         "  J          repair: run the repair pipeline on the file and show the result, with the\n"
         "             doctor's findings on it (counts before and after in the console); again:\n"
         "             back to the file\n"
         "the doctor's findings on the shown mesh, one key each:\n" +
         shown_findings().help();
}

std::string mesh_scene::status() const {
  std::ostringstream out;
  out << (show_repaired_ ? "repaired, " : "") << shading_name(options_.shading);
  if (options_.shading == HW_SHADING_CREASE)
    out << " " << std::lround(options_.crease_angle / degrees) << " deg";
  if (options_.shading == HW_SHADING_SMOOTH) out << " (" << weighting_name(options_.weighting) << ")";
  out << ", " << buffers_->n_vertices() << " render vertices; wireframe "
      << (show_wireframe_ ? "on" : "off") << ", boundary " << (show_boundary_ ? "on" : "off")
      << ", non-manifold " << (show_non_manifold_ ? "on" : "off") << ", normals "
      << (show_vertex_normals_ ? "V" : "") << (show_face_normals_ ? "F" : "")
      << (show_vertex_normals_ || show_face_normals_ ? "" : "off");
  return out.str();
}

std::string mesh_scene::summary() const {
  std::ostringstream out;
  out << path_ << ": " << mesh_.n_vertices() << " vertices, " << mesh_.n_edges() << " edges, "
      << mesh_.n_faces() << " faces, " << mesh_.boundary_loops().size() << " boundary loops ("
      << boundary_->n_segments() << " edges), " << non_manifold_->n_segments()
      << " non-manifold edges\n"
      << "diagnostic: " << (report_.is_clean() ? std::string("clean") : report_.summary())
      << "\n" << findings_.summary();
  return out.str();
}

void mesh_scene::toggle_repaired() {
  if (!repaired_) {
    const hw::soup file = hw::soup::read(path_);
    auto [mesh, fates] = hw::repair_mesh(file);
    const hw_repair_fate_counts counts = fates.counts();
    repaired_ = std::make_unique<hw::mesh>(std::move(mesh));
    repaired_findings_ = std::make_unique<findings_layer>(face_list::of(*repaired_));
    std::printf("repair of %s\n"
                "  before: %zu vertices, %zu faces\n  %s\n"
                "  after: %zu vertices, %zu edges, %zu faces, %zu boundary loops\n"
                "  vertices: %zu kept, %zu merged, %zu removed, %zu added (copies)\n"
                "  faces: %zu kept (%zu reversed), %zu removed\n  %s\n",
                path_.c_str(), file.positions().size() / 3, file.face_sizes().size(),
                findings_.summary().c_str(), repaired_->n_vertices(), repaired_->n_edges(),
                repaired_->n_faces(), repaired_->boundary_loops().size(), counts.kept_vertices,
                counts.merged_vertices, counts.removed_vertices, counts.added_vertices,
                counts.kept_faces, counts.reversed_faces, counts.removed_faces,
                repaired_findings_->summary().c_str());
  }
  show_repaired_ = !show_repaired_;
  std::printf("showing %s\n", show_repaired_ ? "the repaired mesh" : "the file");
  std::fflush(stdout);
}

std::pair<std::array<float, 3>, std::array<float, 3>> mesh_scene::bounds() const {
  return buffers_->bounds();
}

}  // namespace viewer
