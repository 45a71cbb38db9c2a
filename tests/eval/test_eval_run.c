/* semsplat eval end to end on a world nobody tuned on: the test writes the second small world,
 * renders a walk-only capture of it, trains a small splat, lifts label features, and runs
 * sp_eval_run_report; the reports (md, html with inline figures, json) hold every object of the
 * world, the ten vocabulary queries and the figures. Then the refrigerator is moved in a copy of
 * the world: the same model's report moves its ground truth by the offset and its error with it. */
#include <cjson/cJSON.h>

#include "eval/small_world.h"
#include "semsplat/clip.h"
#include "semsplat/eval.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "semsplat/synth.h"
#include "semsplat/train.h"
#include "test.h"

static sp_device *g_dev;
static char g_dir[1100], g_model[1200], g_world[1200];

static int build_model(sp_error *err)
{
    char cap[1200], feats[1200];
    snprintf(g_dir, sizeof g_dir, "%s", test_tmpdir("eval_run"));
    snprintf(g_world, sizeof g_world, "%s/small_flat.world", g_dir);
    snprintf(cap, sizeof cap, "%s/capture", g_dir);
    snprintf(g_model, sizeof g_model, "%s/model", g_dir);
    snprintf(feats, sizeof feats, "%s/features", g_dir);
    if (small_world_write(g_world, SMALL_WORLD_FRIDGE_X, SMALL_WORLD_FRIDGE_Y))
        return sp_error_set(err, SP_E_IO, "%s: cannot write", g_world);
    sp_synth_load_opts lo = {.no_env = 1};
    sp_world w;
    int rc = sp_synth_load_world(g_world, &lo, &w, err);
    if (rc) return rc;
    sp_synth_capture_opts co = {.n_views = 48, .width = 96, .height = 72, .n_points = 6000, .seed = 1,
                                .n_threads = 2, .plan = SP_SYNTH_PLAN_WALK};
    rc = sp_synth_capture(&w, cap, &co, err);
    sp_world_free(&w);
    if (rc) return rc;
    sp_train_model_opts t = sp_train_model_opts_default(400);
    t.colmap_dir = cap;
    t.out_dir = g_model;
    t.train.checkpoint_every = 0;
    sp_train_result tr;
    if ((rc = sp_train_model(g_dev, &t, &tr, NULL, err))) return rc;
    sp_features_opts f = sp_features_opts_default();
    f.colmap_dir = cap, f.out_dir = feats, f.source = "labels", f.dim = 16, f.dev = g_dev;
    if ((rc = sp_features_extract(&f, err))) return rc;
    return sp_semantic_lift_model(g_model, feats, cap, g_dev, NULL, err);
}

static const sp_eval_object *object(const sp_eval_run *r, const char *name)
{
    for (size_t i = 0; i < r->loc.n_objects; i++)
        if (!strcmp(r->loc.objects[i].name, name)) return &r->loc.objects[i];
    return NULL;
}

static void check_files(const char *out)
{
    char p[1300];
    sp_error err = {0};
    snprintf(p, sizeof p, "%s/report.json", out);
    cJSON *j = NULL;
    CHECK_OK(sp_json_read_file(p, &j, &err), &err);
    const cJSON *loc = cJSON_GetObjectItem(j, "localization"), *voc = cJSON_GetObjectItem(j, "vocabulary");
    CHECK(cJSON_IsArray(cJSON_GetObjectItem(loc, "objects")) &&
          cJSON_GetArraySize(cJSON_GetObjectItem(loc, "objects")) == 11);
    CHECK(cJSON_IsArray(voc) && cJSON_GetArraySize(voc) == 10);
    CHECK(!strcmp(cJSON_GetObjectItem(j, "capture_plan")->valuestring, "walk"));
    const cJSON *figs = cJSON_GetObjectItem(j, "figures"), *f;
    CHECK(cJSON_GetArraySize(figs) == 2);
    cJSON_ArrayForEach(f, figs)
    {
        sp_image im = {0};
        CHECK_OK(sp_image_read(f->valuestring, &im, &err), &err);
        CHECK(im.width == 1100 && im.height > 200);
        sp_image_free(&im);
    }
    cJSON_Delete(j);
    char *text = NULL;
    size_t n = 0;
    snprintf(p, sizeof p, "%s/report.html", out);
    CHECK_OK(sp_read_file(p, &text, &n, &err), &err);
    CHECK(text && strstr(text, "data:image/png;base64,iVBORw0KGgo") && strstr(text, "5.2 Open vs closed"));
    free(text);
    snprintf(p, sizeof p, "%s/report.md", out);
    CHECK_OK(sp_read_file(p, &text, &n, &err), &err);
    CHECK(text && strstr(text, "## 5.1 Object localization") && strstr(text, "Capture plan: `walk`") &&
          strstr(text, "(figures/localization.png)") && strstr(text, "**What this measures.**"));
    free(text);
}

static void test_eval_on_the_small_world(void)
{
    sp_error err = {0};
    CHECK_OK(build_model(&err), &err);
    if (err.code) return;
    char out[1300], moved[1300], out2[1300];
    snprintf(out, sizeof out, "%s/report", g_dir);
    sp_eval_run_opts o = {.model_dir = g_model, .world = g_world, .out_dir = out, .dev = g_dev, .no_navigation = 1};
    sp_eval_run r;
    CHECK_OK(sp_eval_run_report(&o, &r, &err), &err);
    if (err.code) return;
    CHECK(r.gt.n == 11 && r.loc.n_objects == 11 && r.n_vocab == 10);
    CHECK(!strcmp(r.vocab_encoder, "lexical"));
    fprintf(stderr, "small world: 3D recall %d/%d mean %.3f m; multi-view %d/%d mean %.3f m\n",
            r.loc.summary[0].matched, r.loc.summary[0].objects, r.loc.summary[0].mean_error_m,
            r.loc.summary[1].matched, r.loc.summary[1].objects, r.loc.summary[1].mean_error_m);
    CHECK(r.loc.summary[0].matched >= 6);
    const sp_eval_object *fr = object(&r, "refrigerator");
    CHECK(fr && fr->instance[0] >= 0 && fr->error_m[0] < 0.5f);
    check_files(out);
    float truth[3] = {NAN, NAN, NAN}, err0 = fr ? fr->error_m[0] : NAN, est[3];
    if (fr) memcpy(truth, fr->truth, sizeof truth), memcpy(est, fr->estimate[0], sizeof est);
    sp_eval_run_free(&r);
    /* the same model against a copy of the world whose refrigerator stands 1.5 m further along x */
    snprintf(moved, sizeof moved, "%s/moved.world", g_dir);
    CHECK(small_world_write(moved, SMALL_WORLD_FRIDGE_X + 1.5, SMALL_WORLD_FRIDGE_Y) == 0);
    snprintf(out2, sizeof out2, "%s/report_moved", g_dir);
    o.world = moved;
    o.out_dir = out2;
    CHECK_OK(sp_eval_run_report(&o, &r, &err), &err);
    if (err.code) return;
    fr = object(&r, "refrigerator");
    CHECK(fr != NULL);
    if (fr) {
        CHECK_NEAR(fr->truth[0] - truth[0], 1.5, 1e-4);
        CHECK_NEAR(fr->truth[1], truth[1], 1e-4);
        /* the splat still puts it where it was: 1.5 m from the new truth, beyond the match radius */
        CHECK(fr->instance[0] < 0);
        float d = sqrtf((est[0] - fr->truth[0]) * (est[0] - fr->truth[0]) + (est[1] - fr->truth[1]) * (est[1] - fr->truth[1]) +
                        (est[2] - fr->truth[2]) * (est[2] - fr->truth[2]));
        CHECK_MSG(fabsf(d - 1.5f) <= err0 + 1e-3f, "estimate %.2f m from the moved truth (was %.2f m)", d, err0);
    }
    sp_eval_run_free(&r);
    /* refusals */
    o.world = "/no/such.world";
    CHECK_FAILS(sp_eval_run_report(&o, &r, &err), SP_E_IO, &err, "no/such.world");
    o.world = g_world;
    o.queries = "/no/such/queries.json";
    CHECK_FAILS(sp_eval_run_report(&o, &r, &err), SP_E_IO, &err, "queries.json");
}

int main(void)
{
    sp_error err = {0};
    if (sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    RUN(test_eval_on_the_small_world);
    sp_device_free(g_dev);
    return TEST_EXIT();
}
