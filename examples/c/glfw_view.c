/* glfw_view.c — from a model file to pixels in C: read it with hw_mesh_read(), turn it into
 * GPU-ready arrays with hw_render_buffers_build(), upload them with glBufferData and draw them
 * with OpenGL 3.3 core (the seed's VBO/EBO slide, end to end).
 *
 *   glfw_view [model.obj|.off|.ply] [--screenshot out.png] [--size WxH] [--no-wireframe]
 *
 * Passes (shaders in ../shared/mesh_shader.c): the crease-shaded surface (an interleaved vertex
 * buffer and a uint32 element buffer), the wireframe (a GL_LINES array), and the boundary edges
 * in magenta on top, so holes show.
 * Interactive: drag with the left button to orbit, scroll to zoom, W toggles the wireframe,
 * Esc quits. With --screenshot it renders one frame offscreen, writes the PNG and exits, so it
 * runs headless under Xvfb with Mesa's llvmpipe.
 */
#include "gl_core.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_program.h"
#include "halfwing.h"
#include "mesh_shader.h"
#include "offscreen.h"
#include "orbit_camera.h"

#ifndef HALFWING_EXAMPLE_MODEL
#define HALFWING_EXAMPLE_MODEL "hole_capsule.off"
#endif

/* ---- the GPU side: one surface and a few line sets ------------------------------------------ */

/* The surface: a vertex array object binding one interleaved buffer (x y z nx ny nz per vertex)
 * to attributes 0 and 1, and the triangle element buffer. */
typedef struct {
    GLuint vao, vertices, triangles;
    GLsizei n_indices;
} gpu_surface;

/* A line set for glDrawArrays(GL_LINES): x y z per point, two points per segment. */
typedef struct {
    GLuint vao, points;
    GLsizei n_points;
} gpu_lines;

static int upload_surface(gpu_surface *gpu, const hw_render_buffers *buffers) {
    const float *vertices = NULL;
    const uint32_t *triangles = NULL;
    size_t n_floats = 0, n_indices = 0;
    size_t stride = hw_render_buffers_stride(buffers) * sizeof(float);
    if (hw_render_buffers_floats(buffers, HW_RENDER_FLOATS_INTERLEAVED, &vertices, &n_floats) !=
            HW_OK ||
        hw_render_buffers_indices(buffers, HW_RENDER_INDICES_TRIANGLES, &triangles, &n_indices) !=
            HW_OK ||
        stride == 0)
      return -1;
    glGenVertexArrays(1, &gpu->vao);
    glBindVertexArray(gpu->vao);
    glGenBuffers(1, &gpu->vertices);
    glBindBuffer(GL_ARRAY_BUFFER, gpu->vertices);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n_floats * sizeof(float)), vertices, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, (GLsizei)stride, (void *)0);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, (GLsizei)stride, (void *)(3 * sizeof(float)));
    glEnableVertexAttribArray(1);
    /* The element buffer binding is part of the VAO's state. */
    glGenBuffers(1, &gpu->triangles);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu->triangles);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(n_indices * sizeof(uint32_t)), triangles, GL_STATIC_DRAW);
    glBindVertexArray(0);
    gpu->n_indices = (GLsizei)n_indices;
    return 0;
}

static int upload_lines(gpu_lines *gpu, const hw_render_buffers *buffers, hw_render_floats which) {
    const float *points = NULL;
    size_t n_floats = 0;
    if (hw_render_buffers_floats(buffers, which, &points, &n_floats) != HW_OK) return -1;
    glGenVertexArrays(1, &gpu->vao);
    glBindVertexArray(gpu->vao);
    glGenBuffers(1, &gpu->points);
    glBindBuffer(GL_ARRAY_BUFFER, gpu->points);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n_floats * sizeof(float)), points, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), (void *)0);
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    gpu->n_points = (GLsizei)(n_floats / 3);
    return 0;
}

/* ---- drawing ------------------------------------------------------------------------------- */

typedef struct {
    GLuint surface_program, line_program;
    gpu_surface surface;
    gpu_lines wireframe, boundary;
    orbit_camera camera;
    int show_wireframe;
    int dragging;
    double last_x, last_y;
} view_state;

static void draw_lines(const view_state *s, const gpu_lines *lines, float width, float r, float g, float b) {
    glUniform1f(glGetUniformLocation(s->line_program, "line_width"), width);
    glUniform3f(glGetUniformLocation(s->line_program, "line_color"), r, g, b);
    glBindVertexArray(lines->vao);
    glDrawArrays(GL_LINES, 0, lines->n_points);
}

static void draw(void *context, int width, int height) {
    const view_state *s = context;
    float mvp[16], eye[3];
    orbit_camera_mvp(&s->camera, (float)width / (float)(height > 0 ? height : 1), mvp, eye);
    float light[3] = {eye[0] - s->camera.target[0], eye[1] - s->camera.target[1], eye[2] - s->camera.target[2]};
    float length = sqrtf(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);

    glViewport(0, 0, width, height);
    glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* The surface, pushed back a little so the lines on top are not lost to depth fighting. */
    glUseProgram(s->surface_program);
    glUniformMatrix4fv(glGetUniformLocation(s->surface_program, "mvp"), 1, GL_FALSE, mvp);
    glUniform3f(glGetUniformLocation(s->surface_program, "light_dir"), light[0] / length, light[1] / length,
                light[2] / length);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glBindVertexArray(s->surface.vao);
    glDrawElements(GL_TRIANGLES, s->surface.n_indices, GL_UNSIGNED_INT, (void *)0);
    glDisable(GL_POLYGON_OFFSET_FILL);

    /* The lines, widened to pixels by the geometry shader. */
    glUseProgram(s->line_program);
    glUniformMatrix4fv(glGetUniformLocation(s->line_program, "mvp"), 1, GL_FALSE, mvp);
    glUniform2f(glGetUniformLocation(s->line_program, "viewport"), (float)width, (float)height);
    if (s->show_wireframe) draw_lines(s, &s->wireframe, 1.2f, 0.08f, 0.08f, 0.08f);
    /* The boundary edges are wireframe edges too: LEQUAL lets the highlight win the depth tie. */
    glDepthFunc(GL_LEQUAL);
    draw_lines(s, &s->boundary, 3.0f, 1.0f, 0.0f, 1.0f);
    glDepthFunc(GL_LESS);
    glBindVertexArray(0);
}

/* ---- loading: file -> hw_mesh -> hw_render_buffers -> GPU ----------------------------------- */

static int report(const char *what, hw_status status) {
    char message[512];
    if (hw_last_error_message(message, sizeof message, NULL) != HW_OK) message[0] = '\0';
    fprintf(stderr, "glfw_view: %s: %s (%s)\n", what, hw_status_str(status), message);
    return -1;
}

static int load(view_state *s, const char *path) {
    hw_mesh *mesh = NULL;
    hw_render_buffers *buffers = NULL;
    hw_render_options options = hw_render_options_default();
    float lo[3], hi[3];
    hw_status status = hw_mesh_read(path, HW_BUILD_POLICY_REPAIR, &mesh, NULL);
    if (status != HW_OK) return report(path, status);
    options.shading = HW_SHADING_CREASE; /* smooth, but keep edges sharper than 30 degrees */
    options.interleaved = true;
    status = hw_render_buffers_build(mesh, NULL, &options, &buffers);
    if (status != HW_OK) {
        hw_mesh_free(mesh);
        return report("render buffers", status);
    }
    printf("glfw_view: %s: %zu vertices, %zu faces -> %zu render vertices\n", path, hw_mesh_n_vertices(mesh),
           hw_mesh_n_faces(mesh), hw_render_buffers_n_vertices(buffers));
    int rc = upload_surface(&s->surface, buffers) == 0 &&
                     upload_lines(&s->wireframe, buffers, HW_RENDER_FLOATS_WIREFRAME) == 0 &&
                     upload_lines(&s->boundary, buffers, HW_RENDER_FLOATS_BOUNDARY) == 0 &&
                     hw_render_buffers_bounds(buffers, lo, hi) == HW_OK
                 ? 0
                 : -1;
    if (rc == 0) orbit_camera_frame(&s->camera, lo, hi);
    /* glBufferData copied everything: the library's arrays and the mesh can go. */
    hw_render_buffers_free(buffers);
    hw_mesh_free(mesh);
    return rc;
}

static void release(view_state *s) {
    const gpu_lines *lines[2] = {&s->wireframe, &s->boundary};
    for (int i = 0; i < 2; ++i) {
        glDeleteBuffers(1, &lines[i]->points);
        glDeleteVertexArrays(1, &lines[i]->vao);
    }
    glDeleteBuffers(1, &s->surface.vertices);
    glDeleteBuffers(1, &s->surface.triangles);
    glDeleteVertexArrays(1, &s->surface.vao);
    glDeleteProgram(s->surface_program);
    glDeleteProgram(s->line_program);
}

/* ---- window and input ------------------------------------------------------------------------ */

static void on_key(GLFWwindow *window, int key, int scancode, int action, int mods) {
    view_state *s = glfwGetWindowUserPointer(window);
    (void)scancode, (void)mods;
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (key == GLFW_KEY_W) s->show_wireframe = !s->show_wireframe;
}

static void on_button(GLFWwindow *window, int button, int action, int mods) {
    view_state *s = glfwGetWindowUserPointer(window);
    (void)mods;
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    s->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(window, &s->last_x, &s->last_y);
}

static void on_cursor(GLFWwindow *window, double x, double y) {
    view_state *s = glfwGetWindowUserPointer(window);
    if (!s->dragging) return;
    orbit_camera_drag(&s->camera, x - s->last_x, y - s->last_y);
    s->last_x = x, s->last_y = y;
}

static void on_scroll(GLFWwindow *window, double dx, double dy) {
    view_state *s = glfwGetWindowUserPointer(window);
    (void)dx;
    orbit_camera_zoom(&s->camera, dy);
}

static void on_glfw_error(int code, const char *message) { fprintf(stderr, "glfw_view: GLFW error %d: %s\n", code, message); }

static int usage(const char *argv0) {
    fprintf(stderr, "usage: %s [model.obj|.off|.ply] [--screenshot out.png] [--size WxH] [--no-wireframe]\n", argv0);
    return 2;
}

int main(int argc, char **argv) {
    const char *shot = NULL, *path = HALFWING_EXAMPLE_MODEL;
    int width = 1024, height = 768;
    view_state state;
    memset(&state, 0, sizeof state);
    state.show_wireframe = 1;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--screenshot") && i + 1 < argc) shot = argv[++i];
        else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 16 || height < 16 || width > 8192 ||
                height > 8192)
                return usage(argv[0]);
        } else if (!strcmp(argv[i], "--no-wireframe")) state.show_wireframe = 0;
        else if (argv[i][0] != '-') path = argv[i];
        else return usage(argv[0]);
    }

    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) return 1;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    if (shot) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow *window = glfwCreateWindow(width, height, "halfwing - glfw_view", NULL, NULL);
    if (!window) {
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window, &state);

    int rc = 1;
    state.surface_program = gl_program_build(surface_vertex_shader, NULL, surface_fragment_shader);
    state.line_program = gl_program_build(line_vertex_shader, line_geometry_shader, line_fragment_shader);
    if (state.surface_program && state.line_program && load(&state, path) == 0) {
        if (shot) {
            rc = offscreen_png(shot, width, height, draw, &state) == 0 ? 0 : 1;
            if (rc == 0) printf("glfw_view: wrote %s (%dx%d) with %s\n", shot, width, height, glGetString(GL_RENDERER));
        } else {
            glfwSetKeyCallback(window, on_key);
            glfwSetMouseButtonCallback(window, on_button);
            glfwSetCursorPosCallback(window, on_cursor);
            glfwSetScrollCallback(window, on_scroll);
            printf("glfw_view: drag = orbit, scroll = zoom, W = wireframe, Esc = quit\n");
            fflush(stdout); /* shown now, also when stdout is a pipe */
            while (!glfwWindowShouldClose(window)) {
                int fb_width, fb_height;
                glfwGetFramebufferSize(window, &fb_width, &fb_height);
                draw(&state, fb_width, fb_height);
                glfwSwapBuffers(window);
                glfwWaitEvents();
            }
            rc = 0;
        }
    }
    release(&state);
    glfwDestroyWindow(window);
    glfwTerminate();
    return rc;
}
