/* CLIP throughput: ViT-B/16 image embeddings (224x224) and text embeddings on the CPU and on the
 * GPU (fp32/fp16, batch 1 and 32), and dense feature maps of 640x480 images. Random weights with
 * the exact ViT-B/16 shapes (timing does not depend on the values). With --anchor FILE (the JSON
 * lines of shared/bench/anchors/bench_clip.py from the same run) it prints ratios against
 * transformers. Output: `name  value  unit  (settings)`.
 * On the GPU the batch-32/128 image figures are also given with the pixels already on the device
 * (`_resident`, as the transformers anchor times it: its inputs are on the GPU), and --variants
 * adds batch 128 / text 256 in fp16 with the tiled fused-attention kernel and with neither
 * cuBLASLt epilogues nor fused attention (the previous design), and with the MLP / the blocks /
 * both in L2-sized slabs (_mlpslabs, _blockslabs, _bothslabs; both precisions); --variants 2 adds
 * each alone.
 * --ncu runs one of each GPU workload only (for Nsight Compute). On the GPU, clip_stage_* lines
 * give the time per stage (CUDA events) of the image batch 128 and text batch 256 forwards, and
 * clip_attn_* the fused attention kernel alone.
 *   bench_clip [--cpu-only | --gpu-only] [--threads N] [--reps N] [--dense-cpu] [--anchor FILE]
 *              [--variants [2]] [--ncu] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clip/clip_internal.h"
#include "semsplat/clip.h"
#include "semsplat/render.h"

static int reps = 5;
static const char *variant = ""; /* suffix of the figure names ("_nolt", ...) */

static double median(double *t, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && t[j] < t[j - 1]; j--) {
            double x = t[j]; t[j] = t[j - 1]; t[j - 1] = x;
        }
    return t[n / 2];
}

/* anchors: transformers figures from bench_clip.py's JSON lines */
static double anchor_img[2][3], anchor_txt[2];

static void read_anchor(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[512];
    if (!f) { fprintf(stderr, "bench_clip: cannot read %s\n", path); return; }
    while (fgets(line, sizeof line, f)) {
        int half = strstr(line, "float16") != NULL;
        char *b = strstr(line, "\"batch\": "), *v;
        if (strstr(line, "\"clip_image\"") && b && (v = strstr(line, "\"img_per_s\": "))) {
            int batch = atoi(b + 9);
            int k = batch == 1 ? 0 : batch == 32 ? 1 : batch == 128 ? 2 : -1;
            if (k >= 0) anchor_img[half][k] = atof(v + 13);
        } else if (strstr(line, "\"clip_text\"") && (v = strstr(line, "\"text_per_s\": "))) {
            anchor_txt[half] = atof(v + 14);
        }
    }
    fclose(f);
}

static int bench_images(sp_clip *c, const char *dev_name, const char *prec, int batch, int anchor_k)
{
    sp_error err = {0};
    const int S = 224, P = sp_clip_embed_dim(c);
    float *px = malloc(sizeof(float) * batch * 3 * S * S), *out = malloc(sizeof(float) * batch * P);
    for (long i = 0; i < (long)batch * 3 * S * S; i++) px[i] = (float)((i * 7919) % 1000) / 500.f - 1.f;
    double t[64];
    int rc = sp_clip_encode_pixels(c, px, batch, S, S, out, &err); /* warm-up */
    for (int r = 0; r < reps && !rc; r++) {
        double t0 = sp_time_now();
        rc = sp_clip_encode_pixels(c, px, batch, S, S, out, &err);
        t[r] = sp_time_now() - t0;
    }
    if (rc) fprintf(stderr, "bench_clip: %s\n", err.msg);
    else {
        double ips = batch / median(t, reps);
        printf("clip_image_%s_%s_b%d%s  %.1f  img/s  (ViT-B/16 224x224, batch %d, host pixels in, %s)\n",
               sp_clip_on_gpu(c) ? "gpu" : "cpu", prec, batch, variant, ips, batch, dev_name);
        double a = anchor_k >= 0 ? anchor_img[!strcmp(prec, "fp16")][anchor_k] : 0;
        if (a > 0)
            printf("clip_image_%s_b%d%s_vs_transformers  %.2f  x  (ours %.1f / transformers %.1f img/s, same GPU)\n",
                   prec, batch, variant, ips / a, ips, a);
        if (sp_clip_on_gpu(c) && batch >= 32) {
            for (int r = 0; r < reps && !rc; r++) {
                double t0 = sp_time_now();
                rc = clip_gpu_vision_again(c, batch, S, S, out, &err);
                t[r] = sp_time_now() - t0;
            }
            if (rc) fprintf(stderr, "bench_clip: %s\n", err.msg);
            else {
                double rps = batch / median(t, reps);
                printf("clip_image_gpu_%s_b%d%s_resident  %.1f  img/s  (pixels already on the GPU, %s)\n", prec, batch,
                       variant, rps, dev_name);
                if (a > 0)
                    printf("clip_image_%s_b%d%s_resident_vs_transformers  %.2f  x  (ours %.1f / transformers %.1f img/s)\n",
                           prec, batch, variant, rps / a, rps, a);
            }
        }
    }
    free(px);
    free(out);
    return rc;
}

static int bench_text(sp_clip *c, const char *dev_name, const char *prec, int batch)
{
    sp_error err = {0};
    int32_t *ids = malloc(sizeof(int32_t) * batch * 77);
    float *out = malloc(sizeof(float) * batch * sp_clip_embed_dim(c));
    /* full-length sequences, as the transformers anchor (random ids, 77 tokens) */
    for (int i = 0; i < batch * 77; i++) ids[i] = (i % 77) == 76 ? SP_CLIP_EOS : (int32_t)((i * 7919) % 49000);
    double t[64];
    int rc = sp_clip_encode_tokens(c, ids, batch, out, &err);
    for (int r = 0; r < reps && !rc; r++) {
        double t0 = sp_time_now();
        rc = sp_clip_encode_tokens(c, ids, batch, out, &err);
        t[r] = sp_time_now() - t0;
    }
    if (rc) fprintf(stderr, "bench_clip: %s\n", err.msg);
    else {
        double tps = batch / median(t, reps);
        printf("clip_text_%s_%s_b%d%s  %.1f  texts/s  (77 tokens, batch %d, %s)\n", sp_clip_on_gpu(c) ? "gpu" : "cpu",
               prec, batch, variant, tps, batch, dev_name);
        double a = anchor_txt[!strcmp(prec, "fp16")];
        if (a > 0 && batch == 256)
            printf("clip_text_%s_b256%s_vs_transformers  %.2f  x  (ours %.1f / transformers %.1f texts/s)\n", prec,
                   variant, tps / a, tps, a);
    }
    free(ids);
    free(out);
    return rc;
}

/* Where the time of a batch goes: 3 forwards with CUDA events after every stage (the image one on
 * the pixels already on the device); ms per forward summed over the layers, and per layer for the
 * stages every layer has. Printed as clip_stage_<what>_<prec>_b<batch>_<stage>  ms. */
static void bench_stages(sp_clip *c, const char *what, const char *prec, int batch)
{
    sp_error err = {0};
    int image = !strcmp(what, "image"), S = 224, P = sp_clip_embed_dim(c), rc = 0;
    const sp_clip_config *cf = sp_clip_get_config(c);
    int layers = image ? cf->vision.layers : cf->text.layers;
    float *px = image ? malloc(sizeof(float) * batch * 3 * S * S) : NULL, *out = malloc(sizeof(float) * batch * P);
    int32_t *ids = image ? NULL : malloc(sizeof(int32_t) * batch * 77);
    for (long i = 0; image && i < (long)batch * 3 * S * S; i++) px[i] = (float)((i * 7919) % 1000) / 500.f - 1.f;
    for (int i = 0; !image && i < batch * 77; i++) ids[i] = (i % 77) == 76 ? SP_CLIP_EOS : (int32_t)((i * 7919) % 49000);
    double ms[CLIP_STAGES];
    rc = image ? sp_clip_encode_pixels(c, px, batch, S, S, out, &err) : sp_clip_encode_tokens(c, ids, batch, out, &err);
    clip_gpu_set_flags(c, CLIP_GPU_PROFILE);
    clip_gpu_stage_ms(c, ms); /* clear */
    for (int r = 0; r < 3 && !rc; r++)
        rc = image ? clip_gpu_vision_again(c, batch, S, S, out, &err) : sp_clip_encode_tokens(c, ids, batch, out, &err);
    clip_gpu_set_flags(c, 0);
    int n = clip_gpu_stage_ms(c, ms);
    if (rc || n < 1) fprintf(stderr, "bench_clip: stage timing: %s\n", rc ? err.msg : "no events");
    else {
        double total = 0;
        for (int s = 0; s < CLIP_STAGES; s++) total += ms[s] / n;
        for (int s = 0; s < CLIP_STAGES; s++)
            printf("clip_stage_%s_%s_b%d_%s  %.3f  ms  (%.1f%% of %.3f ms per forward, %.1f us per layer, %d forwards)\n",
                   what, prec, batch, clip_stage_name(s), ms[s] / n, 100 * ms[s] / n / total, total,
                   s == CLIP_STAGE_OTHER ? 0 : 1000 * ms[s] / n / layers, n);
    }
    free(px);
    free(ids);
    free(out);
}

/* The fused attention kernel alone (random fp16 data on the device): ViT-B/16's batch 128
 * (197 tokens, 12 heads of 64; and batch 32, whose input stays in L2) and the text tower's batch
 * 256 (77 tokens, 8 heads, causal); the
 * kernel the towers use, the tiled one, and the resident one as q blocks of n warps per head
 * ("resident_qxn", mode 100 q + n; "_qsmem": + 1000, the queries through shared memory too). */
static void bench_attention(sp_device *dev)
{
    static const struct { const char *what; int B, T, H, w, causal, modes[8]; } shapes[] = {
        {"image_b128", 128, 197, 12, 768, 0, {0, 1, 104, 107, 207, 404, 1104, 1207}},
        {"text_b256", 256, 77, 8, 512, 1, {0, 1, 105, 203, 302, 501, 1103, 1203}},
        /* 29 MB of QKV rows: L2-resident from one launch to the next (as in a 32-image slab) */
        {"image_b32", 32, 197, 12, 768, 0, {0, 1, 104, 107, 207, 404, 1104, 1207}}};
    for (int k = 0; k < 3; k++)
        for (int m = 0; m < 8; m++) {
            sp_error err = {0};
            double us = 0;
            int B = shapes[k].B, T = shapes[k].T, H = shapes[k].H, d = shapes[k].w / H, mode = shapes[k].modes[m];
            if (clip_gpu_attention_bench(dev, B, T, H, shapes[k].w, shapes[k].causal, mode, 20, &us, &err)) {
                fprintf(stderr, "bench_clip: %s\n", err.msg);
                return;
            }
            char name[32];
            if (mode >= 100)
                snprintf(name, sizeof name, "resident_%dx%d%s", mode % 1000 / 100, mode % 100, mode >= 1000 ? "_qsmem" : "");
            else snprintf(name, sizeof name, "%s", mode ? "tiled" : "auto");
            /* 4 T^2 d per head (Q K^T and P V), halved by the causal mask */
            double flop = 4.0 * T * T * d * H * B * (shapes[k].causal ? 0.5 : 1.0);
            printf("clip_attn_%s_%s  %.1f  us  (one layer, fp16, %d x %d tokens, %d heads of %d%s, %.0f TFLOP/s)\n",
                   shapes[k].what, name, us, B, T, H, d, shapes[k].causal ? ", causal" : "", flop / (us * 1e-6) / 1e12);
        }
}

static int bench_dense(sp_clip *c, const char *dev_name, const char *prec, int n_img)
{
    sp_error err = {0};
    const int W = 640, H = 480, P = sp_clip_embed_dim(c);
    sp_clip_dense_opts o = sp_clip_dense_opts_default();
    o.batch = sp_clip_on_gpu(c) ? 32 : 4;
    int gw, gh;
    sp_clip_dense_grid(c, &o, W, H, &gw, &gh);
    float *rgb = malloc(sizeof(float) * W * H * 3), *out = malloc(sizeof(float) * gw * gh * P);
    for (long i = 0; i < (long)W * H * 3; i++) rgb[i] = (float)((i * 31) % 255) / 255.f;
    int rc = sp_clip_dense_features(c, rgb, W, H, &o, out, &err); /* warm-up: scratch, plans */
    double t0 = sp_time_now();
    for (int r = 0; r < n_img && !rc; r++) rc = sp_clip_dense_features(c, rgb, W, H, &o, out, &err);
    double dt = sp_time_now() - t0;
    if (rc) fprintf(stderr, "bench_clip: %s\n", err.msg);
    else
        printf("clip_dense_%s_%s  %.2f  img/s  (640x480 -> %dx%d x %d features, scale 2, tiles 224 stride 112, %s)\n",
               sp_clip_on_gpu(c) ? "gpu" : "cpu", prec, n_img / dt, gw, gh, P, dev_name);
    free(rgb);
    free(out);
    return rc;
}

/* image batch 128 and text batch 256 under each of n variants (clip_gpu_set_flags) */
struct bench_variant { int flags; const char *suffix; };
static void bench_variants(sp_clip *c, const char *name, const char *prec, const struct bench_variant *vs, int n)
{
    for (int v = 0; v < n; v++) {
        clip_gpu_set_flags(c, vs[v].flags);
        variant = vs[v].suffix;
        bench_images(c, name, prec, 128, 2);
        bench_text(c, name, prec, 256);
        clip_gpu_set_flags(c, 0);
        variant = "";
    }
}

int main(int argc, char **argv)
{
    int cpu = 1, gpu = 1, dense_cpu = 0, variants = 0, ncu = 0;
    long threads = 2;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--cpu-only")) gpu = 0;
        else if (!strcmp(argv[i], "--gpu-only")) cpu = 0;
        else if (!strcmp(argv[i], "--dense-cpu")) dense_cpu = 1;
        else if (!strcmp(argv[i], "--variants")) variants = i + 1 < argc && !strcmp(argv[i + 1], "2") ? (i++, 2) : 1;
        else if (!strcmp(argv[i], "--ncu")) ncu = 1;
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atol(argv[++i]);
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--anchor") && i + 1 < argc) read_anchor(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_clip [--cpu-only|--gpu-only] [--threads N] [--reps N] [--dense-cpu] [--anchor FILE] "
                    "[--variants] [--ncu]\n");
            return 2;
        }
    }
    if (reps < 1) reps = 1;
    if (reps > 64) reps = 64;
    sp_clip_config cfg;
    clip_config_vit_b16(&cfg);
    sp_error err = {0};
    if (cpu) {
        sp_device *dev = NULL;
        sp_clip *c = NULL;
        if (sp_device_create(&dev, SP_DEVICE_CPU, (int)threads, &err) || clip_create_random(&c, &cfg, 1, dev, &err)) {
            fprintf(stderr, "bench_clip: %s\n", err.msg);
            return 1;
        }
        char name[128];
        snprintf(name, sizeof name, "CPU, %ld threads", threads);
        bench_images(c, name, "fp32", 1, -1);
        bench_images(c, name, "fp32", 4, -1);
        bench_text(c, name, "fp32", 16);
        if (dense_cpu) bench_dense(c, name, "fp32", 1);
        sp_clip_free(c);
        sp_device_free(dev);
    }
    if (gpu) {
        if (!sp_cuda_available()) {
            fprintf(stderr, "bench_clip: no GPU, GPU figures skipped\n");
            return 0;
        }
        sp_device *dev = NULL;
        sp_clip *c = NULL;
        if (sp_device_create(&dev, SP_DEVICE_CUDA, 0, &err) || clip_create_random(&c, &cfg, 1, dev, &err)) {
            fprintf(stderr, "bench_clip: %s\n", err.msg);
            return 1;
        }
        const char *name = sp_device_name(dev);
        if (ncu) { /* one of each, fp16 */
            reps = 1;
            if (!sp_clip_set_fp16(c, 1, &err)) {
                bench_images(c, name, "fp16", 128, -1);
                bench_text(c, name, "fp16", 256);
                bench_dense(c, name, "fp16", 1);
            }
            sp_clip_free(c);
            sp_device_free(dev);
            return 0;
        }
        bench_attention(dev);
        for (int half = 0; half <= 1; half++) {
            const char *prec = half ? "fp16" : "fp32";
            if (sp_clip_set_fp16(c, half, &err)) { fprintf(stderr, "bench_clip: %s\n", err.msg); break; }
            bench_images(c, name, prec, 1, 0);
            bench_images(c, name, prec, 32, 1);
            bench_images(c, name, prec, 128, 2);
            bench_text(c, name, prec, 256);
            bench_stages(c, "image", prec, 128);
            bench_stages(c, "text", prec, 256);
            bench_dense(c, name, prec, 10);
            /* the same in L2-sized slabs (the MLP, the whole blocks, both; both precisions), without
             * cuBLASLt epilogues, without the fused attention (--variants 2: also each alone),
             * with the tiled fused kernel instead of the sequence-resident one */
            static const struct bench_variant vs[] = {
                {CLIP_GPU_MLP_SLABS, "_mlpslabs"}, {CLIP_GPU_BLOCK_SLABS, "_blockslabs"},
                {CLIP_GPU_MLP_SLABS | CLIP_GPU_BLOCK_SLABS, "_bothslabs"}, {CLIP_GPU_FLASH_V1, "_flashv1"},
                {CLIP_GPU_NO_LT | CLIP_GPU_NO_FLASH, "_nolt_noflash"}, {CLIP_GPU_NO_LT, "_nolt"},
                {CLIP_GPU_NO_FLASH, "_noflash"}};
            if (variants) {
                bench_variants(c, name, prec, vs, 3);
                if (half) bench_variants(c, name, prec, vs + 3, variants > 1 ? 4 : 2);
                else if (variants > 1) bench_variants(c, name, prec, vs + 5, 2);
            }
        }
        sp_clip_free(c);
        sp_device_free(dev);
    }
    return 0;
}
