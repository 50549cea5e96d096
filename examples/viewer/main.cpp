// halfwing viewer — opens an OBJ, OFF or PLY model (default: the bundled hole_capsule.off) and
// shows what halfwing knows about it: shading flat / smooth / by crease angle, the wireframe,
// boundary loops and non-manifold edges from the build diagnostic, vertex and face normals.
// V switches to a 2D Voronoi diagram (clicks add sites, L runs Lloyd steps) and back.
// Everything drawn comes from hw::render_buffers. GLFW + OpenGL 3.3 core, no other library.
//
//   halfwing_viewer [model] [--screenshot out.png] [--size WxH] [--keys KEYS] [--help]
//
// --screenshot renders one frame offscreen, writes the PNG and exits (headless under Xvfb).
// --keys presses keys before the first frame, as if typed (e.g. "1WN": flat shading, no
// wireframe, vertex normals; "VLL": the Voronoi diagram after two Lloyd steps), so every mode can
// be shot from a script.
#include "gl_core.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <system_error>
#include <string>

#include "gl_program.h"
#include "mesh_scene.hpp"
#include "mesh_shader.h"
#include "offscreen.h"
#include "orbit_camera.h"
#include "voronoi_scene.hpp"

#ifndef HALFWING_EXAMPLE_MODEL
#define HALFWING_EXAMPLE_MODEL "hole_capsule.off"
#endif
// Where an installed viewer finds its copy of the bundled model, relative to its own folder.
#ifndef HALFWING_INSTALLED_MODEL
#define HALFWING_INSTALLED_MODEL "../share/halfwing/hole_capsule.off"
#endif

namespace {

struct viewer_state {
  std::unique_ptr<viewer::scene> scene;
  std::unique_ptr<viewer::scene> other;  // the scene V switches to (the Voronoi one made on demand)
  viewer::programs programs{0, 0};
  orbit_camera camera{};
  bool dragging = false;
  double press_x = 0, press_y = 0, last_x = 0, last_y = 0;
};

void frame_scene(viewer_state& state) {
  const auto box = state.scene->bounds();
  orbit_camera_frame(&state.camera, box.first.data(), box.second.data());
}

void print_help(const viewer_state& state) {
  std::printf(
      "halfwing viewer keys:\n"
      "  drag       orbit (left button)\n"
      "  scroll     zoom\n"
      "  R          reset the camera\n"
      "  V          switch between the mesh and a 2D Voronoi diagram\n"
      "%s"
      "  H          this help\n"
      "  Esc / Q    quit\n",
      state.scene->help().c_str());
  std::fflush(stdout);  // shown now, also when stdout is a pipe
}

void draw(void* context, int width, int height) {
  const auto& state = *static_cast<const viewer_state*>(context);
  float mvp[16], eye[3], light[3], length = 0;
  orbit_camera_mvp(&state.camera, float(width) / float(height > 0 ? height : 1), mvp, eye);
  for (int axis = 0; axis < 3; ++axis) {
    light[axis] = eye[axis] - state.camera.target[axis];
    length += light[axis] * light[axis];
  }
  for (float& c : light) c /= std::sqrt(length);

  glViewport(0, 0, width, height);
  glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const GLuint surface = state.programs.surface, lines = state.programs.lines;
  glUseProgram(surface);
  glUniformMatrix4fv(glGetUniformLocation(surface, "mvp"), 1, GL_FALSE, mvp);
  glUniform3fv(glGetUniformLocation(surface, "light_dir"), 1, light);
  glUseProgram(lines);
  glUniformMatrix4fv(glGetUniformLocation(lines, "mvp"), 1, GL_FALSE, mvp);
  glUniform2f(glGetUniformLocation(lines, "viewport"), float(width), float(height));
  state.scene->draw(state.programs);
}

viewer_state& state_of(GLFWwindow* window) {
  return *static_cast<viewer_state*>(glfwGetWindowUserPointer(window));
}

void on_key(GLFWwindow* window, int key, int, int action, int) {
  viewer_state& state = state_of(window);
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) {
    glfwSetWindowShouldClose(window, GLFW_TRUE);
  } else if (key == GLFW_KEY_H) {
    print_help(state);
  } else if (key == GLFW_KEY_R) {
    frame_scene(state);
  } else if (key == GLFW_KEY_V) {
    try {
      if (!state.other) state.other = std::make_unique<viewer::voronoi_scene>();
      std::swap(state.scene, state.other);
      frame_scene(state);
      std::printf("%s\n", state.scene->status().c_str());
      print_help(state);
    } catch (const std::exception& failure) {
      std::fprintf(stderr, "halfwing_viewer: %s\n", failure.what());
    }
  } else {
    try {
      if (state.scene->on_key(key)) {
        std::printf("%s\n", state.scene->status().c_str());
        std::fflush(stdout);
      }
    } catch (const hw::error& failure) {
      std::fprintf(stderr, "halfwing_viewer: %s\n", failure.what());
    }
  }
}

void on_button(GLFWwindow* window, int button, int action, int) {
  viewer_state& state = state_of(window);
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  state.dragging = action == GLFW_PRESS;
  if (action == GLFW_PRESS) {
    state.press_x = state.last_x = x, state.press_y = state.last_y = y;
  } else if (std::fabs(x - state.press_x) + std::fabs(y - state.press_y) < 3) {
    // A click, not a drag: the scene may use it (the Voronoi scene adds a site).
    int width = 0, height = 0;
    glfwGetWindowSize(window, &width, &height);
    if (width <= 0 || height <= 0) return;
    try {
      if (state.scene->on_click(x / width, y / height)) {
        std::printf("%s\n", state.scene->status().c_str());
        std::fflush(stdout);
      }
    } catch (const hw::error& failure) {
      std::fprintf(stderr, "halfwing_viewer: %s\n", failure.what());
    }
  }
}

void on_cursor(GLFWwindow* window, double x, double y) {
  viewer_state& state = state_of(window);
  if (!state.dragging) return;
  orbit_camera_drag(&state.camera, x - state.last_x, y - state.last_y);
  state.last_x = x, state.last_y = y;
}

void on_scroll(GLFWwindow* window, double, double dy) { orbit_camera_zoom(&state_of(window).camera, dy); }

void on_glfw_error(int code, const char* message) {
  std::fprintf(stderr, "halfwing_viewer: GLFW error %d: %s\n", code, message);
}

void print_usage(std::FILE* to, const char* argv0) {
  std::fprintf(to, "usage: %s [model.obj|.off|.ply] [--screenshot out.png] [--size WxH] [--keys KEYS]\n",
               argv0);
}

int usage(const char* argv0) {
  print_usage(stderr, argv0);
  return 2;
}

int help(const char* argv0) {
  print_usage(stdout, argv0);
  std::printf(
      "Opens the model (default: the bundled capsule) in a window; H there lists the keys.\n"
      "  --screenshot out.png  render one frame offscreen, write it as a PNG and exit\n"
      "  --size WxH            window or screenshot size (default 1024x768)\n"
      "  --keys KEYS           keys pressed before the first frame, as if typed (e.g. VLL)\n"
      "  --help                this text\n");
  return 0;
}

/// The bundled model: the installed copy beside an installed viewer, else the source tree's.
std::string default_model() {
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const auto installed = self.parent_path() / HALFWING_INSTALLED_MODEL;
    if (std::filesystem::is_regular_file(installed, error)) return installed.string();
  }
  return HALFWING_EXAMPLE_MODEL;
}

/// Creates the window and its OpenGL 3.3 core context (hidden for screenshots).
GLFWwindow* open_window(int width, int height, bool visible) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(width, height, "halfwing viewer", nullptr, nullptr);
  if (window) {
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
  }
  return window;
}

/// Presses the keys of `keys` in order. GLFW's key codes of letters, digits and brackets are their
/// upper-case ASCII codes.
void press_keys(GLFWwindow* window, const std::string& keys) {
  for (char key : keys)
    on_key(window, std::toupper(static_cast<unsigned char>(key)), 0, GLFW_PRESS, 0);
}

int run(GLFWwindow* window, viewer_state& state, const std::string& model, const char* shot, int width,
        int height, const std::string& keys) {
  state.programs.surface = gl_program_build(surface_vertex_shader, nullptr, surface_fragment_shader);
  state.programs.lines = gl_program_build(line_vertex_shader, line_geometry_shader, line_fragment_shader);
  if (state.programs.surface == 0 || state.programs.lines == 0) return 1;
  auto scene = std::make_unique<viewer::mesh_scene>(model);
  std::printf("%s\n", scene->summary().c_str());
  state.scene = std::move(scene);
  frame_scene(state);
  glfwSetWindowUserPointer(window, &state);
  press_keys(window, keys);
  if (shot) {
    if (offscreen_png(shot, width, height, draw, &state) != 0) return 1;
    std::printf("halfwing_viewer: wrote %s (%dx%d) with %s\n", shot, width, height,
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    return 0;
  }
  glfwSetKeyCallback(window, on_key);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetScrollCallback(window, on_scroll);
  print_help(state);
  while (!glfwWindowShouldClose(window)) {
    int fb_width = 0, fb_height = 0;
    glfwGetFramebufferSize(window, &fb_width, &fb_height);
    draw(&state, fb_width, fb_height);
    glfwSwapBuffers(window);
    glfwWaitEvents();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string model;
  const char* shot = nullptr;
  std::string keys;
  int width = 1024, height = 768;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--screenshot") && i + 1 < argc) {
      shot = argv[++i];
    } else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 16 || height < 16 ||
          width > 8192 || height > 8192)
        return usage(argv[0]);
    } else if (!std::strcmp(argv[i], "--keys") && i + 1 < argc) {
      keys = argv[++i];
    } else if (!std::strcmp(argv[i], "--help")) {
      return help(argv[0]);
    } else if (argv[i][0] != '-') {
      model = argv[i];
    } else {
      return usage(argv[0]);
    }
  }
  if (model.empty()) model = default_model();

  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) return 1;
  GLFWwindow* window = open_window(width, height, shot == nullptr);
  if (!window) {
    glfwTerminate();
    return 1;
  }
  int rc = 1;
  {
    viewer_state state;  // its GL objects go before the context does
    try {
      rc = run(window, state, model, shot, width, height, keys);
    } catch (const std::exception& failure) {
      std::fprintf(stderr, "halfwing_viewer: %s\n", failure.what());
    }
    glDeleteProgram(state.programs.surface);  // 0 is ignored
    glDeleteProgram(state.programs.lines);
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return rc;
}
