/* semsplat clip: CLIP in C, the dense text-aligned feature maps built from it, the scene PCA, and
 * the feature folders that every later stage reads.
 *
 *   tokenizer   byte-level BPE exactly as Hugging Face CLIPTokenizer (clean-up, NFC, lower-case,
 *               the pre-tokenization pattern, </w>, <|startoftext|> ... <|endoftext|>, 77 tokens)
 *   model       a Hugging Face CLIPModel checkpoint (model.safetensors + config.json): text tower,
 *               ViT image tower, projections; CPU (OpenBLAS + sp_pool) or GPU (cuBLAS + our
 *               kernels, fp32 or fp16). Embeddings come out L2-normalised.
 *   dense       per-patch features in the text space: the last block's attention is replaced by
 *               a value path (MaskCLIP) or q-q attention without residual/FFN (ClearCLIP), then
 *               post-LayerNorm and the visual projection; tiles over an upscaled image give one
 *               feature per patch/scale pixels (8 px for ViT-B/16 at scale 2).
 *   features    a folder (features.json, pca_mean.npy, pca_basis.npy, maps/<stem>.npy float16)
 *               written by sp_features_extract from one of three sources (clip, npy, labels) and
 *               read by sp_features_open.
 *
 * Ownership: sp_clip and sp_clip_tokenizer are opaque and freed with their *_free(); an
 * sp_features owns its arrays (sp_features_free). Buffers passed in are host memory. */
#ifndef SEMSPLAT_CLIP_H
#define SEMSPLAT_CLIP_H

#include "semsplat/core.h"
#include "semsplat/device.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- label embeddings (no weights needed) ----------------------------------------------------- */

/* A deterministic pseudo-random unit vector for a class name, used as its "text embedding" when
 * no CLIP weights are given (features source `labels` and queries on such scenes). The text is
 * normalised first (ASCII lower-case, leading/trailing whitespace trimmed, inner whitespace runs
 * collapsed to one space); then h = FNV-1a 64 of the normalised bytes seeds splitmix64, whose
 * 53-bit uniforms feed Box-Muller (double precision) for dim Gaussians, which are normalised. */
void sp_label_embedding(const char *text, int dim, float *out);

/* ---- tokenizer -------------------------------------------------------------------------------- */

#define SP_CLIP_CONTEXT 77   /* text context length of every CLIP */
#define SP_CLIP_BOS 49406    /* <|startoftext|> */
#define SP_CLIP_EOS 49407    /* <|endoftext|>, also used as padding */

typedef struct sp_clip_tokenizer sp_clip_tokenizer;

/* Loads vocab.json and merges.txt from dir (NULL: sp_data_dir()/clip). */
int sp_clip_tokenizer_load(sp_clip_tokenizer **out, const char *dir, sp_error *err);
void sp_clip_tokenizer_free(sp_clip_tokenizer *t);
/* BPE ids of text without start/end tokens, as CLIPTokenizer(text, add_special_tokens=False).
 * Writes at most cap ids; *n_out is the full count (may exceed cap). Fails only on bad UTF-8
 * handling limits (never on content: invalid bytes become U+FFFD as Python would decode). */
int sp_clip_tokenize(const sp_clip_tokenizer *t, const char *text, int32_t *ids, int cap,
                     int *n_out, sp_error *err);
/* The model input: BOS + the first 75 ids + EOS, padded with EOS to 77; *len = used length
 * (position of EOS + 1). */
int sp_clip_tokenize_context(const sp_clip_tokenizer *t, const char *text,
                             int32_t ids[SP_CLIP_CONTEXT], int *len, sp_error *err);

/* ---- model ------------------------------------------------------------------------------------ */

typedef struct sp_clip_tower_config {
    int width, layers, heads, mlp; /* hidden size, blocks, attention heads, MLP hidden size */
    int quick_gelu;                /* 1: x*sigmoid(1.702x) (OpenAI CLIP), 0: exact erf GELU */
    float eps;                     /* LayerNorm epsilon */
} sp_clip_tower_config;

typedef struct sp_clip_config {
    sp_clip_tower_config text, vision;
    int vocab_size, context;  /* text: 49408, 77 */
    int eos_token_id;         /* 2 in legacy configs: the EOS position is argmax(ids) */
    int patch_size, image_size;
    int projection_dim;       /* the shared embedding size (512 for ViT-B/16) */
    float image_mean[3], image_std[3]; /* preprocessor_config.json, or OpenAI's defaults */
} sp_clip_config;

typedef struct sp_clip sp_clip;

/* Loads a Hugging Face CLIPModel safetensors checkpoint (f32, f16 or bf16 tensors; converted to
 * f32, or f16 on the GPU when enabled). config: a config.json path; NULL uses config.json beside
 * the weights when present, else infers every shape from the tensors (heads = width/64).
 * preprocessor_config.json beside the weights is read when present. dev: NULL or a CPU device =
 * CPU (its pool is used for threads); a CUDA device = GPU. Errors name the file and the missing
 * or mis-shaped tensor (SP_E_NOTFOUND, SP_E_FORMAT), or the config field. */
int sp_clip_load(sp_clip **out, const char *safetensors_path, const char *config_json,
                 sp_device *dev, sp_error *err);
void sp_clip_free(sp_clip *c);
const sp_clip_config *sp_clip_get_config(const sp_clip *c);
int sp_clip_embed_dim(const sp_clip *c);
int sp_clip_on_gpu(const sp_clip *c);
/* GPU only: run the towers in fp16 (weights and activations, fp32 accumulation, LayerNorm and
 * softmax in fp32). SP_E_UNSUPPORTED on the CPU. */
int sp_clip_set_fp16(sp_clip *c, int on, sp_error *err);

/* Text embeddings: out [n][embed_dim], L2-normalised. */
int sp_clip_encode_text(sp_clip *c, const char *const *texts, int n, float *out, sp_error *err);
/* Same from token ids [n][77] as sp_clip_tokenize_context makes them. */
int sp_clip_encode_tokens(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err);

/* Image embeddings from model inputs: pixels [n][3][H][W], already normalised (x/255 - mean)/std.
 * H, W multiples of the patch size; other sizes than image_size interpolate the position
 * embeddings bicubically (as transformers' interpolate_pos_encoding). out [n][embed_dim]. */
int sp_clip_encode_pixels(sp_clip *c, const float *pixels, int n, int H, int W, float *out,
                          sp_error *err);
/* CLIP preprocessing of one RGB image [height][width][3] in [0,1]: resize the shortest side to
 * image_size (bicubic, antialiased as PIL), centre crop, normalise -> pixels [3][S][S]. */
int sp_clip_preprocess(const sp_clip *c, const float *rgb, int width, int height, float *pixels,
                       sp_error *err);
/* Image embeddings of n RGB images of one size [n][height][width][3] in [0,1]. */
int sp_clip_encode_image(sp_clip *c, const float *rgb, int n, int width, int height, float *out,
                         sp_error *err);

/* ---- dense features --------------------------------------------------------------------------- */

typedef enum {
    SP_CLIP_HEAD_MASKCLIP = 0,  /* last block: out_proj(v_proj(ln1 x)), no residual/FFN */
    SP_CLIP_HEAD_CLEARCLIP = 1  /* last block: out_proj(softmax(q q^T/sqrt(d)) v), no residual/FFN */
} sp_clip_head;

/* The dense head on one input: pixels [3][H][W] normalised -> out [H/p][W/p][embed_dim],
 * each L2-normalised (p = patch size). Position embeddings interpolated for other sizes. */
int sp_clip_dense_pixels(sp_clip *c, const float *pixels, int H, int W, sp_clip_head head,
                         float *out, sp_error *err);

typedef struct sp_clip_dense_opts {
    sp_clip_head head;
    float scales[4];  /* image upscale factors; the grid is at patch/scales[0] pixels */
    int n_scales;
    int tile;         /* tile side in model pixels (multiple of the patch size; 0: image_size) */
    int stride;       /* tile stride in model pixels (0: tile/2) */
    int batch;        /* tiles per forward pass (on the GPU a minimum: up to max(batch, 128)) */
} sp_clip_dense_opts;

/* ClearCLIP head, scale 2 (8 px per feature for ViT-B/16), tiles of image_size, stride half. */
sp_clip_dense_opts sp_clip_dense_opts_default(void);
/* Grid size sp_clip_dense_features will produce for an image of width x height. */
void sp_clip_dense_grid(const sp_clip *c, const sp_clip_dense_opts *o, int width, int height,
                        int *grid_w, int *grid_h);
/* Dense features of one RGB image [height][width][3] in [0,1] -> out [grid_h][grid_w][embed_dim]
 * (caller allocates, size from sp_clip_dense_grid), L2-normalised. Overlapping tiles are
 * averaged; several scales are resampled onto the first scale's grid and averaged. On the GPU
 * every step after the upload of the image runs on the device. */
int sp_clip_dense_features(sp_clip *c, const float *rgb, int width, int height,
                           const sp_clip_dense_opts *o, float *out, sp_error *err);
/* Bilinear upsampling of a feature grid [gh][gw][dim] to [height][width][dim] (align_corners
 * false: grid cell centres at (i+0.5)*width/gw). */
void sp_clip_upsample(const float *grid, int gw, int gh, int dim, int width, int height,
                      float *out);

/* ---- PCA ---------------------------------------------------------------------------------------- */

/* Mean and the top-dim principal directions of x [n][full_dim] (covariance, then Householder +
 * implicit QL in double). basis [dim][full_dim] has orthonormal rows in decreasing variance, each signed
 * so that its largest-magnitude entry is positive. When the data has fewer than dim directions
 * of variance the remaining rows are completed to an orthonormal set. */
int sp_clip_pca_fit(const float *x, size_t n, int full_dim, int dim, float *mean, float *basis,
                    sp_error *err);

/* ---- feature folders ---------------------------------------------------------------------------- */

typedef struct sp_features_image {
    char name[256];     /* image name as in the COLMAP model (e.g. "frame_0001.png") */
    char map_file[256]; /* map file relative to the folder ("maps/frame_0001.npy") */
    int h, w;           /* map size */
    int image_h, image_w; /* source image size */
    float *map;         /* [h][w][dim] decoded float32, NULL until loaded */
} sp_features_image;

typedef struct sp_features {
    char dir[1024];
    char source[32];          /* "clip", "npy", "labels" */
    int dim, full_dim;
    char model_path[1024];    /* CLIP weights used ("" when none) */
    char label_embedding[16]; /* labels source: "clip" or "hash" (sp_label_embedding); else "" */
    size_t n_images;
    sp_features_image *images;
    float *pca_mean;  /* [full_dim] */
    float *pca_basis; /* [dim][full_dim], orthonormal rows */
} sp_features;

/* Reads features.json and the PCA (maps are loaded with sp_features_load_map). */
int sp_features_open(const char *dir, sp_features *f, sp_error *err);
int sp_features_load_map(sp_features *f, size_t i, sp_error *err);
int sp_features_load_all(sp_features *f, sp_error *err);
/* Index of the image with this name (or same stem), or -1. */
long sp_features_find(const sp_features *f, const char *name);
void sp_features_free(sp_features *f);
/* full = mean + basis^T f. */
void sp_features_decode(const sp_features *f, const float *feat, float *full);
/* feat = basis (full - mean). */
void sp_features_encode(const sp_features *f, const float *full, float *feat);

/* What `semsplat features` does. */
typedef struct sp_features_opts {
    const char *colmap_dir;   /* capture root or model folder (image names and sizes) */
    const char *images_dir;   /* NULL: <capture>/images */
    const char *out_dir;
    const char *source;       /* "clip", "npy", "labels" */
    const char *clip_weights; /* clip: required; labels: optional (class names through CLIP) */
    const char *clip_config;  /* NULL: beside the weights */
    const char *maps_dir;     /* npy: folder of <stem>.npy, [H][W][C] or [C][H][W] */
    const char *labels_dir;   /* labels: NULL = <capture>/labels */
    int dim;                  /* PCA dimension, 1..SP_FEATURE_DIM_MAX (64), 16..64 typical (0: 32) */
    int map_factor;           /* labels/npy: map = image / factor (0: 4) */
    long pca_samples;         /* pixel features sampled for the PCA (0: 50000) */
    sp_clip_dense_opts dense;
    sp_device *dev;           /* NULL: CPU */
    int fp16;                 /* CLIP in fp16 (GPU only) */
    const sp_log *log;
} sp_features_opts;

sp_features_opts sp_features_opts_default(void);
int sp_features_extract(const sp_features_opts *o, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
