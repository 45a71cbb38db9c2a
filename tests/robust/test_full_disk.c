/* Every long stage (robust.h's table) on a disk that fills up. Two ways:
 *  - tests/robust/enospc_shim.c (LD_PRELOAD, test-only): writes under the output folder fail
 *    with ENOSPC once the process has written a budget of bytes; budgets at fractions of what the
 *    stage writes (measured by a first run through the shim without a limit);
 *  - a real small tmpfs over the output folder, when this machine lets the test make a mount
 *    namespace (root, or unprivileged user namespaces); skipped (and said so) otherwise.
 * Each failing run must exit non-zero without a signal, say which file could not be written and
 * why, and leave only whole files under final names; a repeated run (with space) succeeds. */
#include "robust.h"

static char self[1024];

/* KB the regular files under dir take on a tmpfs (whole 4 KB pages). */
static long long tree_kb(const char *dir)
{
    long long n = 0;
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        char p[2048];
        struct stat st;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        if (lstat(p, &st) == 0) n += S_ISDIR(st.st_mode) ? tree_kb(p) : ((long long)st.st_size + 4095) / 4096 * 4;
    }
    if (d) closedir(d);
    return n;
}

/* The error names the file (a path under OUT) and the cause. */
static void check_message(const rb_stage *s, const char *out, const char *msg, const char *how)
{
    CHECK_MSG(strstr(msg, out) != NULL, "%s (%s): the error does not name a file under %s: %s", s->name, how, out, msg);
    CHECK_MSG(strstr(msg, "No space left on device") != NULL, "%s (%s): the error does not say the disk is full: %s",
              s->name, how, msg);
}

/* A stage's second run: with space, it succeeds and leaves only whole files. */
static void repeat_ok(const rb_stage *s, const rb_paths *p, const char *how)
{
    rb_result r;
    char again[2048];
    rb_resume_args(s, p->out, again, sizeof again);
    rb_run(again, p, NULL, 300, -1, &r);
    CHECK_MSG(r.status == 0, "%s: the run after a full disk (%s) failed: %s", s->name, how, r.out);
    rb_tree t = rb_check_tree(p->out);
    CHECK_MSG(t.bad == 0, "%s: after the repeated run %d files are not whole: %s", s->name, t.bad, t.first_bad);
}

/* Returns the KB a complete output takes on a tmpfs. */
static long long with_shim(const rb_stage *s, const rb_paths *in)
{
    rb_paths p = *in;
    snprintf(p.out, sizeof p.out, "%s/../%s", in->cap, s->name);
    char report[1200], e_pre[1200], e_dir[1200], e_bytes[64], e_rep[1300];
    snprintf(report, sizeof report, "%s.bytes", p.out);
    snprintf(e_pre, sizeof e_pre, "LD_PRELOAD=%s", SP_ENOSPC_SHIM);
    snprintf(e_dir, sizeof e_dir, "SP_ENOSPC_DIR=%s", p.out);
    snprintf(e_rep, sizeof e_rep, "SP_ENOSPC_REPORT=%s", report);
    /* ASan insists on being first in the library list; the shim does not need that. */
    char e_asan[] = "ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0";
    char *env[] = {e_pre, e_dir, e_bytes, e_rep, e_asan, NULL};
    snprintf(e_bytes, sizeof e_bytes, "SP_ENOSPC_BYTES=-1");
    rb_result r;
    rb_fresh_out(s, &p, p.out);
    rb_run(s->args, &p, env, 300, -1, &r);
    CHECK_MSG(r.status == 0, "%s through the shim without a limit failed: %s", s->name, r.out);
    char *txt = NULL;
    size_t n;
    long long total = 0;
    if (!sp_read_file(report, &txt, &n, NULL)) total = atoll(txt);
    free(txt);
    CHECK_MSG(total > 0, "%s: the shim saw no writes under %s", s->name, p.out);
    const double fractions[] = {0.0, 0.3, 0.9};
    int failed_cleanly = 0;
    for (size_t k = 0; k < sizeof fractions / sizeof fractions[0] && total > 0; k++) {
        long long budget = (long long)(fractions[k] * (double)total);
        snprintf(e_bytes, sizeof e_bytes, "SP_ENOSPC_BYTES=%lld", budget);
        rb_fresh_out(s, &p, p.out);
        rb_run(s->args, &p, env, 300, -1, &r);
        char how[64];
        snprintf(how, sizeof how, "%lld of %lld bytes", budget, total);
        CHECK_MSG(r.signal == 0 && !r.timed_out, "%s (%s): ended by signal %d%s: %s", s->name, how, r.signal,
                  r.timed_out ? " (timed out)" : "", r.out);
        CHECK_MSG(r.status != 0, "%s (%s): succeeded on a full disk", s->name, how);
        if (r.status != 0 && r.signal == 0) {
            check_message(s, p.out, r.out, how);
            failed_cleanly++;
        }
        rb_tree t = rb_check_tree(p.out);
        CHECK_MSG(t.bad == 0, "%s (%s): %d files under final names are not whole: %s", s->name, how, t.bad,
                  t.first_bad);
        CHECK_MSG(t.temps == 0, "%s (%s): %d temporary files left behind after a failed write", s->name, how, t.temps);
        repeat_ok(s, &p, how);
    }
    fprintf(stderr, "%-9s writes %lld bytes: %d budgets, each failed cleanly naming the file, repeat ok\n", s->name,
            total, failed_cleanly);
    return tree_kb(p.out); /* the repeated run's complete output */
}

static int tmpfs_usable(void) { return system("unshare -rm true >/dev/null 2>&1") == 0; }

/* A tmpfs over OUT, in a private mount namespace, with room for the model the stage starts from
 * and half of what its finished output adds (`full_kb`: the output of a complete run): the stage
 * runs there, then this program checks the folder (--check OUT) before the namespace and its
 * tmpfs go away. */
static void with_tmpfs(const rb_stage *s, const rb_paths *in, long long full_kb)
{
    rb_paths p = *in;
    snprintf(p.out, sizeof p.out, "%s/../%s", in->cap, s->name);
    rb_sh("rm -rf '%s' && mkdir -p '%s'", p.out, p.out);
    long long start = s->mode == RB_MODEL_COPY ? tree_kb(p.model) : 0;
    long long adds = full_kb > start ? full_kb - start : 0;
    int kb = (int)(start + (adds / 2 > 4 ? adds / 2 : 4));
    char cmd[8192], *argv[128], line[4096], script[12000];
    rb_argv(s->args, &p, cmd, sizeof cmd, argv, 128);
    size_t n = 0;
    for (int i = 0; argv[i] && n < sizeof line; i++) n += (size_t)snprintf(line + n, sizeof line - n, "%s ", argv[i]);
    snprintf(script, sizeof script,
             "mount -t tmpfs -o size=%dk tmpfs \"$0\" || exit 90\n"
             "%s%s%s\n"
             "%s >\"$0.log\" 2>&1; rc=$?\n"
             "'%s' --check \"$0\" || exit 91\n"
             "exit $rc\n",
             kb, s->mode == RB_MODEL_COPY ? "cp -r '" : "", s->mode == RB_MODEL_COPY ? p.model : "",
             s->mode == RB_MODEL_COPY ? "/.' \"$0\" || exit 92" : "", line, self);
    char *sh[] = {"/usr/bin/unshare", "-rm", "/bin/sh", "-c", script, p.out, NULL};
    rb_result r;
    rb_run_argv(sh, NULL, 300, -1, &r);
    char *log = NULL, logp[1200];
    size_t ln;
    snprintf(logp, sizeof logp, "%s.log", p.out);
    sp_read_file(logp, &log, &ln, NULL);
    CHECK_MSG(r.status < 90, "%s on a %d KB tmpfs: setup or check failed (status %d): %s", s->name, kb, r.status, r.out);
    CHECK_MSG(r.status != 0 && r.signal == 0, "%s on a %d KB tmpfs: status %d signal %d", s->name, kb, r.status,
              r.signal);
    if (log && r.status != 0 && r.status < 90) check_message(s, p.out, log, "tmpfs");
    fprintf(stderr, "%-9s on a %d KB tmpfs: exit %d, files whole%s\n", s->name, kb, r.status,
            log && strstr(log, "No space left on device") ? ", the error names the file and ENOSPC" : "");
    free(log);
    rb_fresh_out(s, &p, p.out);
    repeat_ok(s, &p, "tmpfs");
}

int main(int argc, char **argv)
{
    snprintf(self, sizeof self, "%s", argv[0][0] == '/' ? argv[0] : "");
    if (!self[0]) {
        char cwd[800];
        snprintf(self, sizeof self, "%s/%s", getcwd(cwd, sizeof cwd) ? cwd : ".", argv[0]);
    }
    if (argc == 3 && !strcmp(argv[1], "--check")) { /* inside the tmpfs namespace */
        rb_tree t = rb_check_tree(argv[2]);
        if (t.bad) fprintf(stderr, "%d files are not whole, first: %s\n", t.bad, t.first_bad);
        return t.bad ? 1 : 0;
    }
    const char *base = test_tmpdir("robust_full_disk");
    rb_paths in;
    if (rb_inputs(base, &in)) return 1;
    long long full_kb[RB_N_STAGES];
    for (size_t i = 0; i < RB_N_STAGES; i++) full_kb[i] = with_shim(&rb_stages[i], &in);
    if (tmpfs_usable()) {
        for (size_t i = 0; i < RB_N_STAGES; i++) with_tmpfs(&rb_stages[i], &in, full_kb[i]);
    } else {
        fprintf(stderr, "tmpfs variant skipped: this machine does not let the test make a mount namespace "
                        "(unshare -rm); the LD_PRELOAD shim covered every stage\n");
    }
    return TEST_EXIT();
}
