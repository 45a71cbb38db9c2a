/* The model-folder path end to end on the tiny scene: a capture (COLMAP model) and a feature
 * folder (features.json, PCA, f16 maps at half resolution, written here as `semsplat features`
 * writes them), a trained-model folder (splat.ply without features, train.json naming the
 * capture) -> sp_semantic_lift_model -> f_sem_* in splat.ply + semantic.json -> the engine opens
 * the folder and finds the objects; bad folders give named errors. */
#include <cjson/cJSON.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "test.h"

enum { N = 12, W = 160, H = 120, MW = 80, MH = 60 };

static int write_capture(const char *dir, const sp_camera *cams, sp_error *err)
{
    char path[1400];
    snprintf(path, sizeof path, "%s/sparse/0", dir);
    return sc_write_colmap(path, cams, N, W, H, "%05d.png", err);
}

/* A model folder's semantic part as made elsewhere: DIR/semantic.json naming the PCA files,
 * semantic_pca_mean.npy [F] and semantic_pca_basis.npy [D][F]; model NULL = label embedding. */
static int write_sidecar(const char *dir, int D, int F, const float *mean, const float *basis,
                         const char *model, sp_error *err)
{
    char path[1400];
    size_t s1[1] = {(size_t)F}, s2[2] = {(size_t)D, (size_t)F};
    snprintf(path, sizeof path, "%s/semantic_pca_mean.npy", dir);
    int rc = sp_npy_write(path, SP_DTYPE_F32, 1, s1, mean, err);
    snprintf(path, sizeof path, "%s/semantic_pca_basis.npy", dir);
    if (!rc) rc = sp_npy_write(path, SP_DTYPE_F32, 2, s2, basis, err);
    if (rc) return rc;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "source", model ? "clip" : "labels");
    cJSON_AddStringToObject(o, "pca_mean", "semantic_pca_mean.npy");
    cJSON_AddStringToObject(o, "pca_basis", "semantic_pca_basis.npy");
    cJSON_AddStringToObject(o, "label_embedding", model ? "clip" : "hash");
    if (model) cJSON_AddStringToObject(o, "model", model);
    snprintf(path, sizeof path, "%s/semantic.json", dir);
    rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
    return rc;
}

static void test_lift_model_folder_then_query(void)
{
    const char *root = test_tmpdir("semantic_model");
    char cap[1200], feat[1200], model[1200], path[1400];
    snprintf(cap, sizeof cap, "%s/capture", root);
    snprintf(feat, sizeof feat, "%s/features", root);
    snprintf(model, sizeof model, "%s/model", root);
    float emb[SC_CLASSES][SC_FULL];
    sp_sem_pca pca;
    sc_make_pca(&pca, emb);
    sp_splat s;
    int *cls;
    sc_make_splat(&s, &cls, &pca, emb);
    sp_camera cams[N];
    sc_make_cams(cams, N, W, H);
    sp_error err = {0};
    CHECK_OK(write_capture(cap, cams, &err), &err);
    CHECK_OK(sc_write_features(feat, &s, &pca, cams, N, NULL, &err), &err);
    /* the trained model: geometry only, and train.json naming the capture */
    sp_splat geo;
    CHECK_OK(sp_splat_copy(&geo, &s, &err), &err);
    sp_free(geo.features);
    geo.features = NULL;
    geo.feat_dim = 0;
    CHECK_OK(sp_mkdirs(model, &err), &err);
    snprintf(path, sizeof path, "%s/splat.ply", model);
    CHECK_OK(sp_ply_write_splat(path, &geo, &err), &err);
    cJSON *tj = cJSON_CreateObject(), *set = cJSON_AddObjectToObject(tj, "settings");
    cJSON_AddStringToObject(set, "colmap", cap);
    snprintf(path, sizeof path, "%s/train.json", model);
    CHECK_OK(sp_json_write_file(path, tj, &err), &err);
    cJSON_Delete(tj);

    sp_device *dev = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_semantic_lift_model(model, feat, NULL, dev, NULL, &err), &err);
    sp_splat back;
    snprintf(path, sizeof path, "%s/splat.ply", model);
    CHECK_OK(sp_ply_read_splat(path, &back, &err), &err);
    CHECK(back.feat_dim == SC_DIM && back.n == s.n);
    sp_splat_free(&back);
    cJSON *sj = NULL;
    snprintf(path, sizeof path, "%s/semantic.json", model);
    CHECK_OK(sp_json_read_file(path, &sj, &err), &err);
    CHECK(sj && !strcmp(cJSON_GetObjectItem(sj, "method")->valuestring, "lift"));
    CHECK(sj && !strcmp(cJSON_GetObjectItem(sj, "source")->valuestring, "labels"));
    CHECK(sj && cJSON_GetObjectItem(sj, "dim")->valueint == SC_DIM);
    cJSON_Delete(sj);

    sp_query_engine *e = NULL;
    CHECK_OK(sp_query_engine_open(&e, model, NULL, dev, NULL, &err), &err);
    if (e) {
        CHECK(sp_query_engine_n_cameras(e) == N);
        const char *names[3] = {"table", "lamp", "chair"};
        const int objs[3] = {2, 3, 0};
        for (int q = 0; q < 3; q++) {
            sp_query_result res;
            CHECK_OK(sp_query_engine_query(e, names[q], NULL, &res, &err), &err);
            float c[3];
            sc_center(objs[q], c);
            double best = 1e9;
            for (int k = 0; k < res.n_instances; k++) {
                double d = 0;
                for (int a = 0; a < 3; a++) d += (res.instances[k].position[a] - c[a]) * (res.instances[k].position[a] - c[a]);
                best = fmin(best, sqrt(d));
            }
            CHECK_MSG(res.valid && best < 0.1, "%s: nearest instance %.3f m away", names[q], best);
            CHECK(!strncmp(res.view_name, "000", 3)); /* views named from the COLMAP model */
            sp_query_result_free(&res);
        }
        sp_query_engine_free(e);
    }
    /* bad inputs name what is wrong */
    CHECK_FAILS(sp_semantic_lift_model(model, "/nonexistent/features", cap, dev, NULL, &err), SP_E_IO, &err,
                "features.json");
    snprintf(path, sizeof path, "%s/train.json", model);
    remove(path);
    CHECK_FAILS(sp_semantic_lift_model(model, feat, NULL, dev, NULL, &err), SP_E_ARG, &err, "--colmap");
    snprintf(path, sizeof path, "%s/semantic_pca_basis.npy", model);
    remove(path);
    CHECK(sp_query_engine_open(&e, model, NULL, dev, NULL, &err) != 0);
    CHECK(strstr(err.msg, "semantic_pca_basis.npy") != NULL);
    sp_device_free(dev);
    sp_splat_free(&s);
    sp_splat_free(&geo);
    sp_sem_pca_free(&pca);
    free(cls);
}

/* Features in a CLIP space: the engine embeds text with the CLIP text tower named in the sidecar
 * (here the tiny random CLIP fixture, 32-dim); a sidecar whose features do not match the model's
 * embedding size is refused with a message naming both. */
static void test_clip_text_tower_sidecar(void)
{
    const char *dir = test_tmpdir("semantic_clip_sidecar");
    char path[1400], model[1200];
    snprintf(model, sizeof model, "%s/tests/fixtures/clip/tiny/model.safetensors", SP_SOURCE_DIR);
    if (!sp_file_exists(model)) {
        fprintf(stderr, "no tiny CLIP fixture: case skipped\n");
        return;
    }
    enum { F = 32, D = 8, NG = 200 };
    test_rng r = {11};
    float mean[F], basis[D * F];
    memset(basis, 0, sizeof basis);
    for (int j = 0; j < F; j++) mean[j] = (float)test_range(&r, -0.1, 0.1);
    for (int k = 0; k < D; k++) basis[k * F + k] = 1.0f;
    sp_splat s;
    sp_error err = {0};
    CHECK_OK(sp_splat_alloc(&s, NG, 0, D, &err), &err);
    for (size_t i = 0; i < NG * 3; i++) s.means[i] = (float)test_range(&r, -1, 1);
    for (size_t i = 0; i < NG * 3; i++) s.log_scales[i] = -3.0f;
    for (size_t i = 0; i < NG; i++) s.opacity_logits[i] = 2.0f;
    for (size_t i = 0; i < NG * D; i++) s.features[i] = (float)test_range(&r, -1, 1);
    snprintf(path, sizeof path, "%s/splat.ply", dir);
    CHECK_OK(sp_ply_write_splat(path, &s, &err), &err);
    CHECK_OK(write_sidecar(dir, D, F, mean, basis, model, &err), &err);
    sp_device *dev = NULL;
    sp_query_engine *e = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_query_engine_open(&e, dir, NULL, dev, NULL, &err), &err);
    if (e) {
        float a[F], b[F];
        CHECK_OK(sp_query_engine_embed(e, "a red mug", a, &err), &err);
        sp_clip *c = NULL;
        const char *t = "a red mug";
        CHECK_OK(sp_clip_load(&c, model, NULL, NULL, &err), &err);
        if (c) {
            CHECK_OK(sp_clip_encode_text(c, &t, 1, b, &err), &err);
            double worst = 0;
            for (int j = 0; j < F; j++) worst = fmax(worst, fabs(a[j] - b[j]));
            CHECK_NEAR(worst, 0, 1e-6);
            sp_clip_free(c);
        }
        sp_query_result res;
        CHECK_OK(sp_query_engine_query(e, "a red mug", NULL, &res, &err), &err);
        CHECK(res.confidence > -1.0f && res.confidence <= 1.0f);
        sp_query_result_free(&res);
        sp_query_engine_free(e);
    }
    /* a 64-dim feature space with a 32-dim CLIP: refused, naming both sizes */
    sp_splat_free(&s);
    float mean2[64] = {0}, basis2[D * 64];
    memset(basis2, 0, sizeof basis2);
    for (int k = 0; k < D; k++) basis2[k * 64 + k] = 1.0f;
    CHECK_OK(write_sidecar(dir, D, 64, mean2, basis2, model, &err), &err);
    CHECK_OK(sp_query_engine_open(&e, dir, NULL, dev, NULL, &err), &err);
    if (e) {
        sp_query_result res;
        CHECK_FAILS(sp_query_engine_query(e, "mug", NULL, &res, &err), SP_E_FORMAT, &err, "64");
        sp_query_engine_free(e);
    }
    sp_device_free(dev);
}

static int lift_zero(void *user, size_t view, float *target, uint8_t *mask, sp_error *err)
{
    (void)user, (void)view, (void)mask, (void)err, (void)target;
    return 0;
}

/* One limit on the feature dimension for every stage (64, what the query engine scores):
 * lifting refuses more, and a model folder with more is refused by the engine with a message
 * that names the value and the limit (it used to say "got ndim 2"). */
static void test_feature_dim_limit(void)
{
    const char *dir = test_tmpdir("semantic_dim_limit");
    enum { D = 65, F = 512, NG = 50 };
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    sp_splat s;
    test_rng rng = {5};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    CHECK_OK(sp_splat_alloc(&s, NG, 0, 0, &err), &err);
    for (size_t i = 0; i < NG * 3; i++) s.means[i] = (float)test_range(&rng, -1, 1);
    for (size_t i = 0; i < NG * 3; i++) s.log_scales[i] = -3.0f;
    sp_camera cam;
    sc_make_cams(&cam, 1, 32, 24);
    CHECK_FAILS(sp_semantic_lift(r, &s, D, &cam, 1, lift_zero, NULL, NULL, NULL, NULL, &err), SP_E_ARG, &err, "65");
    CHECK_MSG(strstr(err.msg, "limit of 64") != NULL, "message '%s' does not name the limit", err.msg);
    sp_splat_free(&s);
    /* a model folder made elsewhere with 65-dim features */
    CHECK_OK(sp_splat_alloc(&s, NG, 0, D, &err), &err);
    for (size_t i = 0; i < NG * 3; i++) s.means[i] = (float)test_range(&rng, -1, 1);
    char path[1400];
    snprintf(path, sizeof path, "%s/splat.ply", dir);
    CHECK_OK(sp_ply_write_splat(path, &s, &err), &err);
    static float mean[F], basis[D * F];
    for (int k = 0; k < D; k++) basis[k * F + k] = 1.0f;
    CHECK_OK(write_sidecar(dir, D, F, mean, basis, NULL, &err), &err);
    sp_query_engine *e = NULL;
    CHECK_FAILS(sp_query_engine_open(&e, dir, NULL, dev, NULL, &err), SP_E_FORMAT, &err, "65");
    CHECK_MSG(strstr(err.msg, "limit of 64") != NULL && !strstr(err.msg, "ndim"),
              "message '%s' does not name the value and the limit", err.msg);
    CHECK(e == NULL);
    sp_splat_free(&s);
    sp_raster_free(r);
    sp_device_free(dev);
}

int main(void)
{
    RUN(test_lift_model_folder_then_query);
    RUN(test_clip_text_tower_sidecar);
    RUN(test_feature_dim_limit);
    return TEST_EXIT();
}
