/* The per-Gaussian projection backward (sp_gm_project_vjp, shared by both backends) against
 * central finite differences of the independent double-precision projection in render_ref.h, on
 * the shapes where the gradient is ill-conditioned: nearly round Gaussians (whose rotation
 * gradient is proportional to the tiny differences of their scales), exactly round ones (zero),
 * flat discs seen face-on and edge-on, needles, and Gaussians near the camera. Every entry must
 * be within 1e-3 of the double result, relative to the entry (with a floor of 1e-6 of the
 * Gaussian's largest gradient), which the route through the 3D covariance gradient missed by
 * orders of magnitude on nearly round Gaussians. */
#include "render/gauss_math.h"
#include "render_ref.h"
#include "test.h"

typedef struct {
    double mean[3], quat[4], log_scale[3], logit;
} gparams;

typedef struct {
    double v_mean2d[2], v_conic[3], v_depth, v_opacity;
} upstream;

static sp_camera make_camera(void)
{
    sp_camera c;
    memset(&c, 0, sizeof c);
    c.width = 640;
    c.height = 480;
    c.fx = c.fy = 500.f;
    c.cx = 320.f;
    c.cy = 240.f;
    /* a slightly tilted camera so no axis is aligned with the world's */
    double a = 0.3, b = -0.2;
    double R[9] = {cos(a), 0, sin(a), sin(a) * sin(b), cos(b), -cos(a) * sin(b),
                   -sin(a) * cos(b), sin(b), cos(a) * cos(b)};
    for (int k = 0; k < 9; k++) c.R[k] = (float)R[k];
    c.t[0] = 0.1f;
    c.t[1] = -0.05f;
    c.t[2] = 0.2f;
    return c;
}

/* The scalar the finite differences differentiate: <upstream, projection outputs>. The vjp's
 * v_conic uses the element convention, so the conic's off-diagonal b weighs 2 v_conic[1]. */
static double loss(const gparams *g, const upstream *u, const sp_camera *cam,
                   const sp_raster_cfg *cfg, int *visible)
{
    double means[3], quats[4], ls[3], logit = g->logit, col = 0;
    memcpy(means, g->mean, sizeof means);
    memcpy(quats, g->quat, sizeof quats);
    memcpy(ls, g->log_scale, sizeof ls);
    ref_scene s = {1, 1, means, quats, ls, &logit, &col, NULL, NULL};
    ref_proj p;
    ref_project(&s, 0, cam, cfg, &p);
    *visible = p.visible;
    return u->v_mean2d[0] * p.mean2d[0] + u->v_mean2d[1] * p.mean2d[1] +
           u->v_conic[0] * p.conic[0] + 2.0 * u->v_conic[1] * p.conic[1] +
           u->v_conic[2] * p.conic[2] + u->v_depth * p.depth + u->v_opacity * p.opacity;
}

/* The vjp takes the conic gradient in the conic's principal frame, as the rasterizer sums it:
 * G' = Q G Q^T for the frame Q of the conic the forward computed. */
static void conic_gradient_in_frame(const float m[3], const float q[4], const float l[3],
                                    float logit, const sp_camera *cam, const sp_raster_cfg *cfg,
                                    const upstream *u, float vc[3])
{
    float m2[2], conic[3] = {0, 0, 0}, depth, op, cs, sn;
    int radius;
    sp_gm_project(m, q, l, logit, cam, cfg, m2, conic, &depth, &op, &radius);
    sp_gm_conic_frame(conic, &cs, &sn);
    float g[3] = {(float)u->v_conic[0], (float)u->v_conic[1], (float)u->v_conic[2]};
    sp_gm_to_frame(g, cs, sn, vc);
}

/* Checks one Gaussian: returns the worst relative error over its 11 parameters. */
static double check_one(const char *what, const gparams *g, const upstream *u,
                        const sp_camera *cam, const sp_raster_cfg *cfg)
{
    float m[3], q[4], l[3];
    for (int k = 0; k < 3; k++) m[k] = (float)g->mean[k], l[k] = (float)g->log_scale[k];
    for (int k = 0; k < 4; k++) q[k] = (float)g->quat[k];
    /* differentiate the float parameters exactly as the vjp sees them */
    gparams gf = *g;
    for (int k = 0; k < 3; k++) gf.mean[k] = m[k], gf.log_scale[k] = l[k];
    for (int k = 0; k < 4; k++) gf.quat[k] = q[k];
    gf.logit = (float)g->logit;
    float v2[2] = {(float)u->v_mean2d[0], (float)u->v_mean2d[1]};
    float vc[3];
    conic_gradient_in_frame(m, q, l, (float)gf.logit, cam, cfg, u, vc);
    float vm[3] = {0}, vq[4] = {0}, vs[3] = {0}, vo = 0;
    sp_gm_project_vjp(m, q, l, (float)gf.logit, cam, cfg, v2, vc, (float)u->v_depth,
                      (float)u->v_opacity, vm, vq, vs, &vo);
    double an[11] = {vm[0], vm[1], vm[2], vq[0], vq[1], vq[2], vq[3], vs[0], vs[1], vs[2], vo};
    double *par[11] = {&gf.mean[0], &gf.mean[1], &gf.mean[2], &gf.quat[0], &gf.quat[1],
                       &gf.quat[2], &gf.quat[3], &gf.log_scale[0], &gf.log_scale[1],
                       &gf.log_scale[2], &gf.logit};
    double fd[11], gmax = 0;
    for (int k = 0; k < 11; k++) {
        double keep = *par[k], h = 1e-6 * fmax(1.0, fabs(keep));
        int vp, vmn;
        *par[k] = keep + h;
        double lp = loss(&gf, u, cam, cfg, &vp);
        *par[k] = keep - h;
        double lm = loss(&gf, u, cam, cfg, &vmn);
        *par[k] = keep;
        CHECK_MSG(vp && vmn, "%s: not visible", what);
        fd[k] = (lp - lm) / (2 * h);
        gmax = fmax(gmax, fabs(fd[k]));
    }
    double worst = 0;
    int wk = 0;
    for (int k = 0; k < 11; k++) {
        double rel = fabs(an[k] - fd[k]) / fmax(fabs(fd[k]), 1e-6 * gmax + 1e-30);
        if (rel > worst) worst = rel, wk = k;
    }
    fprintf(stderr, "    %-34s worst rel err %.2e (param %d: %.7g vs fd %.7g)\n", what, worst, wk,
            an[wk], fd[wk]);
    return worst;
}

static void random_quat(test_rng *r, double q[4])
{
    double n = 0;
    for (int k = 0; k < 4; k++) q[k] = test_range(r, -1, 1), n += q[k] * q[k];
    for (int k = 0; k < 4; k++) q[k] *= 1.3 / sqrt(n); /* not unit: the normalisation is tested too */
}

static void random_upstream(test_rng *r, upstream *u)
{
    u->v_mean2d[0] = test_range(r, -1, 1);
    u->v_mean2d[1] = test_range(r, -1, 1);
    for (int k = 0; k < 3; k++) u->v_conic[k] = test_range(r, -50, 50);
    u->v_depth = test_range(r, -0.5, 0.5);
    u->v_opacity = test_range(r, -1, 1);
}

/* Places a Gaussian in front of the camera at depth z, near the image centre. */
static void place(test_rng *r, const sp_camera *cam, double z, double mean[3])
{
    double pc[3] = {test_range(r, -0.3, 0.3) * z, test_range(r, -0.2, 0.2) * z, z};
    for (int k = 0; k < 3; k++) pc[k] -= cam->t[k];
    for (int j = 0; j < 3; j++) /* world = Rc^T (pc - t) */
        mean[j] = cam->R[j] * pc[0] + cam->R[3 + j] * pc[1] + cam->R[6 + j] * pc[2];
}

static void run_shapes(int antialiased)
{
    sp_camera cam = make_camera();
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.antialiased = antialiased;
    test_rng r = {antialiased ? 77u : 11u};
    const struct {
        const char *name;
        double l[3]; /* log-scales */
        double z;
    } shapes[] = {
        {"random", {-3.0, -3.6, -2.5}, 2.0},
        {"nearly round (1e-5 apart)", {-3.0, -3.0 + 1e-5, -3.0 - 2e-5}, 2.0},
        {"nearly round, large", {-1.0, -1.0 + 3e-5, -1.0 + 1e-5}, 3.0},
        {"two axes equal", {-2.5, -2.5, -4.0}, 2.0},
        {"flat disc", {-2.0, -2.3, -9.0}, 2.0},
        {"needle", {-1.5, -7.0, -7.5}, 2.5},
        {"near the camera", {-4.0, -4.4, -3.8}, 0.05},
    };
    for (size_t i = 0; i < sizeof shapes / sizeof *shapes; i++)
        for (int trial = 0; trial < 4; trial++) {
            gparams g;
            place(&r, &cam, shapes[i].z, g.mean);
            random_quat(&r, g.quat);
            memcpy(g.log_scale, shapes[i].l, sizeof g.log_scale);
            g.logit = test_range(&r, -1, 2);
            upstream u;
            random_upstream(&r, &u);
            char what[64];
            snprintf(what, sizeof what, "%s #%d%s", shapes[i].name, trial, antialiased ? " (aa)" : "");
            double worst = check_one(what, &g, &u, &cam, &cfg);
            CHECK_MSG(worst < 1e-3, "%s: worst relative error %.3g", what, worst);
        }
}

static void test_shapes(void) { run_shapes(0); }
static void test_shapes_antialiased(void) { run_shapes(1); }

/* An exactly round Gaussian has no rotation gradient: the vjp must say exactly zero, not noise. */
static void test_round_has_zero_rotation_gradient(void)
{
    sp_camera cam = make_camera();
    sp_raster_cfg cfg = sp_raster_cfg_default();
    test_rng r = {5};
    for (int trial = 0; trial < 20; trial++) {
        gparams g;
        place(&r, &cam, 1.5, g.mean);
        random_quat(&r, g.quat);
        float m[3], q[4], l[3] = {-2.7f, -2.7f, -2.7f};
        for (int k = 0; k < 3; k++) m[k] = (float)g.mean[k];
        for (int k = 0; k < 4; k++) q[k] = (float)g.quat[k];
        upstream u;
        random_upstream(&r, &u);
        float v2[2] = {(float)u.v_mean2d[0], (float)u.v_mean2d[1]};
        float vc[3];
        conic_gradient_in_frame(m, q, l, 0.5f, &cam, &cfg, &u, vc);
        float vm[3] = {0}, vq[4] = {0}, vs[3] = {0}, vo = 0;
        sp_gm_project_vjp(m, q, l, 0.5f, &cam, &cfg, v2, vc, 0.f, 0.f, vm, vq, vs, &vo);
        CHECK(vq[0] == 0.f && vq[1] == 0.f && vq[2] == 0.f && vq[3] == 0.f);
        CHECK(vs[0] != 0.f);
    }
}

static void test_sinh(void)
{
    double worst = 0;
    for (int i = -4000; i <= 4000; i++) {
        float d = (float)i * 1e-3f;
        double ref = sinh((double)d);
        if (ref == 0) {
            CHECK(sp_gm_sinhf(d) == 0.f);
            continue;
        }
        worst = fmax(worst, fabs(sp_gm_sinhf(d) - ref) / fabs(ref));
    }
    float tiny = 1e-30f;
    CHECK(sp_gm_sinhf(tiny) == tiny);
    fprintf(stderr, "    sp_gm_sinhf: worst rel err %.2e on [-4, 4]\n", worst);
    CHECK(worst < 1e-6);
}

int main(void)
{
    RUN(test_sinh);
    RUN(test_shapes);
    RUN(test_shapes_antialiased);
    RUN(test_round_has_zero_rotation_gradient);
    return TEST_EXIT();
}
