/* semsplat align --matches on camera-centre matches with planted misregistrations (5 of 49, as
 * a COLMAP run of a synth capture gave): the transformed splat lands in the world frame within
 * the matches' noise (plain least squares was pulled off by the five), the five images are named
 * in the output and in OUT.align.json, and when most matches disagree the command refuses. */
#include "test.h"

#include <cjson/cJSON.h>

#include "semantic/matches.h"
#include "semsplat/io.h"

static int run_cli(const char *args, char *out, size_t cap) { return test_run_cli(args, out, cap); }

enum { N = 49, NB = 5 };

static void test_align_names_misregistered(void)
{
    const char *dir = test_tmpdir("align_cli");
    test_rng r = {4242};
    const int bad[NB] = {3, 11, 12, 30, 47};
    double src[N * 3], dst[N * 3], M[16];
    planted_matches(&r, N, bad, NB, 0.02, src, dst, M);
    char model[1200], matches[1300], in[1300], out[1300], report[1300], args[6000], text[16384];
    snprintf(model, sizeof model, "%s/sparse", dir);
    snprintf(matches, sizeof matches, "%s/matches.txt", dir);
    snprintf(in, sizeof in, "%s/colmap_frame.ply", dir);
    snprintf(out, sizeof out, "%s/world.ply", dir);
    snprintf(report, sizeof report, "%s/world.align.json", dir);
    sp_error err = {0};
    CHECK_OK(write_centres(model, matches, src, dst, N, &err), &err);
    /* a splat with one Gaussian at each COLMAP-frame camera centre */
    sp_splat s;
    CHECK_OK(sp_splat_alloc(&s, N, 0, 0, &err), &err);
    for (int i = 0; i < N * 3; i++) s.means[i] = (float)src[i];
    CHECK_OK(sp_ply_write_splat(in, &s, &err), &err);
    sp_splat_free(&s);
    snprintf(args, sizeof args, "align --splat %s --colmap %s --matches %s --out %s", in, model, matches, out);
    int rc = run_cli(args, text, sizeof text);
    CHECK_MSG(rc == 0, "exit %d: %s", rc, text);
    for (int k = 0; k < NB; k++) {
        char name[32];
        snprintf(name, sizeof name, "outlier  img_%02d.png", bad[k]);
        CHECK_MSG(strstr(text, name) != NULL, "'%s' not in the output: %s", name, text);
    }
    /* the good cameras are where the world says, within the noise (0.02 per axis) */
    sp_splat w = {0};
    CHECK_OK(sp_ply_read_splat(out, &w, &err), &err);
    double worst = 0;
    for (int i = 0; i < N && w.means; i++) {
        int is_bad = 0;
        for (int k = 0; k < NB; k++) is_bad |= bad[k] == i;
        if (is_bad) continue;
        double d2 = 0;
        for (int a = 0; a < 3; a++) d2 += (w.means[3 * i + a] - dst[3 * i + a]) * (w.means[3 * i + a] - dst[3 * i + a]);
        worst = fmax(worst, sqrt(d2));
    }
    fprintf(stderr, "  worst consistent camera off by %.4f m\n", worst);
    CHECK_MSG(worst < 0.06, "a consistent camera is %.3f m from its world position", worst);
    sp_splat_free(&w);
    /* the fit is recorded: inliers, RMS, the outlying images exactly */
    cJSON *js = NULL;
    CHECK_OK(sp_json_read_file(report, &js, &err), &err);
    if (js) {
        CHECK(cJSON_GetObjectItem(js, "inliers")->valueint == N - NB);
        CHECK(cJSON_GetObjectItem(js, "rms_inliers")->valuedouble < 0.04);
        const cJSON *o = cJSON_GetObjectItem(js, "outliers");
        CHECK(cJSON_GetArraySize(o) == NB);
        for (int k = 0; k < NB && k < cJSON_GetArraySize(o); k++) {
            char name[32];
            snprintf(name, sizeof name, "img_%02d.png", bad[k]);
            CHECK(!strcmp(cJSON_GetObjectItem(cJSON_GetArrayItem(o, k), "image")->valuestring, name));
        }
        cJSON_Delete(js);
    }
    /* most matches wrong: refused, nothing written */
    const int many[30] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29};
    planted_matches(&r, N, many, 30, 0.02, src, dst, M);
    CHECK_OK(write_centres(model, matches, src, dst, N, &err), &err);
    snprintf(out, sizeof out, "%s/refused.ply", dir);
    snprintf(args, sizeof args, "align --splat %s --colmap %s --matches %s --out %s", in, model, matches, out);
    rc = run_cli(args, text, sizeof text);
    CHECK_MSG(rc != 0 && strstr(text, "do not agree"), "exit %d: %s", rc, text);
    CHECK(!sp_file_exists(out));
}

int main(void)
{
    RUN(test_align_names_misregistered);
    return TEST_EXIT();
}
