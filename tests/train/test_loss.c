/* Training losses and Adam against independent references: a naive double-precision SSIM (2D
 * window, no separability), finite differences of that reference for the gradients, and Adam
 * steps computed by hand. */
#include "semsplat/train.h"
#include "test.h"
#include "train/train_internal.h"

/* Naive double reference of the RGB loss on [H][W][stride] (channels [0,C)) vs [H][W][C]. */
static void ref_loss(const double *x, int stride, const double *t, int H, int W, int C, double lambda,
                     double out[4])
{
    double g1[11], sum = 0;
    for (int i = 0; i < 11; i++) {
        g1[i] = exp(-(i - 5) * (i - 5) / (2 * 1.5 * 1.5));
        sum += g1[i];
    }
    for (int i = 0; i < 11; i++) g1[i] /= sum;
    double l1 = 0, mse = 0, ssim = 0;
    for (int y = 0; y < H; y++)
        for (int xx = 0; xx < W; xx++)
            for (int c = 0; c < C; c++) {
                double d = x[(y * W + xx) * stride + c] - t[(y * W + xx) * C + c];
                l1 += fabs(d);
                mse += d * d;
            }
    int n = 0;
    for (int oy = 0; oy + 11 <= H; oy++)
        for (int ox = 0; ox + 11 <= W; ox++)
            for (int c = 0; c < C; c++) {
                double mx = 0, my = 0, exx = 0, eyy = 0, exy = 0;
                for (int j = 0; j < 11; j++)
                    for (int i = 0; i < 11; i++) {
                        double w = g1[j] * g1[i];
                        double a = x[((oy + j) * W + ox + i) * stride + c], b = t[((oy + j) * W + ox + i) * C + c];
                        mx += w * a, my += w * b, exx += w * a * a, eyy += w * b * b, exy += w * a * b;
                    }
                double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
                double sxx = exx - mx * mx, syy = eyy - my * my, sxy = exy - mx * my;
                ssim += (2 * mx * my + c1) * (2 * sxy + c2) / ((mx * mx + my * my + c1) * (sxx + syy + c2));
                n++;
            }
    l1 /= (double)H * W * C;
    mse /= (double)H * W * C;
    ssim /= n;
    out[0] = (1 - lambda) * l1 + lambda * (1 - ssim);
    out[1] = l1;
    out[2] = ssim;
    out[3] = mse;
}

enum { H = 19, W = 23, C = 3, S = 4 };

static void make_images(test_rng *r, float *x, double *xd, float *t, double *td)
{
    for (int i = 0; i < H * W; i++) {
        for (int c = 0; c < C; c++) {
            /* a smooth-ish target plus noise so SSIM is neither 0 nor 1 */
            double base = 0.5 + 0.3 * sin(0.3 * (i % W) + c) * cos(0.2 * (i / W));
            td[i * C + c] = base + test_range(r, -0.05, 0.05);
            xd[i * S + c] = base + test_range(r, -0.2, 0.2);
        }
        xd[i * S + 3] = 7.0; /* an extra channel the loss must ignore */
    }
    for (int i = 0; i < H * W * C; i++) t[i] = (float)td[i];
    for (int i = 0; i < H * W * S; i++) x[i] = (float)xd[i];
}

static void test_value_and_gradient(double lambda)
{
    test_rng r = {12345 + (unsigned long long)(lambda * 100)};
    static float x[H * W * S], t[H * W * C], v[H * W * S];
    static double xd[H * W * S], td[H * W * C];
    make_images(&r, x, xd, t, td);
    for (int i = 0; i < H * W * S; i++) v[i] = -99.0f; /* untouched channels must stay */
    sp_error err = {0};
    double st[4], ref[4];
    CHECK_OK(sp_train_rgb_loss(NULL, x, S, t, H, W, C, (float)lambda, v, st, &err), &err);
    ref_loss(xd, S, td, H, W, C, lambda, ref);
    CHECK_NEAR(st[0], ref[0], 2e-6);
    CHECK_NEAR(st[1], ref[1], 1e-6);
    CHECK_NEAR(st[2], ref[2], 2e-6);
    CHECK_NEAR(st[3], ref[3], 1e-7);
    /* Central differences of the double reference at 40 random elements. */
    int bad = 0;
    double maxrel = 0;
    for (int k = 0; k < 40; k++) {
        int p = (int)(test_uniform(&r) * H * W), c = (int)(test_uniform(&r) * C);
        int idx = p * S + c;
        if (fabs(xd[idx] - td[p * C + c]) < 1e-3) continue; /* L1 kink */
        double h = 1e-6, lp[4], lm[4], keep = xd[idx];
        xd[idx] = keep + h;
        ref_loss(xd, S, td, H, W, C, lambda, lp);
        xd[idx] = keep - h;
        ref_loss(xd, S, td, H, W, C, lambda, lm);
        xd[idx] = keep;
        double fd = (lp[0] - lm[0]) / (2 * h), an = v[idx];
        double rel = fabs(fd - an) / (fabs(fd) + 1e-7);
        if (rel > maxrel) maxrel = rel;
        if (rel > 2e-3 && fabs(fd - an) > 1e-8) bad++;
    }
    CHECK_MSG(bad == 0, "lambda %.1f: %d gradients off, max rel err %g", lambda, bad, maxrel);
    for (int i = 0; i < H * W; i++) CHECK(v[i * S + 3] == -99.0f);
}

static void test_ssim_lambda1(void) { test_value_and_gradient(1.0); }
static void test_l1_only(void) { test_value_and_gradient(0.0); }
static void test_combined(void) { test_value_and_gradient(0.2); }

static void test_identical_images(void)
{
    static float x[H * W * C];
    test_rng r = {7};
    for (int i = 0; i < H * W * C; i++) x[i] = (float)test_uniform(&r);
    double st[4];
    sp_error err = {0};
    CHECK_OK(sp_train_rgb_loss(NULL, x, C, x, H, W, C, 0.2f, NULL, st, &err), &err);
    CHECK_NEAR(st[2], 1.0, 1e-5);
    CHECK_NEAR(st[0], 0.0, 1e-5);
    CHECK(st[3] == 0.0);
}

static void test_threaded_matches_serial(void)
{
    enum { h = 40, w = 37 };
    static float x[h * w * 3], t[h * w * 3], v1[h * w * 3], v2[h * w * 3];
    test_rng r = {99};
    for (int i = 0; i < h * w * 3; i++) x[i] = (float)test_uniform(&r), t[i] = (float)test_uniform(&r);
    sp_pool *pool = NULL;
    sp_error err = {0};
    CHECK_OK(sp_pool_create(&pool, 2, &err), &err);
    double s1[4], s2[4];
    CHECK_OK(sp_train_rgb_loss(NULL, x, 3, t, h, w, 3, 0.2f, v1, s1, &err), &err);
    CHECK_OK(sp_train_rgb_loss(pool, x, 3, t, h, w, 3, 0.2f, v2, s2, &err), &err);
    CHECK(memcmp(v1, v2, sizeof v1) == 0);
    CHECK(s1[0] == s2[0]);
    sp_pool_free(pool);
}

static void test_bad_sizes(void)
{
    float x[10 * 10 * 3] = {0};
    double st[4];
    sp_error err = {0};
    CHECK_FAILS(sp_train_rgb_loss(NULL, x, 3, x, 10, 10, 3, 0.2f, NULL, st, &err), SP_E_ARG, &err, "10x10");
    CHECK_FAILS(sp_train_rgb_loss(NULL, x, 2, x, 11, 11, 3, 0.2f, NULL, st, &err), SP_E_ARG, &err, "channels");
}

static void test_feature_mse(void)
{
    enum { h = 5, w = 4, F = 3, D = 6 };
    float p[h * w * D], t[h * w * F], v[h * w * D];
    test_rng r = {5};
    for (int i = 0; i < h * w * D; i++) p[i] = (float)test_range(&r, -1, 1), v[i] = 42;
    for (int i = 0; i < h * w * F; i++) t[i] = (float)test_range(&r, -1, 1);
    double mse = 0, ref = 0;
    sp_error err = {0};
    CHECK_OK(cpu_feature_mse(NULL, p, D, 3, t, h, w, F, 0.5f, v, &mse, &err), &err);
    for (int i = 0; i < h * w; i++)
        for (int f = 0; f < F; f++) {
            double d = (double)p[i * D + 3 + f] - t[i * F + f];
            ref += d * d;
            /* d/dp of 0.5 * mean(d^2) = 0.5 * 2 d / N */
            CHECK_NEAR(v[i * D + 3 + f], 0.5 * 2 * d / (h * w * F), 1e-7);
            CHECK(v[i * D + f] == 42);
        }
    CHECK_NEAR(mse, ref / (h * w * F), 1e-6);
    CHECK_FAILS(cpu_feature_mse(NULL, p, D, 4, t, h, w, F, 0.5f, v, &mse, &err), SP_E_ARG, &err, "stride");
}

static void test_adam_by_hand(void)
{
    float p[2] = {1.0f, -2.0f}, m[2] = {0, 0}, v[2] = {0, 0};
    float g1[2] = {0.5f, -0.1f}, g2[2] = {-0.2f, 0.3f};
    /* the reference uses the float-rounded hyper-parameters the kernel sees */
    double lr = 0.01, b1 = (double)0.9f, b2 = (double)0.999f, eps = 1e-8;
    sp_train_adam_host(p, g1, m, v, 2, (float)lr, (float)b1, (float)b2, (float)eps, 1);
    sp_train_adam_host(p, g2, m, v, 2, (float)lr, (float)b1, (float)b2, (float)eps, 2);
    double pe[2] = {1.0, -2.0};
    double ga[2][2] = {{0.5, -0.1}, {-0.2, 0.3}};
    for (int i = 0; i < 2; i++) {
        double mm = 0, vv = 0;
        for (int s = 1; s <= 2; s++) {
            double g = ga[s - 1][i];
            mm = b1 * mm + (1 - b1) * g;
            vv = b2 * vv + (1 - b2) * g * g;
            pe[i] -= lr * (mm / (1 - pow(b1, s))) / (sqrt(vv / (1 - pow(b2, s))) + eps);
        }
        CHECK_NEAR(p[i], pe[i], 1e-6);
        CHECK_NEAR(m[i], mm, 1e-7);
        CHECK_NEAR(v[i], vv, 1e-5 * vv);
    }
}

static void test_densify_accumulate(void)
{
    float g[6] = {0.001f, 0.002f, 5, 5, -0.003f, 0.0f};
    int32_t radii[3] = {2, 0, 1};
    float sum[3] = {0, 0, 0}, cnt[3] = {0, 0, 0};
    cpu_densify_accumulate(g, radii, 3, 160, 120, sum, cnt);
    CHECK_NEAR(sum[0], sqrt(0.16 * 0.16 + 0.24 * 0.24), 1e-6);
    CHECK(sum[1] == 0 && cnt[1] == 0);
    CHECK_NEAR(sum[2], 0.48, 1e-6);
    CHECK(cnt[0] == 1 && cnt[2] == 1);
}

int main(void)
{
    RUN(test_ssim_lambda1);
    RUN(test_l1_only);
    RUN(test_combined);
    RUN(test_identical_images);
    RUN(test_threaded_matches_serial);
    RUN(test_bad_sizes);
    RUN(test_feature_mse);
    RUN(test_adam_by_hand);
    RUN(test_densify_accumulate);
    return TEST_EXIT();
}
