/* The agent driving a ROS 2 robot over DDS (issue 20's acceptance that needs the agent):
 * `semsplat sim-robot` and `semsplat agent --ros` as separate processes on the loopback interface
 * (Cyclone on 127.0.0.1, no multicast, a random domain and namespace), on the ideal house model
 * (house_model.h: label features, i.e. a perfect 2D segmentation). This test watches the robot's
 * odometry through a bridge of its own.
 *   - "go to the refrigerator": a NavigateToPose goal is sent, feedback arrives, the result is
 *     success and the odometry ends within 0.3 m of the goal;
 *   - a cancel mid-way (Ctrl-C to the agent while the robot drives) stops the robot;
 *   - a goal inside a wall: an LLM (a scripted local server) sends raw coordinates into a wall
 *     and the agent refuses them without moving the robot; the robot's action server rejects
 *     such a goal when one reaches it (the agent's ROS robot reports REJECTED);
 *   - with no action server the agent reports it after a bounded timeout;
 *   - every process is stopped; every wait is bounded. */
#include <cjson/cJSON.h>
#include <math.h>

#include "agent/agent_internal.h"
#include "house_model.h"
#include "http_server.h"
#include "ros/ros_test.h"
#include "test.h"

static int domain;
static char ns[64], dir[1024], model[1200];
static float start[3];
static sp_ros_bridge *observer;

static pid_t start_robot(void)
{
    char ready[1200], log[1200], dom[16], yaml[1300], st[96];
    snprintf(ready, sizeof ready, "%s/robot_ready", dir);
    snprintf(log, sizeof log, "%s/robot.log", dir);
    snprintf(yaml, sizeof yaml, "%s/map.yaml", model);
    snprintf(dom, sizeof dom, "%d", domain);
    snprintf(st, sizeof st, "%.3f,%.3f,%.3f", start[0], start[1], start[2]);
    unlink(ready);
    char *argv[] = {SP_BUILD_DIR "/semsplat", "sim-robot", "--map", yaml, "--start", st, "--loopback",
                    "--domain", dom, "--namespace", ns, "--max-speed", "1.0", "--time-scale", "2",
                    "--duration", "300", "--ready-file", ready, "--quiet", NULL};
    pid_t pid = test_spawn(argv, log);
    if (test_wait_file(ready, 30.0)) {
        fprintf(stderr, "sim-robot did not get ready; its log:\n");
        test_print_file(log);
        test_stop(pid);
        return -1;
    }
    return pid;
}

/* Starts `semsplat agent --ros` with extra arguments (NULL-terminated) and a command. */
static pid_t start_agent(const char *tag, const char *command, const char *const *extra, char *out, size_t cap)
{
    char log[1200], dom[16];
    snprintf(out, cap, "%s/agent_%s", dir, tag);
    snprintf(log, sizeof log, "%s/agent_%s.log", dir, tag);
    snprintf(dom, sizeof dom, "%d", domain);
    char *argv[40];
    int n = 0;
    const char *base[] = {SP_BUILD_DIR "/semsplat", "agent", "--model", model, "--out", out, "--ros",
                          "--loopback", "--domain", dom, "--namespace", ns, "--device", "cpu",
                          "--threads", "1", "--quiet"};
    for (size_t i = 0; i < sizeof base / sizeof base[0]; i++) argv[n++] = (char *)base[i];
    for (int i = 0; extra && extra[i] && n < 37; i++) argv[n++] = (char *)extra[i];
    argv[n++] = (char *)command;
    argv[n] = NULL;
    return test_spawn(argv, log);
}

/* Waits for the agent to finish (bounded) and reads its first answer. */
static cJSON *agent_answer(pid_t pid, const char *out, double timeout_s, int *status)
{
    *status = test_wait_pid(pid, timeout_s);
    if (*status < 0) test_stop(pid);
    char path[1300], log[1300];
    snprintf(path, sizeof path, "%s/answer_001.json", out);
    cJSON *a = NULL;
    sp_error err = {0};
    if (sp_json_read_file(path, &a, &err)) {
        snprintf(log, sizeof log, "%s.log", out);
        fprintf(stderr, "no answer (%s); the agent's log:\n", err.msg);
        test_print_file(log);
    }
    return a;
}

/* The result of `tool` in an answer file's trace (borrowed from a). */
static const cJSON *trace_result(const cJSON *a, const char *tool)
{
    const cJSON *t, *found = NULL;
    cJSON_ArrayForEach(t, cJSON_GetObjectItemCaseSensitive(a, "trace"))
        if (!strcmp(cJSON_GetObjectItemCaseSensitive(t, "tool")->valuestring, tool))
            found = cJSON_GetObjectItemCaseSensitive(t, "result");
    return found;
}

static const char *text_of(const cJSON *a)
{
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(a, "answer");
    return cJSON_IsString(t) ? t->valuestring : "";
}

/* Fresh odometry once the robot stands still. */
static int settled(sp_ros_odom *o)
{
    sp_error err = {0};
    double until = sp_time_now() + 8.0;
    while (sp_time_now() < until) {
        if (sp_ros_odom_wait(observer, 2.0, o, &err) == 0 && fabs(o->vx) < 1e-3 && fabs(o->wz) < 1e-3) return 0;
        usleep(50000);
    }
    return -1;
}

static void test_go_to_refrigerator(void)
{
    char out[1200];
    pid_t pid = start_agent("fridge", "go to the refrigerator", NULL, out, sizeof out);
    int st;
    cJSON *a = agent_answer(pid, out, 120, &st);
    CHECK_MSG(st == 0, "agent exit %d", st);
    const cJSON *g = a ? trace_result(a, "send_nav2_goal") : NULL, *d = cJSON_GetObjectItemCaseSensitive(g, "data");
    const cJSON *status = cJSON_GetObjectItemCaseSensitive(d, "status");
    CHECK_MSG(cJSON_IsString(status) && !strcmp(status->valuestring, "succeeded"), "%s", a ? text_of(a) : "");
    const cJSON *fb = cJSON_GetObjectItemCaseSensitive(d, "feedback_messages");
    CHECK_MSG(cJSON_IsNumber(fb) && fb->valuedouble >= 3, "feedback messages: %g", cJSON_IsNumber(fb) ? fb->valuedouble : -1);
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(d, "robot")->valuestring, "ros2"));
    const cJSON *goal = cJSON_GetObjectItemCaseSensitive(d, "goal");
    sp_ros_odom o;
    CHECK(settled(&o) == 0);
    if (cJSON_GetArraySize(goal) == 3) {
        double miss = hypot(o.pose.x - cJSON_GetArrayItem(goal, 0)->valuedouble, o.pose.y - cJSON_GetArrayItem(goal, 1)->valuedouble);
        fprintf(stderr, "  refrigerator: %g feedback messages, odometry ends %.3f m from the goal\n", fb->valuedouble, miss);
        CHECK(miss <= 0.3);
    }
    cJSON_Delete(a);
}

static void test_cancel_midway(void)
{
    sp_ros_odom o0, o;
    CHECK(settled(&o0) == 0);
    char out[1200];
    pid_t pid = start_agent("cancel", "go to the bed", NULL, out, sizeof out);
    sp_error err = {0};
    double until = sp_time_now() + 60;
    do { /* mid-way: once the robot has covered a metre */
        usleep(100000);
        sp_ros_odom_latest(observer, &o, NULL, &err);
    } while (hypot(o.pose.x - o0.pose.x, o.pose.y - o0.pose.y) < 1.0 && sp_time_now() < until);
    CHECK_MSG(sp_time_now() < until, "the robot did not start");
    kill(pid, SIGINT); /* Ctrl-C: the agent cancels the goal */
    int st;
    cJSON *a = agent_answer(pid, out, 30, &st);
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(a ? trace_result(a, "send_nav2_goal") : NULL, "data");
    const cJSON *status = cJSON_GetObjectItemCaseSensitive(d, "status");
    CHECK_MSG(cJSON_IsString(status) && !strcmp(status->valuestring, "canceled"), "%s", a ? text_of(a) : "");
    sp_ros_odom s1, s2;
    CHECK(settled(&s1) == 0);
    usleep(1000000);
    CHECK_OK(sp_ros_odom_wait(observer, 2.0, &s2, &err), &err);
    double moved = hypot(s2.pose.x - s1.pose.x, s2.pose.y - s1.pose.y);
    CHECK_MSG(moved < 0.01, "the robot still moves: %.3f m in 1 s", moved);
    const cJSON *goal = cJSON_GetObjectItemCaseSensitive(d, "goal");
    if (cJSON_GetArraySize(goal) == 3) {
        double left = hypot(s2.pose.x - cJSON_GetArrayItem(goal, 0)->valuedouble, s2.pose.y - cJSON_GetArrayItem(goal, 1)->valuedouble);
        fprintf(stderr, "  canceled: stopped %.2f m short of the goal\n", left);
        CHECK(left > 1.0);
    }
    cJSON_Delete(a);
}

/* A model that makes up a goal inside the wall between the living room and the kitchen. */
static const char wall_call[] =
    "{\"id\":\"c1\",\"object\":\"chat.completion\",\"choices\":[{\"index\":0,\"finish_reason\":\"tool_calls\","
    "\"message\":{\"role\":\"assistant\",\"content\":null,\"tool_calls\":[{\"id\":\"call_1\",\"type\":\"function\","
    "\"function\":{\"name\":\"send_nav2_goal\",\"arguments\":\"{\\\"x\\\":1.25,\\\"y\\\":4.5,\\\"yaw\\\":0}\"}}]}}]}";
static const char wall_done[] =
    "{\"id\":\"c2\",\"object\":\"chat.completion\",\"choices\":[{\"index\":0,\"finish_reason\":\"stop\","
    "\"message\":{\"role\":\"assistant\",\"content\":\"The goal was refused.\"}}]}";

static void test_wall_goal(void)
{
    sp_ros_odom o0, o1;
    CHECK(settled(&o0) == 0);
    test_server srv;
    ts_response script[] = {{200, NULL, wall_call, NULL, 0, 0}, {200, NULL, wall_done, NULL, 0, 0}};
    CHECK(ts_start(&srv, script, 2, NULL) == 0);
    char url[96], out[1200];
    snprintf(url, sizeof url, "http://127.0.0.1:%d/v1", srv.port);
    const char *extra[] = {"--llm", "openai", "--llm-url", url, "--llm-model", "test", NULL};
    pid_t pid = start_agent("wall", "go to 1.25, 4.5", extra, out, sizeof out);
    int st;
    cJSON *a = agent_answer(pid, out, 60, &st);
    ts_stop(&srv);
    const cJSON *r = a ? trace_result(a, "send_nav2_goal") : NULL;
    const cJSON *code = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(r, "error"), "code");
    CHECK_MSG(cJSON_IsString(code) && !strcmp(code->valuestring, "PLAN_REQUIRED"), "%s", a ? text_of(a) : "");
    CHECK(settled(&o1) == 0);
    CHECK(hypot(o1.pose.x - o0.pose.x, o1.pose.y - o0.pose.y) < 0.01);
    cJSON_Delete(a);
    /* A goal in the wall that does reach the robot (no plan in between): rejected. */
    sp_agent_config cfg = sp_agent_config_default();
    cfg.ros.domain_id = domain, cfg.ros.ns = ns, cfg.ros.loopback_only = 1, cfg.ros.node_name = "agent_test_robot";
    sp_agent_robot robot;
    sp_error err = {0};
    CHECK_OK(agent_robot_open_ros(&robot, &cfg, &err), &err);
    if (!robot.ops) return;
    sp_agent_goal g = {{1.25, 4.5, 0, 0}, NULL, 0, 0.4};
    sp_agent_feedback fb;
    CHECK_OK(robot.ops->send_goal(robot.ctx, &g, &err), &err);
    CHECK_OK(robot.ops->poll(robot.ctx, &fb, &err), &err);
    CHECK_MSG(fb.status == SP_AGENT_GOAL_REJECTED, "a goal in a wall is %s", sp_agent_goal_status_name(fb.status));
    fprintf(stderr, "  wall goal: the agent refused the made-up one; the robot rejected the sent one (%s)\n", fb.message);
    sp_agent_robot_close(&robot);
}

static void test_no_action_server(void)
{
    char out[1200];
    const char *extra[] = {"--nav-action", "nobody_serves_this", NULL};
    double t0 = sp_time_now();
    pid_t pid = start_agent("noserver", "go to the refrigerator", extra, out, sizeof out);
    int st;
    cJSON *a = agent_answer(pid, out, 90, &st);
    double took = sp_time_now() - t0;
    CHECK_MSG(a && strstr(text_of(a), "no NavigateToPose action server"), "%s", a ? text_of(a) : "");
    fprintf(stderr, "  no action server: reported and exited after %.1f s: %s\n", took, a ? text_of(a) : "");
    CHECK(st >= 0);
    cJSON_Delete(a);
}

int main(void)
{
    sp_error err = {0};
    sp_ros_options o;
    sp_ros_options_default(&o);
    o.loopback_only = 1;
    domain = test_random_domain(ns, sizeof ns);
    o.domain_id = domain;
    o.ns = ns;
    o.node_name = "agent_test_observer";
    if (sp_ros_bridge_create(&observer, &o, &err) == SP_E_UNSUPPORTED) TEST_SKIP(err.msg);
    snprintf(dir, sizeof dir, "%s", test_tmpdir("agent_ros"));
    double t0 = sp_time_now();
    ws_scene sc;
    char world[1024];
    snprintf(world, sizeof world, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    sp_device *dev = NULL;
    CHECK_OK(ws_build(&sc, world, NULL, 120, 128, 96, 0.07f, &err), &err);
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(hm_write(&sc, dir, dev, model, sizeof model, start, &err), &err);
    ws_free(&sc);
    sp_device_free(dev);
    fprintf(stderr, "domain %d, namespace %s, model %s (%.1f s)\n", domain, ns, model, sp_time_now() - t0);
    pid_t robot = start_robot();
    CHECK(robot > 0);
    if (robot > 0) {
        RUN(test_go_to_refrigerator);
        RUN(test_cancel_midway);
        RUN(test_wall_goal);
        RUN(test_no_action_server);
        test_stop(robot);
    }
    sp_ros_bridge_free(observer);
    fprintf(stderr, "agent over ROS 2: %.1f s\n", sp_time_now() - t0);
    return TEST_EXIT();
}
