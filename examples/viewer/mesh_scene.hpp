// mesh_scene.hpp — a loaded polygon mesh as the viewer shows it: shaded flat, smooth, with a
// crease angle or with the file's normals, with its wireframe, boundary loops, non-manifold
// edges, normal glyphs and the doctor's findings on the file, each toggled by a key; a key runs
// the repair pipeline and shows its result with the doctor's findings on it. Every array comes
// from hw::render_buffers.
#ifndef HALFWING_VIEWER_MESH_SCENE_HPP
#define HALFWING_VIEWER_MESH_SCENE_HPP

#include <memory>
#include <string>

#include "findings_layer.hpp"
#include "gl_objects.hpp"
#include "halfwing.hpp"
#include "scene.hpp"

namespace viewer {

/// Boundary and non-manifold edges are highlights, wide and in colours the surface never takes:
/// the tests look for them in screenshots.
namespace styles {
constexpr line_style wireframe{{0.08f, 0.08f, 0.08f}, 1.2f};
constexpr line_style boundary{{1.0f, 0.0f, 1.0f}, 3.0f};      // magenta
constexpr line_style non_manifold{{0.0f, 1.0f, 1.0f}, 4.0f};  // cyan
constexpr line_style vertex_normals{{0.2f, 0.9f, 0.2f}, 1.5f};
constexpr line_style face_normals{{1.0f, 0.85f, 0.1f}, 1.5f};
}  // namespace styles

class mesh_scene : public scene {
 public:
  /// Reads a model (OBJ, OFF, PLY). Non-manifold input is repaired so it can be shown, and the
  /// diagnostic keeps the non-manifold edges to highlight. Throws hw::error.
  explicit mesh_scene(const std::string& path);

  void draw(const programs& with) const override;
  bool on_key(int key) override;
  bool on_click(double, double) override { return false; }
  std::string help() const override;
  std::string status() const override;
  std::pair<std::array<float, 3>, std::array<float, 3>> bounds() const override;

  /// What was loaded, for the console.
  std::string summary() const;

 private:
  /// Rebuilds the render buffers for the current shading and uploads them.
  void rebuild();
  /// Repairs the file (hw::repair_mesh with the default options) the first time, printing the
  /// counts before and after; then switches between the file and the repaired mesh.
  void toggle_repaired();
  /// The mesh shown: the file's, or the repaired one.
  const hw::mesh& shown_mesh() const { return show_repaired_ ? *repaired_ : mesh_; }
  const findings_layer& shown_findings() const {
    return show_repaired_ ? *repaired_findings_ : findings_;
  }

  std::string path_;
  hw::diagnostic report_;
  hw::mesh mesh_;
  hw_render_options options_ = hw_render_options_default();
  std::unique_ptr<hw::render_buffers> buffers_;
  std::unique_ptr<gpu_surface> surface_;
  std::unique_ptr<gpu_lines> wireframe_, boundary_, non_manifold_, vertex_normals_, face_normals_;
  findings_layer findings_;
  std::unique_ptr<hw::mesh> repaired_;
  std::unique_ptr<findings_layer> repaired_findings_;
  bool show_repaired_ = false;
  bool show_wireframe_ = true, show_boundary_ = true, show_non_manifold_ = true;
  bool show_vertex_normals_ = false, show_face_normals_ = false;
};

}  // namespace viewer

#endif
