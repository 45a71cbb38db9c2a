/* sfm: spawning (exit status, timeout kills the child, output to the log, a missing program is
 * named), alignment of a reconstruction given in another frame (a known similarity recovered,
 * one misplaced image named and not pulling the fit), and the whole sp_sfm_colmap flow against a
 * stand-in COLMAP script (argument checks, the largest of two models taken, the capture written
 * with linked images, labels and a capture.json naming COLMAP's poses). A run of the real COLMAP
 * is measured by hand (README), not here: it takes minutes on 2 cores. */
#include <sys/stat.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "semsplat/io.h"
#include "semsplat/sfm.h"
#include "sfm/sfm_internal.h"
#include "test.h"

static void test_find_and_spawn(void)
{
    sp_error err = {0};
    char path[4096];
    CHECK_FAILS(sp_sfm_find_colmap("no-such-colmap-xyz", path, sizeof path, &err), SP_E_NOTFOUND, &err,
                "apt-get install colmap");
    CHECK_OK(sp_sfm_find_colmap("sh", path, sizeof path, &err), &err);
    CHECK(strstr(path, "/sh") != NULL);
    const char *dir = test_tmpdir("sfm_spawn");
    char log[1200];
    snprintf(log, sizeof log, "%s/log.txt", dir);
    char *ok[] = {"/bin/sh", "-c", "echo hello from the child; echo to stderr >&2", NULL};
    CHECK_OK(sp_sfm_spawn(ok, log, 5, 10, &err), &err);
    char *text = NULL;
    size_t n = 0;
    CHECK_OK(sp_read_file(log, &text, &n, &err), &err);
    CHECK(text && strstr(text, "hello from the child") && strstr(text, "to stderr"));
    free(text);
    char *fail[] = {"/bin/sh", "-c", "exit 3", NULL};
    CHECK_FAILS(sp_sfm_spawn(fail, log, 0, 10, &err), SP_E_IO, &err, "exit status 3");
    char *missing[] = {"/no/such/program", "x", NULL};
    CHECK_FAILS(sp_sfm_spawn(missing, log, 0, 10, &err), SP_E_IO, &err, "could not be started");
    /* a timeout stops the child and its group: the grandchild's marker never appears */
    char marker[1300], cmd[1500];
    snprintf(marker, sizeof marker, "%s/late", dir);
    snprintf(cmd, sizeof cmd, "(sleep 2; touch '%s') & sleep 30", marker);
    char *slow[] = {"/bin/sh", "-c", cmd, NULL};
    double t0 = sp_time_now();
    CHECK_FAILS(sp_sfm_spawn(slow, log, 0, 0.3, &err), SP_E_IO, &err, "limit");
    CHECK(sp_time_now() - t0 < 5);
    sleep(3);
    CHECK(!sp_file_exists(marker));
    CHECK_FAILS(sp_sfm_spawn(ok, log, 30, 10, &err), SP_E_ARG, &err, "niceness 30");
}

/* A reference model: n cameras on a circle looking inwards, 1 PINHOLE camera, a few points. */
static void make_reference(sp_colmap_model *m, size_t n, sp_colmap_camera *cam, sp_colmap_image *ims,
                           char (*names)[32], sp_colmap_point *pts, size_t np)
{
    memset(m, 0, sizeof *m);
    *cam = (sp_colmap_camera){.id = 1, .model = SP_COLMAP_PINHOLE, .width = 64, .height = 48,
                              .n_params = 4, .params = {50, 50, 32, 24}};
    for (size_t i = 0; i < n; i++) {
        sp_camera c = {0};
        float a = (float)(2 * M_PI * i / n);
        sp_vec3 eye = sp_v3(3 + 2 * cosf(a), 1 + 2 * sinf(a), 0.8f + 0.1f * (i % 3));
        sp_camera_look_at(&c, eye, sp_v3(3, 1, 0.5f), sp_v3(0, 0, 1));
        memset(&ims[i], 0, sizeof ims[i]);
        ims[i].id = (uint32_t)(i + 1);
        ims[i].camera_id = 1;
        snprintf(names[i], 32, "%05zu.png", i);
        ims[i].name = names[i];
        sp_colmap_image_set_pose(&ims[i], &c);
    }
    for (size_t p = 0; p < np; p++)
        pts[p] = (sp_colmap_point){.id = p + 1, .xyz = {3 + 0.1 * p, 1 - 0.05 * p, 0.3 + 0.02 * p}};
    m->n_cameras = 1;
    m->cameras = cam;
    m->n_images = n;
    m->images = ims;
    m->n_points = np;
    m->points = pts;
}

/* COLMAP's frame: x_c = (R^T (x_w - t)) / s for a known similarity. */
static const double S = 0.37, T[3] = {0.5, -2.0, 1.0};
static const float RZ = 0.7f; /* about z */
static void to_colmap_frame(sp_colmap_model *m)
{
    float R[9] = {cosf(RZ), -sinf(RZ), 0, sinf(RZ), cosf(RZ), 0, 0, 0, 1};
    for (size_t i = 0; i < m->n_images; i++) {
        sp_camera c;
        sp_colmap_image_camera(m, i, &c, NULL);
        /* x_cam_metric = Rc x_w + tc; x_w = s R x_c + T -> x_cam = Rc R x_c + (Rc T + tc)/s */
        float Rn[9], tn[3];
        sp_mat3_mul(c.R, R, Rn);
        for (int r = 0; r < 3; r++)
            tn[r] = (float)((c.R[r * 3] * T[0] + c.R[r * 3 + 1] * T[1] + c.R[r * 3 + 2] * T[2] + c.t[r]) / S);
        memcpy(c.R, Rn, sizeof Rn);
        memcpy(c.t, tn, sizeof tn);
        sp_colmap_image_set_pose(&m->images[i], &c);
    }
    for (size_t p = 0; p < m->n_points; p++) {
        double *x = m->points[p].xyz, d[3] = {x[0] - T[0], x[1] - T[1], x[2] - T[2]};
        for (int r = 0; r < 3; r++) x[r] = (R[r] * d[0] + R[3 + r] * d[1] + R[6 + r] * d[2]) / S;
    }
}

static void test_align_recovers_similarity(void)
{
    enum { N = 24, NP = 5 };
    sp_colmap_model ref, est;
    sp_colmap_camera c1, c2;
    sp_colmap_image i1[N], i2[N];
    char n1[N][32], n2[N][32];
    sp_colmap_point p1[NP], p2[NP];
    make_reference(&ref, N, &c1, i1, n1, p1, NP);
    make_reference(&est, N, &c2, i2, n2, p2, NP);
    to_colmap_frame(&est);
    /* millimetre noise on every camera, as a real reconstruction has, and one image COLMAP put
     * 40 cm off */
    test_rng rng = {7};
    for (int i = 0; i < N; i++)
        for (int k = 0; k < 3; k++) i2[i].tvec[k] += test_range(&rng, -1e-3, 1e-3) / S;
    i2[7].tvec[0] += 0.4 / S;
    sp_sfm_result res = {0};
    sp_error err = {0};
    char *fit = NULL;
    CHECK_OK(sfm_align(&est, &ref, &res, &fit, &err), &err);
    CHECK(fit && strstr(fit, "00007.png")); /* the outlier, named in the fit's report */
    free(fit);
    CHECK_NEAR(res.scale, S, 1e-3);
    CHECK_MSG(res.n_inliers == N - 1, "%d inliers, bound %g m", res.n_inliers, res.align_threshold_m);
    CHECK(!strcmp(res.worst_image, "00007.png"));
    CHECK_NEAR(res.ate_max_m, 0.4, 0.02);
    CHECK(res.ate_median_m < 2e-3);
    CHECK(res.rot_err_max_deg < 0.1);
    for (size_t i = 0; i < N; i++) {
        if (i == 7) continue;
        sp_camera a, b;
        sp_colmap_image_camera(&est, i, &a, NULL);
        sp_colmap_image_camera(&ref, i, &b, NULL);
        for (int k = 0; k < 9; k++) CHECK_NEAR(a.R[k], b.R[k], 1e-3);
        for (int k = 0; k < 3; k++) CHECK_NEAR(a.t[k], b.t[k], 3e-3);
    }
    for (size_t p = 0; p < NP; p++)
        for (int k = 0; k < 3; k++) CHECK_NEAR(est.points[p].xyz[k], ref.points[p].xyz[k], 2e-3);
    /* too few images known to the reference */
    est.n_images = 3;
    CHECK_FAILS(sfm_align(&est, &ref, &res, &fit, &err), SP_E_FORMAT, &err, "at least 4");
    CHECK(fit == NULL);
}

/* A stand-in for COLMAP: checks the CPU flags and, as the mapper, writes two models. */
static const char *fake_colmap =
    "#!/bin/sh\n"
    "stage=$1; shift\n"
    "echo \"fake colmap $stage $*\"\n"
    "case \"$stage\" in\n"
    "feature_extractor) echo \"$*\" | grep -q 'SiftExtraction.use_gpu 0' || exit 9;\n"
    "  echo \"$*\" | grep -q 'ImageReader.camera_params 50,50,32,24' || exit 8 ;;\n"
    "sequential_matcher) echo \"$*\" | grep -q 'SiftMatching.use_gpu 0' || exit 9 ;;\n"
    "mapper) out=''; while [ $# -gt 0 ]; do [ \"$1\" = --output_path ] && out=$2; shift; done\n"
    "  mkdir -p \"$out/0\" \"$out/1\" && cp \"$FAKE_SMALL\"/*.bin \"$out/0/\" && cp \"$FAKE_BIG\"/*.bin \"$out/1/\" ;;\n"
    "*) exit 2 ;;\n"
    "esac\n";

static void test_pipeline_with_stand_in(void)
{
    enum { N = 12, NP = 4 };
    sp_error err = {0};
    const char *base = test_tmpdir("sfm_pipeline");
    char cap[1200], out[1200], p[1400], q[1400], prog[1300];
    snprintf(cap, sizeof cap, "%s/capture", base);
    snprintf(out, sizeof out, "%s/out", base);
    /* the reference capture: model, images, labels, ground truth */
    sp_colmap_model ref, est;
    sp_colmap_camera c1, c2;
    sp_colmap_image i1[N], i2[N];
    char n1[N][32], n2[N][32];
    sp_colmap_point p1[NP], p2[NP];
    make_reference(&ref, N, &c1, i1, n1, p1, NP);
    snprintf(p, sizeof p, "%s/sparse/0", cap);
    CHECK_OK(sp_mkdirs(p, &err), &err);
    CHECK_OK(sp_colmap_write_bin(p, &ref, &err), &err);
    for (int d = 0; d < 2; d++) {
        snprintf(p, sizeof p, "%s/%s", cap, d ? "labels" : "images");
        CHECK_OK(sp_mkdirs(p, &err), &err);
        for (int i = 0; i < N; i++) {
            snprintf(q, sizeof q, "%s/%05d.png", p, i);
            CHECK_OK(sp_write_file_atomic(q, d ? "label" : "image", 5, &err), &err);
        }
    }
    snprintf(p, sizeof p, "%s/ground_truth.json", cap);
    CHECK_OK(sp_write_file_atomic(p, "{\"objects\": []}", 15, &err), &err);
    snprintf(p, sizeof p, "%s/capture.json", cap);
    const char *cj = "{\"plan\": \"drive\", \"poses\": \"exact\"}";
    CHECK_OK(sp_write_file_atomic(p, cj, strlen(cj), &err), &err);
    /* what the stand-in's mapper "reconstructs": all but image 3 (big), and 4 images (small) */
    make_reference(&est, N, &c2, i2, n2, p2, NP);
    to_colmap_frame(&est);
    memmove(&i2[3], &i2[4], (N - 4) * sizeof i2[0]);
    est.n_images = N - 1;
    snprintf(p, sizeof p, "%s/big", base);
    CHECK_OK(sp_mkdirs(p, &err), &err);
    CHECK_OK(sp_colmap_write_bin(p, &est, &err), &err);
    setenv("FAKE_BIG", p, 1);
    est.n_images = 4;
    snprintf(p, sizeof p, "%s/small", base);
    CHECK_OK(sp_mkdirs(p, &err), &err);
    CHECK_OK(sp_colmap_write_bin(p, &est, &err), &err);
    setenv("FAKE_SMALL", p, 1);
    snprintf(prog, sizeof prog, "%s/colmap", base);
    CHECK_OK(sp_write_file_atomic(prog, fake_colmap, strlen(fake_colmap), &err), &err);
    chmod(prog, 0755);

    sp_sfm_opts o = {.capture = cap, .out = out, .colmap = prog, .threads = 1, .nice = 1, .timeout_s = 20};
    sp_sfm_result r;
    CHECK_OK(sp_sfm_colmap(&o, &r, &err), &err);
    CHECK(r.n_images == N && r.n_models == 2 && r.n_registered == N - 1);
    if (r.n_models == 2) CHECK(r.model_images[0] == N - 1 && r.model_images[1] == 4);
    CHECK_NEAR(r.scale, S, 1e-4);
    CHECK(r.ate_max_m < 1e-3);
    sp_sfm_result_free(&r);
    /* the capture: the model in the reference frame, 11 images and labels, no image 3 */
    sp_colmap_model back = {0};
    CHECK_OK(sp_colmap_read(out, &back, &err), &err);
    CHECK(back.n_images == N - 1);
    for (size_t i = 0; i < back.n_images; i++) {
        sp_camera a;
        sp_colmap_image_camera(&back, i, &a, NULL);
        int k = atoi(back.images[i].name);
        sp_camera b;
        sp_colmap_image_camera(&ref, (size_t)k, &b, NULL);
        sp_vec3 ca = sp_camera_center(&a), cb = sp_camera_center(&b);
        CHECK(sp_v3_norm(sp_v3_sub(ca, cb)) < 1e-3f);
    }
    sp_colmap_free(&back);
    snprintf(p, sizeof p, "%s/images/00002.png", out);
    CHECK(sp_file_exists(p));
    snprintf(p, sizeof p, "%s/labels/00002.png", out);
    CHECK(sp_file_exists(p));
    snprintf(p, sizeof p, "%s/images/00003.png", out);
    CHECK(!sp_file_exists(p));
    snprintf(p, sizeof p, "%s/ground_truth.json", out);
    CHECK(sp_file_exists(p));
    snprintf(p, sizeof p, "%s/capture.json", out);
    cJSON *j = NULL;
    CHECK_OK(sp_json_read_file(p, &j, &err), &err);
    const cJSON *poses = cJSON_GetObjectItem(j, "poses"), *sfm = cJSON_GetObjectItem(j, "sfm");
    CHECK(cJSON_IsString(poses) && !strncmp(poses->valuestring, "colmap: 11 of 12", 16));
    CHECK(cJSON_IsObject(sfm) && cJSON_GetObjectItem(sfm, "alignment"));
    CHECK(cJSON_IsString(cJSON_GetObjectItem(j, "plan")));
    cJSON_Delete(j);
    /* frame.json: a world frame made by alignment, with the fit's residual */
    snprintf(p, sizeof p, "%s/frame.json", out);
    sp_frame fr;
    CHECK_OK(sp_frame_read(p, &fr, &err), &err);
    CHECK(!strcmp(fr.source, "align") && sp_frame_is_world(&fr) && fr.residual_m >= 0 && fr.residual_m < 1e-3);
    snprintf(p, sizeof p, "%s/colmap/colmap.log", out);
    char *log = NULL;
    size_t n = 0;
    CHECK_OK(sp_read_file(p, &log, &n, &err), &err);
    CHECK(log && strstr(log, "fake colmap mapper"));
    free(log);
    /* a stage that fails is named with its status and the log */
    o.estimate_intrinsics = 1; /* the stand-in wants the given intrinsics: exit 8 */
    CHECK_FAILS(sp_sfm_colmap(&o, &r, &err), SP_E_IO, &err, "exit status 8");
    sp_sfm_result_free(&r);
    o.colmap = "no-such-colmap-xyz";
    CHECK_FAILS(sp_sfm_colmap(&o, &r, &err), SP_E_NOTFOUND, &err, "colmap");
    sp_sfm_result_free(&r);
}

int main(void)
{
    RUN(test_find_and_spawn);
    RUN(test_align_recovers_similarity);
    RUN(test_pipeline_with_stand_in);
    return TEST_EXIT();
}
