#include "mesh_shader.h"

const char *const mesh_vertex_shader =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 normal;\n"
    "uniform mat4 mvp;\n"
    "out vec3 world_normal;\n"
    "void main() { world_normal = normal; gl_Position = mvp * vec4(position, 1.0); }\n";

/* Two-sided Lambert with a headlight: open meshes show their inside through the holes, in a
 * different colour so the boundary reads at a glance. */
const char *const mesh_fragment_shader =
    "#version 330 core\n"
    "in vec3 world_normal;\n"
    "uniform vec3 light_dir;\n"
    "uniform vec4 flat_color;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  if (flat_color.a > 0.0) { color = vec4(flat_color.rgb, 1.0); return; }\n"
    "  vec3 n = normalize(world_normal);\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  float lambert = max(dot(n, light_dir), 0.0);\n"
    "  vec3 base = gl_FrontFacing ? vec3(0.85, 0.62, 0.32) : vec3(0.45, 0.50, 0.60);\n"
    "  color = vec4(base * (0.2 + 0.8 * lambert), 1.0);\n"
    "}\n";
