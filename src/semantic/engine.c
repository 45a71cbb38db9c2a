/* The query engine: opens a language-embedded model folder once (splat with f_sem_*, sidecar,
 * PCA, frame, cameras), puts splat and cameras into the folder's frame, and answers text queries
 * with a position, instances, a confidence and a heatmap; per-Gaussian relevancy and heatmaps
 * from any camera for other modules. Text goes through the folder's text encoder (encoder.c:
 * clip, lexical or exact). Every public call holds the engine's lock. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"
#include "semantic/sem_cuda.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"

sp_query_opts sp_query_opts_default(void)
{
    sp_query_opts o;
    memset(&o, 0, sizeof o);
    o.method = SP_QUERY_3D;
    o.temperature = SP_SEM_DEFAULT_TEMPERATURE;
    o.min_confidence = 0.2f;
    o.keep_fraction = 0.6f;
    o.min_relevancy = 0.55f;
    o.min_opacity = 0.1f;
    o.voxel_m = 0.12f;
    o.min_instance_fraction = 0.1f;
    o.n_views = 4;
    o.render_downscale = 2;
    o.heatmap = 1;
    o.heatmap_view = -1;
    return o;
}

void sp_query_result_free(sp_query_result *res)
{
    if (!res) return;
    free(res->relevancy_image);
    free(res->relevancy);
    free(res->instances);
    free(res->matches);
    free(res->explanation);
    memset(res, 0, sizeof *res);
}

void sp_query_engine_free(sp_query_engine *e)
{
    if (!e) return;
    if (e->d_feat) sp_device_release(e->dev, e->d_feat);
    if (e->d_raw) sp_device_release(e->dev, e->d_raw);
    if (e->d_rel) sp_device_release(e->dev, e->d_rel);
    if (e->d_scores2) sp_device_release(e->dev, e->d_scores2);
    sp_device_scratch_release(e->dev, &e->mv_out);
    sp_device_scratch_release(e->dev, &e->mv_work);
    sp_device_scratch_release(e->dev, &e->hm_out);
    sp_raster_free(e->raster);
    sp_splat_free(&e->splat);
    sp_sem_pca_free(&e->pca);
    free(e->cams);
    free(e->cam_names);
    if (e->clip) sp_clip_free(e->clip);
    free(e->neg_emb);
    free(e->opacity);
    free(e->raw);
    free(e->rel);
    free(e->scores2);
    sp_grid3_free(&e->occ);
    sp_scene_free(e->scene);
    sp_scene_free(e->scores_scene);
    sp_lex_vocab_free(e->vocab);
    sp_lexicon_free(e->lx);
    free(e->classes);
    if (e->has_mutex) pthread_mutex_destroy(&e->mu);
    free(e);
}

/* Puts splat and cameras into the frame (model -> world); nothing to do for identity frames. */
static int apply_frame(sp_query_engine *e, sp_error *err)
{
    static const double I[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (!memcmp(e->frame.world_from_model, I, sizeof I)) return 0;
    int rc = sp_splat_transform(&e->splat, e->frame.world_from_model, err);
    if (rc) return sp_error_prefix(err, "query engine: frame.json: ");
    for (size_t i = 0; i < e->n_cams; i++) sp_frame_apply_camera(&e->frame, &e->cams[i]);
    return 0;
}

static void set_qframe(sp_query_engine *e)
{
    sp_query_frame *q = &e->qframe;
    snprintf(q->name, sizeof q->name, "%s", sp_frame_name(&e->frame));
    snprintf(q->source, sizeof q->source, "%s", e->frame.source);
    snprintf(q->units, sizeof q->units, "%s", e->frame.units);
    snprintf(q->up, sizeof q->up, "%s", e->frame.up);
}

static int engine_finish(sp_query_engine *e, const sp_query_opts *opts, sp_error *err)
{
    e->defaults = opts ? *opts : sp_query_opts_default();
    if (pthread_mutex_init(&e->mu, NULL) != 0)
        return sp_error_set(err, SP_E_NOMEM, "query engine: cannot create its lock");
    e->has_mutex = 1;
    int frc = sp_frame_check(&e->frame, "query engine: frame", err);
    if (frc) return frc;
    if ((frc = apply_frame(e, err))) return frc;
    set_qframe(e);
    if (e->splat.feat_dim != e->pca.dim)
        return sp_error_set(err, SP_E_FORMAT,
                            "query engine: the splat has %d f_sem_* features but the PCA has dim %d",
                            e->splat.feat_dim, e->pca.dim);
    int rc = sp_feature_dim_check(e->pca.dim, SP_E_FORMAT, "query engine", err);
    if (rc) return rc;
    size_t n = e->splat.n ? e->splat.n : 1;
    e->opacity = malloc(sizeof(float) * n);
    e->raw = malloc(sizeof(float) * n);
    e->rel = malloc(sizeof(float) * n);
    e->scores2 = malloc(sizeof(float) * 2 * n);
    if (!e->opacity || !e->raw || !e->rel || !e->scores2)
        return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory for %zu Gaussians", n);
    for (size_t i = 0; i < e->splat.n; i++) e->opacity[i] = sp_sigmoid(e->splat.opacity_logits[i]);
    rc = sp_raster_create(&e->raster, e->dev, err);
    /* A GPU engine keeps the features on the GPU and scores them there. */
    if (!rc && sp_device_kind_of(e->dev) == SP_DEVICE_CUDA &&
        sp_device_supports(e->dev, SP_STAGE_SEM_SCORE, e->splat.feat_dim) && e->splat.n > 0) {
        size_t fb = sizeof(float) * e->splat.n * (size_t)e->splat.feat_dim;
        if (!(e->d_feat = sp_device_alloc(e->dev, fb, err)) ||
            !(e->d_raw = sp_device_alloc(e->dev, sizeof(float) * e->splat.n, err)) ||
            !(e->d_rel = sp_device_alloc(e->dev, sizeof(float) * e->splat.n, err)) ||
            !(e->d_scores2 = sp_device_alloc(e->dev, sizeof(float) * 2 * e->splat.n, err)))
            return err && err->code ? err->code : SP_E_NOMEM;
        rc = sp_device_upload(e->dev, e->d_feat, e->splat.features, fb, err);
    }
    return rc;
}

static void source_init(sp_query_source *s, const char *encoder, const char *features)
{
    memset(s, 0, sizeof *s);
    snprintf(s->encoder, sizeof s->encoder, "%s", encoder);
    snprintf(s->features, sizeof s->features, "%s", features);
    s->ground_truth = !strcmp(features, "labels");
}

static int copy_inputs(sp_query_engine *e, const sp_query_model *m, sp_error *err)
{
    const sp_sem_pca *pca = m->pca;
    int rc = sp_splat_copy(&e->splat, m->splat, err);
    if (rc) return rc;
    e->pca.dim = pca->dim;
    e->pca.full_dim = pca->full_dim;
    e->pca.mean = malloc(sizeof(float) * pca->full_dim);
    e->pca.basis = malloc(sizeof(float) * pca->full_dim * pca->dim);
    e->n_cams = m->n_cams;
    e->cams = malloc(sizeof(sp_camera) * (m->n_cams ? m->n_cams : 1));
    e->cam_names = calloc(m->n_cams ? m->n_cams : 1, sizeof *e->cam_names);
    if (!e->pca.mean || !e->pca.basis || !e->cams || !e->cam_names)
        return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory");
    memcpy(e->pca.mean, pca->mean, sizeof(float) * pca->full_dim);
    memcpy(e->pca.basis, pca->basis, sizeof(float) * pca->full_dim * pca->dim);
    for (size_t i = 0; i < m->n_cams; i++) {
        e->cams[i] = m->cams[i];
        if (m->cam_names && m->cam_names[i]) snprintf(e->cam_names[i], 256, "%s", m->cam_names[i]);
        else snprintf(e->cam_names[i], 256, "view %zu", i);
    }
    if (m->n_classes > 0 && m->classes) {
        e->classes = calloc((size_t)m->n_classes, sizeof *e->classes);
        if (!e->classes) return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory");
        for (int i = 0; i < m->n_classes; i++)
            snprintf(e->classes[e->n_classes++], sizeof e->classes[0], "%s", m->classes[i] ? m->classes[i] : "");
    }
    return 0;
}

int sp_query_engine_create(sp_query_engine **out, const sp_query_model *m, const sp_query_opts *opts,
                           sp_device *dev, const sp_log *log, sp_error *err)
{
    *out = NULL;
    if (!m || !m->splat || !m->pca || !dev || (m->n_cams && !m->cams))
        return sp_error_set(err, SP_E_ARG, "query engine: missing argument");
    sp_query_engine *e = calloc(1, sizeof *e);
    if (!e) return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory");
    e->dev = dev;
    if (log) e->log = *log, e->has_log = 1;
    if (m->source) e->source = *m->source;
    else source_init(&e->source, "exact", "labels");
    if (m->frame) e->frame = *m->frame;
    else sp_frame_init(&e->frame, "colmap");
    if (m->clip_weights) snprintf(e->clip_path, sizeof e->clip_path, "%s", m->clip_weights);
    int rc = copy_inputs(e, m, err);
    if (!rc) rc = sem_encoder_prepare(e, e->source.encoder, m->wordnet_dir, m->regions_path, err);
    if (!rc) rc = engine_finish(e, opts, err);
    if (rc) {
        sp_query_engine_free(e);
        return rc;
    }
    *out = e;
    return 0;
}

static const char *jstr(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsString(v) ? v->valuestring : NULL;
}

/* Resolves a sidecar path: absolute as is, else relative to the model folder. */
static void resolve(char *out, size_t cap, const char *dir, const char *p)
{
    if (p[0] == '/') snprintf(out, cap, "%s", p);
    else sp_path_join(out, cap, dir, p);
}

static int load_cameras(sp_query_engine *e, const char *colmap_dir, sp_error *err)
{
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    int rc = sp_colmap_read(colmap_dir, &m, err);
    if (rc) return sp_error_prefix(err, "query engine: cameras: ");
    e->cams = calloc(m.n_images ? m.n_images : 1, sizeof(sp_camera));
    e->cam_names = calloc(m.n_images ? m.n_images : 1, sizeof *e->cam_names);
    if (!e->cams || !e->cam_names) {
        sp_colmap_free(&m);
        return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory for cameras");
    }
    for (size_t i = 0; i < m.n_images; i++) {
        /* The lens is kept: renders use the pinhole part (the renderer ignores distortion) and
         * heatmaps are resampled into the photo's own pixels (sem_heatmap). */
        if ((rc = sp_colmap_image_camera(&m, i, &e->cams[e->n_cams], err))) break;
        snprintf(e->cam_names[e->n_cams], 256, "%s", m.images[i].name ? m.images[i].name : "");
        e->n_cams++;
    }
    sp_colmap_free(&m);
    return rc;
}

/* Whether the folder's features are hashed label embeddings (else CLIP's text space). */
static int label_space_of(const cJSON *js)
{
    const char *le = jstr(js, "label_embedding"), *enc = jstr(js, "encoder");
    if (le) return !strcmp(le, "hash");
    return enc && (!strcmp(enc, SP_ENCODER_EXACT) || !strcmp(enc, SP_ENCODER_LEXICAL));
}

/* The encoder asked for, else the one the folder records, else the features' default (lexical on
 * hashed labels, clip otherwise). A lexical encoder the folder records or defaults to but that
 * cannot be prepared (no WordNet, no class names) falls back to exact with a warning; one asked
 * for is an error. */
static int choose_encoder(sp_query_engine *e, const char *model_dir, const cJSON *js,
                          const sp_encoder_opts *eo, sp_error *err)
{
    const char *asked = eo && eo->encoder && eo->encoder[0] ? eo->encoder : NULL;
    const char *name = asked ? asked : jstr(js, "encoder");
    int label = label_space_of(js);
    if (!name) name = label ? SP_ENCODER_LEXICAL : SP_ENCODER_CLIP;
    const sem_encoder *enc = sem_encoder_find(name);
    if (!enc)
        return sp_error_set(err, asked ? SP_E_ARG : SP_E_UNSUPPORTED, "%s/semantic.json: text encoder '%s' is "
                            "not clip, lexical or exact", model_dir, name);
    if (enc->label_space != label)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: the text encoder %s does not fit its features (%s): "
                            "use %s", model_dir, name, label ? "hashed class names" : "CLIP's text space",
                            label ? "lexical or exact" : "clip");
    sp_error lerr = {0};
    int rc = label ? sem_model_classes(model_dir, js, &e->classes, &e->n_classes, &lerr) : 0;
    if (!rc) rc = sem_encoder_prepare(e, name, eo ? eo->wordnet_dir : NULL, eo ? eo->regions_path : NULL, &lerr);
    if (rc && (asked || strcmp(name, SP_ENCODER_LEXICAL))) {
        if (err) *err = lerr;
        return rc;
    }
    if (rc) {
        sp_logf(e->has_log ? &e->log : NULL, SP_LOG_WARN, "%s: %s; the exact encoder answers instead (only "
                "exact class names match)", model_dir, lerr.msg);
        rc = sem_encoder_prepare(e, SP_ENCODER_EXACT, NULL, NULL, err);
    }
    return rc;
}

int sp_query_engine_open(sp_query_engine **out, const char *model_dir, const sp_query_opts *opts,
                         sp_device *dev, const sp_log *log, sp_error *err)
{
    return sp_query_engine_open_with(out, model_dir, NULL, opts, dev, log, err);
}

int sp_query_engine_open_with(sp_query_engine **out, const char *model_dir, const sp_encoder_opts *eo,
                              const sp_query_opts *opts, sp_device *dev, const sp_log *log, sp_error *err)
{
    *out = NULL;
    if (!model_dir || !dev) return sp_error_set(err, SP_E_ARG, "query engine: missing argument");
    char path[2048], p2[2048];
    cJSON *js = NULL;
    sp_query_engine *e = calloc(1, sizeof *e);
    if (!e) return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory");
    e->dev = dev;
    if (log) e->log = *log, e->has_log = 1;
    int rc;
    sp_path_join(path, sizeof path, model_dir, "semantic.json");
    if (!sp_file_exists(path)) {
        rc = sp_error_set(err, SP_E_NOTFOUND,
                          "%s: no semantic field in this model folder (run semsplat lift or distill)",
                          path);
        goto fail;
    }
    if ((rc = sp_json_read_file(path, &js, err))) goto fail;
    const char *mean = jstr(js, "pca_mean"), *basis = jstr(js, "pca_basis");
    if (!mean || !basis) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: pca_mean / pca_basis missing", path);
        goto fail;
    }
    resolve(path, sizeof path, model_dir, mean);
    resolve(p2, sizeof p2, model_dir, basis);
    if ((rc = sp_sem_pca_read(path, p2, &e->pca, err))) goto fail;
    const char *model = jstr(js, "model"), *fsrc = jstr(js, "source");
    source_init(&e->source, "", fsrc ? fsrc : "clip");
    if ((rc = choose_encoder(e, model_dir, js, eo, err))) goto fail;
    if (!strcmp(e->source.encoder, SP_ENCODER_CLIP)) {
        if (!model || !model[0]) {
            rc = sp_error_set(err, SP_E_NOTFOUND,
                              "%s/semantic.json: features need CLIP text embeddings but name no "
                              "model (set \"model\" to a CLIP model.safetensors)", model_dir);
            goto fail;
        }
        snprintf(e->clip_path, sizeof e->clip_path, "%s", model);
    }
    sp_path_join(path, sizeof path, model_dir, "splat.ply");
    if ((rc = sp_ply_read_splat(path, &e->splat, err))) goto fail;
    const char *colmap = jstr(js, "colmap");
    if (colmap && colmap[0]) resolve(p2, sizeof p2, model_dir, colmap);
    if ((rc = sp_frame_of_model(model_dir, colmap && colmap[0] ? p2 : NULL, &e->frame, err))) goto fail;
    if (colmap && colmap[0]) {
        /* Without the capture the engine still localizes in 3D; views and heatmaps need it. */
        snprintf(path, sizeof path, "%s", p2);
        sp_error cerr = {0};
        if (load_cameras(e, path, &cerr)) {
            sp_logf(log, SP_LOG_WARN, "%s (queries work without views: no multi-view, no heatmaps)",
                    cerr.msg);
            free(e->cams), free(e->cam_names);
            e->cams = NULL, e->cam_names = NULL, e->n_cams = 0;
        }
    }
    if ((rc = engine_finish(e, opts, err))) goto fail;
    cJSON_Delete(js);
    *out = e;
    return 0;
fail:
    cJSON_Delete(js);
    sp_query_engine_free(e);
    return rc;
}

const sp_query_opts *sp_query_engine_defaults(const sp_query_engine *e) { return &e->defaults; }
const sp_frame *sp_query_engine_frame(const sp_query_engine *e) { return &e->frame; }
const sp_query_source *sp_query_engine_source(const sp_query_engine *e) { return &e->source; }
const char *sp_query_engine_camera_name(const sp_query_engine *e, size_t i)
{
    return i < e->n_cams && e->cam_names ? e->cam_names[i] : NULL;
}
int sp_query_engine_full_dim(const sp_query_engine *e) { return e->pca.full_dim; }
size_t sp_query_engine_n_cameras(const sp_query_engine *e) { return e->n_cams; }
const sp_splat *sp_query_engine_splat(const sp_query_engine *e) { return &e->splat; }
const sp_camera *sp_query_engine_camera(const sp_query_engine *e, size_t i)
{
    return i < e->n_cams ? &e->cams[i] : NULL;
}

int sem_embed_base(sp_query_engine *e, const char *const *texts, int n, float *out, sp_error *err)
{
    int F = e->pca.full_dim;
    if (e->enc->label_space) {
        for (int i = 0; i < n; i++) sp_label_embedding(texts[i], F, out + (size_t)i * F);
        return 0;
    }
    if (!e->clip) {
        if (!e->clip_path[0])
            return sp_error_set(err, SP_E_NOTFOUND, "query engine: text encoder clip, but no CLIP weights given");
        int rc = sp_clip_load(&e->clip, e->clip_path, NULL, e->dev, err);
        if (rc) return sp_error_prefix(err, "query engine: text embeddings: ");
        if (sp_clip_embed_dim(e->clip) != F)
            return sp_error_set(err, SP_E_FORMAT, "%s: CLIP embeds to %d dims, the features to %d",
                                e->clip_path, sp_clip_embed_dim(e->clip), F);
    }
    return sp_clip_encode_text(e->clip, texts, n, out, err);
}

static int embed_text(sp_query_engine *e, const char *text, float *out, sp_error *err)
{
    if (!text || !text[0]) return sp_error_set(err, SP_E_ARG, "query: empty text");
    return e->enc->embed(e, text, out, err);
}

int sp_query_engine_embed(sp_query_engine *e, const char *text, float *out, sp_error *err)
{
    pthread_mutex_lock(&e->mu);
    int rc = embed_text(e, text, out, err);
    pthread_mutex_unlock(&e->mu);
    return rc;
}

static int ensure_negatives(sp_query_engine *e, const sp_query_opts *o, sp_error *err)
{
    const char *key = o->negatives[0] ? o->negatives : SP_SEM_DEFAULT_NEGATIVES;
    if (e->neg_emb && !strcmp(key, e->neg_key)) return 0;
    char buf[256];
    snprintf(buf, sizeof buf, "%s", key);
    const char *words[SP_SEM_MAX_NEGATIVES];
    int n = 0;
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        while (*tok == ' ') tok++;
        if (!*tok) continue;
        if (n == SP_SEM_MAX_NEGATIVES)
            return sp_error_set(err, SP_E_ARG, "query: more than %d negatives in '%s'",
                                SP_SEM_MAX_NEGATIVES, key);
        words[n++] = tok;
    }
    float *emb = malloc(sizeof(float) * (size_t)(n ? n : 1) * e->pca.full_dim);
    if (!emb) return sp_error_set(err, SP_E_NOMEM, "query: out of memory");
    int rc = n ? sem_embed_base(e, words, n, emb, err) : 0;
    if (rc) {
        free(emb);
        return rc;
    }
    free(e->neg_emb);
    e->neg_emb = emb;
    e->n_neg = n;
    snprintf(e->neg_key, sizeof e->neg_key, "%s", key);
    return 0;
}

/* Confidence: the 5th largest raw cosine among visible Gaussians, so that a handful of stray
 * Gaussians cannot claim a match. */
static float robust_max(const float *v, const float *op, float min_op, size_t n)
{
    float top[5] = {-2, -2, -2, -2, -2};
    for (size_t i = 0; i < n; i++) {
        if (op[i] < min_op || !(v[i] > top[4])) continue;
        int j = 4;
        while (j > 0 && top[j - 1] < v[i]) {
            top[j] = top[j - 1];
            j--;
        }
        top[j] = v[i];
    }
    for (int j = 4; j >= 0; j--)
        if (top[j] > -2) return top[j];
    return 0;
}

/* Raw cosine and relevancy of every Gaussian into e->raw, e->rel (on the GPU when the features
 * live there). */
static int score_gaussians(sp_query_engine *e, const sp_sem_scorer *sc, sp_error *err)
{
    int on_gpu = 0, rc = 0;
    e->dev_scores = 0;
    if (e->d_feat && sc->orthonormal) {
        size_t nb = sizeof(float) * e->splat.n;
        if ((rc = sem_cuda_score(e->dev, sc, e->splat.n, e->d_feat, e->d_raw, e->d_rel, err)) ||
            (rc = sp_device_download(e->dev, e->raw, e->d_raw, nb, err)) ||
            (rc = sp_device_download(e->dev, e->rel, e->d_rel, nb, err)))
            return rc;
        on_gpu = e->dev_scores = 1;
    }
    if (!on_gpu) sp_sem_score(sc, sp_device_pool(e->dev), e->splat.n, e->splat.features, e->raw, e->rel);
    return rc;
}

/* Negatives, scorer and per-Gaussian scores of an embedding under options o. */
static int score_embedding(sp_query_engine *e, const float *embedding, const sp_query_opts *o,
                           sp_sem_scorer *sc, sp_error *err)
{
    int rc = ensure_negatives(e, o, err);
    if (!rc) rc = sp_sem_scorer_init(sc, &e->pca, embedding, e->neg_emb, e->n_neg, o->temperature, err);
    if (!rc) rc = score_gaussians(e, sc, err);
    return rc;
}

/* The view that best sees the best instance: its relevant Gaussians inside its box. */
static int best_view(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                     const sp_query_result *res, int *v, sp_error *err)
{
    const sp_query_instance *I = &res->instances[0];
    uint8_t *mask = calloc(e->splat.n ? e->splat.n : 1, 1);
    if (!mask) return sp_error_set(err, SP_E_NOMEM, "query: out of memory");
    float pad = th->opts->voxel_m;
    for (size_t i = 0; i < e->splat.n; i++) {
        const float *m = e->splat.means + 3 * i;
        int in = e->raw[i] >= th->thr_raw && e->opacity[i] >= th->min_op;
        for (int a = 0; a < 3 && in; a++)
            in = m[a] >= I->extent_min[a] - pad && m[a] <= I->extent_max[a] + pad;
        mask[i] = (uint8_t)in;
    }
    int got = sem_pick_views(e, sc, th, mask, 1, 1, v, NULL, err);
    free(mask);
    if (got < 0) return got;
    if (got == 0) *v = -1;
    return 0;
}

void sp_query_engine_result_init(const sp_query_engine *e, const char *text, sp_query_result *res)
{
    memset(res, 0, sizeof *res);
    res->view_index = -1;
    res->position[0] = res->position[1] = res->position[2] = NAN;
    snprintf(res->text, sizeof res->text, "%s", text ? text : "");
    res->source = e->source;
    res->frame = e->qframe;
}

static void result_init(const sp_query_engine *e, const char *label, int method, sp_query_result *res)
{
    memset(res, 0, sizeof *res);
    res->view_index = -1;
    res->position[0] = res->position[1] = res->position[2] = NAN;
    snprintf(res->text, sizeof res->text, "%s", label ? label : "");
    res->method = method;
    res->source = e->source;
    res->frame = e->qframe;
}

static int query_embedding(sp_query_engine *e, const float *embedding, const char *label,
                           const sp_query_opts *o, sp_query_result *res, sp_error *err)
{
    double t0 = sp_time_now();
    result_init(e, label, o->method, res);
    sp_sem_scorer sc;
    int rc = score_embedding(e, embedding, o, &sc, err);
    if (rc) return rc;
    res->confidence = robust_max(e->raw, e->opacity, o->min_opacity, e->splat.n);
    float rmax = 0;
    for (size_t i = 0; i < e->splat.n; i++)
        if (e->opacity[i] >= o->min_opacity && e->rel[i] > rmax) rmax = e->rel[i];
    res->relevancy_max = rmax;
    double t2 = sp_time_now();
    res->ms_relevancy = (t2 - t0) * 1e3;
    sem_thresholds th;
    th.thr_raw = o->keep_fraction * res->confidence;
    if (th.thr_raw < 0.1f) th.thr_raw = 0.1f;
    th.thr_rel = o->min_relevancy;
    th.min_op = o->min_opacity;
    th.opts = o;
    if (o->method == SP_QUERY_MULTIVIEW && e->n_cams > 0)
        rc = sem_localize_multiview(e, &sc, &th, res, err);
    else {
        res->method = SP_QUERY_3D;
        rc = sem_localize_3d(e, &sc, &th, res, err);
    }
    if (rc) return rc;
    for (int k = 0; k < res->n_instances; k++) res->instances[k].relation_m = NAN;
    res->threshold = o->min_confidence;
    double t3 = sp_time_now();
    res->ms_localize = (t3 - t2) * 1e3;
    if (o->heatmap && e->n_cams > 0) {
        int v = o->heatmap_view;
        if (v >= 0 && (size_t)v >= e->n_cams)
            return sp_error_set(err, SP_E_ARG, "query: heatmap view %d not in 0..%zu", v, e->n_cams - 1);
        if (v < 0 && res->view_index >= 0) v = res->view_index;
        double tp = sp_time_now();
        if (v < 0 && res->n_instances > 0 && (rc = best_view(e, &sc, &th, res, &v, err))) return rc;
        res->ms_stage.hm_pick = (sp_time_now() - tp) * 1e3;
        if (v < 0) v = 0;
        if ((rc = sem_heatmap(e, &th, v, res, err))) return rc;
        res->ms_heatmap = (sp_time_now() - t3) * 1e3;
    }
    res->ms_total = (sp_time_now() - t0) * 1e3;
    return 0;
}

static int check_opts(const sp_query_engine *e, const sp_query_opts *o, sp_error *err)
{
    int rc = sem_check_opts(o, err); /* the numeric ranges (opts.c) */
    if (rc) return rc;
    if (o->heatmap && e->n_cams > 0 && o->heatmap_view >= 0 && (size_t)o->heatmap_view >= e->n_cams)
        return sp_error_set(err, SP_E_ARG, "query: heatmap view %d not in 0..%zu", o->heatmap_view,
                            e->n_cams - 1);
    if (o->method != SP_QUERY_3D && o->method != SP_QUERY_MULTIVIEW)
        return sp_error_set(err, SP_E_ARG, "query: method %d is not 3d (0) or multiview (1)", o->method);
    if (!(o->temperature > 0) || !(o->voxel_m > 0))
        return sp_error_set(err, SP_E_ARG, "query: temperature (%g) and voxel_m (%g) must be > 0",
                            (double)o->temperature, (double)o->voxel_m);
    if (!memchr(o->negatives, 0, sizeof o->negatives))
        return sp_error_set(err, SP_E_ARG, "query: negatives is not NUL-terminated");
    return 0;
}

int sem_query_embedding(sp_query_engine *e, const float *embedding, const char *label,
                        const sp_query_opts *o, sp_query_result *res, sp_error *err)
{
    memset(res, 0, sizeof *res);
    int rc = check_opts(e, o, err);
    if (!rc) rc = query_embedding(e, embedding, label, o, res, err);
    if (rc) sp_query_result_free(res); /* nothing half-made is handed back */
    return rc;
}

int sp_query_engine_query_embedding(sp_query_engine *e, const float *embedding, const char *label,
                                    const sp_query_opts *opts, sp_query_result *res, sp_error *err)
{
    pthread_mutex_lock(&e->mu);
    int rc = sem_query_embedding(e, embedding, label, opts ? opts : &e->defaults, res, err);
    pthread_mutex_unlock(&e->mu);
    return rc;
}

/* Embed, localize, explain (clip, exact). */
static int query_text(sp_query_engine *e, const char *text, const sp_query_opts *o, sp_query_result *res,
                      sp_error *err)
{
    float *q = malloc(sizeof(float) * e->pca.full_dim);
    if (!q) return sp_error_set(err, SP_E_NOMEM, "query: out of memory");
    double t0 = sp_time_now();
    int rc = embed_text(e, text, q, err);
    if (!rc) rc = ensure_negatives(e, o, err);
    double t1 = sp_time_now();
    if (!rc) rc = query_embedding(e, q, text, o, res, err);
    free(q);
    if (!rc && e->enc->explain) rc = e->enc->explain(e, o, res, err);
    res->ms_embed = (t1 - t0) * 1e3;
    res->ms_total += res->ms_embed;
    return rc;
}

int sp_query_engine_query(sp_query_engine *e, const char *text, const sp_query_opts *opts,
                          sp_query_result *res, sp_error *err)
{
    const sp_query_opts *o = opts ? opts : &e->defaults;
    memset(res, 0, sizeof *res);
    int rc = check_opts(e, o, err);
    if (rc) return rc;
    if (!text || !text[0]) return sp_error_set(err, SP_E_ARG, "query: empty text");
    pthread_mutex_lock(&e->mu);
    rc = e->enc->query ? e->enc->query(e, text, o, res, err) : query_text(e, text, o, res, err);
    pthread_mutex_unlock(&e->mu);
    if (rc) sp_query_result_free(res); /* nothing half-made is handed back */
    return rc;
}

/* Embeds text and scores every Gaussian with the default negatives and temperature. */
static int score_text(sp_query_engine *e, const char *text, sp_sem_scorer *sc, sp_error *err)
{
    float *q = malloc(sizeof(float) * e->pca.full_dim);
    if (!q) return sp_error_set(err, SP_E_NOMEM, "query: out of memory");
    int rc = embed_text(e, text, q, err);
    if (!rc) rc = score_embedding(e, q, &e->defaults, sc, err);
    free(q);
    return rc;
}

int sp_query_engine_relevancy(sp_query_engine *e, const char *text, float *relevancy,
                              float *raw_cos, sp_error *err)
{
    if (!relevancy) return sp_error_set(err, SP_E_ARG, "relevancy: no output buffer");
    sp_sem_scorer sc;
    pthread_mutex_lock(&e->mu);
    int rc = score_text(e, text, &sc, err);
    if (!rc) {
        memcpy(relevancy, e->rel, sizeof(float) * e->splat.n);
        if (raw_cos) memcpy(raw_cos, e->raw, sizeof(float) * e->splat.n);
    }
    pthread_mutex_unlock(&e->mu);
    return rc;
}

int sp_query_engine_heatmap(sp_query_engine *e, const char *text, const sp_camera *cam,
                            uint8_t *rgb, float *relevancy, sp_error *err)
{
    if (!cam || !rgb) return sp_error_set(err, SP_E_ARG, "heatmap: no camera or output buffer");
    sp_sem_scorer sc;
    pthread_mutex_lock(&e->mu);
    int rc = score_text(e, text, &sc, err);
    if (!rc) {
        const sp_query_opts *o = &e->defaults;
        float conf = robust_max(e->raw, e->opacity, o->min_opacity, e->splat.n);
        rc = sem_heatmap_render(e, cam, conf >= o->min_confidence, conf, o->min_confidence,
                                o->host_stages, rgb, relevancy, NULL, err);
    }
    pthread_mutex_unlock(&e->mu);
    return rc;
}
