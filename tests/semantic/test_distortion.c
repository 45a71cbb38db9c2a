/* Lens distortion through lift and the query engine: the tiny scene captured through an OPENCV
 * lens (strong barrel, as a wide webcam) gives feature maps whose pixels sit where the lens put
 * them. Lifted into the splat, every Gaussian must get its own class's feature as well as from
 * the same capture taken with a pinhole camera (the undistorted truth); and the engine's heatmap
 * of a distorted view must lie on the object in that image's own pixels. */
#include <cjson/cJSON.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "test.h"

enum { N = 12, W = 160, H = 120 };

static const float K1 = -0.30f, K2 = 0.08f, P1 = 0.002f, P2 = -0.002f;

static float g_emb[SC_CLASSES][SC_FULL];
static sp_sem_pca g_pca;
static sp_splat g_s;
static int *g_cls;
static sp_camera g_cams[N];
static sp_device *g_dev;

/* A capture (COLMAP model with a PINHOLE or OPENCV camera), its feature folder, and a model
 * folder (geometry only, train.json naming the capture) lifted with sp_semantic_lift_model. */
static int make_model(const char *root, int distorted, char *model, size_t cap, sp_error *err)
{
    char capdir[1200], feat[1200], path[1400];
    snprintf(capdir, sizeof capdir, "%s/capture", root);
    snprintf(feat, sizeof feat, "%s/features", root);
    snprintf(model, cap, "%s/model", root);
    const sp_camera *c = &g_cams[0];
    sp_colmap_camera cam = {1, SP_COLMAP_PINHOLE, W, H, 4, {c->fx, c->fy, c->cx, c->cy}};
    sp_camera lens = *c;
    if (distorted) {
        sp_colmap_camera oc = {1, SP_COLMAP_OPENCV, W, H, 8, {c->fx, c->fy, c->cx, c->cy, K1, K2, P1, P2}};
        cam = oc;
        lens.distortion = SP_DIST_OPENCV;
        lens.dist[0] = K1, lens.dist[1] = K2, lens.dist[2] = P1, lens.dist[3] = P2;
    }
    snprintf(path, sizeof path, "%s/sparse/0", capdir);
    int rc = sc_write_colmap_camera(path, &cam, g_cams, N, "%05d.png", err);
    if (!rc) rc = sc_write_features(feat, &g_s, &g_pca, g_cams, N, distorted ? &lens : NULL, err);
    sp_splat geo;
    memset(&geo, 0, sizeof geo);
    if (!rc) rc = sp_splat_copy(&geo, &g_s, err);
    if (!rc) {
        sp_free(geo.features);
        geo.features = NULL;
        geo.feat_dim = 0;
        rc = sp_mkdirs(model, err);
    }
    snprintf(path, sizeof path, "%s/splat.ply", model);
    if (!rc) rc = sp_ply_write_splat(path, &geo, err);
    sp_splat_free(&geo);
    if (!rc) rc = sp_semantic_lift_model(model, feat, capdir, g_dev, NULL, err);
    return rc;
}

/* Mean distance of the lifted features from each Gaussian's true class feature (over Gaussians
 * that were seen), and the share whose nearest class feature is the true one. */
static void score_lift(const char *model, double *mean_err, double *accuracy)
{
    char path[1400];
    snprintf(path, sizeof path, "%s/splat.ply", model);
    sp_splat b;
    sp_error err = {0};
    *mean_err = 1e9, *accuracy = 0;
    CHECK_OK(sp_ply_read_splat(path, &b, &err), &err);
    if (err.code) return;
    float tf[SC_CLASSES][SC_DIM];
    for (int k = 0; k < SC_CLASSES; k++) sc_encode(&g_pca, g_emb[k], tf[k]);
    double se = 0;
    long seen = 0, right = 0;
    for (size_t i = 0; i < b.n && b.feat_dim == SC_DIM; i++) {
        const float *f = b.features + i * SC_DIM;
        double n2 = 0;
        for (int d = 0; d < SC_DIM; d++) n2 += f[d] * f[d];
        if (n2 == 0) continue; /* never seen */
        seen++;
        int best = -1;
        double bd = 1e30;
        for (int k = 0; k < SC_CLASSES; k++) {
            double d2 = 0;
            for (int d = 0; d < SC_DIM; d++) d2 += (f[d] - tf[k][d]) * (f[d] - tf[k][d]);
            if (k == g_cls[i]) se += sqrt(d2);
            if (d2 < bd) bd = d2, best = k;
        }
        right += best == g_cls[i];
    }
    *mean_err = seen ? se / seen : 1e9;
    *accuracy = seen ? (double)right / seen : 0;
    sp_splat_free(&b);
}

/* Pixels of the table in distorted view v at full size: the table's indicator rendered pinhole
 * on a doubled canvas and resampled through the lens. */
static void table_mask(int v, uint8_t *truth)
{
    sp_splat ind;
    sp_error err = {0};
    CHECK_OK(sp_splat_copy(&ind, &g_s, &err), &err);
    sp_free(ind.features);
    ind.feat_dim = 1;
    ind.features = sp_calloc(ind.n, sizeof(float));
    for (size_t i = 0; i < ind.n; i++) ind.features[i] = g_cls[i] == 2;
    sp_camera lens = g_cams[v], pin = g_cams[v];
    lens.distortion = SP_DIST_OPENCV;
    lens.dist[0] = K1, lens.dist[1] = K2, lens.dist[2] = P1, lens.dist[3] = P2;
    pin.width *= 2, pin.height *= 2, pin.cx += 0.5f * W, pin.cy += 0.5f * H;
    size_t big = (size_t)pin.width * pin.height;
    float *f = malloc(sizeof(float) * big), *a = malloc(sizeof(float) * big), *m = malloc(sizeof(float) * W * H);
    sp_raster *r = NULL;
    CHECK_OK(sp_raster_create(&r, g_dev, &err), &err);
    sp_render_request req = {.features = f, .alpha = a};
    CHECK_OK(sp_render_splat(r, &ind, &pin, &req, &err), &err);
    for (size_t p = 0; p < big; p++) f[p] = a[p] > 0.5f ? f[p] / a[p] : 0;
    CHECK_OK(sp_camera_remap_from_pinhole(&pin, f, 1, &lens, m, NULL, &err), &err);
    for (int p = 0; p < W * H; p++) truth[p] = m[p] > 0.5f;
    sp_raster_free(r);
    free(f), free(a), free(m);
    sp_splat_free(&ind);
}

static void test_lift_and_heatmap_through_a_lens(void)
{
    const char *root = test_tmpdir("semantic_distortion");
    char dir[1200], model_pin[1300], model_dis[1300];
    sp_error err = {0};
    snprintf(dir, sizeof dir, "%s/pinhole", root);
    CHECK_OK(make_model(dir, 0, model_pin, sizeof model_pin, &err), &err);
    snprintf(dir, sizeof dir, "%s/opencv", root);
    CHECK_OK(make_model(dir, 1, model_dis, sizeof model_dis, &err), &err);
    double e_pin, a_pin, e_dis, a_dis;
    score_lift(model_pin, &e_pin, &a_pin);
    score_lift(model_dis, &e_dis, &a_dis);
    fprintf(stderr, "  lift: pinhole capture error %.4f, class accuracy %.4f; OPENCV capture %.4f, %.4f\n", e_pin,
            a_pin, e_dis, a_dis);
    /* resampling twice (making the lens's maps, undoing them) blurs a little: within 15% */
    CHECK_MSG(a_dis >= a_pin - 0.005 && e_dis <= 1.15 * e_pin,
              "through the lens: error %.4f (pinhole %.4f), accuracy %.4f (pinhole %.4f)", e_dis, e_pin, a_dis, a_pin);

    /* the heatmap of a distorted view, in that image's pixels */
    sp_query_engine *e = NULL;
    CHECK_OK(sp_query_engine_open(&e, model_dis, NULL, g_dev, NULL, &err), &err);
    if (!e) return;
    CHECK(sp_query_engine_camera(e, 0)->distortion == SP_DIST_OPENCV);
    const int v = 5;
    sp_query_opts qo = sp_query_opts_default();
    qo.heatmap_view = v;
    sp_query_result res;
    CHECK_OK(sp_query_engine_query(e, "table", &qo, &res, &err), &err);
    uint8_t *truth = malloc(W * H);
    table_mask(v, truth);
    long inter = 0, uni = 0, n_truth = 0;
    for (int p = 0; p < W * H && res.relevancy && res.width == W; p++) {
        int hot = res.relevancy[p] > 0.6f;
        inter += hot && truth[p];
        uni += hot || truth[p];
        n_truth += truth[p];
    }
    double iou = uni ? (double)inter / uni : 0;
    fprintf(stderr, "  heatmap of view %d: IoU %.3f with the table's %ld pixels in the distorted image\n", v, iou,
            n_truth);
    CHECK(n_truth > 300);
    CHECK_MSG(iou > 0.8, "heatmap IoU %.3f", iou);
    free(truth);
    sp_query_result_free(&res);
    sp_query_engine_free(e);
}

/* Distill does not resample feature maps through a lens: it refuses such a capture, naming it. */
static void test_distill_refuses_a_lens(void)
{
    const char *root = test_tmpdir("semantic_distortion_distill");
    char model[1300], path[1400], cmd[6000];
    sp_error err = {0};
    CHECK_OK(make_model(root, 1, model, sizeof model, &err), &err);
    /* images for the trainer's loader (their content does not matter here) */
    static float grey[W * H * 3];
    for (int i = 0; i < W * H * 3; i++) grey[i] = 0.5f;
    snprintf(path, sizeof path, "%s/capture/images", root);
    CHECK_OK(sp_mkdirs(path, &err), &err);
    for (int v = 0; v < N; v++) {
        snprintf(path, sizeof path, "%s/capture/images/%05d.png", root, v);
        CHECK_OK(sp_write_png_f32(path, grey, W, H, 3, &err), &err);
    }
    snprintf(cmd, sizeof cmd, "distill --model %s --features %s/features --colmap %s/capture --steps 1 "
             "--device cpu --quiet", model, root, root);
    char out[4096];
    int st = test_run_cli(cmd, out, sizeof out);
    CHECK_MSG(st != 0 && strstr(out, "12 of 12 images have a distorted camera"), "exit %d: %s", st, out);
}

int main(void)
{
    sc_make_pca(&g_pca, g_emb);
    sc_make_splat(&g_s, &g_cls, &g_pca, g_emb);
    sc_make_cams(g_cams, N, W, H);
    sp_error err = {0};
    if (sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    RUN(test_lift_and_heatmap_through_a_lens);
    RUN(test_distill_refuses_a_lens);
    sp_device_free(g_dev);
    sp_splat_free(&g_s);
    sp_sem_pca_free(&g_pca);
    free(g_cls);
    return TEST_EXIT();
}
