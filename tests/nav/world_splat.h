/* An ideal splat of a synth world for the nav tests: flat Gaussians tiling every triangle (about
 * one per spacing^2) within the region the cameras cover, kept where a camera sees them (as a
 * reconstruction would have them), coloured by the material, with label
 * features (each object's class through sp_label_embedding, compressed by an exact PCA), and the
 * capture planner's cameras. What a perfect reconstruction would give: the nav module measured
 * apart from reconstruction error (the trained models are measured by bench_nav). */
#ifndef SP_TEST_WORLD_SPLAT_H
#define SP_TEST_WORLD_SPLAT_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/clip.h"
#include "semsplat/semantic.h"
#include "semsplat/synth.h"

#define WS_FULL 512
#define WS_MAX_CLASSES 64

typedef struct ws_scene {
    sp_world w;
    sp_splat splat;
    sp_sem_pca pca;
    sp_camera *cams;
    size_t n_cams;
    int n_classes;
    char classes[WS_MAX_CLASSES][128];
} ws_scene;

static inline int ws_class_index(ws_scene *sc, const char *name)
{
    for (int k = 0; k < sc->n_classes; k++)
        if (!strcmp(sc->classes[k], name)) return k;
    if (sc->n_classes == WS_MAX_CLASSES) return WS_MAX_CLASSES - 1;
    snprintf(sc->classes[sc->n_classes], 128, "%s", name);
    return sc->n_classes++;
}

/* PCA of the class embeddings: mean, then Gram-Schmidt of (e_k - mean): classes decode exactly. */
static inline int ws_make_pca(ws_scene *sc, float (*emb)[WS_FULL], sp_error *err)
{
    sp_sem_pca *p = &sc->pca;
    p->full_dim = WS_FULL;
    p->mean = calloc(WS_FULL, sizeof(float));
    p->basis = calloc((size_t)WS_FULL * WS_MAX_CLASSES, sizeof(float));
    if (!p->mean || !p->basis) return sp_error_set(err, SP_E_NOMEM, "ws: out of memory");
    for (int k = 0; k < sc->n_classes; k++) {
        sp_label_embedding(sc->classes[k], WS_FULL, emb[k]);
        for (int j = 0; j < WS_FULL; j++) p->mean[j] += emb[k][j] / sc->n_classes;
    }
    int rows = 0;
    for (int k = 0; k < sc->n_classes; k++) {
        float *row = p->basis + (size_t)rows * WS_FULL;
        for (int j = 0; j < WS_FULL; j++) row[j] = emb[k][j] - p->mean[j];
        for (int q = 0; q < rows; q++) {
            const float *o = p->basis + (size_t)q * WS_FULL;
            double d = 0;
            for (int j = 0; j < WS_FULL; j++) d += (double)row[j] * o[j];
            for (int j = 0; j < WS_FULL; j++) row[j] -= (float)(d * o[j]);
        }
        double n = 0;
        for (int j = 0; j < WS_FULL; j++) n += (double)row[j] * row[j];
        if (n < 1e-8) continue;
        for (int j = 0; j < WS_FULL; j++) row[j] /= (float)sqrt(n);
        rows++;
    }
    p->dim = rows;
    return SP_OK;
}

/* Rotation (row-major) whose columns are t1, t2, n. */
static inline void ws_frame(const float n[3], float R[9])
{
    float a[3] = {fabsf(n[0]) < 0.9f ? 1.0f : 0.0f, fabsf(n[0]) < 0.9f ? 0.0f : 1.0f, 0};
    float t1[3] = {a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2], a[0] * n[1] - a[1] * n[0]};
    float l = sqrtf(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (int k = 0; k < 3; k++) t1[k] /= l;
    float t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
    for (int r = 0; r < 3; r++) R[r * 3] = t1[r], R[r * 3 + 1] = t2[r], R[r * 3 + 2] = n[r];
}

/* Keeps the Gaussians some camera sees (nothing in front of the centre by more than the depth a
 * pixel spans on the surface, plus 1 cm):
 * a reconstruction has no surfaces under walls or inside furniture. */
static inline int ws_keep_visible(ws_scene *sc, sp_error *err)
{
    sp_splat *s = &sc->splat;
    uint8_t *seen = calloc(s->n ? s->n : 1, 1);
    sp_synth_render_opts ro = {1, 1, -1};
    sp_synth_frame fr;
    memset(&fr, 0, sizeof fr);
    int rc = 0;
    for (size_t c = 0; c < sc->n_cams && !rc; c++) {
        const sp_camera *cam = &sc->cams[c];
        if ((rc = sp_synth_render(&sc->w, cam, &ro, NULL, &fr, err))) break;
        for (size_t i = 0; i < s->n; i++) {
            const float *m = s->means + 3 * i;
            sp_vec3 pc = sp_v3_add(sp_mat3_apply(cam->R, sp_v3(m[0], m[1], m[2])), sp_v3(cam->t[0], cam->t[1], cam->t[2]));
            if (pc.z < 0.05f) continue;
            int u = (int)floorf(cam->fx * pc.x / pc.z + cam->cx), v = (int)floorf(cam->fy * pc.y / pc.z + cam->cy);
            if (u < 0 || v < 0 || u >= cam->width || v >= cam->height) continue;
            float d = fr.depth[(size_t)v * cam->width + u], R[9];
            /* a pixel spans d * (pixel angle) / cos(incidence) of depth on a surface seen at a slant */
            sp_quat_to_mat3(s->quats + 4 * i, R);
            sp_vec3 ray = sp_v3_normalize(sp_v3_sub(sp_v3(m[0], m[1], m[2]), sp_camera_center(cam)));
            float cosi = fabsf(ray.x * R[2] + ray.y * R[5] + ray.z * R[8]);
            float tol = 0.01f + d / cam->fx / fmaxf(cosi, 0.1f);
            if (d > 0 && pc.z < d + tol) seen[i] = 1; /* nothing clearly in front */
        }
    }
    sp_synth_frame_free(&fr);
    size_t k = 0, K = (size_t)sp_sh_coeffs(s->sh_degree) * 3;
    for (size_t i = 0; i < s->n && !rc; i++) {
        if (!seen[i]) continue;
        memmove(s->means + 3 * k, s->means + 3 * i, sizeof(float) * 3);
        memmove(s->quats + 4 * k, s->quats + 4 * i, sizeof(float) * 4);
        memmove(s->log_scales + 3 * k, s->log_scales + 3 * i, sizeof(float) * 3);
        s->opacity_logits[k] = s->opacity_logits[i];
        memmove(s->sh + K * k, s->sh + K * i, sizeof(float) * K);
        memmove(s->features + (size_t)s->feat_dim * k, s->features + (size_t)s->feat_dim * i, sizeof(float) * s->feat_dim);
        k++;
    }
    s->n = k;
    free(seen);
    return rc;
}

static inline int ws_build(ws_scene *sc, const char *world, const char *model_path, int n_views,
                           int width, int height, float spacing, sp_error *err)
{
    memset(sc, 0, sizeof *sc);
    sp_synth_load_opts lo = {model_path, 1, 1, NULL};
    int rc = sp_synth_load_world(world, &lo, &sc->w, err);
    if (rc) return rc;
    sp_synth_capture_opts co;
    memset(&co, 0, sizeof co);
    co.n_views = n_views, co.width = width, co.height = height, co.seed = 7, co.n_threads = 2;
    if ((rc = sp_synth_plan_views(&sc->w, &co, &sc->cams, &sc->n_cams, err))) return rc;
    float lo_b[2] = {INFINITY, INFINITY}, hi_b[2] = {-INFINITY, -INFINITY};
    for (size_t c = 0; c < sc->n_cams; c++) {
        sp_vec3 p = sp_camera_center(&sc->cams[c]);
        lo_b[0] = fminf(lo_b[0], p.x - 3), lo_b[1] = fminf(lo_b[1], p.y - 3);
        hi_b[0] = fmaxf(hi_b[0], p.x + 3), hi_b[1] = fmaxf(hi_b[1], p.y + 3);
    }
    int *tri_class = malloc(sizeof(int) * (sc->w.n_objects + 1));
    for (size_t o = 0; o < sc->w.n_objects; o++)
        tri_class[o] = ws_class_index(sc, sc->w.objects[o].is_structure ? "wall" : sc->w.objects[o].class_name);
    /* count, then fill */
    size_t cap = 0;
    const sp_world *w = &sc->w;
    for (int pass = 0; pass < 2; pass++) {
        size_t n = 0;
        float emb[WS_MAX_CLASSES][WS_FULL], feat[WS_MAX_CLASSES][WS_MAX_CLASSES];
        if (pass == 1) {
            if ((rc = ws_make_pca(sc, emb, err)) || (rc = sp_splat_alloc(&sc->splat, cap, 0, sc->pca.dim, err))) break;
            for (int k = 0; k < sc->n_classes; k++)
                for (int r = 0; r < sc->pca.dim; r++) {
                    double d = 0;
                    for (int j = 0; j < WS_FULL; j++)
                        d += (double)sc->pca.basis[(size_t)r * WS_FULL + j] * (emb[k][j] - sc->pca.mean[j]);
                    feat[k][r] = (float)d;
                }
        }
        for (size_t t = 0; t < w->n_triangles; t++) {
            const float *a = &w->positions[w->tris[3 * t] * 3], *b = &w->positions[w->tris[3 * t + 1] * 3];
            const float *c = &w->positions[w->tris[3 * t + 2] * 3];
            float e1[3], e2[3], nrm[3];
            for (int k = 0; k < 3; k++) e1[k] = b[k] - a[k], e2[k] = c[k] - a[k];
            nrm[0] = e1[1] * e2[2] - e1[2] * e2[1], nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
            nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
            float area2 = sqrtf(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
            if (area2 < 1e-9f) continue;
            for (int k = 0; k < 3; k++) nrm[k] /= area2;
            if (fmaxf(a[0], fmaxf(b[0], c[0])) < lo_b[0] || fminf(a[0], fminf(b[0], c[0])) > hi_b[0] ||
                fmaxf(a[1], fmaxf(b[1], c[1])) < lo_b[1] || fminf(a[1], fminf(b[1], c[1])) > hi_b[1])
                continue;
            int m = (int)ceilf(sqrtf(0.5f * area2) / spacing);
            if (m < 1) m = 1;
            float R[9], q[4];
            ws_frame(nrm, R);
            sp_mat3_to_quat(R, q);
            int obj = w->tri_object[t], mat = w->tri_material[t];
            float step = sqrtf(0.5f * area2) / m;
            /* m x m regular subdivision: the centroids of the m^2 sub-triangles */
            for (int i = 0; i < m; i++)
                for (int j = 0; j < m - i; j++)
                    for (int up = 0; up < (j < m - i - 1 ? 2 : 1); up++) {
                        float u = (i + (up ? 2.0f : 1.0f) / 3) / m, v = (j + (up ? 2.0f : 1.0f) / 3) / m;
                        float p[3];
                        for (int k = 0; k < 3; k++) p[k] = a[k] + u * e1[k] + v * e2[k];
                        if (p[0] < lo_b[0] || p[0] > hi_b[0] || p[1] < lo_b[1] || p[1] > hi_b[1]) continue;
                        if (pass == 0) {
                            n++;
                            continue;
                        }
                        sp_splat *s = &sc->splat;
                        memcpy(s->means + 3 * n, p, sizeof p);
                        memcpy(s->quats + 4 * n, q, sizeof q);
                        s->log_scales[3 * n] = s->log_scales[3 * n + 1] = logf(0.5f * step);
                        s->log_scales[3 * n + 2] = logf(0.004f);
                        s->opacity_logits[3 * n / 3] = 4.0f;
                        for (int k = 0; k < 3; k++)
                            s->sh[3 * n + k] = (w->materials[mat].diffuse[k] - 0.5f) / SP_SH_C0;
                        memcpy(s->features + (size_t)n * s->feat_dim, feat[tri_class[obj]], sizeof(float) * s->feat_dim);
                        n++;
                    }
        }
        cap = n;
    }
    free(tri_class);
    if (!rc) rc = ws_keep_visible(sc, err);
    return rc;
}

static inline void ws_free(ws_scene *sc)
{
    sp_world_free(&sc->w);
    sp_splat_free(&sc->splat);
    sp_sem_pca_free(&sc->pca);
    free(sc->cams);
}

#endif
