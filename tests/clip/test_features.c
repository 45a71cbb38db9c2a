/* Feature folders end to end on a hand-built capture (COLMAP model, 16-bit label images,
 * labels.json as synth writes it, and .npy maps in both layouts): sp_features_extract, then
 * sp_features_open / load_map / decode must give back each pixel's class embedding. */
#include <stdint.h>

#include <cjson/cJSON.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "test.h"

enum { W = 64, H = 48, NI = 3 };
static char cap[1024];

static void make_capture(void)
{
    snprintf(cap, sizeof cap, "%s", test_tmpdir("clip_features"));
    char p[1400];
    sp_error err = {0};
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    sp_colmap_camera cam = {1, SP_COLMAP_PINHOLE, W, H, 4, {50, 50, W / 2.0, H / 2.0}};
    sp_colmap_image im[NI];
    char names[NI][32];
    memset(im, 0, sizeof im);
    for (int i = 0; i < NI; i++) {
        snprintf(names[i], sizeof names[i], "%05d.png", i);
        im[i].id = (uint32_t)i + 1;
        im[i].qvec[0] = 1;
        im[i].tvec[0] = i;
        im[i].camera_id = 1;
        im[i].name = names[i];
    }
    m.n_cameras = 1;
    m.cameras = &cam;
    m.n_images = NI;
    m.images = im;
    snprintf(p, sizeof p, "%s/sparse/0", cap);
    CHECK_OK(sp_mkdirs(p, &err), &err);
    CHECK_OK(sp_colmap_write_txt(p, &m, &err), &err);
    snprintf(p, sizeof p, "%s/labels", cap);
    sp_mkdirs(p, &err);
    /* three vertical bands per image: ids 0 (background), 1 (chair), 2/3 (two tables) */
    uint16_t lab[W * H];
    for (int i = 0; i < NI; i++) {
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) lab[y * W + x] = (uint16_t)(x < 16 ? 0 : x < 40 ? 1 : 2 + (i % 2));
        sp_image img = {W, H, 1, 16, lab};
        snprintf(p, sizeof p, "%s/labels/%05d.png", cap, i);
        CHECK_OK(sp_image_write_png(p, &img, &err), &err);
    }
    snprintf(p, sizeof p, "%s/labels.json", cap);
    FILE *f = fopen(p, "w");
    fputs("{\"format\": \"semsplat-labels-1\", \"background\": 0, \"labels\": {"
          "\"1\": {\"name\": \"chair_1\", \"class\": \"chair\", \"is_structure\": false},"
          "\"2\": {\"name\": \"table_1\", \"class\": \"table\", \"is_structure\": false},"
          "\"3\": {\"name\": \"table_2\", \"class\": \"table\", \"is_structure\": false}}}\n", f);
    fclose(f);
}

static void test_labels(void)
{
    char out[1400];
    snprintf(out, sizeof out, "%s/feat_labels", cap);
    sp_features_opts o = sp_features_opts_default();
    o.colmap_dir = cap;
    o.out_dir = out;
    o.source = "labels";
    o.dim = 16;
    sp_error err = {0};
    CHECK_OK(sp_features_extract(&o, &err), &err);
    sp_features f;
    CHECK_OK(sp_features_open(out, &f, &err), &err);
    CHECK(!strcmp(f.source, "labels") && !strcmp(f.label_embedding, "hash"));
    CHECK(f.dim == 16 && f.full_dim == 512 && f.n_images == NI);
    CHECK(f.images[0].w == W / 4 && f.images[0].h == H / 4 && f.images[0].image_w == W);
    CHECK(sp_features_find(&f, "00001.png") == 1 && sp_features_find(&f, "images/00002.jpg") == 2);
    CHECK_OK(sp_features_load_map(&f, 1, &err), &err);
    float chair[512], table[512], full[512];
    sp_label_embedding("chair", 512, chair);
    sp_label_embedding("table", 512, table);
    /* map cell (x=6, y=3) covers pixels 24..27: chair; x=12 -> table (ids 2 and 3 share it) */
    sp_features_decode(&f, f.images[1].map + (3 * f.images[1].w + 6) * f.dim, full);
    double e1 = 0, e2 = 0;
    for (int k = 0; k < 512; k++) e1 = fmax(e1, fabs(full[k] - chair[k]));
    sp_features_decode(&f, f.images[1].map + (3 * f.images[1].w + 12) * f.dim, full);
    for (int k = 0; k < 512; k++) e2 = fmax(e2, fabs(full[k] - table[k]));
    CHECK_MSG(e1 < 2e-3 && e2 < 2e-3, "decoded class features off by %g, %g", e1, e2);
    sp_features_free(&f);
    /* a bad dim and a missing labels folder are named */
    o.dim = 600;
    CHECK_FAILS(sp_features_extract(&o, &err), SP_E_ARG, &err, "dim");
    o.dim = 16;
    o.labels_dir = "/nonexistent/labels";
    CHECK(sp_features_extract(&o, &err) != 0);
    CHECK(strstr(err.msg, "/nonexistent/labels") != NULL);
}

static void test_npy(void)
{
    char maps[1400], out[1400], p[1600];
    snprintf(maps, sizeof maps, "%s/ext", cap);
    snprintf(out, sizeof out, "%s/feat_npy", cap);
    sp_error err = {0};
    sp_mkdirs(maps, &err);
    /* 20 channels, 12x16 maps; image 0 as [C][H][W], the others [H][W][C] */
    enum { C = 20, MH = 12, MW = 16 };
    static float a[MH * MW * C];
    for (int i = 0; i < NI; i++) {
        for (int y = 0; y < MH; y++)
            for (int x = 0; x < MW; x++)
                for (int c = 0; c < C; c++) {
                    float v = (float)((x + 2 * y + c * c + i) % 7) * 0.1f;
                    if (i == 0) a[(c * MH + y) * MW + x] = v;
                    else a[(y * MW + x) * C + c] = v;
                }
        size_t shp_chw[3] = {C, MH, MW}, shp_hwc[3] = {MH, MW, C};
        snprintf(p, sizeof p, "%s/%05d.npy", maps, i);
        CHECK_OK(sp_npy_write(p, SP_DTYPE_F32, 3, i == 0 ? shp_chw : shp_hwc, a, &err), &err);
    }
    sp_features_opts o = sp_features_opts_default();
    o.colmap_dir = cap;
    o.out_dir = out;
    o.source = "npy";
    o.maps_dir = maps;
    o.dim = C;
    CHECK_OK(sp_features_extract(&o, &err), &err);
    sp_features f;
    CHECK_OK(sp_features_open(out, &f, &err), &err);
    CHECK(f.full_dim == C && f.images[0].w == MW && f.images[0].h == MH);
    CHECK_OK(sp_features_load_all(&f, &err), &err);
    /* dim == C: lossless up to float16 */
    double worst = 0;
    for (int i = 0; i < NI; i++)
        for (int y = 0; y < MH; y++)
            for (int x = 0; x < MW; x++) {
                float full[C];
                sp_features_decode(&f, f.images[i].map + (y * MW + x) * C, full);
                for (int c = 0; c < C; c++)
                    worst = fmax(worst, fabs(full[c] - (float)((x + 2 * y + c * c + i) % 7) * 0.1f));
            }
    CHECK_MSG(worst < 5e-3, "npy round trip off by %g", worst);
    sp_features_free(&f);
    o.maps_dir = "/nonexistent/maps";
    CHECK(sp_features_extract(&o, &err) != 0);
    CHECK(strstr(err.msg, "00000.npy") != NULL);
}

/* The feature dimension has one limit for every stage (the query engine scores at most 64
 * dims): `features` refuses more at once, naming the value and the limit, and a folder that
 * claims more (made elsewhere) is refused when opened, so lift and distill never see it. */
static void test_dim_limit(void)
{
    char out[1400], p[1600];
    snprintf(out, sizeof out, "%s/feat_dim", cap);
    sp_features_opts o = sp_features_opts_default();
    o.colmap_dir = cap;
    o.out_dir = out;
    o.source = "labels";
    sp_error err = {0};
    o.dim = 65;
    CHECK_FAILS(sp_features_extract(&o, &err), SP_E_ARG, &err, "65");
    CHECK_MSG(strstr(err.msg, "limit of 64") != NULL, "message '%s' does not name the limit", err.msg);
    CHECK(!sp_file_exists(out)); /* refused before anything is written */
    o.dim = 64;
    CHECK_OK(sp_features_extract(&o, &err), &err);
    /* the same folder claiming 65 dims (features.json and a 65-row basis) */
    static float basis[65 * 512];
    for (int k = 0; k < 65; k++) basis[k * 512 + k] = 1.0f;
    size_t shape[2] = {65, 512};
    snprintf(p, sizeof p, "%s/pca_basis.npy", out);
    CHECK_OK(sp_npy_write(p, SP_DTYPE_F32, 2, shape, basis, &err), &err);
    cJSON *js = NULL;
    snprintf(p, sizeof p, "%s/features.json", out);
    CHECK_OK(sp_json_read_file(p, &js, &err), &err);
    cJSON_ReplaceItemInObject(js, "dim", cJSON_CreateNumber(65));
    CHECK_OK(sp_json_write_file(p, js, &err), &err);
    cJSON_Delete(js);
    sp_features f;
    memset(&f, 0, sizeof f);
    CHECK_FAILS(sp_features_open(out, &f, &err), SP_E_FORMAT, &err, "65");
    CHECK_MSG(strstr(err.msg, "limit of 64") != NULL, "message '%s' does not name the limit", err.msg);
    sp_features_free(&f);
}

static void test_open_errors(void)
{
    sp_features f;
    sp_error err = {0};
    CHECK(sp_features_open("/nonexistent/features", &f, &err) != 0);
    CHECK(strstr(err.msg, "features.json") != NULL);
}

int main(void)
{
    make_capture();
    RUN(test_labels);
    RUN(test_npy);
    RUN(test_open_errors);
    RUN(test_dim_limit);
    return TEST_EXIT();
}
