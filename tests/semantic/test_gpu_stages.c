/* The semantic stages on the GPU (multi-view rendering in one batch, per-pixel scoring,
 * back-projection and compaction on the device; heatmaps rendered and coloured there) against
 * the same GPU engine's host stages (sp_query_opts.host_stages = 1: the renders downloaded and
 * scored, back-projected and coloured on the host, as CPU engines do), on the tiny labelled
 * scene: the same instances (positions, extents, weights, point counts) and the same heatmap up
 * to float rounding (the device's rsqrtf / expf in the scores). Skips without a GPU. */
#include <math.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"
#include "test.h"

/* Instances of the device stages (b) against the host stages' (a). */
static void same_instances(const sp_query_result *a, const sp_query_result *b)
{
    CHECK_MSG(a->valid == b->valid && a->n_instances == b->n_instances,
              "'%s': host stages %d instances (valid %d), device %d (valid %d)", a->text,
              a->n_instances, a->valid, b->n_instances, b->valid);
    CHECK(a->view_index == b->view_index);
    for (int k = 0; k < a->n_instances && k < b->n_instances; k++) {
        const sp_query_instance *x = &a->instances[k], *y = &b->instances[k];
        for (int c = 0; c < 3; c++) {
            CHECK_NEAR(x->position[c], y->position[c], 2e-3);
            CHECK_NEAR(x->extent_min[c], y->extent_min[c], 2e-3);
            CHECK_NEAR(x->extent_max[c], y->extent_max[c], 2e-3);
        }
        /* a pixel exactly at a threshold may go either way under a rounding difference */
        CHECK_MSG(abs(x->n_points - y->n_points) <= 2 + x->n_points / 200,
                  "'%s' instance %d: %d points on the host, %d on the device", a->text, k, x->n_points,
                  y->n_points);
        CHECK_NEAR(x->score, y->score, 1e-3 * fmax(1.0, fabs(x->score)));
        CHECK_NEAR(x->confidence, y->confidence, 1e-5);
    }
}

/* Heatmaps: relevancy within float rounding, colours within one step (rounding at .5). */
static void same_heatmap(const sp_query_result *a, const sp_query_result *b)
{
    CHECK(a->relevancy_image && b->relevancy_image && a->relevancy && b->relevancy);
    CHECK(a->width == b->width && a->height == b->height && a->view_index == b->view_index);
    if (!a->relevancy_image || !b->relevancy_image || a->width != b->width || a->height != b->height) return;
    size_t np = (size_t)a->width * a->height, off = 0;
    double worst_rel = 0;
    int worst_px = 0;
    for (size_t p = 0; p < np; p++) {
        worst_rel = fmax(worst_rel, fabs(a->relevancy[p] - b->relevancy[p]));
        int d = 0;
        for (int c = 0; c < 3; c++) {
            int dc = abs(a->relevancy_image[3 * p + c] - b->relevancy_image[3 * p + c]);
            if (dc > d) d = dc;
        }
        off += d > 0;
        if (d > worst_px) worst_px = d;
    }
    fprintf(stderr, "  '%s' heatmap %dx%d: relevancy differs by %.2g at most, %zu pixels' colour by "
            "%d at most\n", a->text, a->width, a->height, worst_rel, off, worst_px);
    CHECK(worst_rel < 1e-5);
    CHECK(worst_px <= 1 && off <= np / 100);
}

static void test_device_stages_match_host_stages(void)
{
    float emb[SC_CLASSES][SC_FULL];
    sp_sem_pca pca;
    sc_make_pca(&pca, emb);
    sp_splat s;
    int *cls;
    sc_make_splat(&s, &cls, &pca, emb);
    enum { NC = 12 };
    sp_camera cams[NC];
    sc_make_cams(cams, NC, 320, 240);
    sp_error err = {0};
    sp_device *gpu = NULL;
    sp_query_engine *e = NULL;
    CHECK_OK(sp_device_create(&gpu, SP_DEVICE_CUDA, 2, &err), &err);
    sp_query_model qm = {.splat = &s, .pca = &pca, .cams = cams, .n_cams = NC};
    CHECK_OK(sp_query_engine_create(&e, &qm, NULL, gpu, NULL, &err), &err);
    const char *texts[5] = {"table", "chair", "lamp", "floor", "refrigerator"};
    for (int m = 0; m < 2 && e; m++) {
        sp_query_opts qo = sp_query_opts_default();
        qo.method = m ? SP_QUERY_MULTIVIEW : SP_QUERY_3D;
        for (int q = 0; q < 5; q++) {
            sp_query_result a, b;
            qo.host_stages = 1;
            CHECK_OK(sp_query_engine_query(e, texts[q], &qo, &a, &err), &err);
            qo.host_stages = 0;
            CHECK_OK(sp_query_engine_query(e, texts[q], &qo, &b, &err), &err);
            fprintf(stderr, "  %s '%s': %d instances, device stages: render %.2f score %.2f "
                    "back-project %.2f ms, heatmap render %.2f colour %.2f copy %.2f ms\n",
                    m ? "multi-view" : "3D", texts[q], b.n_instances, b.ms_stage.render,
                    b.ms_stage.score, b.ms_stage.backproject, b.ms_stage.hm_render,
                    b.ms_stage.hm_colormap, b.ms_stage.hm_copy);
            same_instances(&a, &b);
            same_heatmap(&a, &b);
            /* the device path copied the image: its stage says so */
            CHECK(b.ms_stage.hm_copy > 0 && a.ms_stage.hm_copy == 0);
            sp_query_result_free(&a);
            sp_query_result_free(&b);
        }
    }
    /* the engine's heatmap call (default options: device stages) against a host-stage query's */
    if (e) {
        size_t np = (size_t)cams[3].width * cams[3].height;
        uint8_t *img = malloc(np * 3);
        float *rel = malloc(np * sizeof(float));
        CHECK_OK(sp_query_engine_heatmap(e, "chair", &cams[3], img, rel, &err), &err);
        sp_query_opts qo = sp_query_opts_default();
        qo.host_stages = 1;
        qo.heatmap_view = 3;
        sp_query_result a, b;
        CHECK_OK(sp_query_engine_query(e, "chair", &qo, &a, &err), &err);
        b = a;
        b.relevancy_image = img, b.relevancy = rel;
        same_heatmap(&a, &b);
        sp_query_result_free(&a);
        free(img), free(rel);
    }
    sp_query_engine_free(e);
    sp_device_free(gpu);
    sp_splat_free(&s);
    sp_sem_pca_free(&pca);
    free(cls);
}

int main(void)
{
    if (!sp_cuda_available()) TEST_SKIP("no CUDA device");
    RUN(test_device_stages_match_host_stages);
    return TEST_EXIT();
}
