/* Depth colour map (moved out of the CLI): near is red, far is blue, uncovered pixels black, and
 * the 2%..98% stretch keeps a few outliers from flattening the rest. */
#include "semsplat/render.h"
#include "test.h"

static void test_depth_colormap(void)
{
    enum { N = 200 };
    float depth[N], alpha[N], rgb[3 * N];
    for (int i = 0; i < N; i++) depth[i] = 1.0f + 0.01f * i, alpha[i] = 1.0f;
    depth[N - 1] = 1000.0f; /* an outlier */
    alpha[5] = 0.2f;        /* not covered */
    sp_error err = {0};
    CHECK_OK(sp_depth_colormap(depth, alpha, N, rgb, &err), &err);
    CHECK(rgb[0] > rgb[2] + 0.3f);                          /* nearest: red */
    CHECK(rgb[3 * 178 + 2] > rgb[3 * 178] + 0.3f);           /* far (below the outlier): blue */
    CHECK(rgb[15] == 0 && rgb[16] == 0 && rgb[17] == 0);    /* pixel 5: black */
    float mid[3];
    sp_turbo(0.5f, mid);
    CHECK(mid[1] > 0.8f); /* turbo's middle is green */
}

int main(void)
{
    RUN(test_depth_colormap);
    return TEST_EXIT();
}
