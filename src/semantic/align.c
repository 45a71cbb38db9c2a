/* Frames (semsplat align): a COLMAP-frame splat is put into the robot's world (odometry) frame by
 * a similarity fitted to known camera positions (Umeyama 1991, solved with Horn's quaternion
 * method so the result is always a proper rotation), or by a floor plane found with RANSAC on the
 * lowest Gaussians for scenes that are not z-up. Transforming a splat rotates means, quaternions
 * and every SH band (band rotation matrices fitted by least squares on sample directions: each
 * band is closed under rotation, so the fit is exact up to rounding). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/semantic.h"

/* Cyclic Jacobi eigen-decomposition of a symmetric n x n matrix (n <= 4): A is destroyed,
 * eigenvalues in w, eigenvectors in the columns of V. */
static void jacobi(double *A, int n, double *w, double *V)
{
    for (int i = 0; i < n * n; i++) V[i] = (i / n == i % n);
    for (int sweep = 0; sweep < 60; sweep++) {
        double off = 0;
        for (int p = 0; p < n; p++)
            for (int q = p + 1; q < n; q++) off += A[p * n + q] * A[p * n + q];
        if (off < 1e-30) break;
        for (int p = 0; p < n; p++)
            for (int q = p + 1; q < n; q++) {
                double apq = A[p * n + q];
                if (fabs(apq) < 1e-300) continue;
                double theta = (A[q * n + q] - A[p * n + p]) / (2 * apq);
                double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < n; k++) {
                    double akp = A[k * n + p], akq = A[k * n + q];
                    A[k * n + p] = c * akp - s * akq;
                    A[k * n + q] = s * akp + c * akq;
                }
                for (int k = 0; k < n; k++) {
                    double apk = A[p * n + k], aqk = A[q * n + k];
                    A[p * n + k] = c * apk - s * aqk;
                    A[q * n + k] = s * apk + c * aqk;
                }
                for (int k = 0; k < n; k++) {
                    double vkp = V[k * n + p], vkq = V[k * n + q];
                    V[k * n + p] = c * vkp - s * vkq;
                    V[k * n + q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < n; i++) w[i] = A[i * n + i];
}

static void quat_to_R(const double q[4], double R[9])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z); R[1] = 2 * (x * y - w * z);     R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z);     R[4] = 1 - 2 * (x * x + z * z); R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y);     R[7] = 2 * (y * z + w * x);     R[8] = 1 - 2 * (x * x + y * y);
}

int sp_umeyama(const double *src, const double *dst, size_t n, int with_scale, double M[16],
               double *rms, sp_error *err)
{
    if (n < 3) return sp_error_set(err, SP_E_ARG, "align: %zu point pairs (need at least 3)", n);
    double ms[3] = {0}, md[3] = {0};
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) ms[a] += src[3 * i + a] / n, md[a] += dst[3 * i + a] / n;
    double S[9] = {0}, var_s = 0, C[9] = {0};
    for (size_t i = 0; i < n; i++) {
        double a[3], b[3];
        for (int k = 0; k < 3; k++) a[k] = src[3 * i + k] - ms[k], b[k] = dst[3 * i + k] - md[k];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) S[r * 3 + c] += a[r] * b[c], C[r * 3 + c] += a[r] * a[c];
        var_s += a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    }
    /* Collinear or coincident sources leave the rotation about their line undetermined. */
    double w3[3], V3[9];
    jacobi(C, 3, w3, V3);
    double wmax = fmax(w3[0], fmax(w3[1], w3[2]));
    int small = 0;
    for (int k = 0; k < 3; k++) small += w3[k] < 1e-9 * (wmax > 0 ? wmax : 1) + 1e-18;
    if (!(var_s > 1e-18) || small >= 2)
        return sp_error_set(err, SP_E_ARG, "align: the %zu source points are collinear or coincident", n);
    /* Horn (1987): the rotation quaternion is the top eigenvector of N built from S. */
    double Sxx = S[0], Sxy = S[1], Sxz = S[2], Syx = S[3], Syy = S[4], Syz = S[5], Szx = S[6],
           Szy = S[7], Szz = S[8];
    double N[16] = {Sxx + Syy + Szz, Syz - Szy,        Szx - Sxz,        Sxy - Syx,
                    Syz - Szy,       Sxx - Syy - Szz,  Sxy + Syx,        Szx + Sxz,
                    Szx - Sxz,       Sxy + Syx,        -Sxx + Syy - Szz, Syz + Szy,
                    Sxy - Syx,       Szx + Sxz,        Syz + Szy,        -Sxx - Syy + Szz};
    double w[4], V[16];
    jacobi(N, 4, w, V);
    int best = 0;
    for (int k = 1; k < 4; k++)
        if (w[k] > w[best]) best = k;
    double q[4] = {V[0 * 4 + best], V[1 * 4 + best], V[2 * 4 + best], V[3 * 4 + best]};
    double R[9];
    quat_to_R(q, R);
    double s = 1;
    if (with_scale) {
        double num = 0;
        for (size_t i = 0; i < n; i++) {
            double a[3], b[3];
            for (int k = 0; k < 3; k++) a[k] = src[3 * i + k] - ms[k], b[k] = dst[3 * i + k] - md[k];
            for (int r = 0; r < 3; r++)
                num += b[r] * (R[r * 3] * a[0] + R[r * 3 + 1] * a[1] + R[r * 3 + 2] * a[2]);
        }
        s = num / var_s;
        if (!(s > 0)) return sp_error_set(err, SP_E_NUMERIC, "align: degenerate scale %g", s);
    }
    memset(M, 0, sizeof(double) * 16);
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) M[r * 4 + c] = s * R[r * 3 + c];
        M[r * 4 + 3] = md[r] - s * (R[r * 3] * ms[0] + R[r * 3 + 1] * ms[1] + R[r * 3 + 2] * ms[2]);
    }
    M[15] = 1;
    if (rms) {
        double e2 = 0;
        for (size_t i = 0; i < n; i++)
            for (int r = 0; r < 3; r++) {
                double y = M[r * 4 + 3];
                for (int c = 0; c < 3; c++) y += M[r * 4 + c] * src[3 * i + c];
                e2 += (y - dst[3 * i + r]) * (y - dst[3 * i + r]);
            }
        *rms = sqrt(e2 / n);
    }
    return 0;
}

/* Real SH basis of band l exactly as 3DGS evaluates it (constants and signs matter: the rotation
 * matrix of a band depends on how each of its functions is scaled). */
static void sh_band(int l, double x, double y, double z, double *out)
{
    const double C1 = 0.4886025119029199;
    const double C2[5] = {1.0925484305920792, -1.0925484305920792, 0.31539156525252005,
                          -1.0925484305920792, 0.5462742152960396};
    const double C3[7] = {-0.5900435899266435, 2.890611442640554, -0.4570457994644658,
                          0.3731763325901154, -0.4570457994644658, 1.445305721320277,
                          -0.5900435899266435};
    if (l == 1) {
        out[0] = -C1 * y, out[1] = C1 * z, out[2] = -C1 * x;
    } else if (l == 2) {
        out[0] = C2[0] * x * y, out[1] = C2[1] * y * z, out[2] = C2[2] * (2 * z * z - x * x - y * y),
        out[3] = C2[3] * x * z, out[4] = C2[4] * (x * x - y * y);
    } else {
        out[0] = C3[0] * y * (3 * x * x - y * y), out[1] = C3[1] * x * y * z,
        out[2] = C3[2] * y * (4 * z * z - x * x - y * y),
        out[3] = C3[3] * z * (2 * z * z - 3 * x * x - 3 * y * y),
        out[4] = C3[4] * x * (4 * z * z - x * x - y * y), out[5] = C3[5] * z * (x * x - y * y),
        out[6] = C3[6] * x * (x * x - 3 * y * y);
    }
}

/* Solves the m x m system A X = B (B m x m, in place) by Gauss-Jordan with partial pivoting. */
static int solve(double *A, double *B, int m)
{
    for (int c = 0; c < m; c++) {
        int p = c;
        for (int r = c + 1; r < m; r++)
            if (fabs(A[r * m + c]) > fabs(A[p * m + c])) p = r;
        if (fabs(A[p * m + c]) < 1e-12) return -1;
        for (int k = 0; k < m; k++) {
            double t = A[c * m + k]; A[c * m + k] = A[p * m + k]; A[p * m + k] = t;
            t = B[c * m + k]; B[c * m + k] = B[p * m + k]; B[p * m + k] = t;
        }
        for (int r = 0; r < m; r++) {
            if (r == c) continue;
            double f = A[r * m + c] / A[c * m + c];
            for (int k = 0; k < m; k++) A[r * m + k] -= f * A[c * m + k], B[r * m + k] -= f * B[c * m + k];
        }
    }
    for (int r = 0; r < m; r++)
        for (int k = 0; k < m; k++) B[r * m + k] /= A[r * m + r];
    return 0;
}

/* T_l = M^T (m x m, m = 2l+1), new coefficients c' = T c:
 * Y_l(R^T d) = M Y_l(d)  =>  c' = M^T c, and M^T = (A^T A)^-1 A^T B with rows A_j = Y(d_j),
 * B_j = Y(R^T d_j). */
static int band_rotation(int l, const double R[9], double *T)
{
    int m = 2 * l + 1;
    double AtA[49] = {0}, AtB[49] = {0};
    uint64_t st = 0x9E3779B97F4A7C15ull;
    for (int j = 0; j < 64; j++) {
        double d[3], nrm = 0;
        for (int k = 0; k < 3; k++) {
            st ^= st >> 12, st ^= st << 25, st ^= st >> 27;
            d[k] = (double)((st * 2685821657736338717ull) >> 11) / 9007199254740992.0 - 0.5;
            nrm += d[k] * d[k];
        }
        nrm = sqrt(nrm);
        for (int k = 0; k < 3; k++) d[k] /= nrm;
        double rd[3] = {R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2],
                        R[2] * d[0] + R[5] * d[1] + R[8] * d[2]}; /* R^T d */
        double a[7], b[7];
        sh_band(l, d[0], d[1], d[2], a);
        sh_band(l, rd[0], rd[1], rd[2], b);
        for (int r = 0; r < m; r++)
            for (int c = 0; c < m; c++) AtA[r * m + c] += a[r] * a[c], AtB[r * m + c] += a[r] * b[c];
    }
    if (solve(AtA, AtB, m)) return -1;
    memcpy(T, AtB, sizeof(double) * m * m); /* T = M^T: c'_r = sum_c T[r][c] c_c */
    return 0;
}

int sp_splat_transform(sp_splat *s, const double M[16], sp_error *err)
{
    double sc = cbrt(M[0] * (M[5] * M[10] - M[6] * M[9]) - M[1] * (M[4] * M[10] - M[6] * M[8]) +
                     M[2] * (M[4] * M[9] - M[5] * M[8]));
    if (!(sc > 1e-12) || !isfinite(sc))
        return sp_error_set(err, SP_E_ARG, "align: transform has determinant <= 0 (scale %g)", sc);
    double R[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) R[r * 3 + c] = M[r * 4 + c] / sc;
    double dev = 0; /* R must be a rotation */
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            double d = R[a * 3] * R[b * 3] + R[a * 3 + 1] * R[b * 3 + 1] + R[a * 3 + 2] * R[b * 3 + 2];
            dev = fmax(dev, fabs(d - (a == b)));
        }
    if (dev > 1e-3)
        return sp_error_set(err, SP_E_ARG, "align: transform is not a similarity (R R^T off by %g)", dev);
    float Rf[9], qR[4];
    for (int k = 0; k < 9; k++) Rf[k] = (float)R[k];
    sp_mat3_to_quat(Rf, qR);
    double T[3][49];
    for (int l = 1; l <= s->sh_degree; l++)
        if (band_rotation(l, R, T[l - 1]))
            return sp_error_set(err, SP_E_NUMERIC, "align: SH band %d rotation is singular", l);
    int K = sp_sh_coeffs(s->sh_degree);
    float ls = (float)log(sc);
    for (size_t i = 0; i < s->n; i++) {
        float *m = s->means + 3 * i;
        double x = m[0], y = m[1], z = m[2];
        for (int r = 0; r < 3; r++) m[r] = (float)(M[r * 4] * x + M[r * 4 + 1] * y + M[r * 4 + 2] * z + M[r * 4 + 3]);
        float *q = s->quats + 4 * i, a0 = q[0], a1 = q[1], a2 = q[2], a3 = q[3];
        /* q' = qR (x) q (Hamilton product): the Gaussian's frame rotated with the world */
        q[0] = qR[0] * a0 - qR[1] * a1 - qR[2] * a2 - qR[3] * a3;
        q[1] = qR[0] * a1 + qR[1] * a0 + qR[2] * a3 - qR[3] * a2;
        q[2] = qR[0] * a2 - qR[1] * a3 + qR[2] * a0 + qR[3] * a1;
        q[3] = qR[0] * a3 + qR[1] * a2 - qR[2] * a1 + qR[3] * a0;
        for (int k = 0; k < 3; k++) s->log_scales[3 * i + k] += ls;
        float *sh = s->sh + (size_t)i * K * 3;
        for (int l = 1; l <= s->sh_degree; l++) {
            int mm = 2 * l + 1, k0 = l * l;
            for (int ch = 0; ch < 3; ch++) {
                double in[7], out[7];
                for (int j = 0; j < mm; j++) in[j] = sh[(k0 + j) * 3 + ch];
                for (int r = 0; r < mm; r++) {
                    out[r] = 0;
                    for (int c = 0; c < mm; c++) out[r] += T[l - 1][r * mm + c] * in[c];
                }
                for (int j = 0; j < mm; j++) sh[(k0 + j) * 3 + ch] = (float)out[j];
            }
        }
    }
    return 0;
}

int sp_detect_floor(const sp_splat *s, const sp_camera *cams, size_t n_cams, double M[16],
                    double normal[3], double *inliers, sp_error *err)
{
    if (s->n < 10) return sp_error_set(err, SP_E_ARG, "floor: %zu Gaussians are too few", s->n);
    /* Rough up: cameras' -y axis (robots hold cameras upright); +z when no cameras. */
    double up[3] = {0, 0, 0}, cc[3] = {0, 0, 0};
    for (size_t c = 0; c < n_cams; c++) {
        for (int k = 0; k < 3; k++) up[k] -= cams[c].R[3 + k];
        sp_vec3 o = sp_camera_center(&cams[c]);
        cc[0] += o.x / n_cams, cc[1] += o.y / n_cams, cc[2] += o.z / n_cams;
    }
    double un = sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (un < 1e-6) up[0] = 0, up[1] = 0, up[2] = 1, un = 1;
    for (int k = 0; k < 3; k++) up[k] /= un;
    /* Candidates: opaque Gaussians in the lowest 30% along the rough up. */
    size_t m = 0;
    double *h = malloc(sizeof(double) * s->n);
    size_t *idx = malloc(sizeof(size_t) * s->n);
    if (!h || !idx) {
        free(h), free(idx);
        return sp_error_set(err, SP_E_NOMEM, "floor: out of memory");
    }
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < s->n; i++) {
        if (sp_sigmoid(s->opacity_logits[i]) < 0.3f) continue;
        const float *p = s->means + 3 * i;
        h[m] = p[0] * up[0] + p[1] * up[1] + p[2] * up[2];
        lo = fmin(lo, h[m]), hi = fmax(hi, h[m]);
        idx[m++] = i;
    }
    size_t k = 0;
    double cut = lo + 0.3 * (hi - lo);
    for (size_t j = 0; j < m; j++)
        if (h[j] <= cut) idx[k++] = idx[j];
    free(h);
    if (k < 3) {
        free(idx);
        return sp_error_set(err, SP_E_NOTFOUND, "floor: not enough opaque low Gaussians");
    }
    double thr = 0.01 * (hi - lo) + 1e-6, bestn[3] = {0}, bestd = 0;
    size_t best_cnt = 0;
    uint64_t st = 0x2545F4914F6CDD1Dull;
    for (int it = 0; it < 400; it++) {
        const float *p[3];
        for (int j = 0; j < 3; j++) {
            st ^= st >> 12, st ^= st << 25, st ^= st >> 27;
            p[j] = s->means + 3 * idx[(st * 2685821657736338717ull >> 11) % k];
        }
        double a[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        double b[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (nn < 1e-12) continue;
        for (int j = 0; j < 3; j++) n[j] /= nn;
        if (fabs(n[0] * up[0] + n[1] * up[1] + n[2] * up[2]) < 0.7) continue; /* floors are level-ish */
        double d = -(n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2]);
        size_t cnt = 0;
        for (size_t j = 0; j < k; j++) {
            const float *q = s->means + 3 * idx[j];
            if (fabs(n[0] * q[0] + n[1] * q[1] + n[2] * q[2] + d) < thr) cnt++;
        }
        if (cnt > best_cnt) best_cnt = cnt, memcpy(bestn, n, sizeof bestn), bestd = d;
    }
    if (best_cnt < 3) {
        free(idx);
        return sp_error_set(err, SP_E_NOTFOUND, "floor: no level plane found among the low Gaussians");
    }
    /* Least-squares refits on the inliers (normal = smallest-variance direction), three rounds
     * with a shrinking band so clutter just above the floor (rugs, feet) stops tilting it. */
    double n[3] = {bestn[0], bestn[1], bestn[2]}, mu[3] = {0}, d = bestd;
    size_t ni = 0;
    for (int round = 0; round < 3; round++) {
        double band = thr / (double)(1 << round), C[9] = {0};
        size_t cnt = 0;
        double m[3] = {0};
        for (size_t j = 0; j < k; j++) {
            const float *q = s->means + 3 * idx[j];
            if (fabs(n[0] * q[0] + n[1] * q[1] + n[2] * q[2] + d) >= band) continue;
            for (int a = 0; a < 3; a++) m[a] += q[a];
            cnt++;
        }
        if (cnt < 3) break;
        for (int a = 0; a < 3; a++) m[a] /= cnt;
        for (size_t j = 0; j < k; j++) {
            const float *q = s->means + 3 * idx[j];
            if (fabs(n[0] * q[0] + n[1] * q[1] + n[2] * q[2] + d) >= band) continue;
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) C[a * 3 + b] += (q[a] - m[a]) * (q[b] - m[b]);
        }
        double w[3], V[9];
        jacobi(C, 3, w, V);
        int sm = 0;
        for (int j = 1; j < 3; j++)
            if (w[j] < w[sm]) sm = j;
        double nn[3] = {V[0 * 3 + sm], V[1 * 3 + sm], V[2 * 3 + sm]};
        if (nn[0] * n[0] + nn[1] * n[1] + nn[2] * n[2] < 0) nn[0] = -nn[0], nn[1] = -nn[1], nn[2] = -nn[2];
        memcpy(n, nn, sizeof n);
        memcpy(mu, m, sizeof mu);
        d = -(n[0] * mu[0] + n[1] * mu[1] + n[2] * mu[2]);
        if (round == 0) ni = cnt;
    }
    free(idx);
    /* orient toward the cameras (or the rough up) */
    double toward = n_cams ? (cc[0] - mu[0]) * n[0] + (cc[1] - mu[1]) * n[1] + (cc[2] - mu[2]) * n[2]
                           : n[0] * up[0] + n[1] * up[1] + n[2] * up[2];
    if (toward < 0) n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
    d = -(n[0] * mu[0] + n[1] * mu[1] + n[2] * mu[2]);
    /* Rotation taking n to +z (Rodrigues about n x z). */
    double ax[3] = {n[1], -n[0], 0}, sa = sqrt(ax[0] * ax[0] + ax[1] * ax[1]), ca = n[2];
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (sa > 1e-12) {
        for (int j = 0; j < 3; j++) ax[j] /= sa;
        double K[9] = {0, -ax[2], ax[1], ax[2], 0, -ax[0], -ax[1], ax[0], 0}, K2[9];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                K2[r * 3 + c] = K[r * 3] * K[c] + K[r * 3 + 1] * K[3 + c] + K[r * 3 + 2] * K[6 + c];
        for (int j = 0; j < 9; j++) R[j] += sa * K[j] + (1 - ca) * K2[j];
    } else if (ca < 0) {
        R[4] = -1, R[8] = -1; /* upside down: rotate 180 degrees about x */
    }
    memset(M, 0, sizeof(double) * 16);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) M[r * 4 + c] = R[r * 3 + c];
    M[11] = d; /* z' = n.x + d: the floor lands on z = 0 */
    M[15] = 1;
    if (normal) memcpy(normal, n, sizeof n);
    if (inliers) *inliers = (double)ni / (double)k;
    return 0;
}
