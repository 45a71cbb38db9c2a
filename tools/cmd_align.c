/* semsplat align: puts a COLMAP-frame splat into the world (odometry) frame, from known camera
 * positions (a robust similarity, >= 4 matches, the fit written as JSON), a given 4x4 transform,
 * or the detected floor plane (z up, floor at z = 0). With --model it writes DIR/frame.json
 * (source "align"), which the query engine applies to splat and cameras; --out writes a
 * transformed copy of the splat. */
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
           "                      [--no-scale] [--inlier-m D] [--report FILE]\n\n"
           "  --matches FILE   lines 'IMAGE_NAME x y z' (that camera's world position; needs\n"
           "                   --colmap) or 'x y z X Y Z' (a COLMAP-frame point and its world\n"
           "                   position); at least 4. Fits a similarity robustly (least median\n"
           "                   of squares over Umeyama fits of triples, refit on the inliers),\n"
           "                   names the outlying images, and refuses when fewer than half agree.\n"
           "  --inlier-m D     inlier bound in world units (default: 4.03 x the noise scale\n"
           "                   estimated from the median residual)\n"
           "  --report FILE    the fit as JSON (default: OUT with .ply replaced by .align.json;\n"
           "                   with --model it is also under \"fit\" in DIR/frame.json)\n"
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

/* The model folder's frame: the fitted similarity as world_from_model (metres, z up). */
static int write_frame(const char *model, const double M[16], double rms, const char *how,
                       const char *fit_json, sp_error *err)
{
    sp_frame f;
    sp_frame_init(&f, "align");
    memcpy(f.world_from_model, M, sizeof f.world_from_model);
    f.residual_m = rms;
    snprintf(f.note, sizeof f.note, "semsplat align --%s", how);
    if (!strcmp(how, "floor")) snprintf(f.units, sizeof f.units, "unknown"); /* no scale from a plane */
    char path[2100];
    snprintf(path, sizeof path, "%s/frame.json", model);
    return sp_frame_write_fit(path, &f, fit_json, err);
}

int cmd_align(int argc, char **argv)
{
    const char *splat = NULL, *model = NULL, *out = NULL, *matches = NULL, *tfile = NULL,
               *colmap = NULL, *report = NULL, *v;
    double inlier_m = 0;
    int floor_ = 0, scale = 1, bad = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--splat", &bad))) splat = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--matches", &bad))) matches = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--transform", &bad))) tfile = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--report", &bad))) report = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--inlier-m", &bad))) {
            if (cli_parse_float("align", "--inlier-m", v, &inlier_m)) return 2;
        }
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
    double M[16];
    sp_camera *cams = NULL;
    size_t nc = 0;
    sp_align_matches mt = {0};
    sp_align_fit fit = {0};
    char *json = NULL, rpath[2100];
    int rc = sp_ply_read_splat(in, &s, &err);
    if (!rc && colmap) rc = sp_colmap_read(colmap, &m, &err);
    if (!rc && tfile) rc = read_transform(tfile, M, &err);
    if (!rc && matches) {
        rc = sp_align_read_matches(matches, colmap, &mt, &err);
        if (!rc) rc = sp_align_fit_robust(mt.src, mt.dst, mt.n, scale, inlier_m, &fit, &err);
        for (size_t i = 0; fit.inlier && i < fit.n; i++)
            if (!fit.inlier[i])
                printf("outlier  %s  residual %.4f\n", mt.name[i][0] ? mt.name[i] : "(point)", fit.residual[i]);
        if (fit.inlier)
            printf("similarity from %zu of %zu matches: rms %.4f on the inliers (bound %.4f; plain least squares "
                   "over all: rms %.4f)\n", fit.n_inliers, fit.n, fit.rms_inliers, fit.threshold, fit.rms_all);
        memcpy(M, fit.M, sizeof M);
        if (!rc && !(json = sp_align_fit_json(&fit, &mt, scale))) rc = sp_error_set(&err, SP_E_NOMEM, "out of memory");
    }
    if (!rc && floor_) {
        cams = calloc(m.n_images ? m.n_images : 1, sizeof *cams);
        for (size_t i = 0; cams && i < m.n_images && !rc; i++) rc = sp_colmap_image_camera(&m, i, &cams[nc++], &err);
        double n3[3], inl = 0;
        if (!rc) rc = sp_detect_floor(&s, cams, nc, M, n3, &inl, &err);
        if (!rc) printf("floor normal (%.4f, %.4f, %.4f), %.1f%% of low Gaussians on it\n", n3[0], n3[1], n3[2], 100 * inl);
    }
    if (!rc && model)
        rc = write_frame(model, M, matches ? fit.rms_inliers : -1, matches ? "matches" : tfile ? "transform" : "floor",
                         json, &err);
    if (!rc && out) rc = sp_splat_transform(&s, M, &err);
    if (!rc && out) rc = sp_ply_write_splat(out, &s, &err);
    size_t stem = out && strlen(out) > 4 && !strcmp(out + strlen(out) - 4, ".ply") ? strlen(out) - 4 : out ? strlen(out) : 0;
    snprintf(rpath, sizeof rpath, "%s", report ? report : "");
    if (!report && out) snprintf(rpath, sizeof rpath, "%.*s.align.json", (int)stem, out);
    int write_report = report || out; /* with --model only, the fit lives in frame.json */
    if (!rc && json && write_report) rc = sp_write_file_atomic(rpath, json, strlen(json), &err);
    if (!rc) {
        printf("transform (row-major 4x4):\n");
        for (int r = 0; r < 4; r++)
            printf("  %12.6f %12.6f %12.6f %12.6f\n", M[r * 4], M[r * 4 + 1], M[r * 4 + 2], M[r * 4 + 3]);
        if (model) printf("wrote %s/frame.json (source align)\n", model);
        if (out) printf("wrote %s (%zu Gaussians)\n", out, s.n);
        if (json && write_report) printf("wrote %s (the fit)\n", rpath);
    }
    free(cams), free(json);
    sp_align_fit_free(&fit);
    sp_align_matches_free(&mt);
    sp_colmap_free(&m);
    sp_splat_free(&s);
    return rc ? cli_fail("align", &err) : 0;
}
