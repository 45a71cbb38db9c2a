/* The demo video: navigation commands run end to end through the agent and the simulated robot,
 * drawn scene by scene with media's canvas and written with its H.264 writer. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_video.h"
#include "drive.h"

/* Nav's default start is the training camera in the largest free region: on the CPU demo model of
 * the house that stands beside the refrigerator, so it comes last (a drive across the house). */
static const char *const default_commands[] = {"take me to the couch", "navigate to the dining table",
                                               "go to the refrigerator"};

sp_demo_video_opts sp_demo_video_opts_default(void)
{
    sp_demo_video_opts o;
    memset(&o, 0, sizeof o);
    o.drive.out_dir = "demo";
    return o;
}

typedef struct dv_ctx {
    const sp_demo_video_opts *o;
    ev_drive_env env;
    sp_video *video;
    sp_canvas *c;
    dv_map map;
    int W, H, fps, vw, vh;
    float *view;
} dv_ctx;

static int hold(dv_ctx *x, double seconds, sp_error *err)
{
    int n = (int)(seconds * x->fps + 0.5);
    return sp_video_frame_canvas(x->video, x->c, n < 1 ? 1 : n, err);
}

static float S(const dv_ctx *x, float v) { return v * (float)x->H / 720.0f; }

static int scene_title(dv_ctx *x, int i, int n, const char *show, const char *go)
{
    char title[64], sub[700];
    snprintf(title, sizeof title, "Command %d of %d", i + 1, n);
    snprintf(sub, sizeof sub, "you typed:  \"%s\"\nthen:  \"%s\"", show, go);
    sp_media_title_card(x->c, title, sub, x->env.robot_note);
    return 0;
}

static int scene_heatmap(dv_ctx *x, const ev_answer_info *ai, const char *target, sp_error *err)
{
    sp_canvas_clear(x->c, sp_rgba_of(0.09f, 0.10f, 0.13f, 1));
    int rc = dv_image_file(x->c, ai->heatmap, S(x, 40), S(x, 60), (float)x->W - S(x, 80), (float)x->H - S(x, 170), err);
    char t[300], cap[400];
    snprintf(t, sizeof t, "query_object_location(\"%s\"): relevancy heatmap of the splat", target);
    sp_media_label(x->c, S(x, 40), S(x, 14), S(x, 26), t);
    if (ai->have_target)
        snprintf(cap, sizeof cap, "Found \"%s\" at (%.2f, %.2f, %.2f) m in the world frame: red = most relevant.", target,
                 ai->target[0], ai->target[1], ai->target[2]);
    else
        snprintf(cap, sizeof cap, "\"%s\" was not found on the map.", target);
    sp_media_caption(x->c, cap);
    return rc;
}

static int scene_trajectories(dv_ctx *x, const ev_answer_info *ai, sp_error *err)
{
    sp_canvas_clear(x->c, sp_rgba_of(0.09f, 0.10f, 0.13f, 1));
    float mw = (float)x->W * 0.5f;
    int rc = dv_image_file(x->c, ai->map_image, S(x, 20), S(x, 60), mw - S(x, 30), (float)x->H - S(x, 170), err);
    sp_media_label(x->c, S(x, 20), S(x, 14), S(x, 24), "show_trajectories: ranked paths on the map");
    sp_media_label(x->c, mw + S(x, 10), S(x, 14), S(x, 24), "previews (rendered from the splat)");
    int np = ai->n_previews < 6 ? ai->n_previews : 6;
    float pw = (mw - S(x, 40)) / 2, ph = ((float)x->H - S(x, 190)) / 3;
    for (int k = 0; k < np && !rc; k++)
        rc = dv_image_file(x->c, ai->previews[k], mw + S(x, 10) + (float)(k % 2) * (pw + S(x, 10)),
                           S(x, 60) + (float)(k / 2) * (ph + S(x, 5)), pw, ph, err);
    char cap[600];
    int u = snprintf(cap, sizeof cap, "%d trajectories:", ai->n_traj);
    for (int k = 0; k < ai->n_traj && u < (int)sizeof cap; k++)
        u += snprintf(cap + u, sizeof cap - (size_t)u, " #%d %.1f m (score %.2f)%s", k + 1, ai->traj_len[k],
                      ai->traj_score[k], k + 1 < ai->n_traj ? "," : "");
    sp_media_caption(x->c, ai->n_traj ? cap : "no trajectory found");
    return rc;
}

static int scene_tools(dv_ctx *x, const sp_agent_answer *a1, const ev_answer_info *i1, const sp_agent_answer *a2,
                       const ev_answer_info *i2, sp_error *err)
{
    (void)err;
    char l1[300], l2[300];
    snprintf(l1, sizeof l1, "\"%s\"  (intent: %s)", a1->command, sp_agent_intent_name(a1->intent));
    snprintf(l2, sizeof l2, "\"%s\"  (intent: %s)", a2->command, sp_agent_intent_name(a2->intent));
    const char *blocks[2] = {i1->tools, i2->tools}, *labels[2] = {l1, l2};
    dv_tools_panel(x->c, "The agent's tool calls (built-in parser brain)", blocks, labels, 2);
    sp_media_caption(x->c, a2->text ? a2->text : "");
    return 0;
}

/* One frame of the drive: the splat from the robot's pose, the map with plan, trail and robot. */
static int drive_frame(dv_ctx *x, const ev_track *t, int upto, const ev_answer_info *ai, const char *caption, sp_error *err)
{
    const sp_drive_sample *s = &t->s[upto];
    int rc = ev_drive_render(&x->env, s->x, s->y, s->yaw, x->vw, x->vh, x->view, NULL, err);
    if (rc) return rc;
    sp_canvas_clear(x->c, sp_rgba_of(0.09f, 0.10f, 0.13f, 1));
    float half = (float)x->W * 0.5f, top = S(x, 60), h = (float)x->H - S(x, 170);
    rc = sp_canvas_image_f32(x->c, x->view, x->vw, x->vh, S(x, 20), top, half - S(x, 30), h, NULL, err);
    if (!rc) rc = dv_map_draw(x->c, &x->map, half + S(x, 10), top, half - S(x, 30), h, err);
    if (rc) return rc;
    for (int k = ai->n_traj - 1; k >= 1; k--) /* the other ranked paths, faint */
        dv_map_path(x->c, &x->map, &ai->traj[k][0][0], ai->traj_n[k], 2, sp_rgba_of(0.5f, 0.5f, 0.6f, 0.6f), 2);
    dv_map_path(x->c, &x->map, t->plan, t->n_plan, 4, sp_media_palette(0), 4);
    double *trail = malloc(sizeof(double) * 2 * (size_t)(upto + 1));
    for (int i = 0; trail && i <= upto; i++) trail[2 * i] = t->s[i].x, trail[2 * i + 1] = t->s[i].y;
    if (trail) dv_map_path(x->c, &x->map, trail, upto + 1, 2, sp_rgba_of(0.85f, 0.1f, 0.1f, 0.9f), 3);
    free(trail);
    dv_map_marker(x->c, &x->map, t->goal[0], t->goal[1], sp_rgba_of(0.0f, 0.6f, 0.3f, 1), "goal");
    dv_map_robot(x->c, &x->map, s->x, s->y, s->yaw);
    sp_media_label(x->c, S(x, 20), S(x, 14), S(x, 24), "the splat rendered from the robot's pose");
    sp_media_label(x->c, half + S(x, 10), S(x, 14), S(x, 24), "map: plan (blue), driven (red), robot");
    sp_media_caption(x->c, caption);
    return SP_OK;
}

static int scene_drive(dv_ctx *x, const ev_answer_info *ai, const char *target, sp_error *err)
{
    const ev_track *t = &x->env.track;
    if (!t->goal_sent || t->n < 1) {
        sp_canvas_clear(x->c, sp_rgba_of(0.09f, 0.10f, 0.13f, 1));
        char cap[400];
        snprintf(cap, sizeof cap, "No goal was sent: %s", ai->first_error[0] ? ai->first_error : "nothing to drive to");
        sp_media_caption(x->c, cap);
        return hold(x, 3, err);
    }
    int F = x->o->drive_frames > 0 ? x->o->drive_frames : 60;
    double t_end = t->s[t->n - 1].t;
    int repeat = (int)ceil(6.0 * x->fps / F);
    int j = 0, rc = 0, fed = 0;
    const char *via = x->env.dds ? "sim-robot over DDS" : "OFFLINE robot (no DDS)";
    for (int k = 0; k < F && !rc; k++) {
        double tk = F > 1 ? t_end * k / (F - 1) : t_end;
        while (j + 1 < t->n && t->s[j + 1].t <= tk) j++;
        char cap[300];
        for (int q = fed; q <= j && !fed; q++) fed = t->s[q].remaining_m > 0; /* a feedback message came */
        if (fed || t->s[j].status != SP_AGENT_GOAL_ACTIVE)
            snprintf(cap, sizeof cap, "Driving (%s): %.2f m remaining (the robot's feedback), t = %.1f s", via,
                     t->s[j].remaining_m, t->s[j].t);
        else
            snprintf(cap, sizeof cap, "Goal accepted (%s), waiting for the robot's first feedback, t = %.1f s", via,
                     t->s[j].t);
        rc = drive_frame(x, t, j, ai, cap, err);
        if (!rc) rc = sp_video_frame_canvas(x->video, x->c, repeat < 1 ? 1 : repeat, err);
    }
    char cap[300];
    int ok = !strcmp(ai->goal_status, "succeeded");
    snprintf(cap, sizeof cap, "%s at the %s: %s, %.2f m from the goal after %.1f s.", ok ? "ARRIVED" : "NOT ARRIVED",
             target, ai->goal_status[0] ? ai->goal_status : "no result", ai->distance_to_goal_m, t_end);
    if (!rc) rc = drive_frame(x, t, t->n - 1, ai, cap, err);
    if (!rc) rc = hold(x, 2.5, err);
    return rc;
}

static int one_command(dv_ctx *x, int i, int n, const char *go, sp_demo_video_result *r, sp_error *err)
{
    sp_agent_intent in;
    sp_agent_parse(go, &in);
    char show[300];
    snprintf(show, sizeof show, "show me the top 3 trajectories to the %s", in.target[0] ? in.target : go);
    sp_agent_answer a1, a2;
    memset(&a1, 0, sizeof a1), memset(&a2, 0, sizeof a2);
    ev_answer_info i1, i2;
    int rc = scene_title(x, i, n, show, go);
    if (!rc) rc = hold(x, 3, err);
    if (!rc) rc = ev_drive_ask(&x->env, show, &a1, err);
    if (!rc) ev_answer_read(&a1, &i1);
    if (!rc) rc = ev_drive_ask(&x->env, go, &a2, err);
    if (!rc) ev_answer_read(&a2, &i2);
    if (!rc) rc = scene_tools(x, &a1, &i1, &a2, &i2, err);
    if (!rc) rc = hold(x, 5, err);
    if (!rc) rc = scene_heatmap(x, &i1, in.target, err);
    if (!rc) rc = hold(x, 3.5, err);
    if (!rc) rc = scene_trajectories(x, &i1, err);
    if (!rc) rc = hold(x, 4.5, err);
    if (!rc) rc = scene_drive(x, &i2, in.target, err);
    if (!rc && !strcmp(i2.goal_status, "succeeded")) r->n_arrived++;
    sp_agent_answer_free(&a1);
    sp_agent_answer_free(&a2);
    return rc;
}

static int closing(dv_ctx *x, const sp_demo_video_result *r, sp_error *err)
{
    char sub[400];
    snprintf(sub, sizeof sub, "%d of %d commands arrived.\nRobot: %s", r->n_arrived, r->n_commands, x->env.robot_note);
    sp_media_title_card(x->c, "semsplat demo", sub, "language-embedded 3D Gaussian splatting for robot navigation");
    return hold(x, 3, err);
}

int sp_demo_video(const sp_demo_video_opts *o, sp_demo_video_result *r, sp_error *err)
{
    memset(r, 0, sizeof *r);
    double t0 = sp_time_now();
    dv_ctx x;
    memset(&x, 0, sizeof x);
    x.o = o;
    x.W = o->width > 0 ? o->width : 1280, x.H = o->height > 0 ? o->height : 720;
    x.fps = o->fps > 0 ? o->fps : 10;
    x.vw = o->view_width > 0 ? o->view_width : 480, x.vh = o->view_height > 0 ? o->view_height : 360;
    const char *const *cmds = o->commands ? o->commands : default_commands;
    int n = o->commands ? o->n_commands : 3;
    if (n < 1) return sp_error_set(err, SP_E_ARG, "demo video: no commands");
    if (o->out_path) snprintf(r->path, sizeof r->path, "%s", o->out_path);
    else snprintf(r->path, sizeof r->path, "%s/demo.mp4", o->drive.out_dir ? o->drive.out_dir : "demo");
    sp_video_opts vo = {.width = x.W, .height = x.H, .fps = x.fps};
    x.view = malloc(sizeof(float) * 3 * (size_t)x.vw * x.vh);
    int rc = x.view ? 0 : sp_error_set(err, SP_E_NOMEM, "demo video: out of memory");
    if (!rc) rc = sp_canvas_create(&x.c, x.W, x.H, err);
    if (!rc) rc = ev_drive_open(&x.env, &o->drive, err);
    if (!rc) rc = dv_map_init(&x.map, sp_nav_costmap(x.env.nav), err);
    if (!rc) rc = sp_video_open(&x.video, r->path, &vo, err);
    if (!rc) snprintf(r->robot, sizeof r->robot, "%s", x.env.robot_note);
    r->n_commands = n;
    for (int i = 0; i < n && !rc; i++) rc = one_command(&x, i, n, cmds[i], r, err);
    if (!rc) rc = closing(&x, r, err);
    if (!rc) {
        r->frames = sp_video_frames(x.video);
        r->seconds = (double)r->frames / x.fps;
        rc = sp_video_close(x.video, err);
    } else {
        sp_video_discard(x.video);
    }
    dv_map_free(&x.map);
    ev_drive_close(&x.env);
    sp_canvas_free(x.c);
    free(x.view);
    r->t_wall = sp_time_now() - t0;
    return rc ? sp_error_prefix(err, "demo video: ") : 0;
}
