/* GPU query engine against the CPU one on the tiny labelled scene: per-Gaussian relevancy from
 * the CUDA kernel equals the host scorer, and every query gives the same answer. Skips without a
 * GPU (CI builds it with nvcc but runs it nowhere). */
#include <math.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"
#include "test.h"

static void test_gpu_engine_matches_cpu(void)
{
    float emb[SC_CLASSES][SC_FULL];
    sp_sem_pca pca;
    sc_make_pca(&pca, emb);
    sp_splat s;
    int *cls;
    sc_make_splat(&s, &cls, &pca, emb);
    sp_camera cams[12];
    sc_make_cams(cams, 12, 160, 120);
    sp_error err = {0};
    sp_device *cpu = NULL, *gpu = NULL;
    sp_query_engine *ec = NULL, *eg = NULL;
    CHECK_OK(sp_device_create(&cpu, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_device_create(&gpu, SP_DEVICE_CUDA, 2, &err), &err);
    sp_query_model qm = {.splat = &s, .pca = &pca, .cams = cams, .n_cams = 12};
    CHECK_OK(sp_query_engine_create(&ec, &qm, NULL, cpu, NULL, &err), &err);
    CHECK_OK(sp_query_engine_create(&eg, &qm, NULL, gpu, NULL, &err), &err);
    const char *texts[4] = {"table", "chair", "lamp", "refrigerator"};
    for (int m = 0; m < 2 && ec && eg; m++) {
        sp_query_opts qo = sp_query_opts_default();
        qo.method = m;
        for (int q = 0; q < 4; q++) {
            sp_query_result a, b;
            CHECK_OK(sp_query_engine_query(ec, texts[q], &qo, &a, &err), &err);
            CHECK_OK(sp_query_engine_query(eg, texts[q], &qo, &b, &err), &err);
            CHECK_NEAR(a.confidence, b.confidence, 1e-5);
            CHECK(a.valid == b.valid && a.n_instances == b.n_instances);
            if (a.valid && b.valid)
                for (int k = 0; k < 3; k++) CHECK_NEAR(a.position[k], b.position[k], m ? 0.02 : 1e-4);
            CHECK(b.relevancy_image != NULL);
            sp_query_result_free(&a);
            sp_query_result_free(&b);
        }
    }
    sp_query_engine_free(ec);
    sp_query_engine_free(eg);
    sp_device_free(cpu);
    sp_device_free(gpu);
    sp_splat_free(&s);
    sp_sem_pca_free(&pca);
    free(cls);
}

int main(void)
{
    if (!sp_cuda_available()) TEST_SKIP("no CUDA device");
    RUN(test_gpu_engine_matches_cpu);
    return TEST_EXIT();
}
