#include "gl_program.h"

#include <stdio.h>

static GLuint compile(GLenum kind, const char *source) {
    GLuint shader = glCreateShader(kind);
    GLint ok = 0;
    glShaderSource(shader, 1, &source, NULL);
    glCompileShader(shader);
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(shader, sizeof log, NULL, log);
        fprintf(stderr, "%s shader does not compile: %s\n",
                kind == GL_VERTEX_SHADER ? "vertex" : kind == GL_GEOMETRY_SHADER ? "geometry" : "fragment", log);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

GLuint gl_program_build(const char *vertex_source, const char *geometry_source, const char *fragment_source) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertex_source), fs = compile(GL_FRAGMENT_SHADER, fragment_source);
    GLuint gs = geometry_source ? compile(GL_GEOMETRY_SHADER, geometry_source) : 0;
    GLuint program = 0;
    GLint ok = 0;
    if (vs && fs && (gs || !geometry_source)) {
        program = glCreateProgram();
        glAttachShader(program, vs);
        if (gs) glAttachShader(program, gs);
        glAttachShader(program, fs);
        glLinkProgram(program);
        glGetProgramiv(program, GL_LINK_STATUS, &ok);
        if (!ok) {
            char log[2048];
            glGetProgramInfoLog(program, sizeof log, NULL, log);
            fprintf(stderr, "shader program does not link: %s\n", log);
            glDeleteProgram(program);
            program = 0;
        }
    }
    /* Deleting attached shaders only flags them: they live as long as the program. */
    if (vs) glDeleteShader(vs);
    if (gs) glDeleteShader(gs);
    if (fs) glDeleteShader(fs);
    return program;
}
