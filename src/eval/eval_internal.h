/* Private pieces of the eval module. */
#ifndef SP_EVAL_INTERNAL_H
#define SP_EVAL_INTERNAL_H

#include "semsplat/eval.h"
#include "semsplat/semantic.h"

/* The demo's synth stage: o->world rendered into capture_dir with views x width x height
 * (synth/demo_synth.c; without assimp/libxml2 the stub in nosynth/ fails with SP_E_UNSUPPORTED). */
int ev_demo_synth(const sp_demo_opts *o, const char *capture_dir, int views, int width, int height, int plan,
                  sp_error *err);

/* 5.2's answering context (vocab.c): the engine; the scene's lexical vocabulary (NULL: answer
 * with the engine's own text encoder); the COCO names as a vocabulary (the closed baseline). */
typedef struct ev_vocab_ctx {
    sp_query_engine *engine;
    const sp_lex_vocab *scene;
    const sp_lex_vocab *coco;
    float radius, merge_gap_m;
} ev_vocab_ctx;
int ev_vocab_row(const ev_vocab_ctx *c, const sp_ground_truth *gt, const sp_eval_query_spec *q,
                 sp_eval_vocab_row *row, sp_error *err);

/* 5.4 (traj.c): nav's top 3 to o->trajectory_target, written under out/trajectories/; a
 * target the scene lacks or cannot reach is recorded in r->traj_note, not an error. */
int ev_trajectories(const sp_eval_run_opts *o, sp_eval_run *r, sp_error *err);

/* What the model was made from (run_info.c): the capture (semantic.json), its plan and poses
 * (capture.json), training figures (train.json). Missing files leave "unknown" / NaN. */
void ev_model_info(const char *model_dir, sp_eval_run *r);
/* A string / number member of a JSON object (NULL / NAN when absent or of another type). */
struct cJSON;
const char *ev_json_str(const struct cJSON *o, const char *key);
double ev_json_num(const struct cJSON *o, const char *key);

/* Figures (figures.c): per-object localization errors, per-query vocabulary errors; paths are
 * written into figs[] (NULL-terminated, "" when a figure could not be drawn). */
int ev_figures(const sp_eval_run *r, const char *out_dir, char figs[][1100], int max, sp_error *err);

/* The written analysis from the numbers (analysis.c), into r->analysis. */
void ev_analysis(sp_eval_run *r);

/* The documents (doc.c): report.md, report.html (figures inline), report.json. */
int ev_write_docs(const sp_eval_run *r, const char *out_dir, char figs[][1100], int n_figs,
                  const char *title, sp_error *err);

#endif
