/* The costmap: floor detection, footprints and carving against the room's boxes, Nav2's inflation
 * formula on core's distance transform, the map_server round trip (unknown
 * stays unknown; the 0.25 trap shown), the OccupancyGrid table, the goal check and bad input;
 * thin things, the measured floor tolerance (a low sill, a hazy floor), a faint thin surface
 * (faint_blocks_free), hidden cells inflated (unseen_unknown), cropped views. */
#include <stdio.h>

#include "nav/nav_internal.h"
#include "nav_scene.h"
#include "semsplat/nav.h"
#include "test.h"

static sp_costmap g_cm; /* the room's costmap, built once */
static sp_splat g_splat;

static void build_room_at(sp_costmap *cm, const sp_costmap_opts *o, int w, int h)
{
    sp_error err = {0};
    sp_camera *cams = NULL;
    size_t n = 0;
    CHECK(ns_make_cams(&cams, &n, w, h) == 0);
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    CHECK_OK(sp_costmap_build(cm, &g_splat, cams, n, o, r, NULL, &err), &err);
    sp_raster_free(r);
    sp_device_free(dev);
    free(cams);
}

static void build_room_with(sp_costmap *cm, const sp_costmap_opts *o) { build_room_at(cm, o, 160, 120); }

static void build_room(void)
{
    sp_error err = {0};
    CHECK_OK(ns_make_splat(&g_splat, 1, &err), &err);
    sp_costmap_opts o = sp_costmap_opts_default();
    build_room_with(&g_cm, &o);
}

/* The room's costmap against its boxes (what = the occupancy rule, for the messages). */
static void check_room(const sp_costmap *cm, const char *what)
{
    CHECK_NEAR(cm->floor_z, 0.0f, 0.01f);
    CHECK_NEAR(cm->res, 0.05f, 1e-6);
    /* inside the room, away from edges: free; the pillar and walls: occupied; outside: unknown */
    long agree = 0, known = 0, occ_marked_free = 0, occ_total = 0;
    for (int iy = 0; iy < cm->ny; iy++)
        for (int ix = 0; ix < cm->nx; ix++) {
            float p[2];
            sp_costmap_cell_center(cm, ix, iy, p);
            uint8_t v = cm->occ[nav_idx(cm, ix, iy)];
            float x = p[0] - NS_OFFX, y = p[1] - NS_OFFY, h = 0.5f * cm->res;
            int inside = x > 0 && x < 6 && y > 0 && y < 4;
            if (!inside) {
                /* behind the walls nobody looked */
                if (x < -0.1f || x > 6.1f || y < -0.1f || y > 4.1f)
                    CHECK_MSG(v != SP_CELL_FREE, "cell (%.2f, %.2f) outside the room is free", p[0], p[1]);
                continue;
            }
            int truth = ns_truth_cell(p[0] - h, p[1] - h, p[0] + h, p[1] + h, 1);
            if (truth) occ_total++;
            if (v == SP_CELL_UNKNOWN) continue;
            known++;
            if ((v == SP_CELL_OCCUPIED) == truth) agree++;
            else if (getenv("NAV_DEBUG")) fprintf(stderr, "disagree (%.3f, %.3f) ours %d truth %d dist %.3f\n", x, y, v, truth, cm->dist[nav_idx(cm, ix, iy)]);
            if (truth && v == SP_CELL_FREE) occ_marked_free++;
        }
    fprintf(stderr, "room (%s): %ld of %ld known cells agree, %ld of %ld occupied marked free\n", what, agree,
            known, occ_marked_free, occ_total);
    CHECK(known > 0.9 * 6 / 0.05 * 4 / 0.05 * 0.85);
    CHECK(agree >= 0.95 * known);
    CHECK(occ_marked_free <= 0.01 * occ_total);
    int ix, iy;
    CHECK(sp_costmap_cell(cm, 1.5f, 1.0f, &ix, &iy) == 0);
    CHECK(cm->occ[nav_idx(cm, ix, iy)] == SP_CELL_FREE);
    CHECK(sp_costmap_cell(cm, 3.0f, 2.0f, &ix, &iy) == 0);
    CHECK(cm->occ[nav_idx(cm, ix, iy)] == SP_CELL_OCCUPIED);
    /* the table top (0.7 m) is inside the 0.05..1.0 m band */
    CHECK(sp_costmap_cell(cm, 4.8f, 0.9f, &ix, &iy) == 0);
    CHECK(cm->occ[nav_idx(cm, ix, iy)] == SP_CELL_OCCUPIED);
}

static void test_floor_and_cells(void) { check_room(&g_cm, "footprints, the default"); }

/* The other occupancy rule: the training views' scans alone, fused as log-odds. */
static void test_scans_occupancy(void)
{
    sp_costmap_opts o = sp_costmap_opts_default();
    o.occupancy = SP_OCCUPANCY_SCANS;
    sp_costmap cm;
    build_room_with(&cm, &o);
    check_room(&cm, "scans");
    sp_costmap_free(&cm);
}

static void test_inflation_formula(void)
{
    /* cost of each cell equals Nav2's computeCost of its distance */
    const sp_costmap_opts *o = &g_cm.opts;
    long checked = 0;
    for (long i = 0; i < (long)g_cm.nx * g_cm.ny; i++) {
        if (g_cm.occ[i] != SP_CELL_FREE) continue;
        float d = g_cm.dist[i];
        int expect = d <= o->robot_radius_m ? 253
                     : d > o->inflation_radius_m ? 0
                     : (int)(252 * exp(-o->cost_scaling_factor * (d - o->robot_radius_m)));
        if (g_cm.cost[i] == 253 && expect < 253) continue; /* near unknown: keep_clear_of_unknown */
        CHECK_MSG(g_cm.cost[i] == expect, "cell %ld: d %.3f cost %d, expected %d", i, d, g_cm.cost[i], expect);
        checked++;
    }
    CHECK(checked > 1000);
    for (long i = 0; i < (long)g_cm.nx * g_cm.ny; i++) {
        if (g_cm.occ[i] == SP_CELL_OCCUPIED) CHECK(g_cm.cost[i] == SP_COST_LETHAL);
        if (g_cm.occ[i] == SP_CELL_UNKNOWN) CHECK(g_cm.cost[i] == SP_COST_UNKNOWN);
    }
    /* the worked table of the reference: inscribed 0.2 m, csf 10 */
    sp_costmap_opts t = sp_costmap_opts_default();
    t.cost_scaling_factor = 10;
    t.inflation_radius_m = 2.0f;
    const float d[6] = {0.25f, 0.30f, 0.40f, 0.50f, 0.75f, 1.00f};
    const int expect[6] = {152, 92, 34, 12, 1, 0};
    for (int k = 0; k < 6; k++)
        CHECK_NEAR((int)(252 * exp(-t.cost_scaling_factor * (d[k] - t.robot_radius_m))), expect[k], 0);
}

static void test_map_roundtrip(void)
{
    sp_error err = {0};
    char yaml[1024];
    snprintf(yaml, sizeof yaml, "%s/map.yaml", test_tmpdir("nav_map"));
    CHECK_OK(sp_costmap_write_map(&g_cm, yaml, &err), &err);
    sp_costmap back;
    CHECK_OK(sp_costmap_read_map(&back, yaml, &g_cm.opts, &err), &err);
    CHECK(back.nx == g_cm.nx && back.ny == g_cm.ny);
    CHECK_NEAR(back.origin[0], g_cm.origin[0], 1e-5);
    CHECK_NEAR(back.origin[1], g_cm.origin[1], 1e-5);
    long diff = 0, unknown = 0;
    for (long i = 0; i < (long)g_cm.nx * g_cm.ny; i++) {
        diff += back.occ[i] != g_cm.occ[i];
        unknown += g_cm.occ[i] == SP_CELL_UNKNOWN;
    }
    CHECK(diff == 0);
    CHECK(unknown > 100);
    sp_costmap_free(&back);
    /* the map_saver trap: the same image with free_thresh 0.25 reads unknown (205) as free */
    char yaml2[1024], text[512];
    snprintf(yaml2, sizeof yaml2, "%s", yaml);
    snprintf(strrchr(yaml2, '/'), 16, "/trap.yaml");
    snprintf(text, sizeof text, "image: map.pgm\nresolution: %g\norigin: [%g, %g, 0]\nnegate: 0\n"
             "occupied_thresh: 0.65\nfree_thresh: 0.25\n", g_cm.res, g_cm.origin[0], g_cm.origin[1]);
    CHECK_OK(sp_write_file_atomic(yaml2, text, strlen(text), &err), &err);
    CHECK_OK(sp_costmap_read_map(&back, yaml2, NULL, &err), &err);
    long became_free = 0;
    for (long i = 0; i < (long)g_cm.nx * g_cm.ny; i++)
        became_free += g_cm.occ[i] == SP_CELL_UNKNOWN && back.occ[i] == SP_CELL_FREE;
    CHECK(became_free == unknown);
    sp_costmap_free(&back);
    /* block-style origin, negate as a bool, scale mode */
    snprintf(text, sizeof text, "image: \"map.pgm\"\nmode: scale\nresolution: 0.05\norigin:\n  - 1.5\n"
             "  - -2\n  - 0\nnegate: false\noccupied_thresh: 0.65\nfree_thresh: 0.19\n");
    CHECK_OK(sp_write_file_atomic(yaml2, text, strlen(text), &err), &err);
    CHECK_OK(sp_costmap_read_map(&back, yaml2, NULL, &err), &err);
    CHECK_NEAR(back.origin[0], 1.5, 1e-6);
    CHECK_NEAR(back.origin[1], -2.0, 1e-6);
    sp_costmap_free(&back);
}

static void test_bad_maps(void)
{
    sp_error err = {0};
    const char *dir = test_tmpdir("nav_badmap");
    char yaml[1024];
    snprintf(yaml, sizeof yaml, "%s/bad.yaml", dir);
    const char *cases[][2] = {
        {"image: map.pgm\nresolution: 0.05\norigin: [0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "3 elements"},
        {"image: map.pgm\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "resolution"},
        {"image: map.pgm\nresolution: abc\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "not a number"},
        {"image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0.5]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "yaw"},
        {"image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "missing.pgm"},
        {"image: trunc.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "truncated"},
        /* found by fuzzing: equal thresholds (scale mode divided by 0), an origin no float holds */
        {"image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.4\nfree_thresh: 0.4\n", "free_thresh <"},
        {"image: map.pgm\nresolution: 0.05\norigin: [1e40, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "1000 km"},
        {"image: map.pgm\nresolution: 1e-9\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.19\n", "outside"},
    };
    char pgm[1024];
    snprintf(pgm, sizeof pgm, "%s/trunc.pgm", dir);
    CHECK_OK(sp_write_file_atomic(pgm, "P5\n10 10\n255\n\x01\x02", 15, &err), &err);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        CHECK_OK(sp_write_file_atomic(yaml, cases[k][0], strlen(cases[k][0]), &err), &err);
        sp_costmap cm;
        int rc = sp_costmap_read_map(&cm, yaml, NULL, &err);
        CHECK_MSG(rc < 0 && strstr(err.msg, cases[k][1]), "case %zu: rc %d, '%s'", k, rc, err.msg);
        CHECK(cm.occ == NULL);
    }
}

static void test_occupancy_grid(void)
{
    size_t n = (size_t)g_cm.nx * g_cm.ny;
    int8_t *map = malloc(n), *costs = malloc(n);
    sp_costmap_to_occupancy_grid(&g_cm, 0, map);
    sp_costmap_to_occupancy_grid(&g_cm, 1, costs);
    for (size_t i = 0; i < n; i++) {
        int8_t e = g_cm.occ[i] == SP_CELL_UNKNOWN ? -1 : g_cm.occ[i] == SP_CELL_OCCUPIED ? 100 : 0;
        CHECK(map[i] == e);
        uint8_t c = g_cm.cost[i];
        int ec = c == 255 ? -1 : c == 254 ? 100 : c == 253 ? 99 : c == 0 ? 0 : 1 + 97 * (c - 1) / 251;
        CHECK(costs[i] == ec);
        CHECK(costs[i] >= -1 && costs[i] <= 100);
    }
    free(map), free(costs);
}

static void test_goal_check(void)
{
    char why[256];
    float s[2] = {1.0f, 1.0f};
    float ok[2] = {5.0f, 3.0f}, wall[2] = {3.0f, 2.0f}, outside[2] = {-3.0f, 0.5f}, behind[2] = {6.3f, 2.0f};
    CHECK(sp_costmap_check_goal(&g_cm, s, ok, why, sizeof why) == SP_NAV_OK);
    CHECK(sp_costmap_check_goal(&g_cm, s, wall, why, sizeof why) == SP_NAV_GOAL_OCCUPIED);
    CHECK(strstr(why, "occupied") != NULL);
    CHECK(sp_costmap_check_goal(&g_cm, s, outside, why, sizeof why) == SP_NAV_GOAL_OUTSIDE_MAP);
    int st = sp_costmap_check_goal(&g_cm, s, behind, why, sizeof why);
    CHECK_MSG(st == SP_NAV_GOAL_OCCUPIED || st == SP_NAV_GOAL_OUTSIDE_MAP, "%d %s", st, why);
    CHECK(sp_costmap_check_goal(&g_cm, wall, ok, why, sizeof why) == SP_NAV_START_OCCUPIED);
}

static void test_bad_build(void)
{
    sp_error err = {0};
    sp_costmap cm;
    sp_costmap_opts o = sp_costmap_opts_default();
    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, &cam, 0, &o, NULL, NULL, &err), SP_E_ARG, &err, "camera");
    o.band_hi_m = o.band_lo_m;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, &cam, 1, &o, NULL, NULL, &err), SP_E_ARG, &err, "band");
    o = sp_costmap_opts_default();
    o.resolution_m = 0.0005f;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, &cam, 1, &o, NULL, NULL, &err), SP_E_ARG, &err, "resolution");
    o = sp_costmap_opts_default();
    o.occupancy = 7;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, &cam, 1, &o, NULL, NULL, &err), SP_E_ARG, &err, "occupancy");
    o = sp_costmap_opts_default();
    o.prob_miss = 0.6f;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, &cam, 1, &o, NULL, NULL, &err), SP_E_ARG, &err, "prob_miss");
    o = sp_costmap_opts_default();
    o.carve_discretize = 5;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, &cam, 1, &o, NULL, NULL, &err), SP_E_ARG, &err, "carve_discretize");
    o = sp_costmap_opts_default();
    o.robot_radius_m = 2.0f;
    CHECK_FAILS(sp_costmap_inflate(&g_cm, &o, &err), SP_E_ARG, &err, "radius");
    /* a NaN in the splat, a camera with a broken pose */
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 1, &err), &err);
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    sp_camera *cams = NULL;
    size_t n = 0;
    CHECK(ns_make_cams(&cams, &n, 32, 24) == 0);
    o = sp_costmap_opts_default();
    float keep = g_splat.means[7];
    g_splat.means[7] = NAN;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, cams, n, &o, r, NULL, &err), SP_E_NUMERIC, &err, "costmap");
    g_splat.means[7] = keep;
    cams[3].t[1] = INFINITY;
    CHECK_FAILS(sp_costmap_build(&cm, &g_splat, cams, n, &o, r, NULL, &err), SP_E_ARG, &err, "camera 3");
    free(cams);
    sp_raster_free(r);
    sp_device_free(dev);
}

/* Thin things: legs (3 cm square posts 0.45 m tall, a chair's) and a 1 cm panel seen edge-on
 * by some views, one Gaussian across each face (as a reconstruction has them). The rays pass
 * beside them through the 5 cm cells they stand in, and their rendered surface points (each
 * Gaussian's depth), good to about a cell, often land in the cell beside; with veto_beside a
 * scan that hit a voxel beside one does not count as having seen through it. */
static const ns_box thin_things[] = {
    {{1.80f, 2.00f, 0.0f}, {1.83f, 2.03f, 0.45f}}, {{2.20f, 1.20f, 0.0f}, {2.23f, 1.23f, 0.45f}},
    {{4.00f, 2.00f, 0.0f}, {4.03f, 2.03f, 0.45f}}, {{3.80f, 2.80f, 0.0f}, {3.83f, 2.83f, 0.45f}},
    {{1.50f, 3.40f, 0.0f}, {1.53f, 3.43f, 0.45f}}, {{5.00f, 3.00f, 0.0f}, {5.03f, 3.03f, 0.45f}},
    {{1.40f, 1.50f, 0.0f}, {2.20f, 1.51f, 0.50f}}, {{4.60f, 1.80f, 0.0f}, {4.61f, 2.60f, 0.50f}}};
#define N_THIN ((int)(sizeof thin_things / sizeof thin_things[0]))

/* The cells boxes b[0..n) overlap that are occupied, of *total. */
static int boxes_occupied(const sp_costmap *cm, const ns_box *b, int n, int *total)
{
    int occ = 0;
    *total = 0;
    for (int k = 0; k < n; k++)
        for (int iy = 0; iy < cm->ny; iy++)
            for (int ix = 0; ix < cm->nx; ix++) {
                float x0 = cm->origin[0] + ix * cm->res - NS_OFFX, y0 = cm->origin[1] + iy * cm->res - NS_OFFY;
                if (!ns_overlap(&b[k], x0, y0, x0 + cm->res, y0 + cm->res)) continue;
                (*total)++;
                occ += cm->occ[nav_idx(cm, ix, iy)] == SP_CELL_OCCUPIED;
            }
    return occ;
}

static void test_thin_things(void)
{
    sp_error err = {0};
    sp_splat s;
    CHECK_OK(ns_make_splat(&s, 1, &err), &err);
    size_t n = s.n;
    for (int k = 0; k < N_THIN; k++) ns_box_faces(&s, &n, 200000, &thin_things[k], 0.05f);
    s.n = n;
    sp_splat keep = g_splat;
    g_splat = s;
    int occ[2], total = 0;
    for (int beside = 0; beside < 2; beside++) {
        sp_costmap cm;
        sp_costmap_opts o = sp_costmap_opts_default();
        o.veto_beside = beside;
        build_room_at(&cm, &o, 160, 120);
        occ[beside] = boxes_occupied(&cm, thin_things, N_THIN, &total);
        fprintf(stderr, "thin things (veto_beside %d): %d of %d cells occupied\n", beside, occ[beside], total);
        CHECK_MSG(!beside || occ[beside] == total, "%d of the %d cells under thin things are not occupied",
                  total - occ[beside], total);
        sp_costmap_free(&cm);
    }
    g_splat = keep;
    sp_splat_free(&s);
}

/* A sill: 9 cm tall, lower than the 0.15 m cap on the floor tolerance. The room's floor renders
 * within a centimetre or two, so the measured tolerance is a few centimetres and the sill's top
 * is a hit in the band: its cells occupied. With the cap (measure_floor_tolerance 0) the top is
 * floor and the rays passing over it through the lowest slice make it free (the bookstore's shop
 * window frame). Haze over the floor (faint Gaussians up to 12 cm, a CPU-trained floor) widens
 * the rendered floor and the measured tolerance with it. */
static const ns_box sill = {{3.8f, 2.40f, 0.0f}, {5.0f, 2.44f, 0.09f}};

static void add_haze(sp_splat *s, size_t *n, size_t cap)
{
    uint32_t seed = 12345;
    for (int k = 0; k < 6000 && *n < cap; k++) {
        float r[3];
        for (int j = 0; j < 3; j++) {
            seed = seed * 1664525u + 1013904223u;
            r[j] = (float)(seed >> 8) / 16777216.0f;
        }
        float p[3] = {0.3f + 5.4f * r[0], 0.3f + 3.4f * r[1], 0.12f * r[2]};
        size_t i = *n;
        ns_push(s, n, p, 2, 0.04f);
        s->log_scales[3 * i + 2] = logf(0.02f);
        s->opacity_logits[i] = -0.5f;
    }
}

static void test_floor_tolerance(void)
{
    sp_error err = {0};
    sp_splat s;
    CHECK_OK(ns_make_splat(&s, 1, &err), &err);
    size_t n = s.n, plain;
    ns_box_faces(&s, &n, 200000, &sill, 0.02f);
    s.n = plain = n;
    sp_splat keep = g_splat;
    g_splat = s;
    int occ[2], total = 0;
    float tol[3];
    for (int measure = 0; measure < 2; measure++) {
        sp_costmap cm;
        sp_costmap_opts o = sp_costmap_opts_default();
        o.measure_floor_tolerance = measure;
        build_room_at(&cm, &o, 160, 120);
        occ[measure] = boxes_occupied(&cm, &sill, 1, &total);
        tol[measure] = cm.opts.floor_tolerance_m;
        fprintf(stderr, "sill (measure_floor_tolerance %d, tolerance %.2f m): %d of %d cells occupied\n", measure,
                tol[measure], occ[measure], total);
        sp_costmap_free(&cm);
    }
    CHECK_NEAR(tol[0], 0.15f, 1e-6);
    CHECK_MSG(tol[1] <= 0.06f, "a sharp floor measured %.2f m thick", tol[1]);
    CHECK_MSG(total > 0 && occ[1] == total, "%d of the sill's %d cells are not occupied", total - occ[1], total);
    add_haze(&s, &n, 200000);
    s.n = n;
    g_splat = s;
    sp_costmap cm;
    build_room_at(&cm, NULL, 160, 120);
    tol[2] = cm.opts.floor_tolerance_m;
    fprintf(stderr, "hazy floor (%zu faint Gaussians): tolerance %.2f m\n", n - plain, tol[2]);
    CHECK_MSG(tol[2] >= tol[1] + 0.04f, "haze up to 0.12 m: tolerance %.2f m (sharp floor %.2f)", tol[2], tol[1]);
    sp_costmap_free(&cm);
    g_splat = keep;
    sp_splat_free(&s);
}

/* A thin surface the views render too faintly to stop a ray (a trained table top of a few faint
 * Gaussians, summed opacity well under 0.5): every ray sees through it, so without
 * faint_blocks_free its cells are free; with it (the default) its footprint evidence, at least 0.1
 * but under occupied_evidence, makes them unknown. hit_blocks_free is off in both runs. */
static const ns_box faint_top = {{1.6f, 2.4f, 0.6f}, {2.4f, 3.0f, 0.6f}};

static void test_faint_surface(void)
{
    sp_error err = {0};
    sp_splat s;
    CHECK_OK(ns_make_splat(&s, 1, &err), &err);
    size_t n = s.n;
    for (float x = faint_top.lo[0] + 0.05f; x < faint_top.hi[0]; x += 0.1f)
        for (float y = faint_top.lo[1] + 0.05f; y < faint_top.hi[1]; y += 0.1f) {
            float p[3] = {x, y, faint_top.lo[2]};
            size_t i = n;
            ns_push(&s, &n, p, 2, 0.06f);
            s.opacity_logits[i] = -1.4f; /* opacity 0.2 */
        }
    s.n = n;
    sp_splat keep = g_splat;
    g_splat = s;
    int n_free[2] = {0, 0}, total = 0;
    for (int faint = 0; faint < 2; faint++) {
        sp_costmap cm;
        sp_costmap_opts o = sp_costmap_opts_default();
        o.hit_blocks_free = 0;
        if (!faint) o.faint_blocks_free = 0;
        build_room_at(&cm, &o, 160, 120);
        total = 0;
        for (int iy = 0; iy < cm.ny; iy++)
            for (int ix = 0; ix < cm.nx; ix++) {
                float x0 = cm.origin[0] + ix * cm.res - NS_OFFX, y0 = cm.origin[1] + iy * cm.res - NS_OFFY;
                if (!ns_overlap(&faint_top, x0, y0, x0 + cm.res, y0 + cm.res)) continue;
                total++;
                n_free[faint] += cm.occ[nav_idx(&cm, ix, iy)] == SP_CELL_FREE;
            }
        sp_costmap_free(&cm);
    }
    fprintf(stderr, "faint table top: %d of %d cells free without faint_blocks_free, %d with it\n", n_free[0],
            total, n_free[1]);
    CHECK_MSG(n_free[0] > total / 2, "without the rule only %d of %d cells free: the test shows nothing", n_free[0],
              total);
    CHECK_MSG(n_free[1] == 0, "%d of the faint top's %d cells are free", n_free[1], total);
    g_splat = keep;
    sp_splat_free(&s);
}

/* cm->hidden (unseen_unknown): an unknown cell where Gaussians no ray observed stand is inflated
 * as an obstacle is (its own cost stays unknown), and sp_costmap_copy keeps it. */
static void test_hidden_inflated(void)
{
    sp_error err = {0};
    sp_costmap cm;
    memset(&cm, 0, sizeof cm);
    cm.nx = cm.ny = 21, cm.res = 0.05f, cm.opts = sp_costmap_opts_default(); /* robot radius 0.2 m */
    size_t n = 21 * 21;
    cm.occ = calloc(n, 1), cm.cost = malloc(n), cm.dist = malloc(n * sizeof(float)), cm.hidden = calloc(n, 1);
    long mid = 10 * 21 + 10;
    cm.occ[mid] = SP_CELL_UNKNOWN, cm.hidden[mid] = 1;
    CHECK_OK(sp_costmap_inflate(&cm, NULL, &err), &err);
    CHECK(cm.cost[mid] == SP_COST_UNKNOWN);
    CHECK_NEAR(cm.dist[mid + 1], 0.05f, 1e-6);
    CHECK(cm.cost[mid + 1] == SP_COST_INSCRIBED);
    CHECK(cm.cost[mid + 21 * 4] == SP_COST_INSCRIBED); /* 0.2 m: the robot radius */
    CHECK(cm.cost[mid + 21 * 5] < SP_COST_INSCRIBED);
    sp_costmap c2;
    CHECK_OK(sp_costmap_copy(&c2, &cm, &err), &err);
    CHECK(c2.hidden && c2.hidden[mid] == 1 && c2.hidden[mid + 1] == 0);
    sp_costmap_free(&c2);
    cm.hidden[mid] = 0; /* a plain unknown cell is not inflated (Nav2's inflate_around_unknown off) */
    CHECK_OK(sp_costmap_inflate(&cm, NULL, &err), &err);
    CHECK(cm.cost[mid + 1] == SP_COST_FREE);
    sp_costmap_free(&cm);
}

/* Views from above the band are cropped to the rows whose rays fall (only when no view counts
 * are asked for, which need every pixel): the map is the same as from the whole views (cells may
 * differ by float rounding of the shifted principal point: at most 0.1 %). */
static void test_crop_same(void)
{
    sp_error err = {0};
    sp_camera *cams = NULL;
    size_t n = 0;
    CHECK(ns_make_cams(&cams, &n, 160, 120) == 0);
    for (size_t c = 0; c < n; c++) /* the camera 0.4 m higher: t -= R (0, 0, 0.4) */
        for (int i = 0; i < 3; i++) cams[c].t[i] -= cams[c].R[3 * i + 2] * 0.4f;
    CHECK_NEAR(sp_camera_center(&cams[0]).z, 1.4f, 1e-4);
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    sp_costmap a, b;
    uint16_t *counts = calloc(g_splat.n, sizeof(uint16_t));
    CHECK_OK(nav_costmap_build(&a, &g_splat, cams, n, NULL, r, NULL, NULL, &err), &err);
    CHECK_OK(nav_costmap_build(&b, &g_splat, cams, n, NULL, r, counts, NULL, &err), &err);
    CHECK(a.nx == b.nx && a.ny == b.ny);
    long differ = 0, cells = (long)a.nx * a.ny, n_free = 0;
    for (long i = 0; i < cells && a.nx == b.nx && a.ny == b.ny; i++) differ += a.occ[i] != b.occ[i], n_free += a.occ[i] == SP_CELL_FREE;
    fprintf(stderr, "cropped views: %ld of %ld cells differ (%ld free)\n", differ, cells, n_free);
    CHECK(differ <= cells / 1000);
    CHECK(n_free > cells / 4);
    sp_costmap_free(&a), sp_costmap_free(&b);
    free(counts);
    sp_raster_free(r);
    sp_device_free(dev);
    free(cams);
}

int main(void)
{
    build_room();
    RUN(test_floor_and_cells);
    RUN(test_scans_occupancy);
    RUN(test_thin_things);
    RUN(test_floor_tolerance);
    RUN(test_faint_surface);
    RUN(test_hidden_inflated);
    RUN(test_crop_same);
    RUN(test_inflation_formula);
    RUN(test_map_roundtrip);
    RUN(test_bad_maps);
    RUN(test_occupancy_grid);
    RUN(test_goal_check);
    RUN(test_bad_build);
    sp_costmap_free(&g_cm);
    sp_splat_free(&g_splat);
    return TEST_EXIT();
}
