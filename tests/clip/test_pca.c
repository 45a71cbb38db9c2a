/* PCA: orthonormal basis, eigen-equation residual against a double covariance computed here,
 * decreasing variance, sign convention, exact recovery of data lying in a low-dim subspace, and the
 * label embeddings' determinism and normalisation. */
#include "semsplat/clip.h"
#include "test.h"

static void test_pca(void)
{
    enum { N = 3000, F = 40, D = 8 };
    test_rng rng = {7};
    float *x = malloc(sizeof(float) * N * F);
    /* anisotropic Gaussian-ish data: coordinate j scaled by 1/(1+j), then mixed by a rotation */
    for (int i = 0; i < N; i++)
        for (int j = 0; j < F; j++) x[i * F + j] = (float)((test_uniform(&rng) - 0.5) * 4.0 / (1 + j) + 0.1 * j);
    float mean[F], basis[D * F];
    sp_error err = {0};
    CHECK_OK(sp_clip_pca_fit(x, N, F, D, mean, basis, &err), &err);
    double m[F] = {0}, C[F][F] = {{0}};
    for (int i = 0; i < N; i++) for (int j = 0; j < F; j++) m[j] += x[i * F + j] / (double)N;
    for (int i = 0; i < N; i++)
        for (int a = 0; a < F; a++)
            for (int b = 0; b < F; b++) C[a][b] += (x[i * F + a] - m[a]) * (x[i * F + b] - m[b]) / N;
    for (int j = 0; j < F; j++) CHECK_NEAR(mean[j], m[j], 1e-5);
    double prev = 1e30;
    for (int r = 0; r < D; r++) {
        const float *v = basis + r * F;
        double lam = 0, res = 0, big = 0;
        for (int a = 0; a < F; a++) for (int b = 0; b < F; b++) lam += v[a] * C[a][b] * v[b];
        for (int a = 0; a < F; a++) {
            double cv = 0;
            for (int b = 0; b < F; b++) cv += C[a][b] * v[b];
            res = fmax(res, fabs(cv - lam * v[a]));
            if (fabs(v[a]) > fabs(big)) big = v[a];
        }
        CHECK_MSG(res < 1e-5, "row %d eigen residual %g", r, res);
        CHECK(lam <= prev + 1e-9);
        CHECK(big > 0);
        prev = lam;
        for (int s = 0; s <= r; s++) {
            double d = 0;
            for (int a = 0; a < F; a++) d += v[a] * basis[s * F + a];
            CHECK_NEAR(d, r == s ? 1 : 0, 1e-5);
        }
    }
    free(x);
    CHECK_FAILS(sp_clip_pca_fit(mean, 1, F, F + 1, mean, basis, &err), SP_E_ARG, &err, "PCA");
}

static void test_subspace(void)
{
    /* 5 distinct unit vectors in 64-D: PCA to 16 reconstructs each exactly */
    enum { F = 64, D = 16, K = 5, N = 500 };
    float cls[K][F], *x = malloc(sizeof(float) * N * F), mean[F], basis[D * F];
    const char *names[K] = {"chair", "table", "refrigerator", "sofa", "wall"};
    for (int k = 0; k < K; k++) sp_label_embedding(names[k], F, cls[k]);
    for (int i = 0; i < N; i++) memcpy(x + i * F, cls[i % K], sizeof cls[0]);
    sp_error err = {0};
    CHECK_OK(sp_clip_pca_fit(x, N, F, D, mean, basis, &err), &err);
    sp_features f = {0};
    f.dim = D;
    f.full_dim = F;
    f.pca_mean = mean;
    f.pca_basis = basis;
    for (int k = 0; k < K; k++) {
        float e[D], back[F];
        sp_features_encode(&f, cls[k], e);
        sp_features_decode(&f, e, back);
        for (int j = 0; j < F; j++) CHECK_NEAR(back[j], cls[k][j], 1e-5);
    }
    free(x);
}

static void test_label_embedding(void)
{
    float a[512], b[512], c[512];
    sp_label_embedding("Dining Chair", 512, a);
    sp_label_embedding("  dining   chair\n", 512, b);
    sp_label_embedding("chair", 512, c);
    double n = 0, d = 0, ac = 0;
    for (int i = 0; i < 512; i++) { n += a[i] * a[i]; d += fabs(a[i] - b[i]); ac += a[i] * c[i]; }
    CHECK_NEAR(n, 1.0, 1e-5);
    CHECK(d == 0);
    CHECK(fabs(ac) < 0.2); /* different classes: nearly orthogonal in 512-D */
    /* pinned values so the embedding never changes silently between versions */
    CHECK_NEAR(c[0], 0.0424331, 2e-7);
    CHECK_NEAR(c[1], 0.0147367, 2e-7);
    CHECK_NEAR(c[2], 0.0855709, 2e-7);
}

int main(void)
{
    RUN(test_pca);
    RUN(test_subspace);
    RUN(test_label_embedding);
    return TEST_EXIT();
}
