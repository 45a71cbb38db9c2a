/* Grids and exact distance transforms against a brute-force double-precision reference. */
#include "semsplat/core.h"
#include "test.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;
static double rnd(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

/* Nearest-seed distance by trying every seed (dims[2] == 1 for 2D). */
static double brute(const uint8_t *seed, const int *dims, int x, int y, int z, double res)
{
    double best = INFINITY;
    for (int k = 0; k < dims[2]; k++)
        for (int j = 0; j < dims[1]; j++)
            for (int i = 0; i < dims[0]; i++)
                if (seed[((size_t)k * dims[1] + j) * dims[0] + i]) {
                    double d = sqrt((double)(i - x) * (i - x) + (double)(j - y) * (j - y) +
                                    (double)(k - z) * (k - z));
                    if (d < best) best = d;
                }
    return best * res;
}

static int compare(const uint8_t *seed, const int *dims, const float *out, double res)
{
    int bad = 0;
    for (int k = 0; k < dims[2]; k++)
        for (int j = 0; j < dims[1]; j++)
            for (int i = 0; i < dims[0]; i++) {
                double ref = brute(seed, dims, i, j, k, res);
                float got = out[((size_t)k * dims[1] + j) * dims[0] + i];
                if (isinf(ref) ? !isinf(got) : fabs(got - ref) > 1e-5 * (1 + ref)) {
                    if (bad++ < 3)
                        fprintf(stderr, "cell (%d,%d,%d): %g, expected %g\n", i, j, k, (double)got, ref);
                }
            }
    return bad;
}

static void test_edt2_random(void)
{
    sp_error err = {0};
    sp_pool *pool = NULL;
    CHECK_OK(sp_pool_create(&pool, 2, &err), &err);
    const int sizes[][2] = {{1, 1}, {1, 17}, {23, 1}, {37, 29}, {64, 5}};
    const double dens[] = {0.002, 0.05, 0.5};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++)
        for (size_t d = 0; d < 3; d++) {
            int dims[3] = {sizes[s][0], sizes[s][1], 1};
            size_t n = (size_t)dims[0] * dims[1];
            uint8_t *seed = calloc(n, 1);
            float *out = malloc(n * sizeof *out);
            for (size_t i = 0; i < n; i++) seed[i] = rnd() < dens[d];
            CHECK_OK(sp_edt2(seed, dims[0], dims[1], 0.05f, out, d == 1 ? NULL : pool, &err), &err);
            CHECK_MSG(compare(seed, dims, out, 0.05) == 0, "2D %dx%d density %g", dims[0], dims[1], dens[d]);
            free(seed);
            free(out);
        }
    sp_pool_free(pool);
}

static void test_edt3_random(void)
{
    sp_error err = {0};
    sp_pool *pool = NULL;
    CHECK_OK(sp_pool_create(&pool, 2, &err), &err);
    int dims[3] = {13, 9, 7};
    size_t n = (size_t)dims[0] * dims[1] * dims[2];
    uint8_t *seed = calloc(n, 1);
    float *out = malloc(n * sizeof *out);
    for (size_t i = 0; i < n; i++) seed[i] = rnd() < 0.01;
    seed[n / 2] = 1;
    CHECK_OK(sp_edt3(seed, dims[0], dims[1], dims[2], 0.1f, out, pool, &err), &err);
    CHECK(compare(seed, dims, out, 0.1) == 0);
    free(seed);
    free(out);
    sp_pool_free(pool);
}

static void test_edt_edges(void)
{
    sp_error err = {0};
    uint8_t seed[12] = {0};
    float out[12];
    CHECK_OK(sp_edt2(seed, 4, 3, 1.0f, out, NULL, &err), &err);
    for (int i = 0; i < 12; i++) CHECK(isinf(out[i])); /* no seed: infinitely far */
    seed[0] = 1;
    CHECK_OK(sp_edt2(seed, 4, 3, 2.0f, out, NULL, &err), &err);
    CHECK_NEAR(out[0], 0.0, 0);
    CHECK_NEAR(out[11], 2.0 * sqrt(9.0 + 4.0), 1e-5); /* (3,2) from (0,0), 2 m cells */
    CHECK_FAILS(sp_edt2(seed, 0, 3, 1.0f, out, NULL, &err), SP_E_ARG, &err, "size");
    CHECK_FAILS(sp_edt2(seed, 4, 3, 0.0f, out, NULL, &err), SP_E_ARG, &err, "cell size");
    CHECK_FAILS(sp_edt2(seed, 4, 3, NAN, out, NULL, &err), SP_E_ARG, &err, "cell size");
    CHECK_FAILS(sp_edt3(seed, 1 << 16, 1 << 16, 4, 1.0f, out, NULL, &err), SP_E_NOMEM, &err, "too many");
}

static void test_grid_cells(void)
{
    sp_error err = {0};
    sp_grid2 g;
    CHECK_OK(sp_grid2_alloc(&g, 10, 5, 0.5f, -1.0f, 2.0f, &err), &err);
    int ix, iy;
    CHECK(sp_grid2_cell(&g, -1.0f, 2.0f, &ix, &iy) && ix == 0 && iy == 0);
    CHECK(sp_grid2_cell(&g, 3.99f, 4.49f, &ix, &iy) && ix == 9 && iy == 4);
    CHECK(!sp_grid2_cell(&g, 4.0f, 3.0f, &ix, &iy) && ix == 10);
    CHECK(!sp_grid2_cell(&g, -1e30f, NAN, &ix, &iy));
    float x, y;
    sp_grid2_center(&g, 2, 1, &x, &y);
    CHECK_NEAR(x, 0.25, 1e-6);
    CHECK_NEAR(y, 2.75, 1e-6);
    CHECK(g.data[49] == 0.0f);
    sp_grid2_free(&g);
    CHECK(g.data == NULL);
    CHECK_FAILS(sp_grid2_alloc(&g, 10, -5, 0.5f, 0, 0, &err), SP_E_ARG, &err, "size");
    sp_grid3 v;
    float o[3] = {0, 0, -1};
    CHECK_OK(sp_grid3_alloc(&v, 4, 4, 4, 0.25f, o, &err), &err);
    int idx[3];
    float p[3] = {0.3f, 0.9f, -0.1f};
    CHECK(sp_grid3_cell(&v, p, idx) && idx[0] == 1 && idx[1] == 3 && idx[2] == 3);
    sp_grid3_center(&v, idx, p);
    CHECK_NEAR(p[2], -0.125, 1e-6);
    sp_grid3_free(&v);
}

int main(void)
{
    RUN(test_edt2_random);
    RUN(test_edt3_random);
    RUN(test_edt_edges);
    RUN(test_grid_cells);
    return TEST_EXIT();
}
