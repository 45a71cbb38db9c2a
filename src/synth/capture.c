/* Captures: renders the planned views and writes a COLMAP capture with ground truth (images,
 * metric depth, instance labels, labels.json, ground_truth.json). Poses are exact; points3D are
 * sampled on the visible surfaces of the rendered views with their rendered colours. */
#include "internal.h"

#include "semsplat/io.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct pt {
    double xyz[3];
    uint8_t rgb[3];
    uint32_t image_id;
    double xy[2];
} pt;

static uint64_t mix64(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ULL;
    x ^= x >> 33;
    return x;
}

static int write_view(const char *out, size_t i, const sp_synth_frame *f, sp_error *err)
{
    char path[2048];
    size_t np = (size_t)f->width * f->height;
    uint8_t *rgb8 = malloc(np * 3);
    if (!rgb8) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (size_t p = 0; p < np * 3; p++) {
        float v = f->rgb[p] * 255.0f + 0.5f;
        rgb8[p] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
    }
    sp_image img = {.width = f->width, .height = f->height, .channels = 3, .bit_depth = 8, .data = rgb8};
    snprintf(path, sizeof path, "%s/images/%05zu.png", out, i);
    int rc = sp_image_write_png(path, &img, err);
    free(rgb8);
    if (rc) return rc;
    sp_image lab = {.width = f->width, .height = f->height, .channels = 1, .bit_depth = 16, .data = f->labels};
    snprintf(path, sizeof path, "%s/labels/%05zu.png", out, i);
    if ((rc = sp_image_write_png(path, &lab, err))) return rc;
    size_t shape[2] = {(size_t)f->height, (size_t)f->width};
    snprintf(path, sizeof path, "%s/depth/%05zu.npy", out, i);
    return sp_npy_write(path, SP_DTYPE_F32, 2, shape, f->depth, err);
}

static cJSON *vec3(const float *v)
{
    double d[3] = {v[0], v[1], v[2]};
    return cJSON_CreateDoubleArray(d, 3);
}

static int write_json(const sp_world *w, const char *out, sp_error *err)
{
    char path[2048];
    cJSON *lab = cJSON_CreateObject(), *map = cJSON_CreateObject();
    cJSON_AddStringToObject(lab, "format", "semsplat-labels-1");
    cJSON_AddNumberToObject(lab, "background", 0);
    cJSON_AddItemToObject(lab, "labels", map);
    cJSON *gt = cJSON_CreateObject(), *objs = cJSON_CreateArray(), *st = cJSON_CreateArray();
    cJSON_AddStringToObject(gt, "world", w->path);
    cJSON_AddStringToObject(gt, "frame", "world: metres, z up (the SDF world frame; COLMAP poses are in it too)");
    cJSON_AddItemToObject(gt, "objects", objs);
    cJSON_AddItemToObject(gt, "structure", st);
    for (size_t i = 0; i < w->n_objects; i++) {
        const sp_synth_object *o = &w->objects[i];
        char id[16];
        snprintf(id, sizeof id, "%zu", i + 1);
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "name", o->name);
        cJSON_AddStringToObject(e, "class", o->class_name);
        cJSON_AddStringToObject(e, "source", o->source);
        cJSON_AddBoolToObject(e, "is_structure", o->is_structure);
        cJSON_AddItemToObject(map, id, e);
        cJSON *g = cJSON_CreateObject();
        cJSON_AddNumberToObject(g, "id", (double)(i + 1));
        cJSON_AddStringToObject(g, "name", o->name);
        cJSON_AddStringToObject(g, "class", o->class_name);
        float R[9], q[4], t[3] = {o->pose[3], o->pose[7], o->pose[11]};
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) R[r * 3 + c] = o->pose[r * 4 + c];
        sp_mat3_to_quat(R, q);
        float rpy[3] = {atan2f(R[7], R[8]), asinf(fmaxf(-1.0f, fminf(1.0f, -R[6]))), atan2f(R[3], R[0])};
        cJSON_AddItemToObject(g, "position", vec3(t));
        double qd[4] = {q[0], q[1], q[2], q[3]};
        cJSON_AddItemToObject(g, "quaternion_wxyz", cJSON_CreateDoubleArray(qd, 4));
        cJSON_AddItemToObject(g, "rpy", vec3(rpy));
        cJSON_AddItemToObject(g, "aabb_min", vec3(o->aabb_min));
        cJSON_AddItemToObject(g, "aabb_max", vec3(o->aabb_max));
        float ctr[3] = {0.5f * (o->aabb_min[0] + o->aabb_max[0]), 0.5f * (o->aabb_min[1] + o->aabb_max[1]),
                        0.5f * (o->aabb_min[2] + o->aabb_max[2])};
        cJSON_AddItemToObject(g, "aabb_center", vec3(ctr));
        cJSON_AddNumberToObject(g, "n_triangles", (double)o->n_triangles);
        cJSON_AddItemToArray(o->is_structure ? st : objs, g);
    }
    snprintf(path, sizeof path, "%s/labels.json", out);
    int rc = sp_json_write_file(path, lab, err);
    snprintf(path, sizeof path, "%s/ground_truth.json", out);
    if (!rc) rc = sp_json_write_file(path, gt, err);
    cJSON_Delete(lab);
    cJSON_Delete(gt);
    return rc;
}

/* The capture's frame.json: poses, points and ground truth are all in the SDF world frame. */
static int write_frame(const sp_world *w, const char *out, sp_error *err)
{
    sp_frame f;
    sp_frame_init(&f, "synth");
    snprintf(f.note, sizeof f.note, "synth capture of %s", w->path);
    char path[2048];
    snprintf(path, sizeof path, "%s/frame.json", out);
    return sp_frame_write(path, &f, err);
}

typedef struct write_job {
    const char *out;
    const sp_camera *cams;
    sp_synth_frame *frames;
    pt *pts;
    size_t *got, per_view, first;
    unsigned seed;
    int rc[8];
    sp_error err[8];
} write_job;

/* Writes view first + j and samples its points into its own slots (deterministic). */
static void write_one(void *ctx, long j, int tid)
{
    write_job *jb = ctx;
    size_t i = jb->first + (size_t)j;
    const sp_synth_frame *f = &jb->frames[j];
    jb->rc[j] = write_view(jb->out, i, f, &jb->err[j]);
    if (jb->rc[j]) return;
    /* points on the visible surfaces of this view, at pixel centres */
    const sp_camera *c = &jb->cams[i];
    uint64_t s = mix64((uint64_t)jb->seed * 0x9e3779b97f4a7c15ULL + i + 1);
    size_t got = 0;
    pt *slot = jb->pts + i * jb->per_view;
    for (size_t tries = 0; got < jb->per_view && tries < jb->per_view * 8; tries++) {
        s = mix64(s + 0x632be59bd9b4e019ULL);
        int px = (int)(s % (uint64_t)c->width), py = (int)((s >> 32) % (uint64_t)c->height);
        size_t at = (size_t)py * c->width + px;
        float z = f->depth[at];
        if (!(z > 0)) continue;
        double xc = ((px + 0.5) - c->cx) / c->fx * z, yc = ((py + 0.5) - c->cy) / c->fy * z;
        double pc[3] = {xc - c->t[0], yc - c->t[1], z - c->t[2]};
        pt *p = &slot[got++];
        for (int r = 0; r < 3; r++) p->xyz[r] = c->R[r] * pc[0] + c->R[3 + r] * pc[1] + c->R[6 + r] * pc[2];
        for (int k = 0; k < 3; k++) {
            float v = f->rgb[at * 3 + k] * 255.0f + 0.5f;
            p->rgb[k] = (uint8_t)(v > 255 ? 255 : v);
        }
        p->image_id = (uint32_t)(i + 1);
        p->xy[0] = px + 0.5;
        p->xy[1] = py + 0.5;
    }
    jb->got[i] = got;
}

int sp_synth_capture(const sp_world *w, const char *out, const sp_synth_capture_opts *opts,
                     sp_error *err)
{
    sp_camera *cams = NULL;
    size_t n = 0;
    int rc = sp_synth_plan_views(w, opts, &cams, &n, err);
    if (rc) return rc;
    char path[2048];
    const char *sub[] = {"images", "depth", "labels", "sparse/0"};
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, "%s/%s", out, sub[i]);
        if ((rc = sp_mkdirs(path, err))) {
            free(cams);
            return rc;
        }
    }
    sp_pool *pool = NULL;
    if ((rc = sp_pool_create(&pool, opts->n_threads, err))) {
        free(cams);
        return rc;
    }
    size_t target = opts->n_points > 0 ? (size_t)opts->n_points : 30000;
    size_t per_view = (target + n - 1) / n;
    pt *pts = calloc(per_view * n + 1, sizeof *pts);
    size_t *got = calloc(n, sizeof *got);
    size_t n_pts = 0;
    /* Views are rendered one at a time (rows in parallel), then written in batches with one
     * view per thread: PNG compression costs as much as rendering. */
    enum { BATCH = 8 };
    sp_synth_frame f[BATCH];
    memset(f, 0, sizeof f);
    write_job job = {.out = out, .cams = cams, .frames = f, .pts = pts, .got = got, .per_view = per_view,
                     .seed = opts->seed};
    sp_synth_render_opts ro = {.supersample = opts->supersample, .psf_px = opts->psf_px};
    sp_progress prog;
    sp_progress_begin(&prog, opts->log, "synth", (long)n, "views");
    if (!pts || !got) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (size_t b0 = 0; b0 < n && !rc; b0 += BATCH) {
        size_t nb = n - b0 < BATCH ? n - b0 : BATCH;
        for (size_t j = 0; j < nb && !rc; j++)
            rc = sp_synth_render(w, &cams[b0 + j], &ro, pool, &f[j], err);
        if (rc) break;
        job.first = b0;
        memset(job.rc, 0, sizeof job.rc);
        sp_pool_for(pool, (long)nb, write_one, &job);
        for (size_t j = 0; j < nb && !rc; j++)
            if (job.rc[j]) {
                *err = job.err[j];
                rc = job.rc[j];
            }
        sp_progress_update(&prog, (long)(b0 + nb), NULL);
    }
    /* compact the per-view point slots in view order */
    for (size_t i = 0; !rc && i < n; i++)
        for (size_t k = 0; k < got[i]; k++) pts[n_pts++] = pts[i * per_view + k];
    free(got);
    for (int j = 0; j < BATCH; j++) sp_synth_frame_free(&f[j]);
    sp_pool_free(pool);
    if (!rc) {
        /* COLMAP model: one PINHOLE camera, every image with its exact pose and its points. */
        sp_colmap_model m = {0};
        sp_colmap_camera cam = {.id = 1, .model = SP_COLMAP_PINHOLE, .width = (uint64_t)cams[0].width,
                                .height = (uint64_t)cams[0].height, .n_params = 4,
                                .params = {cams[0].fx, cams[0].fy, cams[0].cx, cams[0].cy}};
        m.n_cameras = 1;
        m.cameras = &cam;
        m.n_images = n;
        m.images = calloc(n, sizeof *m.images);
        m.n_points = n_pts;
        m.points = calloc(n_pts + 1, sizeof *m.points);
        uint32_t *tracks = calloc(2 * n_pts + 1, sizeof(uint32_t));
        char (*names)[32] = calloc(n, 32);
        size_t *first = calloc(n + 1, sizeof(size_t));
        double *xys = calloc(2 * n_pts + 1, sizeof(double));
        int64_t *pids = calloc(n_pts + 1, sizeof(int64_t));
        if (!m.images || !m.points || !tracks || !names || !first || !xys || !pids)
            rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
        /* points are in image order, so each image's 2D points are one contiguous run */
        for (size_t p = 0; !rc && p < n_pts; p++) first[pts[p].image_id]++;
        for (size_t i = 0; !rc && i < n; i++) first[i + 1] += first[i];
        for (size_t i = 0; !rc && i < n; i++) {
            sp_colmap_image *im = &m.images[i];
            im->id = (uint32_t)(i + 1);
            sp_colmap_image_set_pose(im, &cams[i]);
            im->camera_id = 1;
            snprintf(names[i], 32, "%05zu.png", i);
            im->name = names[i];
            im->n_points2d = first[i + 1] - first[i];
            im->xys = xys + 2 * first[i];
            im->point3d_ids = pids + first[i];
        }
        for (size_t p = 0; !rc && p < n_pts; p++) {
            sp_colmap_point *cp = &m.points[p];
            cp->id = p + 1;
            memcpy(cp->xyz, pts[p].xyz, sizeof cp->xyz);
            memcpy(cp->rgb, pts[p].rgb, 3);
            cp->error = 0;
            cp->track_len = 1;
            cp->track = tracks + 2 * p;
            size_t img = pts[p].image_id - 1;
            tracks[2 * p] = pts[p].image_id;
            tracks[2 * p + 1] = (uint32_t)(p - first[img]);
            xys[2 * p] = pts[p].xy[0];
            xys[2 * p + 1] = pts[p].xy[1];
            pids[p] = (int64_t)(p + 1);
        }
        snprintf(path, sizeof path, "%s/sparse/0", out);
        if (!rc) rc = sp_colmap_write_bin(path, &m, err);
        free(m.images);
        free(m.points);
        free(tracks);
        free(names);
        free(first);
        free(xys);
        free(pids);
    }
    if (!rc) rc = write_json(w, out, err);
    if (!rc) rc = write_frame(w, out, err);
    sp_progress_end(&prog, rc ? "failed" : NULL);
    free(pts);
    free(cams);
    return rc;
}
