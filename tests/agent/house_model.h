/* The ideal house splat (tests/nav/world_splat.h) written as a model folder, for tests that run
 * `semsplat agent` and `semsplat sim-robot` as processes: DIR/capture (COLMAP cameras, frame.json
 * of a synth capture, labels.json with the class names) and DIR/model (splat.ply with f_sem_*
 * label features, the PCA, semantic.json naming the "exact" encoder and label features,
 * frame.json, train.json, and map.yaml + map.pgm: nav's costmap of the same splat, which
 * sim-robot plans on). What a lift of ground-truth labels into a perfect reconstruction gives. */
#ifndef SEMSPLAT_TEST_HOUSE_MODEL_H
#define SEMSPLAT_TEST_HOUSE_MODEL_H

#include <cjson/cJSON.h>
#include <stdio.h>

#include "nav/world_splat.h"
#include "semsplat/io.h"
#include "semsplat/nav.h"

static inline int hm_write_capture(const ws_scene *sc, const char *cap, sp_error *err)
{
    char path[1300];
    snprintf(path, sizeof path, "%s/sparse/0", cap);
    int rc = sp_mkdirs(path, err);
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    sp_colmap_camera *cams = calloc(sc->n_cams, sizeof *cams);
    sp_colmap_image *ims = calloc(sc->n_cams, sizeof *ims);
    char (*names)[32] = calloc(sc->n_cams, 32);
    if (!cams || !ims || !names) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (size_t i = 0; i < sc->n_cams && !rc; i++) {
        const sp_camera *c = &sc->cams[i];
        cams[i] = (sp_colmap_camera){(uint32_t)i + 1, SP_COLMAP_PINHOLE, (uint64_t)c->width, (uint64_t)c->height, 4,
                                     {c->fx, c->fy, c->cx, c->cy}};
        ims[i].id = (uint32_t)i + 1, ims[i].camera_id = (uint32_t)i + 1;
        sp_colmap_image_set_pose(&ims[i], c);
        snprintf(names[i], 32, "%05zu.png", i);
        ims[i].name = names[i];
    }
    m.n_cameras = sc->n_cams, m.cameras = cams, m.n_images = sc->n_cams, m.images = ims;
    if (!rc) rc = sp_colmap_write_bin(path, &m, err);
    free(cams), free(ims), free(names);
    sp_frame f;
    sp_frame_init(&f, "synth");
    snprintf(path, sizeof path, "%s/frame.json", cap);
    if (!rc) rc = sp_frame_write(path, &f, err);
    cJSON *o = cJSON_CreateObject(), *labs = cJSON_AddObjectToObject(o, "labels");
    cJSON_AddStringToObject(o, "format", "semsplat-labels-1");
    cJSON_AddNumberToObject(o, "background", 0);
    for (int k = 0; k < sc->n_classes; k++) {
        char id[16];
        snprintf(id, sizeof id, "%d", k + 1);
        cJSON *l = cJSON_AddObjectToObject(labs, id);
        cJSON_AddStringToObject(l, "name", sc->classes[k]);
        cJSON_AddStringToObject(l, "class", sc->classes[k]);
        cJSON_AddBoolToObject(l, "is_structure", !strcmp(sc->classes[k], "wall"));
    }
    snprintf(path, sizeof path, "%s/labels.json", cap);
    if (!rc) rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
    return rc;
}

static inline int hm_write_semantics(const ws_scene *sc, const char *model, const char *cap, sp_error *err)
{
    char path[1300];
    size_t shape[2] = {(size_t)sc->pca.full_dim, 0};
    snprintf(path, sizeof path, "%s/semantic_pca_mean.npy", model);
    int rc = sp_npy_write(path, SP_DTYPE_F32, 1, shape, sc->pca.mean, err);
    shape[0] = (size_t)sc->pca.dim, shape[1] = (size_t)sc->pca.full_dim;
    snprintf(path, sizeof path, "%s/semantic_pca_basis.npy", model);
    if (!rc) rc = sp_npy_write(path, SP_DTYPE_F32, 2, shape, sc->pca.basis, err);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "source", "labels");
    cJSON_AddNumberToObject(o, "dim", sc->pca.dim);
    cJSON_AddNumberToObject(o, "full_dim", sc->pca.full_dim);
    cJSON_AddStringToObject(o, "pca_mean", "semantic_pca_mean.npy");
    cJSON_AddStringToObject(o, "pca_basis", "semantic_pca_basis.npy");
    cJSON_AddStringToObject(o, "label_embedding", "hash");
    cJSON_AddStringToObject(o, "encoder", "exact");
    cJSON_AddStringToObject(o, "method", "ideal splat (test)");
    cJSON_AddStringToObject(o, "colmap", cap);
    snprintf(path, sizeof path, "%s/semantic.json", model);
    if (!rc) rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
    return rc;
}

/* Writes dir/capture and dir/model; model_out gets the model folder, start (x, y, yaw) nav's
 * default start on that map. */
static inline int hm_write(const ws_scene *sc, const char *dir, sp_device *dev, char *model_out, size_t cap,
                           float start[3], sp_error *err)
{
    char capdir[1100], path[1300];
    snprintf(capdir, sizeof capdir, "%s/capture", dir);
    snprintf(model_out, cap, "%s/model", dir);
    int rc = sp_mkdirs(model_out, err);
    if (!rc) rc = hm_write_capture(sc, capdir, err);
    if (!rc) rc = hm_write_semantics(sc, model_out, capdir, err);
    snprintf(path, sizeof path, "%s/splat.ply", model_out);
    if (!rc) rc = sp_ply_write_splat(path, &sc->splat, err);
    sp_frame f;
    sp_frame_init(&f, "synth");
    snprintf(path, sizeof path, "%s/frame.json", model_out);
    if (!rc) rc = sp_frame_write(path, &f, err);
    char js[1300];
    snprintf(js, sizeof js, "{\"settings\": {\"colmap\": \"%s\"}}", capdir);
    snprintf(path, sizeof path, "%s/train.json", model_out);
    if (!rc) rc = sp_write_file_atomic(path, js, strlen(js), err);
    sp_nav *nav = NULL;
    if (!rc) rc = sp_nav_create(&nav, NULL, &sc->splat, sc->cams, sc->n_cams, NULL, dev, NULL, err);
    snprintf(path, sizeof path, "%s/map.yaml", model_out);
    if (!rc) rc = sp_costmap_write_map(sp_nav_costmap(nav), path, err);
    if (!rc) rc = sp_nav_default_start(nav, start, err);
    sp_nav_free(nav);
    return rc;
}

#endif
