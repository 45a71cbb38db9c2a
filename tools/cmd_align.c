/* semsplat align: puts a COLMAP-frame splat into the world (odometry) frame, from known camera
 * positions (Umeyama similarity, >= 3 matches), a given 4x4 transform, or the detected floor
 * plane (z up, floor at z = 0). With --model it writes DIR/frame.json (source "align"), which the
 * query engine applies to splat and cameras; --out writes a transformed copy of the splat. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"

static void help(void)
{
    printf("usage: semsplat align (--splat IN.ply --out OUT.ply | --model DIR [--out OUT.ply])\n"
           "                      (--matches FILE --colmap DIR | --transform FILE | --floor [--colmap DIR])\n"
           "                      [--no-scale]\n\n"
           "  --matches FILE   lines 'IMAGE_NAME x y z' (that camera's world position; needs\n"
           "                   --colmap) or 'x y z X Y Z' (a COLMAP-frame point and its world\n"
           "                   position); at least 3. Fits a similarity (Umeyama).\n"
           "  --transform FILE 12 or 16 numbers: a row-major 3x4 / 4x4 similarity.\n"
           "  --floor          RANSAC floor plane on the lowest Gaussians: z up, floor at z=0\n"
           "                   (uses --colmap cameras for the rough up direction when given).\n"
           "  --model DIR      writes DIR/frame.json (world_from_model, source align); splat.ply\n"
           "                   stays as it is and queries report world positions.\n");
}

static int read_transform(const char *path, double M[16], sp_error *err)
{
    FILE *f = fopen(path, "r");
    if (!f) return sp_error_set(err, SP_E_IO, "%s: cannot open", path);
    int n = 0;
    double v;
    while (n < 17 && fscanf(f, " %lf%*[ ,\t\n\r[]]", &v) == 1) M[n++] = v;
    fclose(f);
    if (n == 12) M[12] = 0, M[13] = 0, M[14] = 0, M[15] = 1;
    else if (n != 16) return sp_error_set(err, SP_E_FORMAT, "%s: %d numbers (need 12 or 16)", path, n);
    return 0;
}

static int read_matches(const char *path, const sp_colmap_model *m, double **src, double **dst,
                        size_t *n, sp_error *err)
{
    FILE *f = fopen(path, "r");
    if (!f) return sp_error_set(err, SP_E_IO, "%s: cannot open", path);
    char line[1024];
    size_t cap = 0, k = 0;
    int lineno = 0, rc = 0;
    *src = *dst = NULL;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *p = line;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '#' || *p == '\n' || !*p) continue;
        double a[6];
        char name[512];
        int got = sscanf(p, "%lf %lf %lf %lf %lf %lf", &a[0], &a[1], &a[2], &a[3], &a[4], &a[5]);
        if (got != 6) {
            if (sscanf(p, "%511s %lf %lf %lf", name, &a[3], &a[4], &a[5]) != 4) {
                rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: expected 'IMAGE x y z' or 'x y z X Y Z'", path, lineno);
                break;
            }
            size_t i;
            for (i = 0; m && i < m->n_images; i++)
                if (m->images[i].name && !strcmp(m->images[i].name, name)) break;
            if (!m || i == m->n_images) {
                rc = sp_error_set(err, SP_E_NOTFOUND, "%s:%d: image '%s' is not in the COLMAP model%s",
                                  path, lineno, name, m ? "" : " (pass --colmap)");
                break;
            }
            sp_camera cam;
            if ((rc = sp_colmap_image_camera(m, i, &cam, err))) break;
            sp_vec3 c = sp_camera_center(&cam);
            a[0] = c.x, a[1] = c.y, a[2] = c.z;
        }
        if (k == cap) {
            cap = cap ? cap * 2 : 16;
            double *s2 = realloc(*src, sizeof(double) * 3 * cap);
            if (s2) *src = s2;
            double *d2 = s2 ? realloc(*dst, sizeof(double) * 3 * cap) : NULL;
            if (d2) *dst = d2;
            if (!s2 || !d2) {
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
                break;
            }
        }
        memcpy(*src + 3 * k, a, sizeof(double) * 3);
        memcpy(*dst + 3 * k, a + 3, sizeof(double) * 3);
        k++;
    }
    fclose(f);
    *n = k;
    return rc;
}

/* The model folder's frame: the fitted similarity as world_from_model (metres, z up). */
static int write_frame(const char *model, const double M[16], double rms, const char *how, sp_error *err)
{
    sp_frame f;
    sp_frame_init(&f, "align");
    memcpy(f.world_from_model, M, sizeof f.world_from_model);
    f.residual_m = rms;
    snprintf(f.note, sizeof f.note, "semsplat align --%s", how);
    if (!strcmp(how, "floor")) snprintf(f.units, sizeof f.units, "unknown"); /* no scale from a plane */
    char path[2100];
    snprintf(path, sizeof path, "%s/frame.json", model);
    return sp_frame_write(path, &f, err);
}

int cmd_align(int argc, char **argv)
{
    const char *splat = NULL, *model = NULL, *out = NULL, *matches = NULL, *tfile = NULL,
               *colmap = NULL, *v;
    int floor_ = 0, scale = 1, bad = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--splat", &bad))) splat = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--matches", &bad))) matches = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--transform", &bad))) tfile = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap = v;
        else if (!strcmp(argv[i], "--floor")) floor_ = 1;
        else if (!strcmp(argv[i], "--no-scale")) scale = 0;
        else if (!bad) return cli_usage_error("align", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    char in[2048];
    if (splat) snprintf(in, sizeof in, "%s", splat);
    else if (model) snprintf(in, sizeof in, "%s/splat.ply", model);
    else return cli_usage_error("align", "--splat IN.ply or --model DIR is required");
    if (!out && !model) return cli_usage_error("align", "--out OUT.ply is required with --splat");
    if (!!matches + !!tfile + floor_ != 1)
        return cli_usage_error("align", "give exactly one of --matches, --transform, --floor");
    sp_error err = {0};
    sp_splat s = {0};
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    double M[16], *src = NULL, *dst = NULL, rms = -1;
    sp_camera *cams = NULL;
    size_t nc = 0;
    int rc = sp_ply_read_splat(in, &s, &err);
    if (!rc && colmap) rc = sp_colmap_read(colmap, &m, &err);
    if (!rc && tfile) rc = read_transform(tfile, M, &err);
    if (!rc && matches) {
        size_t n = 0;
        rc = read_matches(matches, colmap ? &m : NULL, &src, &dst, &n, &err);
        if (!rc) rc = sp_umeyama(src, dst, n, scale, M, &rms, &err);
        if (!rc) printf("similarity from %zu matches: rms %.4f\n", n, rms);
    }
    if (!rc && floor_) {
        cams = calloc(m.n_images ? m.n_images : 1, sizeof *cams);
        for (size_t i = 0; cams && i < m.n_images && !rc; i++) rc = sp_colmap_image_camera(&m, i, &cams[nc++], &err);
        double n3[3], inl = 0;
        if (!rc) rc = sp_detect_floor(&s, cams, nc, M, n3, &inl, &err);
        if (!rc) printf("floor normal (%.4f, %.4f, %.4f), %.1f%% of low Gaussians on it\n", n3[0], n3[1], n3[2], 100 * inl);
    }
    if (!rc && model) rc = write_frame(model, M, rms, matches ? "matches" : tfile ? "transform" : "floor", &err);
    if (!rc && out) rc = sp_splat_transform(&s, M, &err);
    if (!rc && out) rc = sp_ply_write_splat(out, &s, &err);
    if (!rc) {
        printf("transform (row-major 4x4):\n");
        for (int r = 0; r < 4; r++)
            printf("  %12.6f %12.6f %12.6f %12.6f\n", M[r * 4], M[r * 4 + 1], M[r * 4 + 2], M[r * 4 + 3]);
        if (model) printf("wrote %s/frame.json (source align)\n", model);
        if (out) printf("wrote %s (%zu Gaussians)\n", out, s.n);
    }
    free(src), free(dst), free(cams);
    sp_colmap_free(&m);
    sp_splat_free(&s);
    return rc ? cli_fail("align", &err) : 0;
}
