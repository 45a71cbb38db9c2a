/* semsplat demo: the whole pipeline on the bundled house (or a capture you give):
 * synth -> train -> features -> lift -> a query for every ground-truth class with both
 * localization methods, scored against ground_truth.json, with heatmaps and a report. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

int cmd_synth(int argc, char **argv) __attribute__((weak));
int cmd_train(int argc, char **argv) __attribute__((weak));
int cmd_features(int argc, char **argv) __attribute__((weak));
int cmd_lift(int argc, char **argv) __attribute__((weak));

/* Classes that are not in the house: their queries must come back unconfident. */
static const char *const absent_classes[] = {"fire extinguisher", "piano", "bicycle"};

static const char *usage_text =
    "usage: semsplat demo [--out DIR] [--world W.world] [--model-path DIR] [--capture DIR]\n"
    "                     [--views N] [--size WxH] [--steps N] [--dim D] [--device cpu|cuda|auto]\n"
    "                     [--clip MODEL.safetensors] [--skip-missing] [--reuse] [--quiet]\n\n"
    "Runs synth -> train -> features -> lift -> queries and writes DIR (default demo/):\n"
    "  capture/ (COLMAP model, images, depth, labels, ground_truth.json), model/ (splat.ply with\n"
    "  f_sem_* features, train.json, semantic.json), features/, heatmaps/<class>.png,\n"
    "  demo.json and report.md (per-object localization errors for both methods).\n"
    "Defaults: the bundled house (data/worlds/house.world); on a GPU 150 views at 640x480 and\n"
    "7000 steps, on the CPU 48 views at 320x240 and 2000 steps. --capture DIR skips synth and\n"
    "uses an existing capture (features then need --clip unless it has labels/). --reuse skips\n"
    "the stages whose outputs already exist in DIR (to re-run only the queries, say).\n";

typedef struct {
    char name[128], cls[128];
    float center[3];
} gt_object;

static int load_ground_truth(const char *path, gt_object **objs, int *n, sp_error *err)
{
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    cJSON *arr = cJSON_GetObjectItem(root, "objects");
    int count = cJSON_IsArray(arr) ? cJSON_GetArraySize(arr) : -1;
    if (count < 0) {
        cJSON_Delete(root);
        return sp_error_set(err, SP_E_FORMAT, "%s: no \"objects\" array", path);
    }
    *objs = calloc((size_t)(count ? count : 1), sizeof **objs);
    *n = 0;
    cJSON *o;
    cJSON_ArrayForEach(o, arr)
    {
        cJSON *nm = cJSON_GetObjectItem(o, "name"), *cl = cJSON_GetObjectItem(o, "class"),
              *c = cJSON_GetObjectItem(o, "aabb_center");
        if (!cJSON_IsString(nm) || !cJSON_IsString(cl) || !cJSON_IsArray(c) ||
            cJSON_GetArraySize(c) != 3) {
            free(*objs);
            cJSON_Delete(root);
            return sp_error_set(err, SP_E_FORMAT, "%s: object %d lacks name/class/aabb_center",
                                path, *n);
        }
        gt_object *g = &(*objs)[(*n)++];
        snprintf(g->name, sizeof g->name, "%s", nm->valuestring);
        snprintf(g->cls, sizeof g->cls, "%s", cl->valuestring);
        for (int k = 0; k < 3; k++) g->center[k] = (float)cJSON_GetArrayItem(c, k)->valuedouble;
    }
    cJSON_Delete(root);
    return SP_OK;
}

static float dist3(const float *a, const float *b)
{
    float dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrtf(dx * dx + dy * dy + dz * dz);
}

/* Per-object error: the distance from each ground-truth object of the class to the nearest
 * instance the query returned (so several chairs are scored as several objects). */
static float object_error(const sp_query_result *r, const float *center)
{
    float best = INFINITY;
    if (!r->valid) return best;
    for (int i = 0; i < r->n_instances; i++) {
        float d = dist3(r->instances[i].position, center);
        if (d < best) best = d;
    }
    return best;
}

static void slug(const char *text, char *out, size_t cap)
{
    size_t j = 0;
    for (size_t i = 0; text[i] && j + 1 < cap; i++) {
        char c = text[i];
        out[j++] = ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) ? c : '_';
    }
    out[j] = 0;
}

/* Appends to a fixed report buffer, clamping so a long report is cut rather than overrun. */
static void md_append(char *md, size_t cap, size_t *n, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void md_append(char *md, size_t cap, size_t *n, const char *fmt, ...)
{
    if (*n + 1 >= cap) return;
    va_list ap;
    va_start(ap, fmt);
    int w = vsnprintf(md + *n, cap - *n, fmt, ap);
    va_end(ap);
    if (w > 0) *n = *n + (size_t)w < cap - 1 ? *n + (size_t)w : cap - 1;
}

static int run_step(const char *what, int (*fn)(int, char **), int argc, char **argv)
{
    if (!fn) {
        fprintf(stderr, "semsplat demo: '%s' is not built into this binary\n", what);
        return 1;
    }
    fprintf(stderr, "\n== demo: %s ==\n", what);
    int rc = fn(argc, argv);
    if (rc) fprintf(stderr, "semsplat demo: step '%s' failed (exit %d)\n", what, rc);
    return rc;
}

typedef struct {
    const char *out, *world, *model_path, *capture, *clip, *device;
    long views, steps, dim;
    int width, height, quiet, skip_missing, reuse;
} demo_opts;

/* With --reuse, a stage whose output already exists is skipped (re-run queries after a change). */
static int done_before(const demo_opts *o, const char *dir, const char *file)
{
    char p[1400];
    snprintf(p, sizeof p, "%s/%s", dir, file);
    return o->reuse && sp_file_exists(p);
}

static int parse(int argc, char **argv, demo_opts *o)
{
    int bad = 0;
    const char *v;
    for (int i = 1; i < argc && !bad; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(usage_text, stdout);
            return -1;
        } else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) o->out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--world", &bad))) o->world = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model-path", &bad))) o->model_path = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--capture", &bad))) o->capture = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--clip", &bad))) o->clip = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) o->device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--views", &bad))) {
            if (cli_parse_int("demo", "--views", v, &o->views)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--steps", &bad))) {
            if (cli_parse_int("demo", "--steps", v, &o->steps)) return 2;
            if (o->steps < 1) return cli_usage_error("demo", "--steps %ld: expected at least 1", o->steps);
        } else if ((v = cli_flag_value(argc, argv, &i, "--dim", &bad))) {
            if (cli_parse_int("demo", "--dim", v, &o->dim)) return 2;
            if (o->dim < 1) return cli_usage_error("demo", "--dim %ld: expected at least 1", o->dim);
        } else if ((v = cli_flag_value(argc, argv, &i, "--size", &bad))) {
            if (cli_parse_size("demo", "--size", v, &o->width, &o->height)) return 2;
        } else if (!strcmp(argv[i], "--quiet")) o->quiet = 1;
        else if (!strcmp(argv[i], "--skip-missing")) o->skip_missing = 1;
        else if (!strcmp(argv[i], "--reuse")) o->reuse = 1;
        else if (!bad) return cli_usage_error("demo", "unknown flag '%s'", argv[i]);
    }
    return bad ? 2 : 0;
}

int cmd_demo(int argc, char **argv)
{
    static char world_default[1200];
    snprintf(world_default, sizeof world_default, "%s/worlds/house.world", sp_data_dir());
    demo_opts o = {"demo", world_default, NULL, NULL, NULL, "auto", 0, 0, 32, 0, 0, 0, 0, 0};
    int prc = parse(argc, argv, &o);
    if (prc) return prc < 0 ? 0 : prc;

    int gpu = strcmp(o.device, "cpu") != 0 && sp_cuda_available();
    if (!strcmp(o.device, "cuda") && !gpu) {
        fprintf(stderr, "semsplat demo: error: --device cuda, but no usable GPU was found\n");
        return 1;
    }
    if (!o.views) o.views = gpu ? 150 : 48;
    if (!o.steps) o.steps = gpu ? 7000 : 2000;
    if (!o.width) {
        o.width = gpu ? 640 : 320;
        o.height = gpu ? 480 : 240;
    }
    sp_error err = {0};
    if (sp_mkdirs(o.out, &err)) return cli_fail("demo", &err);
    char capture[1100], model[1100], feats[1100], heat[1100], path[1200];
    snprintf(capture, sizeof capture, "%s/capture", o.out);
    snprintf(model, sizeof model, "%s/model", o.out);
    snprintf(feats, sizeof feats, "%s/features", o.out);
    snprintf(heat, sizeof heat, "%s/heatmaps", o.out);
    if (o.capture) snprintf(capture, sizeof capture, "%s", o.capture);
    char views_s[32], steps_s[32], size_s[64], dim_s[32];
    snprintf(views_s, sizeof views_s, "%ld", o.views);
    snprintf(steps_s, sizeof steps_s, "%ld", o.steps);
    snprintf(size_s, sizeof size_s, "%dx%d", o.width, o.height);
    snprintf(dim_s, sizeof dim_s, "%ld", o.dim);
    double t0 = sp_time_now(), t_synth = 0, t_train = 0, t_feat = 0, t_lift = 0;

    if (!o.capture && !done_before(&o, capture, "ground_truth.json")) {
        char *a[16] = {"synth", "--world", (char *)o.world, "--out", capture, "--views", views_s,
                       "--size", size_s};
        int n = 9;
        if (o.model_path) { a[n++] = "--model-path"; a[n++] = (char *)o.model_path; }
        if (o.skip_missing) a[n++] = "--skip-missing";
        if (o.quiet) a[n++] = "--quiet";
        double t = sp_time_now();
        if (run_step("synth", cmd_synth, n, a)) return 1;
        t_synth = sp_time_now() - t;
    }
    if (!done_before(&o, model, "train.json")) {
        char *a[16] = {"train", "--colmap", capture, "--out", model, "--steps", steps_s,
                       "--device", (char *)o.device};
        int n = 9;
        if (o.quiet) a[n++] = "--quiet";
        double t = sp_time_now();
        if (run_step("train", cmd_train, n, a)) return 1;
        t_train = sp_time_now() - t;
    }
    if (!done_before(&o, feats, "features.json")) {
        snprintf(path, sizeof path, "%s/labels", capture);
        int labels = sp_file_exists(path);
        if (!labels && !o.clip) {
            fprintf(stderr, "semsplat demo: error: %s has no labels/ folder, so features need CLIP "
                            "weights: pass --clip model.safetensors (see README)\n", capture);
            return 1;
        }
        char *a[20] = {"features", "--colmap", capture, "--out", feats, "--dim", dim_s,
                       "--source", labels && !o.clip ? "labels" : "clip", "--device",
                       (char *)o.device};
        int n = 11;
        if (o.clip) { a[n++] = "--clip"; a[n++] = (char *)o.clip; }
        if (o.quiet) a[n++] = "--quiet";
        double t = sp_time_now();
        if (run_step("features", cmd_features, n, a)) return 1;
        t_feat = sp_time_now() - t;
    }
    if (!done_before(&o, model, "semantic.json")) {
        char *a[12] = {"lift", "--model", model, "--features", feats, "--colmap", capture,
                       "--device", (char *)o.device};
        int n = 9;
        if (o.quiet) a[n++] = "--quiet";
        double t = sp_time_now();
        if (run_step("lift", cmd_lift, n, a)) return 1;
        t_lift = sp_time_now() - t;
    }

    /* ---- queries against ground truth ---- */
    fprintf(stderr, "\n== demo: queries ==\n");
    gt_object *gt = NULL;
    int n_gt = 0;
    snprintf(path, sizeof path, "%s/ground_truth.json", capture);
    if (!sp_file_exists(path)) {
        /* A real capture has no ground truth: the model is ready, there is nothing to score. */
        printf("%s has no ground_truth.json, so there is nothing to score; the model is ready:\n"
               "  semsplat query --model %s \"refrigerator\" --heatmap fridge.png\n", capture, model);
        return 0;
    }
    if (load_ground_truth(path, &gt, &n_gt, &err)) return cli_fail("demo", &err);
    if (sp_mkdirs(heat, &err)) return cli_fail("demo", &err);
    sp_device *dev = NULL;
    if (sp_device_create(&dev, gpu ? SP_DEVICE_CUDA : SP_DEVICE_CPU, 0, &err)) return cli_fail("demo", &err);
    sp_query_opts qo = sp_query_opts_default();
    sp_query_engine *eng = NULL;
    sp_log log = sp_log_stderr(SP_LOG_INFO, o.quiet);
    if (sp_query_engine_open(&eng, model, &qo, dev, &log, &err)) {
        sp_device_free(dev);
        free(gt);
        return cli_fail("demo", &err);
    }

    /* Distinct classes in ground-truth order, then the absent ones. */
    const char *classes[256];
    int n_cls = 0;
    for (int i = 0; i < n_gt && n_cls < 250; i++) {
        int seen = 0;
        for (int j = 0; j < n_cls; j++) seen |= !strcmp(classes[j], gt[i].cls);
        if (!seen) classes[n_cls++] = gt[i].cls;
    }
    int n_present = n_cls;
    for (size_t i = 0; i < sizeof absent_classes / sizeof *absent_classes; i++)
        classes[n_cls++] = absent_classes[i];

    cJSON *report = cJSON_CreateObject(), *jq = cJSON_AddArrayToObject(report, "queries");
    char md[65536];
    size_t mdn = 0;
    md_append(md, sizeof md, &mdn, "# semsplat demo report\n\n| query | object | confidence | error 3D (m) | "
                            "error multi-view (m) | instances | heatmap |\n|---|---|---|---|---|---|---|\n");
    double sum_err[2] = {0, 0}, sum_q[2] = {0, 0};
    int n_q[2] = {0, 0};
    int n_err[2] = {0, 0}, found[2] = {0, 0}, absent_ok = 0;
    printf("%-22s %-22s %6s %9s %9s %5s\n", "query", "object", "conf", "err3d_m", "errmv_m", "inst");
    for (int c = 0; c < n_cls; c++) {
        sp_query_result res[2];
        memset(res, 0, sizeof res);
        int ok = 1;
        for (int m = 0; m < 2 && ok; m++) {
            sp_query_opts *mo = sp_query_engine_opts(eng);
            mo->method = m ? SP_QUERY_MULTIVIEW : SP_QUERY_3D;
            mo->heatmap = m == 0;
            if (sp_query_engine_query(eng, classes[c], &res[m], &err)) ok = 0;
        }
        if (!ok) {
            fprintf(stderr, "semsplat demo: query '%s' failed: %s\n", classes[c], err.msg);
            continue;
        }
        char hp[1400] = "", sl[200];
        slug(classes[c], sl, sizeof sl);
        if (res[0].relevancy_image) {
            sp_image img = {res[0].width, res[0].height, 3, 8, res[0].relevancy_image};
            snprintf(hp, sizeof hp, "%s/%s.png", heat, sl);
            if (sp_image_write_png(hp, &img, &err)) hp[0] = 0;
        }
        cJSON *q = cJSON_CreateObject();
        cJSON_AddStringToObject(q, "query", classes[c]);
        cJSON_AddBoolToObject(q, "present", c < n_present);
        cJSON_AddNumberToObject(q, "confidence", res[0].confidence);
        cJSON_AddBoolToObject(q, "valid_3d", res[0].valid);
        cJSON_AddBoolToObject(q, "valid_multiview", res[1].valid);
        cJSON_AddNumberToObject(q, "instances", res[0].n_instances);
        cJSON_AddStringToObject(q, "heatmap", hp);
        cJSON *jo = cJSON_AddArrayToObject(q, "objects");
        if (c >= n_present) {
            int quiet_ok = !res[0].valid && !res[1].valid;
            absent_ok += quiet_ok;
            printf("%-22s %-22s %6.3f %9s %9s %5d  (absent: %s)\n", classes[c], "-",
                   res[0].confidence, "-", "-", res[0].n_instances,
                   quiet_ok ? "not found, as it should" : "FOUND, wrongly");
            md_append(md, sizeof md, &mdn, "| %s | (absent) | %.3f | %s | %s | %d | |\n",
                                    classes[c], res[0].confidence, res[0].valid ? "found" : "-",
                                    res[1].valid ? "found" : "-", res[0].n_instances);
        } else {
            for (int m = 0; m < 2; m++) {
                found[m] += res[m].valid;
                /* Query error: the returned position to the nearest object of its class. */
                float qe = INFINITY;
                for (int i = 0; i < n_gt && res[m].valid; i++)
                    if (!strcmp(gt[i].cls, classes[c])) qe = fminf(qe, dist3(res[m].position, gt[i].center));
                if (isfinite(qe)) { sum_q[m] += qe; n_q[m]++; }
                cJSON_AddNumberToObject(q, m ? "query_error_multiview_m" : "query_error_3d_m", isfinite(qe) ? qe : -1);
            }
            for (int i = 0; i < n_gt; i++) {
                if (strcmp(gt[i].cls, classes[c])) continue;
                float e[2] = {object_error(&res[0], gt[i].center), object_error(&res[1], gt[i].center)};
                for (int m = 0; m < 2; m++)
                    if (isfinite(e[m])) { sum_err[m] += e[m]; n_err[m]++; }
                cJSON *jx = cJSON_CreateObject();
                cJSON_AddStringToObject(jx, "name", gt[i].name);
                cJSON_AddNumberToObject(jx, "error_3d_m", isfinite(e[0]) ? e[0] : -1);
                cJSON_AddNumberToObject(jx, "error_multiview_m", isfinite(e[1]) ? e[1] : -1);
                cJSON_AddItemToArray(jo, jx);
                printf("%-22s %-22s %6.3f %9.3f %9.3f %5d\n", classes[c], gt[i].name,
                       res[0].confidence, e[0], e[1], res[0].n_instances);
                md_append(md, sizeof md, &mdn, "| %s | %s | %.3f | %.3f | %.3f | %d | %s |\n",
                                        classes[c], gt[i].name, res[0].confidence, e[0], e[1],
                                        res[0].n_instances, hp);
            }
        }
        cJSON_AddItemToArray(jq, q);
        sp_query_result_free(&res[0]);
        sp_query_result_free(&res[1]);
    }
    double mean3d = n_err[0] ? sum_err[0] / n_err[0] : NAN, meanmv = n_err[1] ? sum_err[1] / n_err[1] : NAN;
    double q3d = n_q[0] ? sum_q[0] / n_q[0] : NAN, qmv = n_q[1] ? sum_q[1] / n_q[1] : NAN;
    int n_abs = n_cls - n_present;
    printf("\nclasses found: 3D %d/%d, multi-view %d/%d; absent queries rejected: %d/%d\n"
           "mean query error (returned position -> nearest object of the class, over classes): "
           "3D %.3f m, multi-view %.3f m\n"
           "mean instance error (every object -> nearest returned instance, over objects): "
           "3D %.3f m, multi-view %.3f m\n", found[0], n_present, found[1], n_present, absent_ok,
           n_abs, q3d, qmv, mean3d, meanmv);
    printf("times: synth %.1f s, train %.1f s, features %.1f s, lift %.1f s, total %.1f s\n",
           t_synth, t_train, t_feat, t_lift, sp_time_now() - t0);
    md_append(md, sizeof md, &mdn, "\nClasses found: 3D %d/%d, multi-view %d/%d. Absent queries rejected: %d/%d.\n"
                            "Mean query error (returned position to the nearest object of the class): "
                            "3D %.3f m, multi-view %.3f m.\nMean instance error (each object to the "
                            "nearest returned instance): 3D %.3f m, multi-view %.3f m.\n",
                            found[0], n_present, found[1], n_present, absent_ok, n_abs, q3d, qmv,
                            mean3d, meanmv);
    cJSON_AddNumberToObject(report, "classes", n_present);
    cJSON_AddNumberToObject(report, "found_3d", found[0]);
    cJSON_AddNumberToObject(report, "found_multiview", found[1]);
    cJSON_AddNumberToObject(report, "mean_query_error_3d_m", isfinite(q3d) ? q3d : -1);
    cJSON_AddNumberToObject(report, "mean_query_error_multiview_m", isfinite(qmv) ? qmv : -1);
    cJSON_AddNumberToObject(report, "mean_error_3d_m", isfinite(mean3d) ? mean3d : -1);
    cJSON_AddNumberToObject(report, "mean_error_multiview_m", isfinite(meanmv) ? meanmv : -1);
    cJSON_AddNumberToObject(report, "absent_rejected", absent_ok);
    cJSON_AddNumberToObject(report, "seconds_total", sp_time_now() - t0);
    snprintf(path, sizeof path, "%s/demo.json", o.out);
    int rc = sp_json_write_file(path, report, &err);
    if (!rc) {
        snprintf(path, sizeof path, "%s/report.md", o.out);
        rc = sp_write_file_atomic(path, md, mdn, &err);
    }
    cJSON_Delete(report);
    sp_query_engine_free(eng);
    sp_device_free(dev);
    free(gt);
    if (rc) return cli_fail("demo", &err);
    printf("wrote %s/demo.json, %s/report.md and heatmaps in %s\n", o.out, o.out, heat);
    return 0;
}
