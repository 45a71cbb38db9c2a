/* The offline robot: a differential-drive robot simulated along the issued plan, so the agent's
 * whole loop (goal, feedback, result, cancel) runs without a robot. It turns in place where the
 * path turns sharply, accelerates and brakes within accel_mps2 so that it stops on the goal, and
 * turns to the goal's yaw at the end. Simulated time advances step_s per poll; no sleeping. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

#define TURN_IN_PLACE_RAD 0.35 /* heading error above which the robot stops and turns */
#define YAW_DONE_RAD 0.02

typedef struct offline {
    sp_agent_offline_opts opts;
    sp_agent_pose pose;
    int status;
    double *wp; /* [n][4] */
    int n, seg; /* driving from wp[seg] to wp[seg + 1] */
    double goal_yaw, v, vmax, elapsed, remaining;
    long steps;
    char message[200];
} offline;

sp_agent_offline_opts sp_agent_offline_opts_default(void)
{
    sp_agent_offline_opts o = {{0, 0, 0, 0}, 0.5, 1.0, 0.25};
    return o;
}

static double remaining_length(const offline *r)
{
    if (r->seg >= r->n - 1) return 0;
    double d = agent_dist2d(r->pose.x, r->pose.y, r->wp[(r->seg + 1) * 4], r->wp[(r->seg + 1) * 4 + 1]);
    for (int i = r->seg + 1; i < r->n - 1; i++)
        d += agent_dist2d(r->wp[i * 4], r->wp[i * 4 + 1], r->wp[(i + 1) * 4], r->wp[(i + 1) * 4 + 1]);
    return d;
}

/* Distance along the path to where the robot must stand still: the next sharp corner (where it
 * turns in place) or the end. */
static double stop_distance(const offline *r)
{
    if (r->seg >= r->n - 1) return 0;
    double d = agent_dist2d(r->pose.x, r->pose.y, r->wp[(r->seg + 1) * 4], r->wp[(r->seg + 1) * 4 + 1]);
    for (int i = r->seg + 1; i < r->n - 1; i++) {
        const double *a = r->wp + (i - 1) * 4, *b = r->wp + i * 4, *c = r->wp + (i + 1) * 4;
        double h0 = atan2(b[1] - a[1], b[0] - a[0]), h1 = atan2(c[1] - b[1], c[0] - b[0]);
        if (fabs(agent_wrap_angle(h1 - h0)) > TURN_IN_PLACE_RAD) break;
        d += agent_dist2d(b[0], b[1], c[0], c[1]);
    }
    return d;
}

static int off_pose(void *ctx, sp_agent_pose *pose, sp_error *err)
{
    *pose = ((offline *)ctx)->pose;
    return SP_OK;
}

static int off_send(void *ctx, const sp_agent_goal *g, sp_error *err)
{
    offline *r = ctx;
    if (!g->waypoints || g->n_waypoints < 1)
        return sp_error_set(err, SP_E_ARG, "offline robot: a goal needs the plan's waypoints");
    double *wp = malloc((size_t)(g->n_waypoints + 1) * 4 * sizeof *wp);
    if (!wp) return sp_error_set(err, SP_E_NOMEM, "offline robot: out of memory");
    /* Drive from where the robot is to the plan's first waypoint, then along the plan. */
    wp[0] = r->pose.x, wp[1] = r->pose.y, wp[2] = r->pose.z, wp[3] = r->pose.yaw;
    memcpy(wp + 4, g->waypoints, (size_t)g->n_waypoints * 4 * sizeof *wp);
    free(r->wp);
    r->wp = wp;
    r->n = g->n_waypoints + 1;
    r->seg = 0;
    r->goal_yaw = isfinite(g->pose.yaw) ? g->pose.yaw : r->pose.yaw;
    r->vmax = g->max_speed_mps > 0 ? g->max_speed_mps : 0.3;
    r->v = 0;
    r->elapsed = 0;
    r->steps = 0;
    r->status = SP_AGENT_GOAL_ACTIVE;
    r->message[0] = 0;
    return SP_OK;
}

/* Turns toward `target` by at most yaw_rate * dt; returns the time left in the step. */
static double turn_toward(offline *r, double target, double dt)
{
    double e = agent_wrap_angle(target - r->pose.yaw), max = r->opts.yaw_rate_rps * dt;
    if (fabs(e) <= max) {
        r->pose.yaw = target;
        return dt - fabs(e) / r->opts.yaw_rate_rps;
    }
    r->pose.yaw = agent_wrap_angle(r->pose.yaw + (e > 0 ? max : -max));
    return 0;
}

static void step(offline *r, double dt)
{
    while (dt > 1e-9 && r->status == SP_AGENT_GOAL_ACTIVE) {
        if (r->seg >= r->n - 1) { /* at the end: face the goal's yaw */
            r->v = 0;
            dt = turn_toward(r, r->goal_yaw, dt);
            if (fabs(agent_wrap_angle(r->goal_yaw - r->pose.yaw)) < YAW_DONE_RAD)
                r->status = SP_AGENT_GOAL_SUCCEEDED;
            continue;
        }
        const double *b = r->wp + (r->seg + 1) * 4;
        double dx = b[0] - r->pose.x, dy = b[1] - r->pose.y, d = hypot(dx, dy);
        if (d < 1e-6) {
            r->seg++;
            continue;
        }
        double heading = atan2(dy, dx);
        if (fabs(agent_wrap_angle(heading - r->pose.yaw)) > TURN_IN_PLACE_RAD && r->v < 1e-3) {
            r->v = 0;
            dt = turn_toward(r, heading, dt);
            continue;
        }
        r->pose.yaw = heading;
        /* Accelerate or brake by at most a dt toward the speed from which the robot can still
         * stop at the corner or the goal (v^2 <= 2 a s); a creep speed finishes the last cm. */
        double rem = stop_distance(r), a = r->opts.accel_mps2;
        double ahead = fmax(rem - r->v * dt, 0); /* where this step will leave the robot */
        double target = fmax(fmin(r->vmax, sqrt(2 * a * ahead)), 0.02);
        double v = fmin(fmax(target, r->v - a * dt), r->v + a * dt);
        double ds = fmin(fmin(0.5 * (r->v + v) * dt, d), rem);
        if (ds < 1e-9) ds = fmin(d, 1e-3);
        r->pose.x += dx / d * ds;
        r->pose.y += dy / d * ds;
        if (isfinite(b[2])) r->pose.z = b[2];
        double used = 0.5 * (r->v + v) > 1e-9 ? ds / (0.5 * (r->v + v)) : dt;
        r->v = v;
        dt -= fmin(used, dt);
        if (ds >= d - 1e-9) {
            r->seg++;
            /* A sharp corner (braked for above): turn in place there. */
            if (r->seg < r->n - 1) {
                const double *c = r->wp + (r->seg + 1) * 4;
                double next = atan2(c[1] - b[1], c[0] - b[0]);
                if (fabs(agent_wrap_angle(next - heading)) > TURN_IN_PLACE_RAD) r->v = 0;
            }
        }
    }
}

static int off_poll(void *ctx, sp_agent_feedback *fb, sp_error *err)
{
    offline *r = ctx;
    memset(fb, 0, sizeof *fb);
    if (r->status == SP_AGENT_GOAL_ACTIVE) {
        step(r, r->opts.step_s);
        r->elapsed += r->opts.step_s;
        r->steps++;
    }
    fb->status = r->status;
    fb->pose = r->pose;
    fb->distance_remaining_m = r->status == SP_AGENT_GOAL_ACTIVE ? remaining_length(r) : 0;
    fb->eta_s = r->vmax > 0 ? fb->distance_remaining_m / r->vmax : 0;
    fb->elapsed_s = r->elapsed;
    fb->feedback_count = r->steps;
    snprintf(fb->message, sizeof fb->message, "%s", r->message);
    return SP_OK;
}

static int off_cancel(void *ctx, sp_error *err)
{
    offline *r = ctx;
    if (r->status == SP_AGENT_GOAL_ACTIVE) {
        r->status = SP_AGENT_GOAL_CANCELED;
        r->v = 0;
        snprintf(r->message, sizeof r->message, "cancelled on request");
    }
    return SP_OK;
}

static void off_close(void *ctx)
{
    offline *r = ctx;
    if (!r) return;
    free(r->wp);
    free(r);
}

static const sp_agent_robot_ops offline_ops = {"offline", 0, off_pose, off_send, off_poll,
                                                off_cancel, off_close};

int sp_agent_robot_offline(sp_agent_robot *out, const sp_agent_offline_opts *opts, sp_error *err)
{
    memset(out, 0, sizeof *out);
    sp_agent_offline_opts o = opts ? *opts : sp_agent_offline_opts_default();
    if (!(o.accel_mps2 > 0) || !(o.yaw_rate_rps > 0) || !(o.step_s > 0) || o.step_s > 5 ||
        !isfinite(o.start.x) || !isfinite(o.start.y))
        return sp_error_set(err, SP_E_ARG,
                            "offline robot: accel, yaw rate and step must be positive, start finite");
    offline *r = calloc(1, sizeof *r);
    if (!r) return sp_error_set(err, SP_E_NOMEM, "offline robot: out of memory");
    r->opts = o;
    r->pose = o.start;
    if (!isfinite(r->pose.z)) r->pose.z = 0;
    if (!isfinite(r->pose.yaw)) r->pose.yaw = 0;
    out->ops = &offline_ops;
    out->ctx = r;
    return SP_OK;
}

void sp_agent_robot_close(sp_agent_robot *r)
{
    if (r && r->ops && r->ops->close) r->ops->close(r->ctx);
    if (r) memset(r, 0, sizeof *r);
}

const char *sp_agent_goal_status_name(int s)
{
    static const char *const names[] = {"none", "active", "succeeded", "canceled", "aborted",
                                        "rejected"};
    return s >= 0 && s < (int)(sizeof names / sizeof names[0]) ? names[s] : "unknown";
}
