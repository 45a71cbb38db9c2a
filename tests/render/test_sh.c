/* sp_sh_to_rgb and its backward against a double implementation of the 3DGS SH basis written out
 * here, and central finite differences of it for v_sh and v_means, degrees 0-3 with active
 * degree below the stored one, clamped channels, and bad arguments. */
#include "test.h"

#include "semsplat/render.h"

/* 3DGS real SH basis, double, straight from the published constants. */
static void sh_basis_d(int deg, double x, double y, double z, double *b)
{
    b[0] = 0.28209479177387814;
    if (deg < 1) return;
    b[1] = -0.4886025119029199 * y;
    b[2] = 0.4886025119029199 * z;
    b[3] = -0.4886025119029199 * x;
    if (deg < 2) return;
    b[4] = 1.0925484305920792 * x * y;
    b[5] = -1.0925484305920792 * y * z;
    b[6] = 0.31539156525252005 * (2 * z * z - x * x - y * y);
    b[7] = -1.0925484305920792 * x * z;
    b[8] = 0.5462742152960396 * (x * x - y * y);
    if (deg < 3) return;
    b[9] = -0.5900435899266435 * y * (3 * x * x - y * y);
    b[10] = 2.890611442640554 * x * y * z;
    b[11] = -0.4570457994644658 * y * (4 * z * z - x * x - y * y);
    b[12] = 0.3731763325901154 * z * (2 * z * z - 3 * x * x - 3 * y * y);
    b[13] = -0.4570457994644658 * x * (4 * z * z - x * x - y * y);
    b[14] = 1.445305721320277 * z * (x * x - y * y);
    b[15] = -0.5900435899266435 * x * (x * x - 3 * y * y);
}

/* rgb of one Gaussian (before the clamp when raw != 0). */
static void sh_rgb_d(int deg_active, int K, const double *sh, const double *m, const double *cc,
                     double *rgb, int raw)
{
    double d[3] = {m[0] - cc[0], m[1] - cc[1], m[2] - cc[2]};
    double nn = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double b[16];
    sh_basis_d(deg_active, d[0] / nn, d[1] / nn, d[2] / nn, b);
    int Ka = (deg_active + 1) * (deg_active + 1);
    (void)K;
    for (int c = 0; c < 3; c++) {
        double acc = 0.5;
        for (int k = 0; k < Ka; k++) acc += b[k] * sh[k * 3 + c];
        rgb[c] = raw ? acc : fmax(0.0, acc);
    }
}

static void run(int degree, int degree_active, unsigned long long seed)
{
    test_rng rng = {seed};
    size_t n = 40;
    int K = sp_sh_coeffs(degree), stride = 5; /* stride > 3: rgb inside a wider buffer */
    float *sh = malloc(n * K * 3 * sizeof(float)), *means = malloc(n * 3 * sizeof(float));
    float *rgb = calloc(n * stride, sizeof(float)), *v_rgb = calloc(n * stride, sizeof(float));
    float *v_sh = calloc(n * K * 3, sizeof(float)), *v_means = calloc(n * 3, sizeof(float));
    for (size_t i = 0; i < n * K * 3; i++) sh[i] = (float)test_range(&rng, -1, 1);
    for (size_t i = 0; i < n * 3; i++) means[i] = (float)test_range(&rng, -3, 3);
    for (size_t i = 0; i < n * stride; i++) v_rgb[i] = (float)test_range(&rng, -1, 1);
    sp_vec3 cc = sp_v3(0.3f, -0.2f, 0.1f);
    double ccd[3] = {0.3f, -0.2f, 0.1f};

    sp_device *dev = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_sh_to_rgb(dev, n, degree, degree_active, sh, means, cc, rgb, stride, &err), &err);
    CHECK_OK(sp_sh_to_rgb_backward(dev, n, degree, degree_active, sh, means, cc, rgb, v_rgb, stride,
                                   v_sh, v_means, &err), &err);

    double max_fwd = 0, worst_sh = 0, worst_m = 0;
    int clamped = 0;
    for (size_t i = 0; i < n; i++) {
        double shd[48], md[3], out[3], raw[3];
        for (int k = 0; k < K * 3; k++) shd[k] = sh[i * K * 3 + k];
        for (int k = 0; k < 3; k++) md[k] = means[i * 3 + k];
        sh_rgb_d(degree_active, K, shd, md, ccd, out, 0);
        sh_rgb_d(degree_active, K, shd, md, ccd, raw, 1);
        for (int c = 0; c < 3; c++) {
            max_fwd = fmax(max_fwd, fabs(out[c] - rgb[i * stride + c]));
            clamped += raw[c] < 0;
        }
        /* loss = sum_c v_rgb[c] * max(0, raw[c]) */
        double vr[3] = {v_rgb[i * stride], v_rgb[i * stride + 1], v_rgb[i * stride + 2]};
        for (int k = 0; k < K * 3 + 3; k++) {
            double *p = k < K * 3 ? &shd[k] : &md[k - K * 3];
            double keep = *p, h = 1e-6, Lp = 0, Lm = 0, o[3];
            *p = keep + h;
            sh_rgb_d(degree_active, K, shd, md, ccd, o, 0);
            for (int c = 0; c < 3; c++) Lp += vr[c] * o[c];
            *p = keep - h;
            sh_rgb_d(degree_active, K, shd, md, ccd, o, 0);
            for (int c = 0; c < 3; c++) Lm += vr[c] * o[c];
            *p = keep;
            double fd = (Lp - Lm) / (2 * h);
            double a = k < K * 3 ? v_sh[i * K * 3 + k] : v_means[i * 3 + k - K * 3];
            double rel = fabs(a - fd) / fmax(fabs(fd), 1e-2);
            if (k < K * 3)
                worst_sh = fmax(worst_sh, rel);
            else
                worst_m = fmax(worst_m, rel);
        }
    }
    fprintf(stderr, "  degree %d active %d: fwd max diff %.2e, v_sh worst rel %.2e, v_means worst rel "
            "%.2e, %d clamped channels\n", degree, degree_active, max_fwd, worst_sh, worst_m, clamped);
    CHECK(max_fwd < 1e-6);
    CHECK(worst_sh < 1e-3);
    CHECK(worst_m < 1e-3);
    /* coefficients above the active degree get no gradient */
    int ok = 1;
    for (size_t i = 0; i < n; i++)
        for (int k = sp_sh_coeffs(degree_active) * 3; k < K * 3; k++) ok &= v_sh[i * K * 3 + k] == 0.f;
    CHECK(ok);
    free(sh), free(means), free(rgb), free(v_rgb), free(v_sh), free(v_means);
    sp_device_free(dev);
}

static void test_degrees(void)
{
    run(0, 0, 1);
    run(1, 1, 2);
    run(2, 2, 3);
    run(3, 3, 4);
    run(3, 1, 5);
    run(3, 0, 6);
}

static void test_bad_args(void)
{
    sp_device *dev = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 1, &err), &err);
    float sh[48] = {0}, m[3] = {0, 0, 1}, rgb[3];
    sp_vec3 cc = sp_v3(0, 0, 0);
    CHECK_FAILS(sp_sh_to_rgb(dev, 1, 4, 4, sh, m, cc, rgb, 3, &err), SP_E_ARG, &err, "degree 4");
    CHECK_FAILS(sp_sh_to_rgb(dev, 1, 2, 3, sh, m, cc, rgb, 3, &err), SP_E_ARG, &err, "active SH degree 3");
    CHECK_FAILS(sp_sh_to_rgb(dev, 1, 2, 2, sh, m, cc, rgb, 2, &err), SP_E_ARG, &err, "stride 2");
    CHECK_FAILS(sp_sh_to_rgb_backward(dev, 1, 1, 1, sh, m, cc, rgb, NULL, 3, sh, NULL, &err), SP_E_ARG,
                &err, "v_rgb");
    sp_device_free(dev);
}

int main(void)
{
    RUN(test_degrees);
    RUN(test_bad_args);
    return TEST_EXIT();
}
