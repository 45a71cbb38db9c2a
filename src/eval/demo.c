/* The demo: the whole pipeline on the bundled house (or a given capture) through library calls,
 * synth -> train -> features -> lift -> the localization report, with demo.json and report.md. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_internal.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/nav.h"

sp_demo_opts sp_demo_opts_default(void)
{
    sp_demo_opts o;
    memset(&o, 0, sizeof o);
    o.out_dir = "demo";
    o.device = SP_DEVICE_AUTO;
    o.dim = 32;
    o.depth_lambda = SP_DEMO_DEPTH_LAMBDA;
    return o;
}

void sp_demo_result_free(sp_demo_result *res)
{
    if (!res) return;
    sp_eval_report_free(&res->report);
    memset(res, 0, sizeof *res);
}

/* With reuse, a stage whose output already exists is skipped (re-run the queries after a change). */
static int done_before(const sp_demo_opts *o, const char *dir, const char *file)
{
    char p[1400];
    snprintf(p, sizeof p, "%s/%s", dir, file);
    return o->reuse && sp_file_exists(p);
}

/* The GPU settings when the device is a GPU, the CPU ones (smaller, minutes on 2 cores) else. */
static void settle(const sp_demo_opts *o, sp_device *dev, sp_demo_result *r)
{
    int gpu = sp_device_kind_of(dev) == SP_DEVICE_CUDA;
    r->views = o->views > 0 ? o->views : gpu ? 150 : 48;
    r->steps = o->steps > 0 ? o->steps : gpu ? 7000 : 2000;
    r->width = o->width > 0 ? o->width : gpu ? 640 : 320;
    r->height = o->height > 0 ? o->height : gpu ? 480 : 240;
    r->plan = o->plan != SP_DEMO_PLAN_AUTO ? o->plan : o->walk_only ? SP_DEMO_PLAN_WALK : SP_DEMO_PLAN_MIXED;
    snprintf(r->device, sizeof r->device, "%s", sp_device_name(dev));
    snprintf(r->capture_dir, sizeof r->capture_dir, "%s/capture", o->out_dir);
    if (o->capture) snprintf(r->capture_dir, sizeof r->capture_dir, "%s", o->capture);
    snprintf(r->model_dir, sizeof r->model_dir, "%s/model", o->out_dir);
    snprintf(r->features_dir, sizeof r->features_dir, "%s/features", o->out_dir);
    snprintf(r->heatmap_dir, sizeof r->heatmap_dir, "%s/heatmaps", o->out_dir);
}

static int stage_train(const sp_demo_opts *o, sp_device *dev, sp_demo_result *r, sp_error *err)
{
    sp_train_model_opts t = sp_train_model_opts_default(r->steps);
    t.colmap_dir = r->capture_dir;
    t.out_dir = r->model_dir;
    t.downscale = o->downscale > 0 ? o->downscale : 1;
    /* Depth supervision where the capture measured depth (a synth capture always; an outside
     * one may not): the trained geometry is what the costmap is built from. */
    char depth[1200];
    snprintf(depth, sizeof depth, "%s/depth", r->capture_dir);
    if (o->depth_lambda > 0 && sp_file_exists(depth)) t.train.depth_lambda = o->depth_lambda;
    else if (o->depth_lambda > 0)
        sp_logf(o->log, SP_LOG_WARN, "demo: %s has no depth/: training on RGB only", r->capture_dir);
    int rc = sp_train_model(dev, &t, &r->train, o->log, err);
    r->trained = rc == 0;
    return rc ? sp_error_prefix(err, "demo: train: ") : 0;
}

static int stage_features(const sp_demo_opts *o, sp_device *dev, sp_demo_result *r, sp_error *err)
{
    char labels[1200];
    snprintf(labels, sizeof labels, "%s/labels", r->capture_dir);
    int have_labels = sp_file_exists(labels);
    if (!have_labels && !o->clip)
        return sp_error_set(err, SP_E_NOTFOUND, "demo: %s has no labels/ folder, so features need CLIP "
                            "weights (a CLIP model.safetensors; see README)", r->capture_dir);
    sp_features_opts f = sp_features_opts_default();
    f.colmap_dir = r->capture_dir;
    f.out_dir = r->features_dir;
    f.source = have_labels && !o->clip ? "labels" : "clip";
    f.clip_weights = o->clip;
    f.dim = o->dim > 0 ? o->dim : 32;
    f.dev = dev;
    f.log = o->log;
    int rc = sp_features_extract(&f, err);
    return rc ? sp_error_prefix(err, "demo: features: ") : 0;
}

/* Runs the stages whose outputs are missing (or all without reuse), timing each. */
static int run_stages(const sp_demo_opts *o, sp_device *dev, sp_demo_result *r, sp_error *err)
{
    double t;
    int rc = 0;
    if (!o->capture && !done_before(o, r->capture_dir, "ground_truth.json")) {
        sp_logf(o->log, SP_LOG_INFO, "demo: synth %s -> %s (%d views at %dx%d)", o->world, r->capture_dir,
                r->views, r->width, r->height);
        t = sp_time_now();
        rc = ev_demo_synth(o, r->capture_dir, r->views, r->width, r->height, r->plan, err);
        if (rc) return sp_error_prefix(err, "demo: synth: ");
        r->t_synth = sp_time_now() - t;
    }
    if (!done_before(o, r->model_dir, "train.json")) {
        sp_logf(o->log, SP_LOG_INFO, "demo: train %d steps on %s", r->steps, r->device);
        t = sp_time_now();
        if ((rc = stage_train(o, dev, r, err))) return rc;
        r->t_train = sp_time_now() - t;
    }
    if (!done_before(o, r->features_dir, "features.json")) {
        sp_logf(o->log, SP_LOG_INFO, "demo: features");
        t = sp_time_now();
        if ((rc = stage_features(o, dev, r, err))) return rc;
        r->t_features = sp_time_now() - t;
    }
    if (!done_before(o, r->model_dir, "semantic.json")) {
        sp_logf(o->log, SP_LOG_INFO, "demo: lift");
        t = sp_time_now();
        rc = sp_semantic_lift_model(r->model_dir, r->features_dir, r->capture_dir, dev, o->log, err);
        if (rc) return sp_error_prefix(err, "demo: lift: ");
        r->t_lift = sp_time_now() - t;
    }
    return 0;
}

static cJSON *demo_json(const sp_demo_result *r)
{
    cJSON *j = sp_eval_report_json(&r->report);
    if (!j) return NULL;
    cJSON *d = cJSON_AddObjectToObject(j, "demo");
    cJSON_AddStringToObject(d, "capture", r->capture_dir);
    cJSON_AddStringToObject(d, "model", r->model_dir);
    cJSON_AddStringToObject(d, "device", r->device);
    cJSON_AddNumberToObject(d, "views", r->views);
    cJSON_AddNumberToObject(d, "steps", r->steps);
    cJSON_AddNumberToObject(d, "width", r->width);
    cJSON_AddNumberToObject(d, "height", r->height);
    if (r->trained) {
        cJSON_AddNumberToObject(d, "psnr", r->train.psnr);
        cJSON_AddNumberToObject(d, "gaussians", (double)r->train.gaussians);
    }
    cJSON *t = cJSON_AddObjectToObject(d, "seconds");
    cJSON_AddNumberToObject(t, "synth", r->t_synth);
    cJSON_AddNumberToObject(t, "train", r->t_train);
    cJSON_AddNumberToObject(t, "features", r->t_features);
    cJSON_AddNumberToObject(t, "lift", r->t_lift);
    cJSON_AddNumberToObject(t, "queries", r->t_queries);
    cJSON_AddNumberToObject(t, "video", r->t_video);
    if (r->have_video) {
        cJSON *v = cJSON_AddObjectToObject(d, "video");
        cJSON_AddStringToObject(v, "path", r->video.path);
        cJSON_AddStringToObject(v, "robot", r->video.robot);
        cJSON_AddNumberToObject(v, "commands", r->video.n_commands);
        cJSON_AddNumberToObject(v, "arrived", r->video.n_arrived);
        cJSON_AddNumberToObject(v, "frames", (double)r->video.frames);
        cJSON_AddNumberToObject(v, "seconds", r->video.seconds);
    }
    cJSON_AddNumberToObject(t, "total", r->t_total);
    return j;
}

static int write_outputs(const sp_demo_opts *o, const sp_demo_result *r, sp_error *err)
{
    char path[1200];
    cJSON *j = demo_json(r);
    char *md = sp_eval_report_markdown(&r->report, "semsplat demo report");
    int rc = !j || !md ? sp_error_set(err, SP_E_NOMEM, "demo: out of memory writing the report") : 0;
    sp_strbuf b = {0};
    if (!rc) {
        sp_strbuf_printf(&b, "%s\n## Pipeline\n\n%d views at %dx%d, %d training steps on %s", md, r->views,
                         r->width, r->height, r->steps, r->device);
        if (r->trained) sp_strbuf_printf(&b, "; held-out PSNR %.2f dB, %zu Gaussians", r->train.psnr, r->train.gaussians);
        sp_strbuf_printf(&b, ".\nSeconds: synth %.1f, train %.1f, features %.1f, lift %.1f, queries %.1f, "
                         "video %.1f, total %.1f (0 = reused).\n", r->t_synth, r->t_train, r->t_features, r->t_lift,
                         r->t_queries, r->t_video, r->t_total);
        if (r->have_video)
            sp_strbuf_printf(&b, "\nVideo: %s, %.1f s (%ld frames), %d of %d commands arrived; robot: %s.\n",
                             r->video.path, r->video.seconds, r->video.frames, r->video.n_arrived,
                             r->video.n_commands, r->video.robot);
        if (b.failed) rc = sp_error_set(err, SP_E_NOMEM, "demo: out of memory writing the report");
    }
    snprintf(path, sizeof path, "%s/demo.json", o->out_dir);
    if (!rc) rc = sp_json_write_file(path, j, err);
    snprintf(path, sizeof path, "%s/report.md", o->out_dir);
    if (!rc) rc = sp_write_file_atomic(path, b.data, b.len, err);
    sp_strbuf_free(&b);
    free(md);
    cJSON_Delete(j);
    return rc;
}

static int score(const sp_demo_opts *o, sp_device *dev, sp_demo_result *r, sp_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/ground_truth.json", r->capture_dir);
    if (!sp_file_exists(path)) return 0; /* a real capture: the model is ready, nothing to score */
    sp_ground_truth gt;
    int rc = sp_ground_truth_read(path, &gt, err);
    if (rc) return rc;
    sp_query_engine *e = NULL;
    double t = sp_time_now();
    rc = sp_query_engine_open(&e, r->model_dir, NULL, dev, o->log, err);
    sp_eval_opts eo = {.match_radius_m = o->match_radius_m, .heatmap_dir = r->heatmap_dir, .log = o->log};
    if (!rc) rc = sp_eval_localization(e, &gt, &eo, &r->report, err);
    r->t_queries = sp_time_now() - t;
    r->scored = rc == 0;
    sp_query_engine_free(e);
    sp_ground_truth_free(&gt);
    return rc;
}

/* Three commands driven end to end through the agent and the simulated robot, as a video. */
static int stage_video(const sp_demo_opts *o, sp_device *dev, sp_demo_result *r, sp_error *err)
{
    sp_demo_video_opts v = sp_demo_video_opts_default();
    sp_nav_opts nav;
    sp_eval_drive_map_opts(&nav);
    v.drive.nav = &nav;
    v.drive.model_dir = r->model_dir;
    v.drive.out_dir = o->out_dir;
    v.drive.robot = o->robot;
    v.drive.time_scale = o->time_scale;
    v.drive.dev = dev;
    v.drive.log = o->log;
    v.width = o->video_width, v.height = o->video_height, v.fps = o->fps, v.drive_frames = o->drive_frames;
    v.view_width = o->view_width, v.view_height = o->view_height;
    sp_logf(o->log, SP_LOG_INFO, "demo: video of three commands -> %s/demo.mp4", o->out_dir);
    double t = sp_time_now();
    sp_error e = {0};
    int rc = sp_demo_video(&v, &r->video, &e);
    r->t_video = sp_time_now() - t;
    r->have_video = rc == 0;
    if (rc == SP_E_NOMEM || (rc && o->model)) return *err = e, rc; /* only the video was asked for */
    /* The report stands without it (a model too small to navigate, no FFmpeg): said, not fatal. */
    if (rc) snprintf(r->video_error, sizeof r->video_error, "%s", e.msg);
    if (rc) sp_logf(o->log, SP_LOG_WARN, "demo: no video: %s", e.msg);
    return SP_OK;
}

int sp_demo_run(const sp_demo_opts *opts, sp_demo_result *r, sp_error *err)
{
    memset(r, 0, sizeof *r);
    sp_demo_opts o = *opts;
    char world[1200];
    if (!o.out_dir) o.out_dir = "demo";
    if (!o.world) {
        snprintf(world, sizeof world, "%s/worlds/house.world", sp_data_dir());
        o.world = world;
    }
    if (o.capture && !sp_file_exists(o.capture))
        return sp_error_set(err, SP_E_NOTFOUND, "demo: capture %s does not exist", o.capture);
    double t0 = sp_time_now();
    sp_device *dev = NULL;
    int rc = sp_device_create(&dev, o.device, o.threads, err);
    if (rc) return rc;
    settle(&o, dev, r);
    rc = sp_mkdirs(o.out_dir, err);
    if (o.model) snprintf(r->model_dir, sizeof r->model_dir, "%s", o.model);
    if (!rc && !o.model) rc = run_stages(&o, dev, r, err);
    if (!rc && !o.model) rc = score(&o, dev, r, err);
    r->t_total = sp_time_now() - t0;
    if (!rc && r->scored) rc = write_outputs(&o, r, err); /* the report stands even if the video fails */
    if (!rc && !o.no_video && (r->scored || o.model)) rc = stage_video(&o, dev, r, err); /* a capture of ours */
    r->t_total = sp_time_now() - t0;
    if (!rc && r->scored && r->have_video) rc = write_outputs(&o, r, err);
    sp_device_free(dev);
    if (rc) sp_eval_report_free(&r->report);
    return rc;
}
