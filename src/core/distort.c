/* Lens distortion as COLMAP models it (SIMPLE_RADIAL, RADIAL, OPENCV) on normalised image
 * coordinates, its inverse by Newton iteration, and resampling between a distorted camera and
 * the pinhole camera the renderer uses. Lift and the query engine use it so that a feature map
 * or heatmap pixel refers to the ray it was computed for. Pixel centres are at i + 0.5. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/core.h"

typedef struct {
    double k1, k2, p1, p2;
} lens;

static lens lens_of(const sp_camera *c)
{
    lens l = {0, 0, 0, 0};
    if (c->distortion == SP_DIST_NONE) return l;
    l.k1 = c->dist[0];
    if (c->distortion != SP_DIST_SIMPLE_RADIAL) l.k2 = c->dist[1];
    if (c->distortion == SP_DIST_OPENCV) l.p1 = c->dist[2], l.p2 = c->dist[3];
    return l;
}

/* COLMAP's OpenCVCameraModel::Distortion (the radial models are its special cases), and its
 * Jacobian J = d(ud, vd) / d(u, v). */
static void distort_j(const lens *l, double u, double v, double *ud, double *vd, double J[4])
{
    double r2 = u * u + v * v, radial = 1 + l->k1 * r2 + l->k2 * r2 * r2;
    *ud = u * radial + 2 * l->p1 * u * v + l->p2 * (r2 + 2 * u * u);
    *vd = v * radial + 2 * l->p2 * u * v + l->p1 * (r2 + 2 * v * v);
    if (!J) return;
    double g = 2 * l->k1 + 4 * l->k2 * r2; /* d radial / d(r2) times 2 */
    J[0] = radial + g * u * u + 2 * l->p1 * v + 6 * l->p2 * u;
    J[1] = g * u * v + 2 * l->p1 * u + 2 * l->p2 * v;
    J[2] = g * u * v + 2 * l->p2 * v + 2 * l->p1 * u;
    J[3] = radial + g * v * v + 2 * l->p2 * u + 6 * l->p1 * v;
}

void sp_camera_distort(const sp_camera *cam, double u, double v, double *ud, double *vd)
{
    lens l = lens_of(cam);
    distort_j(&l, u, v, ud, vd, NULL);
}

/* Where the model folds back (det J <= 0, e.g. beyond the radius where r (1 + k1 r^2) peaks for
 * k1 < 0) two rays share a pixel: such rays have no image. */
static int folds(const double J[4]) { return !(J[0] * J[3] - J[1] * J[2] > 1e-9); }

int sp_camera_undistort(const sp_camera *cam, double ud, double vd, double *u, double *v)
{
    lens l = lens_of(cam);
    double x = ud, y = vd;
    for (int it = 0; it < 50; it++) {
        double fx, fy, J[4];
        distort_j(&l, x, y, &fx, &fy, J);
        fx -= ud, fy -= vd;
        if (folds(J)) break;
        if (fx * fx + fy * fy < 1e-24) {
            *u = x, *v = y;
            return 0;
        }
        double det = J[0] * J[3] - J[1] * J[2];
        x -= (J[3] * fx - J[1] * fy) / det;
        y -= (J[0] * fy - J[2] * fx) / det;
        if (!isfinite(x) || !isfinite(y)) break;
    }
    *u = ud, *v = vd;
    return -1;
}

/* Bilinear sample of img [h][w][ch] at pixel-index coordinates (sx, sy) (centre of pixel i at
 * i); 0 and no write when outside the image's area [-0.5, w - 0.5] x [-0.5, h - 0.5]. */
static int sample(const float *img, int w, int h, int ch, double sx, double sy, float *out)
{
    if (!(sx >= -0.5 && sy >= -0.5 && sx <= w - 0.5 && sy <= h - 0.5)) return 0;
    double cx = sx < 0 ? 0 : sx > w - 1 ? w - 1 : sx, cy = sy < 0 ? 0 : sy > h - 1 ? h - 1 : sy;
    int x0 = (int)cx, y0 = (int)cy, x1 = x0 + 1 < w ? x0 + 1 : x0, y1 = y0 + 1 < h ? y0 + 1 : y0;
    double ax = cx - x0, ay = cy - y0;
    const float *a = img + ((size_t)y0 * w + x0) * ch, *b = img + ((size_t)y0 * w + x1) * ch;
    const float *c = img + ((size_t)y1 * w + x0) * ch, *d = img + ((size_t)y1 * w + x1) * ch;
    for (int k = 0; k < ch; k++)
        out[k] = (float)((1 - ay) * ((1 - ax) * a[k] + ax * b[k]) + ay * ((1 - ax) * c[k] + ax * d[k]));
    return 1;
}

static int check_cams(const sp_camera *a, const sp_camera *b, const float *img, int ch, float *out,
                      sp_error *err)
{
    if (!a || !b || !img || !out || ch < 1)
        return sp_error_set(err, SP_E_ARG, "remap: missing argument or %d channels", ch);
    if (a->width < 1 || a->height < 1 || b->width < 1 || b->height < 1 || !(a->fx > 0) || !(a->fy > 0) ||
        !(b->fx > 0) || !(b->fy > 0))
        return sp_error_set(err, SP_E_ARG, "remap: cameras %dx%d and %dx%d need positive sizes and focal lengths",
                            a->width, a->height, b->width, b->height);
    return 0;
}

int sp_camera_remap_to_pinhole(const sp_camera *src, const float *img, int channels,
                               const sp_camera *dst, float *out, uint8_t *mask, sp_error *err)
{
    int rc = check_cams(src, dst, img, channels, out, err);
    if (rc) return rc;
    lens l = lens_of(src);
    for (int y = 0; y < dst->height; y++)
        for (int x = 0; x < dst->width; x++) {
            size_t p = (size_t)y * dst->width + x;
            double u = (x + 0.5 - dst->cx) / dst->fx, v = (y + 0.5 - dst->cy) / dst->fy, ud, vd, J[4];
            distort_j(&l, u, v, &ud, &vd, J);
            int ok = !folds(J) &&
                     sample(img, src->width, src->height, channels, ud * src->fx + src->cx - 0.5,
                            vd * src->fy + src->cy - 0.5, out + p * channels);
            if (!ok) memset(out + p * channels, 0, sizeof(float) * channels);
            if (mask) mask[p] = (uint8_t)ok;
        }
    return 0;
}

int sp_camera_remap_from_pinhole(const sp_camera *src, const float *img, int channels,
                                 const sp_camera *dst, float *out, uint8_t *mask, sp_error *err)
{
    int rc = check_cams(src, dst, img, channels, out, err);
    if (rc) return rc;
    for (int y = 0; y < dst->height; y++)
        for (int x = 0; x < dst->width; x++) {
            size_t p = (size_t)y * dst->width + x;
            double ud = (x + 0.5 - dst->cx) / dst->fx, vd = (y + 0.5 - dst->cy) / dst->fy, u, v;
            int ok = !sp_camera_undistort(dst, ud, vd, &u, &v) &&
                     sample(img, src->width, src->height, channels, u * src->fx + src->cx - 0.5,
                            v * src->fy + src->cy - 0.5, out + p * channels);
            if (!ok) memset(out + p * channels, 0, sizeof(float) * channels);
            if (mask) mask[p] = (uint8_t)ok;
        }
    return 0;
}
