#include "offscreen.h"

#include <stdio.h>
#include <stdlib.h>

#include "gl_core.h"
#include "png_write.h"

int offscreen_png(const char *path, int width, int height, void (*draw)(void *context, int width, int height),
                  void *context) {
    /* fbo[0] multisampled (colour + depth) is drawn into; fbo[1] single-sampled receives the
     * resolve, since glReadPixels cannot read a multisampled buffer. */
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
        fprintf(stderr, "offscreen framebuffer incomplete\n");
    } else if (pixels == NULL) {
        fprintf(stderr, "out of memory for a %dx%d screenshot\n", width, height);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
        draw(context, width, height);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo[1]);
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[1]);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels);
        if (glGetError() != GL_NO_ERROR) {
            fprintf(stderr, "OpenGL error while rendering the screenshot\n");
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
