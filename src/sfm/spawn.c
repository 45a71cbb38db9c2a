/* Running an external program (COLMAP) from the library: fork + execv with the output appended
 * to a log, the child in its own process group (so a timeout kills it and anything it started,
 * and nothing else), niceness raised on request, and a bounded wait. The child is also told to
 * die with its parent (Linux's PR_SET_PDEATHSIG), so an interrupted run leaves no COLMAP behind. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "semsplat/sfm.h"

int sp_sfm_find_colmap(const char *name, char *out, size_t cap, sp_error *err)
{
    const char *n = name && *name ? name : "colmap";
    if (strchr(n, '/')) {
        if (access(n, X_OK) == 0 && snprintf(out, cap, "%s", n) < (int)cap) return 0;
        return sp_error_set(err, SP_E_NOTFOUND, "%s: not an executable program", n);
    }
    const char *path = getenv("PATH");
    if (!path || !*path) path = "/usr/local/bin:/usr/bin:/bin";
    for (const char *p = path; *p;) {
        const char *e = strchr(p, ':');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        char cand[4096];
        if (len > 0 && len + strlen(n) + 2 < sizeof cand) {
            memcpy(cand, p, len);
            snprintf(cand + len, sizeof cand - len, "/%s", n);
            struct stat st;
            if (stat(cand, &st) == 0 && S_ISREG(st.st_mode) && access(cand, X_OK) == 0) {
                if (snprintf(out, cap, "%s", cand) >= (int)cap) break;
                return 0;
            }
        }
        if (!e) break;
        p = e + 1;
    }
    return sp_error_set(err, SP_E_NOTFOUND,
                        "'%s' is not on PATH: structure-from-motion needs COLMAP (Debian: apt-get "
                        "install colmap, as scripts/install-deps.sh does), or give its path", n);
}

static void sleep_s(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {}
}

/* Waits for pid up to limit seconds; 1 when it exited (status in *st), 0 on timeout. */
static int wait_for(pid_t pid, double limit, int *st)
{
    double t0 = sp_time_now(), nap = 0.01;
    for (;;) {
        pid_t r = waitpid(pid, st, WNOHANG);
        if (r == pid) return 1;
        if (r < 0 && errno != EINTR) return -1;
        if (sp_time_now() - t0 >= limit) return 0;
        sleep_s(nap);
        if (nap < 0.2) nap *= 1.5;
    }
}

int sp_sfm_spawn(char *const argv[], const char *log_path, int nice_inc, double timeout_s,
                 sp_error *err)
{
    if (!argv || !argv[0]) return sp_error_set(err, SP_E_ARG, "spawn: no program");
    if (nice_inc < 0 || nice_inc > 19)
        return sp_error_set(err, SP_E_ARG, "spawn %s: niceness %d: expected 0..19", argv[0], nice_inc);
    if (!(timeout_s > 0)) return sp_error_set(err, SP_E_ARG, "spawn %s: timeout %g s", argv[0], timeout_s);
    int logfd = open(log_path, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (logfd < 0) return sp_error_set(err, SP_E_IO, "%s: %s", log_path, strerror(errno));
    int nullfd = open("/dev/null", O_RDONLY | O_CLOEXEC);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid < 0) {
        int e = errno;
        close(logfd);
        if (nullfd >= 0) close(nullfd);
        return sp_error_set(err, SP_E_IO, "spawn %s: fork: %s", argv[0], strerror(e));
    }
    if (pid == 0) { /* child: async-signal-safe calls only */
        setpgid(0, 0);
#ifdef __linux__
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(126);
#endif
        if (nullfd >= 0) dup2(nullfd, 0);
        dup2(logfd, 1);
        dup2(logfd, 2);
        if (nice_inc > 0 && nice(nice_inc) == -1 && errno != 0) {}
        execv(argv[0], argv);
        static const char msg[] = "exec failed\n";
        if (write(2, msg, sizeof msg - 1) < 0) {}
        _exit(127);
    }
    setpgid(pid, pid); /* also from here: whichever runs first */
    close(logfd);
    if (nullfd >= 0) close(nullfd);
    int st = 0, done = wait_for(pid, timeout_s, &st);
    if (done == 0) {
        kill(-pid, SIGTERM);
        if (wait_for(pid, 3.0, &st) != 1) {
            kill(-pid, SIGKILL);
            waitpid(pid, &st, 0);
        }
        return sp_error_set(err, SP_E_IO, "%s ran past its %.0f s limit and was stopped (log: %s)",
                            argv[1] ? argv[1] : argv[0], timeout_s, log_path);
    }
    if (done < 0) return sp_error_set(err, SP_E_IO, "spawn %s: waitpid: %s", argv[0], strerror(errno));
    const char *what = argv[1] ? argv[1] : argv[0];
    if (WIFSIGNALED(st))
        return sp_error_set(err, SP_E_IO, "%s %s was killed by signal %d (log: %s)", argv[0], what,
                            WTERMSIG(st), log_path);
    if (WIFEXITED(st) && WEXITSTATUS(st) == 127)
        return sp_error_set(err, SP_E_IO, "%s could not be started (log: %s)", argv[0], log_path);
    if (WIFEXITED(st) && WEXITSTATUS(st) != 0)
        return sp_error_set(err, SP_E_IO, "%s %s failed with exit status %d (log: %s)", argv[0], what,
                            WEXITSTATUS(st), log_path);
    return 0;
}
