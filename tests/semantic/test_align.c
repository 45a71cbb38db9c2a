/* Frames: Umeyama similarity recovery, splat transforms (means, orientations, scales and every SH
 * band: the view-dependent colour must move with the world), floor-plane detection. */
#include <math.h>
#include <stdlib.h>

#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "test.h"
#include "semantic/matches.h"

/* The 3DGS real SH (degree 3) evaluated in double: an independent reference for band rotation. */
static double sh_eval(const float *sh, int ch, const double d[3])
{
    const double C0 = 0.28209479177387814, C1 = 0.4886025119029199;
    const double C2[5] = {1.0925484305920792, -1.0925484305920792, 0.31539156525252005,
                          -1.0925484305920792, 0.5462742152960396};
    const double C3[7] = {-0.5900435899266435, 2.890611442640554, -0.4570457994644658,
                          0.3731763325901154, -0.4570457994644658, 1.445305721320277,
                          -0.5900435899266435};
    double x = d[0], y = d[1], z = d[2], xx = x * x, yy = y * y, zz = z * z;
    double b[16] = {C0, -C1 * y, C1 * z, -C1 * x,
                    C2[0] * x * y, C2[1] * y * z, C2[2] * (2 * zz - xx - yy), C2[3] * x * z,
                    C2[4] * (xx - yy),
                    C3[0] * y * (3 * xx - yy), C3[1] * x * y * z, C3[2] * y * (4 * zz - xx - yy),
                    C3[3] * z * (2 * zz - 3 * xx - 3 * yy), C3[4] * x * (4 * zz - xx - yy),
                    C3[5] * z * (xx - yy), C3[6] * x * (xx - 3 * yy)};
    double v = 0;
    for (int k = 0; k < 16; k++) v += b[k] * sh[k * 3 + ch];
    return v;
}

static void test_umeyama_recovers_similarity(void)
{
    test_rng r = {42};
    double M[16], s, src[10 * 3], dst[10 * 3], F[16], rms = 1;
    random_similarity(&r, M, &s);
    for (int i = 0; i < 10; i++) {
        for (int a = 0; a < 3; a++) src[3 * i + a] = test_range(&r, -3, 3);
        apply(M, src + 3 * i, dst + 3 * i);
    }
    sp_error err = {0};
    CHECK_OK(sp_umeyama(src, dst, 10, 1, F, &rms, &err), &err);
    double worst = 0;
    for (int k = 0; k < 16; k++) worst = fmax(worst, fabs(F[k] - M[k]));
    CHECK_NEAR(worst, 0, 1e-6);
    CHECK_NEAR(rms, 0, 1e-6);
    /* exactly 3 points suffice; noise gives a small rms */
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 3; a++) dst[3 * i + a] += test_range(&r, -0.01, 0.01);
    CHECK_OK(sp_umeyama(src, dst, 3, 1, F, &rms, &err), &err);
    CHECK(rms < 0.02);
}

static void test_umeyama_bad_input(void)
{
    double src[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2}, dst[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, M[16];
    sp_error err = {0};
    CHECK_FAILS(sp_umeyama(src, dst, 2, 1, M, NULL, &err), SP_E_ARG, &err, "at least 3");
    CHECK_FAILS(sp_umeyama(src, dst, 3, 1, M, NULL, &err), SP_E_ARG, &err, "collinear");
}

static void test_transform_splat_and_sh(void)
{
    test_rng r = {7};
    sp_splat s;
    sp_error err = {0};
    CHECK_OK(sp_splat_alloc(&s, 20, 3, 2, &err), &err);
    for (size_t i = 0; i < s.n * 3; i++) s.means[i] = (float)test_range(&r, -2, 2);
    for (size_t i = 0; i < s.n * 4; i++) s.quats[i] = (float)test_range(&r, -1, 1);
    for (size_t i = 0; i < s.n * 3; i++) s.log_scales[i] = (float)test_range(&r, -4, -1);
    for (size_t i = 0; i < s.n * 16 * 3; i++) s.sh[i] = (float)test_range(&r, -0.5, 0.5);
    for (size_t i = 0; i < s.n * 2; i++) s.features[i] = (float)i;
    sp_splat o;
    CHECK_OK(sp_splat_copy(&o, &s, &err), &err);
    double M[16], sc;
    random_similarity(&r, M, &sc);
    CHECK_OK(sp_splat_transform(&s, M, &err), &err);
    double worst_mean = 0, worst_sh = 0, worst_rot = 0;
    double R[9];
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) R[a * 3 + b] = M[a * 4 + b] / sc;
    for (size_t i = 0; i < s.n; i++) {
        double p[3] = {o.means[3 * i], o.means[3 * i + 1], o.means[3 * i + 2]}, q[3];
        apply(M, p, q);
        for (int a = 0; a < 3; a++) worst_mean = fmax(worst_mean, fabs(q[a] - s.means[3 * i + a]));
        CHECK_NEAR(s.log_scales[3 * i], o.log_scales[3 * i] + log(sc), 1e-5);
        /* orientation: R_new = R * R_old */
        float Ro[9], Rn[9];
        sp_quat_to_mat3(o.quats + 4 * i, Ro);
        sp_quat_to_mat3(s.quats + 4 * i, Rn);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                double v = 0;
                for (int k = 0; k < 3; k++) v += R[a * 3 + k] * Ro[k * 3 + b];
                worst_rot = fmax(worst_rot, fabs(v - Rn[a * 3 + b]));
            }
        /* colour seen along d before == colour seen along R d after */
        for (int t = 0; t < 8; t++) {
            double d[3], n = 0;
            for (int a = 0; a < 3; a++) d[a] = test_range(&r, -1, 1), n += d[a] * d[a];
            for (int a = 0; a < 3; a++) d[a] /= sqrt(n);
            double rd[3] = {R[0] * d[0] + R[1] * d[1] + R[2] * d[2], R[3] * d[0] + R[4] * d[1] + R[5] * d[2],
                            R[6] * d[0] + R[7] * d[1] + R[8] * d[2]};
            for (int ch = 0; ch < 3; ch++)
                worst_sh = fmax(worst_sh, fabs(sh_eval(o.sh + i * 48, ch, d) - sh_eval(s.sh + i * 48, ch, rd)));
        }
        CHECK(s.features[2 * i] == o.features[2 * i]);
    }
    CHECK_NEAR(worst_mean, 0, 1e-4);
    CHECK_NEAR(worst_rot, 0, 1e-4);
    CHECK_NEAR(worst_sh, 0, 1e-4);
    double bad[16] = {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    CHECK_FAILS(sp_splat_transform(&s, bad, &err), SP_E_ARG, &err, "similarity");
    double mirror[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    CHECK_FAILS(sp_splat_transform(&s, mirror, &err), SP_E_ARG, &err, "determinant");
    sp_splat_free(&s);
    sp_splat_free(&o);
}

/* The robust fit names exactly the planted misregistrations (5 of 49, as the reviewed COLMAP run
 * had) and recovers the similarity from the rest, where plain least squares is pulled off by
 * metres; over many seeds and outlier sets. */
static void test_robust_fit_names_outliers(void)
{
    sp_error err = {0};
    double worst_rms = 0, worst_M = 0, min_ls = 1e9;
    for (int trial = 0; trial < 20; trial++) {
        test_rng r = {1000 + (unsigned long long)trial};
        enum { N = 49, NB = 5 };
        int bad[NB];
        for (int k = 0; k < NB; k++) {
            int dup;
            do {
                bad[k] = (int)(test_uniform(&r) * N);
                dup = 0;
                for (int q = 0; q < k; q++) dup |= bad[q] == bad[k];
            } while (dup);
        }
        double src[N * 3], dst[N * 3], M[16];
        planted_matches(&r, N, bad, NB, 0.03, src, dst, M);
        sp_align_fit fit;
        CHECK_OK(sp_align_fit_robust(src, dst, N, 1, 0, &fit, &err), &err);
        if (!fit.inlier) continue;
        int wrong = 0;
        for (int i = 0; i < N; i++) {
            int is_bad = 0;
            for (int k = 0; k < NB; k++) is_bad |= bad[k] == i;
            wrong += fit.inlier[i] == is_bad;
        }
        CHECK_MSG(wrong == 0 && fit.n_inliers == N - NB, "trial %d: %d matches misjudged (%zu inliers)", trial,
                  wrong, fit.n_inliers);
        /* the fit: world positions of the inliers within the noise; the transform near the truth */
        double dm = 0;
        for (int k = 0; k < 12; k++) dm = fmax(dm, fabs(fit.M[k] - M[k]) / (k % 4 == 3 ? 1.0 : 1.0));
        worst_M = fmax(worst_M, dm);
        worst_rms = fmax(worst_rms, fit.rms_inliers);
        min_ls = fmin(min_ls, fit.rms_all);
        sp_align_fit_free(&fit);
    }
    fprintf(stderr, "  5 of 49 misregistered: inlier rms <= %.4f m, |M - M_true| <= %.4f; plain least squares "
                    "rms >= %.3f m\n", worst_rms, worst_M, min_ls);
    CHECK(worst_rms < 0.035);     /* uniform +-0.03 per axis: rms 0.03 m */
    CHECK(worst_M < 0.05);
    CHECK(min_ls > 0.2);          /* what the old plain fit would have reported */
}

/* Too few agreeing matches is a refusal naming the counts; fewer than 4 matches cannot be fit
 * robustly at all; an explicit bound is used as given. */
static void test_robust_fit_refuses(void)
{
    sp_error err = {0};
    test_rng r = {77};
    enum { N = 20 };
    int bad[11] = {0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 19};
    double src[N * 3], dst[N * 3], M[16];
    planted_matches(&r, N, bad, 11, 0.01, src, dst, M);
    sp_align_fit fit;
    CHECK_FAILS(sp_align_fit_robust(src, dst, N, 1, 0, &fit, &err), SP_E_FORMAT, &err, "do not agree");
    CHECK(fit.inlier != NULL);
    sp_align_fit_free(&fit);
    /* with an explicit bound, the majority rule */
    CHECK_FAILS(sp_align_fit_robust(src, dst, N, 1, 0.05, &fit, &err), SP_E_FORMAT, &err, "of 20 matches agree");
    CHECK(strstr(err.msg, "need at least 10") != NULL);
    CHECK(fit.inlier != NULL && fit.n_inliers < 10);
    sp_align_fit_free(&fit);
    CHECK_FAILS(sp_align_fit_robust(src, dst, 3, 1, 0, &fit, &err), SP_E_ARG, &err, "at least 4");
    /* 9 bad of 20: accepted, the 9 named */
    planted_matches(&r, N, bad, 9, 0.01, src, dst, M);
    CHECK_OK(sp_align_fit_robust(src, dst, N, 1, 0, &fit, &err), &err);
    CHECK(fit.n_inliers == N - 9);
    for (int k = 0; k < 9 && fit.inlier; k++) CHECK(!fit.inlier[bad[k]]);
    sp_align_fit_free(&fit);
    /* a given bound: 10 m takes everything in */
    CHECK_OK(sp_align_fit_robust(src, dst, N, 1, 10.0, &fit, &err), &err);
    CHECK(fit.n_inliers == N && fit.threshold == 10.0);
    sp_align_fit_free(&fit);
}

/* Image-name matches read against a COLMAP model; the JSON names the outlying images. */
static void test_matches_file_and_json(void)
{
    const char *dir = test_tmpdir("align_matches");
    test_rng r = {9};
    enum { N = 12 };
    int bad[1] = {7};
    double src[N * 3], dst[N * 3], M[16];
    planted_matches(&r, N, bad, 1, 0.005, src, dst, M);
    char model[1200], path[1300];
    snprintf(model, sizeof model, "%s/sparse", dir);
    snprintf(path, sizeof path, "%s/matches.txt", dir);
    sp_error err = {0};
    CHECK_OK(write_centres(model, path, src, dst, N, &err), &err);
    sp_align_matches mt;
    CHECK_OK(sp_align_read_matches(path, model, &mt, &err), &err);
    CHECK(mt.n == N && !strcmp(mt.name[3], "img_03.png"));
    CHECK_NEAR(mt.src[3 * 5 + 1], src[3 * 5 + 1], 1e-5);
    sp_align_fit fit;
    CHECK_OK(sp_align_fit_robust(mt.src, mt.dst, mt.n, 1, 0, &fit, &err), &err);
    char *js = sp_align_fit_json(&fit, &mt, 1);
    CHECK(js != NULL);
    if (js) {
        CHECK_MSG(strstr(js, "\"img_07.png\"") != NULL && !strstr(js, "\"img_06.png\""), "%s", js);
        CHECK(strstr(js, "\"inliers\":\t11") != NULL);
        free(js);
    }
    sp_align_fit_free(&fit);
    sp_align_matches_free(&mt);
    /* an unknown image is named with its line */
    FILE *f = fopen(path, "a");
    fprintf(f, "nope.png 1 2 3\n");
    fclose(f);
    CHECK_FAILS(sp_align_read_matches(path, model, &mt, &err), SP_E_NOTFOUND, &err, "matches.txt:14: image 'nope.png'");
}

static void test_floor_detection(void)
{
    /* a y-down (COLMAP-like) scene: floor on the plane y = 1.2 tilted by 10 degrees about x,
     * clutter above it (smaller y), cameras at y ~ 0 looking along +z with y pointing down */
    test_rng r = {99};
    sp_splat s;
    sp_error err = {0};
    CHECK_OK(sp_splat_alloc(&s, 3000, 0, 0, &err), &err);
    double th = 10 * M_PI / 180;
    double n_true[3] = {0, -cos(th), sin(th)}; /* up in this frame: -y, tilted */
    for (size_t i = 0; i < s.n; i++) {
        float *m = s.means + 3 * i;
        double u = test_range(&r, -4, 4), v = test_range(&r, -4, 4);
        /* on the plane through (0, 1.2, 0) spanned by e1, e2; clutter 0.2..2 above it */
        double e1[3] = {1, 0, 0}, e2[3] = {0, sin(th), cos(th)};
        double h = i < 2000 ? 0 : test_range(&r, 0.2, 2.0);
        for (int a = 0; a < 3; a++)
            m[a] = (float)(u * e1[a] + v * e2[a] + (a == 1 ? 1.2 : 0) + h * n_true[a]);
        s.opacity_logits[i] = 3;
    }
    sp_camera cams[4];
    for (int c = 0; c < 4; c++) {
        sp_camera_look_at(&cams[c], sp_v3((float)c - 1.5f, -0.3f, -3), sp_v3((float)c - 1.5f, -0.3f, 1),
                          sp_v3(0, -1, 0));
        cams[c].width = 64, cams[c].height = 48, cams[c].fx = cams[c].fy = 50, cams[c].cx = 32, cams[c].cy = 24;
    }
    double M[16], n[3], inl = 0;
    CHECK_OK(sp_detect_floor(&s, cams, 4, M, n, &inl, &err), &err);
    double dot = n[0] * n_true[0] + n[1] * n_true[1] + n[2] * n_true[2];
    CHECK_NEAR(dot, 1, 1e-3);
    CHECK(inl > 0.5);
    CHECK_OK(sp_splat_transform(&s, M, &err), &err);
    double worst = 0;
    for (size_t i = 0; i < 2000; i++) worst = fmax(worst, fabs(s.means[3 * i + 2]));
    CHECK_NEAR(worst, 0, 1e-3);
    int above = 1;
    for (size_t i = 2000; i < s.n; i++) above &= s.means[3 * i + 2] > 0.1f;
    CHECK(above);
    sp_splat_free(&s);
    sp_splat tiny;
    CHECK_OK(sp_splat_alloc(&tiny, 3, 0, 0, &err), &err);
    CHECK_FAILS(sp_detect_floor(&tiny, NULL, 0, M, n, &inl, &err), SP_E_ARG, &err, "too few");
    sp_splat_free(&tiny);
}

int main(void)
{
    RUN(test_umeyama_recovers_similarity);
    RUN(test_umeyama_bad_input);
    RUN(test_transform_splat_and_sh);
    RUN(test_floor_detection);
    RUN(test_robust_fit_names_outliers);
    RUN(test_robust_fit_refuses);
    RUN(test_matches_file_and_json);
    return TEST_EXIT();
}
