/* The offline robot: it follows the plan to the goal pose, never faster than the speed it is
 * given nor accelerating harder than its limit, takes about as long as a trapezoidal profile
 * says, stops on cancel, and rejects bad options. */
#include "agent/agent_internal.h"
#include "test.h"

static void drive(sp_agent_robot *r, const double *wp, int n, double speed, double yaw, int max_polls,
                  sp_agent_feedback *fb, double *vmax_seen, double *amax_seen, double *path_dev)
{
    sp_error err = {0};
    sp_agent_goal g = {{wp[(n - 1) * 4], wp[(n - 1) * 4 + 1], 0, yaw}, wp, n, speed};
    CHECK_OK(r->ops->send_goal(r->ctx, &g, &err), &err);
    sp_agent_pose last;
    r->ops->get_pose(r->ctx, &last, &err);
    double v_prev = 0, step = sp_agent_offline_opts_default().step_s;
    *vmax_seen = *amax_seen = *path_dev = 0;
    for (int i = 0; i < max_polls; i++) {
        CHECK_OK(r->ops->poll(r->ctx, fb, &err), &err);
        double v = agent_dist2d(last.x, last.y, fb->pose.x, fb->pose.y) / step;
        *vmax_seen = fmax(*vmax_seen, v);
        *amax_seen = fmax(*amax_seen, fabs(v - v_prev) / step);
        v_prev = v;
        last = fb->pose;
        /* distance to the polyline */
        double best = 1e9;
        for (int k = 0; k + 1 < n; k++) {
            double ax = wp[k * 4], ay = wp[k * 4 + 1], bx = wp[k * 4 + 4], by = wp[k * 4 + 5];
            double L2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
            double t = L2 > 0 ? ((fb->pose.x - ax) * (bx - ax) + (fb->pose.y - ay) * (by - ay)) / L2 : 0;
            t = fmin(fmax(t, 0), 1);
            best = fmin(best, hypot(fb->pose.x - (ax + t * (bx - ax)), fb->pose.y - (ay + t * (by - ay))));
        }
        *path_dev = fmax(*path_dev, best);
        if (fb->status != SP_AGENT_GOAL_ACTIVE) return;
    }
}

static void test_follows_plan(void)
{
    sp_agent_robot r;
    sp_error err = {0};
    sp_agent_offline_opts o = sp_agent_offline_opts_default();
    CHECK_OK(sp_agent_robot_offline(&r, &o, &err), &err);
    const double wp[] = {0, 0, 0, 0, 4, 0, 0, 0, 4, 3, 0, M_PI / 2};
    sp_agent_feedback fb;
    double vmax, amax, dev;
    drive(&r, wp, 3, 0.5, M_PI, 1000, &fb, &vmax, &amax, &dev);
    CHECK(fb.status == SP_AGENT_GOAL_SUCCEEDED);
    CHECK_NEAR(fb.pose.x, 4, 1e-6);
    CHECK_NEAR(fb.pose.y, 3, 1e-6);
    CHECK_NEAR(fabs(agent_wrap_angle(fb.pose.yaw - M_PI)), 0, 0.03);
    CHECK_MSG(vmax <= 0.5 + 1e-6, "vmax %.3f", vmax);
    /* one poll may mix a ramp with a stop inside the step: allow the discretization */
    CHECK_MSG(amax <= 1.2 * o.accel_mps2, "amax %.3f", amax);
    CHECK_MSG(dev < 1e-6, "left the path by %.3f m", dev);
    /* two trapezoids of 4 m and 3 m at 0.5 m/s with 0.5 m/s^2 (1 s ramps), a 90 deg and a 90 deg turn at 1 rad/s */
    double expect = (4 / 0.5 + 1) + (3 / 0.5 + 1) + 2 * (M_PI / 2);
    CHECK_MSG(fabs(fb.elapsed_s - expect) < 1.0, "took %.2f s, expected about %.2f", fb.elapsed_s, expect);
    sp_agent_robot_close(&r);
}

static void test_cancel_and_bad_opts(void)
{
    sp_agent_robot r;
    sp_error err = {0};
    CHECK_OK(sp_agent_robot_offline(&r, NULL, &err), &err);
    const double wp[] = {0, 0, 0, 0, 10, 0, 0, 0};
    sp_agent_goal g = {{10, 0, 0, 0}, wp, 2, 0.4};
    CHECK_OK(r.ops->send_goal(r.ctx, &g, &err), &err);
    sp_agent_feedback fb;
    for (int i = 0; i < 20; i++) r.ops->poll(r.ctx, &fb, &err);
    CHECK(fb.status == SP_AGENT_GOAL_ACTIVE && fb.distance_remaining_m > 5 && fb.eta_s > 0);
    CHECK_OK(r.ops->cancel(r.ctx, &err), &err);
    sp_agent_pose at = fb.pose;
    for (int i = 0; i < 5; i++) r.ops->poll(r.ctx, &fb, &err);
    CHECK(fb.status == SP_AGENT_GOAL_CANCELED);
    CHECK(fabs(fb.pose.x - at.x) < 0.25); /* stopped (within one step) */
    sp_agent_goal empty = {{1, 1, 0, 0}, NULL, 0, 0.4};
    CHECK_FAILS(r.ops->send_goal(r.ctx, &empty, &err), SP_E_ARG, &err, "waypoints");
    sp_agent_robot_close(&r);
    sp_agent_offline_opts o = sp_agent_offline_opts_default();
    o.step_s = 0;
    CHECK_FAILS(sp_agent_robot_offline(&r, &o, &err), SP_E_ARG, &err, "positive");
    o = sp_agent_offline_opts_default();
    o.start.x = NAN;
    CHECK_FAILS(sp_agent_robot_offline(&r, &o, &err), SP_E_ARG, &err, "finite");
    CHECK(agent_clamp_speed(9) == SP_AGENT_SPEED_LIMIT && agent_clamp_speed(NAN) == 0.05 && agent_clamp_speed(0.3) == 0.3);
}

int main(void)
{
    RUN(test_follows_plan);
    RUN(test_cancel_and_bad_opts);
    return TEST_EXIT();
}
