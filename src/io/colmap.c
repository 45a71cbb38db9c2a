/* COLMAP models: the camera-model table, locating a model inside a capture, checks shared by the
 * binary and text readers, and the conversion of a registered image to a pinhole sp_camera. */
#include "colmap_internal.h"

#include <stdlib.h>

/* From COLMAP src/colmap/sensor/models.h (model_id, name, parameter count). Id 11 exists in COLMAP
 * >= 3.9; we read and write it though it has no enum constant in io.h. */
static const struct {
    const char *name;
    int n_params;
} models[] = {
    {"SIMPLE_PINHOLE", 3}, {"PINHOLE", 4},       {"SIMPLE_RADIAL", 4},         {"RADIAL", 5},
    {"OPENCV", 8},         {"OPENCV_FISHEYE", 8}, {"FULL_OPENCV", 12},          {"FOV", 5},
    {"SIMPLE_RADIAL_FISHEYE", 4}, {"RADIAL_FISHEYE", 5}, {"THIN_PRISM_FISHEYE", 12},
    {"RAD_TAN_THIN_PRISM_FISHEYE", 16},
};
#define N_MODELS ((int)(sizeof models / sizeof models[0]))

const char *sp_colmap_model_name(int model) { return model >= 0 && model < N_MODELS ? models[model].name : NULL; }
int sp_colmap_model_num_params(int model) { return model >= 0 && model < N_MODELS ? models[model].n_params : -1; }

int sp_colmap_model_from_name(const char *name)
{
    for (int i = 0; i < N_MODELS; i++)
        if (!strcmp(name, models[i].name)) return i;
    return -1;
}

void sp_colmap_free(sp_colmap_model *m)
{
    if (!m) return;
    for (size_t i = 0; m->images && i < m->n_images; i++) {
        free(m->images[i].name);
        free(m->images[i].xys);
        free(m->images[i].point3d_ids);
    }
    for (size_t i = 0; m->points && i < m->n_points; i++) free(m->points[i].track);
    free(m->cameras);
    free(m->images);
    free(m->points);
    memset(m, 0, sizeof *m);
}

/* ---- locating a model ------------------------------------------------------------------------- */

static int has_model(const char *dir)
{
    char p[4096];
    const char *names[] = {"cameras.bin", "cameras.txt"};
    for (int i = 0; i < 2; i++)
        if (sp_path_join(p, sizeof p, dir, names[i]) == 0 && sp_file_exists(p)) return 1;
    return 0;
}

int sp_colmap_find_model_dir(const char *dir, char *out, size_t cap, sp_error *err)
{
    /* A capture root (images/ + sparse/0/) as COLMAP's mapper leaves it, sparse/ as some
     * exporters write it, or the model folder itself. */
    const char *subs[] = {"", "sparse/0", "sparse"};
    char p[4096];
    for (int i = 0; i < 3; i++) {
        if (i == 0) snprintf(p, sizeof p, "%s", dir);
        else if (sp_path_join(p, sizeof p, dir, subs[i]) != 0) continue;
        if (has_model(p)) {
            if (snprintf(out, cap, "%s", p) >= (int)cap)
                return sp_error_set(err, SP_E_ARG, "%s: path too long", p);
            return SP_OK;
        }
    }
    return sp_error_set(err, SP_E_NOTFOUND,
                        "%s: no COLMAP model (looked for cameras.bin/.txt in it, in sparse/0/ and in sparse/)", dir);
}

int sp_colmap_read(const char *dir, sp_colmap_model *m, sp_error *err)
{
    memset(m, 0, sizeof *m);
    char model_dir[4096], p[4200];
    int rc = sp_colmap_find_model_dir(dir, model_dir, sizeof model_dir, err);
    if (rc) return rc;
    sp_path_join(p, sizeof p, model_dir, "cameras.bin");
    return sp_file_exists(p) ? sp_colmap_read_bin(model_dir, m, err) : sp_colmap_read_txt(model_dir, m, err);
}

/* ---- checks ----------------------------------------------------------------------------------- */

static int all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

int colmap_check_camera(const char *file, size_t rec, const sp_colmap_camera *c, sp_error *err)
{
    if (sp_colmap_model_num_params(c->model) < 0)
        return sp_error_set(err, SP_E_FORMAT, "%s: camera %u (record %zu) has unknown model id %d", file, c->id, rec,
                            c->model);
    if (c->width == 0 || c->height == 0 || c->width > COLMAP_MAX_SIZE || c->height > COLMAP_MAX_SIZE)
        return sp_error_set(err, SP_E_FORMAT, "%s: camera %u has size %llux%llu (must be 1..%llu)", file, c->id,
                            (unsigned long long)c->width, (unsigned long long)c->height,
                            (unsigned long long)COLMAP_MAX_SIZE);
    if (!all_finite(c->params, c->n_params))
        return sp_error_set(err, SP_E_NUMERIC, "%s: camera %u (%s) has a non-finite parameter", file, c->id,
                            sp_colmap_model_name(c->model));
    return SP_OK;
}

int colmap_check_image(const char *file, size_t rec, const sp_colmap_image *im, sp_error *err)
{
    if (!all_finite(im->qvec, 4) || !all_finite(im->tvec, 3))
        return sp_error_set(err, SP_E_NUMERIC, "%s: image %u ('%s') has a non-finite pose (qvec %g %g %g %g, tvec %g %g %g)",
                            file, im->id, im->name ? im->name : "", im->qvec[0], im->qvec[1], im->qvec[2],
                            im->qvec[3], im->tvec[0], im->tvec[1], im->tvec[2]);
    double qn = im->qvec[0] * im->qvec[0] + im->qvec[1] * im->qvec[1] + im->qvec[2] * im->qvec[2] +
                im->qvec[3] * im->qvec[3];
    if (qn < 1e-12)
        return sp_error_set(err, SP_E_FORMAT, "%s: image %u ('%s') has a zero quaternion", file, im->id,
                            im->name ? im->name : "");
    for (size_t k = 0; k < im->n_points2d * 2; k++)
        if (!isfinite(im->xys[k]))
            return sp_error_set(err, SP_E_NUMERIC, "%s: image %u ('%s') point2D %zu is not finite", file, im->id,
                                im->name ? im->name : "", k / 2);
    (void)rec;
    return SP_OK;
}

int colmap_check_point(const char *file, size_t rec, const sp_colmap_point *p, sp_error *err)
{
    if (!all_finite(p->xyz, 3))
        return sp_error_set(err, SP_E_NUMERIC, "%s: point3D %llu (record %zu) has a non-finite position (%g %g %g)",
                            file, (unsigned long long)p->id, rec, p->xyz[0], p->xyz[1], p->xyz[2]);
    if (!isfinite(p->error))
        return sp_error_set(err, SP_E_NUMERIC, "%s: point3D %llu (record %zu) has a non-finite error (%g)", file,
                            (unsigned long long)p->id, rec, p->error);
    return SP_OK;
}

int colmap_check_part(sp_colmap_part part, const char *name, const sp_colmap_model *m, sp_error *err)
{
    if ((int)part < SP_COLMAP_CAMERAS || part > SP_COLMAP_POINTS)
        return sp_error_set(err, SP_E_ARG, "%s: unknown COLMAP model part %d", name, (int)part);
    const void *held[3] = {m->cameras, m->images, m->points};
    if (held[part])
        return sp_error_set(err, SP_E_ARG, "%s: the model already holds its %s", name,
                            part == SP_COLMAP_CAMERAS ? "cameras" : part == SP_COLMAP_IMAGES ? "images" : "points");
    return SP_OK;
}

int colmap_read_dir(const char *dir, const char *ext, colmap_parse_fn parse, sp_colmap_model *m, sp_error *err)
{
    static const char *const stems[3] = {"cameras", "images", "points3D"};
    memset(m, 0, sizeof *m);
    int rc = SP_OK;
    for (int part = 0; part < 3 && !rc; part++) {
        char name[32], path[4200], *buf;
        size_t size;
        snprintf(name, sizeof name, "%s.%s", stems[part], ext);
        if (sp_path_join(path, sizeof path, dir, name)) {
            rc = sp_error_set(err, SP_E_ARG, "%s: path too long", dir);
            break;
        }
        if ((rc = sp_read_file(path, &buf, &size, err))) break;
        rc = parse((sp_colmap_part)part, buf, size, path, m, err);
        free(buf);
    }
    if (!rc) rc = colmap_check_model(dir, m, ext, err);
    if (rc) sp_colmap_free(m);
    return rc;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Sorts a copy of the ids and reports the first repeat. */
static int check_unique(const char *file, const char *what, uint32_t *ids, size_t n, sp_error *err)
{
    qsort(ids, n, sizeof *ids, cmp_u32);
    for (size_t i = 1; i < n; i++)
        if (ids[i] == ids[i - 1]) return sp_error_set(err, SP_E_FORMAT, "%s: %s id %u appears twice", file, what, ids[i]);
    return SP_OK;
}

int colmap_check_model(const char *dir, const sp_colmap_model *m, const char *ext, sp_error *err)
{
    char cams[4200], imgs[4200];
    snprintf(cams, sizeof cams, "%s/cameras.%s", dir, ext);
    snprintf(imgs, sizeof imgs, "%s/images.%s", dir, ext);
    size_t n = m->n_cameras > m->n_images ? m->n_cameras : m->n_images;
    uint32_t *ids = malloc((n ? n : 1) * sizeof *ids);
    if (!ids) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", dir);
    for (size_t i = 0; i < m->n_cameras; i++) ids[i] = m->cameras[i].id;
    int rc = check_unique(cams, "camera", ids, m->n_cameras, err);
    for (size_t i = 0; !rc && i < m->n_images; i++) ids[i] = m->images[i].id;
    if (!rc) rc = check_unique(imgs, "image", ids, m->n_images, err);
    free(ids);
    for (size_t i = 0; !rc && i < m->n_images; i++)
        if (!sp_colmap_find_camera(m, m->images[i].camera_id))
            rc = sp_error_set(err, SP_E_FORMAT, "%s: image %u ('%s') names camera %u, which cameras.%s does not have",
                              imgs, m->images[i].id, m->images[i].name, m->images[i].camera_id, ext);
    return rc;
}

/* ---- cameras ---------------------------------------------------------------------------------- */

const sp_colmap_camera *sp_colmap_find_camera(const sp_colmap_model *m, uint32_t id)
{
    for (size_t i = 0; i < m->n_cameras; i++)
        if (m->cameras[i].id == id) return &m->cameras[i];
    return NULL;
}

int sp_colmap_image_camera(const sp_colmap_model *m, size_t i, sp_camera *cam, sp_error *err)
{
    if (i >= m->n_images)
        return sp_error_set(err, SP_E_ARG, "colmap: image index %zu is out of range (model has %zu images)", i,
                            m->n_images);
    const sp_colmap_image *im = &m->images[i];
    const sp_colmap_camera *c = sp_colmap_find_camera(m, im->camera_id);
    if (!c)
        return sp_error_set(err, SP_E_NOTFOUND, "colmap: image '%s' names camera %u, which the model does not have",
                            im->name, im->camera_id);
    if (c->width > COLMAP_MAX_SIZE || c->height > COLMAP_MAX_SIZE || !c->width || !c->height)
        return sp_error_set(err, SP_E_FORMAT, "colmap: camera %u has an invalid size", c->id);
    sp_camera out;
    memset(&out, 0, sizeof out);
    out.width = (int)c->width;
    out.height = (int)c->height;
    const double *p = c->params;
    switch (c->model) {
    case SP_COLMAP_SIMPLE_PINHOLE:
    case SP_COLMAP_SIMPLE_RADIAL:
    case SP_COLMAP_RADIAL:
        out.fx = out.fy = (float)p[0];
        out.cx = (float)p[1];
        out.cy = (float)p[2];
        if (c->model == SP_COLMAP_SIMPLE_RADIAL) {
            out.distortion = SP_DIST_SIMPLE_RADIAL;
            out.dist[0] = (float)p[3];
        } else if (c->model == SP_COLMAP_RADIAL) {
            out.distortion = SP_DIST_RADIAL;
            out.dist[0] = (float)p[3];
            out.dist[1] = (float)p[4];
        }
        break;
    case SP_COLMAP_PINHOLE:
    case SP_COLMAP_OPENCV:
        out.fx = (float)p[0];
        out.fy = (float)p[1];
        out.cx = (float)p[2];
        out.cy = (float)p[3];
        if (c->model == SP_COLMAP_OPENCV) {
            out.distortion = SP_DIST_OPENCV;
            for (int k = 0; k < 4; k++) out.dist[k] = (float)p[4 + k];
        }
        break;
    default: {
        const char *name = sp_colmap_model_name(c->model);
        return sp_error_set(err, SP_E_UNSUPPORTED,
                            "colmap: image '%s' uses camera %u with model %s, which semsplat does not support "
                            "(SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV; undistort with "
                            "'colmap image_undistorter')",
                            im->name, c->id, name ? name : "unknown");
    }
    }
    /* R from the unit quaternion, in double so that a slightly unnormalised qvec from a text
     * file gives an orthonormal matrix. */
    double w = im->qvec[0], x = im->qvec[1], y = im->qvec[2], z = im->qvec[3];
    double n = sqrt(w * w + x * x + y * y + z * z);
    if (!(n > 1e-6) || !isfinite(n))
        return sp_error_set(err, SP_E_NUMERIC, "colmap: image '%s' has an invalid quaternion", im->name);
    w /= n, x /= n, y /= n, z /= n;
    double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                   2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    for (int k = 0; k < 9; k++) out.R[k] = (float)R[k];
    for (int k = 0; k < 3; k++) out.t[k] = (float)im->tvec[k];
    *cam = out;
    return SP_OK;
}

void sp_colmap_image_set_pose(sp_colmap_image *im, const sp_camera *cam)
{
    float q[4];
    sp_mat3_to_quat(cam->R, q);
    for (int k = 0; k < 4; k++) im->qvec[k] = q[k];
    for (int k = 0; k < 3; k++) im->tvec[k] = cam->t[k];
}
