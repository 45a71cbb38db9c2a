/* semsplat eval as a library call: the ground truth from the world file, the model's engine, the
 * localization report (5.1), the vocabulary comparison (5.2), then figures, the written analysis
 * and the three documents. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval/eval_internal.h"
#include "semsplat/io.h"
#include "semsplat/nav.h"

void sp_eval_run_free(sp_eval_run *r)
{
    if (!r) return;
    sp_ground_truth_free(&r->gt);
    sp_eval_report_free(&r->loc);
    free(r->vocab);
    memset(r, 0, sizeof *r);
}

/* 5.2 over every query; the lexical path when the model is a label scene, else the engine's. */
static int run_vocab(const sp_eval_run_opts *o, sp_query_engine *e, sp_eval_run *r, sp_error *err)
{
    sp_eval_query_spec *own = NULL;
    const sp_eval_query_spec *specs;
    size_t n = 0;
    int rc = 0;
    if (o->queries) {
        if ((rc = sp_eval_read_queries(o->queries, &own, &n, err))) return rc;
        specs = own;
    } else specs = sp_eval_default_vocab(&n);
    sp_lexicon *lx = NULL;
    sp_lex_vocab *scene = NULL, *coco = NULL;
    rc = sp_lexicon_open(&lx, NULL, err);
    if (!rc) {
        int nc = 0;
        const char *const *names = sp_nav_coco_classes(&nc);
        rc = sp_lex_vocab_create(&coco, lx, names, nc, "", err);
    }
    if (!rc && sp_lex_vocab_for_model(&scene, lx, o->model_dir, NULL, NULL)) scene = NULL;
    snprintf(r->vocab_encoder, sizeof r->vocab_encoder, "%s",
             scene ? "lexical" : sp_query_engine_source(e)->encoder);
    r->vocab = rc ? NULL : calloc(n, sizeof *r->vocab);
    if (!rc && !r->vocab) rc = sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    ev_vocab_ctx c = {.engine = e, .scene = scene, .coco = coco,
                      .radius = o->match_radius_m > 0 ? o->match_radius_m : 0.5f,
                      .merge_gap_m = SP_EVAL_MERGE_GAP_M};
    for (size_t k = 0; !rc && k < n; k++) {
        rc = ev_vocab_row(&c, &r->gt, &specs[k], &r->vocab[k], err);
        r->n_vocab = k + 1;
        sp_logf(o->log, SP_LOG_INFO, "eval: '%s': splat %s, COCO baseline (%s) %s", specs[k].text,
                r->vocab[k].open_found ? "found" : "not found",
                r->vocab[k].coco_class[0] ? r->vocab[k].coco_class : "no class",
                r->vocab[k].closed_found ? "found" : "not found");
    }
    sp_lex_vocab_free(scene);
    sp_lex_vocab_free(coco);
    sp_lexicon_free(lx);
    free(own);
    return rc;
}

/* 5.3 through the agent and the simulated robot; a robot that cannot run is a note, not a failure. */
static int run_navigation(const sp_eval_run_opts *o, sp_eval_run *r, sp_error *err)
{
    if (o->no_navigation) {
        snprintf(r->nav_note, sizeof r->nav_note, "not asked for in this run (--no-navigation)");
        return SP_OK;
    }
    sp_nav_opts nav;
    sp_eval_drive_map_opts(&nav);
    sp_drive_opts d = {.model_dir = o->model_dir, .out_dir = o->out_dir, .robot = o->robot, .nav = &nav,
                       .dev = o->dev, .log = o->log};
    char **cmds = NULL;
    int n_cmds = 0;
    if (o->queries) {
        int rc = sp_eval_read_nav_commands(o->queries, &cmds, &n_cmds, err);
        if (rc) return rc;
    }
    sp_error e = {0};
    int rc = sp_eval_nav_success(&d, &r->gt, n_cmds ? (const char *const *)cmds : NULL, n_cmds, o->match_radius_m,
                                 &r->nav, &e);
    sp_eval_free_nav_commands(cmds, n_cmds);
    if (rc == SP_E_NOMEM) return *err = e, rc;
    r->nav_measured = rc == 0;
    if (rc) snprintf(r->nav_note, sizeof r->nav_note, "%.390s", e.msg);
    return SP_OK;
}

int sp_eval_run_report(const sp_eval_run_opts *o, sp_eval_run *r, sp_error *err)
{
    memset(r, 0, sizeof *r);
    if (!o || !o->model_dir || !o->world || !o->out_dir || !o->dev)
        return sp_error_set(err, SP_E_ARG, "eval: a model folder, a world file, an output folder and a "
                            "device are needed");
    double t0 = sp_time_now();
    snprintf(r->world, sizeof r->world, "%s", o->world);
    snprintf(r->model_dir, sizeof r->model_dir, "%s", o->model_dir);
    ev_model_info(o->model_dir, r);
    char heat[1200], figs_dir[1200];
    snprintf(heat, sizeof heat, "%s/heatmaps", o->out_dir);
    snprintf(figs_dir, sizeof figs_dir, "%s/figures", o->out_dir);
    int rc = sp_mkdirs(figs_dir, err);
    if (!rc) rc = sp_ground_truth_from_world(o->world, o->model_path, o->skip_missing, o->log, &r->gt, err);
    sp_query_engine *e = NULL;
    if (!rc) rc = sp_query_engine_open(&e, o->model_dir, NULL, o->dev, o->log, err);
    if (!rc) {
        sp_eval_opts eo = {.match_radius_m = o->match_radius_m, .heatmap_dir = heat, .log = o->log};
        rc = sp_eval_localization(e, &r->gt, &eo, &r->loc, err);
    }
    if (!rc) rc = run_vocab(o, e, r, err);
    sp_query_engine_free(e);
    if (!rc) rc = ev_trajectories(o, r, err);
    if (!rc) rc = run_navigation(o, r, err);
    char figs[8][1100];
    int n_figs = 0;
    if (!rc) n_figs = ev_figures(r, o->out_dir, figs, 8, err);
    if (n_figs < 0) rc = n_figs;
    r->seconds = sp_time_now() - t0;
    if (!rc) {
        ev_analysis(r);
        char title[1200];
        snprintf(title, sizeof title, "%s", o->title ? o->title : "");
        if (!o->title) snprintf(title, sizeof title, "semsplat evaluation: %s", r->gt.world);
        rc = ev_write_docs(r, o->out_dir, figs, n_figs, title, err);
    }
    if (rc) sp_eval_run_free(r);
    return rc;
}
