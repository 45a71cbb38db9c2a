/* Navigation figures on a model folder: costmap build time, planning time for k trajectories to
 * an object of the capture's ground truth, and (with --world) the costmap's agreement with the
 * world's floor plan in the same height band.
 * Usage: bench_nav --model DIR [--world W.world [--model-path DIR]] [--to NAME] [--k 3]
 *                  [--threads N] [--map OUT.yaml] */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/io.h"
#include "semsplat/nav.h"
#include "semsplat/synth.h"

static int fail(const sp_error *e)
{
    fprintf(stderr, "bench_nav: %s\n", e->msg);
    return 1;
}

/* The capture named in DIR/train.json, its cameras, and the footprint of object `name`. */
static int load(const char *model, sp_splat *s, sp_camera **cams, size_t *n, char *capture,
                size_t cap, sp_error *err)
{
    char p[2048];
    snprintf(p, sizeof p, "%s/splat.ply", model);
    int rc = sp_ply_read_splat(p, s, err);
    if (rc) return rc;
    cJSON *tj;
    snprintf(p, sizeof p, "%s/train.json", model);
    if ((rc = sp_json_read_file(p, &tj, err))) return rc;
    cJSON *st = cJSON_GetObjectItem(tj, "settings"), *c = st ? cJSON_GetObjectItem(st, "colmap") : NULL;
    if (!cJSON_IsString(c)) {
        cJSON_Delete(tj);
        return sp_error_set(err, SP_E_FORMAT, "%s: no settings.colmap", p);
    }
    snprintf(capture, cap, "%s", c->valuestring);
    cJSON_Delete(tj);
    sp_colmap_model m;
    if ((rc = sp_colmap_read(capture, &m, err))) return rc;
    *cams = calloc(m.n_images, sizeof(sp_camera));
    *n = 0;
    for (size_t i = 0; i < m.n_images && !rc; i++) rc = sp_colmap_image_camera(&m, i, &(*cams)[(*n)++], err);
    sp_colmap_free(&m);
    return rc;
}

static int object_box(const char *capture, const char *name, float lo[2], float hi[2], sp_error *err)
{
    char p[2048];
    snprintf(p, sizeof p, "%s/ground_truth.json", capture);
    cJSON *gt;
    int rc = sp_json_read_file(p, &gt, err);
    if (rc) return rc;
    cJSON *o;
    rc = sp_error_set(err, SP_E_NOTFOUND, "%s: no object named '%s'", p, name);
    cJSON_ArrayForEach(o, cJSON_GetObjectItem(gt, "objects"))
    {
        cJSON *nm = cJSON_GetObjectItem(o, "name"), *a = cJSON_GetObjectItem(o, "aabb_min"),
              *b = cJSON_GetObjectItem(o, "aabb_max");
        if (!cJSON_IsString(nm) || strcmp(nm->valuestring, name) || !a || !b) continue;
        for (int k = 0; k < 2; k++)
            lo[k] = (float)cJSON_GetArrayItem(a, k)->valuedouble, hi[k] = (float)cJSON_GetArrayItem(b, k)->valuedouble;
        rc = 0;
        sp_error_clear(err);
    }
    cJSON_Delete(gt);
    return rc;
}

int main(int argc, char **argv)
{
    const char *model = NULL, *world = NULL, *model_path = NULL, *to = "refrigerator", *map = NULL;
    int k = 3, threads = 2, verbose = 0;
    sp_costmap_opts co = sp_costmap_opts_default();
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--model")) model = argv[i + 1];
        else if (!strcmp(argv[i], "--world")) world = argv[i + 1];
        else if (!strcmp(argv[i], "--model-path")) model_path = argv[i + 1];
        else if (!strcmp(argv[i], "--to")) to = argv[i + 1];
        else if (!strcmp(argv[i], "--k")) k = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--threads")) threads = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--map")) map = argv[i + 1];
        else if (!strcmp(argv[i], "--band-lo")) co.band_lo_m = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--min-opacity")) co.min_opacity = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--min-views")) co.min_views = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--evidence")) co.occupied_evidence = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--sigmas")) co.footprint_sigmas = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--downscale")) co.carve_downscale = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--stop")) co.carve_stop_m = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--floor-tol")) co.floor_tolerance_m = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--fill")) co.fill_max_area_m2 = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--needs-floor")) co.free_needs_floor = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--veto")) co.pass_veto = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--slice")) co.slice_m = (float)atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--verbose")) verbose = atoi(argv[i + 1]);
    }
    if (!model) {
        fprintf(stderr, "usage: bench_nav --model DIR [--world W.world [--model-path DIR]] [--to NAME] "
                        "[--k 3] [--threads N] [--map OUT.yaml]\n");
        return 2;
    }
    sp_error err = {0};
    sp_splat s;
    sp_camera *cams = NULL;
    size_t n = 0;
    char capture[2048];
    if (load(model, &s, &cams, &n, capture, sizeof capture, &err)) return fail(&err);
    sp_device *dev;
    sp_raster *r;
    if (sp_device_create(&dev, SP_DEVICE_CPU, threads, &err) || sp_raster_create(&r, dev, &err)) return fail(&err);
    sp_costmap cm;
    sp_log log = sp_log_stderr(verbose ? SP_LOG_DEBUG : SP_LOG_WARN, 1);
    double t0 = sp_time_now();
    if (sp_costmap_build(&cm, &s, cams, n, &co, r, &log, &err)) return fail(&err);
    double t_build = sp_time_now() - t0;
    printf("costmap_build  %.0f ms  (%zu Gaussians, %zu views at 1/%d, %dx%d cells of %.2f m, %s)\n",
           1e3 * t_build, s.n, n, co.carve_downscale, cm.nx, cm.ny, cm.res, sp_device_name(dev));
    printf("floor_z  %.3f m\n", cm.floor_z);
    if (map && sp_costmap_write_map(&cm, map, &err)) return fail(&err);
    if (world) {
        sp_world w;
        sp_synth_load_opts lo = {model_path, 1, 0, NULL};
        if (sp_synth_load_world(world, &lo, &w, &err)) return fail(&err);
        uint8_t *truth = malloc((size_t)cm.nx * cm.ny);
        /* the world's floor is z = 0 */
        if (sp_synth_floor_plan(&w, co.band_lo_m, co.band_hi_m, cm.res, cm.origin, cm.nx, cm.ny, truth, &err))
            return fail(&err);
        sp_costmap_agreement a;
        sp_costmap_compare(&cm, truth, &a);
        printf("costmap_agreement  %.2f %%  (%ld of %ld known cells; %.1f %% of the map known)\n",
               100 * a.agreement, a.agree, a.known, 100 * a.known_fraction);
        printf("occupied_marked_free  %.2f %%  (%ld of %ld truly occupied cells)\n",
               100 * a.occupied_free_rate, a.occupied_as_free, a.truth_occupied);
        printf("free_marked_occupied  %ld cells\n", a.free_as_occupied);
        if (map) {
            char tp[2100];
            snprintf(tp, sizeof tp, "%s.truth.pgm", map);
            FILE *f = fopen(tp, "wb");
            fprintf(f, "P5\n%d %d\n255\n", cm.nx, cm.ny);
            for (int y = cm.ny - 1; y >= 0; y--)
                for (int x = 0; x < cm.nx; x++) {
                    long i = (long)y * cm.nx + x;
                    int t = truth[i], o = cm.occ[i];
                    fputc(o == SP_CELL_UNKNOWN ? (t ? 100 : 205) : (o == SP_CELL_OCCUPIED) == t ? (t ? 0 : 254) : (t ? 60 : 150), f);
                }
            fclose(f);
        }
        free(truth);
        sp_world_free(&w);
    }
    float lo[2], hi[2];
    if (object_box(capture, to, lo, hi, &err)) return fail(&err);
    sp_vec3 c0 = sp_camera_center(&cams[0]);
    float start[3] = {c0.x, c0.y, 0};
    sp_nav_goal g = sp_nav_goal_box(lo, hi, 0.5f);
    sp_path_set set;
    sp_planner_opts po = sp_planner_opts_default();
    double best = INFINITY;
    for (int rep = 0; rep < 5; rep++) {
        t0 = sp_time_now();
        if (sp_plan_k(&cm, start, &g, k, &po, &set, &err)) return fail(&err);
        best = fmin(best, sp_time_now() - t0);
        if (rep < 4) sp_path_set_free(&set);
    }
    printf("plan_k%d  %.1f ms  (best of 5; %d paths in %d planner runs, from (%.2f, %.2f) to %s)\n", k,
           1e3 * best, set.n, set.rounds, start[0], start[1], to);
    for (int i = 0; i < set.n; i++)
        printf("  path %d  %.2f m  %d corners  share %.2f\n", i, set.paths[i].length_m, set.paths[i].n_corners,
               set.share[i]);
    if (set.note[0]) printf("  note: %s\n", set.note);
    sp_path_set_free(&set);
    sp_costmap_free(&cm);
    sp_raster_free(r);
    sp_device_free(dev);
    sp_splat_free(&s);
    free(cams);
    return 0;
}
