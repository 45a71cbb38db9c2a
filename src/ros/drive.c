/* The simulated robot's body: a unicycle (differential drive) with speed, yaw-rate and
 * acceleration limits. It follows a path by pure pursuit (steer towards the point one lookahead
 * ahead on the path, curvature 2 sin(e) / L), turns in place when that point is far off its
 * heading, slows so that it can stop at the goal (v <= sqrt(2 a d)), then turns to the goal's
 * heading. Integration is midpoint-in-heading, exact for constant v and w to second order. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ros_internal.h"

/* Heading error beyond which the robot stops and turns in place rather than arcing. */
#define TURN_IN_PLACE_RAD 0.9
/* Slowest approach speed, so the last centimetres do not take forever under v <= sqrt(2 a d). */
#define CREEP_SPEED 0.05
#define AT_REST 1e-3

static double wrap(double a)
{
    while (a > M_PI) a -= 2 * M_PI;
    while (a < -M_PI) a += 2 * M_PI;
    return a;
}

static double clampd(double v, double lo, double hi) { return v < lo ? lo : v > hi ? hi : v; }

void ros_drive_init(ros_drive *d, double x, double y, double yaw)
{
    memset(d, 0, sizeof *d);
    d->x = x;
    d->y = y;
    d->yaw = wrap(yaw);
}

void ros_drive_free(ros_drive *d)
{
    free(d->path);
    d->path = NULL;
    d->n_path = 0;
}

void ros_drive_follow(ros_drive *d, double *path, size_t n, double goal_yaw)
{
    free(d->path);
    d->path = path;
    d->n_path = n;
    d->progress = 0;
    d->goal_yaw = wrap(goal_yaw);
    d->stopping = 0;
    d->turning_in_place = 0;
}

void ros_drive_stop(ros_drive *d) { d->stopping = 1; }

/* Closest point to the robot on segments [progress, progress + 3), advancing progress. */
static void track(ros_drive *d, double *cx, double *cy)
{
    const double *p = d->path;
    size_t best = d->progress;
    double bd = INFINITY, bx = p[2 * d->progress], by = p[2 * d->progress + 1];
    for (size_t s = d->progress; s + 1 < d->n_path && s < d->progress + 3; s++) {
        double ax = p[2 * s], ay = p[2 * s + 1], ex = p[2 * s + 2] - ax, ey = p[2 * s + 3] - ay;
        double len2 = ex * ex + ey * ey;
        double t = len2 > 0 ? clampd(((d->x - ax) * ex + (d->y - ay) * ey) / len2, 0, 1) : 1;
        double qx = ax + t * ex, qy = ay + t * ey;
        double dd = hypot(d->x - qx, d->y - qy);
        if (dd < bd) {
            bd = dd, best = s, bx = qx, by = qy;
        }
    }
    d->progress = best;
    *cx = bx;
    *cy = by;
}

double ros_drive_remaining(const ros_drive *d)
{
    if (!d->path || !d->n_path) return 0;
    size_t s = d->progress;
    const double *p = d->path;
    double cx = p[2 * s], cy = p[2 * s + 1];
    if (s + 1 < d->n_path) { /* from the robot's projection onto its segment */
        double ex = p[2 * s + 2] - cx, ey = p[2 * s + 3] - cy, len2 = ex * ex + ey * ey;
        double t = len2 > 0 ? clampd(((d->x - cx) * ex + (d->y - cy) * ey) / len2, 0, 1) : 1;
        cx += t * ex, cy += t * ey;
    }
    double total = 0, px = cx, py = cy; /* the lateral offset is not distance to go */
    for (size_t i = s + 1; i < d->n_path; i++) {
        total += hypot(p[2 * i] - px, p[2 * i + 1] - py);
        px = p[2 * i], py = p[2 * i + 1];
    }
    return total;
}

/* The point `ahead` metres along the path from (cx, cy) on segment progress. */
static void lookahead(const ros_drive *d, double cx, double cy, double ahead, double *lx,
                      double *ly)
{
    const double *p = d->path;
    double px = cx, py = cy;
    for (size_t i = d->progress + 1; i < d->n_path; i++) {
        double seg = hypot(p[2 * i] - px, p[2 * i + 1] - py);
        if (seg >= ahead && seg > 0) {
            *lx = px + (p[2 * i] - px) * ahead / seg;
            *ly = py + (p[2 * i + 1] - py) * ahead / seg;
            return;
        }
        ahead -= seg;
        px = p[2 * i], py = p[2 * i + 1];
    }
    *lx = p[2 * d->n_path - 2];
    *ly = p[2 * d->n_path - 1];
}

/* Yaw rate that turns through err and can still stop there. */
static double turn_rate(double err, const ros_drive_limits *lim)
{
    double w = fmin(lim->max_yaw_rate, sqrt(2 * lim->max_yaw_accel * fabs(err)));
    return err < 0 ? -w : w;
}

static void targets(ros_drive *d, const ros_drive_limits *lim, double *vt, double *wt)
{
    *vt = 0, *wt = 0;
    if (d->stopping || !d->path) return;
    double gx = d->path[2 * d->n_path - 2], gy = d->path[2 * d->n_path - 1];
    if (!d->turning_in_place && hypot(gx - d->x, gy - d->y) <= lim->goal_tolerance_m) {
        if (fabs(d->v) < AT_REST) d->turning_in_place = 1;
        *wt = 0;
        return; /* decelerate at the goal */
    }
    if (d->turning_in_place) {
        double e = wrap(d->goal_yaw - d->yaw);
        *wt = fabs(e) < lim->yaw_tolerance_rad * 0.5 ? 0 : turn_rate(e, lim);
        return;
    }
    double cx, cy, lx, ly;
    track(d, &cx, &cy);
    lookahead(d, cx, cy, lim->lookahead_m, &lx, &ly);
    double e = wrap(atan2(ly - d->y, lx - d->x) - d->yaw);
    if (fabs(e) > TURN_IN_PLACE_RAD) {
        *wt = turn_rate(e, lim);
        return;
    }
    double remaining = ros_drive_remaining(d) + hypot(cx - d->x, cy - d->y);
    double v = lim->max_speed * (1 - 0.5 * fabs(e) / TURN_IN_PLACE_RAD);
    v = fmin(v, fmax(CREEP_SPEED, sqrt(2 * lim->max_accel * remaining)));
    double L = fmax(hypot(lx - d->x, ly - d->y), 1e-3);
    double w = v * 2 * sin(e) / L;
    if (fabs(w) > lim->max_yaw_rate) { /* keep the arc, slow down */
        v *= lim->max_yaw_rate / fabs(w);
        w = w < 0 ? -lim->max_yaw_rate : lim->max_yaw_rate;
    }
    *vt = v, *wt = w;
}

ros_drive_event ros_drive_step(ros_drive *d, const ros_drive_limits *lim, double dt)
{
    double vt, wt;
    targets(d, lim, &vt, &wt);
    d->v += clampd(vt - d->v, -lim->max_accel * dt, lim->max_accel * dt);
    d->w += clampd(wt - d->w, -lim->max_yaw_accel * dt, lim->max_yaw_accel * dt);
    double mid = d->yaw + 0.5 * d->w * dt;
    d->x += d->v * cos(mid) * dt;
    d->y += d->v * sin(mid) * dt;
    d->yaw = wrap(d->yaw + d->w * dt);
    int at_rest = fabs(d->v) < AT_REST && fabs(d->w) < AT_REST;
    if (d->stopping) {
        if (!at_rest) return ROS_DRIVE_MOVING;
        d->v = d->w = 0;
        d->stopping = 0;
        ros_drive_free(d);
        return ROS_DRIVE_STOPPED;
    }
    if (!d->path) return ROS_DRIVE_IDLE;
    if (d->turning_in_place && at_rest &&
        fabs(wrap(d->goal_yaw - d->yaw)) <= lim->yaw_tolerance_rad) {
        d->v = d->w = 0;
        ros_drive_free(d);
        return ROS_DRIVE_ARRIVED;
    }
    return ROS_DRIVE_MOVING;
}
