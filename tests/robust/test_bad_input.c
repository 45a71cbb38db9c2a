/* Every CLI command with bad arguments and files, from one table: each row is a command, a valid
 * invocation (checked to succeed first) and its flags with the kind of value each takes. From
 * the kind the test makes the bad cases (missing value, not a number, negative, zero, oversized,
 * a missing / empty / truncated / wrong-type / oversized file, a folder missing its contents, an
 * output under a regular file, ...) and runs each with a deadline. Every case must exit non-zero
 * without a signal within the deadline, and its message must name what is wrong (the flag, the
 * value, or the file / the file inside the folder). Plus, per command: no arguments, an unknown
 * flag, and each flag given without its value.
 *
 * To add a command: one row in `commands` (its valid invocation with {PLACEHOLDER}s from
 * `fixture_paths`, and its flags). To add a kind of value: one entry in `kinds`. New file types
 * (a costmap YAML, an LLM response) are a fixture and a kind. */
#include "robust.h"

typedef enum {
    K_COUNT,    /* a positive count with an upper bound: views, steps, points, dim (>= 1) */
    K_COUNT0,   /* the same where 0 means "auto" or "none": threads, SH degree */
    K_STEP,     /* a step index or interval where any non-negative int is meaningful (>= 0) */
    K_STEP1,    /* the same, >= 1 */
    K_INT,      /* any integer (a seed) */
    K_FLOAT,    /* a real number in some range */
    K_SIZE,     /* WxH */
    K_CHOICE,   /* one of a few words */
    K_LIST,     /* comma-separated numbers */
    K_COLMAP,   /* a capture root or COLMAP model folder (cameras only) */
    K_CAPTURE,  /* a capture whose images are read */
    K_MODEL,    /* a model folder with a semantic field (splat.ply, semantic.json, PCA) */
    K_MODEL_SPLAT, /* a model folder whose splat.ply is read (and rewritten) */
    K_FEATURES, /* a feature folder */
    K_PLY,      /* a splat .ply */
    K_WORLD,    /* an SDF world */
    K_ANYFILE,  /* a file `info` describes by its content */
    K_SAFETENSORS,
    K_CONFIG,   /* a CLIP config.json */
    K_TEXTFILE, /* align's matches / transform files */
    K_YAML,     /* a Nav2 map.yaml */
    K_DIR,      /* any input folder (a WordNet database) */
    K_OUTDIR,   /* an output folder */
    K_OUTFILE,  /* an output file */
    K_TEXT,     /* free text (a query) */
    K_NKINDS
} kind;

typedef struct {
    const char *flag; /* NULL: the positional argument at the end of `base` */
    kind k;
} cmd_flag;

typedef struct {
    const char *name;
    const char *base; /* a valid invocation; flags not in it are added with a bad value */
    cmd_flag flags[28];
} command;

/* Commands that run without arguments (demo: the bundled house), so that case is not bad input. */
static int runs_bare(const command *c) { return !strcmp(c->name, "demo"); }
/* Commands whose valid invocation cannot succeed on this machine (agent needs the nav module,
 * ros-goal a robot): their bad cases still must fail naming what is wrong. */
static int base_fails_here(const command *c)
{
    static const char *const names[] = {"agent", "ros-goal", "plan", "explore", "describe"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(c->name, names[i])) return 1;
    return 0;
}

/* Placeholders: {CAP} capture, {MODEL} model with a semantic field, {FEAT} features, {PLY} a splat,
 * {PNG} an image, {NPY}, {ST} a CLIP checkpoint (the tiny test fixture), {CFG} its config,
 * {WORLD}, {MATCHES}, {XFORM}, {OUT} a fresh output path per case. */
static const command commands[] = {
    {"info", "info {PLY}", {{NULL, K_ANYFILE}}},
    {"render", "render --splat {PLY} --colmap {CAP} --image 00000.png --out {OUT} --device cpu --threads 1 --quiet",
     {{"--splat", K_PLY}, {"--colmap", K_COLMAP}, {"--image", K_TEXT}, {"--out", K_OUTDIR},
      {"--channels", K_CHOICE}, {"--device", K_CHOICE}, {"--threads", K_COUNT0}, {"--background", K_LIST},
      {"--downscale", K_COUNT}}},
    {"synth", "synth --world {WORLD} --model-path {FIX}/models --out {OUT} --views 2 --size 16x12 --points 20 --threads 1 --quiet",
     {{"--world", K_WORLD}, {"--out", K_OUTDIR}, {"--views", K_COUNT}, {"--size", K_SIZE}, {"--fov-deg", K_FLOAT},
      {"--heights", K_LIST}, {"--supersample", K_COUNT}, {"--blur-px", K_FLOAT}, {"--points", K_COUNT},
      {"--seed", K_INT}, {"--threads", K_COUNT0}}},
    {"train", "train --colmap {CAP} --out {OUT} --steps 3 --init random --init-points 200 --device cpu --threads 1 --quiet",
     {{"--colmap", K_CAPTURE}, {"--out", K_OUTDIR}, {"--steps", K_COUNT}, {"--downscale", K_COUNT},
      {"--device", K_CHOICE}, {"--threads", K_COUNT0}, {"--init", K_CHOICE}, {"--init-points", K_COUNT},
      {"--init-ply", K_PLY}, {"--sh-degree", K_COUNT0}, {"--sh-interval", K_STEP1}, {"--max-gaussians", K_COUNT0},
      {"--refine-start", K_STEP}, {"--refine-stop", K_STEP}, {"--refine-every", K_STEP1},
      {"--reset-every", K_STEP1}, {"--grow-grad2d", K_FLOAT}, {"--test-every", K_STEP},
      {"--eval-every", K_STEP}, {"--checkpoint-every", K_STEP1}, {"--seed", K_INT}}},
    {"features", "features --colmap {CAP} --out {OUT} --source labels --dim 4 --threads 1 --quiet",
     {{"--colmap", K_COLMAP}, {"--out", K_OUTDIR}, {"--source", K_CHOICE}, {"--dim", K_COUNT},
      {"--factor", K_COUNT}, {"--samples", K_COUNT}, {"--device", K_CHOICE}, {"--threads", K_COUNT0},
      {"--clip", K_SAFETENSORS}}},
    {"embed-text", "embed-text --clip {ST} --device cpu chair", {{"--clip", K_SAFETENSORS}, {"--config", K_CONFIG},
                                                                  {"--device", K_CHOICE}, {NULL, K_TEXT}}},
    {"lift", "lift --model {OUT} --features {FEAT} --colmap {CAP} --device cpu --threads 1 --quiet",
     {{"--model", K_MODEL_SPLAT}, {"--features", K_FEATURES}, {"--colmap", K_COLMAP}, {"--device", K_CHOICE},
      {"--threads", K_COUNT0}}},
    {"distill", "distill --model {OUT} --features {FEAT} --colmap {CAP} --steps 3 --device cpu --threads 1 --quiet",
     {{"--model", K_MODEL_SPLAT}, {"--features", K_FEATURES}, {"--colmap", K_CAPTURE}, {"--steps", K_COUNT},
      {"--lambda", K_FLOAT}, {"--init", K_CHOICE}, {"--downscale", K_COUNT}, {"--device", K_CHOICE},
      {"--threads", K_COUNT0}}},
    {"query", "query --model {MODEL} --heatmap {OUT}.png --device cpu --threads 1 --quiet chair",
     {{"--model", K_MODEL}, {"--heatmap", K_OUTFILE}, {"--heatmap-dir", K_OUTDIR}, {"--method", K_CHOICE},
      {"--view", K_INT}, {"--views", K_COUNT}, {"--min-confidence", K_FLOAT}, {"--device", K_CHOICE},
      {"--threads", K_COUNT0}, {NULL, K_TEXT}}},
    {"align", "align --splat {PLY} --out {OUT}.ply --transform {XFORM}",
     {{"--splat", K_PLY}, {"--out", K_OUTFILE}, {"--transform", K_TEXTFILE}, {"--matches", K_TEXTFILE},
      {"--colmap", K_COLMAP}}},
    {"lexical", "lexical --classes chair,table,sofa --quiet chair",
     {{"--model", K_MODEL}, {"--labels", K_CONFIG}, {"--classes", K_TEXT}, {"--wordnet", K_DIR},
      {"--regions", K_CONFIG}, {NULL, K_TEXT}}},
    {"agent", "agent --model {MODEL} --out {OUT} --quiet where_is_the_table",
     {{"--model", K_MODEL}, {"--out", K_OUTDIR}, {"--llm", K_CHOICE}, {"--llm-preset", K_CHOICE},
      {"--llm-timeout", K_FLOAT}, {"--llm-retries", K_COUNT0}, {"--max-steps", K_COUNT}, {"--max-speed", K_FLOAT},
      {"--start", K_LIST}}},
    {"sim-robot", "sim-robot --map {YAML} --start 0,-1,0 --duration 0.2 --loopback --domain 91 --quiet",
     {{"--map", K_YAML}, {"--model", K_MODEL}, {"--start", K_LIST}, {"--radius", K_FLOAT}, {"--max-speed", K_FLOAT},
      {"--max-accel", K_FLOAT}, {"--max-yaw-rate", K_FLOAT}, {"--rate", K_FLOAT}, {"--time-scale", K_FLOAT},
      {"--duration", K_FLOAT}, {"--ready-file", K_OUTFILE}, {"--domain", K_COUNT0}, {"--ros-distro", K_CHOICE}}},
    {"ros-goal", "ros-goal --pose --timeout 0.3 --loopback --domain 92",
     {{"--to", K_LIST}, {"--plan", K_LIST}, {"--timeout", K_FLOAT}, {"--cancel-after", K_FLOAT},
      {"--domain", K_COUNT0}, {"--ros-distro", K_CHOICE}}},
    /* nav: the tiny fixture's 3-step model has no free floor to plan on, so the valid invocations
     * fail here (base_fails_here); options and input files are checked before the map is built.
     * Their --out is not in the table: nothing is written before the failure (a nav fixture
     * with free floor would cover it) */
    {"plan", "plan --model {MODEL} --goal 0,0 --out {OUT} --no-previews --device cpu --threads 1 --quiet",
     {{"--model", K_MODEL}, {"--to", K_TEXT}, {"--goal", K_LIST}, {"--from", K_LIST}, {"--k", K_COUNT},
      {"--instance", K_INT}, {"--radius", K_FLOAT}, {"--band", K_LIST}, {"--approach", K_FLOAT},
      {"--device", K_CHOICE}, {"--threads", K_COUNT0}}},
    {"explore", "explore --model {MODEL} --region kitchen --out {OUT} --device cpu --threads 1 --quiet",
     {{"--model", K_MODEL}, {"--region", K_TEXT}, {"--from", K_LIST}, {"--views", K_COUNT},
      {"--device", K_CHOICE}, {"--threads", K_COUNT0}}},
    {"describe", "describe --model {MODEL} --near chair --device cpu --threads 1 --quiet",
     {{"--model", K_MODEL}, {"--near", K_TEXT}, {"--radius", K_FLOAT}, {"--from", K_LIST}, {"--vocabulary", K_TEXT},
      {"--device", K_CHOICE}, {"--threads", K_COUNT0}}},
    /* --world and --views/--size only matter without --capture (synth's row covers them) */
    {"demo", "demo --capture {CAP} --out {OUT} --reuse --steps 3 --dim 4 --device cpu --quiet",
     {{"--capture", K_CAPTURE}, {"--out", K_OUTDIR}, {"--steps", K_COUNT}, {"--dim", K_COUNT},
      {"--device", K_CHOICE}, {"--clip", K_SAFETENSORS}}},
};
#define N_COMMANDS (sizeof commands / sizeof commands[0])

/* ---- fixtures ---------------------------------------------------------------------------------- */

static char base_dir[1024];
static int part_k, part_n = 1; /* SP_BAD_INPUT_PART (main) */
static rb_paths in;
static char f_ply[1200], f_png[1200], f_npy[1200], f_st[1200], f_cfg[1200], f_world[1200], f_matches[1200],
    f_xform[1200], f_text[1200], f_empty[1200], f_zeros[1200], f_regular[1200], f_emptydir[1200], f_yaml[1200],
    f_pgm[1200];

static void write_text(const char *path, const char *text)
{
    sp_error err = {0};
    CHECK_OK(sp_write_file_atomic(path, text, strlen(text), &err), &err);
}

/* A copy of src cut to half its size, at dst. */
static void truncated_copy(const char *src, const char *dst)
{
    char *d = NULL;
    size_t n = 0;
    sp_error err = {0};
    CHECK_OK(sp_read_file(src, &d, &n, &err), &err);
    CHECK_OK(sp_write_file_atomic(dst, d, n / 2, &err), &err);
    free(d);
}

static int make_fixtures(void)
{
    char tag[64]; /* one folder per share: the shares run at once */
    snprintf(tag, sizeof tag, "robust_bad_input_%d", part_k);
    snprintf(base_dir, sizeof base_dir, "%s", test_tmpdir(tag));
    if (rb_inputs(base_dir, &in)) return -1;
    rb_result r;
    rb_paths p = in;
    snprintf(p.out, sizeof p.out, "%s", in.model);
    rb_run("lift --model {OUT} --features {FEAT} --colmap {CAP} --device cpu --quiet", &p, NULL, 120, -1, &r);
    if (r.status) fprintf(stderr, "cannot lift the fixture model: %s\n", r.out);
#define F(var, name) snprintf(var, sizeof var, "%s/%s", base_dir, name)
    F(f_ply, "in/model/splat.ply");
    F(f_png, "in/cap/images/00000.png");
    F(f_npy, "in/cap/depth/00000.npy");
    F(f_text, "plain.txt");
    F(f_empty, "empty.bin");
    F(f_zeros, "zeros.bin");
    F(f_regular, "regular-file");
    F(f_emptydir, "emptydir");
    F(f_matches, "matches.txt");
    F(f_xform, "transform.txt");
    F(f_yaml, "map.yaml");
    F(f_pgm, "map.pgm");
    snprintf(f_st, sizeof f_st, "%s/tests/fixtures/clip/tiny/model.safetensors", SP_SOURCE_DIR);
    snprintf(f_cfg, sizeof f_cfg, "%s/tests/fixtures/clip/tiny/config.json", SP_SOURCE_DIR);
    snprintf(f_world, sizeof f_world, "%s/tiny.world", in.fix);
    write_text(f_text, "hello, this is not the file you want\n");
    write_text(f_empty, "");
    write_text(f_regular, "a regular file where a folder should be\n");
    write_text(f_matches, "0 0 0 1 1 1\n1 0 0 2 1 1\n0 1 0 1 2 1\n0 0 1 1 1 2\n");
    write_text(f_xform, "1 0 0 0\n0 1 0 0\n0 0 1 0\n");
    write_text(f_yaml, "image: map.pgm\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\n"
                       "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n");
    {   /* a free 40 x 40 map (2 x 2 m) */
        char pgm[2000];
        int h = snprintf(pgm, sizeof pgm, "P5\n40 40\n255\n");
        memset(pgm + h, 254, 1600);
        sp_error err = {0};
        CHECK_OK(sp_write_file_atomic(f_pgm, pgm, (size_t)h + 1600, &err), &err);
    }
    rb_sh("mkdir -p '%s'%s", f_emptydir, "");
    /* 64 MB of zeros that takes no disk (a file far larger than its format implies) */
    return rb_sh("truncate -s 64M '%s'%s", f_zeros, "");
}

/* A folder fixture with one of its files broken: a copy of src with `file` cut to half (or
 * removed when cut == 0). Returns the copy's path in out. */
static const char *broken_dir(const char *src, const char *file, int cut, const char *tag, char *out)
{
    static int seq;
    snprintf(out, 1200, "%s/broken-%s-%d", base_dir, tag, seq++);
    char cmd[4000];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && cp -r '%s' '%s'", out, src, out);
    if (system(cmd) != 0) fprintf(stderr, "cannot copy %s\n", src);
    char f[2500];
    snprintf(f, sizeof f, "%s/%s", out, file);
    if (cut) {
        char tmp[2600];
        snprintf(tmp, sizeof tmp, "%s.orig", f);
        rename(f, tmp);
        truncated_copy(tmp, f);
        unlink(tmp);
    } else {
        unlink(f);
    }
    return out;
}

/* ---- cases --------------------------------------------------------------------------------------- */

typedef struct {
    char value[1300];  /* the bad value ("" allowed) */
    char needle[1300]; /* what the message must mention besides the flag ("" = the flag or value) */
    const char *what;
    int may_succeed;   /* free text: any answer is fine, as long as it is not a crash or a hang */
} bad_value;

/* The bad values of a kind (up to 16). */
static int bad_values(kind k, bad_value *v)
{
    int n = 0;
#define V(val, ndl, w) (snprintf(v[n].value, sizeof v[n].value, "%s", val), \
                        snprintf(v[n].needle, sizeof v[n].needle, "%s", ndl), v[n].what = w, v[n].may_succeed = 0, n++)
    char b[1200];
    switch (k) {
    case K_COUNT:
    case K_STEP1:
        V("0", "", "zero");
        /* fallthrough */
    case K_COUNT0:
    case K_STEP:
        V("-1", "", "negative");
        V("2.5", "", "not an integer");
        V("", "", "empty");
        V("99999999999999999999", "", "beyond long");
        V("1000000000000", "", "beyond int");
        if (k == K_COUNT || k == K_COUNT0) V("2147483647", "", "oversized (the largest int)");
        break;
    case K_INT:
        V("abc", "", "not a number");
        V("99999999999999999999", "", "beyond long");
        break;
    case K_FLOAT:
        V("abc", "", "not a number");
        V("nan", "", "NaN");
        V("inf", "", "infinite");
        V("1e999", "", "overflow");
        V("-1e30", "", "huge negative");
        V("1e30", "", "huge");
        break;
    case K_SIZE:
        V("abc", "", "not a size");
        V("0x0", "", "zero size");
        V("-5x5", "", "negative size");
        V("64", "", "one number");
        V("100000x100000", "", "oversized");
        break;
    case K_CHOICE:
        V("bogus", "", "unknown word");
        V("", "", "empty");
        break;
    case K_LIST:
        V("abc", "", "not numbers");
        V("1,2,nan", "", "NaN");
        V("1e999,1e999,1e999", "", "overflow");
        break;
    case K_TEXT:
        V("", "text", "empty text");
        v[n - 1].may_succeed = 1;
        memset(b, 'x', 1100);
        b[1100] = 0;
        V(b, "", "1100 characters");
        v[n - 1].may_succeed = 1;
        V("\xff\xfe not UTF-8 \xc3", "", "invalid UTF-8");
        v[n - 1].may_succeed = 1;
        break;
    case K_OUTDIR:
    case K_OUTFILE:
        snprintf(b, sizeof b, "%s/sub", f_regular);
        V(b, f_regular, "under a regular file");
        if (k == K_OUTFILE) V(f_emptydir, f_emptydir, "a folder");
        else V(f_regular, f_regular, "a regular file");
        break;
    default: { /* input files and folders */
        snprintf(b, sizeof b, "%s/does-not-exist", base_dir);
        V(b, b, "missing");
        V(f_empty, f_empty, "empty file");
        V(f_text, f_text, "wrong type (text)");
        V(f_zeros, f_zeros, "oversized (64 MB of zeros)");
        char d[1200];
        if (k == K_COLMAP || k == K_CAPTURE) {
            V(f_emptydir, f_emptydir, "empty folder");
            V(broken_dir(in.cap, "sparse/0/images.bin", 1, "cap", d), "images.bin", "truncated images.bin");
            V(broken_dir(in.cap, "sparse/0/cameras.bin", 0, "cap", d), "cameras", "no cameras.bin");
            if (k == K_CAPTURE) V(broken_dir(in.cap, "images/00000.png", 1, "cap", d), "00000.png", "truncated image");
        } else if (k == K_MODEL || k == K_MODEL_SPLAT) {
            V(f_emptydir, f_emptydir, "empty folder");
            V(broken_dir(in.model, "splat.ply", 1, "model", d), "splat.ply", "truncated splat.ply");
            if (k == K_MODEL) {
                V(broken_dir(in.model, "semantic.json", 1, "model", d), "semantic.json", "truncated semantic.json");
                V(broken_dir(in.model, "semantic_pca_basis.npy", 1, "model", d), "semantic_pca_basis.npy", "truncated PCA");
            }
        } else if (k == K_FEATURES) {
            V(f_emptydir, f_emptydir, "empty folder");
            V(broken_dir(in.feat, "features.json", 1, "feat", d), "features.json", "truncated features.json");
            V(broken_dir(in.feat, "maps/00000.npy", 1, "feat", d), "00000.npy", "truncated map");
            V(broken_dir(in.feat, "pca_basis.npy", 0, "feat", d), "pca_basis.npy", "no PCA basis");
        } else if (k == K_DIR) {
            V(f_emptydir, f_emptydir, "empty folder");
        } else {
            V(f_emptydir, f_emptydir, "a folder");
            const char *src = k == K_PLY ? f_ply : k == K_WORLD ? f_world : k == K_SAFETENSORS ? f_st
                            : k == K_CONFIG ? f_cfg : k == K_TEXTFILE ? f_xform : k == K_YAML ? f_yaml : f_npy;
            snprintf(d, sizeof d, "%s/truncated-%d", base_dir, (int)k);
            truncated_copy(src, d);
            V(d, d, "truncated");
            if (k != K_ANYFILE) V(f_png, f_png, "wrong type (an image)");
        }
    }
    }
    return n;
#undef V
}

/* ---- running a case ------------------------------------------------------------------------------ */

static int n_cases, n_failed;
static double case_seconds;

/* argv of the command's valid invocation, file placeholders expanded, OUT = out. */
static int base_argv(const command *c, const char *out, char *buf, size_t cap, char **argv)
{
    rb_paths p = in;
    snprintf(p.out, sizeof p.out, "%s", out);
    static const char *keys[] = {"{PLY}", "{PNG}", "{NPY}", "{ST}", "{CFG}", "{WORLD}", "{MATCHES}", "{XFORM}", "{YAML}"};
    const char *vals[] = {f_ply, f_png, f_npy, f_st, f_cfg, f_world, f_matches, f_xform, f_yaml};
    char exp[8192] = "";
    size_t L = 0;
    for (const char *s = c->base; *s && L + 1 < sizeof exp;) {
        int k = -1;
        for (int j = 0; j < 9 && k < 0; j++)
            if (!strncmp(s, keys[j], strlen(keys[j]))) k = j;
        if (k >= 0) {
            L += (size_t)snprintf(exp + L, sizeof exp - L, "%s", vals[k]);
            s += strlen(keys[k]);
        } else {
            exp[L++] = *s++;
            exp[L] = 0;
        }
    }
    return rb_argv(exp, &p, buf, cap, argv, 120);
}

/* The valid invocation with flag's value replaced by value (the flag added when the invocation
 * lacks it; flag NULL: the last, positional argument), or with drop_value: the flag last and no
 * value after it. */
static void case_argv(const command *c, const char *flag, const char *value, int drop_value, char *buf, size_t cap,
                      char **argv, const char *out)
{
    static char vcopy[1300];
    snprintf(vcopy, sizeof vcopy, "%s", value);
    int argc = base_argv(c, out, buf, cap, argv);
    if (!flag) {
        argv[argc - 1] = vcopy;
        return;
    }
    int at = -1;
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], flag)) at = i;
    int has_value = at >= 0 && at + 1 < argc && argv[at + 1][0] != '-';
    if (drop_value) {
        if (at >= 0) {
            int skip = has_value ? 2 : 1;
            for (int i = at; i + skip <= argc; i++) argv[i] = argv[i + skip];
            argc -= skip;
        }
        argv[argc++] = (char *)flag;
        argv[argc] = NULL;
    } else if (has_value) {
        argv[at + 1] = vcopy;
    } else { /* added right after the command name, before any positional text */
        for (int i = argc; i >= 2; i--) argv[i + 2] = argv[i];
        argv[2] = (char *)flag;
        argv[3] = vcopy;
    }
}

/* OUT fresh for a case: removed, or a copy of the model for commands that write into it. */
static void fresh_out(const command *c, const char *out, int bad_model)
{
    rb_rm_rf(out);
    if (strstr(c->base, "--model {OUT}") && !bad_model) rb_cp_r(in.model, out);
}

/* The message names the flag: "--sh-interval", or its words as the library spells options
 * ("sh_interval", "sh-interval"), or the flag's last word ("interval"). */
static int names_flag(const char *out, const char *flag)
{
    if (!flag) return 0;
    if (strstr(out, flag)) return 1;
    char w[128];
    snprintf(w, sizeof w, "%s", flag + (flag[0] == '-' && flag[1] == '-' ? 2 : 0));
    if (strlen(w) >= 3 && strstr(out, w)) return 1;
    for (char *p = w; *p; p++)
        if (*p == '-') *p = '_';
    if (strstr(out, w)) return 1;
    const char *last = strrchr(flag, '-');
    return last && strlen(last + 1) >= 4 && strstr(out, last + 1);
}

static void expect_failure(const command *c, char **argv, const char *flag, const char *needle, const char *what,
                           const char *value, int may_succeed)
{
    rb_result r;
    rb_run_argv(argv, NULL, 60, -1, &r);
    n_cases++;
    case_seconds += r.seconds;
    if (r.seconds > 2) { /* what makes the table slow (CI time) */
        fprintf(stderr, "slow case %.1f s: %s %s (%s)\n", r.seconds, c->name, flag ? flag : "(argument)", what);
    }
    int named = names_flag(r.out, flag) || (needle[0] && strstr(r.out, needle)) ||
                (value && value[0] && strlen(value) < 200 && strstr(r.out, value)) ||
                (value && !value[0] && strstr(r.out, "''"));
    /* a value that may succeed may also fail for the reason the valid invocation fails here */
    int ok = !r.signal && !r.timed_out &&
             ((r.status > 0 && named) || (may_succeed && (r.status == 0 || (r.status > 0 && base_fails_here(c)))));
    if (!ok) {
        n_failed++;
        char line[600] = "";
        size_t n = 0;
        for (int i = 1; argv[i] && n < sizeof line - 1; i++)
            n += (size_t)snprintf(line + n, sizeof line - n, "%.60s ", argv[i]);
        CHECK_MSG(ok, "%s %s (%s): %s%s%s; output: %.600s\n    command: %s", c->name, flag ? flag : "(argument)", what,
                  r.timed_out ? "hung (killed after 60 s)" : r.signal ? "killed by a signal" : r.status == 0 ? "succeeded"
                                                                                                  : "",
                  !r.timed_out && !r.signal && r.status != 0 && !named ? "the message does not name " : "",
                  !r.timed_out && !r.signal && r.status != 0 && !named ? (needle[0] ? needle : flag ? flag : "it") : "",
                  r.out, line);
    }
}

static void one_command(const command *c)
{
    char buf[8192], *argv[128], out[1200];
    int before = n_failed, cases = n_cases;
    double t0 = sp_time_now();
    snprintf(out, sizeof out, "%s/out-%s", base_dir, c->name);
    /* the valid invocation works, or its bad cases prove nothing */
    fresh_out(c, out, 0);
    base_argv(c, out, buf, sizeof buf, argv);
    rb_result r;
    rb_run_argv(argv, NULL, 120, -1, &r);
    if (!base_fails_here(c)) CHECK_MSG(r.status == 0, "%s: the valid invocation failed: %s", c->name, r.out);
    /* no arguments, an unknown flag */
    char *none[] = {argv[0], (char *)c->name, NULL};
    if (!runs_bare(c)) expect_failure(c, none, NULL, c->name, "no arguments", NULL, 0);
    fresh_out(c, out, 0);
    case_argv(c, "--no-such-flag-here", "x", 0, buf, sizeof buf, argv, out);
    expect_failure(c, argv, "--no-such-flag-here", "", "unknown flag", NULL, 0);
    for (int f = 0; f < 28 && (c->flags[f].flag || c->flags[f].k); f++) {
        const cmd_flag *fl = &c->flags[f];
        if (fl->flag) {
            fresh_out(c, out, 0);
            case_argv(c, fl->flag, "", 1, buf, sizeof buf, argv, out);
            expect_failure(c, argv, fl->flag, "", "flag without a value", NULL, 0);
        }
        bad_value v[16];
        int nv = bad_values(fl->k, v);
        for (int i = 0; i < nv; i++) {
            int model_is_value = (fl->k == K_MODEL || fl->k == K_MODEL_SPLAT) && strstr(c->base, "--model {OUT}");
            fresh_out(c, out, model_is_value);
            case_argv(c, fl->flag, v[i].value, 0, buf, sizeof buf, argv, out);
            expect_failure(c, argv, fl->flag, v[i].needle, v[i].what, v[i].value, v[i].may_succeed);
        }
    }
    fprintf(stderr, "%-11s %3d cases, %d not handled, %.1f s\n", c->name, n_cases - cases, n_failed - before,
            sp_time_now() - t0);
}

/* Arguments: only these commands (while working on one); none: all of them, or with
 * SP_BAD_INPUT_PART=k/n the k-th of n interleaved shares (CTest runs the table as two tests side
 * by side: it is the suite's longest). */
static int wanted(size_t i, int argc, char **argv)
{
    for (int a = 1; a < argc; a++)
        if (!strcmp(argv[a], commands[i].name)) return 1;
    return argc < 2 && (int)(i % (size_t)part_n) == part_k;
}

int main(int argc, char **argv)
{
    const char *part = getenv("SP_BAD_INPUT_PART");
    if (part && (sscanf(part, "%d/%d", &part_k, &part_n) != 2 || part_n < 1 || part_k < 0 || part_k >= part_n)) {
        fprintf(stderr, "SP_BAD_INPUT_PART '%s': expected k/n with 0 <= k < n\n", part);
        return 2;
    }
    if (make_fixtures()) return 1;
    for (size_t i = 0; i < N_COMMANDS; i++)
        if (wanted(i, argc, argv)) one_command(&commands[i]);
    fprintf(stderr, "%d bad-input cases, %d not handled, %.0f s in the cases\n", n_cases, n_failed, case_seconds);
    return TEST_EXIT();
}
