/* png_content_check.c — checks that a screenshot shows something: reads a PNG (libpng) and
 * fails unless enough pixels differ from the background and, optionally, enough pixels have a
 * given highlight colour.
 *
 *   png_content_check image.png [--min-content FRACTION] [--color R,G,B --min-color-pixels N]
 *                     [--min-distinct-colors N]
 *
 * The background is the colour of the top-left pixel (the clear colour: models are framed with a
 * margin). A pixel is content when one channel differs from it by more than 24; it has the
 * highlight colour when every channel is within 40 of it (multisampled lines blend at their
 * edges, their centres keep the colour). --min-distinct-colors counts the colours (5 bits per
 * channel) other than the background that each cover at least 1% of the image — flat fills
 * such as Voronoi cells, not the blended edges between them — and fails below N.
 */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int near(const unsigned char *pixel, const int rgb[3], int tolerance) {
    for (int c = 0; c < 3; ++c)
        if (abs((int)pixel[c] - rgb[c]) > tolerance) return 0;
    return 1;
}

static int usage(void) {
    fprintf(stderr, "usage: png_content_check image.png [--min-content F] [--color R,G,B --min-color-pixels N] "
                    "[--min-distinct-colors N]\n");
    return 2;
}

int main(int argc, char **argv) {
    double min_content = 0.05;
    int color[3] = {0, 0, 0}, want_color = 0;
    long min_color_pixels = 0, min_distinct = 0;
    if (argc < 2) return usage();
    for (int i = 2; i < argc; ++i) {
        if (!strcmp(argv[i], "--min-content") && i + 1 < argc) min_content = atof(argv[++i]);
        else if (!strcmp(argv[i], "--color") && i + 1 < argc) {
            if (sscanf(argv[++i], "%d,%d,%d", &color[0], &color[1], &color[2]) != 3) return usage();
            want_color = 1;
        } else if (!strcmp(argv[i], "--min-color-pixels") && i + 1 < argc) min_color_pixels = atol(argv[++i]);
        else if (!strcmp(argv[i], "--min-distinct-colors") && i + 1 < argc) min_distinct = atol(argv[++i]);
        else return usage();
    }

    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, argv[1])) {
        fprintf(stderr, "png_content_check: %s: %s\n", argv[1], image.message);
        return 1;
    }
    image.format = PNG_FORMAT_RGB;
    unsigned char *pixels = malloc(PNG_IMAGE_SIZE(image));
    if (pixels == NULL || !png_image_finish_read(&image, NULL, pixels, 0, NULL)) {
        fprintf(stderr, "png_content_check: %s: %s\n", argv[1], pixels ? image.message : "out of memory");
        free(pixels);
        png_image_free(&image);
        return 1;
    }

    const int background[3] = {pixels[0], pixels[1], pixels[2]};
    const size_t n = (size_t)image.width * image.height;
    size_t content = 0, colored = 0;
    /* Pixels per colour, 5 bits per channel (32768 bins). */
    size_t *bins = calloc(32768, sizeof *bins);
    if (bins == NULL) {
        free(pixels);
        png_image_free(&image);
        return 1;
    }
    for (size_t i = 0; i < n; ++i) {
        const unsigned char *pixel = pixels + 3 * i;
        const int is_content = !near(pixel, background, 24);
        content += is_content;
        colored += want_color && near(pixel, color, 40);
        if (is_content) ++bins[(pixel[0] >> 3) << 10 | (pixel[1] >> 3) << 5 | pixel[2] >> 3];
    }
    free(pixels);
    long distinct = 0;
    for (size_t b = 0; b < 32768; ++b) distinct += bins[b] * 100 >= n; /* >= 1% of the image */
    free(bins);

    double fraction = (double)content / (double)n;
    printf("%s: %ux%u, background (%d, %d, %d), %.1f%% content", argv[1], image.width, image.height, background[0],
           background[1], background[2], 100.0 * fraction);
    if (want_color) printf(", %zu pixels near (%d, %d, %d)", colored, color[0], color[1], color[2]);
    printf(", %ld distinct colours over 1%% each\n", distinct);
    int ok = fraction >= min_content && (!want_color || (long)colored >= min_color_pixels) && distinct >= min_distinct;
    if (!ok) fprintf(stderr, "png_content_check: FAIL (need %.1f%% content, %ld highlight pixels, %ld colours)\n",
                     100.0 * min_content, min_color_pixels, min_distinct);
    return ok ? 0 : 1;
}
