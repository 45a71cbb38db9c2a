/* The seed queries on the house through the lexical encoder and the query engine, each
 * within 0.5 m of the right object or region: through sp_lex_query on an engine made in memory,
 * and through the ENGINE'S PLAIN QUERY (sp_query_engine_query(e, text, NULL, ...)) on the model
 * folder, whose semantic.json makes lexical the default text encoder, as every caller (CLI query,
 * Python, eval, the agent) uses it. A LABEL-FEATURE scene: a small synth capture of the
 * house (120 views, 120x90, 60000 points), label features (each pixel's class -> sp_label_embedding, PCA 32),
 * Gaussians initialised on the capture's points3D (not trained: opacity raised to 0.9), and the
 * features lifted into them. It measures localization given a perfect 2D segmentation plus the
 * lexical encoder's matching of text to the scene's class names; it says nothing about visual
 * recognition. Distances are to the expected instance's ground-truth box (0 inside it). */
#include <cjson/cJSON.h>
#include <math.h>
#include <sys/wait.h>
#include <unistd.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "semsplat/synth.h"
#include "semsplat/train.h"
#include "test.h"

typedef struct {
    const char *text;
    const char *expect[4]; /* instance names ("bedroom_door") or classes; any one will do */
    int region;            /* measured against the union box of all expected objects */
} seed;

static const seed seeds[] = {
    {"refrigerator", {"refrigerator"}, 0},
    {"couch", {"couch"}, 0},
    {"dining table", {"dining table"}, 0},
    {"chair", {"dining chair", "armchair"}, 0},
    {"tv monitor", {"tv"}, 0},
    {"kitchen counter", {"kitchen counter"}, 0},
    {"the doorway to the bedroom", {"bedroom_door"}, 0},
    {"something to sit on", {"couch", "armchair", "dining chair"}, 0},
    {"area with appliances", {"refrigerator", "stove"}, 1},
    {"wooden bookshelf", {"bookshelf"}, 0},
    /* beyond the seeds: relations that pick one instance of several, and a named room */
    {"the chair near the window", {"dining_chair_3", "dining_chair_4"}, 0},
    {"the painting above the couch", {"painting_1"}, 0},
    {"the table between the couch and the tv stand", {"coffee_table"}, 0}, /* both anchor it */
    {"the kitchen", {"refrigerator", "kitchen counter", "sink", "stove"}, 1},
};
#define N_SEEDS 10

static float gap_to_box(const float *p, const float *lo, const float *hi)
{
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double g = fmax(0.0, fmax((double)lo[k] - p[k], (double)p[k] - hi[k]));
        d2 += g * g;
    }
    return (float)sqrt(d2);
}

static int box_of(const cJSON *o, float lo[3], float hi[3])
{
    const cJSON *a = cJSON_GetObjectItem(o, "aabb_min"), *b = cJSON_GetObjectItem(o, "aabb_max");
    if (cJSON_GetArraySize(a) != 3 || cJSON_GetArraySize(b) != 3) return -1;
    for (int k = 0; k < 3; k++)
        lo[k] = (float)cJSON_GetArrayItem(a, k)->valuedouble, hi[k] = (float)cJSON_GetArrayItem(b, k)->valuedouble;
    return 0;
}

static int expected(const cJSON *o, const seed *s)
{
    const char *name = cJSON_GetObjectItem(o, "name")->valuestring, *cls = cJSON_GetObjectItem(o, "class")->valuestring;
    for (int k = 0; k < 4 && s->expect[k]; k++)
        if (!strcmp(name, s->expect[k]) || !strcmp(cls, s->expect[k])) return 1;
    return 0;
}

/* Distance of p to the right object (nearest expected instance) or region (their union box);
 * *centre_m gets the distance to that box's centre. */
static float error_m(const cJSON *gt, const seed *s, const float *p, float *centre_m)
{
    float best = INFINITY, ulo[3] = {INFINITY, INFINITY, INFINITY}, uhi[3] = {-INFINITY, -INFINITY, -INFINITY};
    const cJSON *o;
    cJSON_ArrayForEach(o, cJSON_GetObjectItem(gt, "objects")) {
        float lo[3], hi[3];
        if (!expected(o, s) || box_of(o, lo, hi)) continue;
        float g = gap_to_box(p, lo, hi);
        if (g < best) {
            best = g;
            float c2 = 0;
            for (int k = 0; k < 3; k++) c2 += powf(p[k] - 0.5f * (lo[k] + hi[k]), 2.0f);
            *centre_m = sqrtf(c2);
        }
        for (int k = 0; k < 3; k++) ulo[k] = fminf(ulo[k], lo[k]), uhi[k] = fmaxf(uhi[k], hi[k]);
    }
    if (!s->region) return best;
    float c2 = 0;
    for (int k = 0; k < 3; k++) c2 += powf(p[k] - 0.5f * (ulo[k] + uhi[k]), 2.0f);
    *centre_m = sqrtf(c2);
    return gap_to_box(p, ulo, uhi);
}

/* Capture, label features, Gaussians on points3D, lift; writes the model folder dir/model (splat
 * with f_sem_*, semantic.json) for the CLI; returns an engine (NULL on failure). */
static sp_query_engine *build_scene(const char *dir, sp_device *dev, sp_error *err)
{
    char world[1024], cap[1200], feat[1200], sparse[1300];
    snprintf(world, sizeof world, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    snprintf(cap, sizeof cap, "%s/capture", dir);
    snprintf(feat, sizeof feat, "%s/features", dir);
    snprintf(sparse, sizeof sparse, "%s/sparse/0", cap);
    sp_world w;
    sp_synth_load_opts lo = {.no_env = 1};
    CHECK_OK(sp_synth_load_world(world, &lo, &w, err), err);
    if (err->code) return NULL;
    sp_synth_capture_opts co = {.n_views = 120, .width = 120, .height = 90, .fov_deg = 70, .n_points = 60000,
                                .seed = 7, .n_threads = 2};
    CHECK_OK(sp_synth_capture(&w, cap, &co, err), err);
    sp_world_free(&w);
    if (err->code) return NULL;
    sp_features_opts fo = sp_features_opts_default();
    fo.colmap_dir = cap, fo.out_dir = feat, fo.source = "labels", fo.dim = 32, fo.map_factor = 2;
    CHECK_OK(sp_features_extract(&fo, err), err);
    if (err->code) return NULL;
    sp_train_data d;
    sp_splat s;
    memset(&d, 0, sizeof d);
    memset(&s, 0, sizeof s);
    char images[1300];
    snprintf(images, sizeof images, "%s/images", cap);
    CHECK_OK(sp_train_data_load(&d, sparse, images, 1, 0, err), err);
    if (!err->code) CHECK_OK(sp_train_init_from_points(&s, &d, 0, 1, err), err);
    sp_train_data_free(&d);
    if (err->code) return NULL;
    for (size_t i = 0; i < s.n; i++) s.opacity_logits[i] = sp_logit(0.9f);
    CHECK_OK(sp_semantic_lift_features(&s, feat, sparse, dev, NULL, err), err);
    char model[1300], ply[1400];
    snprintf(model, sizeof model, "%s/model", dir);
    snprintf(ply, sizeof ply, "%s/splat.ply", model);
    if (!err->code) CHECK_OK(sp_mkdirs(model, err), err);
    if (!err->code) CHECK_OK(sp_ply_write_splat(ply, &s, err), err);
    if (!err->code) CHECK_OK(sp_semantic_write_sidecar(model, feat, sparse, "lift", err), err);
    sp_features f;
    memset(&f, 0, sizeof f);
    if (!err->code) CHECK_OK(sp_features_open(feat, &f, err), err);
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    if (!err->code) CHECK_OK(sp_colmap_read(sparse, &m, err), err);
    sp_camera *cams = calloc(m.n_images ? m.n_images : 1, sizeof *cams);
    for (size_t i = 0; i < m.n_images && !err->code; i++) CHECK_OK(sp_colmap_image_camera(&m, i, &cams[i], err), err);
    sp_query_engine *e = NULL;
    if (!err->code) {
        sp_sem_pca pca = {f.dim, f.full_dim, f.pca_mean, f.pca_basis};
        sp_query_opts qo = sp_query_opts_default();
        qo.heatmap = 0;
        sp_frame fr;
        sp_frame_init(&fr, "synth"); /* a synth capture: its poses are the world's */
        sp_query_model qm = {.splat = &s, .pca = &pca, .cams = cams, .n_cams = m.n_images, .frame = &fr};
        CHECK_OK(sp_query_engine_create(&e, &qm, &qo, dev, NULL, err), err);
    }
    free(cams);
    sp_colmap_free(&m);
    sp_features_free(&f);
    sp_splat_free(&s);
    return e;
}

/* The phrasing tables (tests/semantic/phrases_*.json) name each world's classes as synth makes
 * them: a change of class naming must show up here, not as silently stale tables. */
static void test_tables_match_worlds(void)
{
    const char *worlds[][3] = {{"house", "data/worlds/house.world", NULL},
                                {"bookstore", "data/worlds/bookstore/worlds/bookstore.world",
                                 "data/worlds/bookstore/models"},
                                {"office", "data/worlds/office.world", NULL},
                                {"ward", "data/worlds/ward.world", NULL},
                                {"garage", "data/worlds/garage.world", NULL},
                                {"cafe", "data/worlds/cafe.world", NULL},
                                {"basement", "data/worlds/basement.world", NULL},
                                {"classroom", "data/worlds/classroom.world", NULL},
                                {"hotel", "data/worlds/hotel.world", NULL},
                                {"grocery", "data/worlds/grocery.world", NULL},
                                {"chemlab", "data/worlds/chemlab.world", NULL},
                                {"pharmacy", "data/worlds/pharmacy.world", NULL},
                                {"salon", "data/worlds/salon.world", NULL}};
    for (int k = 0; k < (int)(sizeof worlds / sizeof worlds[0]); k++) {
        char world[1024], models[1024], table[1024];
        snprintf(world, sizeof world, "%s/%s", SP_SOURCE_DIR, worlds[k][1]);
        snprintf(models, sizeof models, "%s/%s", SP_SOURCE_DIR, worlds[k][2] ? worlds[k][2] : "");
        snprintf(table, sizeof table, "%s/tests/semantic/phrases_%s.json", SP_SOURCE_DIR, worlds[k][0]);
        sp_error err = {0};
        sp_world w;
        sp_synth_load_opts lo = {.model_path = worlds[k][2] ? models : NULL, .skip_missing = 1, .no_env = 1};
        cJSON *js = NULL;
        CHECK_OK(sp_json_read_file(table, &js, &err), &err);
        CHECK_OK(sp_synth_load_world(world, &lo, &w, &err), &err);
        if (err.code) {
            cJSON_Delete(js);
            continue;
        }
        const cJSON *classes = cJSON_GetObjectItem(js, "classes"), *c;
        for (size_t i = 0; i < w.n_objects; i++) {
            int listed = 0;
            cJSON_ArrayForEach(c, classes) listed |= !strcmp(c->valuestring, w.objects[i].class_name);
            CHECK_MSG(listed, "%s: class '%s' missing from %s", worlds[k][0], w.objects[i].class_name, table);
        }
        cJSON_ArrayForEach(c, classes) {
            int made = 0;
            for (size_t i = 0; i < w.n_objects; i++) made |= !strcmp(c->valuestring, w.objects[i].class_name);
            CHECK_MSG(made, "%s: table class '%s' is no class of the world", worlds[k][0], c->valuestring);
        }
        sp_world_free(&w);
        cJSON_Delete(js);
    }
}

/* Runs the CLI; its stdout (and stderr) in out, the exit status returned. */
static int cli(const char *args, char *out, size_t cap)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s/semsplat' %s 2>&1", SP_BUILD_DIR, args);
    FILE *p = popen(cmd, "r");
    size_t n = p ? fread(out, 1, cap - 1, p) : 0;
    out[n] = 0;
    int st = p ? pclose(p) : -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* semsplat query on the label-feature folder: the lexical encoder by default (JSON with matches,
 * regions, instance classes; --explain), exact on request, bad encoders refused. */
static void test_query_cli(const char *dir)
{
    static char out[1 << 20];
    char args[2048];
    snprintf(args, sizeof args, "query --model '%s/model' --device cpu --quiet --json \"the fridge\" \"the kitchen\" "
             "\"giraffe\"", dir);
    int st = cli(args, out, sizeof out);
    cJSON *js = cJSON_Parse(out);
    CHECK_MSG(st == 0 && cJSON_GetArraySize(js) == 3, "query exited %d: %.2000s", st, out);
    const cJSON *fridge = cJSON_GetArrayItem(js, 0), *kitchen = cJSON_GetArrayItem(js, 1), *giraffe = cJSON_GetArrayItem(js, 2);
    const cJSON *m0 = cJSON_GetArrayItem(cJSON_GetObjectItem(fridge, "matches"), 0);
    const cJSON *i0 = cJSON_GetArrayItem(cJSON_GetObjectItem(fridge, "instances"), 0);
    CHECK(cJSON_IsTrue(cJSON_GetObjectItem(fridge, "found")) &&
          !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(fridge, "encoder")), "lexical"));
    CHECK(m0 && !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(m0, "class")), "refrigerator"));
    CHECK(i0 && !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(i0, "class")), "refrigerator"));
    const cJSON *reg = cJSON_GetObjectItem(kitchen, "region");
    CHECK(cJSON_IsObject(reg) && !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(reg, "name")), "kitchen") &&
          cJSON_GetArraySize(cJSON_GetObjectItem(reg, "centre")) == 3);
    CHECK(cJSON_IsFalse(cJSON_GetObjectItem(giraffe, "found")) && cJSON_IsNull(cJSON_GetObjectItem(giraffe, "position")));
    cJSON_Delete(js);
    snprintf(args, sizeof args, "query --model '%s/model' --device cpu --quiet --explain \"something to sit on\"", dir);
    st = cli(args, out, sizeof out);
    CHECK_MSG(st == 0 && strstr(out, "text encoder lexical") && strstr(out, "gloss") && strstr(out, "sit") &&
              strstr(out, "not recognition"), "query --explain exited %d: %.3000s", st, out);
    snprintf(args, sizeof args, "query --model '%s/model' --device cpu --quiet --encoder exact --json fridge", dir);
    st = cli(args, out, sizeof out);
    js = cJSON_Parse(out);
    CHECK_MSG(st == 0 && cJSON_IsFalse(cJSON_GetObjectItem(js, "found")) &&
              !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(js, "encoder")), "exact"), "exact: %.2000s", out);
    cJSON_Delete(js);
    snprintf(args, sizeof args, "query --model '%s/model' --encoder clip fridge", dir);
    CHECK_MSG(cli(args, out, sizeof out) == 1 && strstr(out, "does not fit"), "clip on labels: %s", out);
    snprintf(args, sizeof args, "query --model '%s/model' --encoder bogus fridge", dir);
    CHECK_MSG(cli(args, out, sizeof out) == 2 && strstr(out, "bogus"), "bogus encoder: %s", out);
}

/* The CLI on the model folder: semsplat lexical --model DIR --json, read back as JSON. */
static void test_cli(const char *dir)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s/semsplat' lexical --model '%s/model' --device cpu --quiet --json "
             "\"the fridge\" \"the kitchen\" \"giraffe\" 2>&1", SP_BUILD_DIR, dir);
    FILE *p = popen(cmd, "r");
    static char out[1 << 20];
    size_t n = p ? fread(out, 1, sizeof out - 1, p) : 0;
    out[n] = 0;
    int st = p ? pclose(p) : -1;
    CHECK_MSG(st == 0, "semsplat lexical exited %d: %.2000s", st, out);
    cJSON *js = cJSON_Parse(out);
    CHECK_MSG(cJSON_IsArray(js) && cJSON_GetArraySize(js) == 3, "not 3 JSON answers: %.2000s", out);
    const cJSON *fridge = cJSON_GetArrayItem(js, 0), *kitchen = cJSON_GetArrayItem(js, 1), *giraffe = cJSON_GetArrayItem(js, 2);
    CHECK(cJSON_IsTrue(cJSON_GetObjectItem(fridge, "found")));
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(fridge, "encoder")), "lexical"));
    const cJSON *inst = cJSON_GetArrayItem(cJSON_GetObjectItem(fridge, "instances"), 0);
    CHECK(inst && !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(inst, "class")), "refrigerator"));
    CHECK(cJSON_IsObject(cJSON_GetObjectItem(kitchen, "region")));
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(cJSON_GetObjectItem(kitchen, "region"), "centre")) == 3);
    CHECK(cJSON_IsFalse(cJSON_GetObjectItem(giraffe, "found")) && cJSON_IsNull(cJSON_GetObjectItem(giraffe, "position")));
    cJSON_Delete(js);
    /* A CLIP model folder is refused with a reason, and bad flags are usage errors. */
    char clip_dir[1300], sj[1400];
    snprintf(clip_dir, sizeof clip_dir, "%s/clip_model", dir);
    snprintf(sj, sizeof sj, "%s/semantic.json", clip_dir);
    sp_error err = {0};
    const char *clip_json = "{\"source\": \"clip\", \"label_embedding\": \"clip\"}";
    CHECK_OK(sp_mkdirs(clip_dir, &err), &err);
    CHECK_OK(sp_write_file_atomic(sj, clip_json, strlen(clip_json), &err), &err);
    snprintf(cmd, sizeof cmd, "'%s/semsplat' lexical --model '%s' \"chair\" 2>&1", SP_BUILD_DIR, clip_dir);
    p = popen(cmd, "r");
    n = p ? fread(out, 1, sizeof out - 1, p) : 0;
    out[n] = 0;
    st = p ? pclose(p) : -1;
    CHECK_MSG(WEXITSTATUS(st) == 1 && strstr(out, "label-feature model"), "exit %d: %s", st, out);
    snprintf(cmd, sizeof cmd, "'%s/semsplat' lexical --classes chair --labels x \"chair\" > /dev/null 2>&1", SP_BUILD_DIR);
    CHECK(WEXITSTATUS(system(cmd)) == 2);
    snprintf(cmd, sizeof cmd, "'%s/semsplat' lexical --classes 'chair, sofa' --frobnicate \"x\" > /dev/null 2>&1", SP_BUILD_DIR);
    CHECK(WEXITSTATUS(system(cmd)) == 2);
}

/* Checks one answer against its seed; prints it. Returns 1 when right. */
static int check_seed(const char *path, const cJSON *gt, const seed *s, size_t i, const sp_query_result *r,
                      const char *relation, const float *relation_m)
{
    float c = INFINITY, d = r->valid ? error_m(gt, s, r->position, &c) : INFINITY;
    printf("%s %s%-30s %-6s confidence %.2f  (%.2f, %.2f, %.2f)  %.2f m from the %s's box, %.2f from its "
           "centre%s%s\n", path, i < N_SEEDS ? "seed " : "more ", s->text, r->valid ? "found" : "NOT",
           (double)r->confidence, (double)r->position[0], (double)r->position[1], (double)r->position[2],
           (double)d, s->region ? "region" : "object", (double)c, relation[0] ? ", relation " : "", relation);
    int ok = r->valid && d <= 0.5f;
    CHECK_MSG(ok, "%s '%s': %.2f m from the right %s", path, s->text, (double)d, s->region ? "region" : "object");
    for (int k = 0; !ok && k < r->n_instances; k++)
        printf("    instance %d %s (%.2f, %.2f, %.2f) confidence %.2f score %.3g%s%.2f\n", k, r->instances[k].label,
               (double)r->instances[k].position[0], (double)r->instances[k].position[1],
               (double)r->instances[k].position[2], (double)r->instances[k].confidence,
               (double)r->instances[k].score, relation_m ? "  relation cost " : "",
               relation_m ? (double)relation_m[k] : 0.0);
    return ok;
}

static const char *const absent[] = {"piano", "dishwasher", "giraffe"};

/* The engine's plain query on the model folder: the lexical encoder by default, every seed within
 * 0.5 m, the result naming its encoder and what it matched; absent things not found. */
static void engine_plain_query(const char *dir, const cJSON *gt, sp_device *dev)
{
    char model[1300];
    snprintf(model, sizeof model, "%s/model", dir);
    sp_error err = {0};
    sp_query_engine *e = NULL;
    CHECK_OK(sp_query_engine_open(&e, model, NULL, dev, NULL, &err), &err);
    if (!e) return;
    CHECK(!strcmp(sp_query_engine_source(e)->encoder, "lexical"));
    int right = 0;
    for (size_t i = 0; i < sizeof seeds / sizeof seeds[0]; i++) {
        sp_query_result r;
        int rc = sp_query_engine_query(e, seeds[i].text, NULL, &r, &err);
        CHECK_MSG(rc == 0, "'%s': %s", seeds[i].text, err.msg);
        if (rc) continue;
        right += check_seed("engine", gt, &seeds[i], i, &r, r.relation, NULL);
        CHECK_MSG(!strcmp(r.source.encoder, "lexical") && r.threshold == SP_LEX_THRESHOLD && r.n_matches > 0 &&
                  r.explanation && strstr(r.explanation, "lexical encoder"), "'%s': encoder %s, %d matches",
                  seeds[i].text, r.source.encoder, r.n_matches);
        CHECK_MSG(!seeds[i].region || r.region.valid, "'%s': no region", seeds[i].text);
        CHECK_MSG(r.n_instances > 0 && r.instances[0].label[0], "'%s': instances without their class", seeds[i].text);
        sp_query_result_free(&r);
    }
    printf("engine's plain query (lexical encoder, label features): %d/%zu right within 0.5 m\n", right,
           sizeof seeds / sizeof seeds[0]);
    for (int i = 0; i < 3; i++) {
        sp_query_result r;
        CHECK_OK(sp_query_engine_query(e, absent[i], NULL, &r, &err), &err);
        CHECK_MSG(!r.valid && isnan(r.position[0]) && r.confidence < SP_LEX_THRESHOLD, "engine: '%s' found", absent[i]);
        sp_query_result_free(&r);
    }
    sp_query_engine_free(e);
}

static void test_seed_queries(void)
{
    sp_error err = {0};
    const char *dir = test_tmpdir("lexical_seed");
    sp_device *dev = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    if (!dev) return;
    double t0 = sp_time_now();
    sp_query_engine *e = build_scene(dir, dev, &err);
    printf("label-feature house scene built in %.1f s\n", sp_time_now() - t0);
    sp_lexicon *lx = NULL;
    sp_lex_vocab *v = NULL;
    char labels[1300], gtp[1300];
    snprintf(labels, sizeof labels, "%s/capture/labels.json", dir);
    snprintf(gtp, sizeof gtp, "%s/capture/ground_truth.json", dir);
    cJSON *gt = NULL;
    if (e) CHECK_OK(sp_lexicon_open(&lx, NULL, &err), &err);
    if (lx) CHECK_OK(sp_lex_vocab_from_labels(&v, lx, labels, NULL, &err), &err);
    if (v) CHECK_OK(sp_json_read_file(gtp, &gt, &err), &err);
    sp_lex_answer *a = malloc(sizeof *a);
    for (size_t i = 0; gt && a && i < sizeof seeds / sizeof seeds[0]; i++) {
        int rc = sp_lex_query(e, v, seeds[i].text, a, &err);
        CHECK_MSG(rc == 0, "'%s': %s", seeds[i].text, err.msg);
        if (rc) continue;
        check_seed("lex   ", gt, &seeds[i], i, &a->result, a->lex.relation, a->relation_m);
        sp_lex_answer_free(a);
    }
    /* Absent things stay absent in the scene too, and say so without a position. */
    for (int i = 0; a && v && i < 3; i++) {
        CHECK_OK(sp_lex_query(e, v, absent[i], a, &err), &err);
        CHECK_MSG(!a->result.valid && isnan(a->result.position[0]), "'%s' found", absent[i]);
        sp_lex_answer_free(a);
    }
    free(a);
    sp_lex_vocab_free(v);
    sp_lexicon_free(lx);
    sp_query_engine_free(e);
    if (gt) engine_plain_query(dir, gt, dev);
    cJSON_Delete(gt);
    sp_device_free(dev);
    if (v) test_cli(dir);
    if (v) test_query_cli(dir);
}

int main(void)
{
    if (access(SP_LEX_DEFAULT_WORDNET "/index.noun", R_OK) != 0) {
        fprintf(stderr, "skipped: no WordNet at %s (Debian wordnet-base)\n", SP_LEX_DEFAULT_WORDNET);
        return 77;
    }
    RUN(test_tables_match_worlds);
    RUN(test_seed_queries);
    return TEST_EXIT();
}
