/* synth rasterizer: depth against ray-box intersection in double precision, labels against the
 * ground-truth boxes, near-plane clipping, and bytes independent of the thread count. */
#include "semsplat/io.h"
#include "semsplat/synth.h"
#include "test.h"

typedef struct { double mn[3], mx[3]; } abox;

/* Ray-AABB (slab) intersection; returns the entry distance or -1. */
static double ray_box(const double o[3], const double d[3], const abox *b)
{
    double t0 = -1e30, t1 = 1e30;
    for (int k = 0; k < 3; k++) {
        if (fabs(d[k]) < 1e-15) {
            if (o[k] < b->mn[k] || o[k] > b->mx[k]) return -1;
            continue;
        }
        double a = (b->mn[k] - o[k]) / d[k], c = (b->mx[k] - o[k]) / d[k];
        if (a > c) { double t = a; a = c; c = t; }
        if (a > t0) t0 = a;
        if (c < t1) t1 = c;
    }
    return t0 <= t1 && t0 > 0 ? t0 : -1;
}

static const char *boxes_world =
    "<sdf version='1.6'><world name='boxes'>\n"
    "<model name='red_box'><pose>2 0 0.5 0 0 0</pose><link name='l'><visual name='v'><geometry><box><size>1 1 1</size></box></geometry>"
    "<material><diffuse>0.8 0.1 0.1 1</diffuse></material></visual></link></model>\n"
    "<model name='tall_box'><pose>3.5 1.2 1 0 0 0</pose><link name='l'><visual name='v'><geometry><box><size>0.6 0.8 2</size></box></geometry></visual></link></model>\n"
    "<model name='flat_box'><pose>1.5 -1.5 0.1 0 0 0</pose><link name='l'><visual name='v'><geometry><box><size>1.2 0.7 0.2</size></box></geometry></visual></link></model>\n"
    "<model name='floor'><pose>2 0 -0.05 0 0 0</pose><link name='l'><visual name='v'><geometry><box><size>8 8 0.1</size></box></geometry></visual></link></model>\n"
    "</world></sdf>\n";

static int load(sp_world *w, sp_error *err)
{
    const char *d = test_tmpdir("synth_render");
    char path[1200];
    snprintf(path, sizeof path, "%s/boxes.world", d);
    FILE *f = fopen(path, "w");
    fputs(boxes_world, f);
    fclose(f);
    sp_synth_load_opts o = {.no_env = 1};
    return sp_synth_load_world(path, &o, w, err);
}

static void make_cam(sp_camera *c, int W, int H, float ex, float ey, float ez, float tx, float ty, float tz)
{
    memset(c, 0, sizeof *c);
    c->width = W;
    c->height = H;
    c->fx = c->fy = 0.6f * W;
    c->cx = 0.5f * W + 0.3f; /* off-centre principal point on purpose */
    c->cy = 0.5f * H - 0.2f;
    sp_camera_look_at(c, sp_v3(ex, ey, ez), sp_v3(tx, ty, tz), sp_v3(0, 0, 1));
}

static void test_depth_and_labels(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    abox boxes[4];
    for (size_t i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) {
            boxes[i].mn[k] = w.objects[i].aabb_min[k];
            boxes[i].mx[k] = w.objects[i].aabb_max[k];
        }
    sp_camera cams[3];
    make_cam(&cams[0], 96, 72, -1.0f, -0.6f, 1.3f, 2.2f, 0.1f, 0.4f);
    make_cam(&cams[1], 80, 64, 4.8f, -2.5f, 0.7f, 2.0f, 0.3f, 0.5f);
    make_cam(&cams[2], 64, 64, 2.0f, 0.0f, 3.0f, 2.1f, 0.05f, 0.0f); /* from above */
    long compared = 0, label_ok = 0, label_n = 0;
    double worst = 0;
    for (int v = 0; v < 3; v++) {
        const sp_camera *c = &cams[v];
        sp_synth_frame fr = {0};
        CHECK_OK(sp_synth_render(&w, c, NULL, NULL, &fr, &err), &err);
        if (!fr.depth) continue;
        double R[9], t[3];
        for (int i = 0; i < 9; i++) R[i] = c->R[i];
        for (int i = 0; i < 3; i++) t[i] = c->t[i];
        double o[3];
        for (int r = 0; r < 3; r++) o[r] = -(R[r] * t[0] + R[3 + r] * t[1] + R[6 + r] * t[2]);
        for (int py = 1; py < c->height - 1; py++)
            for (int px = 1; px < c->width - 1; px++) {
                double xc = (px + 0.5 - c->cx) / c->fx, yc = (py + 0.5 - c->cy) / c->fy;
                double d[3];
                for (int r = 0; r < 3; r++) d[r] = R[r] * xc + R[3 + r] * yc + R[6 + r];
                /* nearest box along the ray, distance in units of camera z (d has z_cam = 1) */
                double best = -1;
                int bi = -1;
                for (int b = 0; b < 4; b++) {
                    double tt = ray_box(o, d, &boxes[b]);
                    if (tt > 0 && (best < 0 || tt < best)) { best = tt; bi = b; }
                }
                size_t at = (size_t)py * c->width + px;
                /* away from edges: the 3x3 neighbourhood has one label */
                int same = 1;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++)
                        same &= fr.labels[at + dy * c->width + dx] == fr.labels[at];
                if (!same) continue;
                label_n++;
                label_ok += (bi < 0 && fr.labels[at] == 0) || (bi >= 0 && fr.labels[at] == bi + 1);
                if (bi < 0 || fr.labels[at] != bi + 1) continue;
                double e = fabs(fr.depth[at] - best);
                if (e > worst) worst = e;
                compared++;
            }
        sp_synth_frame_free(&fr);
    }
    CHECK(compared > 5000);
    CHECK_MSG(worst < 1e-4, "worst depth error %.3g m over %ld pixels", worst, compared);
    CHECK_MSG(label_ok == label_n, "%ld of %ld interior labels agree with ray casting", label_ok, label_n);
    sp_world_free(&w);
}

/* Every labelled pixel lies inside its object's ground-truth box projected into the view. */
static void test_labels_inside_gt_boxes(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_camera c;
    make_cam(&c, 120, 90, -0.5f, 1.8f, 1.6f, 2.5f, -0.2f, 0.3f);
    sp_synth_frame fr = {0};
    CHECK_OK(sp_synth_render(&w, &c, NULL, NULL, &fr, &err), &err);
    for (size_t o = 0; o < w.n_objects && fr.labels; o++) {
        const sp_synth_object *ob = &w.objects[o];
        float umin = 1e9f, umax = -1e9f, vmin = 1e9f, vmax = -1e9f;
        int behind = 0;
        for (int i = 0; i < 8; i++) {
            float p[3] = {(i & 1) ? ob->aabb_max[0] : ob->aabb_min[0], (i & 2) ? ob->aabb_max[1] : ob->aabb_min[1],
                          (i & 4) ? ob->aabb_max[2] : ob->aabb_min[2]}, q[3];
            for (int r = 0; r < 3; r++) q[r] = c.R[r * 3] * p[0] + c.R[r * 3 + 1] * p[1] + c.R[r * 3 + 2] * p[2] + c.t[r];
            if (q[2] <= 0.01f) { behind = 1; continue; }
            float u = c.fx * q[0] / q[2] + c.cx, v = c.fy * q[1] / q[2] + c.cy;
            umin = fminf(umin, u); umax = fmaxf(umax, u); vmin = fminf(vmin, v); vmax = fmaxf(vmax, v);
        }
        if (behind) continue;
        long n = 0, outside = 0;
        for (int py = 0; py < c.height; py++)
            for (int px = 0; px < c.width; px++)
                if (fr.labels[(size_t)py * c.width + px] == o + 1) {
                    n++;
                    outside += px + 1 < umin || px > umax || py + 1 < vmin || py > vmax;
                }
        CHECK_MSG(outside == 0, "object %s: %ld of %ld pixels outside its projected box", ob->name, outside, n);
        if (strcmp(ob->name, "floor")) CHECK_MSG(n > 20, "object %s covers %ld pixels", ob->name, n);
    }
    sp_synth_frame_free(&fr);
    sp_world_free(&w);
}

static void test_threads_and_clipping(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_pool *pool = NULL;
    CHECK_OK(sp_pool_create(&pool, 3, &err), &err);
    sp_camera c;
    /* inside the red box's corner region: triangles cross the near plane */
    make_cam(&c, 73, 51, 1.45f, -0.52f, 0.3f, 3.0f, 0.5f, 0.6f);
    sp_synth_render_opts ro = {.supersample = 3};
    sp_synth_frame a = {0}, b = {0};
    CHECK_OK(sp_synth_render(&w, &c, &ro, NULL, &a, &err), &err);
    CHECK_OK(sp_synth_render(&w, &c, &ro, pool, &b, &err), &err);
    size_t np = (size_t)c.width * c.height;
    CHECK(a.rgb && b.rgb && !memcmp(a.rgb, b.rgb, np * 3 * sizeof(float)));
    CHECK(a.depth && b.depth && !memcmp(a.depth, b.depth, np * sizeof(float)));
    CHECK(a.labels && b.labels && !memcmp(a.labels, b.labels, np * sizeof(uint16_t)));
    long finite = 0;
    for (size_t i = 0; a.depth && i < np; i++) finite += isfinite(a.depth[i]) && a.depth[i] >= 0;
    CHECK(finite == (long)np);
    /* a reused frame of the wrong size is refused */
    sp_camera small = c;
    small.width = 10;
    CHECK_FAILS(sp_synth_render(&w, &small, &ro, pool, &a, &err), SP_E_ARG, &err, "frame is 73x51");
    ro.supersample = 9;
    CHECK_FAILS(sp_synth_render(&w, &c, &ro, pool, &a, &err), SP_E_ARG, &err, "supersample 9");
    sp_synth_frame_free(&a);
    sp_synth_frame_free(&b);
    sp_pool_free(pool);
    sp_world_free(&w);
}

/* The camera blur softens colours only: depth and labels are the same with and without it,
 * edges get smaller pixel-to-pixel jumps, the mean colour stays, and a blur beyond 4 px is
 * refused. */
static void test_camera_blur(void)
{
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load(&w, &err), &err);
    if (err.code) return;
    sp_camera c;
    make_cam(&c, 96, 72, 0.2f, -2.5f, 1.0f, 0.0f, 0.0f, 0.0f);
    sp_synth_render_opts sharp = {.psf_px = -1.f}, soft = {0};
    sp_synth_frame a = {0}, b = {0};
    CHECK_OK(sp_synth_render(&w, &c, &sharp, NULL, &a, &err), &err);
    CHECK_OK(sp_synth_render(&w, &c, &soft, NULL, &b, &err), &err);
    if (!a.rgb || !b.rgb) return;
    size_t np = (size_t)c.width * c.height;
    CHECK(!memcmp(a.depth, b.depth, np * sizeof(float)));
    CHECK(!memcmp(a.labels, b.labels, np * sizeof(uint16_t)));
    double jump_a = 0, jump_b = 0, mean_a = 0, mean_b = 0;
    for (int y = 0; y < c.height; y++)
        for (int x = 0; x + 1 < c.width; x++)
            for (int k = 0; k < 3; k++) {
                size_t i = ((size_t)y * c.width + x) * 3 + k;
                jump_a = fmax(jump_a, fabs(a.rgb[i + 3] - a.rgb[i]));
                jump_b = fmax(jump_b, fabs(b.rgb[i + 3] - b.rgb[i]));
                mean_a += a.rgb[i];
                mean_b += b.rgb[i];
            }
    fprintf(stderr, "    largest neighbour jump: sharp %.3f, blurred %.3f; mean %.4f vs %.4f\n",
            jump_a, jump_b, mean_a / (double)np, mean_b / (double)np);
    CHECK(jump_a > 0.2);
    CHECK(jump_b < 0.8 * jump_a);
    CHECK(fabs(mean_a - mean_b) / (double)np < 2e-3);
    sp_synth_render_opts bad = {.psf_px = 5.f};
    CHECK_FAILS(sp_synth_render(&w, &c, &bad, NULL, &a, &err), SP_E_ARG, &err, "camera blur 5");
    sp_synth_frame_free(&a);
    sp_synth_frame_free(&b);
    sp_world_free(&w);
}

static void put(const char *dir, const char *name, const char *text)
{
    char p[1400];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    FILE *f = fopen(p, "w");
    fputs(text, f);
    fclose(f);
}

/* A textured .obj quad: each quadrant of the texture lands where its UVs say (and the right way
 * up: v = 0 at the image bottom). */
static void test_textured_mesh(void)
{
    const char *d = test_tmpdir("synth_texture");
    static const uint8_t quad_rgb[4][3] = {{230, 20, 20}, {20, 230, 20}, {20, 20, 230}, {230, 230, 230}};
    uint8_t tex[4 * 4 * 3];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++)
            memcpy(&tex[(y * 4 + x) * 3], quad_rgb[(y / 2) * 2 + x / 2], 3); /* TL red, TR green, BL blue, BR white */
    sp_image img = {.width = 4, .height = 4, .channels = 3, .bit_depth = 8, .data = tex};
    sp_error err = {0};
    char p[1400];
    snprintf(p, sizeof p, "%s/tex.png", d);
    CHECK_OK(sp_image_write_png(p, &img, &err), &err);
    put(d, "quad.obj", "mtllib quad.mtl\nv 0 -1 -1\nv 0 1 -1\nv 0 1 1\nv 0 -1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                       "usemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    put(d, "quad.mtl", "newmtl m\nKd 1 1 1\nmap_Kd tex.png\n");
    put(d, "t.world", "<sdf version='1.6'><world name='t'><model name='poster'><pose>0 0 1 0 0 0</pose><link name='l'>"
                      "<visual name='v'><geometry><mesh><uri>quad.obj</uri></mesh></geometry></visual></link></model></world></sdf>");
    snprintf(p, sizeof p, "%s/t.world", d);
    sp_world w;
    sp_synth_load_opts o = {.no_env = 1};
    CHECK_OK(sp_synth_load_world(p, &o, &w, &err), &err);
    if (err.code) return;
    CHECK(w.n_textures == 1 && w.textures[0].n_levels == 3);
    sp_camera c;
    make_cam(&c, 64, 64, -2.5f, 0, 1, 0, 0, 1);
    sp_synth_frame fr = {0};
    CHECK_OK(sp_synth_render(&w, &c, NULL, NULL, &fr, &err), &err);
    for (int qy = 0; qy < 2 && fr.rgb; qy++)
        for (int qx = 0; qx < 2; qx++) {
            /* world point at the centre of texture quadrant (qx, qy): u = (y + 1) / 2, v = (z_local + 1) / 2 */
            float u = 0.25f + 0.5f * qx, v = 0.75f - 0.5f * qy;
            float P[3] = {0, 2 * u - 1, 2 * v - 1 + 1}, Q[3];
            for (int r = 0; r < 3; r++) Q[r] = c.R[r * 3] * P[0] + c.R[r * 3 + 1] * P[1] + c.R[r * 3 + 2] * P[2] + c.t[r];
            int px = (int)(c.fx * Q[0] / Q[2] + c.cx), py = (int)(c.fy * Q[1] / Q[2] + c.cy);
            const float *pix = &fr.rgb[((size_t)py * 64 + px) * 3];
            const uint8_t *want = quad_rgb[qy * 2 + qx];
            for (int k = 0; k < 3; k++)
                for (int k2 = 0; k2 < 3; k2++)
                    if (want[k] > 200 && want[k2] < 50)
                        CHECK_MSG(pix[k] > 2.5f * pix[k2], "quadrant %d,%d pixel %d,%d = %.2f %.2f %.2f", qx, qy, px, py,
                                  pix[0], pix[1], pix[2]);
        }
    sp_synth_frame_free(&fr);
    sp_world_free(&w);
    sp_world_free(&w);
}

static void keep_warnings(void *user, sp_log_level level, const char *msg)
{
    if (level >= SP_LOG_WARN) snprintf(user, 1024, "%s", msg);
}

/* A missing texture does not stop the world from loading (Gazebo draws such a mesh in its
 * material colour and warns): the mesh is drawn in its material's diffuse colour, a warning
 * names the texture, with or without skip_missing. */
static void test_missing_texture_uses_colour(void)
{
    const char *d = test_tmpdir("synth_texture_missing");
    put(d, "quad.obj", "mtllib quad.mtl\nv 0 -1 -1\nv 0 1 -1\nv 0 1 1\nv 0 -1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                       "usemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    put(d, "quad.mtl", "newmtl m\nKd 0.1 0.8 0.1\nmap_Kd missing.png\n");
    put(d, "t.world", "<sdf version='1.6'><world name='t'><model name='poster'><pose>0 0 1 0 0 0</pose><link name='l'>"
                      "<visual name='v'><geometry><mesh><uri>quad.obj</uri></mesh></geometry></visual></link></model></world></sdf>");
    char p[1400], warned[1024] = "";
    snprintf(p, sizeof p, "%s/t.world", d);
    sp_log log = {keep_warnings, warned, SP_LOG_WARN, -1};
    sp_world w;
    sp_error err = {0};
    for (int skip = 0; skip < 2; skip++) {
        sp_synth_load_opts o = {.no_env = 1, .skip_missing = skip, .log = &log};
        warned[0] = 0;
        CHECK_OK(sp_synth_load_world(p, &o, &w, &err), &err);
        if (err.code) return;
        CHECK_MSG(strstr(warned, "missing.png") != NULL, "warning '%s'", warned);
        CHECK(w.n_textures == 0 && w.n_triangles == 2 && w.n_missing == 0 && w.n_missing_textures == 1);
        sp_camera c;
        make_cam(&c, 32, 32, -2.5f, 0, 1, 0, 0, 1);
        sp_synth_render_opts ro = {.no_detail = 1};
        sp_synth_frame fr = {0};
        CHECK_OK(sp_synth_render(&w, &c, &ro, NULL, &fr, &err), &err);
        if (fr.rgb) {
            const float *pix = &fr.rgb[((size_t)16 * 32 + 16) * 3];
            CHECK_MSG(pix[1] > 3 * pix[0] && pix[1] > 3 * pix[2], "centre %.3f %.3f %.3f: not the material's green",
                      pix[0], pix[1], pix[2]);
        }
        sp_synth_frame_free(&fr);
        sp_world_free(&w);
    }
}

/* A spot light inside a model's link lights its cone and nothing outside it. */
static void test_spot_light_in_link(void)
{
    const char *d = test_tmpdir("synth_spot");
    put(d, "s.world", "<sdf version='1.6'><world name='s'><scene><ambient>0.2 0.2 0.2 1</ambient></scene>"
                      "<model name='floor'><link name='l'><visual name='v'><geometry><plane><size>10 10</size></plane></geometry>"
                      "<material><diffuse>0.5 0.5 0.5 1</diffuse></material></visual></link></model>"
                      "<model name='lamp'><pose>1 0 2 0 0 0</pose><link name='l'><light name='spot' type='spot'>"
                      "<direction>0 0 -1</direction><diffuse>1 1 1 1</diffuse><spot><inner_angle>0.2</inner_angle>"
                      "<outer_angle>0.3</outer_angle><falloff>1</falloff></spot></light></link></model></world></sdf>");
    char p[1400];
    snprintf(p, sizeof p, "%s/s.world", d);
    sp_world w;
    sp_error err = {0};
    sp_synth_load_opts o = {.no_env = 1};
    CHECK_OK(sp_synth_load_world(p, &o, &w, &err), &err);
    if (err.code) return;
    CHECK(w.n_lights == 1 && w.lights[0].type == SP_LIGHT_SPOT);
    CHECK_NEAR(w.lights[0].position[0], 1, 1e-6);
    CHECK_NEAR(w.lights[0].position[2], 2, 1e-6);
    sp_camera c;
    make_cam(&c, 64, 64, 1.001f, 0.0f, 4.0f, 1.0f, 0.0f, 0.0f); /* looking straight down at the spot */
    sp_synth_render_opts ro = {.no_detail = 1};
    sp_synth_frame fr = {0};
    CHECK_OK(sp_synth_render(&w, &c, &ro, NULL, &fr, &err), &err);
    if (fr.rgb) {
        float centre = fr.rgb[((size_t)32 * 64 + 32) * 3], corner = fr.rgb[((size_t)2 * 64 + 2) * 3];
        CHECK_MSG(centre > 2.5f * corner, "spot centre %.3f, outside %.3f", centre, corner);
    }
    sp_synth_frame_free(&fr);
    sp_world_free(&w);
}

int main(void)
{
    RUN(test_spot_light_in_link);
    RUN(test_textured_mesh);
    RUN(test_missing_texture_uses_colour);
    RUN(test_depth_and_labels);
    RUN(test_labels_inside_gt_boxes);
    RUN(test_threads_and_clipping);
    RUN(test_camera_blur);
    return TEST_EXIT();
}
