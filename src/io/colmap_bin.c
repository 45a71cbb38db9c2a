/* COLMAP binary model files (cameras.bin, images.bin, points3D.bin), little-endian as written by
 * COLMAP's WriteCamerasBinary / WriteImagesBinary / WritePoints3DBinary. Every count is checked
 * against the bytes left before allocating; reading and writing back gives identical bytes. */
#include "colmap_internal.h"

#include <stdlib.h>

#define TAKE(c, v) io_take((c), &(v), sizeof(v))

static int truncated(const char *file, const char *what, size_t rec, uint64_t total, size_t size, sp_error *err)
{
    return sp_error_set(err, SP_E_FORMAT, "%s: truncated in %s %zu of %llu (file is %zu bytes)", file, what, rec,
                        (unsigned long long)total, size);
}

/* Reads the leading uint64 count and checks it fits the file at `min_bytes` per record. */
static int read_count(const char *file, io_cursor *c, const char *what, size_t min_bytes, uint64_t *n, sp_error *err)
{
    if (TAKE(c, *n)) return sp_error_set(err, SP_E_FORMAT, "%s: truncated header (file is %zu bytes)", file, c->size);
    if (*n > io_left(c) / min_bytes)
        return sp_error_set(err, SP_E_FORMAT,
                            "%s: header says %llu %s but only %zu bytes follow (each takes at least %zu)", file,
                            (unsigned long long)*n, what, io_left(c), min_bytes);
    return SP_OK;
}

static int check_end(const char *file, const io_cursor *c, sp_error *err)
{
    if (io_left(c))
        return sp_error_set(err, SP_E_FORMAT, "%s: %zu unexpected bytes after the last record", file, io_left(c));
    return SP_OK;
}

static int read_cameras(const char *file, const io_cursor *in, sp_colmap_model *m, sp_error *err)
{
    io_cursor c = *in;
    uint64_t n;
    int rc = read_count(file, &c, "cameras", COLMAP_MIN_CAMERA_BYTES, &n, err);
    if (rc) return rc;
    m->cameras = calloc(n ? n : 1, sizeof *m->cameras);
    if (!m->cameras) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %llu cameras", file, (unsigned long long)n);
    for (uint64_t i = 0; i < n; i++) {
        sp_colmap_camera *cam = &m->cameras[i];
        int32_t model;
        if (TAKE(&c, cam->id) || TAKE(&c, model) || TAKE(&c, cam->width) || TAKE(&c, cam->height))
            return truncated(file, "camera", i, n, c.size, err);
        cam->model = model;
        cam->n_params = sp_colmap_model_num_params(model);
        if (cam->n_params < 0)
            return sp_error_set(err, SP_E_FORMAT, "%s: camera %u (record %llu) has unknown model id %d", file, cam->id,
                                (unsigned long long)i, model);
        if (io_take(&c, cam->params, sizeof(double) * (size_t)cam->n_params)) return truncated(file, "camera", i, n, c.size, err);
        m->n_cameras = i + 1;
        if ((rc = colmap_check_camera(file, i, cam, err))) return rc;
    }
    return check_end(file, &c, err);
}

static int read_images(const char *file, const io_cursor *in, sp_colmap_model *m, sp_error *err)
{
    io_cursor c = *in;
    uint64_t n;
    int rc = read_count(file, &c, "images", COLMAP_MIN_IMAGE_BYTES, &n, err);
    if (rc) return rc;
    m->images = calloc(n ? n : 1, sizeof *m->images);
    if (!m->images) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %llu images", file, (unsigned long long)n);
    for (uint64_t i = 0; i < n; i++) {
        sp_colmap_image *im = &m->images[i];
        m->n_images = i + 1;
        if (TAKE(&c, im->id) || io_take(&c, im->qvec, sizeof im->qvec) || io_take(&c, im->tvec, sizeof im->tvec) ||
            TAKE(&c, im->camera_id))
            return truncated(file, "image", i, n, c.size, err);
        const unsigned char *name = c.data + c.pos, *nul = memchr(name, 0, io_left(&c));
        if (!nul) return truncated(file, "image", i, n, c.size, err);
        size_t len = (size_t)(nul - name);
        im->name = malloc(len + 1);
        if (!im->name) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", file);
        memcpy(im->name, name, len + 1);
        c.pos += len + 1;
        uint64_t np;
        if (TAKE(&c, np)) return truncated(file, "image", i, n, c.size, err);
        if (np > io_left(&c) / COLMAP_POINT2D_BYTES)
            return sp_error_set(err, SP_E_FORMAT,
                                "%s: image %u ('%s') says %llu points2D but only %zu bytes follow (24 each)", file,
                                im->id, im->name, (unsigned long long)np, io_left(&c));
        if (np) {
            im->xys = malloc(np * 2 * sizeof(double));
            im->point3d_ids = malloc(np * sizeof(int64_t));
            if (!im->xys || !im->point3d_ids) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", file);
        }
        im->n_points2d = np;
        for (uint64_t k = 0; k < np; k++) {
            /* x, y, point3D_id; COLMAP's "no point" is UINT64_MAX, which reads as -1 here. */
            io_take(&c, &im->xys[2 * k], 2 * sizeof(double));
            io_take(&c, &im->point3d_ids[k], sizeof(int64_t));
        }
        if ((rc = colmap_check_image(file, i, im, err))) return rc;
    }
    return check_end(file, &c, err);
}

static int read_points(const char *file, const io_cursor *in, sp_colmap_model *m, sp_error *err)
{
    io_cursor c = *in;
    uint64_t n;
    int rc = read_count(file, &c, "points", COLMAP_MIN_POINT_BYTES, &n, err);
    if (rc) return rc;
    m->points = calloc(n ? n : 1, sizeof *m->points);
    if (!m->points) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %llu points", file, (unsigned long long)n);
    for (uint64_t i = 0; i < n; i++) {
        sp_colmap_point *p = &m->points[i];
        m->n_points = i + 1;
        uint64_t tl;
        if (TAKE(&c, p->id) || io_take(&c, p->xyz, sizeof p->xyz) || io_take(&c, p->rgb, 3) || TAKE(&c, p->error) ||
            TAKE(&c, tl))
            return truncated(file, "point3D", i, n, c.size, err);
        if (tl > io_left(&c) / COLMAP_TRACK_BYTES)
            return sp_error_set(err, SP_E_FORMAT, "%s: point3D %llu says track length %llu but only %zu bytes follow",
                                file, (unsigned long long)p->id, (unsigned long long)tl, io_left(&c));
        if (tl) {
            p->track = malloc(tl * 2 * sizeof(uint32_t));
            if (!p->track) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", file);
            io_take(&c, p->track, tl * 2 * sizeof(uint32_t));
        }
        p->track_len = tl;
        if ((rc = colmap_check_point(file, i, p, err))) return rc;
    }
    return check_end(file, &c, err);
}

typedef int (*bin_reader)(const char *file, const io_cursor *c, sp_colmap_model *m, sp_error *err);
static const bin_reader readers[3] = {read_cameras, read_images, read_points};

int sp_colmap_parse_bin(sp_colmap_part part, const void *data, size_t size, const char *name, sp_colmap_model *m,
                        sp_error *err)
{
    int rc = colmap_check_part(part, name, m, err);
    if (rc) return rc;
    io_cursor c = {data, size, 0};
    return readers[part](name, &c, m, err);
}

int sp_colmap_read_bin(const char *dir, sp_colmap_model *m, sp_error *err)
{
    return colmap_read_dir(dir, "bin", sp_colmap_parse_bin, m, err);
}

/* ---- writing ---------------------------------------------------------------------------------- */

#define PUT(f, v) fwrite(&(v), sizeof(v), 1, (f))

static int write_cameras(FILE *f, const sp_colmap_model *m, const char *path, sp_error *err)
{
    uint64_t n = m->n_cameras;
    PUT(f, n);
    for (size_t i = 0; i < m->n_cameras; i++) {
        const sp_colmap_camera *c = &m->cameras[i];
        if (sp_colmap_model_num_params(c->model) != c->n_params)
            return sp_error_set(err, SP_E_ARG, "%s: camera %u has model %d with %d params (expected %d)", path, c->id,
                                c->model, c->n_params, sp_colmap_model_num_params(c->model));
        int32_t model = c->model;
        PUT(f, c->id);
        PUT(f, model);
        PUT(f, c->width);
        PUT(f, c->height);
        fwrite(c->params, sizeof(double), (size_t)c->n_params, f);
    }
    return SP_OK;
}

static int write_images(FILE *f, const sp_colmap_model *m, const char *path, sp_error *err)
{
    uint64_t n = m->n_images;
    PUT(f, n);
    for (size_t i = 0; i < m->n_images; i++) {
        const sp_colmap_image *im = &m->images[i];
        PUT(f, im->id);
        fwrite(im->qvec, sizeof(double), 4, f);
        fwrite(im->tvec, sizeof(double), 3, f);
        PUT(f, im->camera_id);
        const char *name = im->name ? im->name : "";
        fwrite(name, 1, strlen(name) + 1, f);
        uint64_t np = im->n_points2d;
        PUT(f, np);
        for (size_t k = 0; k < im->n_points2d; k++) {
            fwrite(&im->xys[2 * k], sizeof(double), 2, f);
            PUT(f, im->point3d_ids[k]);
        }
    }
    (void)path, (void)err;
    return SP_OK;
}

static int write_points(FILE *f, const sp_colmap_model *m, const char *path, sp_error *err)
{
    uint64_t n = m->n_points;
    PUT(f, n);
    for (size_t i = 0; i < m->n_points; i++) {
        const sp_colmap_point *p = &m->points[i];
        PUT(f, p->id);
        fwrite(p->xyz, sizeof(double), 3, f);
        fwrite(p->rgb, 1, 3, f);
        PUT(f, p->error);
        uint64_t tl = p->track_len;
        PUT(f, tl);
        if (tl) fwrite(p->track, sizeof(uint32_t), 2 * tl, f);
    }
    (void)path, (void)err;
    return SP_OK;
}

typedef int (*bin_writer)(FILE *f, const sp_colmap_model *m, const char *path, sp_error *err);

static int write_one(const char *dir, const char *name, bin_writer fn, const sp_colmap_model *m, sp_error *err)
{
    char path[4200], tmp[4300];
    if (sp_path_join(path, sizeof path, dir, name)) return sp_error_set(err, SP_E_ARG, "%s: path too long", dir);
    FILE *f = io_tmp_open(path, tmp, sizeof tmp, err);
    if (!f) return err ? err->code : SP_E_IO;
    int rc = fn(f, m, path, err);
    if (rc) {
        io_tmp_commit(f, tmp, path, 0, NULL);
        return rc;
    }
    return io_tmp_commit(f, tmp, path, 1, err);
}

int sp_colmap_write_bin(const char *dir, const sp_colmap_model *m, sp_error *err)
{
    int rc = sp_mkdirs(dir, err);
    if (!rc) rc = write_one(dir, "cameras.bin", write_cameras, m, err);
    if (!rc) rc = write_one(dir, "images.bin", write_images, m, err);
    if (!rc) rc = write_one(dir, "points3D.bin", write_points, m, err);
    return rc;
}
