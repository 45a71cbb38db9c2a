/* Lens distortion: COLMAP's formulas written out independently here, the Newton inverse against
 * them, and the remaps between a distorted camera and a pinhole one on a smooth analytic pattern
 * (the distorted image made with an independent fixed-point inverse). */
#include "semsplat/core.h"
#include "test.h"

/* COLMAP OpenCVCameraModel::Distortion, as in colmap/src/base/camera_models.h. */
static void ref_distort(const double k[4], double u, double v, double *ud, double *vd)
{
    double u2 = u * u, v2 = v * v, uv = u * v, r2 = u2 + v2;
    double radial = k[0] * r2 + k[1] * r2 * r2;
    *ud = u + u * radial + 2 * k[2] * uv + k[3] * (r2 + 2 * u2);
    *vd = v + v * radial + 2 * k[3] * uv + k[2] * (r2 + 2 * v2);
}

/* Fixed-point inverse u = ud - (distort(u) - u), as COLMAP's IterativeUndistortion starts. */
static void ref_undistort(const double k[4], double ud, double vd, double *u, double *v)
{
    double x = ud, y = vd;
    for (int it = 0; it < 500; it++) {
        double dx, dy;
        ref_distort(k, x, y, &dx, &dy);
        x = ud - (dx - x);
        y = vd - (dy - y);
    }
    *u = x, *v = y;
}

static void make_cam(sp_camera *c, sp_distortion model, double k1, double k2, double p1, double p2)
{
    memset(c, 0, sizeof *c);
    c->width = 96, c->height = 72;
    c->fx = 80, c->fy = 78, c->cx = 47.3f, c->cy = 36.6f;
    c->distortion = model;
    c->dist[0] = (float)k1, c->dist[1] = (float)k2, c->dist[2] = (float)p1, c->dist[3] = (float)p2;
    c->R[0] = c->R[4] = c->R[8] = 1;
}

static void test_models_and_inverse(void)
{
    struct { sp_distortion m; double k[4]; } cases[] = {
        {SP_DIST_SIMPLE_RADIAL, {-0.2, 0, 0, 0}},
        {SP_DIST_RADIAL, {-0.25, 0.06, 0, 0}},
        {SP_DIST_OPENCV, {-0.22, 0.04, 0.003, -0.002}},
        {SP_DIST_OPENCV, {0.12, -0.01, -0.004, 0.005}},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        sp_camera cam;
        const double *k = cases[c].k;
        make_cam(&cam, cases[c].m, k[0], k[1], k[2], k[3]);
        double kf[4] = {cam.dist[0], cases[c].m == SP_DIST_SIMPLE_RADIAL ? 0 : cam.dist[1],
                        cases[c].m == SP_DIST_OPENCV ? cam.dist[2] : 0, cases[c].m == SP_DIST_OPENCV ? cam.dist[3] : 0};
        double worst_d = 0, worst_inv = 0;
        for (double u = -0.6; u <= 0.6; u += 0.05)
            for (double v = -0.45; v <= 0.45; v += 0.05) {
                double a, b, ra, rb, iu, iv;
                sp_camera_distort(&cam, u, v, &a, &b);
                ref_distort(kf, u, v, &ra, &rb);
                worst_d = fmax(worst_d, fmax(fabs(a - ra), fabs(b - rb)));
                CHECK(sp_camera_undistort(&cam, a, b, &iu, &iv) == 0);
                worst_inv = fmax(worst_inv, fmax(fabs(iu - u), fabs(iv - v)));
            }
        CHECK_MSG(worst_d < 1e-12 && worst_inv < 1e-9, "case %zu: distortion off by %g, inverse by %g", c, worst_d,
                  worst_inv);
    }
    /* beyond the fold of a strong barrel there is no inverse */
    sp_camera cam;
    make_cam(&cam, SP_DIST_SIMPLE_RADIAL, -0.5, 0, 0, 0); /* r (1 - 0.5 r^2) peaks at r = 0.816 */
    double u, v;
    CHECK(sp_camera_undistort(&cam, 0.6, 0.0, &u, &v) == -1);
    CHECK(sp_camera_undistort(&cam, 0.3, 0.1, &u, &v) == 0);
}

static double pattern(double u, double v) { return 0.5 + 0.4 * sin(6 * u + 1) * cos(5 * v - 0.5); }

/* A pinhole image and the same view through the lens, both of the analytic pattern: remapping
 * one gives the other within bilinear error, and pixels whose ray the other camera does not see
 * are masked. */
static void test_remaps(void)
{
    sp_camera dcam, pcam;
    make_cam(&dcam, SP_DIST_OPENCV, -0.28, 0.05, 0.002, -0.003);
    pcam = dcam;
    pcam.distortion = SP_DIST_NONE;
    int W = dcam.width, H = dcam.height;
    double k[4] = {dcam.dist[0], dcam.dist[1], dcam.dist[2], dcam.dist[3]};
    float *pin = malloc(sizeof(float) * W * H * 2), *dis = malloc(sizeof(float) * W * H * 2);
    float *out = malloc(sizeof(float) * W * H * 2);
    uint8_t *mask = malloc((size_t)W * H);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double u = (x + 0.5 - pcam.cx) / pcam.fx, v = (y + 0.5 - pcam.cy) / pcam.fy, uu, vv;
            pin[(y * W + x) * 2] = (float)pattern(u, v), pin[(y * W + x) * 2 + 1] = (float)u;
            ref_undistort(k, (x + 0.5 - dcam.cx) / dcam.fx, (y + 0.5 - dcam.cy) / dcam.fy, &uu, &vv);
            dis[(y * W + x) * 2] = (float)pattern(uu, vv), dis[(y * W + x) * 2 + 1] = (float)uu;
        }
    sp_error err = {0};
    /* distorted -> pinhole: barrel distortion sees more than the pinhole, so nothing is masked
     * away in the middle; compare where valid */
    CHECK_OK(sp_camera_remap_to_pinhole(&dcam, dis, 2, &pcam, out, mask, &err), &err);
    double worst = 0, bad_ray = 0;
    long valid = 0;
    for (int p = 0; p < W * H; p++) {
        if (!mask[p]) continue;
        valid++;
        worst = fmax(worst, fabs(out[2 * p] - pin[2 * p]));
        bad_ray = fmax(bad_ray, fabs(out[2 * p + 1] - pin[2 * p + 1]) * pcam.fx); /* in pixels */
    }
    fprintf(stderr, "  to pinhole: %ld of %d valid, pattern off by %.4f, ray by %.3f px\n", valid, W * H, worst, bad_ray);
    CHECK(valid > W * H * 0.95);
    CHECK(worst < 0.02 && bad_ray < 0.05);
    /* the same without distortion moves nothing */
    CHECK_OK(sp_camera_remap_to_pinhole(&pcam, pin, 2, &pcam, out, mask, &err), &err);
    double same = 0;
    for (int p = 0; p < W * H * 2; p++) same = fmax(same, fabs(out[p] - pin[p]));
    CHECK(same < 1e-6);
    /* pinhole -> distorted: the corners of a barrel lens look outside the pinhole frame */
    CHECK_OK(sp_camera_remap_from_pinhole(&pcam, pin, 2, &dcam, out, mask, &err), &err);
    worst = 0, valid = 0;
    for (int p = 0; p < W * H; p++) {
        if (!mask[p]) continue;
        valid++;
        worst = fmax(worst, fabs(out[2 * p] - dis[2 * p]));
    }
    fprintf(stderr, "  from pinhole: %ld of %d valid, pattern off by %.4f\n", valid, W * H, worst);
    CHECK(!mask[0] && !mask[W * H - 1] && mask[(H / 2) * W + W / 2]);
    CHECK(valid > W * H / 2 && valid < W * H);
    CHECK(worst < 0.02);
    CHECK_FAILS(sp_camera_remap_to_pinhole(&dcam, dis, 0, &pcam, out, mask, &err), SP_E_ARG, &err, "channels");
    free(pin), free(dis), free(out), free(mask);
}

int main(void)
{
    RUN(test_models_and_inverse);
    RUN(test_remaps);
    return TEST_EXIT();
}
