/* offscreen.h — renders one frame into an offscreen 4x multisampled framebuffer and writes it as a
 * PNG, so the GLFW programs can make screenshots headless (under Xvfb with Mesa's llvmpipe). */
#ifndef HALFWING_EXAMPLES_OFFSCREEN_H
#define HALFWING_EXAMPLES_OFFSCREEN_H

#ifdef __cplusplus
extern "C" {
#endif

/* Calls draw(context, width, height) with the offscreen framebuffer bound and writes the result
 * to `path`. Needs a current OpenGL 3.3 context. Returns 0, or -1 after printing why. */
int offscreen_png(const char *path, int width, int height, void (*draw)(void *context, int width, int height),
                  void *context);

#ifdef __cplusplus
}
#endif

#endif
