/* Exact ellipse-vs-tile culling (sp_gm_tile_hit, sp_raster_cfg.box_tiles):
 *  - the predicate never rejects a pixel rectangle in which some pixel centre passes the alpha
 *    rule (sp_gm_alpha_g, brute force over every pixel), over random, elongated, huge and needle
 *    conics, means inside and outside the rectangle, opacities from 1/255 up;
 *  - on the CPU backend, rendering with the culling and with every bounding-box tile gives
 *    bit-identical images, depth, alpha and gradients, with fewer pairs. */
#include <stdint.h>

#include "render/gauss_math.h"
#include "scene_util.h"

/* A random conic: the inverse of R diag(s0^2, s1^2) R^T + eps I. */
static void random_conic(test_rng *rng, float con[3])
{
    double s0 = exp(test_range(rng, log(0.3), log(200.0)));
    double s1 = test_uniform(rng) < 0.3 ? s0 * exp(test_range(rng, -7, 0)) /* needles */
                                        : exp(test_range(rng, log(0.3), log(40.0)));
    double th = test_range(rng, 0, 3.14159265), c = cos(th), s = sin(th);
    double a = c * c * s0 * s0 + s * s * s1 * s1 + 0.3, cc = s * s * s0 * s0 + c * c * s1 * s1 + 0.3;
    double b = c * s * (s0 * s0 - s1 * s1);
    double det = a * cc - b * b;
    con[0] = (float)(cc / det);
    con[1] = (float)(-b / det);
    con[2] = (float)(a / det);
}

static void test_never_drops_a_kept_pixel(void)
{
    test_rng rng = {0x7117ull};
    long rects = 0, hit = 0, needed = 0, missed = 0;
    for (int it = 0; it < 60000; it++) {
        float con[3];
        random_conic(&rng, con);
        float op = (float)exp(test_range(&rng, log(1.0 / 250.0), 0.0));
        if (!(op * 255.f > 1.f)) continue;
        float cut = sp_gm_sigma_cut(op);
        /* a 16x16 rectangle (sometimes clipped smaller) near the mean: distance up to ~4 sigma */
        float reach = 3.5f * sqrtf(1.f / fminf(con[0], con[2]));
        float mx = (float)test_range(&rng, -reach - 20.f, reach + 20.f) + 1000.f;
        float my = (float)test_range(&rng, -reach - 20.f, reach + 20.f) + 600.f;
        int x0 = 1000 + (int)test_range(&rng, -16, 16), y0 = 600 + (int)test_range(&rng, -16, 16);
        int x1 = x0 + (test_uniform(&rng) < 0.2 ? (int)test_range(&rng, 0, 15) : 15);
        int y1 = y0 + (test_uniform(&rng) < 0.2 ? (int)test_range(&rng, 0, 15) : 15);
        int keep = sp_gm_tile_hit(con, cut, mx, my, x0, x1, y0, y1);
        int any = 0;
        for (int y = y0; y <= y1 && !any; y++)
            for (int x = x0; x <= x1 && !any; x++) {
                float g;
                any = sp_gm_alpha_g(con, op, cut, ((float)x + 0.5f) - mx, ((float)y + 0.5f) - my,
                                    &g) > 0.f;
            }
        rects++;
        hit += keep;
        needed += any;
        if (any && !keep) missed++;
    }
    fprintf(stderr, "  %ld rectangles: %ld contribute, %ld kept by the test, %ld wrongly dropped\n",
            rects, needed, hit, missed);
    CHECK(missed == 0);
    CHECK(needed > rects / 10 && hit < rects); /* both kinds occur, and the test rejects some */
}

/* One CPU forward + backward; fills image/depth/alpha and the gradients, returns the pairs. */
static size_t render(const test_scene *s, const sp_camera *cam, int box_tiles, float *img,
                     float *dep, float *alp, float *grads)
{
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.box_tiles = box_tiles;
    sp_raster_in in = scene_input(s, 1);
    sp_raster_out out = {img, dep, alp, NULL};
    CHECK_OK(sp_raster_forward(r, cam, &cfg, &in, &out, &err), &err);
    size_t pairs = sp_raster_last_pairs(r);
    size_t npix = (size_t)cam->width * cam->height, n = s->n;
    float *vi = malloc(npix * s->D * sizeof(float)), *vd = malloc(npix * sizeof(float));
    test_rng rng = {99};
    for (size_t k = 0; k < npix * (size_t)s->D; k++) vi[k] = (float)test_range(&rng, -1, 1);
    for (size_t k = 0; k < npix; k++) vd[k] = (float)test_range(&rng, -0.1, 0.1);
    sp_raster_grads g = {grads, grads + 3 * n, grads + 7 * n, grads + 10 * n, grads + 11 * n,
                         grads + (11 + (size_t)s->D) * n};
    sp_raster_grad_in gin = {vi, vd, NULL};
    CHECK_OK(sp_raster_backward(r, &gin, &g, &err), &err);
    free(vi), free(vd);
    sp_raster_free(r);
    sp_device_free(dev);
    return pairs;
}

static void test_same_images_fewer_pairs(void)
{
    for (int hard = 0; hard <= 2; hard++) {
        test_rng rng = {0xC011ull + (unsigned long long)hard};
        sp_camera cam;
        int W = 211, H = 157, D = 3;
        scene_camera(&rng, W, H, &cam);
        test_scene s;
        scene_make(&s, &rng, &cam, 3000, D, -1.0, 9.0, 0.02, 0.999, hard);
        size_t npix = (size_t)W * H, ng = s.n * (13 + (size_t)D);
        float *a[4], *b[4];
        size_t len[4] = {npix * D, npix, npix, ng};
        for (int k = 0; k < 4; k++) a[k] = calloc(len[k], sizeof(float)), b[k] = calloc(len[k], sizeof(float));
        size_t pe = render(&s, &cam, 0, a[0], a[1], a[2], a[3]);
        size_t pb = render(&s, &cam, 1, b[0], b[1], b[2], b[3]);
        int same = 1;
        for (int k = 0; k < 4; k++) same &= memcmp(a[k], b[k], len[k] * sizeof(float)) == 0;
        fprintf(stderr, "  hard=%d: pairs exact %zu, box %zu (%.1f%% fewer); identical %d\n", hard,
                pe, pb, 100.0 * (1.0 - (double)pe / (double)pb), same);
        CHECK(same);
        CHECK(pe < pb);
        for (int k = 0; k < 4; k++) free(a[k]), free(b[k]);
        scene_free(&s);
    }
}

int main(void)
{
    RUN(test_never_drops_a_kept_pixel);
    RUN(test_same_images_fewer_pairs);
    return TEST_EXIT();
}
