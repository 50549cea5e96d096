#include "mesh_shader.h"

const char *const surface_vertex_shader =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 normal;\n"
    "uniform mat4 mvp;\n"
    "out vec3 world_normal;\n"
    "void main() { world_normal = normal; gl_Position = mvp * vec4(position, 1.0); }\n";

/* Two-sided Lambert with a headlight: open meshes show their inside through the holes, in a
 * different colour so the boundary reads at a glance. */
const char *const surface_fragment_shader =
    "#version 330 core\n"
    "in vec3 world_normal;\n"
    "uniform vec3 light_dir;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  vec3 n = normalize(world_normal);\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  float lambert = max(dot(n, light_dir), 0.0);\n"
    "  vec3 base = gl_FrontFacing ? vec3(0.85, 0.62, 0.32) : vec3(0.45, 0.50, 0.60);\n"
    "  color = vec4(base * (0.2 + 0.8 * lambert), 1.0);\n"
    "}\n";

const char *const line_vertex_shader =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "uniform mat4 mvp;\n"
    "void main() { gl_Position = mvp * vec4(position, 1.0); }\n";

/* Offsets both ends sideways by half the width in pixels, converted back to clip space (times w,
 * so the offset survives the perspective divide). Segments behind the eye are dropped: their
 * screen direction is meaningless, and the clip planes keep the model in front anyway. */
const char *const line_geometry_shader =
    "#version 330 core\n"
    "layout(lines) in;\n"
    "layout(triangle_strip, max_vertices = 4) out;\n"
    "uniform vec2 viewport;\n"
    "uniform float line_width;\n"
    "void main() {\n"
    "  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;\n"
    "  if (a.w <= 0.0 || b.w <= 0.0) return;\n"
    "  vec2 half_viewport = 0.5 * viewport;\n"
    "  vec2 direction = b.xy / b.w * half_viewport - a.xy / a.w * half_viewport;\n"
    "  if (dot(direction, direction) < 1e-12) direction = vec2(1.0, 0.0);\n"
    "  vec2 side = normalize(vec2(-direction.y, direction.x)) * (0.5 * line_width) / half_viewport;\n"
    "  gl_Position = vec4(a.xy - side * a.w, a.zw); EmitVertex();\n"
    "  gl_Position = vec4(a.xy + side * a.w, a.zw); EmitVertex();\n"
    "  gl_Position = vec4(b.xy - side * b.w, b.zw); EmitVertex();\n"
    "  gl_Position = vec4(b.xy + side * b.w, b.zw); EmitVertex();\n"
    "  EndPrimitive();\n"
    "}\n";

const char *const line_fragment_shader =
    "#version 330 core\n"
    "uniform vec3 line_color;\n"
    "out vec4 color;\n"
    "void main() { color = vec4(line_color, 1.0); }\n";
