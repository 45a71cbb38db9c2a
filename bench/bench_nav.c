/* Navigation figures: costmap build time, planning time for k trajectories to an object, and
 * with a world file the costmap's agreement with the world's floor plan in the same height band
 * (>= 95 % of known cells, <= 1 % of truly occupied cells marked free is the bar).
 *   bench_nav --model DIR [--world W.world [--model-path DIR]]   a trained model folder
 *   bench_nav --ideal --world W.world [--views N]                 an ideal splat of the world's
 *                                                                 geometry (tests/nav/world_splat.h)
 * Options: --to NAME (a world object's name, default refrigerator) --k N (3) --threads N (2)
 *          --map OUT.yaml (writes the map and OUT.yaml.truth.pgm: agreement colour-coded);
 *          costmap settings --needs-floor 0|1 --evidence E --min-opacity O --despeckle N --fill M2
 *          --floor-tol M --measure-floor 0|1 ... (see the argument loop). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../tests/nav/nav_truth.h"
#include "../tests/nav/world_splat.h"
#include "semsplat/io.h"
#include "semsplat/nav.h"
#include "semsplat/synth.h"

static int fail(const sp_error *e)
{
    fprintf(stderr, "bench_nav: %s\n", e->msg);
    return 1;
}

/* The machine is shared: timings mean little without the load they ran under. */
static double load_average(void)
{
    double l = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1) l = -1;
        fclose(f);
    }
    return l;
}

/* DIR/splat.ply and the cameras of the capture DIR/train.json names. */
static int load_model(const char *model, sp_splat *s, sp_camera **cams, size_t *n, sp_error *err)
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
    sp_colmap_model m;
    rc = sp_colmap_read(c->valuestring, &m, err);
    cJSON_Delete(tj);
    if (rc) return rc;
    *cams = calloc(m.n_images, sizeof(sp_camera));
    *n = 0;
    for (size_t i = 0; i < m.n_images && !rc; i++) rc = sp_colmap_image_camera(&m, i, &(*cams)[(*n)++], err);
    sp_colmap_free(&m);
    return rc;
}

/* Cell i's grey level in one of the diagnostic pictures. */
typedef int (*pixel_fn)(const sp_costmap *cm, const uint8_t *layer, long i);

/* MAP + suffix: a PGM of the grid, image row 0 the largest y (as the map). */
static void write_pgm(const char *map, const char *suffix, const sp_costmap *cm, const uint8_t *layer, pixel_fn px)
{
    char tp[2100];
    snprintf(tp, sizeof tp, "%s%s", map, suffix);
    FILE *f = fopen(tp, "wb");
    if (!f) return;
    fprintf(f, "P5\n%d %d\n255\n", cm->nx, cm->ny);
    for (int y = cm->ny - 1; y >= 0; y--)
        for (int x = 0; x < cm->nx; x++) fputc(px(cm, layer, (long)y * cm->nx + x), f);
    fclose(f);
}

/* .costs.pgm: 254 traversable, 180 inscribed (within the robot radius of an obstacle), 0
 * obstacle, 205 unknown; 120 traversable but not truly reachable from the start. */
static int cost_pixel(const sp_costmap *cm, const uint8_t *reach, long i)
{
    int c = cm->cost[i];
    int v = c == SP_COST_UNKNOWN ? 205 : c == SP_COST_LETHAL ? 0 : c == SP_COST_INSCRIBED ? 180 : 254;
    return v == 254 && !reach[i] ? 120 : v;
}

/* .truth.pgm: white / black: free / occupied, agreeing; 150: free marked occupied; 60: occupied
 * marked free; 205 / 100: unknown over truly free / occupied. */
static int truth_pixel(const sp_costmap *cm, const uint8_t *truth, long i)
{
    int t = truth[i], o = cm->occ[i];
    return o == SP_CELL_UNKNOWN ? (t ? 100 : 205) : (o == SP_CELL_OCCUPIED) == t ? (t ? 0 : 254) : (t ? 60 : 150);
}

/* Issue 18's acceptance: every floor-standing object a robot truly reaches from the start gets a
 * path (to its true footprint: the planner measured apart from the query engine) that enters no
 * occupied or unknown cell and ends in a truly free cell within 0.6 m of the footprint. */
static void objects_reached(const sp_costmap *cm, const sp_world *w, const uint8_t *truth, const uint8_t *reach,
                            const float start[3], const sp_nav_opts *no, int verbose)
{
    int tried = 0, ok = 0, skipped = 0;
    for (size_t o = 0; o < w->n_objects; o++) {
        const sp_synth_object *ob = &w->objects[o];
        if (ob->is_structure || ob->aabb_min[2] > 0.1f) continue; /* floor-standing objects only */
        sp_nav_box box = {{ob->aabb_min[0], ob->aabb_min[1]}, {ob->aabb_max[0], ob->aabb_max[1]}};
        if (!nt_box_reachable(cm, reach, &box)) {
            skipped++;
            continue;
        }
        tried++;
        sp_nav_goal g = sp_nav_goal_box(box.min, box.max, no->approach_m);
        sp_path p;
        sp_error err = {0};
        if (sp_plan_path(cm, start, &g, &no->planner, &p, &err)) {
            if (verbose) printf("  %-20s MISS  %s\n", ob->name, err.msg);
            continue;
        }
        nt_verdict v = nt_judge(cm, truth, &box, &p);
        ok += v.pass;
        if (verbose)
            printf("  %-20s %s  %.2f m, ends %.2f m from its footprint%s, %d untraversable cells entered\n", ob->name,
                   v.pass ? "ok  " : "FAIL", p.length_m, v.end_dist, v.end_free ? "" : " (truly occupied)", v.bad);
        sp_path_free(&p);
    }
    printf("objects_reached  %d of %d  (floor-standing objects truly reachable from the start; %d unreachable "
           "skipped)\n", ok, tried, skipped);
}

int main(int argc, char **argv)
{
    const char *model = NULL, *world = NULL, *model_path = NULL, *to = "refrigerator", *map = NULL;
    int k = 3, threads = 2, ideal = 0, views = 150, verbose = 0;
    sp_costmap_opts co = sp_costmap_opts_default();
    for (int i = 1; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : "";
        if (!strcmp(argv[i], "--ideal")) ideal = 1;
        else if (!strcmp(argv[i], "--verbose")) verbose = 1;
        else if (!strcmp(argv[i], "--model")) model = v, i++;
        else if (!strcmp(argv[i], "--world")) world = v, i++;
        else if (!strcmp(argv[i], "--model-path")) model_path = v, i++;
        else if (!strcmp(argv[i], "--to")) to = v, i++;
        else if (!strcmp(argv[i], "--k")) k = atoi(v), i++;
        else if (!strcmp(argv[i], "--views")) views = atoi(v), i++;
        else if (!strcmp(argv[i], "--threads")) threads = atoi(v), i++;
        else if (!strcmp(argv[i], "--map")) map = v, i++;
        /* costmap settings, to see how each one matters (the defaults are the library's) */
        else if (!strcmp(argv[i], "--band-lo")) co.band_lo_m = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--needs-floor")) co.free_needs_floor = atoi(v), i++;
        else if (!strcmp(argv[i], "--min-opacity")) co.min_opacity = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--despeckle")) co.despeckle_cells = atoi(v), i++;
        else if (!strcmp(argv[i], "--fill")) co.fill_max_area_m2 = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--slice")) co.slice_m = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--stop")) co.carve_stop_m = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--discretize")) co.carve_discretize = atoi(v), i++;
        else if (!strcmp(argv[i], "--floor-tol")) co.floor_tolerance_m = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--min-fresh")) co.carve_min_fresh = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--measure-floor")) co.measure_floor_tolerance = atoi(v), i++;
        else if (!strcmp(argv[i], "--carve-alpha")) co.carve_alpha = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--downscale")) co.carve_downscale = atoi(v), i++;
        else if (!strcmp(argv[i], "--occupancy")) co.occupancy = !strcmp(v, "scans") ? SP_OCCUPANCY_SCANS : SP_OCCUPANCY_FOOTPRINTS, i++;
        else if (!strcmp(argv[i], "--evidence")) co.occupied_evidence = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--veto")) co.pass_veto = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--lowest-needs-hit")) co.lowest_needs_hit = atoi(v), i++;
        else if (!strcmp(argv[i], "--hit-blocks-free")) co.hit_blocks_free = atoi(v), i++;
        else if (!strcmp(argv[i], "--hit-grow")) co.hit_grow_tol = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--faint-blocks-free")) co.faint_blocks_free = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--faint-grow")) co.faint_grow_tol = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--hit-above")) co.hit_above_m = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--unseen-unknown")) co.unseen_unknown = atoi(v), i++;
        else if (!strcmp(argv[i], "--veto-beside")) co.veto_beside = atoi(v), i++;
        else if (!strcmp(argv[i], "--free-from-floor")) co.free_from_floor = atoi(v), i++;
        else if (!strcmp(argv[i], "--hit-scans")) co.min_hit_scans = atoi(v), i++;
        else if (!strcmp(argv[i], "--prob-hit")) co.prob_hit = (float)atof(v), i++;
        else if (!strcmp(argv[i], "--prob-miss")) co.prob_miss = (float)atof(v), i++;
        else {
            fprintf(stderr, "bench_nav: unknown argument '%s'\n", argv[i]);
            return 2;
        }
    }
    if (!(model || (ideal && world))) {
        fprintf(stderr, "usage: bench_nav (--model DIR | --ideal) [--world W.world [--model-path DIR]] [--views N] "
                        "[--to NAME] [--k 3] [--threads N] [--map OUT.yaml]\n");
        return 2;
    }
    sp_error err = {0};
    sp_splat s;
    sp_camera *cams = NULL;
    size_t n = 0;
    ws_scene sc;
    memset(&sc, 0, sizeof sc);
    if (ideal) {
        if (ws_build(&sc, world, model_path, views, 160, 120, 0.07f, &err)) return fail(&err);
        s = sc.splat, cams = sc.cams, n = sc.n_cams;
    } else if (load_model(model, &s, &cams, &n, &err)) {
        return fail(&err);
    }
    sp_device *dev;
    sp_raster *r;
    if (sp_device_create(&dev, SP_DEVICE_CPU, threads, &err) || sp_raster_create(&r, dev, &err)) return fail(&err);
    sp_costmap cm;
    double t0 = sp_time_now(), la = load_average();
    clock_t k0 = clock();
    sp_log log = sp_log_stderr(SP_LOG_DEBUG, 0);
    if (sp_costmap_build(&cm, &s, cams, n, &co, r, verbose ? &log : NULL, &err)) return fail(&err);
    double t_build = sp_time_now() - t0, cpu = (double)(clock() - k0) / CLOCKS_PER_SEC;
    printf("costmap_build  %.0f ms  (%s; %s occupancy; %zu Gaussians, %zu views at 1/%d, %dx%d cells of %.2f m, %s; "
           "%.0f ms of CPU time over all threads; load average %.1f)\n", 1e3 * t_build, ideal ? "ideal splat" : model,
           co.occupancy == SP_OCCUPANCY_SCANS ? "scans" : "footprints", s.n, n, nav_carve_downscale(&co, &cams[0]),
           cm.nx, cm.ny, cm.res, sp_device_name(dev), 1e3 * cpu, la);
    printf("floor_z  %.3f m  (band %.2f..%.2f m above it)\n", cm.floor_z, cm.band[0] - cm.floor_z, cm.band[1] - cm.floor_z);
    if (map && sp_costmap_write_map(&cm, map, &err)) return fail(&err);
    sp_nav_opts no = sp_nav_opts_default();
    float start[3];
    if (nav_pick_start(&cm, cams, n, start, &err)) return fail(&err);
    printf("start  (%.2f, %.2f) yaw %.0f deg  (the default start: a training camera's floor position)\n", start[0],
           start[1], start[2] * 180 / M_PI);
    sp_nav_box goal_box = {{NAN, NAN}, {NAN, NAN}};
    if (world) {
        sp_world w;
        sp_synth_load_opts lo = {model_path, 1, 0, NULL};
        if (sp_synth_load_world(world, &lo, &w, &err)) return fail(&err);
        uint8_t *truth = malloc((size_t)cm.nx * cm.ny), *reach = malloc((size_t)cm.nx * cm.ny);
        /* the world's floor is z = 0; the costmap's band above it */
        if (sp_synth_floor_plan(&w, cm.band[0] - cm.floor_z, cm.band[1] - cm.floor_z, cm.res, cm.origin, cm.nx, cm.ny,
                                truth, &err) ||
            nt_reach(&cm, truth, start, co.robot_radius_m, reach, &err))
            return fail(&err);
        sp_costmap_agreement a;
        sp_costmap_compare(&cm, truth, &a);
        printf("costmap_agreement  %.2f %%  (%ld of %ld known cells; %.1f %% of the map known)\n", 100 * a.agreement,
               a.agree, a.known, 100 * a.known_fraction);
        printf("occupied_marked_free  %.2f %%  (%ld of %ld truly occupied cells)\n", 100 * a.occupied_free_rate,
               a.occupied_as_free, a.truth_occupied);
        printf("free_marked_occupied  %ld cells\n", a.free_as_occupied);
        if (map) {
            write_pgm(map, ".truth.pgm", &cm, truth, truth_pixel);
            write_pgm(map, ".costs.pgm", &cm, reach, cost_pixel);
        }
        objects_reached(&cm, &w, truth, reach, start, &no, verbose);
        for (size_t o = 0; o < w.n_objects; o++)
            if (!strcmp(w.objects[o].name, to))
                for (int d = 0; d < 2; d++) goal_box.min[d] = w.objects[o].aabb_min[d], goal_box.max[d] = w.objects[o].aabb_max[d];
        free(truth), free(reach);
        sp_world_free(&w);
    }
    if (isnan(goal_box.min[0])) {
        fprintf(stderr, "bench_nav: no object named '%s' (give --world and --to NAME) for the planning figure\n", to);
        return 1;
    }
    sp_nav_goal g = sp_nav_goal_box(goal_box.min, goal_box.max, no.approach_m);
    sp_path_set set;
    double best = INFINITY, best_cpu = INFINITY;
    for (int rep = 0; rep < 5; rep++) {
        t0 = sp_time_now();
        k0 = clock();
        if (sp_plan_k(&cm, start, &g, k, &no.planner, &set, &err)) return fail(&err);
        best = fmin(best, sp_time_now() - t0);
        best_cpu = fmin(best_cpu, (double)(clock() - k0) / CLOCKS_PER_SEC);
        if (rep < 4) sp_path_set_free(&set);
    }
    const sp_path *paths[64];
    for (int i = 0; i < set.n && i < 64; i++) paths[i] = &set.paths[i];
    printf("plan_k%d  %.1f ms  (best of 5, %.1f ms of CPU time; %d paths in %d planner runs from (%.2f, %.2f) to %s, "
           "%d distinctness violations; load average %.1f)\n", k, 1e3 * best, 1e3 * best_cpu, set.n, set.rounds,
           start[0], start[1], to, nt_distinct_violations(paths, set.n < 64 ? set.n : 64, &no.planner), load_average());
    for (int i = 0; i < set.n; i++)
        printf("  path %d  %.2f m  %d corners  share %.2f\n", i, set.paths[i].length_m, set.paths[i].n_corners, set.share[i]);
    if (set.note[0]) printf("  note: %s\n", set.note);
    sp_path_set_free(&set);
    sp_costmap_free(&cm);
    sp_raster_free(r);
    sp_device_free(dev);
    if (ideal) ws_free(&sc);
    else sp_splat_free(&s), free(cams);
    return 0;
}
