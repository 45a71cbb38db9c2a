/* The query engine on a tiny labelled scene: both localizations find the table within a few
 * centimetres, the two chairs come back as two instances, absent classes give low confidence and
 * no position, the heatmap is hot on the object and is written as a PNG, and the JSON carries
 * what the CLI and the Python module promise. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"
#include "test.h"

enum { NCAM = 12, CW = 160, CH = 120 };

static sp_device *g_dev;
static sp_query_engine *g_eng;
static sp_query_opts g_opts; /* per-call options: each test sets what it needs */
static float g_emb[SC_CLASSES][SC_FULL];

static double dist3(const float *a, const float *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static void setup(void)
{
    sc_make_engine(NCAM, CW, CH, 2, g_emb, &g_dev, &g_eng);
    g_opts = sp_query_opts_default();
}

static void test_3d_finds_table_and_chairs(void)
{
    sp_query_result res;
    sp_error err = {0};
    g_opts.method = SP_QUERY_3D;
    CHECK_OK(sp_query_engine_query(g_eng, "table", &g_opts, &res, &err), &err);
    float c[3];
    sc_center(2, c);
    CHECK(res.valid);
    CHECK(res.confidence > 0.9f);
    CHECK_MSG(dist3(res.position, c) < 0.08, "table at %.3f %.3f %.3f", res.position[0], res.position[1], res.position[2]);
    CHECK(res.n_instances == 1);
    sp_query_result_free(&res);

    CHECK_OK(sp_query_engine_query(g_eng, "Chair", &g_opts, &res, &err), &err); /* case and spaces normalised */
    CHECK(res.valid);
    CHECK_MSG(res.n_instances == 2, "%d chair instances", res.n_instances);
    float c0[3], c1[3];
    sc_center(0, c0);
    sc_center(1, c1);
    for (int k = 0; k < res.n_instances && k < 2; k++) {
        double d = fmin(dist3(res.instances[k].position, c0), dist3(res.instances[k].position, c1));
        CHECK_MSG(d < 0.08, "chair instance %d off by %.3f m", k, d);
        CHECK(res.instances[k].n_points > 50);
    }
    if (res.n_instances == 2) /* two distinct chairs, not one twice */
        CHECK(dist3(res.instances[0].position, res.instances[1].position) > 1.5);
    sp_query_result_free(&res);
}

static void test_multiview_finds_table_and_lamp(void)
{
    sp_query_result res;
    sp_error err = {0};
    g_opts.method = SP_QUERY_MULTIVIEW;
    const int objs[2] = {2, 3};
    const char *names[2] = {"table", "lamp"};
    for (int q = 0; q < 2; q++) {
        CHECK_OK(sp_query_engine_query(g_eng, names[q], &g_opts, &res, &err), &err);
        float c[3];
        sc_center(objs[q], c);
        CHECK(res.valid && res.method == SP_QUERY_MULTIVIEW);
        CHECK(res.view_index >= 0 && res.view_index < NCAM);
        CHECK_MSG(dist3(res.position, c) < 0.15, "%s at %.3f %.3f %.3f (truth %.2f %.2f %.2f)", names[q],
                  res.position[0], res.position[1], res.position[2], c[0], c[1], c[2]);
        /* the stage breakdown: the CPU engine renders, scores and colours on the host (no copy) */
        const sp_query_stages *st = &res.ms_stage;
        CHECK(st->pick >= 0 && st->render > 0 && st->score > 0 && st->backproject >= 0 && st->cluster >= 0);
        CHECK(st->hm_render > 0 && st->hm_colormap > 0 && st->hm_copy == 0);
        CHECK(st->render + st->score + st->backproject + st->cluster + st->pick <= res.ms_localize + 1e-3);
        /* host_stages changes nothing on a CPU engine */
        sp_query_result h;
        g_opts.host_stages = 1;
        CHECK_OK(sp_query_engine_query(g_eng, names[q], &g_opts, &h, &err), &err);
        g_opts.host_stages = 0;
        CHECK(h.n_instances == res.n_instances && memcmp(h.position, res.position, sizeof h.position) == 0);
        CHECK(memcmp(h.relevancy_image, res.relevancy_image, (size_t)res.width * res.height * 3) == 0);
        sp_query_result_free(&h);
        sp_query_result_free(&res);
    }
    g_opts.method = SP_QUERY_3D;
}

static void test_absent_classes(void)
{
    const char *absent[] = {"refrigerator", "bathtub", "piano"};
    for (int m = 0; m < 2; m++) {
        g_opts.method = m ? SP_QUERY_MULTIVIEW : SP_QUERY_3D;
        for (int q = 0; q < 3; q++) {
            sp_query_result res;
            sp_error err = {0};
            CHECK_OK(sp_query_engine_query(g_eng, absent[q], &g_opts, &res, &err), &err);
            CHECK_MSG(!res.valid, "%s found (method %d)", absent[q], m);
            CHECK(isnan(res.position[0]));
            CHECK_MSG(res.confidence < 0.15f, "%s: confidence %.3f", absent[q], res.confidence);
            char *js = sp_query_result_json(&res, NULL);
            cJSON *o = cJSON_Parse(js);
            CHECK(o && cJSON_IsNull(cJSON_GetObjectItem(o, "position")));
            CHECK(o && cJSON_IsFalse(cJSON_GetObjectItem(o, "found")));
            cJSON_Delete(o);
            free(js);
            sp_query_result_free(&res);
        }
    }
    g_opts.method = SP_QUERY_3D;
}

static void test_heatmap_hot_on_object(void)
{
    sp_query_result res;
    sp_error err = {0};
    CHECK_OK(sp_query_engine_query(g_eng, "lamp", &g_opts, &res, &err), &err);
    CHECK(res.relevancy_image != NULL && res.width == CW && res.height == CH);
    CHECK(res.view_index >= 0);
    if (res.relevancy_image && res.view_index >= 0) {
        /* the lamp's centre projects into the chosen view, onto a hot (red > blue) pixel */
        const sp_camera *cam = sp_query_engine_camera(g_eng, (size_t)res.view_index);
        float c[3];
        sc_center(3, c);
        sp_vec3 x = sp_mat3_apply(cam->R, sp_v3(c[0], c[1], c[2]));
        float z = x.z + cam->t[2];
        int u = (int)(cam->fx * (x.x + cam->t[0]) / z + cam->cx), v = (int)(cam->fy * (x.y + cam->t[1]) / z + cam->cy);
        CHECK(u >= 0 && u < CW && v >= 0 && v < CH);
        if (u >= 0 && u < CW && v >= 0 && v < CH) {
            const uint8_t *p = res.relevancy_image + 3 * ((size_t)v * CW + u);
            CHECK_MSG(p[0] > p[2] + 60, "pixel %d,%d = %d %d %d", u, v, p[0], p[1], p[2]);
            CHECK(res.relevancy[(size_t)v * CW + u] > 0.9f);
        }
        /* a corner pixel (floor or background) is not hot */
        CHECK(res.relevancy[0] < 0.6f);
        const char *dir = test_tmpdir("semantic_heatmap");
        char path[1200];
        snprintf(path, sizeof path, "%s/lamp.png", dir);
        sp_image img = {res.width, res.height, 3, 8, res.relevancy_image};
        CHECK_OK(sp_image_write_png(path, &img, &err), &err);
        sp_image back = {0};
        CHECK_OK(sp_image_read(path, &back, &err), &err);
        CHECK(back.width == CW && back.height == CH && back.channels == 3);
        sp_image_free(&back);
    }
    char *js = sp_query_result_json(&res, "lamp.png");
    cJSON *o = cJSON_Parse(js);
    CHECK(o != NULL);
    cJSON *pos = cJSON_GetObjectItem(o, "position");
    CHECK(cJSON_GetArraySize(pos) == 3 && fabs(cJSON_GetArrayItem(pos, 0)->valuedouble - res.position[0]) < 1e-5);
    CHECK(fabs(cJSON_GetObjectItem(o, "confidence")->valuedouble - res.confidence) < 1e-6);
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(o, "instances")) == res.n_instances);
    CHECK(!strcmp(cJSON_GetObjectItem(o, "heatmap")->valuestring, "lamp.png"));
    cJSON_Delete(o);
    free(js);
    sp_query_result_free(&res);
    /* a given camera */
    g_opts.heatmap_view = 3;
    CHECK_OK(sp_query_engine_query(g_eng, "lamp", &g_opts, &res, &err), &err);
    CHECK(res.view_index == 3);
    sp_query_result_free(&res);
    g_opts.heatmap_view = -1;
}

static void test_embedding_query_and_bad_input(void)
{
    sp_query_result a, b;
    sp_error err = {0};
    float q[SC_FULL];
    CHECK_OK(sp_query_engine_embed(g_eng, "table", q, &err), &err);
    CHECK_OK(sp_query_engine_query_embedding(g_eng, q, "table", &g_opts, &a, &err), &err);
    CHECK_OK(sp_query_engine_query(g_eng, "table", &g_opts, &b, &err), &err);
    CHECK(a.valid && b.valid && dist3(a.position, b.position) < 1e-6);
    sp_query_result_free(&a);
    sp_query_result_free(&b);
    CHECK_FAILS(sp_query_engine_query(g_eng, "", &g_opts, &a, &err), SP_E_ARG, &err, "empty");
    snprintf(g_opts.negatives, sizeof g_opts.negatives, "a,b,c,d,e,f,g,h,i");
    CHECK_FAILS(sp_query_engine_query(g_eng, "table", &g_opts, &a, &err), SP_E_ARG, &err, "negatives");
    g_opts.negatives[0] = 0;
    sp_query_engine *e = NULL;
    CHECK_FAILS(sp_query_engine_open(&e, "/nonexistent/model", NULL, g_dev, NULL, &err), SP_E_NOTFOUND, &err,
                "semantic.json");
}

int main(void)
{
    setup();
    RUN(test_3d_finds_table_and_chairs);
    RUN(test_multiview_finds_table_and_lamp);
    RUN(test_absent_classes);
    RUN(test_heatmap_hot_on_object);
    RUN(test_embedding_query_and_bad_input);
    sp_query_engine_free(g_eng);
    sp_device_free(g_dev);
    return TEST_EXIT();
}
