/* gl_program.h — compiles and links a vertex, optional geometry, and fragment shader, printing
 * the driver's log on failure. */
#ifndef HALFWING_EXAMPLES_GL_PROGRAM_H
#define HALFWING_EXAMPLES_GL_PROGRAM_H

#include "gl_core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The linked program, or 0 (after printing the compile or link log to stderr).
 * `geometry_source` may be NULL. */
GLuint gl_program_build(const char *vertex_source, const char *geometry_source, const char *fragment_source);

#ifdef __cplusplus
}
#endif

#endif
