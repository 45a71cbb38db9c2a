/* Private to eval: navigation commands run end to end for the demo video and for 5.3 (query
 * success rate): the agent session on a model folder, its robot (the simulated robot over
 * loopback DDS in a thread of this process, or the offline robot) wrapped so that every pose
 * the robot reports is recorded, and the splat rendered from any pose. */
#ifndef SEMSPLAT_EVAL_DRIVE_H
#define SEMSPLAT_EVAL_DRIVE_H

#include <pthread.h>
#include <signal.h>

#include "semsplat/agent.h"
#include "semsplat/eval.h"
#include "semsplat/nav.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

/* What the robot reported while following one goal. */
typedef struct ev_track {
    int n, cap;
    sp_drive_sample *s;
    double *plan;   /* [n_plan][4] the issued plan the goal belongs to */
    int n_plan;
    int goal_sent;
    double goal[3]; /* x, y, yaw */
    double t0;
} ev_track;

typedef struct ev_drive_env {
    sp_device *dev;
    const sp_log *log;
    sp_query_engine *engine;
    sp_nav *nav;
    sp_scene *scene;
    sp_raster *raster;
    sp_agent_session *session;
    ev_track track;
    float start[3];
    int dds;              /* 1: the simulated robot over DDS; 0: the offline robot */
    char robot_note[300]; /* what robot drives, and why when it is the offline one */
    pthread_t sim;
    int sim_started;
    volatile sig_atomic_t stop;
    volatile int sim_rc;  /* 1 while the thread runs, then sp_ros_sim_run's return */
    sp_error sim_err;
    sp_ros_sim_options sim_opts;
    char ns[48], ready[1200];
    int lock_fd;
} ev_drive_env;

int ev_drive_open(ev_drive_env *env, const sp_drive_opts *o, sp_error *err);
void ev_drive_close(ev_drive_env *env);
/* One command to the agent; the track is cleared first and holds the drive afterwards. */
int ev_drive_ask(ev_drive_env *env, const char *text, sp_agent_answer *a, sp_error *err);
/* The splat from a robot pose (camera at nav's camera height and pitch): rgb [h][w][3] in
 * [0,1], alpha [h][w] (may be NULL). */
int ev_drive_render(ev_drive_env *env, double x, double y, double yaw, int w, int h, float *rgb,
                    float *alpha, sp_error *err);

/* The pieces of an answer's trace the video and 5.3 read. */
typedef struct ev_answer_info {
    char tools[1200];       /* one line per call: name(args) -> ok / error code */
    char heatmap[1100], map_image[1100];
    char previews[12][1100];
    int n_previews;
    int n_traj;
    double traj[3][12][2];  /* the ranked trajectories' waypoints (as the trace samples them) */
    int traj_n[3];
    double traj_len[3], traj_score[3];
    int found;              /* query_object_location found the target */
    double target[3];
    int have_target;
    int planned;            /* plan_path or show_trajectories gave a path */
    char goal_status[24];   /* send_nav2_goal's status ("" when none was sent) */
    double distance_to_goal_m;
    char first_error[200];
} ev_answer_info;

void ev_answer_read(const sp_agent_answer *a, ev_answer_info *out);

#endif
