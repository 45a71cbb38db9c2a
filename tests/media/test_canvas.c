/* media: text layout against a fake measure (wrapping, breaks, ellipsis, UTF-8 cleaning), and the
 * Cairo canvas, cards and bar charts checked on their pixels and the PNGs they write. */
#include "media/media_internal.h"
#include "semsplat/io.h"
#include "semsplat/media.h"
#include "test.h"

/* 10 px per code point. */
static double fake_width(void *ctx, const char *s, size_t n)
{
    (void)ctx;
    double w = 0;
    for (size_t i = 0; i < n; i++) w += ((unsigned char)s[i] & 0xc0) != 0x80 ? 10 : 0;
    return w;
}

static void test_layout_wraps(void)
{
    media_lines L;
    CHECK(media_layout("the quick brown fox jumps", 100, 0, fake_width, NULL, &L) == 0);
    CHECK(L.n == 3);
    if (L.n == 3) {
        CHECK(!strcmp(L.line[0], "the quick"));
        CHECK(!strcmp(L.line[1], "brown fox"));
        CHECK(!strcmp(L.line[2], "jumps"));
    }
    media_lines_free(&L);
    /* every line fits, none loses a word */
    CHECK(media_layout("a bb ccc dddd eeeee ffffff ggggggg", 75, 0, fake_width, NULL, &L) == 0);
    size_t total = 0;
    for (int i = 0; i < L.n; i++) {
        CHECK(fake_width(NULL, L.line[i], strlen(L.line[i])) <= 75);
        for (const char *q = L.line[i]; *q; q++) total += *q != ' ';
    }
    CHECK(total == strlen("abbcccddddeeeeeffffffggggggg"));
    media_lines_free(&L);
    /* newlines always break, blank paragraphs stay */
    CHECK(media_layout("one\n\ntwo", 0, 0, fake_width, NULL, &L) == 0);
    CHECK(L.n == 3 && !strcmp(L.line[1], "") && !strcmp(L.line[2], "two"));
    media_lines_free(&L);
}

static void test_layout_long_words_and_ellipsis(void)
{
    media_lines L;
    CHECK(media_layout("abcdefghijklmnopqrstuvwxy", 100, 0, fake_width, NULL, &L) == 0);
    CHECK(L.n == 3 && !strcmp(L.line[0], "abcdefghij") && !strcmp(L.line[2], "uvwxy"));
    media_lines_free(&L);
    /* a multi-byte word is broken between code points, never inside one */
    CHECK(media_layout("\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9", 25, 0, fake_width, NULL, &L) == 0);
    CHECK(L.n == 2 && !strcmp(L.line[0], "\xc3\xa9\xc3\xa9"));
    media_lines_free(&L);
    CHECK(media_layout("one two three four five six", 90, 2, fake_width, NULL, &L) == 0);
    CHECK(L.n == 2);
    if (L.n == 2) {
        size_t n = strlen(L.line[1]);
        CHECK(n >= 3 && !strcmp(L.line[1] + n - 3, "..."));
        CHECK(fake_width(NULL, L.line[1], n) <= 90);
    }
    media_lines_free(&L);
    /* a width smaller than one character still makes progress */
    CHECK(media_layout("abc", 5, 0, fake_width, NULL, &L) == 0);
    CHECK(L.n == 3);
    media_lines_free(&L);
}

static void test_sanitize(void)
{
    char *s = media_sanitize("ok\t\x01\xff\xc3(\xed\xa0\x80\xf4\x90\x80\x80\xe2\x82\xac\xc2\x85!");
    CHECK(s != NULL);
    /* tab -> space; control, 0xff, truncated lead, surrogate, > U+10FFFF, C1 -> '?'; euro stays */
    if (s) CHECK_MSG(!strcmp(s, "ok ???" "(" "???????" "\xe2\x82\xac" "?" "!"), "got '%s'", s);
    free(s);
}

static long count_pixels(const uint8_t *rgb, int w, int x0, int y0, int x1, int y1,
                         int (*pred)(const uint8_t *))
{
    long n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) n += pred(rgb + ((size_t)y * w + x) * 3);
    return n;
}
static int not_white(const uint8_t *p) { return p[0] < 200 || p[1] < 200 || p[2] < 200; }
static int bright(const uint8_t *p) { return p[0] > 200 && p[1] > 200 && p[2] > 200; }
static int reddish(const uint8_t *p) { return p[0] > 200 && p[1] < 60 && p[2] < 60; }

static sp_canvas *make(int w, int h)
{
    sp_error err = {0};
    sp_canvas *c = NULL;
    int rc = sp_canvas_create(&c, w, h, &err);
    if (rc == SP_E_UNSUPPORTED) TEST_SKIP("built without Cairo");
    CHECK_MSG(rc == 0, "%s", err.msg);
    return c;
}

static void test_canvas_shapes_images_text(void)
{
    sp_canvas *c = make(320, 200);
    if (!c) return;
    sp_error err = {0};
    uint8_t *rgb = malloc(320 * 200 * 3);
    sp_canvas_rgb(c, rgb);
    CHECK(count_pixels(rgb, 320, 0, 0, 320, 200, not_white) == 0);
    sp_canvas_rect(c, 10, 10, 20, 20, sp_rgba_of(1, 0, 0, 1), sp_rgba_of(0, 0, 0, 0), 0);
    /* a 4x2 red image scaled into a 100x100 box: 100x50, centred vertically */
    uint8_t img[4 * 2 * 3];
    for (int i = 0; i < 8; i++) { img[3 * i] = 255; img[3 * i + 1] = 0; img[3 * i + 2] = 0; }
    float placed[4];
    CHECK_OK(sp_canvas_image(c, img, 4, 2, 200, 50, 100, 100, placed, &err), &err);
    CHECK_NEAR(placed[0], 200, 1e-3);
    CHECK_NEAR(placed[1], 75, 1e-3);
    CHECK_NEAR(placed[2], 100, 1e-3);
    CHECK_NEAR(placed[3], 50, 1e-3);
    sp_text_style ts = {.size_px = 20};
    float h = sp_canvas_text(c, 10, 120, &ts, "Hello, robot");
    CHECK_NEAR(h, 26, 1e-3);
    sp_canvas_rgb(c, rgb);
    CHECK(count_pixels(rgb, 320, 12, 12, 28, 28, reddish) == 16 * 16);
    CHECK(count_pixels(rgb, 320, 205, 80, 295, 120, reddish) == 90 * 40);
    CHECK(count_pixels(rgb, 320, 205, 55, 295, 70, reddish) == 0);
    CHECK(count_pixels(rgb, 320, 10, 100, 160, 126, not_white) > 100); /* the text has ink */
    CHECK(count_pixels(rgb, 320, 10, 130, 160, 200, not_white) == 0);
    /* bad strings do not break the context: later drawing still works */
    sp_canvas_text(c, 10, 160, &ts, "\xff\xfe bad \x01 bytes");
    sp_canvas_rect(c, 300, 180, 10, 10, sp_rgba_of(1, 0, 0, 1), sp_rgba_of(0, 0, 0, 0), 0);
    sp_canvas_rgb(c, rgb);
    CHECK(count_pixels(rgb, 320, 300, 180, 310, 190, reddish) == 100);
    CHECK_FAILS(sp_canvas_image(c, NULL, 4, 2, 0, 0, 10, 10, NULL, &err), SP_E_ARG, &err, "NULL");
    CHECK_FAILS(sp_canvas_image(c, img, 4, 2, 0, 0, 0, 10, NULL, &err), SP_E_ARG, &err, "box");
    free(rgb);
    sp_canvas_free(c);
    CHECK_FAILS(sp_canvas_create(&c, 0, 10, &err), SP_E_ARG, &err, "0x10");
}

static void test_cards_and_png(void)
{
    sp_canvas *c = make(1280, 720);
    if (!c) return;
    sp_error err = {0};
    sp_media_title_card(c, "semsplat", "three commands, end to end", "house.world");
    uint8_t *rgb = malloc(1280 * 720 * 3);
    sp_canvas_rgb(c, rgb);
    long title_ink = count_pixels(rgb, 1280, 340, 240, 940, 340, bright);
    CHECK_MSG(title_ink > 2000, "title ink %ld", title_ink); /* white letters on dark */
    sp_canvas_clear(c, sp_rgba_of(1, 1, 1, 1));
    float band = sp_media_caption(c, "go to the refrigerator: 3 trajectories, the best 6.2 m");
    CHECK(band > 24 && band < 200);
    sp_canvas_rgb(c, rgb);
    CHECK(count_pixels(rgb, 1280, 0, 0, 1280, 720 - (int)band - 1, not_white) == 0);
    CHECK(count_pixels(rgb, 1280, 40, 720 - (int)band + 2, 600, 718, bright) > 500);
    char png[1200];
    snprintf(png, sizeof png, "%s/card.png", test_tmpdir("media_card"));
    CHECK_OK(sp_canvas_write_png(c, png, &err), &err);
    sp_image im = {0};
    CHECK_OK(sp_image_read(png, &im, &err), &err);
    CHECK(im.width == 1280 && im.height == 720 && im.channels == 3);
    if (im.data && im.width == 1280) CHECK(!memcmp(im.data, rgb, 1280 * 720 * 3));
    sp_image_free(&im);
    free(rgb);
    sp_canvas_free(c);
}

static void test_plot(void)
{
    sp_canvas *probe = make(8, 8);
    if (!probe) return;
    sp_canvas_free(probe);
    sp_error err = {0};
    const char *cats[] = {"refrigerator", "bed", "sofa", "tv"};
    double v3d[] = {0.12, 0.40, NAN, 0.05}, vmv[] = {0.20, 0.33, 0.61, NAN};
    uint8_t miss3d[] = {0, 0, 1, 0}, missmv[] = {0, 0, 0, 1};
    sp_plot_series se[2] = {{.name = "3D", .values = v3d, .missed = miss3d},
                            {.name = "multi-view", .values = vmv, .missed = missmv}};
    sp_plot_bars p = {.title = "Localization error per object", .x_label = "error (m)",
                      .n_categories = 4, .categories = cats, .n_series = 2, .series = se,
                      .ref_value = 0.5, .ref_label = "match radius"};
    char png[1200];
    snprintf(png, sizeof png, "%s/plot.png", test_tmpdir("media_plot"));
    CHECK_OK(sp_plot_bars_png(png, 900, 500, &p, &err), &err);
    sp_image im = {0};
    CHECK_OK(sp_image_read(png, &im, &err), &err);
    CHECK(im.width == 900 && im.height == 500);
    /* both series' colours appear as bars */
    long c0 = 0, c1 = 0;
    sp_rgba k0 = sp_media_palette(0), k1 = sp_media_palette(1);
    const uint8_t *d = im.data;
    for (long i = 0; d && i < 900L * 500; i++) {
        const uint8_t *q = d + i * 3;
        c0 += abs(q[0] - (int)(k0.r * 255 + .5f)) < 3 && abs(q[1] - (int)(k0.g * 255 + .5f)) < 3 &&
              abs(q[2] - (int)(k0.b * 255 + .5f)) < 3;
        c1 += abs(q[0] - (int)(k1.r * 255 + .5f)) < 3 && abs(q[1] - (int)(k1.g * 255 + .5f)) < 3 &&
              abs(q[2] - (int)(k1.b * 255 + .5f)) < 3;
    }
    CHECK_MSG(c0 > 1000 && c1 > 1000, "series pixels %ld %ld", c0, c1);
    sp_image_free(&im);
    sp_plot_bars bad = p;
    bad.n_categories = 0;
    CHECK_FAILS(sp_plot_bars_png(png, 900, 500, &bad, &err), SP_E_ARG, &err, "no categories");
    bad = p;
    bad.x_max = -1;
    CHECK_FAILS(sp_plot_bars_png(png, 900, 500, &bad, &err), SP_E_ARG, &err, "x_max");
    sp_plot_series none = {.name = "empty"};
    bad = p;
    bad.series = &none;
    bad.n_series = 1;
    CHECK_FAILS(sp_plot_bars_png(png, 900, 500, &bad, &err), SP_E_ARG, &err, "empty");
    CHECK_FAILS(sp_plot_bars_png(png, 20, 20, &p, &err), SP_E_ARG, &err, "too small");
}

int main(void)
{
    RUN(test_layout_wraps);
    RUN(test_layout_long_words_and_ellipsis);
    RUN(test_sanitize);
    RUN(test_canvas_shapes_images_text);
    RUN(test_cards_and_png);
    RUN(test_plot);
    return TEST_EXIT();
}
