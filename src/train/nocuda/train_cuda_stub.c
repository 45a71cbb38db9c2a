/* Built when nvcc is absent: the train module has no CUDA kernels (nor can a CUDA device be made). */
#include "train/train_kernels.h"

const tr_kernels *tr_cuda_kernels(void) { return NULL; }
