/* `semsplat features`: per-image feature maps from one source (CLIP dense features, external .npy
 * maps, or synthetic label images), a scene PCA fitted on sampled pixel features, and the
 * compressed maps written as a feature folder (features.json, pca_*.npy, maps/<stem>.npy f16).
 * Two passes: maps are computed (CLIP maps cached as f16 under the output folder), pixels are
 * sampled for the PCA, then every map is projected and written. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cJSON.h>

#include "clip_internal.h"
#include "compat/sgemm_blocked.h"
#include "features_internal.h"
#include "semsplat/io.h"

sp_features_opts sp_features_opts_default(void)
{
    sp_features_opts o;
    memset(&o, 0, sizeof o);
    o.source = "clip";
    o.dim = 32;
    o.map_factor = 4;
    o.pca_samples = 50000;
    o.dense = sp_clip_dense_opts_default();
    return o;
}

typedef struct extract_ctx {
    const sp_features_opts *o;
    sp_colmap_model model;
    char capture[1024], images_dir[1200], labels_dir[1200];
    sp_clip *clip;
    int full_dim;
    clip_label_table labels;
    float *class_emb; /* [n_classes][full_dim] */
} extract_ctx;

static void stem_of(const char *name, char *out, size_t cap)
{
    snprintf(out, cap, "%s", name);
    char *dot = strrchr(out, '.');
    char *slash = strrchr(out, '/');
    if (dot && (!slash || dot > slash)) *dot = 0;
    for (char *p = out; *p; p++)
        if (*p == '/') *p = '_';
}

/* The image's own size, from its COLMAP camera. */
static void image_size(const extract_ctx *x, size_t i, int *w, int *h)
{
    const sp_colmap_camera *cam = sp_colmap_find_camera(&x->model, x->model.images[i].camera_id);
    *w = cam ? (int)cam->width : 0;
    *h = cam ? (int)cam->height : 0;
}

static int map_clip(extract_ctx *x, size_t i, float **map, int *mw, int *mh, sp_error *err)
{
    char path[1600];
    sp_path_join(path, sizeof path, x->images_dir, x->model.images[i].name);
    sp_image img;
    int rc = sp_image_read(path, &img, err);
    if (rc) return rc;
    float *rgb = NULL;
    rc = sp_image_to_rgbf(&img, &rgb, err);
    int w = img.width, h = img.height;
    sp_image_free(&img);
    if (rc) return rc;
    sp_clip_dense_grid(x->clip, &x->o->dense, w, h, mw, mh);
    *map = malloc((size_t)*mw * *mh * x->full_dim * sizeof **map);
    if (!*map) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    else rc = sp_clip_dense_features(x->clip, rgb, w, h, &x->o->dense, *map, err);
    free(rgb);
    if (rc) sp_error_prefix(err, "%s: ", path);
    return rc;
}

static int map_npy(extract_ctx *x, size_t i, float **map, int *mw, int *mh, sp_error *err)
{
    char stem[512], file[600], path[1800];
    stem_of(x->model.images[i].name, stem, sizeof stem);
    snprintf(file, sizeof file, "%s.npy", stem);
    sp_path_join(path, sizeof path, x->o->maps_dir, file);
    sp_npy a;
    int rc = sp_npy_read(path, &a, err);
    if (rc) return rc;
    if (a.ndim != 3) {
        sp_npy_free(&a);
        return sp_error_set(err, SP_E_FORMAT, "%s: %d dimensions, expected [H][W][C] or [C][H][W]", path, a.ndim);
    }
    float *f = NULL;
    if ((rc = sp_npy_to_f32(&a, &f, err))) {
        sp_npy_free(&a);
        return rc;
    }
    int iw, ih;
    image_size(x, i, &iw, &ih);
    /* channels last or first: the reading whose map aspect is closer to the image's wins */
    double ar = ih > 0 && iw > 0 ? (double)ih / iw : 1.0;
    double hwc = fabs(log((double)a.shape[0] / a.shape[1] / ar)), chw = fabs(log((double)a.shape[1] / a.shape[2] / ar));
    int is_chw = chw < hwc;
    int C = (int)(is_chw ? a.shape[0] : a.shape[2]);
    *mh = (int)(is_chw ? a.shape[1] : a.shape[0]);
    *mw = (int)(is_chw ? a.shape[2] : a.shape[1]);
    sp_npy_free(&a);
    if (x->full_dim == 0) x->full_dim = C;
    if (C != x->full_dim) {
        free(f);
        return sp_error_set(err, SP_E_FORMAT, "%s: %d channels, earlier maps had %d", path, C, x->full_dim);
    }
    if (is_chw) {
        float *t = malloc((size_t)C * *mh * *mw * sizeof *t);
        if (!t) { free(f); return sp_error_set(err, SP_E_NOMEM, "out of memory"); }
        size_t hw = (size_t)*mh * *mw;
        for (int c = 0; c < C; c++)
            for (size_t p = 0; p < hw; p++) t[p * C + c] = f[c * hw + p];
        free(f);
        f = t;
    }
    *map = f;
    return 0;
}

/* Label maps are class weights per cell (features_labels.c): [cells][n_classes]. */
static int map_labels(extract_ctx *x, size_t i, float **map, int *mw, int *mh, sp_error *err)
{
    char stem[512], file[600], path[1800];
    stem_of(x->model.images[i].name, stem, sizeof stem);
    snprintf(file, sizeof file, "%s.png", stem);
    sp_path_join(path, sizeof path, x->labels_dir, file);
    return label_weights(path, &x->labels, x->o->map_factor > 0 ? x->o->map_factor : 4, map, mw, mh, err);
}

static int compute_map(extract_ctx *x, size_t i, float **map, int *mw, int *mh, sp_error *err)
{
    const char *s = x->o->source;
    if (!strcmp(s, "clip")) return map_clip(x, i, map, mw, mh, err);
    if (!strcmp(s, "npy")) return map_npy(x, i, map, mw, mh, err);
    return map_labels(x, i, map, mw, mh, err);
}

static uint64_t rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static int setup(extract_ctx *x, sp_error *err)
{
    const sp_features_opts *o = x->o;
    int rc = sp_colmap_read(o->colmap_dir, &x->model, err);
    if (rc) return rc;
    if (x->model.n_images == 0)
        return sp_error_set(err, SP_E_FORMAT, "%s: the COLMAP model has no images", o->colmap_dir);
    /* the capture root: colmap_dir itself when it holds images/, else two levels above sparse/0 */
    char mdir[1024];
    snprintf(x->capture, sizeof x->capture, "%s", o->colmap_dir);
    sp_path_join(x->images_dir, sizeof x->images_dir, o->colmap_dir, "images");
    if (!sp_file_exists(x->images_dir) && !sp_colmap_find_model_dir(o->colmap_dir, mdir, sizeof mdir, err)) {
        for (int up = 0; up < 2; up++) {
            char *s = strrchr(mdir, '/');
            if (s) *s = 0;
        }
        snprintf(x->capture, sizeof x->capture, "%s", mdir);
        sp_path_join(x->images_dir, sizeof x->images_dir, mdir, "images");
    }
    if (o->images_dir) snprintf(x->images_dir, sizeof x->images_dir, "%s", o->images_dir);
    if (o->labels_dir) snprintf(x->labels_dir, sizeof x->labels_dir, "%s", o->labels_dir);
    else sp_path_join(x->labels_dir, sizeof x->labels_dir, x->capture, "labels");
    if (!strcmp(o->source, "clip")) {
        if (!o->clip_weights)
            return sp_error_set(err, SP_E_ARG, "source clip needs CLIP weights (--clip MODEL.safetensors)");
        if ((rc = sp_clip_load(&x->clip, o->clip_weights, o->clip_config, o->dev, err))) return rc;
        if (o->fp16 && (rc = sp_clip_set_fp16(x->clip, 1, err))) return rc;
        x->full_dim = sp_clip_embed_dim(x->clip);
    } else if (!strcmp(o->source, "npy")) {
        if (!o->maps_dir) return sp_error_set(err, SP_E_ARG, "source npy needs a folder of maps (--maps DIR)");
    } else if (!strcmp(o->source, "labels")) {
        char lj[1300];
        sp_path_join(lj, sizeof lj, x->capture, "labels.json");
        if (!sp_file_exists(lj)) sp_path_join(lj, sizeof lj, x->labels_dir, "labels.json");
        if ((rc = clip_label_table_read(lj, &x->labels, err))) return rc;
        if (o->clip_weights) {
            if ((rc = sp_clip_load(&x->clip, o->clip_weights, o->clip_config, o->dev, err))) return rc;
            x->full_dim = sp_clip_embed_dim(x->clip);
        } else {
            x->full_dim = 512;
        }
        x->class_emb = malloc((size_t)x->labels.n_classes * x->full_dim * sizeof(float));
        if (!x->class_emb) return sp_error_set(err, SP_E_NOMEM, "out of memory");
        if (x->clip) { /* every class name in one batch */
            const char **names = malloc((size_t)x->labels.n_classes * sizeof *names);
            if (!names) return sp_error_set(err, SP_E_NOMEM, "out of memory");
            for (int k = 0; k < x->labels.n_classes; k++) names[k] = x->labels.class_names[k];
            rc = sp_clip_encode_text(x->clip, names, x->labels.n_classes, x->class_emb, err);
            free(names);
            if (rc) return rc;
        } else {
            for (int k = 0; k < x->labels.n_classes; k++)
                sp_label_embedding(x->labels.class_names[k], x->full_dim, x->class_emb + (size_t)k * x->full_dim);
        }
    } else {
        return sp_error_set(err, SP_E_ARG, "unknown feature source '%s' (clip, npy, labels)", o->source);
    }
    return 0;
}

static int write_json(extract_ctx *x, const int *mw, const int *mh, const char *const *files, sp_error *err)
{
    const sp_features_opts *o = x->o;
    cJSON *root = cJSON_CreateObject(), *imgs = cJSON_CreateArray();
    cJSON_AddStringToObject(root, "format", "semsplat-features-1");
    cJSON_AddStringToObject(root, "source", o->source);
    cJSON_AddNumberToObject(root, "dim", o->dim);
    cJSON_AddNumberToObject(root, "full_dim", x->full_dim);
    if (o->clip_weights && x->clip) cJSON_AddStringToObject(root, "model", o->clip_weights);
    else cJSON_AddNullToObject(root, "model");
    if (!strcmp(o->source, "labels")) {
        cJSON_AddStringToObject(root, "label_embedding", x->clip ? "clip" : "hash");
        cJSON_AddNumberToObject(root, "map_factor", o->map_factor);
        /* the class names embedded (what a text encoder can match against) */
        cJSON *cl = cJSON_AddArrayToObject(root, "classes");
        for (int k = 0; k < x->labels.n_classes; k++)
            if (strcmp(x->labels.class_names[k], "background"))
                cJSON_AddItemToArray(cl, cJSON_CreateString(x->labels.class_names[k]));
    }
    if (!strcmp(o->source, "npy")) cJSON_AddStringToObject(root, "maps_source", o->maps_dir);
    if (x->clip && !strcmp(o->source, "clip")) {
        cJSON *d = cJSON_CreateObject();
        cJSON_AddStringToObject(d, "head", o->dense.head == SP_CLIP_HEAD_MASKCLIP ? "maskclip" : "clearclip");
        cJSON *sc = cJSON_CreateArray();
        for (int s = 0; s < o->dense.n_scales; s++) cJSON_AddItemToArray(sc, cJSON_CreateNumber(o->dense.scales[s]));
        cJSON_AddItemToObject(d, "scales", sc);
        cJSON_AddNumberToObject(d, "tile", o->dense.tile);
        cJSON_AddNumberToObject(d, "stride", o->dense.stride);
        cJSON_AddItemToObject(root, "dense", d);
    }
    cJSON_AddItemToObject(root, "images", imgs);
    for (size_t i = 0; i < x->model.n_images; i++) {
        cJSON *e = cJSON_CreateObject();
        int iw, ih;
        image_size(x, i, &iw, &ih);
        cJSON_AddStringToObject(e, "name", x->model.images[i].name);
        cJSON_AddStringToObject(e, "map", files[i]);
        cJSON_AddNumberToObject(e, "height", mh[i]);
        cJSON_AddNumberToObject(e, "width", mw[i]);
        cJSON_AddNumberToObject(e, "image_height", ih);
        cJSON_AddNumberToObject(e, "image_width", iw);
        cJSON_AddItemToArray(imgs, e);
    }
    char path[1200];
    sp_path_join(path, sizeof path, o->out_dir, "features.json");
    int rc = sp_json_write_file(path, root, err);
    cJSON_Delete(root);
    return rc;
}

/* A labels cell's full feature: its class weights times the class embeddings. */
static void label_feature(const extract_ctx *x, const float *w, float *out)
{
    int F = x->full_dim;
    memset(out, 0, (size_t)F * sizeof *out);
    for (int k = 0; k < x->labels.n_classes; k++) {
        if (w[k] == 0) continue;
        const float *e = x->class_emb + (size_t)k * F;
        for (int j = 0; j < F; j++) out[j] += w[k] * e[j];
    }
}

/* Map rows -> PCA codes as one product: code = row table^T - offset, with table [D][cols] and
 * offset [D]. Full features: table = basis, offset = basis mean. Labels (rows are class weights
 * summing to 1): table^T = the classes' codes (E - mean) basis^T, offset = 0. */
typedef struct encoder {
    int cols, D;
    float *table, *offset;
} encoder;

static int encoder_make(const extract_ctx *x, const float *mean, const float *basis, int D, encoder *e, sp_error *err)
{
    int F = x->full_dim, labels = !strcmp(x->o->source, "labels"), cols = labels ? x->labels.n_classes : F;
    e->cols = cols;
    e->D = D;
    e->table = malloc((size_t)D * cols * sizeof *e->table);
    e->offset = calloc((size_t)D, sizeof *e->offset);
    if (!e->table || !e->offset) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (int k = 0; k < D; k++) {
        const float *b = basis + (size_t)k * F;
        if (labels) {
            for (int c = 0; c < cols; c++) {
                const float *ec = x->class_emb + (size_t)c * F;
                double s = 0;
                for (int j = 0; j < F; j++) s += (double)b[j] * (ec[j] - mean[j]);
                e->table[(size_t)k * cols + c] = (float)s;
            }
        } else {
            double s = 0;
            for (int j = 0; j < F; j++) s += (double)b[j] * mean[j];
            memcpy(e->table + (size_t)k * cols, b, (size_t)F * sizeof *b);
            e->offset[k] = (float)s;
        }
    }
    return 0;
}

static int encode_map(const encoder *e, const float *map, size_t cells, uint16_t *out, sp_error *err)
{
    const size_t chunk = 4096;
    float *code = malloc(chunk * e->D * sizeof *code);
    if (!code) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (size_t c0 = 0; c0 < cells; c0 += chunk) {
        size_t nb = cells - c0 < chunk ? cells - c0 : chunk;
        /* on the calling thread: the images themselves run in parallel */
        if (sp_sgemm_blocked(NULL, 0, 1, (int)nb, e->D, e->cols, 1.f, map + c0 * e->cols, e->cols, e->table, e->cols, 0.f,
                             code, e->D)) {
            free(code);
            return sp_error_set(err, SP_E_NOMEM, "out of memory");
        }
        for (size_t c = 0; c < nb; c++)
            for (int k = 0; k < e->D; k++) out[(c0 + c) * e->D + k] = sp_float_to_half(code[c * e->D + k] - e->offset[k]);
    }
    free(code);
    return 0;
}

/* Pass 2 for one image: its full map (from the cache, or computed again), its PCA codes, the
 * map file. Touches nothing shared but read-only state, so images run in parallel. */
typedef struct codes_job {
    extract_ctx *x;
    const encoder *enc;
    const int *mw, *mh;
    const char *const *files;
    const char *cache_dir; /* NULL: maps are computed again */
    int *rc;
    sp_error *errs;
} codes_job;

static int write_codes(const codes_job *j, size_t i, sp_error *err)
{
    const extract_ctx *x = j->x;
    char stem[512], path[2000];
    float *map = NULL;
    int w2 = 0, h2 = 0, rc, D = j->enc->D;
    stem_of(x->model.images[i].name, stem, sizeof stem);
    if (j->cache_dir) {
        snprintf(path, sizeof path, "%s/%s.npy", j->cache_dir, stem);
        sp_npy a;
        if ((rc = sp_npy_read(path, &a, err))) return rc;
        rc = sp_npy_to_f32(&a, &map, err);
        sp_npy_free(&a);
        unlink(path);
        if (rc) return rc;
    } else if ((rc = compute_map(j->x, i, &map, &w2, &h2, err))) {
        return rc;
    }
    size_t cells = (size_t)j->mw[i] * j->mh[i];
    uint16_t *h = malloc(cells * D * sizeof *h);
    if (!h) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    else rc = encode_map(j->enc, map, cells, h, err);
    size_t shape[3] = {(size_t)j->mh[i], (size_t)j->mw[i], (size_t)D};
    sp_path_join(path, sizeof path, x->o->out_dir, j->files[i]);
    if (!rc) rc = sp_npy_write(path, SP_DTYPE_F16, 3, shape, h, err);
    free(h);
    free(map);
    return rc;
}

static void codes_task(void *ctx, long i, int thread_id)
{
    codes_job *j = ctx;
    (void)thread_id;
    j->rc[i] = write_codes(j, (size_t)i, &j->errs[i]);
}

/* Every image's codes across the device's (or a temporary) pool; the first failing image's
 * error is reported. */
static int write_all_codes(extract_ctx *x, const encoder *enc, const int *mw, const int *mh, const char *const *files,
                           const char *cache_dir, sp_error *err)
{
    size_t n = x->model.n_images;
    codes_job j = {x, enc, mw, mh, files, cache_dir, calloc(n, sizeof(int)), calloc(n, sizeof(sp_error))};
    sp_pool *pool = x->o->dev ? sp_device_pool(x->o->dev) : NULL, *own = NULL;
    int rc = j.rc && j.errs ? 0 : sp_error_set(err, SP_E_NOMEM, "out of memory");
    if (!rc && !pool && sp_pool_create(&own, 0, err) == 0) pool = own;
    if (!rc) sp_pool_for(pool, (long)n, codes_task, &j);
    for (size_t i = 0; !rc && i < n; i++)
        if (j.rc[i]) {
            rc = j.rc[i];
            if (err) *err = j.errs[i];
        }
    sp_pool_free(own);
    free(j.rc);
    free(j.errs);
    return rc;
}

int sp_features_extract(const sp_features_opts *opts, sp_error *err)
{
    sp_features_opts o = *opts;
    /* 0 picks the default; negative or absurd values are errors, not defaults */
    if (o.map_factor < 0 || o.map_factor > 64)
        return sp_error_set(err, SP_E_ARG, "features: map factor %d outside 1..64 (0: 4)", o.map_factor);
    if (o.pca_samples < 0 || o.pca_samples > 100000000)
        return sp_error_set(err, SP_E_ARG, "features: PCA samples %ld outside 1..100000000 (0: 50000)", o.pca_samples);
    if (o.dim == 0) o.dim = 32;
    if (o.map_factor <= 0) o.map_factor = 4;
    if (o.pca_samples <= 0) o.pca_samples = 50000;
    if (o.dense.n_scales <= 0) o.dense = sp_clip_dense_opts_default();
    if (!o.source) o.source = "clip";
    if (!o.colmap_dir || !o.out_dir) return sp_error_set(err, SP_E_ARG, "features: need a COLMAP folder and an output folder");
    int rc0;
    if ((rc0 = sp_feature_dim_check(o.dim, SP_E_ARG, "features: --dim", err))) return rc0;
    extract_ctx x;
    memset(&x, 0, sizeof x);
    x.o = &o;
    size_t n = 0;
    int *mw = NULL, *mh = NULL, rc;
    char **files = NULL, cache_dir[1200], maps_dir[1200], path[2000];
    float *samples = NULL, *mean = NULL, *basis = NULL;
    encoder enc = {0};
    if ((rc = setup(&x, err))) goto done;
    n = x.model.n_images;
    sp_path_join(maps_dir, sizeof maps_dir, o.out_dir, "maps");
    sp_path_join(cache_dir, sizeof cache_dir, o.out_dir, ".full");
    if ((rc = sp_mkdirs(maps_dir, err))) goto done;
    int cache = !strcmp(o.source, "clip");
    if (cache && (rc = sp_mkdirs(cache_dir, err))) goto done;
    mw = calloc(n, sizeof *mw);
    mh = calloc(n, sizeof *mh);
    files = calloc(n, sizeof *files);
    size_t per_image = (size_t)((o.pca_samples + (long)n - 1) / (long)n), n_samp = 0;
    if (!mw || !mh || !files) { rc = sp_error_set(err, SP_E_NOMEM, "out of memory"); goto done; }
    sp_progress pr;
    sp_progress_begin(&pr, o.log, "features", (long)n, "img");
    uint64_t rng = 0x5EED5EED;
    int labels = !strcmp(o.source, "labels");
    for (size_t i = 0; i < n; i++) {
        float *map = NULL;
        if ((rc = compute_map(&x, i, &map, &mw[i], &mh[i], err))) goto done;
        int F = x.full_dim, cols = labels ? x.labels.n_classes : F;
        if (!samples) {
            samples = malloc(per_image * n * F * sizeof *samples);
            if (!samples) { free(map); rc = sp_error_set(err, SP_E_NOMEM, "PCA samples: out of memory"); goto done; }
        }
        size_t cells = (size_t)mw[i] * mh[i];
        for (size_t k = 0; k < per_image && k < cells; k++) {
            size_t c = per_image >= cells ? k : (size_t)(rng_next(&rng) % cells);
            if (labels) label_feature(&x, map + c * cols, samples + n_samp++ * F);
            else memcpy(samples + n_samp++ * F, map + c * F, (size_t)F * sizeof(float));
        }
        char stem[512];
        stem_of(x.model.images[i].name, stem, sizeof stem);
        files[i] = malloc(600);
        if (!files[i]) { free(map); rc = sp_error_set(err, SP_E_NOMEM, "out of memory"); goto done; }
        snprintf(files[i], 600, "maps/%s.npy", stem);
        if (cache) {
            size_t shape[3] = {(size_t)mh[i], (size_t)mw[i], (size_t)F};
            uint16_t *h = malloc(cells * F * sizeof *h);
            if (!h) { free(map); rc = sp_error_set(err, SP_E_NOMEM, "out of memory"); goto done; }
            for (size_t k = 0; k < cells * F; k++) h[k] = sp_float_to_half(map[k]);
            snprintf(path, sizeof path, "%s/%s.npy", cache_dir, stem);
            rc = sp_npy_write(path, SP_DTYPE_F16, 3, shape, h, err);
            free(h);
            if (rc) { free(map); goto done; }
        }
        free(map);
        sp_progress_update(&pr, (long)i + 1, NULL);
    }
    sp_progress_end(&pr, NULL);
    int F = x.full_dim, D = o.dim;
    if (D > F) { rc = sp_error_set(err, SP_E_ARG, "features: --dim %d exceeds the %d feature channels", D, F); goto done; }
    mean = malloc((size_t)F * sizeof *mean);
    basis = malloc((size_t)D * F * sizeof *basis);
    if (!mean || !basis) { rc = sp_error_set(err, SP_E_NOMEM, "out of memory"); goto done; }
    sp_logf(o.log, SP_LOG_INFO, "PCA %d -> %d on %zu pixel features", F, D, n_samp);
    if ((rc = clip_pca_fit_dev(o.dev, samples, n_samp, F, D, mean, basis, err))) goto done;
    if ((rc = encoder_make(&x, mean, basis, D, &enc, err))) goto done;
    if ((rc = write_all_codes(&x, &enc, mw, mh, (const char *const *)files, cache ? cache_dir : NULL, err))) goto done;
    if (cache) rmdir(cache_dir);
    size_t s1 = (size_t)F, s2[2] = {(size_t)D, (size_t)F};
    sp_path_join(path, sizeof path, o.out_dir, "pca_mean.npy");
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 1, &s1, mean, err))) goto done;
    sp_path_join(path, sizeof path, o.out_dir, "pca_basis.npy");
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 2, s2, basis, err))) goto done;
    rc = write_json(&x, mw, mh, (const char *const *)files, err);
done:
    for (size_t i = 0; files && i < n; i++) free(files[i]);
    free(files);
    free(mw);
    free(mh);
    free(samples);
    free(mean);
    free(basis);
    free(enc.table);
    free(enc.offset);
    free(x.class_emb);
    clip_label_table_free(&x.labels);
    sp_clip_free(x.clip);
    sp_colmap_free(&x.model);
    return rc;
}
