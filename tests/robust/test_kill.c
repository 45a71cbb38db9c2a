/* Every long stage (robust.h's table) killed with SIGKILL at spread-out points of its run: after
 * each kill every file under a final name in the output folder opens whole with the library's
 * readers (temporary names are allowed and counted), and a second run (resumed where the stage
 * can resume: train --resume, demo --reuse; else repeated) succeeds and leaves only whole files.
 * Kill points: (k + 0.5 + jitter) / kills of the stage's uninterrupted time, jitter from a fixed
 * seed. The killed runs write through tests/robust/enospc_shim.c, unbuffered, every write slowed
 * by the stage's slow_write_us, so writing is much of a run and the kills land inside writes (the temporary files they
 * leave are counted: each is a file a kill cut short, never under its final name). */
#include "robust.h"

typedef struct {
    int runs, killed, temps, checked;
} kill_stats;

static void one_stage(const rb_stage *s, const rb_paths *in, test_rng *rng)
{
    rb_paths p = *in;
    snprintf(p.out, sizeof p.out, "%s/../%s", in->cap, s->name);
    char e_pre[1200], e_dir[1200];
    snprintf(e_pre, sizeof e_pre, "LD_PRELOAD=%s", SP_ENOSPC_SHIM);
    snprintf(e_dir, sizeof e_dir, "SP_ENOSPC_DIR=%s", p.out);
    char e_slow[64], e_asan[] = "ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0";
    snprintf(e_slow, sizeof e_slow, "SP_SLOW_WRITE_US=%d", s->slow_write_us);
    char *env[] = {e_pre, e_dir, e_slow, e_asan, NULL};
    rb_result r;
    rb_fresh_out(s, &p, p.out);
    rb_run(s->args, &p, env, 300, -1, &r);
    CHECK_MSG(r.status == 0, "%s: the uninterrupted run failed: %s", s->name, r.out);
    double full = r.seconds;
    kill_stats ks = {0};
    for (int k = 0; k < s->kills; k++) {
        double at = full * (k + 0.5 + test_range(rng, -0.3, 0.3)) / s->kills;
        rb_fresh_out(s, &p, p.out);
        rb_run(s->args, &p, env, 300, at, &r);
        ks.runs++;
        ks.killed += r.signal == SIGKILL;
        CHECK_MSG(r.signal == SIGKILL || r.status == 0, "%s killed at %.2f s: ended with status %d signal %d: %s",
                  s->name, at, r.status, r.signal, r.out);
        rb_tree t = rb_check_tree(p.out);
        CHECK_MSG(t.bad == 0, "%s killed at %.2f s: %d of %d files are not whole, first: %s", s->name, at, t.bad,
                  t.checked, t.first_bad);
        ks.temps += t.temps;
        char again[2048];
        rb_resume_args(s, p.out, again, sizeof again);
        rb_run(again, &p, NULL, 300, -1, &r);
        CHECK_MSG(r.status == 0, "%s: the run after a kill at %.2f s failed (%s): %s", s->name, at, again, r.out);
        t = rb_check_tree(p.out);
        CHECK_MSG(t.bad == 0, "%s: after the second run %d files are not whole, first: %s", s->name, t.bad,
                  t.first_bad);
        ks.checked += t.checked;
    }
    fprintf(stderr, "%-9s run %.2f s: %d kills (%d landed), %d files checked after reruns, %d temporary files left by kills\n",
            s->name, full, ks.runs, ks.killed, ks.checked, ks.temps);
}

int main(void)
{
    const char *base = test_tmpdir("robust_kill");
    rb_paths in;
    if (rb_inputs(base, &in)) return 1;
    test_rng rng = {0x5eed1234ULL};
    for (size_t i = 0; i < RB_N_STAGES; i++) one_stage(&rb_stages[i], &in, &rng);
    return TEST_EXIT();
}
