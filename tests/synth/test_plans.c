/* synth capture plans: --walk-only views are the walk's spins only (none aimed at an object),
 * --drive is one continuous drive at the camera's rate through both rooms of a two-room world
 * (steps and turns between kept frames bounded by speed and turn rate, every camera on free floor
 * away from walls, times increasing by keep_every / rate), capture.json records the plan, and
 * bad drive settings are refused. */
#include "semsplat/io.h"
#include "semsplat/synth.h"
#include "test.h"

#include <cjson/cJSON.h>

/* Two 5 x 4 m rooms side by side, a wall at x = 5 with a 1.2 m door at y in [1.4, 2.6]. */
static const char *world_text =
    "<sdf version='1.6'><world name='two_rooms'>\n"
    "<model name='floor'><link name='l'><visual name='v'><pose>5 2 -0.01 0 0 0</pose><geometry><box><size>10 4 0.02</size></box></geometry></visual></link></model>\n"
    "<model name='walls'><link name='l'>\n"
    "<visual name='s'><pose>5 0 1.2 0 0 0</pose><geometry><box><size>10 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='n'><pose>5 4 1.2 0 0 0</pose><geometry><box><size>10 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='w'><pose>0 2 1.2 0 0 0</pose><geometry><box><size>0.1 4 2.4</size></box></geometry></visual>\n"
    "<visual name='e'><pose>10 2 1.2 0 0 0</pose><geometry><box><size>0.1 4 2.4</size></box></geometry></visual>\n"
    "<visual name='m1'><pose>5 0.7 1.2 0 0 0</pose><geometry><box><size>0.1 1.4 2.4</size></box></geometry></visual>\n"
    "<visual name='m2'><pose>5 3.3 1.2 0 0 0</pose><geometry><box><size>0.1 1.4 2.4</size></box></geometry></visual>\n"
    "</link></model>\n"
    "<model name='sofa'><pose>1.5 3.3 0 0 0 0</pose><link name='l'><visual name='v'><pose>0 0 0.4 0 0 0</pose><geometry><box><size>2 0.8 0.8</size></box></geometry></visual></link></model>\n"
    "<model name='bed'><pose>8 1 0 0 0 0</pose><link name='l'><visual name='v'><pose>0 0 0.3 0 0 0</pose><geometry><box><size>1.6 1.8 0.6</size></box></geometry></visual></link></model>\n"
    "</world></sdf>\n";

static int load(sp_world *w, sp_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/two_rooms.world", test_tmpdir("synth_plans_world"));
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fputs(world_text, f);
    fclose(f);
    sp_synth_load_opts o = {.no_env = 1};
    return sp_synth_load_world(path, &o, w, err);
}

static float yaw_of(const sp_camera *c)
{
    /* optical axis = third row of R (camera z in world) */
    return atan2f(c->R[7], c->R[6]);
}

static void test_walk_only(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_synth_capture_opts o = {.n_views = 48, .width = 64, .height = 48, .seed = 2,
                               .plan = SP_SYNTH_PLAN_WALK};
    sp_camera *cams = NULL;
    size_t n = 0;
    sp_synth_plan_info info;
    CHECK_OK(sp_synth_plan(&w, &o, &cams, &n, &info, &err), &err);
    CHECK(n == 48 && !strcmp(info.name, "walk"));
    /* spins of 12 views: one centre, headings 30 degrees apart */
    for (size_t i = 0; i < n; i++) {
        size_t g = i / 12 * 12;
        sp_vec3 a = sp_camera_center(&cams[g]), b = sp_camera_center(&cams[i]);
        CHECK(sp_v3_norm(sp_v3_sub(a, b)) < 1e-4f);
        float d = yaw_of(&cams[i]) - yaw_of(&cams[g]) - (float)(i - g) * (float)(M_PI / 6);
        d = remainderf(d, 2 * (float)M_PI);
        CHECK_MSG(fabsf(d) < 1e-3f, "view %zu heading off its spin by %g rad", i, d);
    }
    free(cams);
    /* the mixed plan has views that are not on a spin (the arcs aimed at objects) */
    o.plan = SP_SYNTH_PLAN_MIXED;
    CHECK_OK(sp_synth_plan(&w, &o, &cams, &n, &info, &err), &err);
    CHECK(!strcmp(info.name, "walk+objects"));
    int off_spin = 0;
    for (size_t i = 0; i < n; i++) {
        sp_vec3 a = sp_camera_center(&cams[i / 12 * 12]), b = sp_camera_center(&cams[i]);
        off_spin += sp_v3_norm(sp_v3_sub(a, b)) > 1e-3f;
    }
    CHECK(off_spin > 0);
    free(cams);
    sp_world_free(&w);
}

static void test_drive(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_synth_capture_opts o = {.n_views = 400, .width = 64, .height = 48, .plan = SP_SYNTH_PLAN_DRIVE,
                               .drive_speed_mps = 0.4f, .drive_rate_hz = 10, .drive_turn_rad_s = 0.5f};
    sp_camera *cams = NULL;
    size_t n = 0;
    sp_synth_plan_info in;
    CHECK_OK(sp_synth_plan(&w, &o, &cams, &n, &in, &err), &err);
    CHECK(!strcmp(in.name, "drive"));
    CHECK(n > 50 && n <= 400 && n == in.n_views);
    CHECK(in.keep_every >= 1 && in.n_frames_driven > (in.keep_every - 1) * n);
    CHECK(in.n_frames_driven <= in.keep_every * n);
    CHECK_NEAR(in.duration_s, (in.n_frames_driven - 1) / 10.0, 0.1 + 0.1);
    CHECK(in.n_segments == 1 && in.n_waypoints >= 4);
    CHECK(in.path_length_m > 5.0); /* at least from one room into the other */
    CHECK_NEAR(in.rate_hz, 10.0 / in.keep_every, 1e-9);
    double step_bound = 0.4 / 10 * in.keep_every + 1e-4, turn_bound = 0.5 / 10 * in.keep_every + 1e-4;
    CHECK_MSG(in.max_step_m <= step_bound, "max step %g m", in.max_step_m);
    CHECK_MSG(in.max_turn_rad <= turn_bound, "max turn %g rad", in.max_turn_rad);
    size_t left = 0, right = 0;
    for (size_t i = 0; i < n; i++) {
        sp_vec3 c = sp_camera_center(&cams[i]);
        CHECK_NEAR(c.z, 0.9, 1e-4); /* the middle of the default heights, fixed on a robot */
        /* at least a robot's clearance (0.3 m, a cell of slack) from every wall */
        int in_room = c.y > 0.05f + 0.25f && c.y < 3.95f - 0.25f && c.x > 0.3f && c.x < 9.7f;
        int by_wall = fabsf(c.x - 5.0f) < 0.05f + 0.25f && (c.y < 1.4f + 0.25f || c.y > 2.6f - 0.25f);
        CHECK_MSG(in_room && !by_wall, "frame %zu at %.2f %.2f", i, c.x, c.y);
        left += c.x < 4.5f;
        right += c.x > 5.5f;
        if (i > 0) {
            sp_vec3 p = sp_camera_center(&cams[i - 1]);
            CHECK(sp_v3_norm(sp_v3_sub(c, p)) <= step_bound + 1e-3);
            CHECK_NEAR(in.t_s[i] - in.t_s[i - 1], in.keep_every / 10.0, 1e-9);
        }
    }
    CHECK_MSG(left > n / 5 && right > n / 5, "frames left %zu right %zu of %zu", left, right, n);
    sp_synth_plan_info_free(&in);
    free(cams);
    /* a smaller budget keeps every k-th frame of the same drive */
    o.n_views = 60;
    sp_synth_plan_info in2;
    CHECK_OK(sp_synth_plan(&w, &o, &cams, &n, &in2, &err), &err);
    CHECK(n <= 60 && in2.n_frames_driven > 0 && in2.keep_every > 1);
    sp_synth_plan_info_free(&in2);
    free(cams);
    /* sp_synth_plan_views follows opts->plan */
    CHECK_OK(sp_synth_plan_views(&w, &o, &cams, &n, &err), &err);
    CHECK(n <= 60 && n > 10);
    free(cams);
    /* refusals */
    o.drive_speed_mps = 50;
    CHECK_FAILS(sp_synth_plan(&w, &o, &cams, &n, NULL, &err), SP_E_ARG, &err, "speed 50");
    o.drive_speed_mps = 0.4f;
    o.drive_rate_hz = -1;
    CHECK_FAILS(sp_synth_plan(&w, &o, &cams, &n, NULL, &err), SP_E_ARG, &err, "rate -1");
    o.drive_rate_hz = 10;
    o.plan = 7;
    CHECK_FAILS(sp_synth_plan(&w, &o, &cams, &n, NULL, &err), SP_E_ARG, &err, "plan 7");
    sp_world_free(&w);
}

static void test_drive_capture_json(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_synth_capture_opts o = {.n_views = 6, .width = 32, .height = 24, .n_points = 200,
                               .plan = SP_SYNTH_PLAN_DRIVE, .supersample = 1};
    const char *out = test_tmpdir("synth_plans_drive");
    CHECK_OK(sp_synth_capture(&w, out, &o, &err), &err);
    char path[1300];
    snprintf(path, sizeof path, "%s/capture.json", out);
    cJSON *j = NULL;
    CHECK_OK(sp_json_read_file(path, &j, &err), &err);
    const cJSON *plan = cJSON_GetObjectItem(j, "plan"), *d = cJSON_GetObjectItem(j, "drive");
    CHECK(cJSON_IsString(plan) && !strcmp(plan->valuestring, "drive"));
    CHECK(cJSON_IsObject(d));
    const cJSON *views = cJSON_GetObjectItem(j, "views");
    const cJSON *times = cJSON_GetObjectItem(d, "frame_time_s");
    CHECK(cJSON_IsNumber(views) && views->valueint >= 1 && views->valueint <= 6);
    CHECK(cJSON_IsArray(times) && cJSON_GetArraySize(times) == views->valueint);
    CHECK(cJSON_IsNumber(cJSON_GetObjectItem(d, "camera_rate_hz")) &&
          cJSON_GetObjectItem(d, "camera_rate_hz")->valuedouble == 10);
    snprintf(path, sizeof path, "%s/images/%05d.png", out, views->valueint - 1);
    CHECK(sp_file_exists(path));
    cJSON_Delete(j);
    /* the walk's capture.json says so, without a drive section */
    o.plan = SP_SYNTH_PLAN_WALK;
    o.n_views = 3;
    out = test_tmpdir("synth_plans_walk");
    CHECK_OK(sp_synth_capture(&w, out, &o, &err), &err);
    snprintf(path, sizeof path, "%s/capture.json", out);
    CHECK_OK(sp_json_read_file(path, &j, &err), &err);
    plan = cJSON_GetObjectItem(j, "plan");
    CHECK(cJSON_IsString(plan) && !strcmp(plan->valuestring, "walk"));
    CHECK(cJSON_GetObjectItem(j, "drive") == NULL);
    cJSON_Delete(j);
    sp_world_free(&w);
}

int main(void)
{
    RUN(test_walk_only);
    RUN(test_drive);
    RUN(test_drive_capture_json);
    return TEST_EXIT();
}
