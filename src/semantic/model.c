/* The semantic field inside a model folder: lifting a feature folder into DIR/splat.ply (f_sem_*)
 * and the sidecar DIR/semantic.json with the PCA copied beside it, so the query engine needs
 * nothing but the model folder (and the COLMAP cameras it names, for views). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"

/* Absolute form of a path (so the sidecar stays valid when the CLI ran from elsewhere). */
static void absolute(const char *p, char *out, size_t cap)
{
    char buf[PATH_MAX];
    if (realpath(p, buf)) snprintf(out, cap, "%s", buf);
    else snprintf(out, cap, "%s", p);
}

static const char *jstr(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsString(v) && v->valuestring[0] ? v->valuestring : NULL;
}

/* The capture a model was trained from, as train.json records it. */
static int train_colmap_dir(const char *model_dir, char *out, size_t cap)
{
    char path[2048];
    sp_path_join(path, sizeof path, model_dir, "train.json");
    cJSON *js = NULL;
    sp_error e;
    if (!sp_file_exists(path) || sp_json_read_file(path, &js, &e)) return -1;
    const char *keys[] = {"colmap", "colmap_dir", "data", "capture"};
    const char *v = NULL;
    for (size_t k = 0; k < sizeof keys / sizeof keys[0] && !v; k++) {
        v = jstr(js, keys[k]);
        if (!v) {
            const cJSON *set = cJSON_GetObjectItemCaseSensitive(js, "settings");
            if (set) v = jstr(set, keys[k]);
        }
    }
    if (v) snprintf(out, cap, "%s", v);
    cJSON_Delete(js);
    return v ? 0 : -1;
}

/* The class names hashed into label features, as a JSON array: features.json "classes" (written
 * by `semsplat features --source labels`), else the classes of the capture's labels.json. */
static cJSON *feature_classes(const char *features_dir, const char *colmap_abs)
{
    sp_error lerr = {0}, *err = &lerr; /* no class list is not an error: the exact encoder then answers */
    char path[2048];
    cJSON *fjs = NULL, *tmp = cJSON_CreateObject(), *arr = NULL;
    sp_path_join(path, sizeof path, features_dir, "features.json");
    if (sp_json_read_file(path, &fjs, err)) fjs = NULL;
    const cJSON *from = fjs && cJSON_GetObjectItemCaseSensitive(fjs, "classes") ? fjs : tmp;
    if (tmp) cJSON_AddStringToObject(tmp, "colmap", colmap_abs);
    char (*names)[128] = NULL;
    int n = 0;
    if (tmp && !sem_model_classes(from == fjs ? path : colmap_abs, from, &names, &n, err) && n > 0) {
        arr = cJSON_CreateArray();
        for (int i = 0; arr && i < n; i++) cJSON_AddItemToArray(arr, cJSON_CreateString(names[i]));
    }
    free(names);
    cJSON_Delete(fjs);
    cJSON_Delete(tmp);
    return arr;
}

int sp_semantic_write_sidecar(const char *model_dir, const char *features_dir,
                              const char *colmap_dir, const char *method, sp_error *err)
{
    sp_features f;
    memset(&f, 0, sizeof f);
    int rc = sp_features_open(features_dir, &f, err);
    if (rc) return rc;
    char path[2048], absf[2048], absc[2048];
    size_t shape[2] = {(size_t)f.full_dim, 0};
    sp_path_join(path, sizeof path, model_dir, "semantic_pca_mean.npy");
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 1, shape, f.pca_mean, err))) goto done;
    shape[0] = (size_t)f.dim;
    shape[1] = (size_t)f.full_dim;
    sp_path_join(path, sizeof path, model_dir, "semantic_pca_basis.npy");
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 2, shape, f.pca_basis, err))) goto done;
    absolute(features_dir, absf, sizeof absf);
    absolute(colmap_dir, absc, sizeof absc);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "source", f.source);
    cJSON_AddNumberToObject(o, "dim", f.dim);
    cJSON_AddNumberToObject(o, "full_dim", f.full_dim);
    cJSON_AddStringToObject(o, "features_dir", absf);
    cJSON_AddStringToObject(o, "pca_mean", "semantic_pca_mean.npy");
    cJSON_AddStringToObject(o, "pca_basis", "semantic_pca_basis.npy");
    /* Which text embedding the features live beside: "hash" = sp_label_embedding (no weights),
     * "clip" = the CLIP text tower of `model`. */
    const char *le = f.label_embedding[0] ? f.label_embedding : "clip";
    cJSON_AddStringToObject(o, "label_embedding", le);
    /* the text encoder by name (what the query engine reads): hashed class names are answered by
     * the lexical encoder when their names are known, else by the exact one */
    cJSON *classes = !strcmp(le, "hash") ? feature_classes(features_dir, absc) : NULL;
    cJSON_AddStringToObject(o, "encoder", strcmp(le, "hash") ? SP_ENCODER_CLIP : classes ? SP_ENCODER_LEXICAL
                                                                                  : SP_ENCODER_EXACT);
    if (classes) cJSON_AddItemToObject(o, "classes", classes);
    if (f.model_path[0]) cJSON_AddStringToObject(o, "model", f.model_path);
    else cJSON_AddNullToObject(o, "model");
    cJSON_AddStringToObject(o, "method", method);
    cJSON_AddStringToObject(o, "colmap", absc);
    sp_path_join(path, sizeof path, model_dir, "semantic.json");
    rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
done:
    sp_features_free(&f);
    return rc;
}

typedef struct {
    sp_features *f;
    const long *map_of_view;
    const sp_camera *cams;     /* pinhole, as rendered */
    const sp_camera *map_cams; /* the lens each map was computed through (at the map's size) */
} lift_ctx;

/* A map of a distorted image sees each ray at the distorted pixel: it is resampled into the
 * pinhole camera the renderer uses, and pixels the image did not see are masked out. */
static int lift_target(void *user, size_t view, float *target, uint8_t *mask, sp_error *err)
{
    lift_ctx *c = user;
    size_t i = (size_t)c->map_of_view[view];
    sp_features_image *im = &c->f->images[i];
    int rc = sp_features_load_map(c->f, i, err);
    if (rc) return rc;
    if (im->w != c->cams[view].width || im->h != c->cams[view].height) {
        return sp_error_set(err, SP_E_FORMAT, "%s: map is %dx%d, the camera %dx%d", im->map_file,
                            im->w, im->h, c->cams[view].width, c->cams[view].height);
    }
    if (c->map_cams[view].distortion != SP_DIST_NONE)
        rc = sp_camera_remap_to_pinhole(&c->map_cams[view], im->map, c->f->dim, &c->cams[view], target,
                                        mask, err);
    else
        memcpy(target, im->map, sizeof(float) * (size_t)im->w * im->h * c->f->dim);
    free(im->map); /* one map at a time: the house has 150 of them */
    im->map = NULL;
    return rc;
}

int sp_semantic_lift_features(sp_splat *s, const char *features_dir, const char *colmap_dir,
                              sp_device *dev, const sp_log *log, sp_error *err)
{
    sp_features f;
    sp_colmap_model m;
    sp_raster *r = NULL;
    memset(&f, 0, sizeof f);
    memset(&m, 0, sizeof m);
    sp_camera *cams = NULL, *map_cams = NULL;
    long *map_of_view = NULL;
    int rc, any_distorted = 0;
    if ((rc = sp_features_open(features_dir, &f, err))) return rc;
    if ((rc = sp_colmap_read(colmap_dir, &m, err))) goto done;
    cams = calloc(m.n_images ? m.n_images : 1, sizeof *cams);
    map_cams = calloc(m.n_images ? m.n_images : 1, sizeof *map_cams);
    map_of_view = calloc(m.n_images ? m.n_images : 1, sizeof *map_of_view);
    if (!cams || !map_cams || !map_of_view) {
        rc = sp_error_set(err, SP_E_NOMEM, "lift: out of memory");
        goto done;
    }
    size_t nv = 0;
    for (size_t i = 0; i < m.n_images; i++) {
        long k = sp_features_find(&f, m.images[i].name);
        if (k < 0) continue; /* images without a map (none in practice) are skipped */
        sp_camera cam;
        if ((rc = sp_colmap_image_camera(&m, i, &cam, err))) goto done;
        const sp_features_image *im = &f.images[k];
        /* Render at the map's resolution: scale intrinsics by the map/image size ratio. */
        float sx = (float)im->w / (float)cam.width, sy = (float)im->h / (float)cam.height;
        cam.fx *= sx, cam.cx *= sx, cam.fy *= sy, cam.cy *= sy;
        cam.width = im->w, cam.height = im->h;
        map_cams[nv] = cam; /* distortion acts on normalised coordinates: unchanged by scaling */
        any_distorted |= cam.distortion != SP_DIST_NONE;
        cam.distortion = SP_DIST_NONE;
        cams[nv] = cam;
        map_of_view[nv] = k;
        nv++;
    }
    if (nv == 0) {
        rc = sp_error_set(err, SP_E_NOTFOUND, "lift: no image of %s has a map in %s", colmap_dir,
                          features_dir);
        goto done;
    }
    if ((rc = sp_raster_create(&r, dev, err))) goto done;
    lift_ctx ctx = {&f, map_of_view, cams, map_cams};
    sp_lift_opts lo = sp_lift_opts_default();
    lo.mask = any_distorted;
    double t0 = sp_time_now();
    rc = sp_semantic_lift(r, s, f.dim, cams, nv, lift_target, &ctx, &lo, NULL, log, err);
    if (!rc)
        sp_logf(log, SP_LOG_INFO, "lifted %d-dim %s features from %zu views into %zu Gaussians in %.2f s",
                f.dim, f.source, nv, s->n, sp_time_now() - t0);
done:
    sp_raster_free(r);
    sp_colmap_free(&m);
    sp_features_free(&f);
    free(cams);
    free(map_cams);
    free(map_of_view);
    return rc;
}

int sp_semantic_lift_model(const char *model_dir, const char *features_dir,
                           const char *colmap_dir, sp_device *dev, const sp_log *log,
                           sp_error *err)
{
    char colmap[2048], path[2048];
    sp_splat s;
    memset(&s, 0, sizeof s);
    int rc;
    if (colmap_dir) snprintf(colmap, sizeof colmap, "%s", colmap_dir);
    else if (train_colmap_dir(model_dir, colmap, sizeof colmap))
        return sp_error_set(err, SP_E_ARG,
                            "%s/train.json names no COLMAP capture: pass --colmap DIR", model_dir);
    sp_path_join(path, sizeof path, model_dir, "splat.ply");
    if ((rc = sp_ply_read_splat(path, &s, err))) return rc;
    rc = sp_semantic_lift_features(&s, features_dir, colmap, dev, log, err);
    if (!rc) rc = sp_ply_write_splat(path, &s, err);
    if (!rc) rc = sp_semantic_write_sidecar(model_dir, features_dir, colmap, "lift", err);
    sp_splat_free(&s);
    return rc;
}

int sp_semantic_set_encoder(const char *model_dir, const char *encoder, sp_error *err)
{
    char path[2048];
    sp_path_join(path, sizeof path, model_dir, "semantic.json");
    const sem_encoder *enc = sem_encoder_find(encoder);
    if (!enc)
        return sp_error_set(err, SP_E_ARG, "text encoder '%s' is not clip, lexical or exact", encoder ? encoder : "");
    cJSON *js = NULL;
    int rc = sp_json_read_file(path, &js, err);
    if (rc) return rc;
    const char *le = jstr(js, "label_embedding");
    int label = le && !strcmp(le, "hash");
    char (*names)[128] = NULL;
    int n = 0;
    if (enc->label_space != label)
        rc = sp_error_set(err, SP_E_UNSUPPORTED, "%s: the text encoder %s does not fit its features (%s): use %s",
                          path, encoder, label ? "hashed class names" : "CLIP's text space",
                          label ? "lexical or exact" : "clip");
    else if (!strcmp(encoder, SP_ENCODER_LEXICAL) && !(rc = sem_model_classes(model_dir, js, &names, &n, err)) && n == 0)
        rc = sp_error_set(err, SP_E_NOTFOUND, "%s: the lexical encoder needs the scene's class names (no \"classes\", "
                          "and no labels.json beside the capture it names)", path);
    free(names);
    if (!rc) {
        cJSON_DeleteItemFromObject(js, "encoder");
        cJSON_AddStringToObject(js, "encoder", encoder);
        rc = sp_json_write_file(path, js, err);
    }
    cJSON_Delete(js);
    return rc;
}
