/* PNG / JPEG: PNGs built byte by byte from the PNG specification (chunks, CRC-32, a stored zlib
 * stream), round trips through our writers at 8 and 16 bits and 1-4 channels, conversions, and
 * bad inputs (not an image, truncated PNG, truncated JPEG). */
#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

static uint32_t crc32_png(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1)));
    }
    return c ^ 0xFFFFFFFFu;
}

static void put_be32(fx_buf *f, uint32_t v)
{
    unsigned char b[4] = {(unsigned char)(v >> 24), (unsigned char)(v >> 16), (unsigned char)(v >> 8), (unsigned char)v};
    fx_put(f, b, 4);
}

static void png_chunk(fx_buf *f, const char *type, const unsigned char *data, size_t n)
{
    put_be32(f, (uint32_t)n);
    size_t start = f->n;
    fx_put(f, type, 4);
    if (n) fx_put(f, data, n);
    put_be32(f, crc32_png(f->b + start, n + 4));
}

/* A PNG of w x h with the given colour type / depth, whose raw scanlines (filter byte 0 each) are
 * `raw`; IDAT is a zlib stream with one stored (uncompressed) deflate block (RFC 1950/1951). */
static void build_png(fx_buf *f, int w, int h, int depth, int ctype, const unsigned char *raw, size_t rawn,
                      const unsigned char *plte, size_t plten, const unsigned char *trns, size_t trnsn)
{
    fx_put(f, "\x89PNG\r\n\x1a\n", 8);
    unsigned char ihdr[13] = {0, 0, 0, (unsigned char)w, 0, 0, 0, (unsigned char)h, (unsigned char)depth,
                              (unsigned char)ctype, 0, 0, 0};
    png_chunk(f, "IHDR", ihdr, 13);
    if (plte) png_chunk(f, "PLTE", plte, plten);
    if (trns) png_chunk(f, "tRNS", trns, trnsn);
    fx_buf z = {0};
    fx_u8(&z, 0x78);
    fx_u8(&z, 0x01);
    fx_u8(&z, 0x01); /* BFINAL = 1, BTYPE = 00 (stored) */
    fx_u8(&z, (uint8_t)(rawn & 0xFF));
    fx_u8(&z, (uint8_t)(rawn >> 8));
    fx_u8(&z, (uint8_t)(~rawn & 0xFF));
    fx_u8(&z, (uint8_t)((~rawn >> 8) & 0xFF));
    fx_put(&z, raw, rawn);
    uint32_t a = 1, b = 0;
    for (size_t i = 0; i < rawn; i++) {
        a = (a + raw[i]) % 65521;
        b = (b + a) % 65521;
    }
    unsigned char ad[4] = {(unsigned char)(b >> 8), (unsigned char)b, (unsigned char)(a >> 8), (unsigned char)a};
    fx_put(&z, ad, 4);
    png_chunk(f, "IDAT", z.b, z.n);
    fx_free(&z);
    png_chunk(f, "IEND", NULL, 0);
}

static void test_handmade_png(void)
{
    const char *dir = test_tmpdir("io_image_hand");
    char p[1024];
    sp_error err = {0};
    sp_image img;
    /* 2x2 RGB 8-bit. */
    unsigned char raw[] = {0, 255, 0, 0, 0, 255, 0, /* row 0: red, green */
                           0, 0, 0, 255, 10, 20, 30}; /* row 1: blue, (10,20,30) */
    fx_buf f = {0};
    build_png(&f, 2, 2, 8, 2, raw, sizeof raw, NULL, 0, NULL, 0);
    fx_write_buf(fx_path(p, sizeof p, dir, "rgb8.png"), &f);
    fx_free(&f);
    CHECK_OK(sp_image_read(p, &img, &err), &err);
    CHECK(img.width == 2 && img.height == 2 && img.channels == 3 && img.bit_depth == 8);
    const unsigned char *d = img.data;
    CHECK(d[0] == 255 && d[1] == 0 && d[4] == 255 && d[8] == 255 && d[9] == 10 && d[10] == 20 && d[11] == 30);
    sp_image_free(&img);

    /* 2x1 grey 16-bit: PNG stores samples big-endian; we must return host-order 0x1234, 0xFFFE. */
    unsigned char raw16[] = {0, 0x12, 0x34, 0xFF, 0xFE};
    build_png(&f, 2, 1, 16, 0, raw16, sizeof raw16, NULL, 0, NULL, 0);
    fx_write_buf(fx_path(p, sizeof p, dir, "g16.png"), &f);
    fx_free(&f);
    CHECK_OK(sp_image_read(p, &img, &err), &err);
    CHECK(img.channels == 1 && img.bit_depth == 16);
    if (img.data) CHECK(((uint16_t *)img.data)[0] == 0x1234 && ((uint16_t *)img.data)[1] == 0xFFFE);
    float *rgb = NULL;
    CHECK_OK(sp_image_to_rgbf(&img, &rgb, &err), &err);
    if (rgb) {
        CHECK_NEAR(rgb[0], 0x1234 / 65535.0, 1e-7);
        CHECK_NEAR(rgb[2], 0x1234 / 65535.0, 1e-7); /* grey replicated */
        CHECK_NEAR(rgb[3], 0xFFFE / 65535.0, 1e-7);
    }
    free(rgb);
    sp_image_free(&img);

    /* 3x1 palette, 8-bit indices, entry 1 half transparent via tRNS -> RGBA. */
    unsigned char plte[] = {0, 0, 0, 200, 100, 50};
    unsigned char trns[] = {255, 128};
    unsigned char rawp[] = {0, 0, 1, 1};
    build_png(&f, 3, 1, 8, 3, rawp, sizeof rawp, plte, sizeof plte, trns, sizeof trns);
    fx_write_buf(fx_path(p, sizeof p, dir, "pal.png"), &f);
    fx_free(&f);
    CHECK_OK(sp_image_read(p, &img, &err), &err);
    CHECK(img.channels == 4 && img.bit_depth == 8 && img.width == 3);
    d = img.data;
    if (d) CHECK(d[3] == 255 && d[4] == 200 && d[5] == 100 && d[6] == 50 && d[7] == 128);
    CHECK_OK(sp_image_to_rgbf(&img, &rgb, &err), &err);
    if (rgb) CHECK_NEAR(rgb[3], 200 / 255.0, 1e-7); /* alpha dropped, RGB kept */
    free(rgb);
    sp_image_free(&img);
}

/* An Adam7-interlaced 13x11 RGB PNG written by libpng's own writer; byte k of the image is
 * (y * 39 + x) mod 256 for row y, byte x. */
static void test_interlaced_png(void)
{
    char p[1024];
    snprintf(p, sizeof p, "%s/tests/fixtures/io/adam7_rgb8_13x11.png", SP_SOURCE_DIR);
    sp_error err = {0};
    sp_image img;
    CHECK_OK(sp_image_read(p, &img, &err), &err);
    CHECK(img.width == 13 && img.height == 11 && img.channels == 3 && img.bit_depth == 8);
    int bad = 0;
    for (int y = 0; img.data && y < 11; y++)
        for (int x = 0; x < 39; x++) bad += ((unsigned char *)img.data)[y * 39 + x] != (unsigned char)(y * 39 + x);
    CHECK(img.data && bad == 0);
    sp_image_free(&img);
}

static void test_png_round_trip(void)
{
    const char *dir = test_tmpdir("io_image_rt");
    char p[1024];
    sp_error err = {0};
    test_rng rng = {42};
    for (int depth = 8; depth <= 16; depth += 8) {
        for (int c = 1; c <= 4; c++) {
            int w = 7, h = 5;
            size_t n = (size_t)w * h * c;
            void *data = malloc(n * (depth / 8));
            for (size_t i = 0; i < n; i++) {
                if (depth == 8) ((uint8_t *)data)[i] = (uint8_t)(test_uniform(&rng) * 256);
                else ((uint16_t *)data)[i] = (uint16_t)(test_uniform(&rng) * 65536);
            }
            sp_image img = {w, h, c, depth, data}, back;
            snprintf(p, sizeof p, "%s/rt_%d_%d.png", dir, depth, c);
            CHECK_OK(sp_image_write_png(p, &img, &err), &err);
            CHECK_OK(sp_image_read(p, &back, &err), &err);
            CHECK(back.width == w && back.height == h && back.channels == c && back.bit_depth == depth);
            CHECK(back.data && memcmp(back.data, data, n * (depth / 8)) == 0);
            sp_image_free(&back);
            free(data);
        }
    }
    /* Float writer: clamps to [0,1], NaN -> 0, rounds to nearest. */
    float px[6] = {0.0f, 0.5f, 1.0f, -3.0f, 7.0f, NAN};
    snprintf(p, sizeof p, "%s/f32.png", dir);
    CHECK_OK(sp_write_png_f32(p, px, 2, 1, 3, &err), &err);
    sp_image back;
    CHECK_OK(sp_image_read(p, &back, &err), &err);
    const unsigned char *d = back.data;
    if (d) CHECK(d[0] == 0 && d[1] == 128 && d[2] == 255 && d[3] == 0 && d[4] == 255 && d[5] == 0);
    sp_image_free(&back);
    /* No temporary file left behind. */
    snprintf(p, sizeof p, "ls %s | grep -q tmp", dir);
    CHECK(system(p) != 0);
}

static void test_jpeg(void)
{
    const char *dir = test_tmpdir("io_image_jpeg");
    char p[1024];
    sp_error err = {0};
    int w = 32, h = 16;
    for (int c = 1; c <= 4; c++) {
        unsigned char *data = malloc((size_t)w * h * c);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                for (int k = 0; k < c; k++) data[((size_t)y * w + x) * c + k] = (unsigned char)(40 + 3 * x + 2 * y + 30 * k);
        sp_image img = {w, h, c, 8, data}, back;
        snprintf(p, sizeof p, "%s/c%d.jpg", dir, c);
        CHECK_OK(sp_image_write_jpeg(p, &img, 95, &err), &err);
        CHECK_OK(sp_image_read(p, &back, &err), &err);
        int oc = c >= 3 ? 3 : 1;
        CHECK(back.width == w && back.height == h && back.channels == oc && back.bit_depth == 8);
        double maxd = 0;
        for (size_t i = 0; back.data && i < (size_t)w * h; i++)
            for (int k = 0; k < oc; k++) {
                double dv = fabs((double)((unsigned char *)back.data)[i * oc + k] - data[i * c + k]);
                if (dv > maxd) maxd = dv;
            }
        CHECK_MSG(maxd <= 6, "JPEG c=%d max abs error %g", c, maxd);
        sp_image_free(&back);
        free(data);
    }
    /* Truncated JPEG (cut inside the entropy-coded scan): libjpeg would pad with grey; we refuse. */
    char q[1024];
    unsigned char *noise = malloc(128 * 128 * 3);
    test_rng rng = {7};
    for (int i = 0; i < 128 * 128 * 3; i++) noise[i] = (unsigned char)(test_uniform(&rng) * 256);
    sp_image big = {128, 128, 3, 8, noise};
    snprintf(p, sizeof p, "%s/noise.jpg", dir);
    CHECK_OK(sp_image_write_jpeg(p, &big, 90, &err), &err);
    free(noise);
    snprintf(q, sizeof q, "%s/cut.jpg", dir);
    size_t n = 0;
    free(fx_slurp(p, &n));
    fx_truncate_copy(p, q, n * 3 / 4);
    sp_image img;
    CHECK_FAILS(sp_image_read(q, &img, &err), SP_E_FORMAT, &err, "cut.jpg");
    CHECK_MSG(strstr(err.msg, "truncated") != NULL, "%s", err.msg);
    fx_truncate_copy(p, q, 100); /* cut inside the headers */
    CHECK_FAILS(sp_image_read(q, &img, &err), SP_E_FORMAT, &err, "cut.jpg");
    sp_image bad = {w, h, 3, 8, NULL};
    CHECK_FAILS(sp_image_write_jpeg(q, &bad, 90, &err), SP_E_ARG, &err, "empty");
}

static void test_bad_images(void)
{
    const char *dir = test_tmpdir("io_image_bad");
    char p[1024], q[1024];
    sp_error err = {0};
    sp_image img;
    fx_write_text(fx_path(p, sizeof p, dir, "text.png"), "hello, not an image");
    CHECK_FAILS(sp_image_read(p, &img, &err), SP_E_FORMAT, &err, "neither a PNG nor a JPEG");
    CHECK(strstr(err.msg, "text.png") != NULL);
    CHECK_FAILS(sp_image_read(fx_path(p, sizeof p, dir, "missing.png"), &img, &err), SP_E_IO, &err, "missing.png");
    /* Truncated PNG: our own 16-bit file cut in the middle of IDAT. */
    uint16_t px[64 * 64];
    for (int i = 0; i < 64 * 64; i++) px[i] = (uint16_t)(i * 977);
    sp_image src = {64, 64, 1, 16, px};
    CHECK_OK(sp_image_write_png(fx_path(p, sizeof p, dir, "full.png"), &src, &err), &err);
    size_t n = 0;
    free(fx_slurp(p, &n));
    fx_truncate_copy(p, fx_path(q, sizeof q, dir, "cut.png"), n / 2);
    CHECK_FAILS(sp_image_read(q, &img, &err), SP_E_FORMAT, &err, "cut.png");
    CHECK(img.data == NULL);
    /* A PNG whose IHDR CRC is wrong. */
    unsigned char *b = fx_slurp(p, &n);
    b[29] ^= 0xFF;
    fx_write(fx_path(q, sizeof q, dir, "crc.png"), b, n);
    free(b);
    CHECK_FAILS(sp_image_read(q, &img, &err), SP_E_FORMAT, &err, "crc.png");
    sp_image five = {2, 2, 5, 8, px};
    CHECK_FAILS(sp_image_write_png(q, &five, &err), SP_E_ARG, &err, "5 channels");
}

int main(void)
{
    RUN(test_handmade_png);
    RUN(test_interlaced_png);
    RUN(test_png_round_trip);
    RUN(test_jpeg);
    RUN(test_bad_images);
    return TEST_EXIT();
}
