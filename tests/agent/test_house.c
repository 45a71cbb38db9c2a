/* The agent end to end on the synth house with the real world adapter (query engine + nav) and
 * the offline robot, through the built-in brain. The map is the ideal splat nav's tests use
 * (tests/nav/world_splat.h: Gaussians on every visible triangle of data/worlds/house.world with
 * label features), so these figures measure the agent on a perfect reconstruction given a perfect
 * 2D segmentation, with the user's words matched to the scene's class names by WordNet (the
 * lexical encoder), not language understanding from images. The trained CPU demo model is
 * measured separately (docs/DESIGN.md, the agent section).
 *   - "go to the refrigerator": the position found within 0.3 m of the ground truth, the robot
 *     arrives beside it (within nav's approach distance of its true footprint);
 *   - "show me the top trajectories to the refrigerator": three ranked, each with previews on disk,
 *     the top-down map written, each a plan the session can drive;
 *   - "what objects are near the dining table?": its chairs among them;
 *   - "explore the area around the kitchen": waypoints in the kitchen;
 *   - "go to the chair": asks which (five chairs), and "the nearest one" then goes;
 *   - raw coordinates into a wall: refused by send_nav2_goal and by plan_path without tolerance;
 *   - render_view_from_splat writes a 640 x 480 view of the splat. */
#include <cjson/cJSON.h>

#include "agent/world_model.h"
#include "agent_test.h"
#include "nav/world_splat.h"
#include "test.h"

static ws_scene g_sc;
static sp_device *g_dev;
static sp_agent_session *g_s;
static const char *g_out;

/* The world's axis-aligned box of the first object of a class (ground truth). */
static int truth_box(const char *cls, float lo[3], float hi[3])
{
    for (size_t o = 0; o < g_sc.w.n_objects; o++)
        if (!strcmp(g_sc.w.objects[o].class_name, cls)) {
            memcpy(lo, g_sc.w.objects[o].aabb_min, sizeof(float) * 3);
            memcpy(hi, g_sc.w.objects[o].aabb_max, sizeof(float) * 3);
            return 1;
        }
    return 0;
}

static double box_dist(const float lo[3], const float hi[3], double x, double y)
{
    double dx = fmax(0, fmax(lo[0] - x, x - hi[0])), dy = fmax(0, fmax(lo[1] - y, y - hi[1]));
    return hypot(dx, dy);
}

static int g_drawn = -1; /* whether this build draws maps (Cairo), once known */

/* The top-down map is drawn with Cairo: without it (an optional dependency) plan.json says so
 * instead (folder_file; NULL: a tour, whose JSON does not, is checked only when maps are drawn). */
static void check_map(const cJSON *data, const char *folder_file)
{
    const cJSON *map = cJSON_GetObjectItemCaseSensitive(data, "map_image");
    if (cJSON_IsString(map)) {
        CHECK(sp_file_exists(map->valuestring));
        g_drawn = 1;
        return;
    }
    CHECK_MSG(folder_file || g_drawn == 0, "no map image");
    if (!folder_file) return;
    g_drawn = 0;
    char *text = NULL;
    size_t n;
    sp_error err = {0};
    CHECK_MSG(folder_file && sp_read_file(folder_file, &text, &n, &err) == 0 && strstr(text, "map_png_unavailable"),
              "no map image, and %s does not say why", folder_file ? folder_file : "(no folder)");
    free(text);
}

static void setup(void)
{
    sp_error err = {0};
    char world[1024];
    snprintf(world, sizeof world, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    double t0 = sp_time_now();
    CHECK_OK(ws_build(&g_sc, world, NULL, 120, 128, 96, 0.07f, &err), &err);
    CHECK_OK(sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err), &err);
    sp_query_engine *engine = NULL;
    CHECK_OK(sp_query_engine_create(&engine,
                                    &(sp_query_model){.splat = &g_sc.splat, .pca = &g_sc.pca,
                                                      .cams = g_sc.cams, .n_cams = g_sc.n_cams},
                                    NULL, g_dev, NULL, &err), &err);
    const char *classes[WS_MAX_CLASSES];
    for (int k = 0; k < g_sc.n_classes; k++) classes[k] = g_sc.classes[k];
    sp_nav_opts no = sp_nav_opts_default();
    no.preview_width = 160, no.preview_height = 120;
    g_out = test_tmpdir("agent_house");
    agent_world w;
    agent_world_parts parts = {engine, 1, g_dev, classes, g_sc.n_classes, &no, g_out, NULL};
    CHECK_OK(agent_world_from_parts(&w, &parts, &err), &err);
    float start[3];
    CHECK_OK(sp_nav_default_start(((model_world *)w.ctx)->nav, start, &err), &err);
    sp_agent_offline_opts oo = sp_agent_offline_opts_default();
    oo.start = (sp_agent_pose){start[0], start[1], 0, start[2]};
    sp_agent_robot robot;
    CHECK_OK(sp_agent_robot_offline(&robot, &oo, &err), &err);
    sp_agent_config cfg = sp_agent_config_default();
    cfg.out_dir = g_out;
    CHECK_OK(agent_session_open_world(&g_s, &cfg, w, robot, &err), &err);
    fprintf(stderr, "setup: %zu Gaussians, %d classes, robot at (%.2f, %.2f), %.1f s\n", g_sc.splat.n,
            g_sc.n_classes, start[0], start[1], sp_time_now() - t0);
}

static sp_agent_pose robot_pose(void)
{
    sp_agent_pose p;
    sp_error e;
    g_s->robot.ops->get_pose(g_s->robot.ctx, &p, &e);
    return p;
}

static int ask(const char *text, sp_agent_answer *a)
{
    sp_error err = {0};
    double t0 = sp_time_now();
    int rc = sp_agent_session_ask(g_s, text, a, &err);
    fprintf(stderr, "> %s (%.1f s)\n  %s\n", text, sp_time_now() - t0, a->text ? a->text : err.msg);
    CHECK_MSG(rc == 0, "%s: %s", text, err.msg);
    return rc;
}

static void test_trajectories(void)
{
    sp_agent_answer a;
    ask("show me the top trajectories to the refrigerator", &a);
    cJSON *r = result_of(&a, "show_trajectories");
    const cJSON *tr = cJSON_GetObjectItemCaseSensitive(data_of(r), "trajectories"), *t;
    CHECK_MSG(cJSON_GetArraySize(tr) == 3, "%d trajectories", cJSON_GetArraySize(tr));
    int rank = 0;
    cJSON_ArrayForEach(t, tr) {
        CHECK(cJSON_GetObjectItemCaseSensitive(t, "rank")->valuedouble == ++rank);
        const cJSON *pv = cJSON_GetObjectItemCaseSensitive(t, "previews"), *f;
        CHECK(cJSON_GetArraySize(pv) >= 2);
        cJSON_ArrayForEach(f, pv) CHECK_MSG(sp_file_exists(f->valuestring), "missing preview %s", f->valuestring);
        const cJSON *sc = cJSON_GetObjectItemCaseSensitive(t, "score");
        CHECK(cJSON_GetObjectItemCaseSensitive(sc, "localizability") && cJSON_GetObjectItemCaseSensitive(sc, "total"));
        CHECK(strncmp(cJSON_GetObjectItemCaseSensitive(t, "plan_id")->valuestring, "plan_", 5) == 0);
    }
    char plan_json[1200] = "";
    const cJSON *pv0 = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(tr, 0), "previews"), 0);
    if (cJSON_IsString(pv0)) { /* <folder>/previews/t1_1.png */
        snprintf(plan_json, sizeof plan_json, "%s", pv0->valuestring);
        char *cut = strstr(plan_json, "/previews/");
        if (cut) snprintf(cut, sizeof plan_json - (size_t)(cut - plan_json), "/plan.json");
    }
    check_map(data_of(r), plan_json);
    CHECK(a.n_images >= 12); /* 4 previews for each of 3 trajectories (and sheets and the map) */
    CHECK(strstr(a.text, "3 trajectories") != NULL);
    cJSON_Delete(r);
    sp_agent_answer_free(&a);
}

static void test_describe_dining_table(void)
{
    sp_agent_answer a;
    ask("what objects are near the dining table?", &a);
    cJSON *r = result_of(&a, "describe_surroundings");
    const cJSON *objs = cJSON_GetObjectItemCaseSensitive(data_of(r), "objects"), *o;
    int chairs = 0;
    cJSON_ArrayForEach(o, objs) chairs += !strcmp(cJSON_GetObjectItemCaseSensitive(o, "name")->valuestring, "dining chair");
    CHECK_MSG(chairs == 4, "%d dining chairs near the dining table", chairs);
    CHECK(strstr(a.text, "dining chair") != NULL);
    cJSON_Delete(r);
    sp_agent_answer_free(&a);
}

static void test_explore_kitchen(void)
{
    sp_agent_answer a;
    ask("explore the area around the kitchen", &a);
    cJSON *r = result_of(&a, "explore_region");
    const cJSON *wp = cJSON_GetObjectItemCaseSensitive(data_of(r), "waypoints"), *p;
    CHECK(cJSON_GetArraySize(wp) >= 2);
    /* the kitchen's floor in house.world: x 0..3.5, y 4.5..8 */
    cJSON_ArrayForEach(p, wp) {
        double x = cJSON_GetArrayItem(p, 0)->valuedouble, y = cJSON_GetArrayItem(p, 1)->valuedouble;
        CHECK_MSG(x >= 0 && x <= 3.5 && y >= 4.5 && y <= 8.0, "waypoint (%.2f, %.2f) is not in the kitchen", x, y);
    }
    check_map(data_of(r), NULL);
    cJSON_Delete(r);
    sp_agent_answer_free(&a);
}

static void test_chair_asks_which(void)
{
    sp_agent_pose before = robot_pose();
    sp_agent_answer a;
    ask("go to the chair", &a);
    CHECK(a.asked_back);
    CHECK(result_of(&a, "send_nav2_goal") == NULL && result_of(&a, "plan_path") == NULL);
    cJSON *q = result_of(&a, "query_object_location");
    int n = cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(data_of(q), "instances"));
    CHECK_MSG(n == 5, "%d chairs (4 dining chairs and the armchair)", n);
    CHECK(strstr(a.text, "chairs") && strstr(a.text, "Which"));
    cJSON_Delete(q);
    sp_agent_answer_free(&a);
    sp_agent_pose after = robot_pose();
    CHECK(agent_dist2d(before.x, before.y, after.x, after.y) < 1e-9);
    ask("the nearest one", &a); /* the answer to the question drives */
    cJSON *g = result_of(&a, "send_nav2_goal");
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(data_of(g), "status");
    CHECK(cJSON_IsString(st) && !strcmp(st->valuestring, "succeeded"));
    cJSON_Delete(g);
    sp_agent_answer_free(&a);
}

static void test_raw_goal_into_wall(void)
{
    double x = 1.25, y = 4.5; /* inside the wall between the living room and the kitchen
                               * (house.world's plaster_living_59 / plaster_kitchen_60): its
                               * faces are occupied, its middle (no ray reaches it, and at the
                               * default occupied_evidence 0.9 no footprint spills into it)
                               * occupied or unknown; refused either way, naming which */
    const int cell = g_s->world.ops->cell(g_s->world.ctx, x, y);
    CHECK_MSG(cell == AGENT_CELL_OCCUPIED || cell == AGENT_CELL_UNKNOWN, "the wall's cell is %d", cell);
    const char *cell_word = cell == AGENT_CELL_OCCUPIED ? "occupied" : "unknown";
    sp_agent_pose before = robot_pose();
    char args[256], code[64];
    int is_error;
    snprintf(args, sizeof args, "{\"x\": %.3f, \"y\": %.3f, \"yaw\": 0}", x, y);
    char *r = run_tool(g_s, "send_nav2_goal", args, &is_error);
    CHECK_MSG(is_error && !strcmp(error_code(r, code, sizeof code), "PLAN_REQUIRED") && strstr(r, cell_word), "%s", r);
    free(r);
    sp_agent_pose p = robot_pose();
    snprintf(args, sizeof args, "{\"start\": [%.3f, %.3f, 0, %.3f], \"goal\": [%.3f, %.3f], \"tolerance_m\": 0}",
             p.x, p.y, p.yaw, x, y);
    r = run_tool(g_s, "plan_path", args, &is_error);
    CHECK_MSG(is_error && !strcmp(error_code(r, code, sizeof code), "GOAL_OCCUPIED"), "%s", r);
    free(r);
    sp_agent_pose after = robot_pose();
    CHECK(agent_dist2d(before.x, before.y, after.x, after.y) < 1e-9);
}

static void test_render_view(void)
{
    int is_error;
    char *r = run_tool(g_s, "render_view_from_splat", "{\"pose\": [1.5, 6.0, 0.8, 1.57]}", &is_error);
    cJSON *j = cJSON_Parse(r);
    const cJSON *img = cJSON_GetObjectItemCaseSensitive(data_of(j), "image");
    CHECK_MSG(!is_error && cJSON_IsString(img), "%s", r);
    sp_image im = {0};
    sp_error err = {0};
    if (cJSON_IsString(img)) {
        CHECK_OK(sp_image_read(img->valuestring, &im, &err), &err);
        CHECK(im.width == 640 && im.height == 480);
        long lit = 0; /* the kitchen seen from its middle: mostly reconstructed, not background */
        const uint8_t *px = im.data;
        for (long i = 0; px && i < 640L * 480; i++) lit += px[3 * i] != 31 || px[3 * i + 1] != 31;
        CHECK_MSG(lit > 640L * 480 * 9 / 10, "%ld of %ld pixels show the splat", lit, 640L * 480);
        free(im.data);
    }
    cJSON_Delete(j);
    free(r);
}

static void test_go_to_refrigerator(void)
{
    float lo[3], hi[3];
    CHECK(truth_box("refrigerator", lo, hi));
    sp_agent_answer a;
    ask("go to the refrigerator", &a);
    cJSON *q = result_of(&a, "query_object_location"), *g = result_of(&a, "send_nav2_goal");
    const cJSON *pos = cJSON_GetObjectItemCaseSensitive(data_of(q), "position");
    double c[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    double err = cJSON_GetArraySize(pos) == 3 ? hypot(cJSON_GetArrayItem(pos, 0)->valuedouble - c[0],
                                                      cJSON_GetArrayItem(pos, 1)->valuedouble - c[1])
                                              : INFINITY;
    fprintf(stderr, "  refrigerator found %.3f m from its true centre\n", err);
    CHECK(err <= 0.3);
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(data_of(g), "status");
    CHECK(cJSON_IsString(st) && !strcmp(st->valuestring, "succeeded"));
    sp_agent_pose p = robot_pose();
    double d = box_dist(lo, hi, p.x, p.y);
    fprintf(stderr, "  the robot stopped %.2f m from the refrigerator's true footprint\n", d);
    CHECK(d <= sp_nav_options(((model_world *)g_s->world.ctx)->nav)->approach_m + 0.1);
    CHECK(strstr(a.text, "Arrived") != NULL);
    const cJSON *hm = cJSON_GetObjectItemCaseSensitive(data_of(q), "heatmap");
    CHECK(cJSON_IsString(hm) && sp_file_exists(hm->valuestring));
    CHECK(a.json_path[0] && sp_file_exists(a.json_path));
    cJSON_Delete(q), cJSON_Delete(g);
    sp_agent_answer_free(&a);
}

int main(void)
{
    double t0 = sp_time_now();
    sp_lexicon *lx = NULL;
    sp_error err = {0};
    if (sp_lexicon_open(&lx, NULL, &err)) TEST_SKIP(err.msg); /* WordNet (wordnet-base) */
    sp_lexicon_free(lx);
    setup();
    if (!g_s) return TEST_EXIT();
    RUN(test_trajectories);
    RUN(test_describe_dining_table);
    RUN(test_explore_kitchen);
    RUN(test_raw_goal_into_wall);
    RUN(test_render_view);
    RUN(test_chair_asks_which);
    RUN(test_go_to_refrigerator);
    sp_agent_session_close(g_s);
    sp_device_free(g_dev);
    ws_free(&g_sc);
    fprintf(stderr, "agent on the house: %.1f s\n", sp_time_now() - t0);
    return TEST_EXIT();
}
