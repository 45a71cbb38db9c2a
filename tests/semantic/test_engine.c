/* The query engine as a service: options belong to one call; per-Gaussian relevancy equals the
 * reference scorer; a heatmap from any camera equals the query's heatmap from the same view; two
 * threads on one engine get the serial answers; and a frame (rotation, translation, scale) moves
 * splat, cameras and every position alike, with results naming it. */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "test.h"

enum { NCAM = 12, CW = 160, CH = 120 };

static sp_device *g_dev;
static sp_splat g_splat;
static sp_sem_pca g_pca;
static sp_camera g_cams[NCAM];
static float g_emb[SC_CLASSES][SC_FULL];

static sp_query_engine *make_engine(const sp_frame *frame)
{
    sp_query_model m = {.splat = &g_splat, .pca = &g_pca, .cams = g_cams, .n_cams = NCAM, .frame = frame};
    sp_query_engine *e = NULL;
    sp_error err = {0};
    CHECK_OK(sp_query_engine_create(&e, &m, NULL, g_dev, NULL, &err), &err);
    return e;
}

static double dist3(const float *a, const float *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static void test_options_per_call(void)
{
    sp_query_engine *e = make_engine(NULL);
    if (!e) return;
    sp_error err = {0};
    sp_query_opts mv = sp_query_opts_default();
    mv.method = SP_QUERY_MULTIVIEW;
    mv.heatmap = 0;
    sp_query_result a, b;
    CHECK_OK(sp_query_engine_query(e, "table", &mv, &a, &err), &err);
    CHECK_OK(sp_query_engine_query(e, "table", NULL, &b, &err), &err);
    CHECK(a.method == SP_QUERY_MULTIVIEW && !a.relevancy_image);
    CHECK(b.method == SP_QUERY_3D && b.relevancy_image); /* the defaults, untouched by the last call */
    CHECK(sp_query_engine_defaults(e)->method == SP_QUERY_3D);
    CHECK(!strcmp(b.source.encoder, "exact") && !strcmp(b.source.features, "labels") && b.source.ground_truth);
    CHECK(!strcmp(b.frame.name, "colmap") && !strcmp(b.frame.units, "unknown"));
    CHECK(strstr(sp_query_source_note(&b.source), "perfect 2D segmentation") != NULL);
    sp_query_result_free(&a);
    sp_query_result_free(&b);
    sp_query_opts bad = sp_query_opts_default();
    bad.method = 7;
    CHECK_FAILS(sp_query_engine_query(e, "table", &bad, &a, &err), SP_E_ARG, &err, "method 7");
    bad = sp_query_opts_default();
    bad.heatmap_view = NCAM;
    CHECK_FAILS(sp_query_engine_query(e, "table", &bad, &a, &err), SP_E_ARG, &err, "heatmap view");
    sp_query_engine_free(e);
}

static void test_relevancy_matches_reference(void)
{
    sp_query_engine *e = make_engine(NULL);
    if (!e) return;
    sp_error err = {0};
    size_t n = sp_query_engine_splat(e)->n;
    float *rel = malloc(sizeof(float) * n), *raw = malloc(sizeof(float) * n);
    float *ref_rel = malloc(sizeof(float) * n), *ref_raw = malloc(sizeof(float) * n);
    CHECK_OK(sp_query_engine_relevancy(e, "chair", rel, raw, &err), &err);
    /* reference: the scorer on the class embedding with the default negatives */
    float q[SC_FULL], neg[4][SC_FULL];
    const char *negs[4] = {"object", "things", "stuff", "texture"};
    sp_label_embedding("chair", SC_FULL, q);
    for (int k = 0; k < 4; k++) sp_label_embedding(negs[k], SC_FULL, neg[k]);
    sp_sem_scorer sc;
    CHECK_OK(sp_sem_scorer_init(&sc, &g_pca, q, &neg[0][0], 4, SP_SEM_DEFAULT_TEMPERATURE, &err), &err);
    sp_sem_score(&sc, NULL, n, g_splat.features, ref_raw, ref_rel);
    double worst = 0;
    for (size_t i = 0; i < n; i++) worst = fmax(worst, fmax(fabs(rel[i] - ref_rel[i]), fabs(raw[i] - ref_raw[i])));
    CHECK_MSG(worst < 1e-6, "relevancy differs from the scorer by %g", worst);
    CHECK_OK(sp_query_engine_relevancy(e, "chair", rel, NULL, &err), &err); /* raw optional */
    CHECK_FAILS(sp_query_engine_relevancy(e, "", rel, NULL, &err), SP_E_ARG, &err, "empty");
    free(rel), free(raw), free(ref_rel), free(ref_raw);
    sp_query_engine_free(e);
}

static void test_heatmap_any_camera(void)
{
    sp_query_engine *e = make_engine(NULL);
    if (!e) return;
    sp_error err = {0};
    sp_query_result res;
    CHECK_OK(sp_query_engine_query(e, "lamp", NULL, &res, &err), &err);
    CHECK(res.valid && res.view_index >= 0 && res.relevancy_image);
    if (res.view_index >= 0 && res.relevancy_image) {
        const sp_camera *cam = sp_query_engine_camera(e, (size_t)res.view_index);
        uint8_t *rgb = malloc((size_t)CW * CH * 3);
        float *rel = malloc(sizeof(float) * CW * CH);
        CHECK_OK(sp_query_engine_heatmap(e, "lamp", cam, rgb, rel, &err), &err);
        CHECK(!memcmp(rgb, res.relevancy_image, (size_t)CW * CH * 3));
        CHECK(!memcmp(rel, res.relevancy, sizeof(float) * CW * CH));
        /* a camera of our own: above the lamp looking down; hot in the middle */
        float c[3];
        sc_center(3, c);
        sp_camera top = *cam;
        sp_camera_look_at(&top, sp_v3(c[0] + 0.01f, c[1], 3.0f), sp_v3(c[0], c[1], c[2]), sp_v3(0, 1, 0));
        CHECK_OK(sp_query_engine_heatmap(e, "lamp", &top, rgb, rel, &err), &err);
        CHECK_MSG(rel[(CH / 2) * CW + CW / 2] > 0.9f, "centre relevancy %.3f", rel[(CH / 2) * CW + CW / 2]);
        CHECK(rel[0] < 0.6f);
        top.width = 0;
        CHECK_FAILS(sp_query_engine_heatmap(e, "lamp", &top, rgb, rel, &err), SP_E_ARG, &err, "camera");
        free(rgb), free(rel);
    }
    sp_query_result_free(&res);
    sp_query_engine_free(e);
}

typedef struct {
    sp_query_engine *e;
    int method, bad;
    float expect[2][3];
} worker_arg;

static void *worker(void *p)
{
    worker_arg *w = p;
    const char *texts[2] = {"table", "lamp"};
    sp_query_opts o = sp_query_opts_default();
    o.method = w->method;
    o.heatmap = 0;
    for (int r = 0; r < 20; r++) {
        sp_query_result res;
        sp_error err = {0};
        int t = r % 2;
        if (sp_query_engine_query(w->e, texts[t], &o, &res, &err) || !res.valid ||
            dist3(res.position, w->expect[t]) > 1e-6)
            w->bad++;
        sp_query_result_free(&res);
    }
    return NULL;
}

static void test_two_threads(void)
{
    sp_query_engine *e = make_engine(NULL);
    if (!e) return;
    worker_arg w[2] = {{e, SP_QUERY_3D, 0, {{0}}}, {e, SP_QUERY_MULTIVIEW, 0, {{0}}}};
    const char *texts[2] = {"table", "lamp"};
    for (int k = 0; k < 2; k++)
        for (int t = 0; t < 2; t++) { /* the serial answers */
            sp_query_opts o = sp_query_opts_default();
            o.method = w[k].method;
            o.heatmap = 0;
            sp_query_result res;
            sp_error err = {0};
            CHECK_OK(sp_query_engine_query(e, texts[t], &o, &res, &err), &err);
            memcpy(w[k].expect[t], res.position, sizeof w[k].expect[t]);
            sp_query_result_free(&res);
        }
    pthread_t th[2];
    for (int k = 0; k < 2; k++) CHECK(pthread_create(&th[k], NULL, worker, &w[k]) == 0);
    for (int k = 0; k < 2; k++) pthread_join(th[k], NULL);
    CHECK_MSG(w[0].bad == 0 && w[1].bad == 0, "wrong answers under two threads: %d, %d", w[0].bad, w[1].bad);
    sp_query_engine_free(e);
}

static void test_frame_moves_everything(void)
{
    sp_frame f;
    sp_frame_init(&f, "align");
    double M[16] = {0, -2, 0, 5, 2, 0, 0, 1, 0, 0, 2, 0.25, 0, 0, 0, 1}; /* 2 Rz(90) + (5, 1, 0.25) */
    memcpy(f.world_from_model, M, sizeof M);
    sp_query_engine *a = make_engine(NULL), *b = make_engine(&f);
    if (!a || !b) return;
    sp_error err = {0};
    for (int m = 0; m < 2; m++) {
        sp_query_opts o = sp_query_opts_default();
        o.method = m;
        o.voxel_m *= 2; /* the clustering voxel is in world units: keep it the same size in model units */
        sp_query_opts oa = sp_query_opts_default();
        oa.method = m;
        sp_query_result ra, rb;
        CHECK_OK(sp_query_engine_query(a, "table", &oa, &ra, &err), &err);
        CHECK_OK(sp_query_engine_query(b, "table", &o, &rb, &err), &err);
        float want[3];
        sp_frame_apply_point(&f, ra.position, want);
        CHECK_MSG(ra.valid && rb.valid && dist3(rb.position, want) < (m ? 0.1 : 1e-3),
                  "method %d: %.3f %.3f %.3f, expected %.3f %.3f %.3f", m, rb.position[0], rb.position[1],
                  rb.position[2], want[0], want[1], want[2]);
        CHECK(!strcmp(rb.frame.name, "world") && !strcmp(rb.frame.source, "align") && !strcmp(rb.frame.units, "m"));
        CHECK(rb.relevancy_image && rb.width == CW); /* view choice is in metres, so it may differ */
        sp_query_result_free(&ra);
        sp_query_result_free(&rb);
    }
    const sp_splat *sb = sp_query_engine_splat(b);
    float want[3];
    sp_frame_apply_point(&f, g_splat.means, want);
    CHECK(dist3(sb->means, want) < 1e-5);
    sp_vec3 ca = sp_camera_center(sp_query_engine_camera(a, 0)), cb = sp_camera_center(sp_query_engine_camera(b, 0));
    float caf[3] = {ca.x, ca.y, ca.z}, cbf[3] = {cb.x, cb.y, cb.z};
    sp_frame_apply_point(&f, caf, want);
    CHECK(dist3(cbf, want) < 1e-4);
    CHECK(!strcmp(sp_query_engine_frame(b)->source, "align"));
    sp_query_engine_free(b);
    /* a rigid frame (no scale): the same views and the same heatmap pixels */
    for (int i = 0; i < 12; i++) f.world_from_model[i] /= (i % 4 == 3) ? 1 : 2;
    b = make_engine(&f);
    sp_query_result ra, rb;
    CHECK_OK(sp_query_engine_query(a, "lamp", NULL, &ra, &err), &err);
    CHECK_OK(sp_query_engine_query(b, "lamp", NULL, &rb, &err), &err);
    CHECK(ra.view_index == rb.view_index && ra.relevancy_image && rb.relevancy_image);
    if (ra.view_index == rb.view_index && ra.relevancy_image && rb.relevancy_image) {
        size_t diff = 0;
        for (size_t p = 0; p < (size_t)CW * CH * 3; p++) diff += abs(ra.relevancy_image[p] - rb.relevancy_image[p]) > 2;
        CHECK_MSG(diff < 50, "%zu of %d heatmap values differ by more than 2", diff, CW * CH * 3);
    }
    sp_query_result_free(&ra);
    sp_query_result_free(&rb);
    sp_query_engine_free(a);
    sp_query_engine_free(b);
}

int main(void)
{
    int *cls;
    sc_make_pca(&g_pca, g_emb);
    sc_make_splat(&g_splat, &cls, &g_pca, g_emb);
    sc_make_cams(g_cams, NCAM, CW, CH);
    free(cls);
    sp_error err = {0};
    if (sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    RUN(test_options_per_call);
    RUN(test_relevancy_matches_reference);
    RUN(test_heatmap_any_camera);
    RUN(test_two_threads);
    RUN(test_frame_moves_everything);
    sp_device_free(g_dev);
    sp_splat_free(&g_splat);
    sp_sem_pca_free(&g_pca);
    return TEST_EXIT();
}
