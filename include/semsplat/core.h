/* semsplat core: error status and messages, logging, progress bars, a thread pool, small linear
 * algebra, and the two types every stage shares (sp_camera, sp_splat).
 *
 * Errors: every function that can fail returns 0 or a negative SP_E* code and, when given an
 * sp_error, writes a message naming the file, field or value at fault. On error, outputs are
 * left as they were (or freed and zeroed where documented). The library never prints by itself:
 * logging and progress go through an sp_log the caller passes (NULL = silent).
 * Ownership: whoever allocates frees; owning structs have *_free(), which accepts NULL. */
#ifndef SEMSPLAT_CORE_H
#define SEMSPLAT_CORE_H

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- errors ---------------------------------------------------------------------------------- */

enum {
    SP_OK = 0,
    SP_E_IO = -1,          /* a file could not be opened, read or written */
    SP_E_FORMAT = -2,      /* a file or string is malformed, truncated or inconsistent */
    SP_E_NOMEM = -3,       /* allocation failed */
    SP_E_ARG = -4,         /* a caller passed an invalid value */
    SP_E_UNSUPPORTED = -5, /* valid input we do not handle (camera model, dtype, ...) */
    SP_E_NODEVICE = -6,    /* no usable GPU, or the CUDA backend is not built */
    SP_E_NUMERIC = -7,     /* NaN/Inf appeared where it must not */
    SP_E_NOTFOUND = -8,    /* a named thing (file, tensor, model, class) does not exist */
    SP_E_NET = -9,         /* a network peer was unreachable or answered badly */
    SP_E_DEVICE = -10      /* a GPU call failed */
};

typedef struct sp_error {
    int code;
    char msg[1024];
} sp_error;

/* Sets err (if not NULL) to code and a printf-style message; returns code so callers can write
 * `return sp_error_set(err, SP_E_FORMAT, "%s: ...", path);`. */
int sp_error_set(sp_error *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Prefixes an existing message with context ("loading scene: " + old message); returns err->code. */
int sp_error_prefix(sp_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void sp_error_clear(sp_error *err);
const char *sp_strerror(int code); /* short name of a code: "I/O error", "malformed input", ... */

/* ---- logging and progress -------------------------------------------------------------------- */

typedef enum { SP_LOG_DEBUG = 0, SP_LOG_INFO = 1, SP_LOG_WARN = 2, SP_LOG_ERROR = 3 } sp_log_level;

/* A log sink the caller owns. fn may be NULL (silent). progress_fd: file descriptor for progress
 * bars (-1 = none); bars redraw in place when it is a terminal, else print a line every few %. */
typedef struct sp_log {
    void (*fn)(void *user, sp_log_level level, const char *msg);
    void *user;
    sp_log_level min_level;
    int progress_fd;
} sp_log;

/* A log writing "[semsplat] msg" lines to stderr at >= min_level, bars to fd 2 (or none if quiet). */
sp_log sp_log_stderr(sp_log_level min_level, int quiet);
void sp_logf(const sp_log *log, sp_log_level level, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* A progress bar: "label  [#####.....]  step/total  rate unit/s  ETA mm:ss  extra". */
typedef struct sp_progress {
    const sp_log *log;
    char label[48];
    const char *unit;
    long total;
    long step;
    double t_start;
    double t_last_draw;
    int last_pct;
    int is_tty;
} sp_progress;

void sp_progress_begin(sp_progress *p, const sp_log *log, const char *label, long total,
                       const char *unit);
/* Sets the step count to `step` and redraws at most ~10x/s; extra (may be NULL) is a short
 * status such as "loss 0.041 psnr 27.3". */
void sp_progress_update(sp_progress *p, long step, const char *extra);
void sp_progress_end(sp_progress *p, const char *extra);

double sp_time_now(void); /* monotonic seconds */

/* ---- thread pool ----------------------------------------------------------------------------- */

typedef struct sp_pool sp_pool;

/* n_threads 0 means the number of online CPUs; negative or above SP_MAX_THREADS is an error
 * (SP_E_ARG naming the value). The pool owns its threads. */
#define SP_MAX_THREADS 1024
int sp_pool_create(sp_pool **out, int n_threads, sp_error *err);
void sp_pool_free(sp_pool *pool);
int sp_pool_size(const sp_pool *pool);
/* Calls fn(ctx, i, thread_id) for i in [0, n) across the pool (and the calling thread) and
 * waits. Items are handed out dynamically, so fn must make results independent of which thread
 * ran them (write to slot i) for determinism. pool may be NULL (runs serially). */
void sp_pool_for(sp_pool *pool, long n, void (*fn)(void *ctx, long i, int thread_id), void *ctx);

/* ---- aligned buffers ------------------------------------------------------------------------- */

void *sp_alloc(size_t bytes);        /* 64-byte aligned, NULL on failure or bytes == 0 */
void *sp_calloc(size_t count, size_t size); /* zeroed, overflow-checked */
void sp_free(void *p);

/* ---- small linear algebra (row-major, float) ------------------------------------------------- */

typedef struct { float x, y, z; } sp_vec3;

static inline sp_vec3 sp_v3(float x, float y, float z) { sp_vec3 v = {x, y, z}; return v; }
static inline sp_vec3 sp_v3_add(sp_vec3 a, sp_vec3 b) { return sp_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline sp_vec3 sp_v3_sub(sp_vec3 a, sp_vec3 b) { return sp_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline sp_vec3 sp_v3_scale(sp_vec3 a, float s) { return sp_v3(a.x * s, a.y * s, a.z * s); }
static inline float sp_v3_dot(sp_vec3 a, sp_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline sp_vec3 sp_v3_cross(sp_vec3 a, sp_vec3 b)
{
    return sp_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline float sp_v3_norm(sp_vec3 a) { return sqrtf(sp_v3_dot(a, a)); }
static inline sp_vec3 sp_v3_normalize(sp_vec3 a)
{
    float n = sp_v3_norm(a);
    return n > 0 ? sp_v3_scale(a, 1.0f / n) : a;
}

/* Quaternion (w, x, y, z), need not be normalised, to a row-major rotation matrix. */
static inline void sp_quat_to_mat3(const float q[4], float R[9])
{
    float n = sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    float w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    R[0] = 1 - 2 * (y * y + z * z); R[1] = 2 * (x * y - w * z);     R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z);     R[4] = 1 - 2 * (x * x + z * z); R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y);     R[7] = 2 * (y * z + w * x);     R[8] = 1 - 2 * (x * x + y * y);
}

/* Rotation matrix to unit quaternion (w, x, y, z) with w >= 0 (Shepperd's method). */
void sp_mat3_to_quat(const float R[9], float q[4]);

static inline void sp_mat3_mul(const float A[9], const float B[9], float C[9])
{
    float T[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            T[i * 3 + j] = A[i * 3] * B[j] + A[i * 3 + 1] * B[3 + j] + A[i * 3 + 2] * B[6 + j];
    for (int i = 0; i < 9; i++) C[i] = T[i];
}
static inline void sp_mat3_transpose(const float A[9], float T[9])
{
    float S[9] = {A[0], A[3], A[6], A[1], A[4], A[7], A[2], A[5], A[8]};
    for (int i = 0; i < 9; i++) T[i] = S[i];
}
static inline sp_vec3 sp_mat3_apply(const float A[9], sp_vec3 v)
{
    return sp_v3(A[0] * v.x + A[1] * v.y + A[2] * v.z, A[3] * v.x + A[4] * v.y + A[5] * v.z,
                 A[6] * v.x + A[7] * v.y + A[8] * v.z);
}
/* 4x4 row-major product and rigid inverse ([R t; 0 1] -> [R^T -R^T t; 0 1]). */
void sp_mat4_mul(const float A[16], const float B[16], float C[16]);
void sp_mat4_rigid_inverse(const float A[16], float Ainv[16]);

/* ---- cameras --------------------------------------------------------------------------------- */

/* Distortion models carried from COLMAP; the renderer itself is pinhole (it ignores them), so
 * images of a distorted camera are resampled (sp_camera_remap_*) before they meet renders. */
typedef enum {
    SP_DIST_NONE = 0,
    SP_DIST_SIMPLE_RADIAL, /* k1 */
    SP_DIST_RADIAL,        /* k1 k2 */
    SP_DIST_OPENCV         /* k1 k2 p1 p2 */
} sp_distortion;

/* A pinhole view: intrinsics in pixels and the world-to-camera rigid transform. Camera frame is
 * OpenCV/COLMAP: x right, y down, z forward. x_cam = R * x_world + t. */
typedef struct sp_camera {
    int width, height;
    float fx, fy, cx, cy;
    float R[9]; /* world -> camera rotation, row-major */
    float t[3]; /* world -> camera translation (metres) */
    sp_distortion distortion;
    float dist[4];
} sp_camera;

/* Camera centre in world coordinates: -R^T t. */
sp_vec3 sp_camera_center(const sp_camera *cam);
/* 4x4 world-to-camera matrix. */
void sp_camera_world_to_cam(const sp_camera *cam, float M[16]);
/* Camera whose optical axis points from eye to target, with world `up` (e.g. 0,0,1). */
void sp_camera_look_at(sp_camera *cam, sp_vec3 eye, sp_vec3 target, sp_vec3 up);
/* Scales intrinsics and size for an image downscaled by `factor` (>= 1). */
void sp_camera_downscale(sp_camera *cam, int factor);

/* Cameras from a pose, for previews and agents (render_view_from_splat). */
/* Pinhole intrinsics from an image size and a horizontal field of view: square pixels
 * (fx = fy = width / (2 tan(hfov / 2))), principal point at the image centre (width / 2,
 * height / 2 in the pixel-centre convention), no distortion. The pose is left as it was. */
void sp_camera_intrinsics_fov(sp_camera *cam, int width, int height, float hfov_rad);
/* The pose of a camera at world position pos in a z-up world frame: yaw about +z from +x
 * (yaw 0 looks along +x, pi/2 along +y), pitch up positive (pi/2 looks straight up), no roll;
 * image x to the right, y down. Intrinsics are left as they were. */
void sp_camera_from_pose(sp_camera *cam, const float pos[3], float yaw, float pitch);
/* The pose from a rigid 4x4 row-major camera-to-world matrix whose camera axes are OpenCV's
 * (x right, y down, z forward): R = rotation^T, t = -R translation. */
void sp_camera_set_world_from_cam(sp_camera *cam, const float M[16]);

/* ---- lens distortion ------------------------------------------------------------------------- */

/* COLMAP's distortion of normalised image coordinates (u, v) = (x/z, y/z) for cam's model
 * (SIMPLE_RADIAL k1; RADIAL k1 k2; OPENCV k1 k2 p1 p2; identity for SP_DIST_NONE). */
void sp_camera_distort(const sp_camera *cam, double u, double v, double *ud, double *vd);
/* Its inverse by Newton iteration on the 2x2 Jacobian: 0, or -1 (u, v = ud, vd) where it does not
 * converge or the model folds back there (no ray has that image point). */
int sp_camera_undistort(const sp_camera *cam, double ud, double vd, double *u, double *v);
/* Resamples img [src.height][src.width][channels], as seen through the distorted camera src, into
 * the pinhole camera dst (same pose; dst's size and intrinsics, its distortion ignored): each dst
 * pixel centre's ray is distorted by src's model and src is sampled bilinearly there. Pixels
 * whose ray falls outside src's image (or beyond the fold of its model) get zeros and mask 0;
 * mask [dst.height][dst.width] may be NULL. */
int sp_camera_remap_to_pinhole(const sp_camera *src, const float *img, int channels,
                               const sp_camera *dst, float *out, uint8_t *mask, sp_error *err);
/* The reverse: img from the pinhole camera src (its distortion ignored) into the pixels of the
 * distorted camera dst, each dst pixel undistorted by Newton iteration. Same masking. */
int sp_camera_remap_from_pinhole(const sp_camera *src, const float *img, int channels,
                                 const sp_camera *dst, float *out, uint8_t *mask, sp_error *err);

/* ---- Gaussians ------------------------------------------------------------------------------- */

/* Number of SH coefficients per channel for degree d: (d+1)^2. */
static inline int sp_sh_coeffs(int degree) { return (degree + 1) * (degree + 1); }

/* A Gaussian splat as a struct of arrays (host memory). Owns every buffer.
 *   means          [n][3]          world metres
 *   quats          [n][4]          (w, x, y, z), not necessarily normalised
 *   log_scales     [n][3]          log of per-axis standard deviation (metres)
 *   opacity_logits [n]             opacity = sigmoid(logit)
 *   sh             [n][K][3]       K = (sh_degree+1)^2; sh[i][0] is the DC term (f_dc in PLY)
 *   features       [n][feat_dim]   semantic features (NULL when feat_dim == 0) */
typedef struct sp_splat {
    size_t n;
    int sh_degree;
    int feat_dim;
    float *means;
    float *quats;
    float *log_scales;
    float *opacity_logits;
    float *sh;
    float *features;
} sp_splat;

/* The largest semantic feature dimension (feat_dim, the scene PCA's dim) any stage accepts:
 * the query engine's scorer keeps a text's projections as SP_FEATURE_DIM_MAX floats (one kernel
 * argument on CUDA) and a Gram matrix of its square. `features` refuses a larger --dim at
 * once, feature folders and model folders that claim more are refused when opened, and lift
 * refuses it, so no stage makes a model that no query can open. */
#define SP_FEATURE_DIM_MAX 64

/* 0 when 1 <= dim <= SP_FEATURE_DIM_MAX, else `code` with a message "<what>: feature dim D is
 * outside 1..64 (the limit of 64 ...)" naming the value and the limit. */
int sp_feature_dim_check(int dim, int code, const char *what, sp_error *err);

/* Allocates n Gaussians (contents zeroed, quats set to identity). */
int sp_splat_alloc(sp_splat *s, size_t n, int sh_degree, int feat_dim, sp_error *err);
void sp_splat_free(sp_splat *s);
/* Deep copy. */
int sp_splat_copy(sp_splat *dst, const sp_splat *src, sp_error *err);
/* Checks every value is finite; names the first bad Gaussian and field. */
int sp_splat_check_finite(const sp_splat *s, sp_error *err);

/* SH band-0 constant: colour = 0.5 + C0 * dc (the 3DGS convention). */
#define SP_SH_C0 0.28209479177387814f

static inline float sp_sigmoid(float x) { return 1.0f / (1.0f + expf(-x)); }
static inline float sp_logit(float p) { return logf(p / (1.0f - p)); }

/* ---- text ------------------------------------------------------------------------------------- */

/* A growing NUL-terminated string for reports and descriptions the library returns as text.
 * Zero-initialise; on allocation failure `failed` is set and further appends are dropped. */
typedef struct sp_strbuf {
    char *data;
    size_t len, cap;
    int failed;
} sp_strbuf;

void sp_strbuf_printf(sp_strbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Hands the text over (caller frees with free(); "" when empty) and resets b; NULL when an
 * append failed. */
char *sp_strbuf_take(sp_strbuf *b);
void sp_strbuf_free(sp_strbuf *b);

/* ---- grids and distance transforms ------------------------------------------------------------ */

/* A regular 2D grid of floats over the world's x-y plane (row-major [ny][nx]; cell (ix, iy)
 * covers [origin + i*res, origin + (i+1)*res) on each axis, row 0 at the origin's y, as Nav2's
 * maps and PGM rows read bottom-up). Owns data. Used by view selection, synth's planner and
 * navigation's costmap. */
typedef struct sp_grid2 {
    int nx, ny;
    float res;       /* cell edge, world units (metres) */
    float origin[2]; /* world x, y of cell (0,0)'s lower-left corner */
    float *data;     /* [ny][nx] */
} sp_grid2;

/* The same in 3D ([nz][ny][nx], origin = the lower corner of voxel (0,0,0)). Owns data. */
typedef struct sp_grid3 {
    int nx, ny, nz;
    float res;
    float origin[3];
    float *data; /* [nz][ny][nx] */
} sp_grid3;

/* Allocates a zeroed grid; fails with SP_E_ARG on non-positive sizes or res, SP_E_NOMEM when the
 * cell count overflows or memory is short. *g is left zeroed on error. */
int sp_grid2_alloc(sp_grid2 *g, int nx, int ny, float res, float origin_x, float origin_y,
                   sp_error *err);
int sp_grid3_alloc(sp_grid3 *g, int nx, int ny, int nz, float res, const float origin[3],
                   sp_error *err);
void sp_grid2_free(sp_grid2 *g);
void sp_grid3_free(sp_grid3 *g);

/* World point -> cell index; returns 1 when inside the grid (indices written either way,
 * floor-rounded, so callers can clamp). */
int sp_grid2_cell(const sp_grid2 *g, float x, float y, int *ix, int *iy);
int sp_grid3_cell(const sp_grid3 *g, const float p[3], int idx[3]);
/* Cell centre in world coordinates. */
void sp_grid2_center(const sp_grid2 *g, int ix, int iy, float *x, float *y);
void sp_grid3_center(const sp_grid3 *g, const int idx[3], float p[3]);

/* Exact Euclidean distance transforms (Felzenszwalb & Huttenlocher, "Distance Transforms of
 * Sampled Functions", 2012: separable lower envelopes of parabolas, O(cells)). out[i] is the
 * distance, in world units (cells * res), from cell i's centre to the centre of the nearest
 * cell whose seed is nonzero: 0 on seeds, INFINITY when there is no seed at all. seed and out
 * are [ny][nx] (2D) or [nz][ny][nx] (3D); out may not alias seed. Runs across pool (may be
 * NULL). Fails with SP_E_ARG on bad sizes, SP_E_NOMEM when scratch cannot be allocated. */
int sp_edt2(const uint8_t *seed, int nx, int ny, float res, float *out, sp_pool *pool,
            sp_error *err);
int sp_edt3(const uint8_t *seed, int nx, int ny, int nz, float res, float *out, sp_pool *pool,
            sp_error *err);

/* ---- paths ----------------------------------------------------------------------------------- */

/* Joins a and b with one '/', into out (size cap); returns -1 if truncated. */
int sp_path_join(char *out, size_t cap, const char *a, const char *b);
/* mkdir -p. */
int sp_mkdirs(const char *path, sp_error *err);
int sp_file_exists(const char *path);
/* Reads a whole file into a NUL-terminated malloc'd buffer (caller frees with free()). */
int sp_read_file(const char *path, char **data, size_t *size, sp_error *err);
/* Writes data to path atomically: path.tmp.<pid> then rename. */
int sp_write_file_atomic(const char *path, const void *data, size_t size, sp_error *err);
/* Directory holding shipped data (the tokenizer vocabulary, worlds): $SEMSPLAT_DATA, else the
 * build-time source data/ folder. */
const char *sp_data_dir(void);

#ifdef __cplusplus
}
#endif
#endif
