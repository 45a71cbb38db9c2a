/* Shared by fuzz_colmap_bin.c and fuzz_colmap_txt.c. An input is one model file: its first byte
 * picks the part (cameras, images, points3D; byte % 3), the rest is the file. What parses must
 * survive our writer and a re-read of the same part bit for bit, and pass through the code that
 * consumes it: images become sp_cameras (against a fixed set of cameras 1..4), cameras become
 * sp_cameras (through one identity-pose image each). */
#ifndef SP_FUZZ_COLMAP_H
#define SP_FUZZ_COLMAP_H

#include "fuzz_util.h"
#include "io/colmap_internal.h"
#include "semsplat/io.h"

typedef int (*fz_colmap_parse_fn)(sp_colmap_part part, const void *data, size_t size, const char *name,
                                  sp_colmap_model *m, sp_error *err);
typedef int (*fz_colmap_write_fn)(const char *dir, const sp_colmap_model *m, sp_error *err);

static inline void fz_same_doubles(const double *a, const double *b, size_t n, const char *what)
{
    FZ_ASSERT(!n || !memcmp(a, b, n * sizeof *a), "%s changed in a round trip", what);
}

static inline void fz_same_part(sp_colmap_part part, const sp_colmap_model *a, const sp_colmap_model *b)
{
    if (part == SP_COLMAP_CAMERAS) {
        FZ_ASSERT(a->n_cameras == b->n_cameras, "camera count changed");
        for (size_t i = 0; i < a->n_cameras; i++) {
            const sp_colmap_camera *x = &a->cameras[i], *y = &b->cameras[i];
            FZ_ASSERT(x->id == y->id && x->model == y->model && x->width == y->width && x->height == y->height &&
                          x->n_params == y->n_params, "camera %zu changed", i);
            fz_same_doubles(x->params, y->params, (size_t)x->n_params, "camera params");
        }
    } else if (part == SP_COLMAP_IMAGES) {
        FZ_ASSERT(a->n_images == b->n_images, "image count changed");
        for (size_t i = 0; i < a->n_images; i++) {
            const sp_colmap_image *x = &a->images[i], *y = &b->images[i];
            FZ_ASSERT(x->id == y->id && x->camera_id == y->camera_id && !strcmp(x->name, y->name) &&
                          x->n_points2d == y->n_points2d, "image %zu changed ('%s' -> '%s')", i, x->name, y->name);
            fz_same_doubles(x->qvec, y->qvec, 4, "qvec");
            fz_same_doubles(x->tvec, y->tvec, 3, "tvec");
            fz_same_doubles(x->xys, y->xys, 2 * x->n_points2d, "points2D");
            FZ_ASSERT(!x->n_points2d || !memcmp(x->point3d_ids, y->point3d_ids, x->n_points2d * 8), "point3D ids changed");
        }
    } else {
        FZ_ASSERT(a->n_points == b->n_points, "point count changed");
        for (size_t i = 0; i < a->n_points; i++) {
            const sp_colmap_point *x = &a->points[i], *y = &b->points[i];
            FZ_ASSERT(x->id == y->id && !memcmp(x->rgb, y->rgb, 3) && x->track_len == y->track_len, "point %zu changed", i);
            fz_same_doubles(x->xyz, y->xyz, 3, "xyz");
            fz_same_doubles(&x->error, &y->error, 1, "error");
            FZ_ASSERT(!x->track_len || !memcmp(x->track, y->track, x->track_len * 8), "track changed");
        }
    }
}

/* Runs what consumes a parsed part: sp_colmap_image_camera over every image. */
static inline void fz_consume(sp_colmap_part part, sp_colmap_model *m)
{
    sp_colmap_camera fixed[4];
    sp_colmap_image one = {0};
    sp_colmap_model v = *m;
    if (part == SP_COLMAP_IMAGES) {
        for (int k = 0; k < 4; k++) {
            memset(&fixed[k], 0, sizeof fixed[k]);
            fixed[k].id = (uint32_t)k + 1;
            fixed[k].model = k; /* SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL */
            fixed[k].n_params = sp_colmap_model_num_params(k);
            fixed[k].width = 64, fixed[k].height = 48;
            for (int p = 0; p < fixed[k].n_params; p++) fixed[k].params[p] = 10 + p;
        }
        v.cameras = fixed, v.n_cameras = 4;
    } else if (part == SP_COLMAP_CAMERAS) {
        one.qvec[0] = 1;
        one.name = "view.png";
        v.images = &one, v.n_images = 1;
    } else {
        return;
    }
    sp_error err = {0};
    int rc = colmap_check_model("fuzz", &v, "bin", &err);
    if (rc) fz_check_error(rc, &err, "colmap_check_model");
    size_t n = part == SP_COLMAP_IMAGES ? v.n_images : v.n_cameras;
    for (size_t i = 0; i < n; i++) {
        if (part == SP_COLMAP_CAMERAS) one.camera_id = v.cameras[i].id;
        sp_camera cam;
        size_t idx = part == SP_COLMAP_IMAGES ? i : 0;
        rc = sp_colmap_image_camera(&v, idx, &cam, &err);
        if (rc) {
            fz_check_error(rc, &err, "sp_colmap_image_camera");
            continue;
        }
        FZ_ASSERT(cam.width > 0 && cam.height > 0, "camera of %dx%d", cam.width, cam.height);
        for (int k = 0; k < 9; k++) FZ_ASSERT(isfinite(cam.R[k]), "R is not finite");
    }
}

static inline int fz_colmap_one(const uint8_t *data, size_t size, fz_colmap_parse_fn parse, fz_colmap_write_fn write,
                         const char *const names[3])
{
    if (size < 1) return 0;
    sp_colmap_part part = (sp_colmap_part)(data[0] % 3);
    sp_colmap_model m, back;
    memset(&m, 0, sizeof m);
    memset(&back, 0, sizeof back);
    sp_error err = {0};
    int rc = parse(part, data + 1, size - 1, names[part], &m, &err);
    if (rc) {
        fz_check_error(rc, &err, "parse");
        sp_colmap_free(&m);
        return 0;
    }
    fz_consume(part, &m);
    /* Round trip through the writer (the other two parts are written empty). */
    char dir[1024], path[1024];
    fz_path("model", dir);
    rc = write(dir, &m, &err);
    FZ_ASSERT(rc == 0, "a model part that parsed does not write back: %s", err.msg);
    snprintf(path, sizeof path, "%s/%s", dir, names[part]);
    size_t n;
    unsigned char *bytes = fz_slurp(path, &n);
    FZ_ASSERT(bytes, "cannot read back %s", path);
    rc = parse(part, bytes, n, path, &back, &err);
    FZ_ASSERT(rc == 0, "what we wrote does not parse: %s", err.msg);
    fz_same_part(part, &m, &back);
    free(bytes);
    sp_colmap_free(&back);
    sp_colmap_free(&m);
    return 0;
}

#endif
