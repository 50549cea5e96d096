// gl_objects.hpp — move-only owners of OpenGL objects, and the two shapes the viewer uploads:
// an indexed triangle surface and a GL_LINES point list, both straight from hw::render_buffers.
#ifndef HALFWING_VIEWER_GL_OBJECTS_HPP
#define HALFWING_VIEWER_GL_OBJECTS_HPP

#include <utility>

#include "gl_core.h"
#include "halfwing.hpp"

namespace viewer {

/// Owns one GL name created by `Gen` and deleted by `Del` (a buffer or a vertex array).
template <void (*Gen)(GLsizei, GLuint*), void (*Del)(GLsizei, const GLuint*)>
class gl_name {
 public:
  gl_name() { Gen(1, &name_); }
  gl_name(const gl_name&) = delete;
  gl_name& operator=(const gl_name&) = delete;
  gl_name(gl_name&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  gl_name& operator=(gl_name&& other) noexcept {
    std::swap(name_, other.name_);
    return *this;
  }
  ~gl_name() {
    if (name_ != 0) Del(1, &name_);
  }
  GLuint get() const noexcept { return name_; }

 private:
  GLuint name_ = 0;
};

// glGenBuffers & co. are functions in Mesa's libGL, so their addresses are constants.
using gl_buffer = gl_name<glGenBuffers, glDeleteBuffers>;
using gl_vertex_array = gl_name<glGenVertexArrays, glDeleteVertexArrays>;

/// Copies a view into a new GL_ARRAY_BUFFER bound to attribute `location` (`size` floats each).
template <class T>
inline void upload_attribute(const gl_buffer& buffer, const hw::values_view<const T>& data, GLuint location,
                             GLint size) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size_bytes()), data.data(),
               GL_STATIC_DRAW);
  glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(location);
}

/// The triangles of a render-buffer object: separate position and normal buffers (attributes 0
/// and 1) and the uint32 element buffer.
class gpu_surface {
 public:
  explicit gpu_surface(const hw::render_buffers& buffers) {
    glBindVertexArray(vao_.get());
    upload_attribute(positions_, buffers.floats(hw::RenderFloats::Positions), 0, 3);
    upload_attribute(normals_, buffers.floats(hw::RenderFloats::Normals), 1, 3);
    const auto triangles = buffers.indices(hw::RenderIndices::Triangles);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangles_.get());  // recorded in the VAO
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size_bytes()),
                 triangles.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    n_indices_ = static_cast<GLsizei>(triangles.size());
  }
  void draw() const {
    glBindVertexArray(vao_.get());
    glDrawElements(GL_TRIANGLES, n_indices_, GL_UNSIGNED_INT, nullptr);
  }

 private:
  gl_vertex_array vao_;
  gl_buffer positions_, normals_, triangles_;
  GLsizei n_indices_ = 0;
};

/// One line set of a render-buffer object, for glDrawArrays(GL_LINES).
class gpu_lines {
 public:
  gpu_lines(const hw::render_buffers& buffers, hw::RenderFloats which)
      : gpu_lines(buffers.floats(which)) {}
  /// x y z of two points per segment.
  explicit gpu_lines(const hw::values_view<const float>& points) {
    glBindVertexArray(vao_.get());
    upload_attribute(points_, points, 0, 3);
    glBindVertexArray(0);
    n_points_ = static_cast<GLsizei>(points.size() / 3);
  }
  void draw() const {
    if (n_points_ == 0) return;
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_LINES, 0, n_points_);
  }
  GLsizei n_segments() const { return n_points_ / 2; }

 private:
  gl_vertex_array vao_;
  gl_buffer points_;
  GLsizei n_points_ = 0;
};

}  // namespace viewer

#endif
