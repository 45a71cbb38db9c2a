/* The dialogue loop with the built-in brain on the fake house world and the offline robot: the
 * four example commands, ambiguity and "nothing matched", and the commitments (raw coordinates
 * refused, plans from this session only, stale plans, distance limit, confirmation, cancel,
 * speed clamp), plus structured errors for invalid arguments. */
#include <cjson/cJSON.h>

#include "agent_test.h"
#include "fake_world.h"
#include "test.h"

static sp_agent_session *open_session(sp_agent_config *cfg, const char *name, double x, double y,
                                      fake_world **fw)
{
    sp_agent_offline_opts o = sp_agent_offline_opts_default();
    o.start.x = x, o.start.y = y;
    sp_agent_robot robot;
    sp_error err = {0};
    CHECK_OK(sp_agent_robot_offline(&robot, &o, &err), &err);
    cfg->out_dir = test_tmpdir(name);
    sp_agent_session *s = NULL;
    CHECK_OK(agent_session_open_world(&s, cfg, fw_world(fw), robot, &err), &err);
    return s;
}

static sp_agent_session *open_default(const char *name, fake_world **fw)
{
    sp_agent_config cfg = sp_agent_config_default();
    return open_session(&cfg, name, 3.0, 1.8, fw);
}

static sp_agent_pose pose_of(sp_agent_session *s)
{
    sp_agent_pose p;
    sp_error e;
    s->robot.ops->get_pose(s->robot.ctx, &p, &e);
    return p;
}

static void test_go_to_refrigerator(void)
{
    fake_world *fw;
    sp_agent_session *s = open_default("go_fridge", &fw);
    sp_agent_answer a;
    sp_error err = {0};
    CHECK_OK(sp_agent_session_ask(s, "go to the refrigerator", &a, &err), &err);
    CHECK(a.n_trace == 4);
    if (a.n_trace == 4) {
        CHECK(!strcmp(a.trace[0].tool, "query_object_location"));
        CHECK(!strcmp(a.trace[1].tool, "get_robot_pose"));
        CHECK(!strcmp(a.trace[2].tool, "plan_path"));
        CHECK(!strcmp(a.trace[3].tool, "send_nav2_goal"));
    }
    cJSON *q = result_of(&a, "query_object_location"), *g = result_of(&a, "send_nav2_goal");
    double pos[3] = {0};
    const cJSON *p = cJSON_GetObjectItemCaseSensitive(data_of(q), "position");
    for (int i = 0; i < 3; i++) pos[i] = cJSON_GetArrayItem(p, i)->valuedouble;
    CHECK_NEAR(hypot(pos[0] - 0.45, pos[1] - 7.55), 0, 1e-6); /* the fake's fridge */
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(data_of(g), "status");
    CHECK(cJSON_IsString(st) && !strcmp(st->valuestring, "succeeded"));
    sp_agent_pose end = pose_of(s);
    agent_instance fridge = {.position = {0.45, 7.55, 0.9}, .extent_min = {0.1, 7.2, 0}, .extent_max = {0.8, 7.9, 1.8}};
    double d = agent_dist_to_footprint(&fridge, end.x, end.y);
    CHECK_MSG(d <= SP_AGENT_DEFAULT_TOLERANCE_M + 0.05, "robot ends %.2f m from the fridge", d);
    CHECK_MSG(fw_cell_at(fw, end.x, end.y) == AGENT_CELL_FREE, "robot ends in a %s cell", agent_cell_name(fw_cell_at(fw, end.x, end.y)));
    CHECK(strstr(a.text, "Arrived") != NULL);
    CHECK(!a.asked_back);
    CHECK(sp_file_exists(a.json_path));
    cJSON *j = NULL;
    CHECK_OK(sp_json_read_file(a.json_path, &j, &err), &err);
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(j, "trace")) == 4);
    fprintf(stderr, "  %s\n", a.text);
    cJSON_Delete(j);
    cJSON_Delete(q);
    cJSON_Delete(g);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_show_trajectories(void)
{
    sp_agent_session *s = open_default("traj", NULL);
    sp_agent_answer a;
    sp_error err = {0};
    sp_agent_pose before = pose_of(s);
    CHECK_OK(sp_agent_session_ask(s, "show me all the top trajectories that reach the refrigerator location", &a, &err), &err);
    cJSON *r = result_of(&a, "show_trajectories");
    const cJSON *tr = cJSON_GetObjectItemCaseSensitive(data_of(r), "trajectories"), *t;
    CHECK(cJSON_GetArraySize(tr) == 3);
    int rank = 1;
    cJSON_ArrayForEach(t, tr) {
        CHECK(cJSON_GetObjectItemCaseSensitive(t, "rank")->valueint == rank++);
        const cJSON *pv = cJSON_GetObjectItemCaseSensitive(t, "previews"), *f;
        CHECK(cJSON_GetArraySize(pv) >= 1);
        cJSON_ArrayForEach(f, pv) CHECK(sp_file_exists(f->valuestring));
        CHECK(strncmp(cJSON_GetObjectItemCaseSensitive(t, "plan_id")->valuestring, "plan_", 5) == 0);
    }
    CHECK(a.n_images >= 7); /* 3 x 2 previews + the map */
    sp_agent_pose after = pose_of(s);
    CHECK(after.x == before.x && after.y == before.y); /* showing does not move */
    fprintf(stderr, "  %s\n", a.text);
    cJSON_Delete(r);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_describe_dining_table(void)
{
    sp_agent_session *s = open_default("describe", NULL);
    sp_agent_answer a;
    sp_error err = {0};
    CHECK_OK(sp_agent_session_ask(s, "what objects are near the dining table?", &a, &err), &err);
    cJSON *r = result_of(&a, "describe_surroundings");
    const cJSON *objs = cJSON_GetObjectItemCaseSensitive(data_of(r), "objects"), *o;
    int chairs = 0;
    cJSON_ArrayForEach(o, objs) chairs += !strcmp(cJSON_GetObjectItemCaseSensitive(o, "name")->valuestring, "dining chair");
    CHECK(chairs == 4);
    CHECK(strstr(a.text, "dining chair") != NULL);
    fprintf(stderr, "  %s\n", a.text);
    cJSON_Delete(r);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_explore_kitchen(void)
{
    sp_agent_session *s = open_default("explore", NULL);
    sp_agent_answer a;
    sp_error err = {0};
    CHECK_OK(sp_agent_session_ask(s, "explore the area around the kitchen", &a, &err), &err);
    cJSON *r = result_of(&a, "explore_region");
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(data_of(r), "waypoints"), *e;
    CHECK(cJSON_GetArraySize(w) >= 3);
    cJSON_ArrayForEach(e, w) {
        double x = cJSON_GetArrayItem(e, 0)->valuedouble, y = cJSON_GetArrayItem(e, 1)->valuedouble;
        CHECK_MSG(x >= 0 && x <= 3.5 && y >= 4.5 && y <= 8, "waypoint (%.2f, %.2f) outside the kitchen", x, y);
    }
    fprintf(stderr, "  %s\n", a.text);
    cJSON_Delete(r);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_chair_asks_which(void)
{
    sp_agent_session *s = open_default("chair", NULL);
    sp_agent_answer a;
    sp_error err = {0};
    sp_agent_pose before = pose_of(s);
    CHECK_OK(sp_agent_session_ask(s, "go to the chair", &a, &err), &err);
    CHECK(a.asked_back);
    CHECK(strstr(a.text, "4 chairs") != NULL && strstr(a.text, "dining room") != NULL);
    CHECK(a.n_trace == 1); /* only the query: no plan, no motion */
    sp_agent_pose mid = pose_of(s);
    CHECK(mid.x == before.x && mid.y == before.y);
    fprintf(stderr, "  %s\n", a.text);
    sp_agent_answer_free(&a);
    CHECK_OK(sp_agent_session_ask(s, "the second one", &a, &err), &err);
    cJSON *g = result_of(&a, "send_nav2_goal");
    CHECK(g && !strcmp(cJSON_GetObjectItemCaseSensitive(data_of(g), "status")->valuestring, "succeeded"));
    fprintf(stderr, "  %s\n", a.text);
    cJSON_Delete(g);
    sp_agent_answer_free(&a);
    /* "nearest" needs no question */
    CHECK_OK(sp_agent_session_ask(s, "go to the nearest chair", &a, &err), &err);
    CHECK(!a.asked_back && a.n_trace == 4);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_nothing_matched(void)
{
    sp_agent_session *s = open_default("nomatch", NULL);
    sp_agent_answer a;
    sp_error err = {0};
    CHECK_OK(sp_agent_session_ask(s, "go to the unicorn", &a, &err), &err);
    CHECK(strstr(a.text, "could not find") != NULL && strstr(a.text, "refrigerator") != NULL);
    CHECK(a.n_trace == 1);
    fprintf(stderr, "  %s\n", a.text);
    sp_agent_answer_free(&a);
    CHECK_OK(sp_agent_session_ask(s, "blorp zzz", &a, &err), &err);
    CHECK(a.asked_back && a.n_trace == 0);
    sp_agent_answer_free(&a);
    CHECK_OK(sp_agent_session_ask(s, "go there", &a, &err), &err);
    CHECK(a.asked_back && a.n_trace == 0);
    sp_agent_answer_free(&a);
    CHECK_OK(sp_agent_session_ask(s, "where is the couch", &a, &err), &err);
    sp_agent_answer_free(&a);
    CHECK_OK(sp_agent_session_ask(s, "go there", &a, &err), &err); /* the couch */
    CHECK(a.n_trace == 4 && strstr(a.text, "couch") != NULL);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_relation(void)
{
    sp_agent_session *s = open_default("relation", NULL);
    int is_err;
    char *r = run_tool(s, "query_object_location", "{\"object_name\":\"the mug on the counter\"}", &is_err);
    cJSON *j = cJSON_Parse(r);
    const cJSON *in = cJSON_GetObjectItemCaseSensitive(data_of(j), "instances");
    CHECK(!is_err && cJSON_GetArraySize(in) == 1);
    CHECK_NEAR(cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(in, 0), "position"), 0)->valuedouble, 1.0, 1e-9);
    cJSON_Delete(j);
    free(r);
    r = run_tool(s, "query_object_location", "{\"object_name\":\"mug\"}", &is_err);
    j = cJSON_Parse(r);
    CHECK(cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(data_of(j), "ambiguous")));
    cJSON_Delete(j);
    free(r);
    sp_agent_session_close(s);
}

static void test_raw_goal_refused(void)
{
    sp_agent_session *s = open_default("raw", NULL);
    sp_agent_pose before = pose_of(s);
    int is_err;
    char code[32];
    /* x = 3.5 is the kitchen/dining wall */
    char *r = run_tool(s, "send_nav2_goal", "{\"x\":3.5,\"y\":7.5,\"yaw\":0}", &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "PLAN_REQUIRED"));
    CHECK(strstr(r, "occupied") != NULL && strstr(r, "plan_path") != NULL);
    fprintf(stderr, "  %s\n", r);
    free(r);
    /* free but unplanned coordinates are refused too */
    r = run_tool(s, "send_nav2_goal", "{\"x\":2.0,\"y\":2.0,\"yaw\":0}", &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "PLAN_REQUIRED"));
    free(r);
    sp_agent_pose after = pose_of(s);
    CHECK(after.x == before.x && after.y == before.y);
    /* a plan into the wall ends at a free pose nearby; with no tolerance there is none */
    r = run_tool(s, "plan_path", "{\"start\":[3.0,1.8,0,0],\"goal\":[3.5,7.5],\"tolerance_m\":0}", &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "GOAL_OCCUPIED"));
    free(r);
    r = run_tool(s, "plan_path", "{\"start\":[3.0,1.8,0,0],\"goal\":[3.5,7.5]}", &is_err);
    CHECK(!is_err && strstr(r, "\"end_cell\":\"free\"") != NULL);
    free(r);
    sp_agent_session_close(s);
}

/* Plans a path and returns its end and id. */
static void plan(sp_agent_session *s, const char *args, double end[4], char *id, size_t cap)
{
    int is_err;
    char *r = run_tool(s, "plan_path", args, &is_err);
    cJSON *j = cJSON_Parse(r);
    CHECK_MSG(!is_err, "%s", r);
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(data_of(j), "end");
    for (int i = 0; i < 4; i++) end[i] = cJSON_GetArrayItem(e, i) ? cJSON_GetArrayItem(e, i)->valuedouble : NAN;
    const cJSON *pid = cJSON_GetObjectItemCaseSensitive(data_of(j), "plan_id");
    snprintf(id, cap, "%s", cJSON_IsString(pid) ? pid->valuestring : "");
    cJSON_Delete(j);
    free(r);
}

static char *send(sp_agent_session *s, double x, double y, double yaw, const char *id, int *is_err)
{
    char args[256];
    if (id) snprintf(args, sizeof args, "{\"x\":%.6f,\"y\":%.6f,\"yaw\":%.6f,\"plan_id\":\"%s\"}", x, y, yaw, id);
    else snprintf(args, sizeof args, "{\"x\":%.6f,\"y\":%.6f,\"yaw\":%.6f}", x, y, yaw);
    return run_tool(s, "send_nav2_goal", args, is_err);
}

static void test_commitments(void)
{
    sp_agent_session *s = open_default("commit", NULL);
    double end[4];
    char id[32], code[32];
    int is_err;
    plan(s, "{\"start\":[3.0,1.8,0,0],\"goal\":[5.0,3.0]}", end, id, sizeof id);
    char *r = send(s, end[0] + 0.5, end[1], end[3], id, &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "GOAL_MISMATCH"));
    free(r);
    r = send(s, end[0], end[1], end[3], "plan_99", &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "PLAN_UNKNOWN"));
    free(r);
    r = send(s, end[0], end[1], end[3] + 1.0, NULL, &is_err); /* wrong heading */
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "PLAN_REQUIRED"));
    free(r);
    r = send(s, end[0] + 0.1, end[1] - 0.1, end[3], NULL, &is_err); /* within 0.25 m, no id */
    CHECK_MSG(!is_err && strstr(r, "succeeded"), "%s", r);
    free(r);
    /* the robot moved: the plan, made from (3.0, 1.8), is stale now */
    r = send(s, end[0], end[1], end[3], id, &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "PLAN_STALE"));
    free(r);
    /* a plan from a made-up start is stale */
    plan(s, "{\"start\":[1.0,2.5,0,0],\"goal\":[2.0,3.0]}", end, id, sizeof id);
    r = send(s, end[0], end[1], end[3], id, &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "PLAN_STALE"));
    free(r);
    sp_agent_session_close(s);
}

static void test_distance_limit_and_speed(void)
{
    sp_agent_config cfg = sp_agent_config_default();
    cfg.max_goal_distance_m = 2.0;
    cfg.max_speed_mps = 5.0; /* clamped to SP_AGENT_SPEED_LIMIT */
    sp_agent_session *s = open_session(&cfg, "limits", 3.0, 1.8, NULL);
    double end[4];
    char id[32], code[32];
    int is_err;
    plan(s, "{\"start\":[3.0,1.8,0,0],\"goal\":[0.45,7.55]}", end, id, sizeof id);
    char *r = send(s, end[0], end[1], end[3], id, &is_err);
    CHECK(is_err && !strcmp(error_code(r, code, sizeof code), "DISTANCE_LIMIT"));
    free(r);
    plan(s, "{\"start\":[3.0,1.8,0,0],\"goal\":[4.0,1.8]}", end, id, sizeof id);
    r = send(s, end[0], end[1], end[3], id, &is_err);
    CHECK_MSG(!is_err && strstr(r, "\"max_speed_mps\":1,") != NULL, "%s", r);
    free(r);
    sp_agent_session_close(s);
}

static int confirm_calls;
static char confirm_text[256];
static int say_no(void *u, const char *what)
{
    confirm_calls++;
    snprintf(confirm_text, sizeof confirm_text, "%s", what);
    return 0;
}
static int say_yes(void *u, const char *what) { return ++confirm_calls > 0; }

static void test_confirm(void)
{
    sp_agent_config cfg = sp_agent_config_default();
    cfg.confirm = 1;
    cfg.confirm_fn = say_no;
    sp_agent_session *s = open_session(&cfg, "confirm", 3.0, 1.8, NULL);
    sp_agent_answer a;
    sp_error err = {0};
    confirm_calls = 0;
    sp_agent_pose before = pose_of(s);
    CHECK_OK(sp_agent_session_ask(s, "go to the refrigerator", &a, &err), &err);
    CHECK(confirm_calls == 1 && strstr(confirm_text, "drive") != NULL);
    CHECK(strstr(a.text, "declined") != NULL);
    sp_agent_pose after = pose_of(s);
    CHECK(after.x == before.x && after.y == before.y);
    sp_agent_answer_free(&a);
    s->cfg.confirm_fn = say_yes;
    CHECK_OK(sp_agent_session_ask(s, "go to the refrigerator", &a, &err), &err);
    CHECK(strstr(a.text, "Arrived") != NULL);
    sp_agent_answer_free(&a);
    s->cfg.confirm_fn = NULL; /* confirmation asked for, nobody to ask: refuse */
    CHECK_OK(sp_agent_session_ask(s, "go to the couch", &a, &err), &err);
    CHECK(strstr(a.text, "no one can be asked") != NULL);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

/* A robot that behaves like the offline one but asks the session to cancel after a few polls,
 * as a Ctrl-C would. */
static sp_agent_session *cancel_target;
static int polls;
static sp_agent_robot inner;
static int w_pose(void *c, sp_agent_pose *p, sp_error *e) { return inner.ops->get_pose(inner.ctx, p, e); }
static int w_send(void *c, const sp_agent_goal *g, sp_error *e) { return inner.ops->send_goal(inner.ctx, g, e); }
static int w_poll(void *c, sp_agent_feedback *f, sp_error *e)
{
    if (++polls == 20) sp_agent_session_cancel(cancel_target);
    return inner.ops->poll(inner.ctx, f, e);
}
static int w_cancel(void *c, sp_error *e) { return inner.ops->cancel(inner.ctx, e); }
static void w_close(void *c) { sp_agent_robot_close(&inner); }
static const sp_agent_robot_ops wrap_ops = {"wrapped", 0, w_pose, w_send, w_poll, w_cancel, w_close};

static void test_cancel(void)
{
    sp_agent_offline_opts o = sp_agent_offline_opts_default();
    o.start.x = 3.0, o.start.y = 1.8;
    sp_error err = {0};
    CHECK_OK(sp_agent_robot_offline(&inner, &o, &err), &err);
    sp_agent_robot robot = {&wrap_ops, NULL};
    sp_agent_config cfg = sp_agent_config_default();
    cfg.out_dir = test_tmpdir("cancel");
    sp_agent_session *s = NULL;
    CHECK_OK(agent_session_open_world(&s, &cfg, fw_world(NULL), robot, &err), &err);
    cancel_target = s;
    polls = 0;
    sp_agent_answer a;
    CHECK_OK(sp_agent_session_ask(s, "go to the refrigerator", &a, &err), &err);
    cJSON *g = result_of(&a, "send_nav2_goal");
    CHECK(g && !strcmp(cJSON_GetObjectItemCaseSensitive(data_of(g), "status")->valuestring, "canceled"));
    CHECK(strstr(a.text, "canceled") != NULL);
    double left = cJSON_GetObjectItemCaseSensitive(data_of(g), "distance_to_goal_m")->valuedouble;
    CHECK_MSG(left > 1.0, "stopped %.2f m short", left);
    fprintf(stderr, "  %s\n", a.text);
    cJSON_Delete(g);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

static void test_invalid_arguments(void)
{
    sp_agent_session *s = open_default("invalid", NULL);
    static const struct {
        const char *tool, *args, *code, *mention;
    } cases[] = {
        {"send_nav2_goal", "{\"x\":\"one\",\"y\":2,\"yaw\":0}", "INVALID_ARGUMENTS", "x: expected a number"},
        {"send_nav2_goal", "{\"x\":1,\"y\":2}", "INVALID_ARGUMENTS", "missing required argument 'yaw'"},
        {"send_nav2_goal", "{\"x\":1,\"y\":2,\"yaw\":0,\"speed\":9}", "INVALID_ARGUMENTS", "unexpected argument 'speed'"},
        {"send_nav2_goal", "{\"x\":1e9,\"y\":2,\"yaw\":0}", "INVALID_ARGUMENTS", "above the maximum"},
        {"show_trajectories", "{\"target\":\"fridge\",\"k\":2.5}", "INVALID_ARGUMENTS", "expected an integer"},
        {"show_trajectories", "{\"target\":\"fridge\",\"k\":50}", "INVALID_ARGUMENTS", "above the maximum 5"},
        {"plan_path", "{\"start\":[1],\"goal\":[2,3]}", "INVALID_ARGUMENTS", "at least 2"},
        {"plan_path", "{\"start\":[1,2],\"goal\":[2,\"x\"]}", "INVALID_ARGUMENTS", "goal[1]"},
        {"query_object_location", "{\"object_name\":\"\"}", "INVALID_ARGUMENTS", "must not be empty"},
        {"query_object_location", "{\"object_name\":\"   \"}", "INVALID_ARGUMENTS", "blanks"},
        {"query_object_location", "{\"object_name\":7}", "INVALID_ARGUMENTS", "expected a string"},
        {"query_object_location", "[\"fridge\"]", "INVALID_ARGUMENTS", "expected an object"},
        {"describe_surroundings", "{\"object_name\":\"bed\",\"radius\":-1}", "INVALID_ARGUMENTS", "below the minimum"},
        {"get_robot_pose", "{\"now\":true}", "INVALID_ARGUMENTS", "unexpected argument"},
        {"query_object_location", "{\"object_name\":\"a\",\"object_name\":\"b\"}", "INVALID_ARGUMENTS", "twice"},
        {"teleport", "{}", "UNKNOWN_TOOL", "send_nav2_goal"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int is_err;
        char code[32];
        char *r = run_tool(s, cases[i].tool, cases[i].args, &is_err);
        CHECK_MSG(is_err && !strcmp(error_code(r, code, sizeof code), cases[i].code) && strstr(r, cases[i].mention),
                  "%s(%s) -> %s", cases[i].tool, cases[i].args, r);
        free(r);
    }
    /* arguments the decoder could not read */
    sp_agent_call c = {0};
    snprintf(c.id, sizeof c.id, "x");
    snprintf(c.name, sizeof c.name, "plan_path");
    snprintf(c.args_error, sizeof c.args_error, "arguments: JSON ends early");
    int is_err;
    char *r = agent_tool_run(s, &c, &is_err);
    CHECK(is_err && strstr(r, "INVALID_ARGUMENTS") && strstr(r, "ends early"));
    free(r);
    sp_agent_session_close(s);
}

int main(void)
{
    RUN(test_go_to_refrigerator);
    RUN(test_show_trajectories);
    RUN(test_describe_dining_table);
    RUN(test_explore_kitchen);
    RUN(test_chair_asks_which);
    RUN(test_nothing_matched);
    RUN(test_relation);
    RUN(test_raw_goal_refused);
    RUN(test_commitments);
    RUN(test_distance_limit_and_speed);
    RUN(test_confirm);
    RUN(test_cancel);
    RUN(test_invalid_arguments);
    return TEST_EXIT();
}
