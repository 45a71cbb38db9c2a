/* semsplat io: the files robotics users already have and the ones we write.
 *   COLMAP models (binary and text: cameras, images, points3D), splat PLY (3DGS / gsplat layout
 *   plus f_sem_* features), PNG/JPEG images, .npy arrays, safetensors (mmap), JSON (cJSON).
 * Readers validate counts against the file size before allocating, reject NaN where a value must
 * be finite, and name the file and record at fault. Writers write to a temporary name and rename.
 * Every struct filled by a reader owns its memory; free it with the matching *_free().
 * Each reader also has an in-memory form (*_parse / sp_image_decode) for bytes that are not a
 * file (a network body, an archive member, the fuzz harnesses): the same checks and messages,
 * with `name` standing for the path; the bytes are only read. */
#ifndef SEMSPLAT_IO_H
#define SEMSPLAT_IO_H

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- COLMAP ----------------------------------------------------------------------------------- */

/* COLMAP camera model ids (src/colmap/sensor/models.h). Models we read but do not undistort are
 * kept with their parameters; sp_colmap_camera_to_sp rejects them with a clear message. */
typedef enum {
    SP_COLMAP_SIMPLE_PINHOLE = 0, /* f cx cy */
    SP_COLMAP_PINHOLE = 1,        /* fx fy cx cy */
    SP_COLMAP_SIMPLE_RADIAL = 2,  /* f cx cy k */
    SP_COLMAP_RADIAL = 3,         /* f cx cy k1 k2 */
    SP_COLMAP_OPENCV = 4,         /* fx fy cx cy k1 k2 p1 p2 */
    SP_COLMAP_OPENCV_FISHEYE = 5,
    SP_COLMAP_FULL_OPENCV = 6,
    SP_COLMAP_FOV = 7,
    SP_COLMAP_SIMPLE_RADIAL_FISHEYE = 8,
    SP_COLMAP_RADIAL_FISHEYE = 9,
    SP_COLMAP_THIN_PRISM_FISHEYE = 10
} sp_colmap_model_id;

const char *sp_colmap_model_name(int model);  /* "PINHOLE", ... or NULL */
int sp_colmap_model_from_name(const char *name); /* id, or -1 */
int sp_colmap_model_num_params(int model);    /* or -1 */

typedef struct sp_colmap_camera {
    uint32_t id;
    int model;
    uint64_t width, height;
    int n_params;
    double params[16];
} sp_colmap_camera;

typedef struct sp_colmap_image {
    uint32_t id;
    double qvec[4]; /* world-to-camera rotation (w, x, y, z) */
    double tvec[3]; /* world-to-camera translation */
    uint32_t camera_id;
    char *name;
    size_t n_points2d;
    double *xys;           /* [n_points2d][2] */
    int64_t *point3d_ids;  /* [n_points2d], -1 = none */
} sp_colmap_image;

typedef struct sp_colmap_point {
    uint64_t id;
    double xyz[3];
    uint8_t rgb[3];
    double error;
    size_t track_len;
    uint32_t *track; /* [track_len][2]: image_id, point2d_idx */
} sp_colmap_point;

typedef struct sp_colmap_model {
    size_t n_cameras, n_images, n_points;
    sp_colmap_camera *cameras;
    sp_colmap_image *images;
    sp_colmap_point *points;
} sp_colmap_model;

/* Reads a model folder holding cameras/images/points3D as .bin (preferred) or .txt. `dir` may be
 * the folder itself or a capture root holding sparse/0/ or sparse/. */
int sp_colmap_read(const char *dir, sp_colmap_model *m, sp_error *err);
int sp_colmap_read_bin(const char *dir, sp_colmap_model *m, sp_error *err);
int sp_colmap_read_txt(const char *dir, sp_colmap_model *m, sp_error *err);
int sp_colmap_write_bin(const char *dir, const sp_colmap_model *m, sp_error *err);
int sp_colmap_write_txt(const char *dir, const sp_colmap_model *m, sp_error *err);
void sp_colmap_free(sp_colmap_model *m);
/* In memory: one model file (cameras, images or points3D, binary or text) into that part of m,
 * which must not hold it yet (start from a zeroed model). Does not run the cross-file checks that
 * sp_colmap_read does (unique ids, cameras that images name). On error free m with sp_colmap_free. */
typedef enum { SP_COLMAP_CAMERAS = 0, SP_COLMAP_IMAGES = 1, SP_COLMAP_POINTS = 2 } sp_colmap_part;
int sp_colmap_parse_bin(sp_colmap_part part, const void *data, size_t size, const char *name,
                        sp_colmap_model *m, sp_error *err);
int sp_colmap_parse_txt(sp_colmap_part part, const char *text, size_t size, const char *name,
                        sp_colmap_model *m, sp_error *err);
/* Resolves `dir` (capture root or model folder) to the folder holding the model files. */
int sp_colmap_find_model_dir(const char *dir, char *out, size_t cap, sp_error *err);

const sp_colmap_camera *sp_colmap_find_camera(const sp_colmap_model *m, uint32_t id);
/* Fills a pinhole sp_camera (intrinsics and world-to-camera pose) for image index i. Radial /
 * OpenCV distortion is carried in cam->distortion; other models fail with SP_E_UNSUPPORTED. */
int sp_colmap_image_camera(const sp_colmap_model *m, size_t i, sp_camera *cam, sp_error *err);
/* The inverse for the pose: sets im->qvec / im->tvec from cam's world-to-camera R, t. */
void sp_colmap_image_set_pose(sp_colmap_image *im, const sp_camera *cam);

/* ---- splat PLY -------------------------------------------------------------------------------- */

/* Reads a binary little-endian or ascii PLY in the 3DGS/gsplat layout: x y z [nx ny nz]
 * f_dc_0..2 f_rest_0..(3(K-1)-1) opacity scale_0..2 rot_0..3 [f_sem_0..d-1]; SH degree inferred
 * from the f_rest count (0, 9, 24, 45). Any property order, float or double properties. */
int sp_ply_read_splat(const char *path, sp_splat *s, sp_error *err);
int sp_ply_parse_splat(const void *data, size_t size, const char *name, sp_splat *s, sp_error *err);
/* Writes binary little-endian in the same layout (f_sem_* when s->feat_dim > 0), atomically. */
int sp_ply_write_splat(const char *path, const sp_splat *s, sp_error *err);

/* ---- images ----------------------------------------------------------------------------------- */

typedef struct sp_image {
    int width, height, channels; /* channels 1..4 */
    int bit_depth;               /* 8 or 16 */
    void *data;                  /* [H][W][C] uint8_t or uint16_t */
} sp_image;

/* PNG or JPEG by content (not extension). 8-bit output unless the PNG is 16-bit. */
int sp_image_read(const char *path, sp_image *img, sp_error *err);
int sp_image_decode(const void *data, size_t size, const char *name, sp_image *img, sp_error *err);
int sp_image_write_png(const char *path, const sp_image *img, sp_error *err);
int sp_image_write_jpeg(const char *path, const sp_image *img, int quality, sp_error *err);
void sp_image_free(sp_image *img);
/* Float [H][W][3] RGB in [0,1] from an 8/16-bit image (grey expanded, alpha dropped). */
int sp_image_to_rgbf(const sp_image *img, float **rgb, sp_error *err);
/* Writes a float [H][W][C] image in [0,1] (clamped) as 8-bit PNG, C in 1..4. */
int sp_write_png_f32(const char *path, const float *data, int width, int height, int channels,
                     sp_error *err);

/* ---- .npy ------------------------------------------------------------------------------------- */

typedef enum {
    SP_DTYPE_F32 = 0,
    SP_DTYPE_F16,
    SP_DTYPE_U8,
    SP_DTYPE_I32,
    SP_DTYPE_U16,
    SP_DTYPE_F64,
    SP_DTYPE_I64,
    SP_DTYPE_BF16
} sp_dtype;

size_t sp_dtype_size(sp_dtype t);

typedef struct sp_npy {
    sp_dtype dtype;
    int ndim;
    size_t shape[8];
    void *data; /* C order */
} sp_npy;

/* Reads .npy version 1/2/3, little-endian, C or Fortran order (Fortran is transposed to C). */
int sp_npy_read(const char *path, sp_npy *a, sp_error *err);
int sp_npy_parse(const void *data, size_t size, const char *name, sp_npy *a, sp_error *err);
/* Writes C-order little-endian .npy atomically; dtype F32, F16, U8, I32, U16, F64, I64. */
int sp_npy_write(const char *path, sp_dtype dtype, int ndim, const size_t *shape, const void *data,
                 sp_error *err);
size_t sp_npy_count(const sp_npy *a);
/* Converts any numeric dtype to a new float32 buffer (caller frees with free()). */
int sp_npy_to_f32(const sp_npy *a, float **out, sp_error *err);
void sp_npy_free(sp_npy *a);

float sp_half_to_float(uint16_t h);
uint16_t sp_float_to_half(float f);
float sp_bf16_to_float(uint16_t h);

/* ---- safetensors ------------------------------------------------------------------------------ */

typedef struct sp_tensor_info {
    char name[256];
    sp_dtype dtype;
    int ndim;
    size_t shape[8];
    const void *data; /* into the mapping */
    size_t nbytes;
} sp_tensor_info;

typedef struct sp_safetensors {
    void *map;
    size_t map_size;
    size_t n;
    sp_tensor_info *tensors;
} sp_safetensors;

/* mmaps the file, parses the JSON header, checks every tensor's offsets and sizes. */
int sp_safetensors_open(const char *path, sp_safetensors *st, sp_error *err);
/* The same on bytes in memory: st->map stays NULL and the tensors point into data, which must
 * outlive st; sp_safetensors_close frees only the table. */
int sp_safetensors_parse(const void *data, size_t size, const char *name, sp_safetensors *st,
                         sp_error *err);
void sp_safetensors_close(sp_safetensors *st);
const sp_tensor_info *sp_safetensors_find(const sp_safetensors *st, const char *name);
/* Writes tensors (host data) as a safetensors file atomically. */
int sp_safetensors_write(const char *path, const sp_tensor_info *tensors, size_t n, sp_error *err);

/* ---- frames (frame.json) ---------------------------------------------------------------------- */

/* Which frame a model or capture folder's coordinates are in. x_world = world_from_model x_model,
 * where "model" coordinates are the splat as stored and the COLMAP poses of its capture.
 *   source "synth":  a synth capture; the model frame IS the SDF world frame (identity, metres, +z up)
 *   source "align":  `semsplat align` fitted world_from_model (metres, +z up in the world)
 *   source "colmap": a plain reconstruction; identity, positions are in COLMAP's arbitrary frame
 *                    (scale and up unknown) and are not world positions.
 * File: {"format": "semsplat-frame-1", "source", "frame": "world"|"colmap", "world_from_model":
 * 4 rows of 4 numbers (a similarity [sR t; 0 0 0 1]), "up", "units", "residual_m" (align's fit
 * residual or null), "note", and from align --matches "fit" (the robust fit's report)}. */
typedef struct sp_frame {
    double world_from_model[16]; /* row-major */
    char source[16];             /* "synth", "align", "colmap" */
    char up[8];                  /* "+z" or "unknown" */
    char units[16];              /* "m" or "unknown" */
    double residual_m;           /* align: RMS of the fit in world units; < 0 = none */
    char note[256];              /* how it was made (free text, may be empty) */
} sp_frame;

/* Identity frame of a source: synth/align get "+z" and "m", colmap "unknown" for both. */
void sp_frame_init(sp_frame *f, const char *source);
int sp_frame_is_world(const sp_frame *f);       /* 1 for synth and align */
const char *sp_frame_name(const sp_frame *f);   /* "world" or "colmap" */
double sp_frame_scale(const sp_frame *f);       /* s of world_from_model */
/* Finite, last row 0 0 0 1, a similarity with positive scale, a known source; `what` names it. */
int sp_frame_check(const sp_frame *f, const char *what, sp_error *err);
int sp_frame_read(const char *path, sp_frame *f, sp_error *err);
int sp_frame_write(const char *path, const sp_frame *f, sp_error *err); /* atomic; checks first */
/* The same with the fit that made the frame recorded under "fit" (fit_json: a JSON object's text,
 * e.g. sp_align_fit_json's: matches, inliers, residuals, the outlying images); NULL = none. */
int sp_frame_write_fit(const char *path, const sp_frame *f, const char *fit_json, sp_error *err);
/* The frame of a capture: <dir>/frame.json, or the capture root's when dir is its sparse/<n>
 * model folder; else a capture with ground_truth.json (synth's, before frame.json existed) is
 * "synth"; else "colmap". */
int sp_frame_of_capture(const char *colmap_dir, sp_frame *f, sp_error *err);
/* The frame of a model folder: <model>/frame.json, else that of its capture (may be NULL). */
int sp_frame_of_model(const char *model_dir, const char *colmap_dir, sp_frame *f, sp_error *err);
/* Model -> world for a point, and for a camera (pixels unchanged, t in world units). */
void sp_frame_apply_point(const sp_frame *f, const float in[3], float out[3]);
void sp_frame_apply_camera(const sp_frame *f, sp_camera *cam);

/* ---- descriptions ------------------------------------------------------------------------------- */

/* What is in PATH (COLMAP model folder or capture root, splat PLY, PNG/JPEG, .npy, safetensors;
 * recognised by content) as text lines: counts, sizes, extents, value ranges. all: list every
 * camera / tensor (else the first 20). *text is malloc'd (caller frees with free()). */
int sp_io_describe(const char *path, int all, char **text, sp_error *err);

/* ---- JSON (cJSON) ----------------------------------------------------------------------------- */

struct cJSON;
/* Parses a file; errors name the file, line and column. */
int sp_json_read_file(const char *path, struct cJSON **out, sp_error *err);
/* text need not be NUL-terminated; a NUL inside the size is an error (as in a file). */
int sp_json_parse(const char *text, size_t size, const char *name, struct cJSON **out, sp_error *err);
/* 0 and *out when v is a number holding an integer in [lo, hi] (|lo|, |hi| < 2^53), else -1.
 * The one way to read an integer field: a plain (int)valuedouble is undefined for 1e300. */
int sp_json_int(const struct cJSON *v, long lo, long hi, long *out);
/* A number node that reads back bit for bit (the shortest of %.15g..%.17g that does; cJSON's own
 * printing keeps 15 digits when they are within an epsilon, which can move the last bit).
 * NULL when d is not finite or memory runs out. */
struct cJSON *sp_json_number_exact(double d);
/* Pretty-prints to path atomically. */
int sp_json_write_file(const char *path, const struct cJSON *json, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
