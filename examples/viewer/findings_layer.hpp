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

/// An indexed face list: a file as it numbers it, or a mesh's faces.
struct face_list {
  std::vector<double> positions;
  std::vector<uint32_t> face_sizes, indices;

  /// The file at `path` as it numbers it (nothing repaired). Throws hw::error.
  static face_list read(const std::string& path);
  /// The faces of `mesh`, whose elements are numbered without gaps (as a repair leaves them).
  static face_list of(const hw::mesh& mesh);
};

class findings_layer {
 public:
  /// Examines `list` with the doctor. Throws hw::error.
  explicit findings_layer(const face_list& list);

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
