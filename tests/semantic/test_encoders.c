/* The query engine's text encoders on the tiny labelled scene (floor, two chairs, a table, a
 * lamp): the plain query answers through the lexical encoder (synonyms, hypernyms, attributes
 * reported as ignored, relations, absent things with a faded heatmap), names its encoder and
 * explains itself; exact stays reachable and matches only exact names; relevancy and heatmaps
 * score the encoder's embedding; the encoder is chosen per model folder (semantic.json, with the
 * fall-backs and refusals semantic.h documents) and overridden at open. Label features: this
 * tests the plumbing and the matching of text to class names, not recognition. */
#include <math.h>
#include <unistd.h>

#include "scene.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "test.h"

enum { NCAM = 12, CW = 160, CH = 120 };

static sp_device *g_dev;
static sp_splat g_splat;
static sp_sem_pca g_pca;
static sp_camera g_cams[NCAM];

static sp_query_engine *engine(const char *encoder, int with_classes, sp_error *err)
{
    sp_query_source src;
    memset(&src, 0, sizeof src);
    snprintf(src.encoder, sizeof src.encoder, "%s", encoder);
    snprintf(src.features, sizeof src.features, "labels");
    src.ground_truth = 1;
    sp_query_model m = {.splat = &g_splat, .pca = &g_pca, .cams = g_cams, .n_cams = NCAM, .source = &src,
                        .classes = with_classes ? sc_class_names : NULL, .n_classes = with_classes ? SC_CLASSES : 0};
    sp_query_engine *e = NULL;
    sp_query_opts o = sp_query_opts_default();
    o.heatmap = 0;
    sp_query_engine_create(&e, &m, &o, g_dev, NULL, err);
    return e;
}

static int near(const float *p, int object, float tol)
{
    float c[3];
    sc_center(object, c);
    return sqrtf((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2])) < tol;
}

static void test_lexical_plain_query(void)
{
    sp_error err = {0};
    sp_query_engine *e = engine("lexical", 1, &err);
    CHECK_MSG(e != NULL, "lexical engine: %s", err.msg);
    if (!e) return;
    CHECK(!strcmp(sp_query_engine_source(e)->encoder, "lexical"));
    sp_query_result r;
    /* a synonym of a class name: the table, with the lexical score as the confidence */
    CHECK_OK(sp_query_engine_query(e, "desk", NULL, &r, &err), &err);
    CHECK_MSG(r.valid && near(r.position, 2, 0.1f), "desk -> the table");
    CHECK(!strcmp(r.source.encoder, "lexical") && r.threshold == SP_LEX_THRESHOLD);
    CHECK(r.confidence >= SP_LEX_THRESHOLD && r.confidence <= 1.0f);
    CHECK(r.n_matches >= 1 && !strcmp(r.matches[0].label, "table") && !strcmp(r.matches[0].role, "target"));
    CHECK(r.n_instances == 1 && !strcmp(r.instances[0].label, "table") && isnan(r.instances[0].relation_m));
    CHECK(r.explanation && strstr(r.explanation, "table") && strstr(r.explanation, "not recognition"));
    char *js = sp_query_result_json(&r, NULL);
    CHECK_MSG(js && strstr(js, "\"encoder\":\t\"lexical\"") && strstr(js, "\"matches\"") && strstr(js, "\"class\":\t\"table\""),
              "json: %.1500s", js ? js : "(null)");
    free(js);
    sp_query_result_free(&r);
    /* a hypernym covers every class it fits; an attribute it cannot see is reported */
    CHECK_OK(sp_query_engine_query(e, "a red seat", NULL, &r, &err), &err);
    CHECK(r.valid && r.n_instances == 2 && !strcmp(r.instances[0].label, "chair") && !strcmp(r.instances[1].label, "chair"));
    CHECK(r.n_ignored == 1 && !strcmp(r.ignored[0], "red"));
    sp_query_result_free(&r);
    /* a relation: the chair nearer the lamp first, with its cost and the anchor's extent */
    CHECK_OK(sp_query_engine_query(e, "the chair near the lamp", NULL, &r, &err), &err);
    CHECK_MSG(r.valid && !strcmp(r.relation, "near") && near(r.position, 1, 0.15f), "chair near the lamp");
    CHECK(r.anchor.valid && r.anchor.n_instances == 1 && r.n_instances == 2);
    CHECK(r.n_instances == 2 && r.instances[0].relation_m < r.instances[1].relation_m);
    int roles = 0;
    for (int i = 0; i < r.n_matches; i++) roles |= !strcmp(r.matches[i].role, "anchor") && !strcmp(r.matches[i].label, "lamp");
    CHECK_MSG(roles, "the anchor's match is listed");
    sp_query_result_free(&r);
    /* absent: not found, below the threshold, no position, the nearest class explained, and a
     * faded heatmap like the other encoders' when one is asked for */
    sp_query_opts o = *sp_query_engine_defaults(e);
    o.heatmap = 1;
    CHECK_OK(sp_query_engine_query(e, "piano", &o, &r, &err), &err);
    CHECK(!r.valid && isnan(r.position[0]) && r.confidence < SP_LEX_THRESHOLD && r.n_instances == 0);
    CHECK(r.relevancy_image && r.width == CW && r.height == CH && r.explanation);
    sp_query_result_free(&r);
    /* per-call options reach every localization inside a lexical query */
    o.method = SP_QUERY_MULTIVIEW;
    o.heatmap = 0;
    CHECK_OK(sp_query_engine_query(e, "seat", &o, &r, &err), &err);
    CHECK(r.valid && r.method == SP_QUERY_MULTIVIEW && !strcmp(r.instances[0].label, "chair"));
    sp_query_result_free(&r);
    CHECK_FAILS(sp_query_engine_query(e, "", NULL, &r, &err), SP_E_ARG, &err, "empty");
    sp_query_engine_free(e);
}

/* The engine's embedding is the lexical one: relevancy of "desk" under lexical equals relevancy of
 * "table" under exact (one class matched: its own label embedding). */
static void test_lexical_embedding(void)
{
    sp_error err = {0};
    sp_query_engine *lx = engine("lexical", 1, &err), *ex = engine("exact", 1, &err);
    CHECK_MSG(lx && ex, "engines: %s", err.msg);
    if (!lx || !ex) goto done;
    size_t n = sp_query_engine_splat(lx)->n;
    float *a = malloc(sizeof(float) * n), *b = malloc(sizeof(float) * n);
    CHECK_OK(sp_query_engine_relevancy(lx, "desk", a, NULL, &err), &err);
    CHECK_OK(sp_query_engine_relevancy(ex, "table", b, NULL, &err), &err);
    double d = 0;
    for (size_t i = 0; i < n; i++) d = fmax(d, fabs((double)a[i] - b[i]));
    CHECK_MSG(d < 1e-5, "relevancy differs by %g", d);
    /* a text matching nothing embeds as its own hash: relevancy stays near 0.5 */
    CHECK_OK(sp_query_engine_relevancy(lx, "giraffe", a, NULL, &err), &err);
    float mx = 0;
    for (size_t i = 0; i < n; i++) mx = fmaxf(mx, a[i]);
    CHECK_MSG(mx < 0.7f, "giraffe relevancy up to %.3f", (double)mx);
    free(a), free(b);
    /* exact: only exact names; it names the class it matched */
    sp_query_result r;
    CHECK_OK(sp_query_engine_query(ex, "desk", NULL, &r, &err), &err);
    CHECK(!r.valid && !strcmp(r.source.encoder, "exact") && r.n_matches == 0 && r.explanation);
    sp_query_result_free(&r);
    CHECK_OK(sp_query_engine_query(ex, " Table ", NULL, &r, &err), &err);
    CHECK(r.valid && r.n_matches == 1 && !strcmp(r.matches[0].label, "table") && !strcmp(r.matches[0].kind, "exact"));
    CHECK(r.threshold == sp_query_opts_default().min_confidence);
    sp_query_result_free(&r);
done:
    sp_query_engine_free(lx);
    sp_query_engine_free(ex);
}

static void test_create_refusals(void)
{
    sp_error err = {0};
    CHECK(engine("lexical", 0, &err) == NULL && err.code == SP_E_NOTFOUND && strstr(err.msg, "class names"));
    memset(&err, 0, sizeof err);
    CHECK(engine("wordnet", 1, &err) == NULL && err.code == SP_E_ARG && strstr(err.msg, "wordnet"));
}

static const char *encoder_of(const char *dir, const sp_encoder_opts *eo, sp_error *err)
{
    static char name[16];
    sp_query_engine *e = NULL;
    name[0] = 0;
    if (sp_query_engine_open_with(&e, dir, eo, NULL, g_dev, NULL, err) == 0)
        snprintf(name, sizeof name, "%s", sp_query_engine_source(e)->encoder);
    sp_query_engine_free(e);
    return e ? name : NULL;
}

/* Chosen per model folder: semantic.json "encoder", the default lexical when the class names are
 * known, exact (with a warning) when they are not or WordNet is missing; an asked-for encoder
 * that cannot be prepared or does not fit is an error; sp_semantic_set_encoder records one. */
static void test_model_folder(void)
{
    char dir[1100], sub[1200];
    snprintf(dir, sizeof dir, "%s", test_tmpdir("encoders"));
    sp_error err = {0};
    const char *e;
    snprintf(sub, sizeof sub, "%s/classes", dir);
    CHECK_OK(sc_write_model(sub, NULL, 1, &err), &err);
    CHECK((e = encoder_of(sub, NULL, &err)) && !strcmp(e, "lexical"));
    sp_encoder_opts ex = {.encoder = "exact"}, cl = {.encoder = "clip"}, bad_wn = {.encoder = "lexical", .wordnet_dir = "/nonexistent"};
    CHECK((e = encoder_of(sub, &ex, &err)) && !strcmp(e, "exact"));
    CHECK(!encoder_of(sub, &cl, &err) && err.code == SP_E_UNSUPPORTED && strstr(err.msg, "does not fit"));
    CHECK(!encoder_of(sub, &bad_wn, &err) && err.code == SP_E_NOTFOUND && strstr(err.msg, "wordnet"));
    sp_encoder_opts rec_wn = {.wordnet_dir = "/nonexistent"}; /* the folder's own choice falls back */
    CHECK((e = encoder_of(sub, &rec_wn, &err)) && !strcmp(e, "exact"));
    CHECK_OK(sp_semantic_set_encoder(sub, "exact", &err), &err);
    CHECK((e = encoder_of(sub, NULL, &err)) && !strcmp(e, "exact"));
    CHECK_OK(sp_semantic_set_encoder(sub, "lexical", &err), &err);
    CHECK((e = encoder_of(sub, NULL, &err)) && !strcmp(e, "lexical"));
    CHECK_FAILS(sp_semantic_set_encoder(sub, "clip", &err), SP_E_UNSUPPORTED, &err, "does not fit");
    CHECK_FAILS(sp_semantic_set_encoder(sub, "bert", &err), SP_E_ARG, &err, "bert");
    /* no class names anywhere: exact answers, and lexical cannot be asked for */
    snprintf(sub, sizeof sub, "%s/noclasses", dir);
    CHECK_OK(sc_write_model(sub, NULL, 0, &err), &err);
    CHECK((e = encoder_of(sub, NULL, &err)) && !strcmp(e, "exact"));
    sp_encoder_opts lex = {.encoder = "lexical"};
    CHECK(!encoder_of(sub, &lex, &err) && err.code == SP_E_NOTFOUND && strstr(err.msg, "class names"));
    CHECK_FAILS(sp_semantic_set_encoder(sub, "lexical", &err), SP_E_NOTFOUND, &err, "class names");
    /* a recorded lexical without class names falls back too; an unknown recorded one is refused */
    snprintf(sub, sizeof sub, "%s/recorded", dir);
    CHECK_OK(sc_write_model(sub, "lexical", 0, &err), &err);
    CHECK((e = encoder_of(sub, NULL, &err)) && !strcmp(e, "exact"));
    snprintf(sub, sizeof sub, "%s/unknown", dir);
    CHECK_OK(sc_write_model(sub, "bert", 1, &err), &err);
    CHECK(!encoder_of(sub, NULL, &err) && err.code == SP_E_UNSUPPORTED && strstr(err.msg, "bert"));
    /* class names from the capture's labels.json when semantic.json has none */
    snprintf(sub, sizeof sub, "%s/labels", dir);
    CHECK_OK(sc_write_model(sub, NULL, 0, &err), &err);
    char lj[1400];
    snprintf(lj, sizeof lj, "%s/sparse/labels.json", sub);
    const char *labels = "{\"labels\": {\"1\": {\"class\": \"chair\"}, \"2\": {\"class\": \"table\"}}}";
    CHECK_OK(sp_write_file_atomic(lj, labels, strlen(labels), &err), &err);
    CHECK((e = encoder_of(sub, NULL, &err)) && !strcmp(e, "lexical"));
}

int main(void)
{
    if (access(SP_LEX_DEFAULT_WORDNET "/index.noun", R_OK) != 0)
        TEST_SKIP("no WordNet at " SP_LEX_DEFAULT_WORDNET " (Debian wordnet-base)");
    float emb[SC_CLASSES][SC_FULL];
    sc_make_pca(&g_pca, emb);
    int *cls;
    sc_make_splat(&g_splat, &cls, &g_pca, emb);
    free(cls);
    sc_make_cams(g_cams, NCAM, CW, CH);
    sp_error err = {0};
    CHECK_OK(sp_device_create(&g_dev, SP_DEVICE_CPU, 2, &err), &err);
    RUN(test_lexical_plain_query);
    RUN(test_lexical_embedding);
    RUN(test_create_refusals);
    RUN(test_model_folder);
    sp_device_free(g_dev);
    sp_splat_free(&g_splat);
    sp_sem_pca_free(&g_pca);
    return TEST_EXIT();
}
