// findings_layer.hpp — the mesh doctor's findings on a model file, drawn over the mesh: one key
// and one colour per kind of finding. Faces are outlined, edges drawn, vertices marked with a
// small cross; small components get their bounding box. Every array comes from
// hw::render_buffers::finding().
#ifndef HALFWING_VIEWER_FINDINGS_LAYER_HPP
#define HALFWING_VIEWER_FINDINGS_LAYER_HPP

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "gl_objects.hpp"
#include "halfwing.hpp"
#include "scene.hpp"

namespace viewer {

class findings_layer {
 public:
  /// Reads `path` as the file numbers it (nothing repaired) and examines it. Throws hw::error.
  explicit findings_layer(const std::string& path);

  /// Draws the shown kinds with the line program.
  void draw(GLuint line_program) const;
  /// Toggles the kind bound to `key`; false when no kind is.
  bool on_key(int key);
  /// A line per kind: its key, colour, name and item count.
  std::string help() const;
  /// The doctor's verdict and the kinds found, on a few lines.
  std::string summary() const;

 private:
  struct kind_layer {
    hw_doctor_finding kind;
    std::size_t n_items = 0;
    std::unique_ptr<gpu_lines> outlines, lines, crosses;
    bool shown = true;
  };
  std::vector<kind_layer> kinds_;
  hw::doctor_report report_;
};

}  // namespace viewer

#endif
