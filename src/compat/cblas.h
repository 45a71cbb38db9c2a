/* Fallback for machines without a CBLAS (e.g. the GPU image): declares the one routine semsplat
 * uses. Only on the include path when CMake finds no OpenBLAS; the real cblas.h wins otherwise. */
#ifndef SP_COMPAT_CBLAS_H
#define SP_COMPAT_CBLAS_H

enum CBLAS_ORDER { CblasRowMajor = 101, CblasColMajor = 102 };
enum CBLAS_TRANSPOSE { CblasNoTrans = 111, CblasTrans = 112, CblasConjTrans = 113 };

void cblas_sgemm(enum CBLAS_ORDER order, enum CBLAS_TRANSPOSE ta, enum CBLAS_TRANSPOSE tb, int M,
                 int N, int K, float alpha, const float *A, int lda, const float *B, int ldb,
                 float beta, float *C, int ldc);

#endif
