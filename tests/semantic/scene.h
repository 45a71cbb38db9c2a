/* A tiny labelled scene for the semantic tests: a floor, two chairs, a table and a lamp made of
 * Gaussians on box surfaces, a ring of cameras around them, and label features (each class's
 * sp_label_embedding, compressed by an exact PCA). Builds in milliseconds. */
#ifndef SP_TEST_SEM_SCENE_H
#define SP_TEST_SEM_SCENE_H

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"
#include "test.h"

#define SC_FULL 512 /* as CLIP: random label embeddings are near-orthogonal in 512-D */
#define SC_DIM 8
#define SC_CLASSES 4
static const char *const sc_class_names[SC_CLASSES] = {"floor", "chair", "table", "lamp"};

typedef struct {
    int cls;
    float lo[3], hi[3];
} sc_box;

/* two chairs, a table, a lamp (world metres, z up) */
static const sc_box sc_objects[] = {
    {1, {-1.25f, 0.30f, 0.0f}, {-0.80f, 0.75f, 0.9f}},
    {1, {0.80f, 0.30f, 0.0f}, {1.25f, 0.75f, 0.9f}},
    {2, {-0.50f, -1.30f, 0.0f}, {0.50f, -0.70f, 0.75f}},
    {3, {1.40f, -1.60f, 0.0f}, {1.60f, -1.40f, 1.2f}},
};
#define SC_N_OBJECTS 4

static inline void sc_center(int k, float c[3])
{
    for (int a = 0; a < 3; a++) c[a] = 0.5f * (sc_objects[k].lo[a] + sc_objects[k].hi[a]);
}

/* PCA of the class embeddings: mean = their average, basis = Gram-Schmidt of (e_k - mean),
 * completed with random directions to SC_DIM rows. Class features are exact. */
static inline void sc_make_pca(sp_sem_pca *p, float emb[SC_CLASSES][SC_FULL])
{
    test_rng r = {2024};
    p->dim = SC_DIM;
    p->full_dim = SC_FULL;
    p->mean = calloc(SC_FULL, sizeof(float));
    p->basis = calloc(SC_FULL * SC_DIM, sizeof(float));
    for (int k = 0; k < SC_CLASSES; k++) {
        sp_label_embedding(sc_class_names[k], SC_FULL, emb[k]);
        for (int j = 0; j < SC_FULL; j++) p->mean[j] += emb[k][j] / SC_CLASSES;
    }
    int rows = 0;
    for (int k = 0; rows < SC_DIM; k++) {
        float *row = p->basis + rows * SC_FULL;
        for (int j = 0; j < SC_FULL; j++)
            row[j] = k < SC_CLASSES ? emb[k][j] - p->mean[j] : (float)test_range(&r, -1, 1);
        for (int q = 0; q < rows; q++) {
            const float *o = p->basis + q * SC_FULL;
            double d = 0;
            for (int j = 0; j < SC_FULL; j++) d += (double)row[j] * o[j];
            for (int j = 0; j < SC_FULL; j++) row[j] -= (float)(d * o[j]);
        }
        double n = 0;
        for (int j = 0; j < SC_FULL; j++) n += (double)row[j] * row[j];
        if (n < 1e-8) continue; /* the k-th class difference is dependent: skip it */
        for (int j = 0; j < SC_FULL; j++) row[j] /= (float)sqrt(n);
        rows++;
    }
}

static inline void sc_encode(const sp_sem_pca *p, const float *full, float *f)
{
    for (int k = 0; k < p->dim; k++) {
        double d = 0;
        for (int j = 0; j < p->full_dim; j++)
            d += (double)p->basis[k * p->full_dim + j] * (full[j] - p->mean[j]);
        f[k] = (float)d;
    }
}

/* Gaussians on the faces of each box (spacing ~5 cm) plus a floor; cls_out [n] gets the class. */
static inline void sc_make_splat(sp_splat *s, int **cls_out, const sp_sem_pca *p,
                                 float emb[SC_CLASSES][SC_FULL])
{
    const float step = 0.05f;
    size_t cap = 20000, n = 0;
    float *pos = malloc(sizeof(float) * 3 * cap);
    int *cls = malloc(sizeof(int) * cap);
    for (float x = -2.5f; x <= 2.5f; x += 2 * step)
        for (float y = -2.5f; y <= 2.5f; y += 2 * step) {
            pos[3 * n] = x, pos[3 * n + 1] = y, pos[3 * n + 2] = 0.0f;
            cls[n++] = 0;
        }
    for (int k = 0; k < SC_N_OBJECTS; k++) {
        const sc_box *b = &sc_objects[k];
        for (int ax = 0; ax < 3; ax++)
            for (int side = 0; side < 2; side++) {
                if (ax == 2 && side == 0) continue; /* the bottom face is on the floor */
                int u = (ax + 1) % 3, v = (ax + 2) % 3;
                for (float a = b->lo[u]; a <= b->hi[u] + 1e-4f; a += step)
                    for (float c = b->lo[v]; c <= b->hi[v] + 1e-4f; c += step) {
                        if (n == cap) break;
                        pos[3 * n + ax] = side ? b->hi[ax] : b->lo[ax];
                        pos[3 * n + u] = a;
                        pos[3 * n + v] = c;
                        cls[n++] = b->cls;
                    }
            }
    }
    sp_error err = {0};
    sp_splat_alloc(s, n, 0, SC_DIM, &err);
    float feat[SC_CLASSES][SC_DIM];
    for (int k = 0; k < SC_CLASSES; k++) sc_encode(p, emb[k], feat[k]);
    /* colours: a distinct tint per class so heatmaps have context */
    const float tint[SC_CLASSES][3] = {{0.6f, 0.55f, 0.5f}, {0.2f, 0.3f, 0.8f}, {0.6f, 0.35f, 0.15f},
                                       {0.9f, 0.9f, 0.3f}};
    for (size_t i = 0; i < n; i++) {
        memcpy(s->means + 3 * i, pos + 3 * i, sizeof(float) * 3);
        float ls = logf(cls[i] == 0 ? 0.06f : 0.03f);
        s->log_scales[3 * i] = s->log_scales[3 * i + 1] = s->log_scales[3 * i + 2] = ls;
        s->opacity_logits[i] = 3.0f;
        for (int c = 0; c < 3; c++) s->sh[3 * i + c] = (tint[cls[i]][c] - 0.5f) / SP_SH_C0;
        memcpy(s->features + SC_DIM * i, feat[cls[i]], sizeof feat[0]);
    }
    free(pos);
    *cls_out = cls;
}

/* n cameras on a ring of radius 3.6 m at height 1.2 m looking at (0, -0.3, 0.4). */
static inline void sc_make_cams(sp_camera *cams, int n, int w, int h)
{
    for (int c = 0; c < n; c++) {
        double a = 2 * M_PI * c / n;
        sp_camera *cam = &cams[c];
        memset(cam, 0, sizeof *cam);
        cam->width = w, cam->height = h;
        cam->fx = cam->fy = 0.8f * w;
        cam->cx = 0.5f * w, cam->cy = 0.5f * h;
        sp_camera_look_at(cam, sp_v3((float)(3.6 * cos(a)), (float)(3.6 * sin(a)) - 0.3f, 1.2f),
                          sp_v3(0, -0.3f, 0.4f), sp_v3(0, 0, 1));
    }
}

/* The query engine on the tiny scene with a ring of n_cams w x h cameras on a new CPU device of
 * n_threads (emb may be NULL). Exits on failure: this is a test's setup. */
static inline void sc_make_engine(int n_cams, int w, int h, int n_threads, float emb[SC_CLASSES][SC_FULL],
                                  sp_device **dev, sp_query_engine **eng)
{
    static float own[SC_CLASSES][SC_FULL];
    sp_sem_pca pca;
    sc_make_pca(&pca, emb ? emb : own);
    sp_splat s;
    int *cls;
    sc_make_splat(&s, &cls, &pca, emb ? emb : own);
    sp_camera *cams = malloc(sizeof(sp_camera) * (size_t)n_cams);
    sc_make_cams(cams, n_cams, w, h);
    sp_error err = {0};
    if (sp_device_create(dev, SP_DEVICE_CPU, n_threads, &err) ||
        sp_query_engine_create(eng, &(sp_query_model){.splat = &s, .pca = &pca, .cams = cams, .n_cams = (size_t)n_cams},
                               NULL, *dev, NULL, &err)) {
        fprintf(stderr, "setup: %s\n", err.msg);
        exit(1);
    }
    free(cams);
    sp_splat_free(&s);
    sp_sem_pca_free(&pca);
    free(cls);
}

/* Writes the cameras' poses as a binary COLMAP model into model_dir with the one camera `cam`
 * (image i named by name_fmt, e.g. "%05d.png"). At most 64 cameras. */
static inline int sc_write_colmap_camera(const char *model_dir, const sp_colmap_camera *cam_in,
                                         const sp_camera *cams, int n, const char *name_fmt, sp_error *err)
{
    if (n > 64) return sp_error_set(err, SP_E_ARG, "sc_write_colmap: %d cameras, at most 64", n);
    int rc = sp_mkdirs(model_dir, err);
    if (rc) return rc;
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    sp_colmap_camera cam = *cam_in;
    sp_colmap_image ims[64];
    char names[64][32];
    memset(ims, 0, sizeof ims);
    for (int i = 0; i < n; i++) {
        ims[i].id = (uint32_t)i + 1;
        ims[i].camera_id = 1;
        sp_colmap_image_set_pose(&ims[i], &cams[i]);
        snprintf(names[i], sizeof names[i], name_fmt, i);
        ims[i].name = names[i];
    }
    m.n_cameras = 1, m.cameras = &cam, m.n_images = (size_t)n, m.images = ims;
    return sp_colmap_write_bin(model_dir, &m, err);
}

/* The same with one PINHOLE camera of cams[0]'s intrinsics and size w x h. */
static inline int sc_write_colmap(const char *model_dir, const sp_camera *cams, int n, int w, int h,
                                  const char *name_fmt, sp_error *err)
{
    sp_colmap_camera cam = {1, SP_COLMAP_PINHOLE, (uint64_t)w, (uint64_t)h, 4,
                            {cams[0].fx, cams[0].fy, cams[0].cx, cams[0].cy}};
    return sc_write_colmap_camera(model_dir, &cam, cams, n, name_fmt, err);
}

/* A model folder of the tiny scene as lift writes it: splat.ply with f_sem_*, the PCA files, a
 * COLMAP model of 12 ring cameras (160x120) in sparse/0, and semantic.json (source labels,
 * hashed label embeddings); encoder (NULL = none recorded) and the class names when with_classes. */
static inline int sc_write_model(const char *dir, const char *encoder, int with_classes, sp_error *err)
{
    float (*emb)[SC_FULL] = malloc(sizeof(float) * SC_CLASSES * SC_FULL);
    if (!emb) return sp_error_set(err, SP_E_NOMEM, "sc_write_model: out of memory");
    sp_sem_pca pca;
    sc_make_pca(&pca, emb);
    sp_splat s;
    int *cls;
    sc_make_splat(&s, &cls, &pca, emb);
    enum { N = 12, W = 160, H = 120 };
    sp_camera cams[N];
    sc_make_cams(cams, N, W, H);
    char path[1400], colmap[1200];
    int rc = sp_mkdirs(dir, err);
    snprintf(path, sizeof path, "%s/splat.ply", dir);
    if (rc || (rc = sp_ply_write_splat(path, &s, err))) goto done;
    size_t sh1[1] = {SC_FULL}, sh2[2] = {SC_DIM, SC_FULL};
    snprintf(path, sizeof path, "%s/semantic_pca_mean.npy", dir);
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 1, sh1, pca.mean, err))) goto done;
    snprintf(path, sizeof path, "%s/semantic_pca_basis.npy", dir);
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 2, sh2, pca.basis, err))) goto done;
    snprintf(colmap, sizeof colmap, "%s/sparse/0", dir);
    if ((rc = sc_write_colmap(colmap, cams, N, W, H, "view_%02d.png", err))) goto done;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "source", "labels");
    cJSON_AddNumberToObject(o, "dim", SC_DIM);
    cJSON_AddNumberToObject(o, "full_dim", SC_FULL);
    cJSON_AddStringToObject(o, "pca_mean", "semantic_pca_mean.npy");
    cJSON_AddStringToObject(o, "pca_basis", "semantic_pca_basis.npy");
    cJSON_AddStringToObject(o, "label_embedding", "hash");
    if (encoder) cJSON_AddStringToObject(o, "encoder", encoder);
    if (with_classes) cJSON_AddItemToObject(o, "classes", cJSON_CreateStringArray(sc_class_names, SC_CLASSES));
    cJSON_AddNullToObject(o, "model");
    cJSON_AddStringToObject(o, "method", "lift");
    cJSON_AddStringToObject(o, "colmap", "sparse/0");
    snprintf(path, sizeof path, "%s/semantic.json", dir);
    rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
done:
    sp_splat_free(&s);
    sp_sem_pca_free(&pca);
    free(cls);
    free(emb);
    return rc;
}

/* The view of a capture's maps: cams[v] downscaled by 2, through `lens` (a camera whose
 * distortion and dist[] are used, NULL = pinhole). */
static inline sp_camera sc_map_camera(const sp_camera *cam, const sp_camera *lens)
{
    sp_camera c = *cam;
    sp_camera_downscale(&c, 2);
    if (lens) {
        c.distortion = lens->distortion;
        memcpy(c.dist, lens->dist, sizeof c.dist);
    }
    return c;
}

/* A feature folder as `semsplat features` writes it (features.json, PCA, f16 maps at half the
 * cameras' resolution) with the scene's true features: each map is rendered pinhole and, with a
 * lens, resampled into that lens's pixels (from a render twice as wide and high, so the whole
 * distorted image sees content). Images are named %05d.png. */
static inline int sc_write_features(const char *dir, const sp_splat *s, const sp_sem_pca *pca,
                                    const sp_camera *cams, int n, const sp_camera *lens, sp_error *err)
{
    char path[1400];
    snprintf(path, sizeof path, "%s/maps", dir);
    int rc = sp_mkdirs(path, err);
    if (rc) return rc;
    const int D = pca->dim;
    sp_camera mc = sc_map_camera(&cams[0], lens);
    const int MW = mc.width, MH = mc.height, W = cams[0].width, H = cams[0].height;
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    size_t big = (size_t)4 * MW * MH;
    float *f = malloc(sizeof(float) * big * D), *a = malloc(sizeof(float) * big);
    float *m = malloc(sizeof(float) * MW * MH * D);
    uint16_t *h = malloc(sizeof(uint16_t) * MW * MH * D);
    cJSON *o = cJSON_CreateObject(), *arr = cJSON_AddArrayToObject(o, "images");
    if ((rc = sp_device_create(&dev, SP_DEVICE_CPU, 2, err)) || (rc = sp_raster_create(&r, dev, err))) goto done;
    for (int v = 0; v < n && !rc; v++) {
        sp_camera c = sc_map_camera(&cams[v], lens), pin = c;
        pin.distortion = SP_DIST_NONE;
        if (lens) pin.width *= 2, pin.height *= 2, pin.cx += 0.5f * c.width, pin.cy += 0.5f * c.height;
        sp_render_request req = {.features = f, .alpha = a};
        if ((rc = sp_render_splat(r, s, &pin, &req, err))) break;
        for (size_t p = 0; p < (size_t)pin.width * pin.height; p++)
            for (int k = 0; k < D; k++) f[p * D + k] = a[p] > 1e-3f ? f[p * D + k] / a[p] : 0.0f;
        if (lens) rc = sp_camera_remap_from_pinhole(&pin, f, D, &c, m, NULL, err);
        else memcpy(m, f, sizeof(float) * MW * MH * D);
        for (int p = 0; p < MW * MH * D; p++) h[p] = sp_float_to_half(m[p]);
        size_t shape[3] = {(size_t)MH, (size_t)MW, (size_t)D};
        snprintf(path, sizeof path, "%s/maps/%05d.npy", dir, v);
        if (rc || (rc = sp_npy_write(path, SP_DTYPE_F16, 3, shape, h, err))) break;
        cJSON *it = cJSON_CreateObject();
        snprintf(path, sizeof path, "%05d.png", v);
        cJSON_AddStringToObject(it, "name", path);
        snprintf(path, sizeof path, "maps/%05d.npy", v);
        cJSON_AddStringToObject(it, "map", path);
        cJSON_AddNumberToObject(it, "height", MH);
        cJSON_AddNumberToObject(it, "width", MW);
        cJSON_AddNumberToObject(it, "image_height", H);
        cJSON_AddNumberToObject(it, "image_width", W);
        cJSON_AddItemToArray(arr, it);
    }
    if (rc) goto done;
    cJSON_AddStringToObject(o, "format", "semsplat-features-1");
    cJSON_AddStringToObject(o, "source", "labels");
    cJSON_AddNumberToObject(o, "dim", D);
    cJSON_AddNumberToObject(o, "full_dim", pca->full_dim);
    cJSON_AddNullToObject(o, "model");
    cJSON_AddStringToObject(o, "label_embedding", "hash");
    snprintf(path, sizeof path, "%s/features.json", dir);
    if ((rc = sp_json_write_file(path, o, err))) goto done;
    size_t s1[1] = {(size_t)pca->full_dim}, s2[2] = {(size_t)D, (size_t)pca->full_dim};
    snprintf(path, sizeof path, "%s/pca_mean.npy", dir);
    if ((rc = sp_npy_write(path, SP_DTYPE_F32, 1, s1, pca->mean, err))) goto done;
    snprintf(path, sizeof path, "%s/pca_basis.npy", dir);
    rc = sp_npy_write(path, SP_DTYPE_F32, 2, s2, pca->basis, err);
done:
    cJSON_Delete(o);
    sp_raster_free(r);
    sp_device_free(dev);
    free(f), free(a), free(m), free(h);
    return rc;
}

#endif
