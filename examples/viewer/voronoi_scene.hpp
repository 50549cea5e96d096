// voronoi_scene.hpp — a 2D Voronoi diagram as the viewer shows it: the cells clipped to a
// rectangle, filled one colour per site, with their outlines and the sites; clicks add sites and a
// key runs Lloyd steps. The fills and outlines come from hw::render_buffers::cells().
#ifndef HALFWING_VIEWER_VORONOI_SCENE_HPP
#define HALFWING_VIEWER_VORONOI_SCENE_HPP

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl_objects.hpp"
#include "halfwing.hpp"
#include "scene.hpp"

namespace viewer {

/// The cells' triangles with a colour per vertex (attributes 0: position, 1: colour).
class gpu_colored_surface {
 public:
  gpu_colored_surface(const hw::render_buffers& buffers, const std::vector<float>& colors);
  void draw() const;

 private:
  gl_vertex_array vao_;
  gl_buffer positions_, colors_, triangles_;
  GLsizei n_indices_ = 0;
};

class voronoi_scene : public scene {
 public:
  /// Starts with `n_sites` sites from a fixed-seed generator (the same picture every run). Needs
  /// a current OpenGL context (it builds its fill shader).
  explicit voronoi_scene(std::size_t n_sites = 40);
  ~voronoi_scene() override;
  voronoi_scene(const voronoi_scene&) = delete;
  voronoi_scene& operator=(const voronoi_scene&) = delete;

  void draw(const programs& with) const override;
  bool on_key(int key) override;
  bool on_click(double x, double y) override;
  std::string help() const override;
  std::string status() const override;
  std::pair<std::array<float, 3>, std::array<float, 3>> bounds() const override;

 private:
  /// Rebuilds the diagram, its cells and their buffers from the sites, and uploads them.
  void rebuild();
  /// Adds `n` sites from the generator.
  void add_random_sites(std::size_t n);
  /// The orthographic view of the rectangle for a viewport of this aspect: {centre, half size}.
  void view(float aspect, float& half_width, float& half_height) const;

  std::vector<hw::point2> sites_;
  uint64_t random_state_ = 2024;
  std::size_t n_cells_ = 0;
  unsigned lloyd_steps_ = 0;
  double last_move_ = 0;
  bool show_outlines_ = true, show_sites_ = true;
  GLuint fill_program_ = 0;
  mutable float aspect_ = 4.0f / 3.0f;  // of the last frame, to map clicks back to the plane
  std::unique_ptr<gpu_colored_surface> cells_;
  std::unique_ptr<gpu_lines> outlines_, site_marks_;
};

}  // namespace viewer

#endif
