/* Camera-centre matches for the frame-fit tests: random similarities and the matches a COLMAP
 * reconstruction with misregistered images gives (unit tests and the align CLI test). */
#ifndef SP_TEST_MATCHES_H
#define SP_TEST_MATCHES_H

#include <math.h>
#include <string.h>

#include "semsplat/core.h"
#include "semsplat/io.h"
#include "test.h"

static inline void random_similarity(test_rng *r, double M[16], double *scale)
{
    float q[4], R[9];
    for (int k = 0; k < 4; k++) q[k] = (float)test_range(r, -1, 1);
    sp_quat_to_mat3(q, R);
    double s = test_range(r, 0.5, 2.0);
    for (int a = 0; a < 3; a++) {
        for (int b = 0; b < 3; b++) M[a * 4 + b] = s * R[a * 3 + b];
        M[a * 4 + 3] = test_range(r, -5, 5);
    }
    M[12] = M[13] = M[14] = 0, M[15] = 1;
    *scale = s;
}

static inline void apply(const double M[16], const double *p, double *o)
{
    for (int a = 0; a < 3; a++) o[a] = M[a * 4] * p[0] + M[a * 4 + 1] * p[1] + M[a * 4 + 2] * p[2] + M[a * 4 + 3];
}

static inline void invert_similarity(const double M[16], double s, double Minv[16])
{
    /* [sR t]^-1 = [R^T/s  -R^T t/s] */
    memset(Minv, 0, sizeof(double) * 16);
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) Minv[a * 4 + b] = M[b * 4 + a] / (s * s);
    for (int a = 0; a < 3; a++)
        Minv[a * 4 + 3] = -(Minv[a * 4] * M[3] + Minv[a * 4 + 1] * M[7] + Minv[a * 4 + 2] * M[11]);
    Minv[15] = 1;
}

/* Camera-centre matches as a COLMAP reconstruction gives them: n world positions in a house-sized
 * box, their COLMAP-frame centres under a random similarity, noise of at most noise_m per axis
 * (uniform) on the world side, and the images in `bad` misregistered by 0.5..3 m. */
static inline void planted_matches(test_rng *r, int n, const int *bad, int n_bad, double noise_m,
                                   double *src, double *dst, double M[16])
{
    double s, Minv[16];
    random_similarity(r, M, &s);
    invert_similarity(M, s, Minv);
    for (int i = 0; i < n; i++) {
        double w[3] = {test_range(r, 0, 10), test_range(r, 0, 8), test_range(r, 0.3, 1.5)}, wb[3];
        memcpy(wb, w, sizeof w);
        for (int k = 0; k < n_bad; k++)
            if (bad[k] == i) {
                double d[3] = {test_range(r, -1, 1), test_range(r, -1, 1), test_range(r, -1, 1)};
                double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 1e-9, m = test_range(r, 0.5, 3.0);
                for (int a = 0; a < 3; a++) wb[a] += d[a] / len * m;
            }
        apply(Minv, wb, src + 3 * i); /* where COLMAP put the camera */
        for (int a = 0; a < 3; a++) dst[3 * i + a] = w[a] + test_range(r, -noise_m, noise_m);
    }
}

/* Writes a text COLMAP model into dir whose n <= 64 images img_NN.png have camera centres src
 * (R = I, t = -c) and a matches file 'img_NN.png x y z' with the world positions dst. */
static inline int write_centres(const char *dir, const char *matches_path, const double *src,
                                const double *dst, int n, sp_error *err)
{
    if (n > 64) return sp_error_set(err, SP_E_ARG, "write_centres: at most 64 images");
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    sp_colmap_camera cam = {1, SP_COLMAP_PINHOLE, 64, 48, 4, {50, 50, 32, 24}};
    sp_colmap_image ims[64];
    char names[64][32];
    memset(ims, 0, sizeof ims);
    for (int i = 0; i < n; i++) {
        snprintf(names[i], sizeof names[i], "img_%02d.png", i);
        ims[i].id = (uint32_t)i + 1, ims[i].camera_id = 1, ims[i].name = names[i];
        ims[i].qvec[0] = 1;
        for (int a = 0; a < 3; a++) ims[i].tvec[a] = -src[3 * i + a];
    }
    m.n_cameras = 1, m.cameras = &cam, m.n_images = (size_t)n, m.images = ims;
    int rc = sp_mkdirs(dir, err);
    if (!rc) rc = sp_colmap_write_txt(dir, &m, err);
    FILE *f = rc ? NULL : fopen(matches_path, "w");
    if (!rc && !f) return sp_error_set(err, SP_E_IO, "%s: cannot write", matches_path);
    if (f) {
        fprintf(f, "# image  world x y z\n");
        for (int i = 0; i < n; i++)
            fprintf(f, "%s %.9f %.9f %.9f\n", names[i], dst[3 * i], dst[3 * i + 1], dst[3 * i + 2]);
        fclose(f);
    }
    return rc;
}

#endif
