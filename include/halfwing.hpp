// halfwing.hpp — header-only C++17 wrapper over the halfwing C API (include/halfwing.h).
//
// Owning classes are move-only and free their object in the destructor; failures throw
// hw::error, which carries the hw_status and the library's message. Element ids stay the C
// structs (hw_vertex, hw_halfedge, hw_edge, hw_face).
#ifndef HALFWING_HPP
#define HALFWING_HPP

#include "halfwing.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hw {

/// A failed halfwing call: the status code and the detailed message of the failure.
class error : public std::runtime_error {
 public:
  error(hw_status status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  /// The C status code (never HW_OK).
  hw_status status() const noexcept { return status_; }

 private:
  hw_status status_;
};

/// The message of the last failed call on this thread (empty if none failed).
inline std::string last_error_message() {
  std::size_t needed = 0;
  hw_last_error_message(nullptr, 0, &needed);
  std::string message(needed, '\0');
  if (hw_last_error_message(&message[0], message.size(), &needed) != HW_OK) return {};
  message.resize(needed - 1);
  return message;
}

/// Throws hw::error when `status` is not HW_OK.
inline void check(hw_status status) {
  if (status != HW_OK) {
    std::string message = last_error_message();
    if (message.empty()) message = hw_status_str(status);
    throw error(status, message);
  }
}

/// The version of the linked library, e.g. "0.1.0".
inline std::string version() { return hw_version_string(); }

namespace detail {

/// A move-only owner of a C object released by `Free`.
template <class T, void (*Free)(T*)>
class owned {
 public:
  owned() noexcept = default;
  explicit owned(T* raw) noexcept : raw_(raw) {}
  owned(const owned&) = delete;
  owned& operator=(const owned&) = delete;
  owned(owned&& other) noexcept : raw_(std::exchange(other.raw_, nullptr)) {}
  owned& operator=(owned&& other) noexcept {
    if (this != &other) {
      Free(raw_);
      raw_ = std::exchange(other.raw_, nullptr);
    }
    return *this;
  }
  ~owned() { Free(raw_); }

  /// The C object, still owned by this wrapper.
  T* get() const noexcept { return raw_; }
  /// Gives up ownership: the caller must free the object.
  T* release() noexcept { return std::exchange(raw_, nullptr); }
  explicit operator bool() const noexcept { return raw_ != nullptr; }

 private:
  T* raw_ = nullptr;
};

}  // namespace detail

/// A half-edge polygon mesh (owns an hw_mesh).
class mesh {
 public:
  /// An empty mesh.
  mesh() : raw_(hw_mesh_new()) {
    if (!raw_) check(HW_ERR_PANIC);
  }

  /// Builds a mesh from positions (x, y, z per vertex), corners per face and the vertex index of
  /// every corner; see hw_mesh_from_indexed().
  static mesh from_indexed(const std::vector<double>& positions,
                           const std::vector<uint32_t>& face_sizes,
                           const std::vector<uint32_t>& indices,
                           hw_build_policy policy = HW_BUILD_STRICT) {
    if (positions.size() % 3 != 0)
      throw error(HW_ERR_INVALID_INPUT, "positions: size is not a multiple of 3 (x, y, z)");
    hw_mesh* raw = nullptr;
    check(hw_mesh_from_indexed(positions.data(), positions.size() / 3, face_sizes.data(),
                               face_sizes.size(), indices.data(), indices.size(), policy, &raw,
                               nullptr));
    return mesh(raw);
  }

  std::size_t n_vertices() const { return hw_mesh_n_vertices(get()); }
  std::size_t n_edges() const { return hw_mesh_n_edges(get()); }
  std::size_t n_halfedges() const { return hw_mesh_n_halfedges(get()); }
  std::size_t n_faces() const { return hw_mesh_n_faces(get()); }

  /// The C object, for calls the wrapper does not cover. Still owned by this mesh.
  hw_mesh* get() const noexcept { return raw_.get(); }
  explicit operator bool() const noexcept { return static_cast<bool>(raw_); }

 private:
  explicit mesh(hw_mesh* raw) : raw_(raw) {}
  detail::owned<hw_mesh, hw_mesh_free> raw_;
};

}  // namespace hw

#endif  // HALFWING_HPP
