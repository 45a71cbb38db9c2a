/* The whole pipeline through library calls alone, on a small room (two crates, a table):
 * synth -> sp_train_model -> sp_features_extract (labels) -> sp_semantic_lift_model -> the query
 * engine -> sp_eval_localization. Checks the model folder (frame.json says the synth world),
 * the answers (each object found near its ground truth, one-to-one), the absent controls, and
 * that the demo runs the same stages through sp_demo_run and writes its report. */
#include <cjson/cJSON.h>
#include <math.h>

#include "pipeline_world.h"
#include "semsplat/clip.h"
#include "semsplat/eval.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "semsplat/synth.h"
#include "semsplat/train.h"
#include "test.h"

static sp_device *g_dev;

static int stage_synth(const char *world, const char *cap, sp_error *err)
{
    sp_synth_load_opts lo = {.no_env = 1};
    sp_world w;
    int rc = sp_synth_load_world(world, &lo, &w, err);
    if (rc) return rc;
    sp_synth_capture_opts co = {.n_views = 24, .width = 96, .height = 72, .n_points = 4000, .seed = 1,
                                .n_threads = 2};
    rc = sp_synth_capture(&w, cap, &co, err);
    sp_world_free(&w);
    return rc;
}

static void check_model_frame(const char *model)
{
    char p[1400];
    sp_frame f;
    sp_error err = {0};
    snprintf(p, sizeof p, "%s/frame.json", model);
    CHECK_OK(sp_frame_read(p, &f, &err), &err);
    CHECK(!strcmp(f.source, "synth") && sp_frame_is_world(&f) && !strcmp(f.units, "m"));
}

static void test_library_pipeline(void)
{
    char dir[1100], cap[1200], model[1200], feats[1200], gtp[1300];
    snprintf(dir, sizeof dir, "%s", test_tmpdir("pipeline_lib"));
    snprintf(cap, sizeof cap, "%s/capture", dir);
    snprintf(model, sizeof model, "%s/model", dir);
    snprintf(feats, sizeof feats, "%s/features", dir);
    sp_error err = {0};
    CHECK_OK(stage_synth(pipeline_world(dir), cap, &err), &err);
    sp_train_model_opts t = sp_train_model_opts_default(300);
    t.colmap_dir = cap;
    t.out_dir = model;
    t.train.checkpoint_every = 0;
    sp_train_result tr;
    CHECK_OK(sp_train_model(g_dev, &t, &tr, NULL, &err), &err);
    CHECK_MSG(tr.psnr > 18, "held-out PSNR %.2f dB", tr.psnr);
    check_model_frame(model);
    sp_features_opts f = sp_features_opts_default();
    f.colmap_dir = cap, f.out_dir = feats, f.source = "labels", f.dim = 16, f.dev = g_dev;
    CHECK_OK(sp_features_extract(&f, &err), &err);
    CHECK_OK(sp_semantic_lift_model(model, feats, cap, g_dev, NULL, &err), &err);

    sp_query_engine *e = NULL;
    CHECK_OK(sp_query_engine_open(&e, model, NULL, g_dev, NULL, &err), &err);
    if (!e) return;
    sp_ground_truth gt;
    snprintf(gtp, sizeof gtp, "%s/ground_truth.json", cap);
    CHECK_OK(sp_ground_truth_read(gtp, &gt, &err), &err);
    CHECK(gt.n == 3);
    sp_query_result res;
    CHECK_OK(sp_query_engine_query(e, "table", NULL, &res, &err), &err);
    CHECK(res.valid && !strcmp(res.frame.name, "world") && !strcmp(res.source.features, "labels"));
    for (size_t i = 0; i < gt.n && res.valid; i++)
        if (!strcmp(gt.objects[i].cls, "table"))
            CHECK_MSG(sp_eval_admissible(&gt.objects[i], res.position, 0.3f), "table at %.2f %.2f %.2f",
                      res.position[0], res.position[1], res.position[2]);
    sp_query_result_free(&res);
    sp_eval_report rep;
    sp_eval_opts eo = {0.3f, NULL, NULL, NULL};
    CHECK_OK(sp_eval_localization(e, &gt, &eo, &rep, &err), &err);
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        const sp_eval_summary *s = &rep.summary[m];
        CHECK_MSG(s->objects == 3 && s->matched == 3, "method %d: %d of %d objects matched", m, s->matched, s->objects);
        CHECK_MSG(s->mean_error_m < 0.3, "method %d: mean error %.3f m", m, s->mean_error_m);
        CHECK(s->absent > 0 && s->absent_rejected == s->absent);
        CHECK(s->classes == 2 && s->classes_correct == 2);
    }
    /* two crates, two matched instances: not one instance counted twice */
    for (size_t i = 0; i < rep.n_objects; i++) CHECK(rep.objects[i].instance[0] >= 0);
    if (rep.objects[1].instance[0] >= 0 && rep.objects[2].instance[0] >= 0)
        CHECK(strcmp(rep.objects[1].cls, rep.objects[2].cls) || rep.objects[1].instance[0] != rep.objects[2].instance[0]);
    sp_eval_report_free(&rep);
    sp_ground_truth_free(&gt);
    sp_query_engine_free(e);
}

static void test_demo_run(void)
{
    char dir[1100], out[1200], p[1400];
    snprintf(dir, sizeof dir, "%s", test_tmpdir("pipeline_demo"));
    snprintf(out, sizeof out, "%s/demo", dir);
    sp_demo_opts o = sp_demo_opts_default();
    o.out_dir = out;
    o.world = pipeline_world(dir);
    o.device = SP_DEVICE_CPU;
    o.threads = 2;
    o.views = 24, o.width = 96, o.height = 72, o.steps = 300, o.dim = 16, o.points = 4000;
    o.match_radius_m = 0.3f;
    sp_demo_result r;
    sp_error err = {0};
    CHECK_OK(sp_demo_run(&o, &r, &err), &err);
    CHECK(r.scored && r.trained && r.views == 24 && r.steps == 300);
    CHECK(r.report.summary[0].matched == 3 && r.report.summary[1].matched == 3);
    const char *files[4] = {"demo.json", "report.md", "heatmaps/table.png", "model/frame.json"};
    for (int k = 0; k < 4; k++) {
        snprintf(p, sizeof p, "%s/%s", out, files[k]);
        CHECK_MSG(sp_file_exists(p), "%s missing", p);
    }
    cJSON *j = NULL;
    snprintf(p, sizeof p, "%s/demo.json", out);
    CHECK_OK(sp_json_read_file(p, &j, &err), &err);
    cJSON *m3 = cJSON_GetObjectItem(cJSON_GetObjectItem(j, "methods"), "3d");
    CHECK(m3 && cJSON_GetObjectItem(m3, "matched")->valueint == 3);
    CHECK(!strcmp(cJSON_GetObjectItem(cJSON_GetObjectItem(j, "source"), "features")->valuestring, "labels"));
    CHECK(cJSON_GetObjectItem(cJSON_GetObjectItem(j, "demo"), "psnr") != NULL);
    cJSON_Delete(j);
    char *md = NULL;
    size_t n = 0;
    snprintf(p, sizeof p, "%s/report.md", out);
    CHECK_OK(sp_read_file(p, &md, &n, &err), &err);
    CHECK(md && strstr(md, "perfect 2D segmentation") && strstr(md, "one-to-one") && strstr(md, "## Pipeline"));
    free(md);
    sp_demo_result_free(&r);
    /* reuse: nothing is trained again, the same scores */
    o.reuse = 1;
    CHECK_OK(sp_demo_run(&o, &r, &err), &err);
    CHECK(r.scored && !r.trained && r.t_train == 0 && r.report.summary[0].matched == 3);
    sp_demo_result_free(&r);
}

int main(void)
{
    sp_error err = {0};
    if (sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    RUN(test_library_pipeline);
    RUN(test_demo_run);
    sp_device_free(g_dev);
    return TEST_EXIT();
}
