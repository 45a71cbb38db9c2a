/* A bounds-checked XCDR1 reader for ROS 2 samples (private to the ros module). Every read names
 * the field it wanted; the first failure sets the sp_error ("nav_msgs/Odometry: pose.position.x:
 * needs 8 bytes at offset 44, the sample has 40") and later reads fail at once, so decoders read
 * straight through and check once. Offsets in messages count from the sample's first byte
 * (the encapsulation header included), as a hex dump shows them. */
#ifndef SP_ROS_CDR_H
#define SP_ROS_CDR_H

#include <stddef.h>
#include <stdint.h>

#include "semsplat/ros.h"

typedef struct cdr_in {
    const uint8_t *body; /* after the 4-byte encapsulation header; alignment is relative to it */
    size_t size;         /* bytes in body */
    size_t pos;
    int swap;            /* sample byte order differs from ours */
    const char *type;    /* ROS type name for messages, "nav_msgs/Odometry" */
    sp_error *err;
    int failed;
} cdr_in;

/* Checks the encapsulation header (CDR_BE 00 00 or CDR_LE 00 01; XCDR2 and parameter lists are
 * refused, as rmw_cyclonedds sends neither) and starts reading after it. */
int cdr_begin(cdr_in *in, const uint8_t *bytes, size_t size, const char *type, sp_error *err);
/* Fails the read with a message about `prefix.field` (either may be NULL). */
int cdr_fail(cdr_in *in, const char *prefix, const char *field, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

int cdr_u8(cdr_in *in, const char *prefix, const char *field, uint8_t *v);
int cdr_i8(cdr_in *in, const char *prefix, const char *field, int8_t *v);
int cdr_bool(cdr_in *in, const char *prefix, const char *field, int *v);
int cdr_i16(cdr_in *in, const char *prefix, const char *field, int16_t *v);
int cdr_u16(cdr_in *in, const char *prefix, const char *field, uint16_t *v);
int cdr_i32(cdr_in *in, const char *prefix, const char *field, int32_t *v);
int cdr_u32(cdr_in *in, const char *prefix, const char *field, uint32_t *v);
int cdr_u64(cdr_in *in, const char *prefix, const char *field, uint64_t *v);
int cdr_i64(cdr_in *in, const char *prefix, const char *field, int64_t *v);
int cdr_f32(cdr_in *in, const char *prefix, const char *field, float *v);
int cdr_f64(cdr_in *in, const char *prefix, const char *field, double *v);
/* n raw bytes (uint8 arrays: no alignment, no count). */
int cdr_bytes(cdr_in *in, const char *prefix, const char *field, void *out, size_t n);
/* Skips n float64 (covariances), aligned. */
int cdr_skip_f64(cdr_in *in, const char *prefix, const char *field, size_t n);
/* A string: uint32 length counting the NUL, the bytes, the NUL. Copied into out[cap]; a longer
 * one fails unless `cut` is set, then it is cut and ends in "...". */
int cdr_string(cdr_in *in, const char *prefix, const char *field, char *out, size_t cap, int cut);
/* A sequence count, checked against the bytes left: each element needs at least min_elem bytes. */
int cdr_count(cdr_in *in, const char *prefix, const char *field, size_t min_elem, size_t *n);

/* ROS building blocks. Times are returned as seconds. */
int cdr_time(cdr_in *in, const char *prefix, double *seconds);
int cdr_duration(cdr_in *in, const char *prefix, double *seconds);
/* std_msgs/Header: stamp, frame_id. */
int cdr_header(cdr_in *in, const char *prefix, double *stamp_s, char *frame, size_t cap);
/* geometry_msgs/Pose into a planar pose; q (may be NULL) receives x, y, z, w. Non-finite values
 * fail with SP_E_NUMERIC. */
int cdr_pose(cdr_in *in, const char *prefix, sp_ros_pose *pose, double q[4]);
/* geometry_msgs/PoseStamped. */
int cdr_pose_stamped(cdr_in *in, const char *prefix, sp_ros_pose *pose, char *frame, size_t cap);
int cdr_rpc_header(cdr_in *in, sp_ros_rpc_header *h);
/* The decoder's result: 0, or the recorded error code. */
int cdr_end(cdr_in *in);

#endif
