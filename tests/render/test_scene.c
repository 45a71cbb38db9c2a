/* Rendering for callers other than training, on the CPU: first-surface depth against a naive
 * double reference (render_ref.h) and at an occlusion edge (where expected depth blends the two
 * surfaces and first-surface depth picks one); sp_scene snapshots and sp_scene_update; batches of
 * views (sp_render_views) equal to one view at a time and to sp_render_splat; bad requests;
 * outputs left on the device (on_device, sp_scene_copy_features) equal to downloaded ones, on
 * the CPU and (--gpu) on CUDA. The CUDA side of the rest is in test_cuda_raster (batches, surface
 * depth bit for bit). */
#include "scene_util.h"

static sp_device *g_cpu;

/* ---- first-surface depth ---------------------------------------------------------------------- */

static void surface_case(unsigned long long seed, int W, int H, size_t n, float thr, int aa)
{
    test_rng rng = {seed};
    sp_camera cam;
    scene_camera(&rng, W, H, &cam);
    test_scene s;
    scene_make(&s, &rng, &cam, n, 1, -1.0, 9.0, 0.05, 0.999, 1);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.surface_alpha = thr;
    cfg.antialiased = aa;
    size_t npix = (size_t)W * H;
    float *img = malloc(npix * sizeof(float)), *surf = malloc(npix * sizeof(float));
    sp_raster *r = NULL;
    sp_error err = {0};
    CHECK_OK(sp_raster_create(&r, g_cpu, &err), &err);
    sp_raster_in in = scene_input(&s, 0);
    sp_raster_out out = {img, NULL, NULL, surf};
    CHECK_OK(sp_raster_forward(r, &cam, &cfg, &in, &out, &err), &err);
    ref_scene rs;
    scene_to_ref(&s, &rs, 0);
    double *rz = malloc(npix * sizeof(double)), *mg = malloc(npix * sizeof(double));
    ref_surface_depth(&rs, &cam, &cfg, thr, rz, mg);
    size_t ambiguous = 0, bad = 0, hit = 0;
    double worst = 0;
    for (size_t p = 0; p < npix; p++) {
        /* float and double may decide differently only this close to a threshold */
        if (mg[p] < 1e-5) {
            ambiguous++;
            continue;
        }
        hit += rz[p] > 0;
        double e = fabs(surf[p] - rz[p]) / fmax(1.0, fabs(rz[p]));
        worst = fmax(worst, e);
        bad += e > 1e-5;
    }
    fprintf(stderr, "  %dx%d n=%zu alpha %.2f aa=%d: %zu pixels reach it, %zu near the threshold "
            "(skipped), %zu differ (worst %.2g)\n", W, H, n, thr, aa, hit, ambiguous, bad, worst);
    CHECK_MSG(bad == 0, "%zu pixels' surface depth differs from the reference", bad);
    CHECK(ambiguous < npix / 100);
    CHECK(thr > 0.9f || hit > npix / 10);
    free(img), free(surf), free(rz), free(mg);
    ref_scene_free(&rs);
    scene_free(&s);
    sp_raster_free(r);
}

static void test_surface_reference(void)
{
    surface_case(11, 64, 48, 400, 0.5f, 0);
    surface_case(12, 90, 61, 900, 0.2f, 0);
    surface_case(13, 50, 40, 300, 0.9f, 1);
    surface_case(14, 37, 29, 200, 0.5f, 1);
}

/* A near wall over the left half of a far one: at the edge the expected depth takes values in
 * between (a surface that is not there), first-surface depth is one wall or the other. */
static void test_surface_at_edges(void)
{
    enum { W = 96, H = 64 };
    sp_splat s;
    sp_error err = {0};
    /* far wall at z = 4: 45 x 31 Gaussians 0.1 m apart; near wall at z = 2 over x < 0: 25 x 33,
     * 0.05 m apart; each a flat disc of sigma 0.8 spacing, opacity 0.97 */
    CHECK_OK(sp_splat_alloc(&s, 45 * 31 + 25 * 33, 0, 0, &err), &err);
    size_t g = 0;
    for (int wall = 0; wall < 2; wall++) {
        int nx = wall ? 25 : 45, ny = wall ? 33 : 31;
        float step = wall ? 0.05f : 0.1f, z = wall ? 2.f : 4.f, x0 = wall ? -1.2f : -2.2f;
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++, g++) {
                s.means[3 * g] = x0 + step * i;
                s.means[3 * g + 1] = step * (j - (ny - 1) / 2.f);
                s.means[3 * g + 2] = z;
                s.log_scales[3 * g] = s.log_scales[3 * g + 1] = logf(0.8f * step);
                s.log_scales[3 * g + 2] = logf(0.005f);
                s.opacity_logits[g] = sp_logit(0.97f);
            }
    }
    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    sp_camera_intrinsics_fov(&cam, W, H, 1.0f);
    cam.R[0] = cam.R[4] = cam.R[8] = 1.f;
    float surf[W * H], expd[W * H], alpha[W * H];
    sp_render_request q[2] = {{.depth = surf, .depth_mode = SP_DEPTH_SURFACE}, {.depth = expd, .alpha = alpha}};
    sp_camera cams[2] = {cam, cam};
    sp_raster *r = NULL;
    sp_scene *sc = NULL;
    CHECK_OK(sp_raster_create(&r, g_cpu, &err), &err);
    CHECK_OK(sp_scene_create(&sc, g_cpu, &s, 0, &err), &err); /* geometry only serves depth */
    CHECK_OK(sp_render_views(r, sc, cams, 2, q, &err), &err);
    size_t blended = 0, surf_between = 0, opaque = 0;
    for (int p = 0; p < W * H; p++) {
        if (alpha[p] < 0.99f) continue;
        opaque++;
        blended += expd[p] > 2.3f && expd[p] < 3.7f;
        surf_between += !(fabsf(surf[p] - 2.f) < 0.05f || fabsf(surf[p] - 4.f) < 0.05f);
    }
    fprintf(stderr, "  edge: %zu opaque pixels, expected depth between the walls at %zu, first-surface "
            "depth between them at %zu\n", opaque, blended, surf_between);
    CHECK(opaque > W * H / 2);
    CHECK(blended >= 10);
    CHECK(surf_between == 0);
    sp_scene_free(sc);
    sp_raster_free(r);
    sp_splat_free(&s);
}

/* ---- scenes and batches ----------------------------------------------------------------------- */

/* A random splat with SH degree 2 and 5 features, in front of a camera at the origin. */
static void random_splat(sp_splat *s, size_t n, unsigned long long seed)
{
    test_rng rng = {seed};
    sp_camera cam;
    scene_camera(&rng, 64, 48, &cam);
    test_scene t;
    scene_make(&t, &rng, &cam, n, 1, 1.0, 6.0, 0.1, 0.99, 0);
    sp_error err = {0};
    CHECK_OK(sp_splat_alloc(s, n, 2, 5, &err), &err);
    memcpy(s->means, t.means, n * 12);
    memcpy(s->quats, t.quats, n * 16);
    memcpy(s->log_scales, t.log_scales, n * 12);
    memcpy(s->opacity_logits, t.opacity_logits, n * 4);
    for (size_t i = 0; i < n * 9 * 3; i++) s->sh[i] = (float)test_range(&rng, -0.7, 0.7);
    for (size_t i = 0; i < n * 5; i++) s->features[i] = (float)test_range(&rng, -1, 1);
    scene_free(&t);
}

static sp_camera view_cam(int W, int H, float yaw)
{
    sp_camera c;
    memset(&c, 0, sizeof c);
    sp_camera_intrinsics_fov(&c, W, H, 1.1f);
    /* a camera at the origin looking down +z, turned by yaw about the image's y axis */
    float cy = cosf(yaw), sy = sinf(yaw);
    float R[9] = {cy, 0, -sy, 0, 1, 0, sy, 0, cy};
    memcpy(c.R, R, sizeof R);
    return c;
}

typedef struct {
    float rgb[40 * 30 * 3], feat[40 * 30 * 5], depth[40 * 30], alpha[40 * 30];
} outs;

static void ask(outs *o, sp_render_request *q, int rgb, int feat, int depth, int alpha,
                sp_depth_mode mode)
{
    memset(o, 0, sizeof *o);
    memset(q, 0, sizeof *q);
    q->rgb = rgb ? o->rgb : NULL;
    q->features = feat ? o->feat : NULL;
    q->depth = depth ? o->depth : NULL;
    q->alpha = alpha ? o->alpha : NULL;
    q->depth_mode = mode;
}

static void test_views_and_scenes(void)
{
    sp_splat s;
    random_splat(&s, 300, 5);
    sp_error err = {0};
    sp_raster *r = NULL;
    sp_scene *sc = NULL;
    CHECK_OK(sp_raster_create(&r, g_cpu, &err), &err);
    CHECK_OK(sp_scene_create(&sc, g_cpu, &s, SP_SCENE_RGB | SP_SCENE_FEATURES, &err), &err);
    CHECK(sp_scene_count(sc) == 300 && sp_scene_feat_dim(sc) == 5 && sp_scene_device(sc) == g_cpu);
    sp_camera cams[3] = {view_cam(40, 30, 0.f), view_cam(31, 22, 0.2f), view_cam(40, 30, -0.15f)};
    static outs a[3], b[3];
    sp_render_request qa[3], qb[3];
    float bg[3] = {0.1f, 0.2f, 0.3f};
    ask(&a[0], &qa[0], 1, 1, 1, 1, SP_DEPTH_EXPECTED), ask(&b[0], &qb[0], 1, 1, 1, 1, SP_DEPTH_EXPECTED);
    qa[0].background = qb[0].background = bg;
    ask(&a[1], &qa[1], 1, 0, 1, 0, SP_DEPTH_SURFACE), ask(&b[1], &qb[1], 1, 0, 1, 0, SP_DEPTH_SURFACE);
    ask(&a[2], &qa[2], 0, 1, 0, 1, SP_DEPTH_EXPECTED), ask(&b[2], &qb[2], 0, 1, 0, 1, SP_DEPTH_EXPECTED);
    qa[1].depth_alpha = qb[1].depth_alpha = 0.7f;
    /* a batch, then one at a time through sp_render_splat: the same bits */
    CHECK_OK(sp_render_views(r, sc, cams, 3, qa, &err), &err);
    for (int v = 0; v < 3; v++) CHECK_OK(sp_render_splat(r, &s, &cams[v], &qb[v], &err), &err);
    CHECK(memcmp(a, b, sizeof a) == 0);
    /* expected depth is sum w z / sum w: consistent with a surface-depth view of the same camera */
    int between = 0;
    for (int p = 0; p < 40 * 30; p++) between += a[0].alpha[p] > 0.5f && a[0].depth[p] > 0.9f;
    CHECK(between > 100);

    /* a scene is a snapshot: editing the splat changes nothing until sp_scene_update */
    for (size_t i = 0; i < s.n; i++) s.sh[i * 27] += 0.5f; /* redder DC */
    outs c;
    sp_render_request qc;
    ask(&c, &qc, 1, 0, 0, 0, SP_DEPTH_EXPECTED);
    qc.background = bg;
    CHECK_OK(sp_render_views(r, sc, cams, 1, &qc, &err), &err);
    CHECK(memcmp(c.rgb, a[0].rgb, sizeof c.rgb) == 0);
    CHECK_OK(sp_scene_update(sc, &s, SP_SCENE_CHANGED_SH, &err), &err);
    CHECK_OK(sp_render_views(r, sc, cams, 1, &qc, &err), &err);
    outs d;
    sp_render_request qd;
    ask(&d, &qd, 1, 0, 0, 0, SP_DEPTH_EXPECTED);
    qd.background = bg;
    CHECK_OK(sp_render_splat(r, &s, &cams[0], &qd, &err), &err);
    CHECK(memcmp(c.rgb, d.rgb, sizeof c.rgb) == 0);
    CHECK(memcmp(c.rgb, a[0].rgb, sizeof c.rgb) != 0);

    /* a new count re-uploads everything, whatever `changed` says */
    sp_splat t;
    random_splat(&t, 120, 6);
    CHECK_OK(sp_scene_update(sc, &t, SP_SCENE_CHANGED_FEATURES, &err), &err);
    CHECK(sp_scene_count(sc) == 120);
    CHECK_OK(sp_render_views(r, sc, cams, 1, &qc, &err), &err);
    CHECK_OK(sp_render_splat(r, &t, &cams[0], &qd, &err), &err);
    CHECK(memcmp(c.rgb, d.rgb, sizeof c.rgb) == 0);

    /* the scene's geometry feeds sp_raster_forward directly */
    sp_raster_in in;
    CHECK_OK(sp_scene_raster_in(sc, &in, &err), &err);
    CHECK(in.n == 120 && in.means && in.opacity_logits && !in.colors);
    CHECK(sp_scene_device_features(sc) != NULL);
    sp_splat_free(&t);
    sp_splat_free(&s);
    sp_scene_free(sc);
    sp_raster_free(r);
}

static void test_bad_requests(void)
{
    sp_splat s;
    random_splat(&s, 50, 9);
    sp_error err = {0};
    sp_raster *r = NULL;
    sp_scene *geo = NULL, *sc = NULL;
    CHECK_OK(sp_raster_create(&r, g_cpu, &err), &err);
    CHECK_OK(sp_scene_create(&geo, g_cpu, &s, 0, &err), &err);
    sp_camera cams[2] = {view_cam(40, 30, 0.f), view_cam(40, 30, 0.f)};
    outs o;
    sp_render_request q[2];
    ask(&o, &q[0], 1, 0, 0, 0, SP_DEPTH_EXPECTED);
    CHECK_FAILS(sp_render_views(r, geo, cams, 1, q, &err), SP_E_ARG, &err, "SP_SCENE_RGB");
    ask(&o, &q[0], 0, 1, 0, 0, SP_DEPTH_EXPECTED);
    CHECK_FAILS(sp_render_views(r, geo, cams, 1, q, &err), SP_E_ARG, &err, "SP_SCENE_FEATURES");
    ask(&o, &q[0], 0, 0, 1, 0, SP_DEPTH_SURFACE);
    q[0].depth_alpha = 1.5f;
    CHECK_FAILS(sp_render_views(r, geo, cams, 1, q, &err), SP_E_ARG, &err, "depth_alpha 1.5");
    q[0].depth_alpha = 0.f;
    q[0].depth_mode = (sp_depth_mode)7;
    CHECK_FAILS(sp_render_views(r, geo, cams, 1, q, &err), SP_E_ARG, &err, "depth mode 7");
    ask(&o, &q[0], 0, 0, 1, 0, SP_DEPTH_SURFACE);
    q[1] = q[0];
    cams[1].width = 0;
    CHECK_FAILS(sp_render_views(r, geo, cams, 2, q, &err), SP_E_ARG, &err, "view 1");
    /* what the splat lacks, and values that are not finite, are named */
    sp_splat none = s;
    none.feat_dim = 0, none.features = NULL;
    CHECK_FAILS(sp_scene_create(&sc, g_cpu, &none, SP_SCENE_FEATURES, &err), SP_E_ARG, &err, "features");
    s.means[3 * 7 + 1] = NAN;
    CHECK_FAILS(sp_scene_create(&sc, g_cpu, &s, SP_SCENE_RGB, &err), SP_E_NUMERIC, &err, "Gaussian 7");
    CHECK(sc == NULL);
    /* a failed update leaves a scene that refuses to render until an update succeeds */
    CHECK_FAILS(sp_scene_update(geo, &s, SP_SCENE_CHANGED_GEOMETRY, &err), SP_E_NUMERIC, &err, "mean");
    s.means[3 * 7 + 1] = 0.5f;
    CHECK_OK(sp_scene_update(geo, &s, SP_SCENE_CHANGED_GEOMETRY, &err), &err);
    CHECK_OK(sp_render_views(r, geo, cams, 1, q, &err), &err);
    /* a raster and a scene on two devices */
    sp_device *other = NULL;
    sp_raster *r2 = NULL;
    CHECK_OK(sp_device_create(&other, SP_DEVICE_CPU, 1, &err), &err);
    CHECK_OK(sp_raster_create(&r2, other, &err), &err);
    CHECK_FAILS(sp_render_views(r2, geo, cams, 1, q, &err), SP_E_ARG, &err, "different devices");
    sp_raster_free(r2);
    sp_device_free(other);
    sp_scene_free(geo);
    sp_raster_free(r);
    sp_splat_free(&s);
}

/* ---- outputs left on the device ------------------------------------------------------------------ */

/* Downloads what a device request got into host outputs o (sizes of outs). */
static void fetch(sp_device *dev, const sp_render_request *d, outs *o, size_t npix, sp_error *err)
{
    memset(o, 0, sizeof *o);
    if (d->rgb) CHECK_OK(sp_device_download(dev, o->rgb, d->rgb, npix * 12, err), err);
    if (d->features) CHECK_OK(sp_device_download(dev, o->feat, d->features, npix * 20, err), err);
    if (d->depth) CHECK_OK(sp_device_download(dev, o->depth, d->depth, npix * 4, err), err);
    if (d->alpha) CHECK_OK(sp_device_download(dev, o->alpha, d->alpha, npix * 4, err), err);
}

/* A request like q whose outputs are fresh device buffers. */
static sp_render_request on_device(sp_device *dev, const sp_render_request *q, size_t npix, sp_error *err)
{
    sp_render_request d = *q;
    d.on_device = 1;
    d.rgb = q->rgb ? sp_device_alloc(dev, npix * 12, err) : NULL;
    d.features = q->features ? sp_device_alloc(dev, npix * 20, err) : NULL;
    d.depth = q->depth ? sp_device_alloc(dev, npix * 4, err) : NULL;
    d.alpha = q->alpha ? sp_device_alloc(dev, npix * 4, err) : NULL;
    return d;
}

static void release(sp_device *dev, sp_render_request *d)
{
    sp_device_release(dev, d->rgb), sp_device_release(dev, d->features);
    sp_device_release(dev, d->depth), sp_device_release(dev, d->alpha);
}

/* on_device requests give the bits host requests give (expected depth divided on the device too),
 * and sp_scene_copy_features equals re-uploading the same features from the host. */
static void views_on_device(sp_device *dev)
{
    sp_splat s;
    random_splat(&s, 300, 6);
    sp_error err = {0};
    sp_raster *r = NULL;
    sp_scene *sc = NULL;
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    CHECK_OK(sp_scene_create(&sc, dev, &s, SP_SCENE_RGB | SP_SCENE_FEATURES, &err), &err);
    sp_camera cams[4] = {view_cam(40, 30, 0.f), view_cam(31, 22, 0.2f), view_cam(40, 30, -0.15f),
                         view_cam(40, 30, 0.1f)};
    static outs a[4], b[4];
    sp_render_request qa[4], qd[4];
    float bg[3] = {0.1f, 0.2f, 0.3f};
    ask(&a[0], &qa[0], 1, 1, 1, 1, SP_DEPTH_EXPECTED);
    qa[0].background = bg;
    ask(&a[1], &qa[1], 1, 0, 1, 0, SP_DEPTH_SURFACE);
    qa[1].depth_alpha = 0.7f;
    ask(&a[2], &qa[2], 0, 1, 1, 0, SP_DEPTH_EXPECTED); /* expected depth without alpha asked */
    ask(&a[3], &qa[3], 0, 0, 1, 1, SP_DEPTH_EXPECTED); /* weights only */
    CHECK_OK(sp_render_views(r, sc, cams, 4, qa, &err), &err);
    for (int v = 0; v < 4; v++) qd[v] = on_device(dev, &qa[v], 40 * 30, &err);
    CHECK_OK(sp_render_views(r, sc, cams, 4, qd, &err), &err);
    for (int v = 0; v < 4; v++) {
        fetch(dev, &qd[v], &b[v], (size_t)cams[v].width * cams[v].height, &err);
        CHECK_MSG(memcmp(&a[v], &b[v], sizeof a[v]) == 0, "view %d left on the device differs", v);
        release(dev, &qd[v]);
    }
    /* features copied on the device = the same features uploaded from the host */
    for (size_t i = 0; i < s.n * 5; i++) s.features[i] = 0.5f * s.features[i] + 0.1f;
    float *d_feat = sp_device_alloc(dev, s.n * 5 * sizeof(float), &err);
    CHECK_OK(sp_device_upload(dev, d_feat, s.features, s.n * 5 * sizeof(float), &err), &err);
    CHECK_OK(sp_scene_copy_features(sc, d_feat, &err), &err);
    sp_scene *fresh = NULL;
    CHECK_OK(sp_scene_create(&fresh, dev, &s, SP_SCENE_FEATURES, &err), &err);
    ask(&a[0], &qa[0], 0, 1, 0, 1, SP_DEPTH_EXPECTED), ask(&b[0], &qd[0], 0, 1, 0, 1, SP_DEPTH_EXPECTED);
    CHECK_OK(sp_render_views(r, sc, cams, 1, qa, &err), &err);
    CHECK_OK(sp_render_views(r, fresh, cams, 1, qd, &err), &err);
    CHECK(memcmp(&a[0], &b[0], sizeof a[0]) == 0);
    sp_scene *geo = NULL;
    CHECK_OK(sp_scene_create(&geo, dev, &s, 0, &err), &err);
    CHECK_FAILS(sp_scene_copy_features(geo, d_feat, &err), SP_E_ARG, &err, "SP_SCENE_FEATURES");
    sp_device_release(dev, d_feat);
    sp_scene_free(geo);
    sp_scene_free(fresh);
    sp_scene_free(sc);
    sp_raster_free(r);
    sp_splat_free(&s);
}

static void test_views_on_device_cpu(void) { views_on_device(g_cpu); }

static void test_views_on_device_gpu(void)
{
    sp_device *gpu = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&gpu, SP_DEVICE_CUDA, 2, &err), &err);
    if (gpu) views_on_device(gpu);
    sp_device_free(gpu);
}

int main(int argc, char **argv)
{
    TEST_ARGS(argc, argv);
    sp_error err = {0};
    if (sp_device_create(&g_cpu, SP_DEVICE_CPU, 2, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    RUN(test_surface_reference);
    RUN(test_surface_at_edges);
    RUN(test_views_and_scenes);
    RUN(test_bad_requests);
    RUN(test_views_on_device_cpu);
    RUN_GPU(test_views_on_device_gpu);
    sp_device_free(g_cpu);
    return TEST_EXIT();
}
