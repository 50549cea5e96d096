/* png_write.h — a small, dependency-free PNG writer for the halfwing examples and viewer.
 *
 * Writes 8-bit RGB images as valid PNG files: one IHDR, one IDAT holding a zlib stream of
 * stored (uncompressed) deflate blocks with its Adler-32, one IEND, every chunk with its CRC-32.
 * Files are larger than compressed PNGs but need no zlib, which keeps the examples self-contained.
 */
#ifndef HALFWING_EXAMPLES_PNG_WRITE_H
#define HALFWING_EXAMPLES_PNG_WRITE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes `rgb` (width * height pixels, 3 bytes each, rows `row_stride` bytes apart; 0 means
 * tightly packed) to `path`. With `bottom_up` non-zero the first row in memory is the bottom
 * of the image, as glReadPixels returns it.
 * Returns 0 on success, -1 on a bad argument, an image too large for PNG, or an I/O error
 * (errno tells which for I/O). A failed write leaves no half-written file behind. */
int png_write_rgb8(const char *path, const unsigned char *rgb, unsigned width, unsigned height,
                   size_t row_stride, int bottom_up);

#ifdef __cplusplus
}
#endif

#endif
