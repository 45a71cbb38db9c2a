/* A model folder from a capture: load the views, initialise (COLMAP points, random, or a splat
 * PLY, or a checkpoint), train, and write splat.ply, train.json, frame.json and checkpoints.
 * What `semsplat train` and the demo run. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/io.h"
#include "semsplat/train.h"

sp_train_model_opts sp_train_model_opts_default(int steps)
{
    sp_train_model_opts o;
    memset(&o, 0, sizeof o);
    o.downscale = 1;
    o.test_every = 8;
    o.init = SP_TRAIN_INIT_POINTS;
    o.init_points = 100000;
    o.train = sp_train_options_default(steps);
    return o;
}

static int init_splat(sp_splat *s, const sp_train_data *d, const sp_train_model_opts *o,
                      const sp_log *log, sp_error *err)
{
    int deg = o->train.sh_degree;
    if (o->init == SP_TRAIN_INIT_PLY) {
        if (!o->init_ply) return sp_error_set(err, SP_E_ARG, "train: init from a PLY, but no init_ply given");
        int rc = sp_ply_read_splat(o->init_ply, s, err);
        if (!rc && s->n == 0) rc = sp_error_set(err, SP_E_FORMAT, "%s: the splat is empty", o->init_ply);
        if (!rc) sp_logf(log, SP_LOG_INFO, "starting from %s: %zu Gaussians", o->init_ply, s->n);
        return rc;
    }
    if (o->init == SP_TRAIN_INIT_RANDOM || d->n_points == 0) {
        if (o->init != SP_TRAIN_INIT_RANDOM)
            sp_logf(log, SP_LOG_WARN, "the COLMAP model has no points3D: using random init");
        if (o->init_points < 1) return sp_error_set(err, SP_E_ARG, "train: init_points must be >= 1");
        return sp_train_init_random(s, d, o->init_points, 3.0f, deg, o->train.seed, err);
    }
    return sp_train_init_from_points(s, d, deg, o->train.seed, err);
}

static int check_opts(const sp_train_model_opts *o, sp_error *err)
{
    if (!o->colmap_dir || !o->out_dir) return sp_error_set(err, SP_E_ARG, "train: colmap_dir and out_dir are required");
    if (o->downscale < 1) return sp_error_set(err, SP_E_ARG, "train: downscale %d must be >= 1", o->downscale);
    if (o->train.steps < 1) return sp_error_set(err, SP_E_ARG, "train: steps %d must be >= 1", o->train.steps);
    if (o->train.sh_degree < 0 || o->train.sh_degree > 3)
        return sp_error_set(err, SP_E_ARG, "train: sh_degree %d not in 0..3", o->train.sh_degree);
    if ((int)o->init < SP_TRAIN_INIT_POINTS || o->init > SP_TRAIN_INIT_PLY)
        return sp_error_set(err, SP_E_ARG, "train: unknown init %d", (int)o->init);
    if (o->resume && !sp_file_exists(o->resume))
        return sp_error_set(err, SP_E_NOTFOUND, "resume: %s does not exist", o->resume);
    return 0;
}

/* The capture's frame, carried into the model folder (positions of a synth-trained model are
 * world positions; a plain reconstruction's are not, and frame.json says so). */
static int write_frame(const sp_train_model_opts *o, sp_error *err)
{
    sp_frame f;
    char path[4200];
    int rc = sp_frame_of_capture(o->colmap_dir, &f, err);
    if (rc) return rc;
    snprintf(path, sizeof path, "%s/frame.json", o->out_dir);
    return sp_frame_write(path, &f, err);
}

/* Depth targets: required with depth_lambda > 0; without, read when the folder exists so train.json
 * reports the depth error of RGB-only training too (a bad file then only costs that report). */
static int load_depth(sp_train_data *d, const sp_train_model_opts *o, const sp_log *log, sp_error *err)
{
    char dir[4200];
    if (o->depth_dir) snprintf(dir, sizeof dir, "%s", o->depth_dir);
    else snprintf(dir, sizeof dir, "%s/depth", o->colmap_dir);
    size_t n = 0;
    if (o->train.depth_lambda > 0) {
        int rc = sp_train_data_load_depth(d, dir, o->downscale, &n, log, err);
        if (rc) return sp_error_prefix(err, "train: --depth-lambda %g: ", (double)o->train.depth_lambda);
        sp_logf(log, SP_LOG_INFO, "depth supervision: lambda %g, %zu of %zu views with depth from %s",
                (double)o->train.depth_lambda, n, d->n_views, dir);
        return SP_OK;
    }
    if (!sp_file_exists(dir)) return SP_OK;
    sp_error e = {0};
    if (sp_train_data_load_depth(d, dir, o->downscale, &n, NULL, &e)) {
        sp_logf(log, SP_LOG_WARN, "depth (for the held-out depth error only): %s", e.msg);
        for (size_t i = 0; i < d->n_views; i++) {
            free(d->views[i].depth);
            d->views[i].depth = NULL;
        }
    }
    return SP_OK;
}

int sp_train_model(sp_device *dev, const sp_train_model_opts *o, sp_train_result *res_out,
                   const sp_log *log, sp_error *err)
{
    int rc = check_opts(o, err);
    if (rc) return rc;
    char ckdir[4096], plyp[4200], jsonp[4200];
    snprintf(ckdir, sizeof ckdir, "%s/checkpoints", o->out_dir);
    snprintf(plyp, sizeof plyp, "%s/splat.ply", o->out_dir);
    snprintf(jsonp, sizeof jsonp, "%s/train.json", o->out_dir);
    if ((rc = sp_mkdirs(o->out_dir, err))) return rc;
    sp_train_data d;
    if ((rc = sp_train_data_load(&d, o->colmap_dir, o->images_dir, o->downscale, o->test_every, err)))
        return rc;
    sp_logf(log, SP_LOG_INFO, "%zu views at %dx%d, %zu points, scene scale %.3f", d.n_views,
            d.views[0].cam.width, d.views[0].cam.height, d.n_points, (double)d.scene_scale);
    if ((rc = load_depth(&d, o, log, err))) {
        sp_train_data_free(&d);
        return rc;
    }
    sp_splat s;
    memset(&s, 0, sizeof s);
    if (!o->resume) rc = init_splat(&s, &d, o, log, err);
    sp_train_options to = o->train;
    to.checkpoint_dir = ckdir;
    to.resume = o->resume;
    sp_train_result res;
    memset(&res, 0, sizeof res);
    if (!rc) rc = sp_train_run(dev, &d, &to, &s, &res, log, err);
    if (!rc) rc = sp_ply_write_splat(plyp, &s, err);
    if (!rc) rc = sp_train_write_json(jsonp, &to, &res, o->colmap_dir, o->images_dir, o->downscale, err);
    if (!rc) rc = write_frame(o, err);
    if (!rc && res_out) *res_out = res;
    sp_splat_free(&s);
    sp_train_data_free(&d);
    return rc;
}
