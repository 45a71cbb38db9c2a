/* The world on a model folder: the query engine and the nav scene behind the tools' world
 * interface. This file opens them and answers queries and map look-ups; world_nav.c plans,
 * renders, describes and explores.
 *
 * Phrases: nav resolves the user's words (an object the engine's text encoder finds, or a room
 * through the objects kept there). On a label-feature scene, whose encoder knows only the exact
 * class names, words nav does not find are matched to the scene's class names with WordNet (the
 * lexical encoder: "chair" -> dining chair, armchair; "fridge" -> refrigerator) and each class
 * is resolved by name. Results from label features measure localization given a perfect 2D
 * segmentation, and every answer's source says so. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "world_model.h"
#include "semsplat/io.h"

/* Class names that are structure, not objects: never suggested, never described. */
static int is_structure(const char *name)
{
    static const char *const s[] = {"wall", "walls", "floor", "floors", "ceiling", "ceilings",
                                    "background", "structure", NULL};
    for (int i = 0; s[i]; i++)
        if (!strcasecmp(name, s[i])) return 1;
    return 0;
}

const mw_known *mw_find_known(const model_world *w, double x, double y)
{
    int n = w->n_known < MW_KNOWN ? w->n_known : MW_KNOWN;
    for (int k = 0; k < n; k++) { /* newest first */
        const mw_known *kn = &w->known[((w->n_known - 1 - k) % MW_KNOWN + MW_KNOWN) % MW_KNOWN];
        if (agent_dist2d(x, y, kn->position[0], kn->position[1]) <= MW_MATCH_M) return kn;
    }
    return NULL;
}

static mw_known *remember(model_world *w)
{
    mw_known *kn = &w->known[w->n_known++ % MW_KNOWN];
    memset(kn, 0, sizeof *kn);
    return kn;
}

int mw_output_dir(model_world *w, const char *out_dir, const char *stem, char *dir, size_t cap,
                  sp_error *err)
{
    snprintf(dir, cap, "%s/%s_%03d", out_dir, stem, ++w->n_outputs);
    return sp_mkdirs(dir, err);
}

const char *mw_status_code(int status)
{
    switch (status) {
    case SP_NAV_START_OUTSIDE_MAP: return "START_OUTSIDE_MAP";
    case SP_NAV_GOAL_OUTSIDE_MAP: return "GOAL_OUTSIDE_MAP";
    case SP_NAV_START_OCCUPIED: return "START_OCCUPIED";
    case SP_NAV_GOAL_OCCUPIED: return "GOAL_OCCUPIED";
    case SP_NAV_TIMEOUT: return "TIMEOUT";
    default: return "NO_VALID_PATH";
    }
}

/* ---- queries ---------------------------------------------------------------------------------- */

static void instance_from(agent_instance *in, const sp_nav_instance *ni)
{
    in->position[0] = ni->position[0], in->position[1] = ni->position[1], in->position[2] = ni->position[2];
    in->extent_min[0] = ni->box.min[0], in->extent_min[1] = ni->box.min[1], in->extent_min[2] = ni->z_min;
    in->extent_max[0] = ni->box.max[0], in->extent_max[1] = ni->box.max[1], in->extent_max[2] = ni->z_max;
    in->confidence = ni->confidence;
    in->score = ni->score;
}

/* A region ("kitchen") is one place to the agent: the extent of the objects that make it. */
static void add_region(model_world *w, const sp_nav_target *t, agent_found *out)
{
    if (out->n >= AGENT_MAX_INSTANCES || t->n < 1) return;
    agent_instance *in = &out->inst[out->n++];
    mw_known *kn = remember(w);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < t->n; k++) {
        const sp_nav_instance *ni = &t->inst[k];
        lo[0] = fmin(lo[0], ni->box.min[0]), hi[0] = fmax(hi[0], ni->box.max[0]);
        lo[1] = fmin(lo[1], ni->box.min[1]), hi[1] = fmax(hi[1], ni->box.max[1]);
        lo[2] = fmin(lo[2], ni->z_min), hi[2] = fmax(hi[2], ni->z_max);
        kn->boxes[kn->n_boxes++] = ni->box;
    }
    for (int a = 0; a < 3; a++) {
        in->extent_min[a] = lo[a], in->extent_max[a] = hi[a];
        in->position[a] = kn->position[a] = 0.5 * (lo[a] + hi[a]);
    }
    in->confidence = t->confidence;
    in->score = NAN; /* a room is not weighed against other rooms */
    snprintf(in->region, sizeof in->region, "%s", t->text);
    snprintf(kn->phrase, sizeof kn->phrase, "%s", t->text);
    kn->index = -1;
}

static void add_target(model_world *w, const sp_nav_target *t, agent_found *out)
{
    out->confidence = fmax(out->confidence, t->confidence);
    if (!strncmp(t->source, "region", 6)) {
        add_region(w, t, out);
        return;
    }
    float best = 0; /* scores relative to this phrase's best: a class's small instances are
                     * weighed against each other, not against a bigger class's */
    for (int k = 0; k < t->n; k++) best = fmaxf(best, t->inst[k].score);
    for (int k = 0; k < t->n && out->n < AGENT_MAX_INSTANCES; k++) {
        instance_from(&out->inst[out->n++], &t->inst[k]);
        out->inst[out->n - 1].score = best > 0 ? t->inst[k].score / best : NAN;
        mw_known *kn = remember(w);
        memcpy(kn->position, out->inst[out->n - 1].position, sizeof kn->position);
        snprintf(kn->phrase, sizeof kn->phrase, "%s", t->text);
        kn->index = k;
        kn->n_boxes = 1;
        kn->boxes[0] = t->inst[k].box;
    }
}

/* The scene's classes WordNet matches to text, best first (at most max; scores in score[]). */
static int lexical_classes(model_world *w, const char *text, int threshold_only, const char **names,
                           float *score, int max, sp_error *err)
{
    if (!w->vocab) return 0;
    sp_lex_result *res = malloc(sizeof *res);
    if (!res) return sp_error_set(err, SP_E_NOMEM, "agent world: out of memory");
    int n = 0, rc = sp_lex_match(w->vocab, text, res, err);
    for (int i = 0; !rc && i < res->target.n_matches && n < max; i++) {
        const sp_lex_class_match *m = &res->target.matches[i];
        const char *name = sp_lex_vocab_class(w->vocab, m->class_index);
        if (threshold_only && m->score < SP_LEX_THRESHOLD) break;
        if (!(m->score > 0.05f) || is_structure(name)) continue;
        names[n] = name, score[n++] = m->score;
    }
    free(res);
    return rc ? rc : n;
}

int mw_nav_phrase(model_world *w, const char *text, char *out, size_t cap, sp_error *err)
{
    out[0] = 0;
    sp_nav_target *t = malloc(sizeof *t);
    if (!t) return sp_error_set(err, SP_E_NOMEM, "agent world: out of memory");
    int rc = sp_nav_resolve(w->nav, text, t, err);
    if (!rc && t->found) snprintf(out, cap, "%s", text);
    free(t);
    if (rc || out[0]) return rc;
    const char *names[1];
    float score[1];
    int n = lexical_classes(w, text, 1, names, score, 1, err);
    if (n < 0) return n;
    if (n == 1) snprintf(out, cap, "%s", names[0]);
    return SP_OK;
}

/* The heatmap of the best match from the engine's best view, as OUT/images/heatmap_NNN.png. */
static void write_heatmap(model_world *w, const char *phrase, agent_found *out)
{
    if (!w->out_dir[0] || sp_query_engine_n_cameras(w->engine) == 0) return;
    sp_query_opts qo = *sp_query_engine_defaults(w->engine);
    qo.heatmap = 1, qo.heatmap_view = -1;
    sp_query_result res;
    sp_error e = {0};
    char dir[AGENT_PATH_CAP];
    snprintf(dir, sizeof dir, "%s/images", w->out_dir);
    if (sp_query_engine_query(w->engine, phrase, &qo, &res, &e) == 0) {
        if (res.relevancy_image && !sp_mkdirs(dir, &e)) {
            sp_image img = {res.width, res.height, 3, 8, res.relevancy_image};
            snprintf(out->heatmap, sizeof out->heatmap, "%s/heatmap_%03d.png", dir, ++w->n_outputs);
            if (sp_image_write_png(out->heatmap, &img, &e)) out->heatmap[0] = 0;
        }
        sp_query_result_free(&res);
    }
    if (e.msg[0]) sp_logf(mw_log(w), SP_LOG_WARN, "agent world: no heatmap for '%s': %s", phrase, e.msg);
}

static int mw_query(void *ctx, const char *text, agent_found *out, sp_error *err)
{
    model_world *w = ctx;
    out->min_confidence = sp_nav_options(w->nav)->min_confidence;
    snprintf(out->source, sizeof out->source, "%s", w->source);
    sp_nav_target *t = malloc(sizeof *t);
    if (!t) return sp_error_set(err, SP_E_NOMEM, "agent world: out of memory");
    char first[64] = "";
    int rc = sp_nav_resolve(w->nav, text, t, err);
    if (!rc) out->confidence = t->confidence;
    if (!rc && t->found) {
        add_target(w, t, out);
        snprintf(first, sizeof first, "%s", t->n && strncmp(t->source, "region", 6) ? t->text : "");
    } else if (!rc && w->vocab) { /* label scene: the classes WordNet matches */
        const char *names[8];
        float score[8];
        int n = lexical_classes(w, text, 1, names, score, 8, err);
        rc = n < 0 ? n : 0;
        size_t j = strlen(out->source);
        for (int i = 0; i < n && !rc; i++) {
            if ((rc = sp_nav_resolve(w->nav, names[i], t, err))) break;
            if (!t->found) continue;
            if (!first[0]) snprintf(first, sizeof first, "%s", names[i]);
            add_target(w, t, out);
            if (j < sizeof out->source)
                j += (size_t)snprintf(out->source + j, sizeof out->source - j, "%s%s %.2f",
                                      j == strlen(w->source) ? "; WordNet: " : ", ", names[i], score[i]);
        }
    }
    free(t);
    if (rc) return rc;
    out->found = out->n > 0;
    if (out->found && first[0]) write_heatmap(w, first, out);
    return SP_OK;
}

/* ---- map look-ups ------------------------------------------------------------------------------ */

static int mw_cell(void *ctx, double x, double y)
{
    const sp_costmap *cm = sp_nav_costmap(((model_world *)ctx)->nav);
    int ix, iy;
    if (!isfinite(x) || !isfinite(y) || sp_costmap_cell(cm, (float)x, (float)y, &ix, &iy)) return AGENT_CELL_OUTSIDE;
    long i = (long)iy * cm->nx + ix;
    uint8_t v = cm->occ[i];
    /* an unknown cell where Gaussians no camera saw stand (the inside of a wall) holds something */
    if (v == SP_CELL_UNKNOWN && cm->hidden && cm->hidden[i]) return AGENT_CELL_OCCUPIED;
    return v == SP_CELL_FREE ? AGENT_CELL_FREE : v == SP_CELL_OCCUPIED ? AGENT_CELL_OCCUPIED : AGENT_CELL_UNKNOWN;
}

static void mw_region_of(void *ctx, double x, double y, char *out, size_t cap)
{
    model_world *w = ctx;
    sp_error e = {0};
    if (sp_nav_region_of(w->nav, (float)x, (float)y, out, cap, &e))
        sp_logf(mw_log(w), SP_LOG_WARN, "agent world: %s", e.msg);
}

/* Letter-pair (Dice) similarity of two names, for "did you mean". */
static double pair_similarity(const char *a, const char *b)
{
    int na = (int)strlen(a), nb = (int)strlen(b), same = 0;
    if (na < 2 || nb < 2) return !strcasecmp(a, b);
    for (int i = 0; i + 1 < na; i++)
        for (int j = 0; j + 1 < nb; j++)
            if (tolower((unsigned char)a[i]) == tolower((unsigned char)b[j]) &&
                tolower((unsigned char)a[i + 1]) == tolower((unsigned char)b[j + 1])) {
                same++;
                break;
            }
    return 2.0 * same / (na - 1 + nb - 1);
}

/* The names in this map nearest to text: WordNet's ranking of the scene's classes on label
 * scenes; else the household terms most alike in spelling that the map does hold. */
static int mw_suggest(void *ctx, const char *text, char (*names)[64], int max)
{
    model_world *w = ctx;
    sp_error e = {0};
    const char *cls[16];
    float score[16];
    int n = lexical_classes(w, text, 0, cls, score, max < 16 ? max : 16, &e);
    for (int i = 0; i < n; i++) snprintf(names[i], 64, "%s", cls[i]);
    if (n > 0 || w->vocab) return n > 0 ? n : 0;
    int nv;
    const char *const *v = sp_nav_vocabulary(&nv);
    enum { TRY = 8 };
    double *sim = malloc(sizeof(double) * (nv > 0 ? nv : 1));
    int best[TRY], nb = 0;
    for (int i = 0; sim && i < nv; i++) sim[i] = pair_similarity(text, v[i]);
    for (; sim && nb < TRY && nb < nv; nb++) { /* the TRY most alike in spelling */
        int b = 0;
        for (int i = 1; i < nv; i++) b = sim[i] > sim[b] ? i : b;
        best[nb] = b, sim[b] = -1;
    }
    free(sim);
    sp_nav_target *t = malloc(sizeof *t);
    for (int i = 0; t && i < nb && n < max; i++)
        if (!sp_nav_resolve(w->nav, v[best[i]], t, &e) && t->found) snprintf(names[n++], 64, "%s", v[best[i]]);
    free(t);
    return n;
}

/* ---- opening and closing ----------------------------------------------------------------------- */

static void mw_close(void *ctx)
{
    model_world *w = ctx;
    if (!w) return;
    sp_scene_free(w->scene);
    sp_raster_free(w->raster);
    sp_nav_free(w->nav);
    if (w->own_engine) sp_query_engine_free(w->engine);
    sp_lex_vocab_free(w->vocab);
    sp_lexicon_free(w->lexicon);
    if (w->own_dev) sp_device_free(w->dev);
    free(w);
}

static int mw_default_start(void *ctx, sp_agent_pose *pose, sp_error *err)
{
    float s[3];
    int rc = sp_nav_default_start(((model_world *)ctx)->nav, s, err);
    if (!rc) *pose = (sp_agent_pose){s[0], s[1], 0, s[2]};
    return rc;
}

static const agent_world_ops model_ops = {"model", mw_query, mw_plan, mw_render, mw_describe,
                                          mw_explore, mw_cell, mw_region_of, mw_suggest, mw_close,
                                          mw_default_start};

/* nav's household terms and the scene's own classes (label scenes), for describe. */
static void build_vocabulary(model_world *w)
{
    int nv;
    const char *const *v = sp_nav_vocabulary(&nv);
    size_t j = 0;
    for (int i = 0; i < nv && j < sizeof w->vocabulary; i++)
        j += (size_t)snprintf(w->vocabulary + j, sizeof w->vocabulary - j, "%s%s", j ? "," : "", v[i]);
    for (int c = 0; w->vocab && c < sp_lex_vocab_size(w->vocab) && j < sizeof w->vocabulary; c++) {
        const char *name = sp_lex_vocab_class(w->vocab, c);
        int dup = is_structure(name) || strchr(name, ',') != NULL;
        for (int i = 0; i < nv && !dup; i++) dup = !strcasecmp(v[i], name);
        if (!dup) j += (size_t)snprintf(w->vocabulary + j, sizeof w->vocabulary - j, ",%s", name);
    }
    if (j >= sizeof w->vocabulary) { /* cut at the last whole term */
        char *c = strrchr(w->vocabulary, ',');
        if (c) *c = 0;
    }
}

/* Everything after the engine (and the vocabulary) are in place. */
static int mw_finish(model_world *w, const struct sp_nav_opts *nav_opts, agent_world *out, sp_error *err)
{
    sp_nav_opts o = nav_opts ? *nav_opts : sp_nav_opts_default();
    build_vocabulary(w);
    if (!o.vocabulary) o.vocabulary = w->vocabulary;
    int rc = sp_nav_create(&w->nav, w->engine, NULL, NULL, 0, &o, w->dev, mw_log(w), err);
    if (!rc) rc = sp_raster_create(&w->raster, w->dev, err);
    if (!rc) rc = sp_scene_create(&w->scene, w->dev, sp_query_engine_splat(w->engine), SP_SCENE_RGB, err);
    if (rc) {
        sp_error_prefix(err, "agent world: ");
        mw_close(w);
        return rc;
    }
    const sp_query_source *src = sp_query_engine_source(w->engine);
    const char *note = sp_query_source_note(src);
    snprintf(w->source, sizeof w->source, "encoder %s, features %s%s%s", src->encoder, src->features,
             note[0] ? ": " : "", note);
    out->ops = &model_ops;
    out->ctx = w;
    return SP_OK;
}

static model_world *mw_alloc(const sp_log *log, const char *out_dir)
{
    model_world *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    if (log) w->log = *log, w->has_log = 1;
    snprintf(w->out_dir, sizeof w->out_dir, "%s", out_dir ? out_dir : "");
    return w;
}

/* WordNet for a label scene; without it the engine's exact class names still work. */
static sp_lexicon *open_lexicon(model_world *w)
{
    sp_lexicon *lx = NULL;
    sp_error e = {0};
    if (sp_lexicon_open(&lx, NULL, &e))
        sp_logf(mw_log(w), SP_LOG_WARN, "agent world: %s (only exact class names will be found)", e.msg);
    return lx;
}

int agent_world_from_parts(agent_world *out, const agent_world_parts *p, sp_error *err)
{
    memset(out, 0, sizeof *out);
    model_world *w = p->engine && p->dev ? mw_alloc(p->log, p->out_dir) : NULL;
    if (!w) {
        if (p->own_engine) sp_query_engine_free(p->engine);
        return sp_error_set(err, p->engine && p->dev ? SP_E_NOMEM : SP_E_ARG,
                            "agent world: needs an engine and a device");
    }
    w->engine = p->engine, w->own_engine = p->own_engine, w->dev = p->dev;
    if (p->classes && p->n_classes > 0 && (w->lexicon = open_lexicon(w))) {
        sp_error e = {0};
        if (sp_lex_vocab_create(&w->vocab, w->lexicon, p->classes, p->n_classes, NULL, &e))
            sp_logf(mw_log(w), SP_LOG_WARN, "agent world: %s", e.msg);
    }
    return mw_finish(w, p->nav, out, err);
}

int agent_world_open_model(agent_world *out, const sp_agent_config *cfg, sp_error *err)
{
    memset(out, 0, sizeof *out);
    model_world *w = mw_alloc(cfg->log, cfg->out_dir);
    if (!w) return sp_error_set(err, SP_E_NOMEM, "agent world: out of memory");
    int rc = 0;
    if (cfg->device) w->dev = cfg->device;
    else rc = sp_device_create(&w->dev, SP_DEVICE_CPU, 0, err), w->own_dev = !rc;
    if (!rc) rc = sp_query_engine_open(&w->engine, cfg->model_dir, NULL, w->dev, mw_log(w), err);
    w->own_engine = w->engine != NULL;
    if (rc) {
        mw_close(w);
        return rc;
    }
    const sp_query_source *src = sp_query_engine_source(w->engine);
    if (!strcmp(src->encoder, "exact") && (w->lexicon = open_lexicon(w))) {
        sp_error e = {0};
        if (sp_lex_vocab_for_model(&w->vocab, w->lexicon, cfg->model_dir, NULL, &e))
            sp_logf(mw_log(w), SP_LOG_WARN, "agent world: %s (only exact class names will be found)", e.msg);
    }
    return mw_finish(w, cfg->nav, out, err);
}
