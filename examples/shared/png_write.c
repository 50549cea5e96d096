/* png_write.c — see png_write.h. PNG: ISO/IEC 15948; zlib: RFC 1950; stored deflate: RFC 1951 §3.2.4. */
#include "png_write.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A stored deflate block carries at most 65535 bytes. */
#define STORED_BLOCK_MAX 65535u
/* PNG chunk lengths must stay below 2^31. */
#define PNG_CHUNK_MAX 0x7fffffffu

static uint32_t crc_table[256];
static int crc_table_ready;

static void crc_init(void) {
    for (uint32_t n = 0; n < 256; ++n) {
        uint32_t c = n;
        for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
    crc_table_ready = 1;
}

static uint32_t crc_update(uint32_t crc, const unsigned char *bytes, size_t len) {
    for (size_t i = 0; i < len; ++i) crc = crc_table[(crc ^ bytes[i]) & 0xffu] ^ (crc >> 8);
    return crc;
}

static void put_be32(unsigned char *out, uint32_t v) {
    out[0] = (unsigned char)(v >> 24);
    out[1] = (unsigned char)(v >> 16);
    out[2] = (unsigned char)(v >> 8);
    out[3] = (unsigned char)v;
}

/* Writes one chunk: length, type, data, CRC of type and data. Returns 0 on success. */
static int write_chunk(FILE *f, const char type[4], const unsigned char *data, uint32_t len) {
    unsigned char header[8];
    unsigned char crc_bytes[4];
    put_be32(header, len);
    memcpy(header + 4, type, 4);
    uint32_t crc = crc_update(0xffffffffu, header + 4, 4);
    crc = crc_update(crc, data, len) ^ 0xffffffffu;
    put_be32(crc_bytes, crc);
    if (fwrite(header, 1, 8, f) != 8) return -1;
    if (len && fwrite(data, 1, len, f) != len) return -1;
    return fwrite(crc_bytes, 1, 4, f) == 4 ? 0 : -1;
}

/* Builds the zlib stream of the filtered scanlines (filter type 0 before every row). */
static unsigned char *zlib_stored(const unsigned char *rgb, unsigned width, unsigned height,
                                  size_t stride, int bottom_up, size_t *out_len) {
    size_t row_bytes = (size_t)width * 3u;
    size_t raw_len = (row_bytes + 1u) * height;
    size_t blocks = raw_len / STORED_BLOCK_MAX + (raw_len % STORED_BLOCK_MAX ? 1u : 0u);
    if (blocks == 0) blocks = 1;
    size_t total = 2u + raw_len + 5u * blocks + 4u;
    if (total > PNG_CHUNK_MAX) return NULL;

    unsigned char *raw = malloc(raw_len);
    unsigned char *z = malloc(total);
    if (!raw || !z) {
        free(raw);
        free(z);
        return NULL;
    }
    for (unsigned y = 0; y < height; ++y) {
        unsigned src_row = bottom_up ? height - 1u - y : y;
        unsigned char *dst = raw + (size_t)y * (row_bytes + 1u);
        dst[0] = 0;
        memcpy(dst + 1, rgb + (size_t)src_row * stride, row_bytes);
    }

    size_t at = 0;
    z[at++] = 0x78; /* CM = 8 (deflate), CINFO = 7 (32 KiB window) */
    z[at++] = 0x01; /* FLEVEL = 0, FCHECK makes 0x7801 a multiple of 31 */
    uint32_t adler_a = 1, adler_b = 0;
    size_t done = 0;
    do {
        size_t len = raw_len - done < STORED_BLOCK_MAX ? raw_len - done : STORED_BLOCK_MAX;
        int final = done + len == raw_len;
        z[at++] = (unsigned char)(final ? 1 : 0); /* BFINAL, BTYPE = 00 (stored) */
        z[at++] = (unsigned char)(len & 0xffu);
        z[at++] = (unsigned char)(len >> 8);
        z[at++] = (unsigned char)(~len & 0xffu);
        z[at++] = (unsigned char)((~len >> 8) & 0xffu);
        memcpy(z + at, raw + done, len);
        for (size_t i = 0; i < len; ++i) {
            adler_a = (adler_a + raw[done + i]) % 65521u;
            adler_b = (adler_b + adler_a) % 65521u;
        }
        at += len;
        done += len;
    } while (done < raw_len);
    put_be32(z + at, (adler_b << 16) | adler_a);
    at += 4;
    free(raw);
    *out_len = at;
    return z;
}

int png_write_rgb8(const char *path, const unsigned char *rgb, unsigned width, unsigned height,
                   size_t row_stride, int bottom_up) {
    if (!path || !rgb || width == 0 || height == 0 || width > PNG_CHUNK_MAX || height > PNG_CHUNK_MAX)
        return -1;
    size_t stride = row_stride ? row_stride : (size_t)width * 3u;
    if (stride < (size_t)width * 3u) return -1;
    if (!crc_table_ready) crc_init();

    size_t idat_len = 0;
    unsigned char *idat = zlib_stored(rgb, width, height, stride, bottom_up, &idat_len);
    if (!idat) return -1;

    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char ihdr[13];
    put_be32(ihdr, width);
    put_be32(ihdr + 4, height);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: truecolour RGB */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering */
    ihdr[12] = 0; /* no interlace */

    FILE *f = fopen(path, "wb");
    int failed = !f;
    if (!failed) {
        failed = fwrite(signature, 1, sizeof signature, f) != sizeof signature
                 || write_chunk(f, "IHDR", ihdr, sizeof ihdr)
                 || write_chunk(f, "IDAT", idat, (uint32_t)idat_len)
                 || write_chunk(f, "IEND", NULL, 0);
        failed = fclose(f) != 0 || failed;
        if (failed) remove(path);
    }
    free(idat);
    return failed ? -1 : 0;
}
