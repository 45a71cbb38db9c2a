/* Temporary bodies for the clip API while the implementation lands (removed file by file). */
#include "semsplat/clip.h"

int sp_clip_load(sp_clip **out, const char *w, const char *c, sp_device *d, sp_error *err)
{
    *out = NULL;
    return sp_error_set(err, SP_E_UNSUPPORTED, "%s: CLIP loading is not implemented yet", w);
}
void sp_clip_free(sp_clip *c) { (void)c; }
int sp_clip_embed_dim(const sp_clip *c) { return 512; }
int sp_clip_encode_text(sp_clip *c, const char *const *texts, int n, float *out, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "CLIP text encoding is not implemented yet");
}
int sp_features_extract(const sp_features_opts *o, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "feature extraction is not implemented yet");
}
