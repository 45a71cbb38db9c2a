/* A small room for the nav tests, made of flat Gaussians on its surfaces: a 6 x 4 m floor, four
 * 2 m walls, a pillar in the middle and a low table, with cameras standing in the room looking
 * around (and a little down). Builds in milliseconds; the ground truth is the boxes below. */
#ifndef SP_TEST_NAV_SCENE_H
#define SP_TEST_NAV_SCENE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/core.h"
#include "semsplat/io.h"

typedef struct {
    float lo[3], hi[3];
} ns_box;

#define NS_OFFX 0.013f
#define NS_OFFY 0.021f

/* Room [0,6] x [0,4]; walls 0.1 m thick inside those bounds. Everything is shifted by NS_OFF so
 * that faces do not fall on cell boundaries (no real scene aligns with the grid). */
static const ns_box ns_walls[] = {
    {{0.0f, 0.0f, 0.0f}, {6.0f, 0.1f, 2.0f}},
    {{0.0f, 3.9f, 0.0f}, {6.0f, 4.0f, 2.0f}},
    {{0.0f, 0.0f, 0.0f}, {0.1f, 4.0f, 2.0f}},
    {{5.9f, 0.0f, 0.0f}, {6.0f, 4.0f, 2.0f}},
};
static const ns_box ns_pillar = {{2.6f, 1.5f, 0.0f}, {3.4f, 2.5f, 2.0f}};
static const ns_box ns_table = {{4.4f, 0.6f, 0.0f}, {5.2f, 1.2f, 0.7f}};

static inline void ns_push(sp_splat *s, size_t *n, const float p[3], int normal_axis, float size)
{
    size_t i = (*n)++;
    s->means[3 * i] = p[0] + NS_OFFX;
    s->means[3 * i + 1] = p[1] + NS_OFFY;
    s->means[3 * i + 2] = p[2];
    /* local z (the thin axis) onto the surface normal */
    float h = 0.70710678f;
    float q[3][4] = {{h, 0, h, 0}, {h, h, 0, 0}, {1, 0, 0, 0}};
    memcpy(s->quats + 4 * i, q[normal_axis], sizeof q[0]);
    s->log_scales[3 * i] = s->log_scales[3 * i + 1] = logf(size);
    s->log_scales[3 * i + 2] = logf(0.003f);
    s->opacity_logits[i] = 4.0f;
    float shade = normal_axis == 2 ? 0.55f : 0.75f;
    for (int c = 0; c < 3; c++) s->sh[3 * i + c] = (shade - 0.5f + 0.05f * c) / SP_SH_C0;
}

/* Gaussians on the faces of box b (no bottom face), spacing step. */
static inline void ns_box_faces(sp_splat *s, size_t *n, size_t cap, const ns_box *b, float step)
{
    for (int ax = 0; ax < 3; ax++)
        for (int side = 0; side < 2; side++) {
            if (ax == 2 && side == 0) continue;
            int u = (ax + 1) % 3, v = (ax + 2) % 3;
            for (float a = b->lo[u] + 0.5f * step; a < b->hi[u]; a += step)
                for (float c = b->lo[v] + 0.5f * step; c < b->hi[v]; c += step) {
                    if (*n == cap) return;
                    float p[3];
                    p[ax] = side ? b->hi[ax] : b->lo[ax];
                    p[u] = a, p[v] = c;
                    ns_push(s, n, p, ax, 0.6f * step);
                }
        }
}

static inline int ns_overlap(const ns_box *b, float x0, float y0, float x1, float y1)
{
    return x0 < b->hi[0] && x1 > b->lo[0] && y0 < b->hi[1] && y1 > b->lo[1];
}

/* Ground truth of the cell [x0, x1) x [y0, y1) (world): 1 when a wall, the pillar (when present)
 * or the table overlaps it. */
static inline int ns_truth_cell(float x0, float y0, float x1, float y1, int with_pillar)
{
    x0 -= NS_OFFX, x1 -= NS_OFFX, y0 -= NS_OFFY, y1 -= NS_OFFY;
    for (int k = 0; k < 4; k++)
        if (ns_overlap(&ns_walls[k], x0, y0, x1, y1)) return 1;
    if (with_pillar && ns_overlap(&ns_pillar, x0, y0, x1, y1)) return 1;
    return ns_overlap(&ns_table, x0, y0, x1, y1);
}

static inline int ns_make_splat(sp_splat *s, int with_pillar, sp_error *err)
{
    const float step = 0.05f;
    size_t cap = 200000, n = 0;
    int rc = sp_splat_alloc(s, cap, 0, 0, err);
    if (rc) return rc;
    /* the floor where it can be seen: not under the walls, the pillar or the table */
    for (float x = 0.5f * step; x < 6.0f; x += step)
        for (float y = 0.5f * step; y < 4.0f; y += step) {
            float p[3] = {x, y, 0.0f};
            if (ns_truth_cell(x + NS_OFFX, y + NS_OFFY, x + NS_OFFX, y + NS_OFFY, with_pillar)) continue;
            ns_push(s, &n, p, 2, 0.6f * step);
        }
    for (int k = 0; k < 4; k++) ns_box_faces(s, &n, cap, &ns_walls[k], step);
    if (with_pillar) ns_box_faces(s, &n, cap, &ns_pillar, step);
    ns_box_faces(s, &n, cap, &ns_table, step);
    s->n = n;
    return SP_OK;
}

/* Cameras at 1 m on a grid of standpoints, 8 headings each, pitched 25 degrees down. */
static inline int ns_make_cams(sp_camera **out, size_t *n_out, int w, int h)
{
    static const float stands[][2] = {{1.0f, 1.0f}, {1.0f, 3.0f}, {2.0f, 0.8f}, {2.0f, 3.2f},
                                      {4.0f, 0.6f}, {4.0f, 3.2f}, {5.2f, 2.0f}, {1.2f, 2.0f},
                                      {3.0f, 0.7f}, {3.0f, 3.3f}};
    size_t ns = sizeof stands / sizeof stands[0], n = 0;
    sp_camera *cams = calloc(ns * 8, sizeof(sp_camera));
    if (!cams) return -1;
    for (size_t s = 0; s < ns; s++)
        for (int k = 0; k < 8; k++) {
            sp_camera *c = &cams[n++];
            c->width = w, c->height = h;
            c->fx = c->fy = 0.7f * w;
            c->cx = 0.5f * w, c->cy = 0.5f * h;
            float yaw = (float)(k * M_PI / 4);
            sp_vec3 eye = sp_v3(stands[s][0] + NS_OFFX, stands[s][1] + NS_OFFY, 1.0f);
            sp_vec3 tgt = sp_v3(eye.x + cosf(yaw), eye.y + sinf(yaw), eye.z - tanf(0.44f));
            sp_camera_look_at(c, eye, tgt, sp_v3(0, 0, 1));
        }
    *out = cams;
    *n_out = n;
    return 0;
}

/* Writes the room as a model folder: <dir>/model/splat.ply and train.json naming the capture
 * <dir>/capture/sparse/0 (one PINHOLE camera, an image per pose of ns_make_cams at w x h; no
 * images, which the costmap does not need). model gets the model folder's path. */
static inline int ns_write_model(const char *dir, int with_pillar, int w, int h, char *model,
                                 size_t cap, sp_error *err)
{
    char capture[1200], path[1300];
    snprintf(model, cap, "%s/model", dir);
    snprintf(capture, sizeof capture, "%s/capture", dir);
    sp_splat s;
    sp_camera *cams = NULL;
    size_t n = 0;
    int rc = ns_make_splat(&s, with_pillar, err);
    if (rc) return rc;
    if (ns_make_cams(&cams, &n, w, h)) rc = sp_error_set(err, SP_E_NOMEM, "ns: cameras");
    snprintf(path, sizeof path, "%s/splat.ply", model);
    if (!rc) rc = sp_mkdirs(model, err);
    if (!rc) rc = sp_ply_write_splat(path, &s, err);
    sp_colmap_camera cam = {1, SP_COLMAP_PINHOLE, (uint64_t)w, (uint64_t)h, 4, {0}};
    sp_colmap_image *ims = calloc(n ? n : 1, sizeof *ims);
    char (*names)[32] = calloc(n ? n : 1, 32);
    if (!rc && (!ims || !names)) rc = sp_error_set(err, SP_E_NOMEM, "ns: images");
    if (!rc) {
        cam.params[0] = cams[0].fx, cam.params[1] = cams[0].fy;
        cam.params[2] = cams[0].cx, cam.params[3] = cams[0].cy;
        for (size_t i = 0; i < n; i++) {
            ims[i].id = (uint32_t)i + 1, ims[i].camera_id = 1;
            sp_colmap_image_set_pose(&ims[i], &cams[i]);
            snprintf(names[i], 32, "%05zu.png", i);
            ims[i].name = names[i];
        }
        sp_colmap_model m;
        memset(&m, 0, sizeof m);
        m.n_cameras = 1, m.cameras = &cam, m.n_images = n, m.images = ims;
        snprintf(path, sizeof path, "%s/sparse/0", capture);
        rc = sp_mkdirs(path, err);
        if (!rc) rc = sp_colmap_write_bin(path, &m, err);
    }
    if (!rc) {
        char js[1500];
        snprintf(js, sizeof js, "{\"settings\": {\"colmap\": \"%s\"}}", capture);
        snprintf(path, sizeof path, "%s/train.json", model);
        rc = sp_write_file_atomic(path, js, strlen(js), err);
    }
    free(ims), free(names), free(cams);
    sp_splat_free(&s);
    return rc;
}

#endif
