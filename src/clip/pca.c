/* Scene PCA for feature maps: mean and covariance of sampled pixel features (the product through
 * OpenBLAS), eigenvectors by Householder tridiagonalisation + implicit QL in double (no LAPACKE
 * on Debian's OpenBLAS), top `dim` rows kept with a deterministic sign. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cblas.h>

#include "clip_internal.h"

/* Householder reduction of symmetric a [n][n] to tridiagonal form (d diagonal, e off-diagonal),
 * a replaced by the orthogonal transform (tred2, Numerical Recipes 11.2, 0-based). */
static void tred2(double *a, int n, double *d, double *e)
{
#define A(i, j) a[(size_t)(i) * n + (j)]
    for (int i = n - 1; i > 0; i--) {
        int l = i - 1;
        double h = 0, scale = 0;
        if (l > 0) {
            for (int k = 0; k <= l; k++) scale += fabs(A(i, k));
            if (scale == 0) {
                e[i] = A(i, l);
            } else {
                for (int k = 0; k <= l; k++) {
                    A(i, k) /= scale;
                    h += A(i, k) * A(i, k);
                }
                double f = A(i, l), g = f >= 0 ? -sqrt(h) : sqrt(h);
                e[i] = scale * g;
                h -= f * g;
                A(i, l) = f - g;
                f = 0;
                for (int j = 0; j <= l; j++) {
                    A(j, i) = A(i, j) / h;
                    g = 0;
                    for (int k = 0; k <= j; k++) g += A(j, k) * A(i, k);
                    for (int k = j + 1; k <= l; k++) g += A(k, j) * A(i, k);
                    e[j] = g / h;
                    f += e[j] * A(i, j);
                }
                double hh = f / (h + h);
                for (int j = 0; j <= l; j++) {
                    f = A(i, j);
                    e[j] = g = e[j] - hh * f;
                    for (int k = 0; k <= j; k++) A(j, k) -= f * e[k] + g * A(i, k);
                }
            }
        } else {
            e[i] = A(i, l);
        }
        d[i] = h;
    }
    d[0] = 0;
    e[0] = 0;
    for (int i = 0; i < n; i++) {
        int l = i - 1;
        if (d[i] != 0) {
            for (int j = 0; j <= l; j++) {
                double g = 0;
                for (int k = 0; k <= l; k++) g += A(i, k) * A(k, j);
                for (int k = 0; k <= l; k++) A(k, j) -= g * A(k, i);
            }
        }
        d[i] = A(i, i);
        A(i, i) = 1;
        for (int j = 0; j <= l; j++) A(j, i) = A(i, j) = 0;
    }
#undef A
}

/* Implicit QL on the tridiagonal (d, e); zt holds the transform TRANSPOSED (rows = vectors), so
 * on return row i of zt is the eigenvector of d[i] (tqli, Numerical Recipes 11.3, 0-based). */
static int tqli(double *d, double *e, int n, double *zt)
{
    for (int i = 1; i < n; i++) e[i - 1] = e[i];
    e[n - 1] = 0;
    for (int l = 0; l < n; l++) {
        int iter = 0, m;
        do {
            for (m = l; m < n - 1; m++) {
                double dd = fabs(d[m]) + fabs(d[m + 1]);
                if (fabs(e[m]) <= 1e-15 * dd) break;
            }
            if (m != l) {
                if (iter++ == 100) return -1;
                double g = (d[l + 1] - d[l]) / (2 * e[l]), r = hypot(g, 1.0);
                g = d[m] - d[l] + e[l] / (g + (g >= 0 ? fabs(r) : -fabs(r)));
                double s = 1, c = 1, p = 0;
                int i;
                for (i = m - 1; i >= l; i--) {
                    double f = s * e[i], b = c * e[i];
                    e[i + 1] = (r = hypot(f, g));
                    if (r == 0) {
                        d[i + 1] -= p;
                        e[m] = 0;
                        break;
                    }
                    s = f / r;
                    c = g / r;
                    g = d[i + 1] - p;
                    r = (d[i] - g) * s + 2 * c * b;
                    d[i + 1] = g + (p = s * r);
                    g = c * r - b;
                    double *zi = zt + (size_t)i * n, *zi1 = zt + (size_t)(i + 1) * n;
                    for (int k = 0; k < n; k++) {
                        f = zi1[k];
                        zi1[k] = s * zi[k] + c * f;
                        zi[k] = c * zi[k] - s * f;
                    }
                }
                if (r == 0 && i >= l) continue;
                d[l] -= p;
                e[l] = g;
                e[m] = 0;
            }
        } while (m != l);
    }
    return 0;
}

/* Eigen-decomposition of symmetric A [n][n] (destroyed): eigenvalues w, eigenvector i in row i
 * of Vt. */
static int sym_eigen(double *A, int n, double *w, double *Vt)
{
    double *e = malloc((size_t)n * sizeof *e);
    if (!e) return -1;
    tred2(A, n, w, e);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) Vt[(size_t)j * n + i] = A[(size_t)i * n + j];
    int rc = tqli(w, e, n, Vt);
    free(e);
    return rc;
}

/* C = (x - m)^T (x - m), accumulated chunk by chunk in float; on the GPU when dev is a CUDA
 * device and the product is large (falls back to the CPU if the GPU cannot run it). */
static int covariance(sp_device *dev, const float *x, size_t n, int F, const double *m, float *C, sp_error *err)
{
    if (dev && sp_device_kind_of(dev) == SP_DEVICE_CUDA && (double)n * F * F >= 1e9) {
        float *mf = malloc((size_t)F * sizeof *mf);
        sp_error e2 = {0};
        int ok = mf != NULL;
        for (int j = 0; ok && j < F; j++) mf[j] = (float)m[j];
        ok = ok && !clip_gpu_gram(dev, x, n, F, mf, C, &e2);
        free(mf);
        if (ok) return 0;
    }
    size_t chunk = 4096;
    float *xc = malloc(chunk * F * sizeof *xc);
    if (!xc) return sp_error_set(err, SP_E_NOMEM, "PCA: out of memory for %d dims", F);
    memset(C, 0, (size_t)F * F * sizeof *C);
    for (size_t i0 = 0; i0 < n; i0 += chunk) {
        size_t nb = n - i0 < chunk ? n - i0 : chunk;
        for (size_t i = 0; i < nb; i++)
            for (int j = 0; j < F; j++) xc[i * F + j] = (float)(x[(i0 + i) * F + j] - m[j]);
        cblas_sgemm(CblasRowMajor, CblasTrans, CblasNoTrans, F, F, (int)nb, 1.f, xc, F, xc, F, 1.f, C, F);
    }
    free(xc);
    return 0;
}

int sp_clip_pca_fit(const float *x, size_t n, int full_dim, int dim, float *mean, float *basis, sp_error *err)
{
    return clip_pca_fit_dev(NULL, x, n, full_dim, dim, mean, basis, err);
}

int clip_pca_fit_dev(sp_device *dev, const float *x, size_t n, int full_dim, int dim, float *mean, float *basis,
                     sp_error *err)
{
    int F = full_dim;
    if (n < 1 || F < 1 || dim < 1 || dim > F)
        return sp_error_set(err, SP_E_ARG, "PCA: %zu samples of %d dims to %d dims", n, F, dim);
    double *m = calloc((size_t)F, sizeof *m), *A = malloc((size_t)F * F * sizeof *A);
    double *V = malloc((size_t)F * F * sizeof *V), *w = malloc((size_t)F * sizeof *w);
    float *C = malloc((size_t)F * F * sizeof *C);
    int *order = malloc((size_t)F * sizeof *order);
    int rc = 0;
    if (!m || !A || !V || !w || !C || !order) {
        rc = sp_error_set(err, SP_E_NOMEM, "PCA: out of memory for %d dims", F);
        goto done;
    }
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < F; j++) {
            float v = x[i * F + j];
            if (!isfinite(v)) {
                rc = sp_error_set(err, SP_E_NUMERIC, "PCA: sample %zu dim %d is %g", i, j, v);
                goto done;
            }
            m[j] += v;
        }
    for (int j = 0; j < F; j++) m[j] /= (double)n;
    if ((rc = covariance(dev, x, n, F, m, C, err))) goto done;
    for (size_t i = 0; i < (size_t)F * F; i++) A[i] = C[i] / (double)n;
    for (int i = 0; i < F; i++) /* exact symmetry */
        for (int j = i + 1; j < F; j++) A[(size_t)i * F + j] = A[(size_t)j * F + i] = 0.5 * (A[(size_t)i * F + j] + A[(size_t)j * F + i]);
    if (sym_eigen(A, F, w, V)) {
        rc = sp_error_set(err, SP_E_NUMERIC, "PCA: eigen-solver did not converge (%d dims)", F);
        goto done;
    }
    for (int i = 0; i < F; i++) order[i] = i;
    for (int i = 1; i < F; i++) { /* insertion sort by decreasing eigenvalue, stable */
        int k = order[i], j = i;
        while (j > 0 && w[order[j - 1]] < w[k]) { order[j] = order[j - 1]; j--; }
        order[j] = k;
    }
    for (int j = 0; j < F; j++) mean[j] = (float)m[j];
    for (int r = 0; r < dim; r++) {
        int col = order[r], big = 0;
        for (int j = 1; j < F; j++)
            if (fabs(V[(size_t)col * F + j]) > fabs(V[(size_t)col * F + big]) + 1e-12) big = j;
        double sgn = V[(size_t)col * F + big] < 0 ? -1 : 1;
        for (int j = 0; j < F; j++) basis[(size_t)r * F + j] = (float)(sgn * V[(size_t)col * F + j]);
    }
done:
    free(m); free(A); free(V); free(w); free(C); free(order);
    return rc;
}
