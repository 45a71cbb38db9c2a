/* Random test scenes for the render tests: a tilted, shifted pinhole camera and Gaussians spread
 * through and around its frustum (some behind the camera, some across the image border, tiny and
 * huge scales), in float for the rasterizer and double for the reference. */
#ifndef SP_TEST_RENDER_SCENE_UTIL_H
#define SP_TEST_RENDER_SCENE_UTIL_H

#include "render_ref.h"
#include "test.h"

typedef struct test_scene {
    size_t n;
    int D;
    float *means, *quats, *log_scales, *opacity_logits, *colors, *bg;
} test_scene;

static inline void scene_camera(test_rng *rng, int W, int H, sp_camera *cam)
{
    memset(cam, 0, sizeof *cam);
    cam->width = W;
    cam->height = H;
    cam->fx = (float)(W * test_range(rng, 0.8, 1.2));
    cam->fy = cam->fx * (float)test_range(rng, 0.95, 1.05);
    cam->cx = (float)(W * test_range(rng, 0.45, 0.55));
    cam->cy = (float)(H * test_range(rng, 0.45, 0.55));
    float q[4] = {1.f, (float)test_range(rng, -0.1, 0.1), (float)test_range(rng, -0.1, 0.1),
                  (float)test_range(rng, -0.1, 0.1)};
    sp_quat_to_mat3(q, cam->R);
    for (int k = 0; k < 3; k++) cam->t[k] = (float)test_range(rng, -0.3, 0.3);
}

/* hard = 1 adds the awkward cases (behind the camera, far outside, tiny/huge scales); hard = 2
 * also needles (one scale 4.5 m, the others centimetres). */
static inline void scene_make(test_scene *s, test_rng *rng, const sp_camera *cam, size_t n, int D,
                       double z_lo, double z_hi, double op_lo, double op_hi, int hard)
{
    s->n = n;
    s->D = D;
    s->means = malloc(n * 3 * sizeof(float));
    s->quats = malloc(n * 4 * sizeof(float));
    s->log_scales = malloc(n * 3 * sizeof(float));
    s->opacity_logits = malloc(n * sizeof(float));
    s->colors = malloc(n * (size_t)D * sizeof(float));
    s->bg = malloc((size_t)D * sizeof(float));
    for (int c = 0; c < D; c++) s->bg[c] = (float)test_range(rng, 0, 1);
    for (size_t i = 0; i < n; i++) {
        double z = test_range(rng, z_lo, z_hi);
        double spread = hard ? 0.75 : 0.5;
        double pc[3] = {fabs(z) * test_range(rng, -spread, spread) * cam->width / cam->fx,
                        fabs(z) * test_range(rng, -spread, spread) * cam->height / cam->fy, z};
        if (hard && i % 17 == 3) pc[0] = fabs(z) * 3.0; /* far outside, exercises the fov clamp */
        /* world = R^T (pc - t) */
        for (int k = 0; k < 3; k++) {
            double acc = 0;
            for (int r = 0; r < 3; r++) acc += cam->R[r * 3 + k] * (pc[r] - cam->t[r]);
            s->means[3 * i + k] = (float)acc;
        }
        for (int k = 0; k < 4; k++) s->quats[4 * i + k] = (float)test_range(rng, -1, 1);
        double sig_px = exp(test_range(rng, log(0.4), log(hard ? 12.0 : 6.0)));
        for (int k = 0; k < 3; k++)
            s->log_scales[3 * i + k] =
                (float)(log(sig_px * fabs(z) / cam->fx) + test_range(rng, -0.5, 0.5));
        if (hard && i % 13 == 5) s->log_scales[3 * i] = -12.f; /* degenerate thin */
        if (hard && i % 29 == 7)
            for (int k = 0; k < 3; k++) s->log_scales[3 * i + k] = -14.f; /* point-like */
        if (hard && i % 31 == 11)
            for (int k = 0; k < 3; k++) s->log_scales[3 * i + k] = (float)test_range(rng, 0.0, 1.5); /* huge */
        if (hard == 2 && i % 7 == 1) s->log_scales[3 * i + 1] = 1.5f; /* needle, 100-1000:1 */
        double op = test_range(rng, op_lo, op_hi);
        s->opacity_logits[i] = (float)log(op / (1 - op));
        for (int c = 0; c < D; c++) s->colors[i * D + c] = (float)test_range(rng, -0.2, 1.0);
    }
}

static inline void scene_free(test_scene *s)
{
    free(s->means);
    free(s->quats);
    free(s->log_scales);
    free(s->opacity_logits);
    free(s->colors);
    free(s->bg);
    memset(s, 0, sizeof *s);
}

static inline double *to_double(const float *a, size_t k)
{
    double *d = malloc((k ? k : 1) * sizeof *d);
    for (size_t i = 0; i < k; i++) d[i] = a[i];
    return d;
}

static inline void scene_to_ref(const test_scene *s, ref_scene *r, int with_bg)
{
    memset(r, 0, sizeof *r);
    r->n = s->n;
    r->D = s->D;
    r->means = to_double(s->means, s->n * 3);
    r->quats = to_double(s->quats, s->n * 4);
    r->log_scales = to_double(s->log_scales, s->n * 3);
    r->opacity_logits = to_double(s->opacity_logits, s->n);
    r->colors = to_double(s->colors, s->n * (size_t)s->D);
    r->bg = with_bg ? to_double(s->bg, (size_t)s->D) : NULL;
}

static inline void ref_scene_free(ref_scene *r)
{
    free(r->means);
    free(r->quats);
    free(r->log_scales);
    free(r->opacity_logits);
    free(r->colors);
    free(r->bg);
    free(r->mean2d_offset);
    memset(r, 0, sizeof *r);
}

static inline sp_raster_in scene_input(const test_scene *s, int with_bg)
{
    sp_raster_in in = {s->n, s->means, s->quats, s->log_scales, s->opacity_logits, s->colors, s->D,
                       with_bg ? s->bg : NULL};
    return in;
}

#endif
