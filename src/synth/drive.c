/* Capture drives: a differential-drive robot follows the route of drive_route.c (spin once round
 * at each waypoint, turn on the spot towards the next corner, drive straight to it) and its
 * camera records at a fixed rate, as a recorded run does; every k-th frame is kept so the run
 * fits the view budget. Also sp_synth_plan, which dispatches between the planners and says what
 * the plan made. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

#define DRIVE_CLEAR_M 0.30f  /* path cells: a 0.25 m robot radius and a margin */
#define DRIVE_MAX_WAYPOINTS 48
#define DRIVE_PITCH_RAD -0.10f
#define DRIVE_MAX_FRAMES 2000000

typedef struct prim {
    float x0, y0, x1, y1; /* a move (x0,y0 == x1,y1 for a turn) */
    double yaw0, yaw1;    /* radians, unwrapped */
    double t0, dur;       /* seconds; dur 0 with distinct ends is a jump to a new segment */
} prim;

typedef struct prims {
    size_t n, cap;
    prim *p;
    double t;
} prims;

static int prim_add(prims *ps, float x0, float y0, float x1, float y1, double yaw0, double yaw1,
                    double dur)
{
    if (ps->n == ps->cap) {
        size_t cap = ps->cap ? 2 * ps->cap : 64;
        prim *np = realloc(ps->p, cap * sizeof *np);
        if (!np) return -1;
        ps->p = np;
        ps->cap = cap;
    }
    ps->p[ps->n++] = (prim){x0, y0, x1, y1, yaw0, yaw1, ps->t, dur};
    ps->t += dur;
    return 0;
}

static double wrap_pi(double a)
{
    a = fmod(a + M_PI, 2 * M_PI);
    if (a < 0) a += 2 * M_PI;
    return a - M_PI;
}

/* The route as turns, moves, spins and jumps. */
static int route_motion(const drive_route *r, double speed, double turn, prims *ps, double *length)
{
    double yaw = 0;
    *length = 0;
    if (r->n > 1) yaw = atan2(r->xy[3] - r->xy[1], r->xy[2] - r->xy[0]);
    for (size_t i = 0; i < r->n; i++) {
        float x = r->xy[2 * i], y = r->xy[2 * i + 1];
        if (i > 0) {
            float px = r->xy[2 * i - 2], py = r->xy[2 * i - 1];
            if (r->jump[i]) {
                if (prim_add(ps, px, py, x, y, yaw, yaw, 0)) return -1;
            } else {
                double L = hypot(x - px, y - py);
                if (L > 1e-6) {
                    double h = yaw + wrap_pi(atan2(y - py, x - px) - yaw);
                    if (prim_add(ps, px, py, px, py, yaw, h, fabs(h - yaw) / turn)) return -1;
                    yaw = h;
                    if (prim_add(ps, px, py, x, y, yaw, yaw, L / speed)) return -1;
                    *length += L;
                }
            }
        }
        if (r->stop[i] && prim_add(ps, x, y, x, y, yaw, yaw + 2 * M_PI, 2 * M_PI / turn)) return -1;
        if (r->stop[i]) yaw += 2 * M_PI;
    }
    return 0;
}

/* Pose at time t within primitive p, and the distance and turn accumulated up to t. */
static void pose_at(const prim *p, double t, float *x, float *y, double *yaw)
{
    double u = p->dur > 0 ? (t - p->t0) / p->dur : 1;
    if (u < 0) u = 0;
    if (u > 1) u = 1;
    *x = (float)(p->x0 + u * (p->x1 - p->x0));
    *y = (float)(p->y0 + u * (p->y1 - p->y0));
    *yaw = p->yaw0 + u * (p->yaw1 - p->yaw0);
}

static int check_drive_opts(const sp_synth_capture_opts *o, double *speed, double *turn,
                            double *rate, sp_error *err)
{
    *speed = o->drive_speed_mps > 0 ? o->drive_speed_mps : 0.4;
    *turn = o->drive_turn_rad_s > 0 ? o->drive_turn_rad_s : 0.5;
    *rate = o->drive_rate_hz > 0 ? o->drive_rate_hz : 10;
    if (!(*speed <= 5) || o->drive_speed_mps < 0)
        return sp_error_set(err, SP_E_ARG, "drive speed %g m/s: expected 0..5", o->drive_speed_mps);
    if (!(*turn <= 2 * M_PI) || o->drive_turn_rad_s < 0)
        return sp_error_set(err, SP_E_ARG, "drive turn rate %g rad/s: expected 0..6.28", o->drive_turn_rad_s);
    if (!(*rate <= 120) || o->drive_rate_hz < 0)
        return sp_error_set(err, SP_E_ARG, "drive frame rate %g Hz: expected 0..120", o->drive_rate_hz);
    return 0;
}

/* Samples the motion at rate, keeps every k-th frame and makes their cameras. */
static int sample(const prims *ps, const sp_synth_capture_opts *o, double rate, float height,
                  sp_camera **cams, size_t *n_out, sp_synth_plan_info *info, sp_error *err)
{
    double T = ps->t;
    double nf = floor(T * rate) + 1;
    if (nf > DRIVE_MAX_FRAMES)
        return sp_error_set(err, SP_E_ARG, "drive of %.0f s at %g Hz: %.0f frames, more than %d", T,
                            rate, nf, DRIVE_MAX_FRAMES);
    size_t n_frames = (size_t)nf, k = (n_frames + (size_t)o->n_views - 1) / (size_t)o->n_views;
    if (k < 1) k = 1;
    size_t n = (n_frames + k - 1) / k;
    sp_camera *out = calloc(n, sizeof *out);
    double *ts = calloc(n, sizeof *ts);
    if (!out || !ts) {
        free(out);
        free(ts);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    float fov = o->fov_deg > 0 ? o->fov_deg : 70.0f;
    size_t pi = 0;
    double dist = 0, turned = 0, last_dist = 0, last_turn = 0, max_step = 0, max_turn = 0;
    double done_dist = 0, done_turn = 0; /* over the primitives before pi */
    for (size_t f = 0, m = 0; f < n_frames; f += k, m++) {
        double t = f / rate;
        while (pi + 1 < ps->n && t > ps->p[pi].t0 + ps->p[pi].dur) {
            const prim *p = &ps->p[pi];
            if (p->dur > 0) {
                done_dist += hypot(p->x1 - p->x0, p->y1 - p->y0);
                done_turn += fabs(p->yaw1 - p->yaw0);
            }
            pi++;
        }
        const prim *p = &ps->p[pi];
        float x, y;
        double yaw;
        pose_at(p, t, &x, &y, &yaw);
        double u = p->dur > 0 ? fmin(fmax((t - p->t0) / p->dur, 0), 1) : 0;
        dist = done_dist + (p->dur > 0 ? u * hypot(p->x1 - p->x0, p->y1 - p->y0) : 0);
        turned = done_turn + (p->dur > 0 ? u * fabs(p->yaw1 - p->yaw0) : 0);
        if (m > 0) {
            max_step = fmax(max_step, dist - last_dist);
            max_turn = fmax(max_turn, turned - last_turn);
        }
        last_dist = dist;
        last_turn = turned;
        synth_view(&out[m], o, fov, x, y, height, (float)wrap_pi(yaw), DRIVE_PITCH_RAD);
        ts[m] = t;
    }
    *cams = out;
    *n_out = n;
    if (info) {
        info->n_frames_driven = n_frames;
        info->keep_every = (int)k;
        info->rate_hz = rate / (double)k;
        info->duration_s = T;
        info->max_step_m = max_step;
        info->max_turn_rad = max_turn;
        info->t_s = ts;
    } else free(ts);
    return 0;
}

static int plan_drive(const sp_world *w, const sp_synth_capture_opts *o, sp_camera **cams,
                      size_t *n, sp_synth_plan_info *info, sp_error *err)
{
    double speed, turn, rate;
    int rc = check_drive_opts(o, &speed, &turn, &rate, err);
    if (rc) return rc;
    if (o->n_views <= 0 || o->width <= 0 || o->height <= 0)
        return sp_error_set(err, SP_E_ARG, "capture: %d views of %dx%d: expected positive numbers",
                            o->n_views, o->width, o->height);
    if (o->fov_deg >= 170) return sp_error_set(err, SP_E_ARG, "fov %g degrees: expected less than 170", o->fov_deg);
    float hmin = o->min_height_m, hmax = o->max_height_m;
    if (hmin <= 0 && hmax <= 0) { hmin = 0.3f; hmax = 1.5f; }
    if (hmax < hmin) return sp_error_set(err, SP_E_ARG, "camera heights %g..%g: max below min", hmin, hmax);
    sp_grid2 clear;
    rc = synth_floor_clearance(w, &clear, err);
    float need = DRIVE_CLEAR_M;
    size_t n_free = 0, nc = rc ? 0 : (size_t)clear.nx * clear.ny;
    for (int pass = 0; !rc && pass < 3; pass++, need *= 0.5f) {
        n_free = 0;
        for (size_t c = 0; c < nc; c++) n_free += clear.data[c] >= need;
        if (n_free >= 4) break;
    }
    if (rc == SP_E_NOTFOUND || (!rc && n_free < 4)) {
        /* nothing to drive on (a single model, say): the walk planner's orbit */
        sp_grid2_free(&clear);
        sp_error_clear(err);
        sp_synth_capture_opts walk = *o;
        walk.plan = SP_SYNTH_PLAN_WALK;
        rc = sp_synth_plan_views(w, &walk, cams, n, err);
        if (!rc && info) {
            info->name = "orbit";
            info->n_views = *n;
        }
        return rc;
    }
    if (rc) return rc;
    drive_route route;
    rc = drive_plan_route(&clear, need, DRIVE_MAX_WAYPOINTS, &route, err);
    sp_grid2_free(&clear);
    if (rc) return rc;
    prims ps = {0};
    double length = 0;
    if (route_motion(&route, speed, turn, &ps, &length)) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    float height = 0.5f * (hmin + hmax);
    if (!rc) rc = sample(&ps, o, rate, height, cams, n, info, err);
    if (!rc && info) {
        info->name = "drive";
        info->n_views = *n;
        info->speed_mps = speed;
        info->turn_rad_s = turn;
        info->camera_height_m = height;
        info->path_length_m = length;
        info->n_waypoints = route.n_waypoints;
        info->n_segments = route.n_segments;
        info->reachable_fraction = route.reachable_fraction;
    }
    free(ps.p);
    drive_route_free(&route);
    return rc;
}

int sp_synth_plan(const sp_world *w, const sp_synth_capture_opts *o, sp_camera **cams,
                  size_t *n, sp_synth_plan_info *info, sp_error *err)
{
    *cams = NULL;
    *n = 0;
    if (info) {
        memset(info, 0, sizeof *info);
        info->plan = o->plan;
    }
    if (o->plan == SP_SYNTH_PLAN_DRIVE) return plan_drive(w, o, cams, n, info, err);
    if (o->plan != SP_SYNTH_PLAN_MIXED && o->plan != SP_SYNTH_PLAN_WALK)
        return sp_error_set(err, SP_E_ARG, "capture plan %d: expected mixed (0), walk (1) or drive (2)",
                            o->plan);
    int rc = sp_synth_plan_views(w, o, cams, n, err);
    if (!rc && info) {
        info->name = o->plan == SP_SYNTH_PLAN_WALK ? "walk" : "walk+objects";
        info->n_views = *n;
    }
    return rc;
}

void sp_synth_plan_info_free(sp_synth_plan_info *info)
{
    if (!info) return;
    free(info->t_s);
    info->t_s = NULL;
}
