/* Navigation on the synth house with an ideal splat of its geometry (world_splat.h, label
 * features): the costmap against the world's floor plan (>= 95 % of known cells agree, <= 1 % of
 * truly occupied cells free); for every labelled floor-standing object reachable on the floor, a
 * path found through its phrase that never enters an occupied or unknown cell and ends within
 * 0.6 m of the object's true footprint in truly free space; the top 3 to the refrigerator obey
 * the distinctness rule; the written map reads back with unknown staying unknown. */
#include <stdio.h>

#include "nav/nav_internal.h"
#include "nav_truth.h"
#include "semsplat/nav.h"
#include "test.h"
#include "world_splat.h"

static ws_scene g_sc;
static sp_device *g_dev;
static sp_query_engine *g_engine;
static sp_nav *g_nav;
static uint8_t *g_truth;   /* the world's floor plan on the costmap's grid */
static uint8_t *g_reach;   /* truly free cells a robot centre reaches from the start */
static float g_start[3];

static void setup(void)
{
    sp_error err = {0};
    char world[1024];
    snprintf(world, sizeof world, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    double t0 = sp_time_now();
    CHECK_OK(ws_build(&g_sc, world, NULL, getenv("NAV_VIEWS") ? atoi(getenv("NAV_VIEWS")) : 120, 128, 96, getenv("NAV_SPACING") ? atof(getenv("NAV_SPACING")) : 0.07f, &err), &err);
    CHECK_OK(sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_query_engine_create(&g_engine,
                                    &(sp_query_model){.splat = &g_sc.splat, .pca = &g_sc.pca,
                                                      .cams = g_sc.cams, .n_cams = g_sc.n_cams},
                                    NULL, g_dev, NULL, &err), &err);
    sp_nav_opts o = sp_nav_opts_default();
    o.preview_width = 160, o.preview_height = 120;
    CHECK_OK(sp_nav_create(&g_nav, g_engine, NULL, NULL, 0, &o, g_dev, NULL, &err), &err);
    const sp_costmap *cm = sp_nav_costmap(g_nav);
    size_t n = (size_t)cm->nx * cm->ny;
    g_truth = malloc(n);
    CHECK_OK(sp_synth_floor_plan(&g_sc.w, o.costmap.band_lo_m, o.costmap.band_hi_m, cm->res, cm->origin, cm->nx,
                                 cm->ny, g_truth, &err), &err);
    CHECK_OK(sp_nav_default_start(g_nav, g_start, &err), &err);
    /* truly reachable: centre at least a robot radius from truly occupied cells, connected */
    g_reach = calloc(n, 1);
    CHECK_OK(nt_reach(cm, g_truth, g_start, o.costmap.robot_radius_m, g_reach, &err), &err);
    fprintf(stderr, "setup: %zu Gaussians, %zu cameras, %dx%d cells from (%.3f, %.3f), %.1f s\n", g_sc.splat.n,
            g_sc.n_cams, cm->nx, cm->ny, cm->origin[0], cm->origin[1], sp_time_now() - t0);
}

static void test_costmap_vs_floor_plan(void)
{
    sp_costmap_agreement a;
    sp_costmap_compare(sp_nav_costmap(g_nav), g_truth, &a);
    fprintf(stderr, "house (ideal splat): %.2f %% of %ld known cells agree (%.1f %% of the map known); %.2f %% "
            "of %ld truly occupied cells marked free\n", 100 * a.agreement, a.known, 100 * a.known_fraction,
            100 * a.occupied_free_rate, a.truth_occupied);
    CHECK(a.agreement >= 0.95);
    CHECK(a.occupied_free_rate <= 0.01);
    const char *dbg = getenv("NAV_DEBUG_PGM");
    if (dbg) { /* white/black agree, orange free marked occupied, red occupied marked free */
        const sp_costmap *cm = sp_nav_costmap(g_nav);
        FILE *f = fopen(dbg, "wb");
        fprintf(f, "P5\n%d %d\n255\n", cm->nx, cm->ny);
        for (int y = cm->ny - 1; y >= 0; y--)
            for (int x = 0; x < cm->nx; x++) {
                long i = (long)y * cm->nx + x;
                int t = g_truth[i], o = cm->occ[i];
                fputc(o == SP_CELL_UNKNOWN ? (t ? 100 : 205) : (o == SP_CELL_OCCUPIED) == t ? (t ? 0 : 254) : (t ? 60 : 150), f);
            }
        fclose(f);
    }
}

static void test_every_object(void)
{
    sp_error err = {0};
    const sp_costmap *cm = sp_nav_costmap(g_nav);
    int tried = 0, ok = 0, skipped = 0, misses = 0;
    for (size_t o = 0; o < g_sc.w.n_objects; o++) {
        const sp_synth_object *ob = &g_sc.w.objects[o];
        if (ob->is_structure || ob->aabb_min[2] > 0.1f) continue; /* floor-standing objects only */
        sp_nav_box truth = {{ob->aabb_min[0], ob->aabb_min[1]}, {ob->aabb_max[0], ob->aabb_max[1]}};
        if (!nt_box_reachable(cm, g_reach, &truth)) {
            fprintf(stderr, "  %-18s not reachable on the floor (ground truth): skipped\n", ob->name);
            skipped++;
            continue;
        }
        tried++;
        sp_nav_target t;
        CHECK_OK(sp_nav_resolve(g_nav, ob->class_name, &t, &err), &err);
        CHECK_MSG(t.found, "%s: '%s' not found", ob->name, ob->class_name);
        if (!t.found) continue;
        int best = 0;
        float c[2] = {0.5f * (truth.min[0] + truth.max[0]), 0.5f * (truth.min[1] + truth.max[1])};
        for (int k = 1; k < t.n; k++)
            if (hypotf(t.inst[k].position[0] - c[0], t.inst[k].position[1] - c[1]) <
                hypotf(t.inst[best].position[0] - c[0], t.inst[best].position[1] - c[1]))
                best = k;
        sp_nav_goal g = sp_nav_goal_box(t.inst[best].box.min, t.inst[best].box.max, sp_nav_options(g_nav)->approach_m);
        sp_path p;
        int rc = sp_plan_path(cm, g_start, &g, NULL, &p, &err);
        if (rc) {
            fprintf(stderr, "  %-18s MISS  %s\n", ob->name, err.msg);
            misses++;
            continue;
        }
        nt_verdict v = nt_judge(cm, g_truth, &truth, &p);
        ok += v.pass;
        fprintf(stderr, "  %-18s %s  %.2f m path, ends %.2f m from its footprint%s, %d non-free cells, %d truly "
                "occupied\n", ob->name, v.pass ? "ok  " : "FAIL", p.length_m, v.end_dist,
                v.end_free ? "" : " (truly occupied)", v.bad, v.truly_occupied);
        CHECK(v.bad == 0);
        CHECK(v.end_dist <= NT_REACH_M);
        CHECK(v.end_free);
        sp_path_free(&p);
    }
    fprintf(stderr, "objects: %d of %d reachable floor-standing objects reached (%d unreachable skipped)\n", ok,
            tried, skipped);
    CHECK(tried >= 20);
    /* The one miss allowed: the nightstand in the corner behind the bed, whose surroundings no
     * camera of this capture sees (the bedroom's one standpoint looks away from its own feet), so
     * the map keeps them unknown and no path may enter them. Every path found must be right. */
    CHECK(misses <= 1);
    CHECK(ok == tried - misses);
}

static void test_refrigerator_top3(void)
{
    sp_error err = {0};
    sp_nav_request req = sp_nav_request_default();
    req.to = "refrigerator";
    req.k = 3;
    sp_nav_plan plan;
    CHECK_OK(sp_nav_plan_request(g_nav, &req, &plan, &err), &err);
    fprintf(stderr, "refrigerator: %d of 3 (%s)\n", plan.n, plan.note);
    CHECK(plan.n == 3);
    const sp_path *paths[3];
    for (int i = 0; i < plan.n; i++) {
        paths[i] = &plan.traj[i].path;
        fprintf(stderr, "  %s %.2f m score %.3f, semantic %.3f\n", plan.traj[i].id, paths[i]->length_m,
                plan.traj[i].score.total, plan.traj[i].score.semantic);
        /* the kitchen's concepts, scored by the engine's per-Gaussian relevancy, seen on the way */
        CHECK(plan.traj[i].score.semantic > 0 && plan.traj[i].score.semantic <= 1);
        CHECK(plan.traj[i].n_previews == sp_nav_options(g_nav)->n_previews);
        CHECK(sp_nav_lookup(g_nav, plan.traj[i].id) != NULL);
    }
    CHECK(nt_distinct_violations(paths, plan.n, &sp_nav_options(g_nav)->planner) == 0);
    CHECK(sp_nav_lookup(g_nav, "plan-99.1") == NULL);
    /* the folder plan writes, and its map read back through its own thresholds */
    const char *dir = test_tmpdir("nav_house_plan");
    CHECK_OK(sp_nav_plan_write(g_nav, &plan, dir, &err), &err);
    char yaml[1200];
    snprintf(yaml, sizeof yaml, "%s/map.yaml", dir);
    sp_costmap back;
    CHECK_OK(sp_costmap_read_map(&back, yaml, NULL, &err), &err);
    const sp_costmap *cm = sp_nav_costmap(g_nav);
    long diff = 0, unknown = 0;
    for (long i = 0; i < (long)cm->nx * cm->ny; i++) diff += back.occ[i] != cm->occ[i], unknown += cm->occ[i] == SP_CELL_UNKNOWN;
    CHECK(diff == 0 && unknown > 0);
    sp_costmap_free(&back);
    char f[1200];
    snprintf(f, sizeof f, "%s/plan.json", dir);
    CHECK(sp_file_exists(f));
    snprintf(f, sizeof f, "%s/previews/t1_1.png", dir);
    CHECK(sp_file_exists(f));
    sp_nav_plan_free(&plan);
}

static void test_describe_dining_table(void)
{
    sp_error err = {0};
    sp_nav_description d;
    double t0 = sp_time_now();
    CHECK_OK(sp_nav_describe(g_nav, "dining table", 0, NULL, &d, &err), &err);
    int chairs = 0;
    for (int i = 0; i < d.n; i++) chairs += !strcmp(d.objects[i].name, "dining chair");
    fprintf(stderr, "describe (%d terms, %.1f s): %s\n", d.n_queried, sp_time_now() - t0, d.sentence);
    CHECK(chairs == 4);
    CHECK(strstr(d.sentence, "4 dining chairs") != NULL);
    CHECK(d.n_queried > 100);
    for (int i = 0; i < d.n; i++) CHECK(d.objects[i].distance_m <= sp_nav_options(g_nav)->near_m);
    char *js = sp_nav_description_json(&d);
    CHECK(js && strstr(js, "\"left of\"") && strstr(js, "\"dining room\""));
    free(js);
    sp_nav_description_free(&d);
    CHECK_FAILS(sp_nav_describe(g_nav, "grand piano", 0, NULL, &d, &err), SP_E_NOTFOUND, &err, "grand piano");
}

static void test_explore_kitchen(void)
{
    sp_error err = {0};
    sp_nav_tour t;
    double t0 = sp_time_now();
    CHECK_OK(sp_nav_explore(g_nav, "explore the area around the kitchen", NULL, &t, &err), &err);
    fprintf(stderr, "explore: %d views, %.0f %% covered, %.1f m tour, %.1f s (%s) %s\n", t.n, 100 * t.coverage,
            t.path.length_m, sp_time_now() - t0, t.target.source, t.note);
    CHECK(strncmp(t.target.source, "region: kitchen", 15) == 0);
    CHECK(t.n >= 2 && t.coverage >= 0.5f);
    const sp_costmap *cm = sp_nav_costmap(g_nav);
    for (int k = 0; k < t.n; k++) {
        int ix, iy;
        CHECK(sp_costmap_cell(cm, t.poses[4 * k], t.poses[4 * k + 1], &ix, &iy) == 0 && sp_costmap_traversable(cm, ix, iy));
        CHECK(t.poses[4 * k] >= t.area.min[0] - 1.01f && t.poses[4 * k] <= t.area.max[0] + 1.01f);
        CHECK(t.quality[k] >= 0 && t.quality[k] <= 1);
    }
    int bad, truly;
    nt_path_cells(cm, g_truth, &t.path, &bad, &truly);
    CHECK(bad == 0);
    const char *dir = test_tmpdir("nav_house_explore");
    CHECK_OK(sp_nav_tour_write(g_nav, &t, dir, &err), &err);
    sp_nav_tour_free(&t);
}

int main(void)
{
    setup();
    RUN(test_costmap_vs_floor_plan);
    RUN(test_every_object);
    RUN(test_refrigerator_top3);
    RUN(test_describe_dining_table);
    RUN(test_explore_kitchen);
    sp_nav_free(g_nav);
    sp_query_engine_free(g_engine);
    sp_device_free(g_dev);
    ws_free(&g_sc);
    free(g_truth), free(g_reach);
    return TEST_EXIT();
}
