/* Capture drives: a differential-drive robot follows the route of drive_route.c with a
 * pure-pursuit controller (heading towards the route a little ahead, turning rate limited, on the
 * spot when far off) and its camera records at a fixed rate, as a recorded run does; every k-th
 * frame is kept so the run fits the view budget. Also sp_synth_plan, which dispatches between
 * the planners and says what the plan made. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

#define DRIVE_CLEAR_M 0.30f  /* path cells: a 0.25 m robot radius and a margin */
#define DRIVE_MAX_WAYPOINTS 48
#define DRIVE_PITCH_RAD -0.10f
#define DRIVE_MAX_FRAMES 2000000

#define DRIVE_LOOKAHEAD_M 0.6f  /* the heading aims at the route this far ahead */
#define DRIVE_TURN_IN_PLACE_RAD 0.7854 /* beyond 45 degrees off, the robot turns on the spot */

/* One camera frame of the drive: pose, and the distance and turn accumulated up to it. */
typedef struct frame {
    float x, y;
    double yaw, dist, turned;
} frame;

typedef struct frames {
    size_t n, cap;
    frame *f;
} frames;

static int frame_add(frames *fs, float x, float y, double yaw, double dist, double turned)
{
    if (fs->n == fs->cap) {
        if (fs->cap >= DRIVE_MAX_FRAMES) return -2;
        size_t cap = fs->cap ? 2 * fs->cap : 1024;
        frame *nf = realloc(fs->f, cap * sizeof *nf);
        if (!nf) return -1;
        fs->f = nf;
        fs->cap = cap;
    }
    fs->f[fs->n++] = (frame){x, y, yaw, dist, turned};
    return 0;
}

static double wrap_pi(double a)
{
    a = fmod(a + M_PI, 2 * M_PI);
    if (a < 0) a += 2 * M_PI;
    return a - M_PI;
}

/* The point at arc length s along the polyline xy[0..n) (clamped to its ends). */
static void along(const float *xy, size_t n, double s, float *x, float *y)
{
    for (size_t i = 1; i < n; i++) {
        double L = hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
        if (s <= L || i + 1 == n) {
            double u = L > 0 ? fmin(fmax(s / L, 0), 1) : 1;
            *x = (float)(xy[2 * i - 2] + u * (xy[2 * i] - xy[2 * i - 2]));
            *y = (float)(xy[2 * i - 1] + u * (xy[2 * i + 1] - xy[2 * i - 1]));
            return;
        }
        s -= L;
    }
    *x = xy[0];
    *y = xy[1];
}

static double polyline_length(const float *xy, size_t n)
{
    double L = 0;
    for (size_t i = 1; i < n; i++) L += hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    return L;
}

/* Drives one segment of the route (no jumps inside) at the camera's rate: the heading turns at
 * most turn*dt per frame towards the route DRIVE_LOOKAHEAD_M ahead (a pure-pursuit controller),
 * the robot advances along the route at speed*cos(heading error), and turns on the spot while the
 * error exceeds 45 degrees, as a differential drive under Nav2's controllers does. */
static int drive_segment(const float *xy, size_t n, double speed, double turn, double dt,
                         frames *fs, double *dist, double *turned)
{
    double L = polyline_length(xy, n), s = 0;
    float x = xy[0], y = xy[1], tx, ty;
    along(xy, n, fmin(DRIVE_LOOKAHEAD_M, L), &tx, &ty);
    double yaw = (tx != x || ty != y) ? atan2(ty - y, tx - x) : 0;
    for (;;) {
        int rc = frame_add(fs, x, y, yaw, *dist, *turned);
        if (rc) return rc;
        if (s >= L - 1e-6) return 0;
        along(xy, n, fmin(s + DRIVE_LOOKAHEAD_M, L), &tx, &ty);
        double err = wrap_pi(atan2(ty - y, tx - x) - yaw);
        double dy = fmax(-turn * dt, fmin(turn * dt, err));
        yaw += dy;
        *turned += fabs(dy);
        if (fabs(err) < DRIVE_TURN_IN_PLACE_RAD) {
            double ds = fmin(speed * dt * cos(err), L - s);
            s += ds;
            *dist += ds;
            along(xy, n, s, &x, &y);
        }
    }
}

/* The whole route, segment after segment (a jump between them moves no distance). */
static int route_motion(const drive_route *r, double speed, double turn, double rate, frames *fs,
                        double *length)
{
    double dist = 0, turned = 0;
    for (size_t a = 0; a < r->n;) {
        size_t b = a + 1;
        while (b < r->n && !r->jump[b]) b++;
        int rc = drive_segment(r->xy + 2 * a, b - a, speed, turn, 1.0 / rate, fs, &dist, &turned);
        if (rc) return rc;
        a = b;
    }
    *length = dist;
    return 0;
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

/* Keeps every k-th frame (k as small as fits the budget) and makes their cameras. */
static int sample(const frames *fs, const sp_synth_capture_opts *o, double rate, float height,
                  sp_camera **cams, size_t *n_out, sp_synth_plan_info *info, sp_error *err)
{
    size_t n_frames = fs->n, k = (n_frames + (size_t)o->n_views - 1) / (size_t)o->n_views;
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
    double max_step = 0, max_turn = 0;
    for (size_t f = 0, m = 0; f < n_frames; f += k, m++) {
        const frame *p = &fs->f[f];
        if (m > 0) {
            const frame *q = &fs->f[f - k];
            max_step = fmax(max_step, p->dist - q->dist);
            max_turn = fmax(max_turn, p->turned - q->turned);
        }
        synth_view(&out[m], o, fov, p->x, p->y, height, (float)wrap_pi(p->yaw), DRIVE_PITCH_RAD);
        ts[m] = f / rate;
    }
    *cams = out;
    *n_out = n;
    if (info) {
        info->n_frames_driven = n_frames;
        info->keep_every = (int)k;
        info->rate_hz = rate / (double)k;
        info->duration_s = (n_frames - 1) / rate;
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
    frames fs = {0};
    double length = 0;
    int mrc = route_motion(&route, speed, turn, rate, &fs, &length);
    if (mrc == -2)
        rc = sp_error_set(err, SP_E_ARG, "drive at %g Hz: more than %d frames", rate, DRIVE_MAX_FRAMES);
    else if (mrc) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    float height = 0.5f * (hmin + hmax);
    if (!rc) rc = sample(&fs, o, rate, height, cams, n, info, err);
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
    free(fs.f);
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
