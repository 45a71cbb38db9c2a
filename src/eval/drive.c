/* Navigation commands end to end: the agent session, its robot wrapped to record every pose it
 * reports, the simulated robot over loopback DDS in a thread of ours (or the offline robot), and
 * the splat rendered from robot poses. */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <time.h>
#include <unistd.h>

#include "drive.h"
#include "semsplat/io.h"

/* ---- the recording robot ---- */

typedef struct rec_robot {
    sp_agent_robot inner;
    sp_agent_robot_ops ops; /* the inner robot's name and realtime, our functions */
    ev_track *track;
} rec_robot;

static int rec_pose(void *ctx, sp_agent_pose *p, sp_error *err)
{
    rec_robot *r = ctx;
    return r->inner.ops->get_pose(r->inner.ctx, p, err);
}

static int rec_send(void *ctx, const sp_agent_goal *g, sp_error *err)
{
    rec_robot *r = ctx;
    ev_track *t = r->track;
    int rc = r->inner.ops->send_goal(r->inner.ctx, g, err);
    if (rc) return rc;
    t->goal_sent = 1;
    t->goal[0] = g->pose.x, t->goal[1] = g->pose.y, t->goal[2] = g->pose.yaw;
    free(t->plan);
    t->plan = NULL, t->n_plan = 0;
    if (g->n_waypoints > 0 && (t->plan = malloc(sizeof(double) * 4 * (size_t)g->n_waypoints))) {
        memcpy(t->plan, g->waypoints, sizeof(double) * 4 * (size_t)g->n_waypoints);
        t->n_plan = g->n_waypoints;
    }
    t->n = 0;
    t->t0 = sp_time_now();
    return SP_OK;
}

static int rec_poll(void *ctx, sp_agent_feedback *fb, sp_error *err)
{
    rec_robot *r = ctx;
    ev_track *t = r->track;
    int rc = r->inner.ops->poll(r->inner.ctx, fb, err);
    if (rc) return rc;
    if (t->n == t->cap) {
        int cap = t->cap ? 2 * t->cap : 256;
        sp_drive_sample *s = realloc(t->s, sizeof *s * (size_t)cap);
        if (!s) return sp_error_set(err, SP_E_NOMEM, "demo: out of memory recording the drive");
        t->s = s, t->cap = cap;
    }
    double time = r->ops.realtime ? sp_time_now() - t->t0 : fb->elapsed_s;
    t->s[t->n++] = (sp_drive_sample){time, fb->pose.x, fb->pose.y, fb->pose.yaw, fb->distance_remaining_m,
                                     fb->status};
    return SP_OK;
}

static int rec_cancel(void *ctx, sp_error *err)
{
    rec_robot *r = ctx;
    return r->inner.ops->cancel(r->inner.ctx, err);
}

static void rec_close(void *ctx)
{
    rec_robot *r = ctx;
    sp_agent_robot_close(&r->inner);
    free(r);
}

static int rec_wrap(sp_agent_robot inner, ev_track *t, sp_agent_robot *out, sp_error *err)
{
    rec_robot *r = calloc(1, sizeof *r);
    if (!r) {
        sp_agent_robot_close(&inner);
        return sp_error_set(err, SP_E_NOMEM, "demo: out of memory");
    }
    r->inner = inner;
    r->track = t;
    r->ops = (sp_agent_robot_ops){inner.ops->name, inner.ops->realtime, rec_pose, rec_send, rec_poll, rec_cancel,
                                  rec_close};
    out->ops = &r->ops;
    out->ctx = r;
    return SP_OK;
}

/* ---- the simulated robot in a thread ---- */

static void *sim_main(void *arg)
{
    ev_drive_env *env = arg;
    env->sim_rc = sp_ros_sim_run(&env->sim_opts, &env->stop, NULL, &env->sim_err);
    return NULL;
}

/* A DDS domain no other run on this machine holds (an flock the kernel drops when we exit), as
 * the ros tests reserve theirs: a shared domain shows other runs' nodes. */
static int reserve_domain(int *fd_out)
{
    int first = (int)(((unsigned)getpid() * 2654435761u ^ (unsigned)time(NULL)) % 230u);
    for (int k = 0; k < 230; k++) {
        int d = 1 + (first + k) % 230;
        char lock[64];
        snprintf(lock, sizeof lock, "/tmp/semsplat-ros-domain-%d.lock", d);
        int fd = open(lock, O_RDONLY | O_CREAT | O_CLOEXEC, 0666);
        if (fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) == 0) {
            *fd_out = fd;
            return d;
        }
        if (fd >= 0) close(fd);
    }
    *fd_out = -1;
    return 1 + first;
}

static void nap(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&ts, NULL);
}

static int start_sim(ev_drive_env *env, const sp_drive_opts *o, sp_ros_options *ros, sp_error *err)
{
    sp_ros_sim_options *so = &env->sim_opts;
    sp_ros_sim_options_default(so);
    so->ros = *ros;
    so->ros.node_name = "semsplat_demo_robot";
    so->costmap = sp_nav_costmap(env->nav);
    so->device = env->dev;
    so->start_x = env->start[0], so->start_y = env->start[1], so->start_yaw = env->start[2];
    so->max_speed = o->max_speed_mps > 0 ? o->max_speed_mps : 0.5;
    so->time_scale = o->time_scale > 0 ? o->time_scale : 3;
    snprintf(env->ready, sizeof env->ready, "%s/agent/sim_ready.%ld", o->out_dir, (long)getpid());
    unlink(env->ready);
    so->ready_file = env->ready;
    env->stop = 0;
    env->sim_rc = 1; /* running */
    if (pthread_create(&env->sim, NULL, sim_main, env))
        return sp_error_set(err, SP_E_IO, "demo: cannot start the simulated robot's thread");
    env->sim_started = 1;
    for (double until = sp_time_now() + 60; !sp_file_exists(env->ready); nap(0.05)) {
        if (env->sim_rc != 1) {
            *err = env->sim_err;
            return sp_error_prefix(err, "demo: the simulated robot stopped: ");
        }
        if (sp_time_now() > until) return sp_error_set(err, SP_E_NET, "demo: the simulated robot was not ready within 60 s");
    }
    return SP_OK;
}

static void stop_sim(ev_drive_env *env)
{
    if (!env->sim_started) return;
    env->stop = 1;
    pthread_join(env->sim, NULL);
    env->sim_started = 0;
    if (env->ready[0]) unlink(env->ready);
}

/* ---- the environment ---- */

/* The map of a small CPU-trained splat splits its free space with floaters and leaves much
 * unobserved at nav's defaults (the CPU demo model of the house: no path from the start at all).
 * Twice the carving rays, occupied specks of up to 20 cells dropped and the body band from 0.15 m
 * connect most of it; chosen on that house model (the bookstore is measured in the report). */
void sp_eval_drive_map_opts(sp_nav_opts *o)
{
    *o = sp_nav_opts_default();
    o->costmap.carve_downscale = 2;
    o->costmap.despeckle_cells = 20;
    o->costmap.band_lo_m = 0.15f;
    /* hit_blocks_free (nav's default since n5) made this map's start a 5.5 m^2 island on the CPU
     * demo model (5 of 24 objects reachable, and the demo video's three commands arrived at none;
     * with n6's rules 11 of 24); off, with faint_blocks_free (on by default), 18 of 24, 72.6 %
     * agreement, 0.43 % of truly occupied cells free (1.13 % without faint_blocks_free) */
    o->costmap.hit_blocks_free = 0;
}

static int open_robot(ev_drive_env *env, const sp_drive_opts *o, sp_agent_config *cfg, sp_agent_robot *robot,
                      sp_error *err)
{
    int rc = SP_E_UNSUPPORTED;
    if (o->robot != SP_DEMO_ROBOT_OFFLINE) {
        sp_ros_options ros;
        sp_ros_options_default(&ros);
        ros.loopback_only = 1;
        ros.domain_id = reserve_domain(&env->lock_fd);
        snprintf(env->ns, sizeof env->ns, "/semsplat_demo_%ld", (long)getpid());
        ros.ns = env->ns;
        ros.node_name = "semsplat_demo_agent";
        sp_error e = {0};
        rc = start_sim(env, o, &ros, &e);
        cfg->ros = ros;
        cfg->ros_wait_s = 30;
        if (!rc) rc = sp_agent_robot_ros(robot, cfg, &e);
        if (!rc) {
            env->dds = 1;
            snprintf(env->robot_note, sizeof env->robot_note,
                     "simulated robot over DDS (Cyclone, loopback, domain %d): Nav2's NavigateToPose, /odom, /tf",
                     ros.domain_id);
            return SP_OK;
        }
        stop_sim(env);
        if (o->robot == SP_DEMO_ROBOT_DDS) {
            *err = e;
            return sp_error_prefix(err, "demo: the robot over DDS: ");
        }
        snprintf(env->robot_note, sizeof env->robot_note, "OFFLINE robot (no DDS: %.200s)", e.msg);
    } else {
        snprintf(env->robot_note, sizeof env->robot_note, "OFFLINE robot (asked for)");
    }
    sp_agent_offline_opts off = sp_agent_offline_opts_default();
    off.start = (sp_agent_pose){env->start[0], env->start[1], 0, env->start[2]};
    return sp_agent_robot_offline(robot, &off, err);
}

int ev_drive_open(ev_drive_env *env, const sp_drive_opts *o, sp_error *err)
{
    memset(env, 0, sizeof *env);
    env->lock_fd = -1;
    env->dev = o->dev;
    env->log = o->log;
    char dir[1200];
    snprintf(dir, sizeof dir, "%s/agent", o->out_dir);
    int rc = sp_mkdirs(dir, err);
    if (!rc) rc = sp_query_engine_open(&env->engine, o->model_dir, NULL, o->dev, o->log, err);
    if (!rc) rc = sp_nav_create(&env->nav, env->engine, NULL, NULL, 0, o->nav, o->dev, o->log, err);
    if (!rc) rc = sp_nav_default_start(env->nav, env->start, err);
    if (!rc) rc = sp_raster_create(&env->raster, o->dev, err);
    if (!rc) rc = sp_scene_create(&env->scene, o->dev, sp_query_engine_splat(env->engine), SP_SCENE_RGB, err);
    sp_agent_config cfg = sp_agent_config_default();
    cfg.model_dir = o->model_dir;
    cfg.out_dir = dir;
    cfg.device = o->dev;
    cfg.nav = o->nav;
    cfg.log = o->log;
    cfg.max_speed_mps = o->max_speed_mps > 0 ? o->max_speed_mps : 0.5;
    sp_agent_robot robot = {0}, rec = {0};
    if (!rc) rc = open_robot(env, o, &cfg, &robot, err);
    if (!rc) rc = rec_wrap(robot, &env->track, &rec, err);
    if (!rc) rc = sp_agent_session_open_with_robot(&env->session, &cfg, rec, err);
    if (!rc) sp_logf(o->log, SP_LOG_INFO, "demo: robot: %s", env->robot_note);
    if (rc) ev_drive_close(env);
    return rc;
}

void ev_drive_close(ev_drive_env *env)
{
    sp_agent_session_close(env->session);
    stop_sim(env);
    if (env->lock_fd >= 0) close(env->lock_fd);
    sp_scene_free(env->scene);
    sp_raster_free(env->raster);
    sp_nav_free(env->nav);
    sp_query_engine_free(env->engine);
    free(env->track.s);
    free(env->track.plan);
    memset(env, 0, sizeof *env);
    env->lock_fd = -1;
}

int ev_drive_ask(ev_drive_env *env, const char *text, sp_agent_answer *a, sp_error *err)
{
    env->track.n = 0;
    env->track.goal_sent = 0;
    sp_logf(env->log, SP_LOG_INFO, "agent: \"%s\"", text);
    return sp_agent_session_ask(env->session, text, a, err);
}

int ev_drive_render(ev_drive_env *env, double x, double y, double yaw, int w, int h, float *rgb, float *alpha,
                    sp_error *err)
{
    const sp_nav_opts *no = sp_nav_options(env->nav);
    const sp_costmap *cm = sp_nav_costmap(env->nav);
    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    float pos[3] = {(float)x, (float)y, cm->floor_z + no->camera_height_m};
    sp_camera_intrinsics_fov(&cam, w, h, no->preview_hfov_deg * (float)M_PI / 180.0f);
    sp_camera_from_pose(&cam, pos, (float)yaw, -no->camera_pitch_deg * (float)M_PI / 180.0f);
    static const float background[3] = {0.12f, 0.12f, 0.14f};
    sp_render_request req = {.rgb = rgb, .alpha = alpha, .background = background};
    return sp_render_views(env->raster, env->scene, &cam, 1, &req, err);
}
