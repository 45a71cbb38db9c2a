/* Training data: undistortion of OPENCV / radial cameras against an analytic pattern, the
 * held-out split and downscaling, and the points3D initialisation (3-nearest-neighbour scales
 * against brute force, opacity, colours). */
#include "semsplat/io.h"
#include "semsplat/train.h"
#include "test.h"

enum { W = 96, H = 72 };

/* Scene seen by a pinhole camera, as a function of normalised image coordinates. */
static double pattern(double u, double v) { return 0.5 + 0.4 * cos(9 * u) * cos(7 * v + 0.3); }

static void cv_distort(const double k[4], double u, double v, double *du, double *dv)
{
    double r2 = u * u + v * v, rad = k[0] * r2 + k[1] * r2 * r2;
    *du = u + u * rad + 2 * k[2] * u * v + k[3] * (r2 + 2 * u * u);
    *dv = v + v * rad + 2 * k[3] * u * v + k[2] * (r2 + 2 * v * v);
}

/* Writes a one-image capture with an OPENCV camera whose image is `pattern` seen through the
 * distortion k (inverted per pixel by fixed-point iteration). */
static void write_distorted(const char *dir, const double k[4], int model)
{
    sp_error err = {0};
    char path[1200];
    snprintf(path, sizeof path, "%s/images", dir);
    sp_mkdirs(path, &err);
    snprintf(path, sizeof path, "%s/sparse/0", dir);
    sp_mkdirs(path, &err);
    double fx = 80, fy = 78, cx = W / 2.0 + 1.5, cy = H / 2.0 - 1;
    static float img[W * H * 3];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double ud = (x + 0.5 - cx) / fx, vd = (y + 0.5 - cy) / fy, u = ud, v = vd;
            for (int it = 0; it < 50; it++) {
                double du, dv;
                cv_distort(k, u, v, &du, &dv);
                u += ud - du;
                v += vd - dv;
            }
            for (int c = 0; c < 3; c++) img[(y * W + x) * 3 + c] = (float)pattern(u, v);
        }
    snprintf(path, sizeof path, "%s/images/a.png", dir);
    CHECK_OK(sp_write_png_f32(path, img, W, H, 3, &err), &err);
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    m.n_cameras = 1;
    m.cameras = calloc(1, sizeof *m.cameras);
    m.cameras[0].id = 1;
    m.cameras[0].model = model;
    m.cameras[0].width = W;
    m.cameras[0].height = H;
    m.cameras[0].n_params = sp_colmap_model_num_params(model);
    double p[8] = {fx, fy, cx, cy, k[0], k[1], k[2], k[3]};
    memcpy(m.cameras[0].params, p, sizeof p);
    m.n_images = 1;
    m.images = calloc(1, sizeof *m.images);
    m.images[0].id = 1;
    m.images[0].camera_id = 1;
    m.images[0].qvec[0] = 1;
    m.images[0].name = strdup("a.png");
    snprintf(path, sizeof path, "%s/sparse/0", dir);
    CHECK_OK(sp_colmap_write_bin(path, &m, &err), &err);
    sp_colmap_free(&m);
}

static void test_undistort_opencv(void)
{
    const char *dir = test_tmpdir("train_undistort");
    double k[4] = {-0.15, 0.03, 0.004, -0.003};
    write_distorted(dir, k, SP_COLMAP_OPENCV);
    sp_error err = {0};
    sp_train_data d;
    CHECK_OK(sp_train_data_load(&d, dir, NULL, 1, 8, &err), &err);
    if (d.n_views != 1) return;
    const sp_camera *c = &d.views[0].cam;
    CHECK(d.n_undistorted == 1 && c->distortion == SP_DIST_NONE);
    CHECK(c->fx > 60 && c->fx < 80); /* barrel: corners pulled in, the pinhole view can widen */
    CHECK_NEAR(c->fx / c->fy, 80.0 / 78.0, 1e-5);
    double sum = 0, worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double u = (x + 0.5 - c->cx) / c->fx, v = (y + 0.5 - c->cy) / c->fy;
            double e = fabs(d.views[0].rgb[(y * W + x) * 3] / 255.0 - pattern(u, v));
            sum += e;
            if (e > worst) worst = e;
        }
    fprintf(stderr, "  undistort: mean abs error %.4f, worst %.4f, fx %.2f\n", sum / (W * H), worst, c->fx);
    CHECK(sum / (W * H) < 0.01);
    CHECK(worst < 0.08);
    sp_train_data_free(&d);
}

static void test_fisheye_rejected(void)
{
    const char *dir = test_tmpdir("train_fisheye");
    double k[4] = {0.01, 0, 0, 0};
    write_distorted(dir, k, SP_COLMAP_OPENCV_FISHEYE);
    sp_error err = {0};
    sp_train_data d;
    CHECK_FAILS(sp_train_data_load(&d, dir, NULL, 1, 8, &err), SP_E_UNSUPPORTED, &err, "OPENCV_FISHEYE");
    CHECK(strstr(err.msg, "image_undistorter") != NULL);
}

static void test_init_from_points(void)
{
    enum { N = 700 };
    sp_train_data d;
    memset(&d, 0, sizeof d);
    d.n_points = N;
    d.points = malloc(N * 3 * sizeof(float));
    d.point_rgb = malloc(N * 3);
    test_rng r = {3};
    for (int i = 0; i < N; i++) {
        /* clustered points: a dense blob and sparse outliers exercise the grid search */
        double spread = i < N / 2 ? 0.05 : 3.0;
        for (int a = 0; a < 3; a++) d.points[i * 3 + a] = (float)test_range(&r, -spread, spread);
        for (int a = 0; a < 3; a++) d.point_rgb[i * 3 + a] = (uint8_t)(i * 7 + a * 50);
    }
    sp_splat s;
    sp_error err = {0};
    CHECK_OK(sp_train_init_from_points(&s, &d, 2, 1, &err), &err);
    CHECK(s.n == N && s.sh_degree == 2);
    int bad = 0;
    for (int i = 0; i < N; i++) {
        double b[3] = {1e30, 1e30, 1e30};
        for (int j = 0; j < N; j++) {
            if (j == i) continue;
            double dd = 0;
            for (int a = 0; a < 3; a++) {
                double t = (double)d.points[j * 3 + a] - d.points[i * 3 + a];
                dd += t * t;
            }
            if (dd < b[2]) {
                if (dd < b[1]) {
                    b[2] = b[1];
                    if (dd < b[0]) b[1] = b[0], b[0] = dd;
                    else b[1] = dd;
                } else b[2] = dd;
            }
        }
        double want = log(sqrt((b[0] + b[1] + b[2]) / 3));
        for (int a = 0; a < 3; a++)
            if (fabs(s.log_scales[i * 3 + a] - want) > 1e-4) bad++;
        CHECK_NEAR(s.opacity_logits[i], sp_logit(0.1f), 1e-6);
        int K3 = 27;
        CHECK_NEAR(0.5 + SP_SH_C0 * s.sh[i * K3 + 1], d.point_rgb[i * 3 + 1] / 255.0, 1e-5);
        CHECK(s.sh[i * K3 + 3] == 0 && s.sh[i * K3 + 26] == 0);
    }
    CHECK_MSG(bad == 0, "%d scales differ from brute-force 3-NN", bad);
    sp_splat_free(&s);
    d.n_points = 0;
    CHECK_FAILS(sp_train_init_from_points(&s, &d, 2, 1, &err), SP_E_ARG, &err, "random");
    sp_train_data_free(&d);
}

int main(void)
{
    RUN(test_undistort_opencv);
    RUN(test_fisheye_rejected);
    RUN(test_init_from_points);
    return TEST_EXIT();
}
