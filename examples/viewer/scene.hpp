// scene.hpp — what the viewer shows: something that draws itself for a camera, reacts to keys and
// clicks, and lists its keys: the mesh scene (mesh_scene.hpp) and the Voronoi scene
// (voronoi_scene.hpp: clicks add sites, a key runs Lloyd steps, cells filled from
// hw::render_buffers::cells()).
#ifndef HALFWING_VIEWER_SCENE_HPP
#define HALFWING_VIEWER_SCENE_HPP

#include <array>
#include <string>
#include <utility>

#include "gl_core.h"

namespace viewer {

/// The shader programs of ../shared/mesh_shader.h, with the per-frame uniforms (mvp, light,
/// viewport) already set.
struct programs {
  GLuint surface;
  GLuint lines;
};

/// How a line set looks.
struct line_style {
  std::array<float, 3> color;
  float width;  // pixels
};

class scene {
 public:
  virtual ~scene() = default;
  /// Draws the scene; it selects the program of each pass itself.
  virtual void draw(const programs& with) const = 0;
  /// Handles a key press; returns true when it changed what is drawn.
  virtual bool on_key(int key) = 0;
  /// Handles a left click at (x, y), fractions of the window's width and height from its top-left
  /// corner; returns true when it changed what is drawn.
  virtual bool on_click(double x, double y) = 0;
  /// One line per key the scene understands.
  virtual std::string help() const = 0;
  /// What is shown right now (mode, toggles), for the console.
  virtual std::string status() const = 0;
  /// The box to frame: {min, max}.
  virtual std::pair<std::array<float, 3>, std::array<float, 3>> bounds() const = 0;
};

}  // namespace viewer

#endif
