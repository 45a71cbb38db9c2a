/* Built when nvcc is absent: the render module has no CUDA backend (a CUDA device cannot be
 * created either, so nothing asks for it). */
#include "render/backend.h"

const sp_render_backend *sp_render_cuda_backend(void) { return NULL; }
