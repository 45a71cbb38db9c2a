/* The alpha rule both backends share (gauss_math.h): the scalar exp is accurate against libm in
 * double, and the CPU's four-lane version (render_internal.h) returns the same bits as the scalar
 * rule the CUDA kernels run, so a contribution kept on one backend is kept on the other. The
 * GPU side of the bargain is checked on the GPU machine (render/test_cuda_raster). */
#include <stdint.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"
#include "test.h"

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* Distance in units in the last place between float x and the double reference y. */
static double ulps(float x, double y)
{
    float yf = (float)y;
    double ulp = (double)nextafterf(fabsf(yf), INFINITY) - (double)fabsf(yf);
    return fabs((double)x - y) / ulp;
}

static void test_expf_accuracy(void)
{
    double worst = 0.0;
    float worst_x = 0.f;
    for (int i = 0; i <= 2000000; i++) {
        float x = -87.f + 175.f * (float)i / 2000000.f;
        double e = ulps(sp_gm_expf(x), exp((double)x));
        if (e > worst) worst = e, worst_x = x;
    }
    fprintf(stderr, "    sp_gm_expf: worst %.2f ulp at x = %.6g\n", worst, worst_x);
    CHECK(worst <= 2.0);
    CHECK(sp_gm_expf(0.f) == 1.f);
    CHECK(sp_gm_expf(-200.f) == sp_gm_expf(-87.f)); /* clamped, not 0 or junk */
    CHECK(isfinite(sp_gm_expf(200.f)));
    CHECK(isnan(sp_gm_expf(NAN)));
}

static void test_vector_exp_matches_scalar(void)
{
    size_t differ = 0;
    uint32_t s = 12345u;
    for (int i = 0; i < 1000000; i++) {
        cpu_v4f x;
        for (int k = 0; k < 4; k++) {
            s = s * 1664525u + 1013904223u;
            x[k] = -80.f * (float)(s >> 8) / 16777216.f;
        }
        cpu_v4f y = cpu_exp_neg4(x);
        for (int k = 0; k < 4; k++) differ += bits(y[k]) != bits(sp_gm_expf(x[k]));
    }
    CHECK_MSG(differ == 0, "%zu of 4M lanes differ", differ);
}

/* cpu_alpha4 with the per-row terms the rasterizer computes, against sp_gm_alpha_g per pixel,
 * on Gaussians near the 1/255 edge where a rounding difference would flip the decision. */
static void test_alpha4_matches_scalar(void)
{
    size_t differ = 0, kept = 0;
    uint32_t s = 777u;
#define RND() ((s = s * 1664525u + 1013904223u), (float)(s >> 8) / 16777216.f)
    for (int i = 0; i < 200000; i++) {
        float sx = 0.3f + 20.f * RND(), sy = 0.3f + 20.f * RND(), rho = 1.8f * RND() - 0.9f;
        float det = sx * sx * sy * sy * (1.f - rho * rho);
        float con[3] = {sy * sy / det, -rho * sx * sy / det, sx * sx / det};
        float op = 0.004f + 0.995f * RND();
        float mx = 100.f * RND(), my = 100.f * RND();
        float cut = sp_gm_sigma_cut(op);
        int px = (int)(mx + (RND() - 0.5f) * 8.f * sx), py = (int)(my + (RND() - 0.5f) * 8.f * sy);
        float dy = (float)py + 0.5f - my;
        float by, hy;
        sp_gm_row_terms(con, dy, &by, &hy);
        cpu_v4f g4;
        cpu_v4f dx = cpu_dx4(px, mx);
        cpu_v4f a4 = cpu_alpha4(cpu_v4_splat(0.5f * con[0]), cpu_v4_splat(by), cpu_v4_splat(hy),
                                cpu_v4_splat(op), cpu_v4_splat(cut), dx, &g4);
        for (int k = 0; k < 4; k++) {
            float g = 0.f, a = sp_gm_alpha_g(con, op, cut, (float)(px + k) + 0.5f - mx, dy, &g);
            differ += bits(a) != bits(a4[k]) || (a > 0.f && bits(g) != bits(g4[k]));
            kept += a > 0.f;
        }
    }
#undef RND
    fprintf(stderr, "    %zu of 800000 pixels kept\n", kept);
    CHECK(kept > 10000);
    CHECK_MSG(differ == 0, "%zu pixels differ", differ);
}

int main(void)
{
    RUN(test_expf_accuracy);
    RUN(test_vector_exp_matches_scalar);
    RUN(test_alpha4_matches_scalar);
    return TEST_EXIT();
}
