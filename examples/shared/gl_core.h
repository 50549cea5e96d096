/* gl_core.h — the OpenGL 3.3 core declarations every GL file of the examples includes first.
 *
 * Mesa's libGL exports every OpenGL 3.3 entry point, so on Linux the prototypes of glcorearb.h
 * link directly and no loader library is needed. GLFW is told not to include any GL header itself.
 */
#ifndef HALFWING_EXAMPLES_GL_CORE_H
#define HALFWING_EXAMPLES_GL_CORE_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#define GLFW_INCLUDE_NONE 1
#include <GLFW/glfw3.h>

#endif
