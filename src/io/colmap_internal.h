/* Private to the COLMAP reader/writer: checks shared by the binary and text paths, so both
 * formats reject the same things with the same words. */
#ifndef SP_IO_COLMAP_INTERNAL_H
#define SP_IO_COLMAP_INTERNAL_H

#include "io_internal.h"

/* Smallest on-disk record sizes of the binary format, used to bound counts by the bytes left
 * before allocating: camera = id 4 + model 4 + width 8 + height 8 + >= 3 params * 8;
 * image = id 4 + qvec 32 + tvec 24 + camera 4 + name >= 1 + n_points2d 8;
 * point = id 8 + xyz 24 + rgb 3 + error 8 + track_len 8. */
#define COLMAP_MIN_CAMERA_BYTES 48
#define COLMAP_MIN_IMAGE_BYTES 73
#define COLMAP_MIN_POINT_BYTES 51
#define COLMAP_POINT2D_BYTES 24
#define COLMAP_TRACK_BYTES 8
/* A camera wider or taller than this is a corrupt record, not a sensor. */
#define COLMAP_MAX_SIZE ((uint64_t)1 << 20)

/* Each returns 0 or an error naming `file` and the record (`rec` is its 0-based index). */
int colmap_check_camera(const char *file, size_t rec, const sp_colmap_camera *c, sp_error *err);
int colmap_check_image(const char *file, size_t rec, const sp_colmap_image *im, sp_error *err);
int colmap_check_point(const char *file, size_t rec, const sp_colmap_point *p, sp_error *err);
/* An in-memory parse may fill `part` of m: a valid part that m does not hold yet. */
int colmap_check_part(sp_colmap_part part, const char *name, const sp_colmap_model *m, sp_error *err);
/* Reads the three files <dir>/{cameras,images,points3D}.<ext> with `parse`, then the cross-file
 * checks; on error m is freed. */
typedef int (*colmap_parse_fn)(sp_colmap_part part, const void *data, size_t size, const char *name,
                               sp_colmap_model *m, sp_error *err);
int colmap_read_dir(const char *dir, const char *ext, colmap_parse_fn parse, sp_colmap_model *m, sp_error *err);
/* Duplicate camera / image ids and images naming a camera the model lacks. */
int colmap_check_model(const char *dir, const sp_colmap_model *m, const char *ext, sp_error *err);

#endif
