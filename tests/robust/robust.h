/* Shared by the robustness tests (tests/robust/test_*.c): running the CLI as a child with a
 * deadline (and killing it), the long stages as a table, the small inputs they run on, and a
 * checker that opens every file of an output folder with the library's own readers.
 *
 * The stage table is the one place to add a long stage (eval and the next ones): a name, the
 * command line with {CAP} {MODEL} {FEAT} {OUT} {FIX} placeholders, whether it writes into a copy of
 * the trained model (in place, as lift and distill do) or a fresh folder, and how a second run
 * resumes. test_kill.c and test_full_disk.c run every row. */
#ifndef SP_TESTS_ROBUST_H
#define SP_TESTS_ROBUST_H

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "semsplat/io.h"
#include "test.h"
#include "train/train_internal.h"

/* ---- running the CLI ---------------------------------------------------------------------------- */

typedef struct rb_result {
    int status;     /* exit status, or -1 when killed by a signal or the deadline */
    int signal;     /* the signal that ended it (0 = none) */
    int timed_out;  /* it ran past the deadline and was killed */
    double seconds;
    char out[16384]; /* stdout and stderr, interleaved (the tail when longer) */
} rb_result;

/* Expands {CAP} {MODEL} {FEAT} {OUT} {FIX} in tmpl, then splits on blanks into argv (argv[0] is
 * the CLI). Paths must not hold blanks. Returns argc. */
typedef struct rb_paths {
    char cap[1024], model[1024], feat[1024], out[1024], fix[1024];
} rb_paths;

static inline int rb_argv(const char *tmpl, const rb_paths *p, char *buf, size_t cap, char **argv, int max)
{
    static const char *keys[] = {"{CAP}", "{MODEL}", "{FEAT}", "{OUT}", "{FIX}"};
    const char *vals[] = {p->cap, p->model, p->feat, p->out, p->fix};
    size_t n = (size_t)snprintf(buf, cap, "%s/semsplat ", SP_BUILD_DIR);
    for (const char *s = tmpl; *s && n + 1 < cap;) {
        int k = -1;
        for (int j = 0; j < 5 && k < 0; j++)
            if (!strncmp(s, keys[j], strlen(keys[j]))) k = j;
        if (k >= 0) {
            n += (size_t)snprintf(buf + n, cap - n, "%s", vals[k]);
            s += strlen(keys[k]);
        } else {
            buf[n++] = *s++;
        }
    }
    buf[n < cap ? n : cap - 1] = 0;
    int argc = 0;
    for (char *t = strtok(buf, " "); t && argc < max - 1; t = strtok(NULL, " ")) argv[argc++] = t;
    argv[argc] = NULL;
    return argc;
}

/* Starts argv with stdout+stderr into fd `out_fd` and env additions `env` (NAME=VALUE, NULL-ended,
 * may be NULL). The child leads its own process group, so a kill reaches its helpers too. */
static inline pid_t rb_spawn(char **argv, int out_fd, char **env)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);
        dup2(out_fd, 1);
        dup2(out_fd, 2);
        for (int i = 0; env && env[i]; i++) putenv(env[i]);
        execv(argv[0], argv);
        fprintf(stderr, "cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    return pid;
}

/* Waits for pid until `deadline` (sp_time_now seconds); kills its group (SIGKILL) past it. */
static inline void rb_wait(pid_t pid, double deadline, rb_result *r)
{
    int st = 0;
    for (;;) {
        pid_t w = waitpid(pid, &st, WNOHANG);
        if (w == pid) break;
        if (w < 0 && errno != EINTR) return;
        if (sp_time_now() > deadline) {
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            r->timed_out = 1;
            waitpid(pid, &st, 0);
            break;
        }
        struct timespec ts = {0, 2000000};
        nanosleep(&ts, NULL);
    }
    r->status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r->signal = WIFSIGNALED(st) ? WTERMSIG(st) : 0;
}

static inline void rb_read_output(int fd, rb_result *r)
{
    off_t size = lseek(fd, 0, SEEK_END);
    off_t from = size > (off_t)sizeof r->out - 1 ? size - (off_t)sizeof r->out + 1 : 0;
    ssize_t n = pread(fd, r->out, sizeof r->out - 1, from);
    r->out[n > 0 ? n : 0] = 0;
}

/* Runs argv to its end or `timeout_s`; kill_after_s >= 0 sends SIGKILL to its group then. */
static inline void rb_run_argv(char **argv, char **env, double timeout_s, double kill_after_s, rb_result *r)
{
    memset(r, 0, sizeof *r);
    char tmpl[] = "/tmp/sp-robust-out-XXXXXX";
    int fd = mkstemp(tmpl);
    unlink(tmpl);
    double t0 = sp_time_now();
    pid_t pid = rb_spawn(argv, fd, env);
    if (kill_after_s >= 0) {
        struct timespec ts = {(time_t)kill_after_s, (long)((kill_after_s - (long)kill_after_s) * 1e9)};
        while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
        }
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
    }
    rb_wait(pid, t0 + timeout_s, r);
    r->seconds = sp_time_now() - t0;
    rb_read_output(fd, r);
    close(fd);
}

static inline void rb_run(const char *tmpl, const rb_paths *p, char **env, double timeout_s, double kill_after_s,
                          rb_result *r)
{
    char buf[8192], *argv[128];
    rb_argv(tmpl, p, buf, sizeof buf, argv, 128);
    rb_run_argv(argv, env, timeout_s, kill_after_s, r);
}

/* rm -rf and cp -r in this process (the tests do them for every case: a shell each was half of
 * the bad-input test's processes). */
static inline void rb_rm_rf(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0) return;
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        struct dirent *e;
        while (d && (e = readdir(d))) {
            if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
            char p[2048];
            snprintf(p, sizeof p, "%s/%s", path, e->d_name);
            rb_rm_rf(p);
        }
        if (d) closedir(d);
        rmdir(path);
    } else {
        unlink(path);
    }
}

static inline void rb_cp_r(const char *src, const char *dst)
{
    struct stat st;
    if (stat(src, &st) != 0) return;
    if (S_ISDIR(st.st_mode)) {
        mkdir(dst, 0755);
        DIR *d = opendir(src);
        struct dirent *e;
        while (d && (e = readdir(d))) {
            if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
            char a[2048], b[2048];
            snprintf(a, sizeof a, "%s/%s", src, e->d_name);
            snprintf(b, sizeof b, "%s/%s", dst, e->d_name);
            rb_cp_r(a, b);
        }
        if (d) closedir(d);
    } else {
        char *data = NULL;
        size_t n = 0;
        if (!sp_read_file(src, &data, &n, NULL)) sp_write_file_atomic(dst, data, n, NULL);
        free(data);
    }
}

static inline int rb_sh(const char *fmt, const char *a, const char *b)
{
    char cmd[4200];
    snprintf(cmd, sizeof cmd, fmt, a, b);
    return system(cmd);
}

/* ---- the long stages ---------------------------------------------------------------------------- */

typedef enum {
    RB_FRESH = 0,     /* writes OUT from nothing */
    RB_MODEL_COPY = 1 /* writes into OUT, a fresh copy of the trained model (lift, distill) */
} rb_mode;

typedef struct rb_stage {
    const char *name;
    const char *args;   /* the command, placeholders as rb_argv */
    rb_mode mode;
    const char *resume; /* appended for the second run after a kill ("--resume", "--reuse"), or NULL */
    const char *resume_if; /* ... only when OUT/<this> exists (NULL: always) */
    int kills;          /* kill points tried (they cost a run and a rerun each) */
    int slow_write_us;  /* killed runs: each write sleeps this long, unbuffered (0: as is) */
} rb_stage;

/* Small enough to run many times, big enough to be killed in the middle of writing. */
static const rb_stage rb_stages[] = {
    {"synth", "synth --world {FIX}/tiny.world --model-path {FIX}/models --out {OUT} --views 8 --size 48x36 --points 200 --threads 2 --quiet",
     RB_FRESH, NULL, NULL, 5, 300},
    {"train", "train --colmap {CAP} --out {OUT} --steps 400 --sh-degree 1 --checkpoint-every 50 --device cpu --threads 2 --quiet",
     RB_FRESH, "--resume", "checkpoints/checkpoint.bin", 5, 300},
    {"features", "features --colmap {CAP} --out {OUT} --source labels --dim 4 --quiet", RB_FRESH, NULL, NULL, 5, 3000},
    {"lift", "lift --model {OUT} --features {FEAT} --device cpu --quiet", RB_MODEL_COPY, NULL, NULL, 4, 3000},
    {"distill", "distill --model {OUT} --features {FEAT} --colmap {CAP} --steps 60 --device cpu --threads 2 --quiet",
     RB_MODEL_COPY, NULL, NULL, 4, 3000},
    {"demo", "demo --out {OUT} --world {FIX}/tiny.world --model-path {FIX}/models --views 6 --size 32x24 --steps 40 --dim 4 --device cpu --quiet",
     RB_FRESH, "--reuse", NULL, 3, 0},
};
#define RB_N_STAGES (sizeof rb_stages / sizeof rb_stages[0])

/* The inputs every stage reads, made once under base: a capture, a trained model, a feature folder. */
static inline int rb_inputs(const char *base, rb_paths *p)
{
    memset(p, 0, sizeof *p);
    snprintf(p->fix, sizeof p->fix, "%s/tests/fuzz/fixtures", SP_SOURCE_DIR);
    snprintf(p->cap, sizeof p->cap, "%s/in/cap", base);
    snprintf(p->model, sizeof p->model, "%s/in/model", base);
    snprintf(p->feat, sizeof p->feat, "%s/in/feat", base);
    rb_result r;
    rb_paths q = *p;
    for (int k = 0; k < 3; k++) {
        snprintf(q.out, sizeof q.out, "%s", k == 0 ? p->cap : k == 1 ? p->model : p->feat);
        rb_run(rb_stages[k].args, &q, NULL, 120, -1, &r);
        if (r.status != 0) {
            fprintf(stderr, "cannot make the %s input: %s\n", rb_stages[k].name, r.out);
            return -1;
        }
    }
    return 0;
}

/* OUT for one run of a stage: removed, then a copy of the model for in-place stages. */
static inline void rb_fresh_out(const rb_stage *s, const rb_paths *p, const char *out)
{
    rb_rm_rf(out);
    if (s->mode == RB_MODEL_COPY) rb_cp_r(p->model, out);
}

/* The second run's command: the stage's own, plus its resume flag when it applies. */
static inline void rb_resume_args(const rb_stage *s, const char *out, char *buf, size_t cap)
{
    char probe[2048];
    int use = s->resume != NULL;
    if (use && s->resume_if) {
        snprintf(probe, sizeof probe, "%s/%s", out, s->resume_if);
        use = sp_file_exists(probe);
    }
    snprintf(buf, cap, "%s%s%s", s->args, use ? " " : "", use ? s->resume : "");
}

/* ---- checking an output folder ------------------------------------------------------------------ */

typedef struct rb_tree {
    int files, checked, temps, bad;
    char first_bad[2048];
} rb_tree;

static inline int rb_has_suffix(const char *s, const char *suf)
{
    size_t a = strlen(s), b = strlen(suf);
    return a >= b && !strcmp(s + a - b, suf);
}

/* Opens path with the reader of its kind; 0 when whole, 1 when not a kind we read, <0 broken. */
static inline int rb_check_file(const char *path, const char *name, sp_error *err)
{
    if (rb_has_suffix(name, ".ply")) {
        sp_splat s;
        int rc = sp_ply_read_splat(path, &s, err);
        sp_splat_free(&s);
        return rc;
    }
    if (rb_has_suffix(name, ".json")) {
        struct cJSON *j = NULL;
        int rc = sp_json_read_file(path, &j, err);
        cJSON_Delete(j);
        return rc;
    }
    if (rb_has_suffix(name, ".npy")) {
        sp_npy a;
        int rc = sp_npy_read(path, &a, err);
        sp_npy_free(&a);
        return rc;
    }
    if (rb_has_suffix(name, ".png") || rb_has_suffix(name, ".jpg")) {
        sp_image img;
        int rc = sp_image_read(path, &img, err);
        sp_image_free(&img);
        return rc;
    }
    static const char *const parts[3] = {"cameras.bin", "images.bin", "points3D.bin"};
    for (int k = 0; k < 3; k++)
        if (!strcmp(name, parts[k])) {
            char *d;
            size_t n;
            sp_colmap_model m;
            memset(&m, 0, sizeof m);
            int rc = sp_read_file(path, &d, &n, err);
            if (!rc) rc = sp_colmap_parse_bin((sp_colmap_part)k, d, n, path, &m, err);
            free(d);
            sp_colmap_free(&m);
            return rc;
        }
    if (!strcmp(name, "checkpoint.bin")) {
        tr_checkpoint ck;
        memset(&ck, 0, sizeof ck);
        int rc = tr_checkpoint_read(path, &ck, err);
        tr_checkpoint_free(&ck);
        return rc;
    }
    if (rb_has_suffix(name, ".md")) { /* text: whole when it ends with a newline */
        char *d;
        size_t n;
        int rc = sp_read_file(path, &d, &n, err);
        if (!rc && (n == 0 || d[n - 1] != '\n')) rc = sp_error_set(err, SP_E_FORMAT, "%s: cut short", path);
        free(d);
        return rc;
    }
    return 1;
}

static inline void rb_check_dir(const char *dir, rb_tree *t)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        char p[2048];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat st;
        if (lstat(p, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            rb_check_dir(p, t);
            continue;
        }
        t->files++;
        if (strstr(e->d_name, ".tmp.")) { /* a writer's temporary name: never a final one */
            t->temps++;
            continue;
        }
        sp_error err = {0};
        int rc = rb_check_file(p, e->d_name, &err);
        if (rc == 1) continue;
        t->checked++;
        if (rc) {
            if (!t->bad) snprintf(t->first_bad, sizeof t->first_bad, "%s", err.msg);
            t->bad++;
        }
    }
    if (d) closedir(d);
}

/* Every file under dir opens whole (temporary names excepted). */
static inline rb_tree rb_check_tree(const char *dir)
{
    rb_tree t;
    memset(&t, 0, sizeof t);
    rb_check_dir(dir, &t);
    return t;
}

#endif
