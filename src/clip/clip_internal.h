/* Private to src/clip: the loaded model (weights as f32 host arrays, HF layout: Linear weights
 * [out][in]) and the entry points shared by the CPU and GPU paths. */
#ifndef SP_CLIP_INTERNAL_H
#define SP_CLIP_INTERNAL_H

#include "semsplat/clip.h"

typedef struct clip_layer {
    const float *ln1_w, *ln1_b, *q_w, *q_b, *k_w, *k_b, *v_w, *v_b, *o_w, *o_b;
    const float *ln2_w, *ln2_b, *fc1_w, *fc1_b, *fc2_w, *fc2_b;
} clip_layer;

typedef struct clip_tower {
    sp_clip_tower_config cfg;
    clip_layer *layers;
} clip_tower;

/* What the vision forward produces. */
typedef enum {
    CLIP_OUT_POOLED = 0, /* [n][proj]: post-LN of CLS, projection (not normalised) */
    CLIP_OUT_DENSE_MASKCLIP = 1, /* [n][gh*gw][proj] (not normalised) */
    CLIP_OUT_DENSE_CLEARCLIP = 2
} clip_out_kind;

struct sp_clip_gpu;

struct sp_clip {
    sp_clip_config cfg;
    char path[1024];
    float *blob; /* every weight, f32 */
    size_t blob_floats;
    /* text */
    const float *tok_emb, *txt_pos, *final_ln_w, *final_ln_b, *text_proj;
    clip_tower text;
    /* vision */
    const float *cls, *patch_w, *vis_pos, *pre_ln_w, *pre_ln_b, *post_ln_w, *post_ln_b, *vis_proj;
    clip_tower vision;
    sp_pool *pool;     /* CPU threads (owned when own_pool) */
    int own_pool;
    sp_device *dev;
    sp_clip_tokenizer *tok; /* loaded on first text encode */
    struct sp_clip_gpu *gpu; /* NULL on the CPU */
    int fp16;
};

/* A model with random weights (benchmarks, no file needed) and the ViT-B/16 configuration. */
int clip_create_random(sp_clip **out, const sp_clip_config *cfg, uint64_t seed, sp_device *dev,
                       sp_error *err);
void clip_config_vit_b16(sp_clip_config *c);

/* Position embeddings for a gh x gw grid: [1 + gh*gw][width] into out (bicubic as torch
 * interpolate(align_corners=False) when the grid differs from the trained one). */
void clip_pos_embed(const sp_clip *c, int gh, int gw, float *out);
/* EOS position of a 77-id sequence as transformers picks it. */
int clip_eos_position(const sp_clip *c, const int32_t *ids);

/* CPU forwards. */
int clip_cpu_text(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err);
int clip_cpu_vision(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind,
                    float *out, sp_error *err);

/* ---- dense planning, shared by the CPU and GPU dense paths (dense.c) ---- */

typedef struct clip_scale_plan {
    int rw, rh; /* resized image */
    int pw, ph; /* padded to whole tiles */
    int gw, gh; /* patch grid covering the resized image */
} clip_scale_plan;
#define CLIP_TILES_MAX 4096 /* tiles along one axis */

void clip_plan_scale(const sp_clip *c, float s, int tile, int width, int height, clip_scale_plan *sp);
void clip_tile_params(const sp_clip *c, const sp_clip_dense_opts *o, int *tile, int *stride);
/* Tile origins along one axis (0, stride, ..., the last flush with the end); returns the count
 * (only the first cap are written). */
int clip_tile_starts(int padded, int tile, int stride, int *out, int cap);

/* PIL's antialiased bicubic weights of one axis: output i takes cnt[i] taps from x0[i],
 * weights w[i * taps ...]. */
typedef struct clip_axis_weights {
    double *w;
    int *x0, *cnt, taps;
} clip_axis_weights;
int clip_axis_weights_make(clip_axis_weights *a, int n_in, int n_out); /* -1: out of memory */
void clip_axis_weights_free(clip_axis_weights *a);

/* fp32 -> fp16, round to nearest even (F16C when the CPU has it): the fp16 GPU path's uploads. */
void clip_floats_to_half(const float *src, uint16_t *dst, size_t n);

/* GPU forwards (cuda/ when built, nocuda/ stubs otherwise). */
int clip_gpu_init(sp_clip *c, sp_error *err);
void clip_gpu_free(sp_clip *c);
int clip_gpu_set_fp16(sp_clip *c, int on, sp_error *err);
int clip_gpu_text(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err);
int clip_gpu_vision(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind,
                    float *out, sp_error *err);
/* Dense features of one image entirely on the device (resize, tiles, the dense head, overlap
 * averaging, scales, normalisation); options already validated, tile/stride from
 * clip_tile_params. Same result as the CPU path of sp_clip_dense_features. */
int clip_gpu_dense(sp_clip *c, const float *rgb, int width, int height, const sp_clip_dense_opts *o,
                   int tile, int stride, clip_out_kind kind, float *out, sp_error *err);

/* C [F][F] = (x - mean)^T (x - mean) for x [n][F] on a CUDA device (cuBLAS, fp32). */
int clip_gpu_gram(sp_device *dev, const float *x, size_t n, int F, const float *mean, float *C, sp_error *err);
/* sp_clip_pca_fit with the covariance product on dev when it is a CUDA device (NULL: CPU). */
int clip_pca_fit_dev(sp_device *dev, const float *x, size_t n, int full_dim, int dim, float *mean, float *basis,
                     sp_error *err);

/* Variants for benchmarks and tests: CLIP_GPU_NO_LT runs the plain cuBLAS products and
 * separate bias kernels, CLIP_GPU_NO_FLASH the unfused attention (cuBLAS + softmax),
 * CLIP_GPU_FLASH_V1 the fused attention's tiled kernel even where the sequence-resident one fits,
 * CLIP_GPU_MLP_SLABS each block's MLP (fc1, activation, fc2) in slabs of at most 4096 rows, so
 * that the fc1 output of a slab is still in L2 for the activation and fc2, CLIP_GPU_BLOCK_SLABS
 * each whole block over slabs of sequences of at most 6400 rows (a slab's QKV rows still in L2
 * for the attention); with CLIP_GPU_SLABS_SMALL slabs of 16 rows / one sequence (tests on small
 * models). */
enum {
    CLIP_GPU_NO_LT = 1, CLIP_GPU_NO_FLASH = 2, CLIP_GPU_FLASH_V1 = 4, CLIP_GPU_PROFILE = 8, CLIP_GPU_MLP_SLABS = 16,
    CLIP_GPU_SLABS_SMALL = 32, CLIP_GPU_BLOCK_SLABS = 64
};
void clip_gpu_set_flags(sp_clip *c, int flags);
/* Stage timing (benchmarks): with CLIP_GPU_PROFILE set, each text or pooled image forward records
 * a CUDA event after every stage and adds the stage times (ms, summed over the layers) to a
 * running total; clip_gpu_stage_ms copies the totals into ms[CLIP_STAGES], clears them and
 * returns how many forwards they cover (-1 without CUDA). The events cost a little: time the
 * throughput figures without the flag. */
enum {
    CLIP_STAGE_LN, CLIP_STAGE_QKV, CLIP_STAGE_ATTN, CLIP_STAGE_OPROJ, CLIP_STAGE_FC1, CLIP_STAGE_ACT,
    CLIP_STAGE_FC2, CLIP_STAGE_OTHER, CLIP_STAGES
};
static inline const char *clip_stage_name(int s)
{
    static const char *const names[CLIP_STAGES] = {"layernorm", "qkv_gemm", "attention", "out_gemm_residual",
                                                   "fc1_gemm", "gelu", "fc2_gemm_residual", "embed_head_other"};
    return s >= 0 && s < CLIP_STAGES ? names[s] : "?";
}
int clip_gpu_stage_ms(sp_clip *c, double ms[CLIP_STAGES]);
/* Benchmarks: the last sp_clip_encode_pixels call again on the pixels still on the device (the
 * upload left out, as a framework's timing with inputs on the GPU). */
int clip_gpu_vision_again(sp_clip *c, int n, int H, int W, float *out, sp_error *err);
/* The fused attention kernel alone on host data: qkv [B*T][3w] (converted to fp16) -> out
 * [B*T][w]; mode 0 the kernel the towers use, 1 the tiled kernel, 100 q + n (q >= 1, n = 1..8)
 * the sequence-resident kernel with q blocks of n warps per head (+ 1000: query rows staged
 * through shared memory); SP_E_UNSUPPORTED when the kernel does not take this head width. */
int clip_gpu_attention_check(sp_device *dev, const float *qkv, int B, int T, int H, int w, int causal,
                             int qq, int mode, float *out, sp_error *err);
/* The same kernel alone on random fp16 device data, reps launches: microseconds per launch. */
int clip_gpu_attention_bench(sp_device *dev, int B, int T, int H, int w, int causal, int mode, int reps,
                             double *us, sp_error *err);

/* label id -> class name, from a capture's labels.json ({"labels": {"1": {"class": ..}}} as synth
 * writes it, or {"labels": [{"id": 1, "class": ..}]}); ids 1..65535, each once; id 0 and ids not
 * listed are "background". Classes are deduplicated (class_of maps an id to its class). */
typedef struct clip_label_table {
    int n;                /* ids 0..n-1 */
    char (*cls)[128];
    int n_classes;
    char (*class_names)[128];
    int *class_of;        /* id -> class index */
} clip_label_table;

int clip_label_table_read(const char *path, clip_label_table *t, sp_error *err);
void clip_label_table_free(clip_label_table *t);

static inline void clip_l2_normalize(float *v, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += (double)v[i] * v[i];
    float inv = s > 0 ? (float)(1.0 / sqrt(s)) : 0.f;
    for (int i = 0; i < n; i++) v[i] *= inv;
}

#endif
