/* glfw_view.c — draw an indexed triangle mesh with OpenGL 3.3 core and GLFW, the path from
 * render buffers to pixels that the seed's VBO/EBO slide sketches.
 *
 * The mesh is a torus generated here in memory (positions, per-vertex normals, a uint32 triangle
 * index buffer and a uint32 line index buffer for the wireframe); the halfwing C API will provide
 * the same four arrays from a loaded model.
 *
 *   glfw_view [--screenshot out.png] [--size WxH] [--no-wireframe]
 *
 * Interactive: drag with the left button to orbit, scroll to zoom, W toggles the wireframe,
 * Esc quits. With --screenshot it renders one frame into an offscreen framebuffer (4x MSAA),
 * writes the PNG and exits, so it runs headless under Xvfb with Mesa's llvmpipe.
 *
 * Mesa's libGL exports every OpenGL 3.3 entry point, so no loader is needed on Linux.
 */
#define GL_GLEXT_PROTOTYPES 1
#define GLFW_INCLUDE_GLCOREARB 1
#include <GLFW/glfw3.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_write.h"

#define PI_F 3.14159265358979f

/* ---- the mesh: what the library's render buffers will provide ------------------------------ */

typedef struct {
    float *vertices;     /* interleaved x y z nx ny nz */
    uint32_t n_vertices;
    uint32_t *triangles; /* 3 indices per triangle */
    uint32_t n_triangle_indices;
    uint32_t *lines;     /* 2 indices per edge */
    uint32_t n_line_indices;
} render_mesh;

/* A torus about z: `around` segments around the axis, `tube` around the tube; quads are split in
 * two triangles, the wireframe shows the quad edges only. */
static int make_torus(render_mesh *m, float major, float minor, uint32_t around, uint32_t tube) {
    m->n_vertices = around * tube;
    m->n_triangle_indices = 6u * around * tube;
    m->n_line_indices = 4u * around * tube;
    m->vertices = malloc(sizeof(float) * 6u * m->n_vertices);
    m->triangles = malloc(sizeof(uint32_t) * m->n_triangle_indices);
    m->lines = malloc(sizeof(uint32_t) * m->n_line_indices);
    if (!m->vertices || !m->triangles || !m->lines) return -1;
    for (uint32_t j = 0; j < tube; ++j) {
        float v = 2.0f * PI_F * (float)j / (float)tube;
        for (uint32_t i = 0; i < around; ++i) {
            float u = 2.0f * PI_F * (float)i / (float)around;
            float *out = m->vertices + 6u * (j * around + i);
            float n[3] = {cosf(v) * cosf(u), cosf(v) * sinf(u), sinf(v)};
            out[0] = (major + minor * cosf(v)) * cosf(u);
            out[1] = (major + minor * cosf(v)) * sinf(u);
            out[2] = minor * sinf(v);
            memcpy(out + 3, n, sizeof n);
        }
    }
    uint32_t *t = m->triangles, *l = m->lines;
    for (uint32_t j = 0; j < tube; ++j) {
        for (uint32_t i = 0; i < around; ++i) {
            uint32_t a = j * around + i, b = j * around + (i + 1) % around;
            uint32_t c = ((j + 1) % tube) * around + (i + 1) % around, d = ((j + 1) % tube) * around + i;
            uint32_t tri[6] = {a, b, c, a, c, d}, edge[4] = {a, b, a, d};
            memcpy(t, tri, sizeof tri);
            memcpy(l, edge, sizeof edge);
            t += 6;
            l += 4;
        }
    }
    return 0;
}

static void free_mesh(render_mesh *m) {
    free(m->vertices);
    free(m->triangles);
    free(m->lines);
}

/* ---- column-major 4x4 matrices --------------------------------------------------------------- */

static void mat_mul(float out[16], const float a[16], const float b[16]) {
    float r[16];
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) {
            float s = 0.0f;
            for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
            r[c * 4 + row] = s;
        }
    memcpy(out, r, sizeof r);
}

static void perspective(float out[16], float fovy, float aspect, float znear, float zfar) {
    float f = 1.0f / tanf(fovy / 2.0f);
    memset(out, 0, 16 * sizeof(float));
    out[0] = f / aspect;
    out[5] = f;
    out[10] = (zfar + znear) / (znear - zfar);
    out[11] = -1.0f;
    out[14] = 2.0f * zfar * znear / (znear - zfar);
}

static void normalize3(float v[3]) {
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0f) v[0] /= len, v[1] /= len, v[2] /= len;
}

static void cross3(float out[3], const float a[3], const float b[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void look_at(float out[16], const float eye[3], const float target[3], const float up[3]) {
    float f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]}, s[3], u[3];
    normalize3(f);
    cross3(s, f, up);
    normalize3(s);
    cross3(u, s, f);
    float m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
                   -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]),
                   -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]),
                   f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2], 1};
    memcpy(out, m, sizeof m);
}

/* ---- orbit camera ---------------------------------------------------------------------------- */

typedef struct {
    float yaw, pitch, distance; /* radians, radians, world units from the target */
    float target[3];
    int dragging;
    double last_x, last_y;
} orbit_camera;

static void camera_eye(const orbit_camera *cam, float eye[3]) {
    eye[0] = cam->target[0] + cam->distance * cosf(cam->pitch) * cosf(cam->yaw);
    eye[1] = cam->target[1] + cam->distance * cosf(cam->pitch) * sinf(cam->yaw);
    eye[2] = cam->target[2] + cam->distance * sinf(cam->pitch);
}

/* ---- GL objects ------------------------------------------------------------------------------ */

static const char *vertex_src =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 normal;\n"
    "uniform mat4 mvp;\n"
    "out vec3 world_normal;\n"
    "void main() { world_normal = normal; gl_Position = mvp * vec4(position, 1.0); }\n";

/* Lambert with a headlight; `flat_color.a > 0` draws lines in that colour instead. */
static const char *fragment_src =
    "#version 330 core\n"
    "in vec3 world_normal;\n"
    "uniform vec3 light_dir;\n"
    "uniform vec3 base_color;\n"
    "uniform vec4 flat_color;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  if (flat_color.a > 0.0) { color = vec4(flat_color.rgb, 1.0); return; }\n"
    "  float lambert = max(dot(normalize(world_normal), light_dir), 0.0);\n"
    "  color = vec4(base_color * (0.15 + 0.85 * lambert), 1.0);\n"
    "}\n";

static GLuint compile(GLenum kind, const char *src) {
    GLuint s = glCreateShader(kind);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "glfw_view: shader compilation failed: %s\n", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static GLuint link_program(void) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertex_src), fs = compile(GL_FRAGMENT_SHADER, fragment_src);
    if (!vs || !fs) return 0;
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        fprintf(stderr, "glfw_view: program link failed: %s\n", log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

/* One VAO, one VBO, and two element buffers: triangles and wireframe lines. */
typedef struct {
    GLuint vao, vbo, triangle_ebo, line_ebo;
    GLsizei n_triangle_indices, n_line_indices;
} gpu_mesh;

static void upload(gpu_mesh *g, const render_mesh *m) {
    glGenVertexArrays(1, &g->vao);
    glBindVertexArray(g->vao);
    glGenBuffers(1, &g->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, g->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 6u * m->n_vertices), m->vertices, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void *)0);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void *)(3 * sizeof(float)));
    glEnableVertexAttribArray(1);
    glGenBuffers(1, &g->line_ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->line_ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof(uint32_t) * m->n_line_indices), m->lines, GL_STATIC_DRAW);
    /* The triangle buffer is bound last, so it is the VAO's default element buffer. */
    glGenBuffers(1, &g->triangle_ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->triangle_ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof(uint32_t) * m->n_triangle_indices), m->triangles,
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    g->n_triangle_indices = (GLsizei)m->n_triangle_indices;
    g->n_line_indices = (GLsizei)m->n_line_indices;
}

static void draw(GLuint program, const gpu_mesh *g, const orbit_camera *cam, int width, int height, int wireframe) {
    float eye[3], view[16], proj[16], mvp[16], up[3] = {0, 0, 1};
    camera_eye(cam, eye);
    look_at(view, eye, cam->target, up);
    perspective(proj, 45.0f * PI_F / 180.0f, (float)width / (float)(height > 0 ? height : 1), 0.05f, 100.0f);
    mat_mul(mvp, proj, view);
    float light[3] = {eye[0] - cam->target[0], eye[1] - cam->target[1], eye[2] - cam->target[2]};
    normalize3(light);

    glViewport(0, 0, width, height);
    glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "mvp"), 1, GL_FALSE, mvp);
    glUniform3fv(glGetUniformLocation(program, "light_dir"), 1, light);
    glUniform3f(glGetUniformLocation(program, "base_color"), 0.85f, 0.62f, 0.32f);
    glBindVertexArray(g->vao);

    /* Push the fill back a little so the wireframe on top is not lost to depth fighting. */
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glUniform4f(glGetUniformLocation(program, "flat_color"), 0, 0, 0, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->triangle_ebo);
    glDrawElements(GL_TRIANGLES, g->n_triangle_indices, GL_UNSIGNED_INT, (void *)0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    if (wireframe) {
        glUniform4f(glGetUniformLocation(program, "flat_color"), 0.1f, 0.1f, 0.1f, 1.0f);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->line_ebo);
        glDrawElements(GL_LINES, g->n_line_indices, GL_UNSIGNED_INT, (void *)0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->triangle_ebo);
    }
    glBindVertexArray(0);
}

/* Renders one frame into a 4x MSAA framebuffer, resolves it and writes it as a PNG. */
static int screenshot(const char *path, GLuint program, const gpu_mesh *g, const orbit_camera *cam, int width,
                      int height, int wireframe) {
    GLuint fbo[2], color[2], depth;
    glGenFramebuffers(2, fbo);
    glGenRenderbuffers(2, color);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, color[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    int complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindRenderbuffer(GL_RENDERBUFFER, color[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color[1]);
    complete = complete && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;

    int rc = -1;
    unsigned char *pixels = malloc((size_t)width * (size_t)height * 3u);
    if (!complete) {
        fprintf(stderr, "glfw_view: offscreen framebuffer incomplete\n");
    } else if (pixels) {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
        draw(program, g, cam, width, height, wireframe);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo[1]);
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[1]);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels);
        if (glGetError() != GL_NO_ERROR) {
            fprintf(stderr, "glfw_view: OpenGL error while rendering the screenshot\n");
        } else if (png_write_rgb8(path, pixels, (unsigned)width, (unsigned)height, 0, 1) != 0) {
            perror(path);
        } else {
            rc = 0;
        }
    }
    free(pixels);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(2, fbo);
    glDeleteRenderbuffers(2, color);
    glDeleteRenderbuffers(1, &depth);
    return rc;
}

/* ---- window and input ------------------------------------------------------------------------ */

typedef struct {
    orbit_camera camera;
    int wireframe;
} view_state;

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods) {
    (void)scancode, (void)mods;
    view_state *s = glfwGetWindowUserPointer(w);
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
    if (key == GLFW_KEY_W) s->wireframe = !s->wireframe;
}

static void on_button(GLFWwindow *w, int button, int action, int mods) {
    (void)mods;
    view_state *s = glfwGetWindowUserPointer(w);
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    s->camera.dragging = action == GLFW_PRESS;
    glfwGetCursorPos(w, &s->camera.last_x, &s->camera.last_y);
}

static void on_cursor(GLFWwindow *w, double x, double y) {
    view_state *s = glfwGetWindowUserPointer(w);
    if (!s->camera.dragging) return;
    s->camera.yaw -= (float)(x - s->camera.last_x) * 0.01f;
    s->camera.pitch += (float)(y - s->camera.last_y) * 0.01f;
    /* Stop short of the poles, where the up vector of look_at degenerates. */
    if (s->camera.pitch > 1.55f) s->camera.pitch = 1.55f;
    if (s->camera.pitch < -1.55f) s->camera.pitch = -1.55f;
    s->camera.last_x = x, s->camera.last_y = y;
}

static void on_scroll(GLFWwindow *w, double dx, double dy) {
    (void)dx;
    view_state *s = glfwGetWindowUserPointer(w);
    s->camera.distance *= powf(0.9f, (float)dy);
    if (s->camera.distance < 0.5f) s->camera.distance = 0.5f;
    if (s->camera.distance > 50.0f) s->camera.distance = 50.0f;
}

static void on_glfw_error(int code, const char *message) { fprintf(stderr, "glfw_view: GLFW error %d: %s\n", code, message); }

static int usage(const char *argv0) {
    fprintf(stderr, "usage: %s [--screenshot out.png] [--size WxH] [--no-wireframe]\n", argv0);
    return 2;
}

int main(int argc, char **argv) {
    const char *shot = NULL;
    int width = 1024, height = 768;
    view_state state = {{0.6f, 0.6f, 7.0f, {0, 0, 0}, 0, 0, 0}, 1};
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--screenshot") && i + 1 < argc) shot = argv[++i];
        else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 16 || height < 16 || width > 8192 ||
                height > 8192)
                return usage(argv[0]);
        } else if (!strcmp(argv[i], "--no-wireframe")) state.wireframe = 0;
        else return usage(argv[0]);
    }

    render_mesh mesh = {0};
    if (make_torus(&mesh, 2.0f, 0.7f, 48, 24) != 0) {
        fprintf(stderr, "glfw_view: out of memory\n");
        free_mesh(&mesh);
        return 1;
    }
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) {
        free_mesh(&mesh);
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    if (shot) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow *window = glfwCreateWindow(width, height, "halfwing — glfw_view", NULL, NULL);
    if (!window) {
        glfwTerminate();
        free_mesh(&mesh);
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window, &state);

    int rc = 1;
    GLuint program = link_program();
    if (program) {
        gpu_mesh gpu;
        upload(&gpu, &mesh);
        if (shot) {
            rc = screenshot(shot, program, &gpu, &state.camera, width, height, state.wireframe) == 0 ? 0 : 1;
            if (rc == 0) printf("glfw_view: wrote %s (%dx%d) with %s\n", shot, width, height, glGetString(GL_RENDERER));
        } else {
            glfwSetKeyCallback(window, on_key);
            glfwSetMouseButtonCallback(window, on_button);
            glfwSetCursorPosCallback(window, on_cursor);
            glfwSetScrollCallback(window, on_scroll);
            printf("glfw_view: drag = orbit, scroll = zoom, W = wireframe, Esc = quit\n");
            while (!glfwWindowShouldClose(window)) {
                int fb_width, fb_height;
                glfwGetFramebufferSize(window, &fb_width, &fb_height);
                draw(program, &gpu, &state.camera, fb_width, fb_height, state.wireframe);
                glfwSwapBuffers(window);
                glfwWaitEvents();
            }
            rc = 0;
        }
        glDeleteBuffers(1, &gpu.vbo);
        glDeleteBuffers(1, &gpu.triangle_ebo);
        glDeleteBuffers(1, &gpu.line_ebo);
        glDeleteVertexArrays(1, &gpu.vao);
        glDeleteProgram(program);
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    free_mesh(&mesh);
    return rc;
}
