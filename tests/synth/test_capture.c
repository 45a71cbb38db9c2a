/* synth captures: a small two-room world rendered to a capture; the COLMAP model round-trips
 * through our reader and writer with the planned poses, files are complete, ground-truth boxes
 * agree with the label images, and the same flags give the same bytes. */
#include "semsplat/io.h"
#include "semsplat/synth.h"
#include "test.h"

#include <cjson/cJSON.h>

static const char *rooms_world =
    "<sdf version='1.6'><world name='rooms'>\n"
    "<model name='floor'><link name='l'><visual name='v'><pose>2 1.5 -0.01 0 0 0</pose><geometry><box><size>4 3 0.02</size></box></geometry>"
    "<material><script><name>Gazebo/WoodFloor</name></script></material></visual></link></model>\n"
    "<model name='walls'><link name='l'>\n"
    "<visual name='s'><pose>2 0 1.2 0 0 0</pose><geometry><box><size>4 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='n'><pose>2 3 1.2 0 0 0</pose><geometry><box><size>4 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='w'><pose>0 1.5 1.2 0 0 0</pose><geometry><box><size>0.1 3 2.4</size></box></geometry></visual>\n"
    "<visual name='e'><pose>4 1.5 1.2 0 0 0</pose><geometry><box><size>0.1 3 2.4</size></box></geometry></visual>\n"
    "<visual name='mid'><pose>2 0.6 1.2 0 0 0</pose><geometry><box><size>0.1 1.2 2.4</size></box></geometry></visual>\n"
    "</link></model>\n"
    "<model name='table_1'><pose>0.9 2.2 0 0 0 0.3</pose><link name='l'><visual name='top'><pose>0 0 0.7 0 0 0</pose>"
    "<geometry><box><size>0.8 0.5 0.05</size></box></geometry><material><diffuse>0.6 0.4 0.2 1</diffuse></material></visual>"
    "<visual name='leg'><pose>0 0 0.35 0 0 0</pose><geometry><cylinder><radius>0.05</radius><length>0.7</length></cylinder></geometry></visual>"
    "</link></model>\n"
    "<model name='ball_2'><pose>3.1 0.8 0.25 0 0 0</pose><link name='l'><visual name='v'><geometry><sphere><radius>0.25</radius></sphere></geometry>"
    "<material><diffuse>0.1 0.3 0.9 1</diffuse></material></visual></link></model>\n"
    "</world></sdf>\n";

static char world_path[1200];

static int load(sp_world *w, sp_error *err)
{
    const char *d = test_tmpdir("synth_capture_world");
    snprintf(world_path, sizeof world_path, "%s/rooms.world", d);
    FILE *f = fopen(world_path, "w");
    fputs(rooms_world, f);
    fclose(f);
    sp_synth_load_opts o = {.no_env = 1};
    return sp_synth_load_world(world_path, &o, w, err);
}

static int same_file(const char *a, const char *b)
{
    char *x = NULL, *y = NULL;
    size_t nx = 0, ny = 0;
    sp_error err = {0};
    int ok = !sp_read_file(a, &x, &nx, &err) && !sp_read_file(b, &y, &ny, &err) && nx == ny && !memcmp(x, y, nx);
    free(x);
    free(y);
    return ok;
}

static void test_capture(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_synth_capture_opts o = {.n_views = 8, .width = 64, .height = 48, .fov_deg = 70, .n_points = 2000,
                               .seed = 3, .n_threads = 2};
    char out1[1200], out2[1200], p[1400], q[1400];
    snprintf(out1, sizeof out1, "%s", test_tmpdir("synth_capture_a"));
    snprintf(out2, sizeof out2, "%s", test_tmpdir("synth_capture_b"));
    CHECK_OK(sp_synth_capture(&w, out1, &o, &err), &err);
    o.n_threads = 1; /* a different thread count, the same bytes */
    CHECK_OK(sp_synth_capture(&w, out2, &o, &err), &err);

    /* the planned cameras: inside the rooms at robot heights */
    sp_camera *cams = NULL;
    size_t n = 0;
    CHECK_OK(sp_synth_plan_views(&w, &o, &cams, &n, &err), &err);
    CHECK(n == 8);
    for (size_t i = 0; i < n; i++) {
        sp_vec3 c = sp_camera_center(&cams[i]);
        CHECK_MSG(c.x > 0.05f && c.x < 3.95f && c.y > 0.05f && c.y < 2.95f && c.z >= 0.29f && c.z <= 1.51f,
                  "view %zu at %.2f %.2f %.2f", i, c.x, c.y, c.z);
    }

    /* COLMAP: read back, poses exact, write again, read again: the same model */
    sp_colmap_model m = {0}, m2 = {0};
    CHECK_OK(sp_colmap_read(out1, &m, &err), &err);
    CHECK(m.n_cameras == 1 && m.n_images == 8);
    CHECK(m.n_points >= 1500 && m.n_points <= 2000);
    if (m.n_cameras == 1) {
        CHECK(m.cameras[0].model == SP_COLMAP_PINHOLE && m.cameras[0].width == 64 && m.cameras[0].height == 48);
        CHECK_NEAR(m.cameras[0].params[0], 32.0 / tan(35.0 * M_PI / 180.0), 1e-3);
    }
    for (size_t i = 0; i < m.n_images && i < n; i++) {
        sp_camera c;
        CHECK_OK(sp_colmap_image_camera(&m, i, &c, &err), &err);
        for (int k = 0; k < 9; k++) CHECK_NEAR(c.R[k], cams[i].R[k], 1e-6);
        for (int k = 0; k < 3; k++) CHECK_NEAR(c.t[k], cams[i].t[k], 1e-6);
    }
    /* each point lies on the surface seen at its 2D observation: depth there matches */
    for (size_t pi = 0; pi < m.n_points; pi += 97) {
        const sp_colmap_point *pt = &m.points[pi];
        CHECK(pt->track_len == 1);
        if (pt->track_len != 1) continue;
        size_t ii = pt->track[0] - 1;
        const sp_colmap_image *im = &m.images[ii];
        CHECK(im->point3d_ids[pt->track[1]] == (int64_t)pt->id);
        snprintf(p, sizeof p, "%s/depth/%05zu.npy", out1, ii);
        sp_npy d = {0};
        CHECK_OK(sp_npy_read(p, &d, &err), &err);
        if (!d.data) continue;
        CHECK(d.dtype == SP_DTYPE_F32 && d.ndim == 2 && d.shape[0] == 48 && d.shape[1] == 64);
        int px = (int)im->xys[2 * pt->track[1]], py = (int)im->xys[2 * pt->track[1] + 1];
        double zc = cams[ii].R[6] * pt->xyz[0] + cams[ii].R[7] * pt->xyz[1] + cams[ii].R[8] * pt->xyz[2] + cams[ii].t[2];
        CHECK_NEAR(((float *)d.data)[py * 64 + px], zc, 1e-4);
        sp_npy_free(&d);
    }
    snprintf(p, sizeof p, "%s/rewritten", out1);
    CHECK_OK(sp_mkdirs(p, &err), &err);
    CHECK_OK(sp_colmap_write_bin(p, &m, &err), &err);
    CHECK_OK(sp_colmap_read(p, &m2, &err), &err);
    const char *bins[] = {"cameras.bin", "images.bin", "points3D.bin"};
    for (int k = 0; k < 3; k++) {
        char a[1500], b[1500];
        snprintf(a, sizeof a, "%s/sparse/0/%s", out1, bins[k]);
        snprintf(b, sizeof b, "%s/%s", p, bins[k]);
        CHECK_MSG(same_file(a, b), "%s differs after a read/write round trip", bins[k]);
    }
    CHECK(m2.n_points == m.n_points && m2.n_images == m.n_images);
    sp_colmap_free(&m2);

    /* labels agree with the ground-truth boxes projected into each view */
    for (size_t i = 0; i < n; i++) {
        sp_image lab = {0};
        snprintf(p, sizeof p, "%s/labels/%05zu.png", out1, i);
        CHECK_OK(sp_image_read(p, &lab, &err), &err);
        if (!lab.data) continue;
        CHECK(lab.bit_depth == 16 && lab.channels == 1 && lab.width == 64);
        const uint16_t *L = lab.data;
        for (size_t ob = 0; ob < w.n_objects; ob++) {
            const sp_synth_object *O = &w.objects[ob];
            float umin = 1e9f, umax = -1e9f, vmin = 1e9f, vmax = -1e9f;
            int behind = 0;
            for (int k = 0; k < 8; k++) {
                float P[3] = {(k & 1) ? O->aabb_max[0] : O->aabb_min[0], (k & 2) ? O->aabb_max[1] : O->aabb_min[1],
                              (k & 4) ? O->aabb_max[2] : O->aabb_min[2]}, Q[3];
                for (int r = 0; r < 3; r++)
                    Q[r] = cams[i].R[r * 3] * P[0] + cams[i].R[r * 3 + 1] * P[1] + cams[i].R[r * 3 + 2] * P[2] + cams[i].t[r];
                if (Q[2] <= 0.02f) { behind = 1; break; }
                float u = cams[i].fx * Q[0] / Q[2] + cams[i].cx, v = cams[i].fy * Q[1] / Q[2] + cams[i].cy;
                umin = fminf(umin, u); umax = fmaxf(umax, u); vmin = fminf(vmin, v); vmax = fmaxf(vmax, v);
            }
            if (behind) continue;
            long outside = 0;
            for (int y = 0; y < 48; y++)
                for (int x = 0; x < 64; x++)
                    if (L[y * 64 + x] == ob + 1) outside += x + 1 < umin || x > umax || y + 1 < vmin || y > vmax;
            CHECK_MSG(outside == 0, "view %zu: %ld pixels of %s outside its box", i, outside, O->name);
        }
        sp_image_free(&lab);
    }

    /* labels.json and ground_truth.json */
    cJSON *lj = NULL, *gt = NULL;
    snprintf(p, sizeof p, "%s/labels.json", out1);
    CHECK_OK(sp_json_read_file(p, &lj, &err), &err);
    snprintf(p, sizeof p, "%s/ground_truth.json", out1);
    CHECK_OK(sp_json_read_file(p, &gt, &err), &err);
    if (lj && gt) {
        cJSON *l3 = cJSON_GetObjectItem(cJSON_GetObjectItem(lj, "labels"), "3");
        CHECK(l3 && !strcmp(cJSON_GetObjectItem(l3, "name")->valuestring, "table_1"));
        CHECK(l3 && !strcmp(cJSON_GetObjectItem(l3, "class")->valuestring, "table"));
        cJSON *l2 = cJSON_GetObjectItem(cJSON_GetObjectItem(lj, "labels"), "2");
        CHECK(l2 && cJSON_IsTrue(cJSON_GetObjectItem(l2, "is_structure")));
        CHECK(!strcmp(cJSON_GetObjectItem(gt, "world")->valuestring, w.path));
        cJSON *objs = cJSON_GetObjectItem(gt, "objects");
        CHECK(cJSON_GetArraySize(objs) == 2 && cJSON_GetArraySize(cJSON_GetObjectItem(gt, "structure")) == 2);
        cJSON *ball = cJSON_GetArrayItem(objs, 1);
        CHECK(ball && !strcmp(cJSON_GetObjectItem(ball, "class")->valuestring, "ball"));
        if (ball) {
            cJSON *mn = cJSON_GetObjectItem(ball, "aabb_min"), *ps = cJSON_GetObjectItem(ball, "position");
            CHECK_NEAR(cJSON_GetArrayItem(mn, 0)->valuedouble, 2.85, 1e-5);
            CHECK_NEAR(cJSON_GetArrayItem(mn, 2)->valuedouble, 0.0, 1e-5);
            CHECK_NEAR(cJSON_GetArrayItem(ps, 1)->valuedouble, 0.8, 1e-6);
        }
    }
    cJSON_Delete(lj);
    cJSON_Delete(gt);

    /* determinism: every file the same bytes */
    const char *files[] = {"sparse/0/cameras.bin", "sparse/0/images.bin", "sparse/0/points3D.bin", "labels.json",
                           "ground_truth.json", "images/00000.png", "images/00007.png", "depth/00003.npy",
                           "labels/00005.png"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        snprintf(p, sizeof p, "%s/%s", out1, files[k]);
        snprintf(q, sizeof q, "%s/%s", out2, files[k]);
        CHECK_MSG(same_file(p, q), "%s differs between two runs", files[k]);
    }
    sp_colmap_free(&m);
    free(cams);
    sp_world_free(&w);
}

/* Furniture named after the structure it stands on or hangs from is an object, not structure:
 * a floor lamp, a wall clock, a ceiling fan (as model names, CamelCase, and through an include of
 * a model so named) must be in ground_truth.json's objects, and walls, floors, ceilings and the
 * ground plane in its structure. The old rule tested whether the model name *started* with
 * wall/floor/ground/ceiling and dropped all four from the objects. */
static const char *furniture_world =
    "<sdf version='1.6'><world name='furniture'>\n"
    "<model name='ground_plane'><link name='l'><visual name='v'><geometry><plane><normal>0 0 1</normal>"
    "<size>6 6</size></plane></geometry></visual></link></model>\n"
    "<model name='kitchen_floor'><link name='l'><visual name='v'><pose>2 1.5 -0.01 0 0 0</pose><geometry><box><size>4 3 0.02</size></box></geometry>"
    "</visual></link></model>\n"
    "<model name='Wall_3'><link name='l'><visual name='s'><pose>2 0 1.2 0 0 0</pose><geometry><box><size>4 0.1 2.4</size></box></geometry></visual></link></model>\n"
    "<model name='walls'><link name='l'><visual name='n'><pose>2 3 1.2 0 0 0</pose><geometry><box><size>4 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='w'><pose>0 1.5 1.2 0 0 0</pose><geometry><box><size>0.1 3 2.4</size></box></geometry></visual>\n"
    "<visual name='e'><pose>4 1.5 1.2 0 0 0</pose><geometry><box><size>0.1 3 2.4</size></box></geometry></visual></link></model>\n"
    "<model name='ceiling'><link name='l'><visual name='v'><pose>2 1.5 2.41 0 0 0</pose><geometry><box><size>4 3 0.02</size></box></geometry></visual></link></model>\n"
    "<model name='floor_lamp'><pose>0.5 0.5 0 0 0 0</pose><link name='l'><visual name='v'><pose>0 0 0.8 0 0 0</pose>"
    "<geometry><cylinder><radius>0.1</radius><length>1.6</length></cylinder></geometry></visual></link></model>\n"
    "<model name='FloorLamp_01'><pose>3.5 0.5 0 0 0 0</pose><link name='l'><visual name='v'><pose>0 0 0.8 0 0 0</pose>"
    "<geometry><cylinder><radius>0.1</radius><length>1.6</length></cylinder></geometry></visual></link></model>\n"
    "<model name='wall_clock'><pose>2 2.9 1.8 0 0 0</pose><link name='l'><visual name='v'>"
    "<geometry><box><size>0.3 0.05 0.3</size></box></geometry></visual></link></model>\n"
    "<model name='ceiling_fan'><pose>2 1.5 2.2 0 0 0</pose><link name='l'><visual name='v'>"
    "<geometry><box><size>0.8 0.8 0.05</size></box></geometry></visual></link></model>\n"
    "<include><uri>model://wall_shelf</uri><name>wall_shelf_2</name><pose>0.2 2 1.2 0 0 0</pose></include>\n"
    "<include><uri>model://aws_robomaker_retail_RetailShopFloor_01</uri><name>RetailShopFloor_01_001</name></include>\n"
    "</world></sdf>\n";

static void put_model(const char *dir, const char *name, const char *box)
{
    char p[1400], cmd[1500];
    snprintf(p, sizeof p, "%s/models/%s", dir, name);
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", p);
    if (system(cmd) != 0) fprintf(stderr, "mkdir failed\n");
    snprintf(p, sizeof p, "%s/models/%s/model.sdf", dir, name);
    FILE *f = fopen(p, "w");
    fprintf(f, "<sdf version='1.6'><model name='%s'><link name='l'><visual name='v'><geometry><box><size>%s</size>"
               "</box></geometry></visual></link></model></sdf>\n", name, box);
    fclose(f);
}

static int in_list(const cJSON *arr, const char *name)
{
    const cJSON *it;
    cJSON_ArrayForEach(it, arr)
    {
        const cJSON *n = cJSON_GetObjectItem(it, "name");
        if (cJSON_IsString(n) && !strcmp(n->valuestring, name)) return 1;
    }
    return 0;
}

static void test_structure_names(void)
{
    const char *d = test_tmpdir("synth_capture_furniture");
    char path[1400], mp[1400], out[1400];
    snprintf(path, sizeof path, "%s/furniture.world", d);
    FILE *f = fopen(path, "w");
    fputs(furniture_world, f);
    fclose(f);
    put_model(d, "wall_shelf", "0.3 0.8 0.05");
    put_model(d, "aws_robomaker_retail_RetailShopFloor_01", "4 3 0.01");
    snprintf(mp, sizeof mp, "%s/models", d);
    sp_world w;
    sp_error err = {0};
    sp_synth_load_opts lo = {.model_path = mp, .no_env = 1};
    CHECK_OK(sp_synth_load_world(path, &lo, &w, &err), &err);
    if (err.code) return;
    snprintf(out, sizeof out, "%s/cap", d);
    sp_synth_capture_opts o = {.n_views = 2, .width = 32, .height = 24, .fov_deg = 70, .n_points = 100,
                               .seed = 3, .n_threads = 1};
    CHECK_OK(sp_synth_capture(&w, out, &o, &err), &err);
    cJSON *gt = NULL;
    snprintf(path, sizeof path, "%s/ground_truth.json", out);
    CHECK_OK(sp_json_read_file(path, &gt, &err), &err);
    const cJSON *objs = cJSON_GetObjectItem(gt, "objects"), *st = cJSON_GetObjectItem(gt, "structure");
    const char *objects[] = {"floor_lamp", "FloorLamp_01", "wall_clock", "ceiling_fan", "wall_shelf_2"};
    const char *structure[] = {"ground_plane", "kitchen_floor", "Wall_3", "walls", "ceiling",
                               "RetailShopFloor_01_001"};
    for (size_t i = 0; i < sizeof objects / sizeof *objects; i++)
        CHECK_MSG(in_list(objs, objects[i]) && !in_list(st, objects[i]),
                  "%s is not among ground_truth.json's objects", objects[i]);
    for (size_t i = 0; i < sizeof structure / sizeof *structure; i++)
        CHECK_MSG(in_list(st, structure[i]) && !in_list(objs, structure[i]),
                  "%s is not among ground_truth.json's structure", structure[i]);
    CHECK(cJSON_GetArraySize(objs) == 5 && cJSON_GetArraySize(st) == 6);
    cJSON_Delete(gt);
    sp_world_free(&w);
}

static void test_bad_options(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_camera *cams = NULL;
    size_t n = 0;
    sp_synth_capture_opts o = {.n_views = 0, .width = 64, .height = 48};
    CHECK_FAILS(sp_synth_plan_views(&w, &o, &cams, &n, &err), SP_E_ARG, &err, "0 views");
    o.n_views = 3;
    o.fov_deg = 175;
    CHECK_FAILS(sp_synth_plan_views(&w, &o, &cams, &n, &err), SP_E_ARG, &err, "fov 175");
    sp_world_free(&w);
}

int main(void)
{
    RUN(test_capture);
    RUN(test_bad_options);
    RUN(test_structure_names);
    return TEST_EXIT();
}
