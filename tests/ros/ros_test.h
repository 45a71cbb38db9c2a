/* Helpers for the ros tests: a synthetic room map (as a grid and as a Nav2 PGM/YAML pair), a
 * random DDS domain and namespace per run, and child processes with bounded waits. */
#ifndef SP_ROS_TEST_H
#define SP_ROS_TEST_H

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "semsplat/core.h"
#include "semsplat/ros.h"

/* An 8 m x 6 m room at 5 cm: walls 0.2 m thick around it, an inner wall at x = 4 with a door
 * at 4 < y < 5, a block of unknown space at 6.5..7.5 x 0.5..1.5, and a closed closet (walls
 * 0.1 m thick around 6.6..7.6 x 3.0..4.0) whose free inside nobody can reach. */
#define ROOM_W 160
#define ROOM_H 120
#define ROOM_RES 0.05

static inline int8_t room_cell_at(double x, double y)
{
    if (x < 0.2 || x > 7.8 || y < 0.2 || y > 5.8) return 100;
    if (x > 3.9 && x < 4.1 && !(y > 4.0 && y < 5.0)) return 100;
    if (x > 6.5 && x < 7.5 && y > 0.5 && y < 1.5) return -1;
    if (x > 6.6 && x < 7.6 && y > 3.0 && y < 4.0 && !(x > 6.7 && x < 7.5 && y > 3.1 && y < 3.9))
        return 100;
    return 0;
}

/* Fills g (cells malloc'd; free with sp_ros_grid_free). */
static inline void room_grid(sp_ros_grid *g)
{
    memset(g, 0, sizeof *g);
    g->width = ROOM_W;
    g->height = ROOM_H;
    g->resolution_m = ROOM_RES;
    g->cells = malloc(ROOM_W * ROOM_H);
    snprintf(g->frame_id, sizeof g->frame_id, "map");
    for (int r = 0; r < ROOM_H; r++)
        for (int c = 0; c < ROOM_W; c++)
            g->cells[r * ROOM_W + c] = room_cell_at((c + 0.5) * ROOM_RES, (r + 0.5) * ROOM_RES);
}

/* Writes dir/map.pgm and dir/map.yaml the way map_saver does (254 free, 0 occupied, 205
 * unknown; image row 0 at the top). Returns the YAML path in a static buffer. */
static inline const char *room_write_yaml(const char *dir)
{
    static char yaml[1024];
    char pgm[1024];
    snprintf(pgm, sizeof pgm, "%s/map.pgm", dir);
    snprintf(yaml, sizeof yaml, "%s/map.yaml", dir);
    FILE *f = fopen(pgm, "wb");
    if (!f) return NULL;
    fprintf(f, "P5\n# synthetic room\n%d %d\n255\n", ROOM_W, ROOM_H);
    for (int r = ROOM_H - 1; r >= 0; r--)
        for (int c = 0; c < ROOM_W; c++) {
            int8_t v = room_cell_at((c + 0.5) * ROOM_RES, (r + 0.5) * ROOM_RES);
            fputc(v < 0 ? 205 : v ? 0 : 254, f);
        }
    fclose(f);
    f = fopen(yaml, "w");
    if (!f) return NULL;
    fprintf(f, "image: map.pgm\nmode: trinary\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n"
               "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    fclose(f);
    return yaml;
}

/* A domain id in 1..230 and a namespace unique to this run, so parallel runs (other tests,
 * other people on the machine) never see each other's robots. The domain is also reserved on
 * this machine for as long as the process lives (an flock on /tmp/semsplat-ros-domain-<d>.lock,
 * released by the kernel when it exits, however it exits): the namespace keeps topics apart,
 * but ros_discovery_info and the peers' distro are domain-wide, and a test sharing its domain
 * with another run saw that run's nodes (test_rmw failed so). */
static inline int test_random_domain(char *ns, size_t cap)
{
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    unsigned long long s = (unsigned long long)ts.tv_nsec ^ ((unsigned long long)getpid() << 20);
    s ^= s >> 17;
    s *= 0x9e3779b97f4a7c15ull;
    snprintf(ns, cap, "/t%ld_%llu", (long)getpid(), (s >> 40) % 100000);
    int first = (int)((s >> 32) % 230);
    for (int k = 0; k < 230; k++) {
        int d = 1 + (first + k) % 230;
        char lock[64];
        snprintf(lock, sizeof lock, "/tmp/semsplat-ros-domain-%d.lock", d);
        int fd = open(lock, O_RDONLY | O_CREAT | O_CLOEXEC, 0666);
        if (fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) == 0) return d; /* fd stays open: held */
        if (fd >= 0) close(fd);
    }
    return 1 + first; /* every domain taken (or /tmp unwritable): share one */
}

/* Starts argv[0] with argv, stdout and stderr to log_path. Returns the pid (or -1). */
static inline pid_t test_spawn(char *const argv[], const char *log_path)
{
    pid_t pid = fork();
    if (pid != 0) return pid;
    int fd = open(log_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        dup2(fd, 1);
        dup2(fd, 2);
        close(fd);
    }
    execv(argv[0], argv);
    _exit(127);
}

/* Waits up to timeout_s for a child; returns its exit status, or -1 if it is still running. */
static inline int test_wait_pid(pid_t pid, double timeout_s)
{
    double until = sp_time_now() + timeout_s;
    for (;;) {
        int st;
        pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid) return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
        if (r < 0 || sp_time_now() > until) return -1;
        usleep(20000);
    }
}

/* Stops a child: SIGTERM, then SIGKILL after 3 s. */
static inline void test_stop(pid_t pid)
{
    if (pid <= 0) return;
    kill(pid, SIGTERM);
    if (test_wait_pid(pid, 3.0) < 0) {
        kill(pid, SIGKILL);
        test_wait_pid(pid, 3.0);
    }
}

/* Sends a NavigateToPose goal at (x, y) and returns the state it was answered with (REJECTED,
 * ACCEPTED, ...), or UNKNOWN when sending failed (err says why). The goal is let go. */
static inline sp_ros_goal_state test_goal_answer(sp_ros_bridge *b, double x, double y,
                                                 sp_error *err)
{
    sp_ros_pose goal = {x, y, 0, 0};
    sp_ros_goal *g = NULL;
    sp_ros_goal_status st;
    st.state = SP_ROS_GOAL_UNKNOWN;
    if (sp_ros_navigate_to(b, &goal, NULL, &g, err) == 0 && sp_ros_goal_poll(g, &st, err))
        st.state = SP_ROS_GOAL_UNKNOWN;
    sp_ros_goal_free(g);
    return st.state;
}

static inline int test_wait_file(const char *path, double timeout_s)
{
    double until = sp_time_now() + timeout_s;
    while (access(path, F_OK) != 0) {
        if (sp_time_now() > until) return -1;
        usleep(20000);
    }
    return 0;
}

static inline void test_print_file(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[512];
    while (fgets(line, sizeof line, f)) fprintf(stderr, "  | %s", line);
    fclose(f);
}

#endif
