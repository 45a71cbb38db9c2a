/* Built when nvcc is absent: the GPU entry points of the clip module report that there is none. */
#include "../clip_internal.h"

int clip_gpu_init(sp_clip *c, sp_error *err)
{
    return sp_error_set(err, SP_E_NODEVICE, "CLIP on the GPU: semsplat was built without CUDA");
}
void clip_gpu_free(sp_clip *c) { (void)c; }
int clip_gpu_set_fp16(sp_clip *c, int on, sp_error *err) { return clip_gpu_init(c, err); }
int clip_gpu_text(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    return clip_gpu_init(c, err);
}
int clip_gpu_vision(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind,
                    float *out, sp_error *err)
{
    return clip_gpu_init(c, err);
}
int clip_gpu_dense(sp_clip *c, const float *rgb, int width, int height, const sp_clip_dense_opts *o,
                   int tile, int stride, clip_out_kind kind, float *out, sp_error *err)
{
    return clip_gpu_init(c, err);
}
void clip_gpu_set_flags(sp_clip *c, int flags) { (void)c; (void)flags; }
int clip_gpu_stage_ms(sp_clip *c, double ms[CLIP_STAGES])
{
    (void)c;
    for (int i = 0; i < CLIP_STAGES; i++) ms[i] = 0;
    return -1;
}
int clip_gpu_attention_check(sp_device *dev, const float *qkv, int B, int T, int H, int w, int causal,
                             int qq, int mode, float *out, sp_error *err)
{
    return sp_error_set(err, SP_E_NODEVICE, "CLIP attention on the GPU: semsplat was built without CUDA");
}
int clip_gpu_attention_bench(sp_device *dev, int B, int T, int H, int w, int causal, int mode, int reps,
                             double *us, sp_error *err)
{
    *us = 0;
    return sp_error_set(err, SP_E_NODEVICE, "CLIP attention on the GPU: semsplat was built without CUDA");
}
int clip_gpu_vision_again(sp_clip *c, int n, int H, int W, float *out, sp_error *err)
{
    return clip_gpu_init(c, err);
}
int clip_gpu_gram(sp_device *dev, const float *x, size_t n, int F, const float *mean, float *C, sp_error *err)
{
    return sp_error_set(err, SP_E_NODEVICE, "PCA on the GPU: semsplat was built without CUDA");
}
