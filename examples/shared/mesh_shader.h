/* mesh_shader.h — the GLSL 3.30 shaders the GLFW programs draw with: a lit surface program and a
 * wide-line program. */
#ifndef HALFWING_EXAMPLES_MESH_SHADER_H
#define HALFWING_EXAMPLES_MESH_SHADER_H

#ifdef __cplusplus
extern "C" {
#endif

/* Surface: attributes 0 = position, 1 = normal; uniforms `mvp` (mat4) and `light_dir` (unit
 * vec3 towards the light). Front faces are warm, back faces seen through holes cool. */
extern const char *const surface_vertex_shader;
extern const char *const surface_fragment_shader;

/* Lines of any width: a core profile draws GL_LINES one pixel wide only, so the geometry shader
 * turns each segment into a screen-space quad. Attribute 0 = position; uniforms `mvp`,
 * `viewport` (vec2, pixels), `line_width` (pixels) and `line_color` (vec3). */
extern const char *const line_vertex_shader;
extern const char *const line_geometry_shader;
extern const char *const line_fragment_shader;

#ifdef __cplusplus
}
#endif

#endif
