/* Parity with Hugging Face transformers: a CLIPModel saved by scripts/clip_reference.py with its
 * reference text/image embeddings and dense-head outputs. CI uses the small model in
 * tests/fixtures/clip/tiny; on the GPU machine SP_CLIP_REF_DIR points at the ViT-B/16-shaped one.
 * CPU always, GPU (fp32 and fp16) when one answers. Prints one line per comparison. */
#include <stdint.h>
#include <stdlib.h>

#include <cJSON.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/device.h"
#include "clip/clip_internal.h"
#include "test.h"

static char dir[1024];

static float *load(const char *name, sp_npy *shape)
{
    char p[1200];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    sp_npy a;
    sp_error err = {0};
    float *f = NULL;
    if (sp_npy_read(p, &a, &err) || sp_npy_to_f32(&a, &f, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return NULL;
    }
    if (shape) {
        *shape = a;
        shape->data = NULL; /* only the shape is wanted */
    }
    sp_npy_free(&a);
    return f;
}

static double maxdiff(const float *a, const float *b, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; i++) m = fmax(m, fabs((double)a[i] - b[i]));
    return m;
}

static void run_model(sp_clip *c, const char *label, double tol)
{
    sp_error err = {0};
    int P = sp_clip_embed_dim(c), p = sp_clip_get_config(c)->patch_size;
    sp_npy ids_s, px_s, wide_s;
    float *ids_f = load("ids.npy", &ids_s), *px = load("pixels.npy", &px_s), *wide = load("pixels_wide.npy", &wide_s);
    float *t_ref = load("text_embeds.npy", NULL), *i_ref = load("image_embeds.npy", NULL);
    float *w_ref = load("image_wide.npy", NULL);
    CHECK(ids_f && px && wide && t_ref && i_ref && w_ref);
    if (!ids_f || !px || !wide || !t_ref || !i_ref || !w_ref) return;
    int nt = (int)ids_s.shape[0], ni = (int)px_s.shape[0], S = (int)px_s.shape[2];
    int WH = (int)wide_s.shape[2], WW = (int)wide_s.shape[3];
    int32_t *ids = malloc(sizeof(int32_t) * nt * 77);
    for (int i = 0; i < nt * 77; i++) ids[i] = (int32_t)ids_f[i];
    float *out = malloc(sizeof(float) * (size_t)P * (WH / p) * (WW / p));
    double t0 = sp_time_now();
    CHECK_OK(sp_clip_encode_tokens(c, ids, nt, out, &err), &err);
    double dt = maxdiff(out, t_ref, (size_t)nt * P);
    /* the same through our tokenizer, from the strings */
    char tp[1200];
    snprintf(tp, sizeof tp, "%s/texts.json", dir);
    char *txt;
    size_t sz;
    double dtok = -1;
    if (!sp_read_file(tp, &txt, &sz, &err)) {
        cJSON *arr = cJSON_Parse(txt);
        const char **texts = malloc(sizeof(char *) * nt);
        for (int i = 0; i < nt; i++) texts[i] = cJSON_GetArrayItem(arr, i)->valuestring;
        CHECK_OK(sp_clip_encode_text(c, texts, nt, out, &err), &err);
        dtok = maxdiff(out, t_ref, (size_t)nt * P);
        free(texts);
        cJSON_Delete(arr);
        free(txt);
    }
    CHECK_OK(sp_clip_encode_pixels(c, px, ni, S, S, out, &err), &err);
    double di = maxdiff(out, i_ref, (size_t)ni * P);
    CHECK_OK(sp_clip_encode_pixels(c, wide, 1, WH, WW, out, &err), &err);
    double dw = maxdiff(out, w_ref, (size_t)P);
    double dd[4];
    const char *names[4] = {"dense_maskclip.npy", "dense_clearclip.npy", "dense_wide_maskclip.npy", "dense_wide_clearclip.npy"};
    for (int k = 0; k < 4; k++) {
        int wide_k = k >= 2, H = wide_k ? WH : S, W = wide_k ? WW : S;
        float *ref = load(names[k], NULL);
        CHECK(ref != NULL);
        if (!ref) return;
        CHECK_OK(sp_clip_dense_pixels(c, wide_k ? wide : px, H, W, (sp_clip_head)(k % 2), out, &err), &err);
        dd[k] = maxdiff(out, ref, (size_t)(H / p) * (W / p) * P);
        free(ref);
    }
    fprintf(stderr, "parity %-9s text %.3g (via tokenizer %.3g)  image %.3g  image_wide %.3g  dense maskclip %.3g "
            "clearclip %.3g  wide %.3g %.3g  max abs  (%.2f s)\n", label, dt, dtok, di, dw, dd[0], dd[1], dd[2], dd[3],
            sp_time_now() - t0);
    CHECK(dt < tol && dtok < tol && di < tol && dw < tol);
    for (int k = 0; k < 4; k++) CHECK(dd[k] < tol);
    free(ids); free(ids_f); free(px); free(wide); free(t_ref); free(i_ref); free(w_ref); free(out);
}

static void test_cpu(void)
{
    sp_clip *c = NULL;
    sp_error err = {0};
    char w[1200];
    snprintf(w, sizeof w, "%s/model.safetensors", dir);
    CHECK_OK(sp_clip_load(&c, w, NULL, NULL, &err), &err);
    if (c) run_model(c, "cpu", 1e-4);
    sp_clip_free(c);
}

static void test_gpu(void)
{
    sp_clip *c = NULL;
    sp_device *dev = NULL;
    sp_error err = {0};
    char w[1200];
    snprintf(w, sizeof w, "%s/model.safetensors", dir);
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CUDA, 0, &err), &err);
    CHECK_OK(sp_clip_load(&c, w, NULL, dev, &err), &err);
    if (c) {
        run_model(c, "gpu-fp32", 1e-4);
        CHECK_OK(sp_clip_set_fp16(c, 1, &err), &err);
        run_model(c, "gpu-fp16", 5e-2);
        clip_gpu_set_flags(c, CLIP_GPU_FLASH_V1); /* the tiled fused-attention kernel */
        run_model(c, "gpu-fp16-tiled", 5e-2);
        clip_gpu_set_flags(c, CLIP_GPU_NO_LT | CLIP_GPU_NO_FLASH); /* plain cuBLAS, no fusion */
        run_model(c, "gpu-fp16-plain", 5e-2);
        clip_gpu_set_flags(c, 0);
    }
    sp_clip_free(c);
    sp_device_free(dev);
}

int main(int argc, char **argv)
{
    TEST_ARGS(argc, argv);
    const char *env = getenv("SP_CLIP_REF_DIR");
    if (env && *env) snprintf(dir, sizeof dir, "%s", env);
    else snprintf(dir, sizeof dir, "%s/tests/fixtures/clip/tiny", SP_SOURCE_DIR);
    char w[1200];
    snprintf(w, sizeof w, "%s/model.safetensors", dir);
    if (!sp_file_exists(w)) TEST_SKIP("no reference model (scripts/clip_reference.py makes one)");
    RUN(test_cpu);
    RUN_GPU(test_gpu);
    return TEST_EXIT();
}
