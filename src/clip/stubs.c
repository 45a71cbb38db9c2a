/* Temporary body for the clip API while the implementation lands (removed when features.c does). */
#include "semsplat/clip.h"

int sp_features_extract(const sp_features_opts *o, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "feature extraction is not implemented yet");
}
