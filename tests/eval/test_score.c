/* The localization report's scoring on hand-made results: one-to-one (a duplicate instance of a
 * chair is a false instance, not a second hit), misses in recall and in the penalised mean,
 * precision with absent controls, medians, the class-level answer, and the text, Markdown and
 * JSON carrying the source caveat and the frame; ground_truth.json errors name the object. */
#include <cjson/cJSON.h>
#include <math.h>

#include "semsplat/eval.h"
#include "semsplat/io.h"
#include "test.h"

static sp_gt_object box(const char *name, const char *cls, float cx, float cy, float h)
{
    sp_gt_object o;
    memset(&o, 0, sizeof o);
    snprintf(o.name, sizeof o.name, "%s", name);
    snprintf(o.cls, sizeof o.cls, "%s", cls);
    float c[3] = {cx, cy, 0.4f};
    for (int a = 0; a < 3; a++) {
        o.center[a] = c[a];
        o.aabb_min[a] = c[a] - (a == 2 ? 0.4f : h);
        o.aabb_max[a] = c[a] + (a == 2 ? 0.4f : h);
    }
    return o;
}

/* A found result with instances at pos [n][3] (best first), kept in inst [8]. */
static sp_query_result result(const char *text, const float *pos, int n, sp_query_instance *inst)
{
    sp_query_result r;
    memset(&r, 0, sizeof r);
    snprintf(r.text, sizeof r.text, "%s", text);
    r.valid = n > 0;
    r.confidence = n > 0 ? 0.9f : 0.05f;
    r.n_instances = n;
    r.instances = inst;
    for (int k = 0; k < n; k++) memcpy(inst[k].position, pos + 3 * k, sizeof inst[k].position);
    for (int a = 0; a < 3; a++) r.position[a] = n ? pos[a] : NAN;
    snprintf(r.source.encoder, sizeof r.source.encoder, "exact");
    snprintf(r.source.features, sizeof r.source.features, "labels");
    r.source.ground_truth = 1;
    snprintf(r.frame.name, sizeof r.frame.name, "world");
    snprintf(r.frame.source, sizeof r.frame.source, "synth");
    r.ms_total = 10;
    return r;
}

static void test_scoring(void)
{
    sp_gt_object objs[4] = {box("chair_1", "chair", 0, 0, 0.25f), box("chair_2", "chair", 2, 0, 0.25f),
                            box("chair_3", "chair", 4, 0, 0.25f), box("table", "table", 0, 3, 0.5f)};
    sp_ground_truth gt = {4, objs, ""};
    const char *absent[] = {"piano", "table", NULL}; /* "table" is present: left out of the controls */
    sp_eval_report rep;
    sp_error err = {0};
    CHECK_OK(sp_eval_report_init(&rep, &gt, absent, 0.5f, &err), &err);
    CHECK(rep.n_queries == 3 && !strcmp(rep.queries[0].text, "chair") && rep.queries[0].n_objects == 3);
    CHECK(!strcmp(rep.queries[2].text, "piano") && !rep.queries[2].present);
    /* chairs: a hit on chair_1 (0.1 m off), a duplicate next to it, a hit on chair_2 (0.3 m), a
     * stray far away; chair_3 missed */
    float chairs[12] = {0.1f, 0, 0.4f, -0.2f, 0, 0.4f, 2.3f, 0, 0.4f, 9, 9, 0.4f};
    float table[3] = {0, 3.2f, 0.4f}, piano[3] = {5, 5, 0};
    for (int m = 0; m < 2; m++) {
        sp_query_instance ic[8], it[8], ip[8];
        sp_query_result rc = result("chair", chairs, 4, ic), rt = result("table", table, 1, it);
        sp_query_result rp = result("piano", piano, m, ip); /* found wrongly by method 1 only */
        CHECK_OK(sp_eval_report_add(&rep, &gt, 0, m, &rc, &err), &err);
        CHECK_OK(sp_eval_report_add(&rep, &gt, 1, m, &rt, &err), &err);
        CHECK_OK(sp_eval_report_add(&rep, &gt, 2, m, &rp, &err), &err);
    }
    sp_eval_report_finish(&rep);
    const sp_eval_summary *s = &rep.summary[0];
    CHECK(s->objects == 4 && s->matched == 3);
    CHECK_NEAR(s->recall, 0.75, 1e-9);
    CHECK(s->instances == 5 && s->true_instances == 3); /* 4 chair instances + 1 table */
    CHECK_NEAR(s->precision, 0.6, 1e-9);
    CHECK_NEAR(s->mean_error_m, (0.1 + 0.3 + 0.2) / 3, 1e-6);
    CHECK_NEAR(s->median_error_m, 0.2, 1e-6);
    double pen = sqrt(0.75 * 0.75 * 2 + 0.9 * 0.9); /* chair_3: centre to a corner of its grown box */
    CHECK_NEAR(s->mean_error_with_misses_m, (0.1 + 0.3 + 0.2 + pen) / 4, 1e-6);
    CHECK(s->classes == 2 && s->classes_found == 2 && s->classes_correct == 2);
    CHECK_NEAR(s->mean_query_error_m, (0.1 + 0.2) / 2, 1e-6);
    CHECK(s->absent == 1 && s->absent_rejected == 1);
    CHECK(rep.summary[1].absent_rejected == 0 && rep.summary[1].instances == 6);
    CHECK_NEAR(rep.summary[1].precision, 0.5, 1e-9);
    CHECK(rep.objects[2].instance[0] == -1 && isnan(rep.objects[2].error_m[0]));
    CHECK(rep.objects[0].instance[0] == 0 && rep.objects[1].instance[0] == 2);

    char *txt = sp_eval_report_text(&rep), *md = sp_eval_report_markdown(&rep, "t");
    CHECK(txt && strstr(txt, "perfect 2D segmentation") && strstr(txt, "frame: world") && strstr(txt, "miss"));
    CHECK(txt && strstr(txt, "recall 3/4") && strstr(txt, "by construction"));
    CHECK(md && strstr(md, "| 3D | 3/4 (0.750) | 3/5 (0.600) |") && strstr(md, "perfect 2D segmentation"));
    cJSON *j = sp_eval_report_json(&rep);
    cJSON *m3 = cJSON_GetObjectItem(cJSON_GetObjectItem(j, "methods"), "3d");
    CHECK(m3 && fabs(cJSON_GetObjectItem(m3, "recall")->valuedouble - 0.75) < 1e-9);
    CHECK(!strcmp(cJSON_GetObjectItem(cJSON_GetObjectItem(j, "source"), "encoder")->valuestring, "exact"));
    CHECK(!strcmp(cJSON_GetObjectItem(cJSON_GetObjectItem(j, "frame"), "name")->valuestring, "world"));
    cJSON *q0 = cJSON_GetArrayItem(cJSON_GetObjectItem(j, "queries"), 0);
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(cJSON_GetObjectItem(q0, "3d"), "instances")) == 4);
    cJSON_Delete(j);
    free(txt), free(md);
    sp_eval_report_free(&rep);
}

static void test_ground_truth_reader(void)
{
    const char *dir = test_tmpdir("eval_gt");
    char path[1200];
    snprintf(path, sizeof path, "%s/ground_truth.json", dir);
    sp_error err = {0};
    sp_ground_truth gt;
    const char *good = "{\"world\": \"w.world\", \"objects\": [{\"name\": \"a\", \"class\": \"chair\", "
                       "\"aabb_min\": [0,0,0], \"aabb_max\": [1,2,3]}]}";
    CHECK_OK(sp_write_file_atomic(path, good, strlen(good), &err), &err);
    CHECK_OK(sp_ground_truth_read(path, &gt, &err), &err);
    CHECK(gt.n == 1 && !strcmp(gt.objects[0].cls, "chair") && gt.objects[0].center[1] == 1.0f);
    sp_ground_truth_free(&gt);
    const char *bad[3] = {"{\"objects\": [{\"name\": \"a\", \"class\": \"c\", \"aabb_min\": [0,0], \"aabb_max\": [1,1,1]}]}",
                          "{\"objects\": [{\"name\": \"a\", \"class\": \"c\", \"aabb_min\": [2,0,0], \"aabb_max\": [1,1,1]}]}",
                          "{\"things\": []}"};
    const char *needle[3] = {"aabb_min", "aabb_min[0] > aabb_max[0]", "objects"};
    for (int k = 0; k < 3; k++) {
        CHECK_OK(sp_write_file_atomic(path, bad[k], strlen(bad[k]), &err), &err);
        CHECK_FAILS(sp_ground_truth_read(path, &gt, &err), SP_E_FORMAT, &err, needle[k]);
    }
}

int main(void)
{
    RUN(test_scoring);
    RUN(test_ground_truth_reader);
    return TEST_EXIT();
}
