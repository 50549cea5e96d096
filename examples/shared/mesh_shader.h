/* mesh_shader.h — the GLSL 3.30 shader pair the GLFW programs draw meshes and lines with. */
#ifndef HALFWING_EXAMPLES_MESH_SHADER_H
#define HALFWING_EXAMPLES_MESH_SHADER_H

#ifdef __cplusplus
extern "C" {
#endif

/* Attributes: location 0 = position, 1 = normal. Uniforms: `mvp` (mat4), `light_dir` (unit
 * vec3, towards the light), `flat_color` (vec4: alpha > 0 draws everything in that colour, for
 * lines; alpha = 0 lights the surface, front faces warm, back faces seen through holes cool). */
extern const char *const mesh_vertex_shader;
extern const char *const mesh_fragment_shader;

#ifdef __cplusplus
}
#endif

#endif
