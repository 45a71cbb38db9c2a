/* Bounds-checked XCDR1 reading (see cdr.h): alignment of n-byte primitives to min(n, 8) relative
 * to the byte after the encapsulation header, strings with their NUL, counts checked against
 * the bytes left before anything is allocated. */
#include "cdr.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static int host_is_little(void)
{
    const uint16_t one = 1;
    return *(const uint8_t *)&one == 1;
}

int cdr_begin(cdr_in *in, const uint8_t *bytes, size_t size, const char *type, sp_error *err)
{
    memset(in, 0, sizeof *in);
    in->type = type;
    in->err = err;
    if (!bytes && size) return cdr_fail(in, NULL, NULL, "no bytes");
    if (size < 4)
        return cdr_fail(in, NULL, "encapsulation",
                        "needs the 4-byte encapsulation header, the sample has %zu bytes", size);
    /* RTPS encapsulation identifiers: 00 00 CDR_BE, 00 01 CDR_LE; 00 02/03 are parameter lists,
     * 00 06..0b XCDR2 ones, none of which a ROS 2 peer sends for these types. */
    if (bytes[0] != 0 || bytes[1] > 1)
        return cdr_fail(in, NULL, "encapsulation",
                        "identifier %02x %02x is not plain CDR (00 00 big- or 00 01 "
                        "little-endian)", bytes[0], bytes[1]);
    int little = bytes[1] == 1;
    in->swap = little != host_is_little();
    in->body = bytes + 4;
    in->size = size - 4;
    return 0;
}

int cdr_fail(cdr_in *in, const char *prefix, const char *field, const char *fmt, ...)
{
    if (in->failed) return -1;
    in->failed = SP_E_FORMAT;
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    sp_error_set(in->err, SP_E_FORMAT, "%s: %s%s%s%s%s", in->type ? in->type : "sample",
                 prefix ? prefix : "", prefix && field ? "." : "", field ? field : "",
                 prefix || field ? ": " : "", what);
    return -1;
}

/* Aligns to `align` and makes sure n bytes follow; returns a pointer to them or NULL. */
static const uint8_t *take(cdr_in *in, const char *prefix, const char *field, size_t align,
                           size_t n)
{
    if (in->failed) return NULL;
    size_t pos = in->pos;
    if (align > 1) pos = (pos + align - 1) / align * align;
    if (pos > in->size || n > in->size - pos) {
        cdr_fail(in, prefix, field, "needs %zu bytes at offset %zu, the sample has %zu", n,
                 pos + 4, in->size + 4);
        return NULL;
    }
    in->pos = pos + n;
    return in->body + pos;
}

static void load(cdr_in *in, const uint8_t *p, void *v, size_t n)
{
    uint8_t tmp[8];
    if (in->swap)
        for (size_t i = 0; i < n; i++) tmp[i] = p[n - 1 - i];
    else
        memcpy(tmp, p, n);
    memcpy(v, tmp, n);
}

#define CDR_PRIM(name, type)                                                                   \
    int name(cdr_in *in, const char *prefix, const char *field, type *v)                       \
    {                                                                                          \
        const uint8_t *p = take(in, prefix, field, sizeof(type), sizeof(type));                \
        if (!p) return -1;                                                                     \
        load(in, p, v, sizeof(type));                                                          \
        return 0;                                                                              \
    }
CDR_PRIM(cdr_u8, uint8_t)
CDR_PRIM(cdr_i8, int8_t)
CDR_PRIM(cdr_i16, int16_t)
CDR_PRIM(cdr_u16, uint16_t)
CDR_PRIM(cdr_i32, int32_t)
CDR_PRIM(cdr_u32, uint32_t)
CDR_PRIM(cdr_u64, uint64_t)
CDR_PRIM(cdr_i64, int64_t)
CDR_PRIM(cdr_f32, float)
CDR_PRIM(cdr_f64, double)
#undef CDR_PRIM

int cdr_bool(cdr_in *in, const char *prefix, const char *field, int *v)
{
    uint8_t b;
    if (cdr_u8(in, prefix, field, &b)) return -1;
    /* CDR booleans are 0 or 1; anything else is a misaligned or foreign layout. */
    if (b > 1) return cdr_fail(in, prefix, field, "boolean is %u (0 or 1 expected)", b);
    *v = b;
    return 0;
}

int cdr_bytes(cdr_in *in, const char *prefix, const char *field, void *out, size_t n)
{
    const uint8_t *p = take(in, prefix, field, 1, n);
    if (!p) return -1;
    if (n) memcpy(out, p, n); /* an empty sequence: out may be NULL */
    return 0;
}

int cdr_skip_f64(cdr_in *in, const char *prefix, const char *field, size_t n)
{
    return take(in, prefix, field, 8, n * 8) ? 0 : -1;
}

int cdr_string(cdr_in *in, const char *prefix, const char *field, char *out, size_t cap, int cut)
{
    uint32_t len;
    if (cdr_u32(in, prefix, field, &len)) return -1;
    /* Every ROS serializer writes at least the NUL (the empty string is length 1). */
    if (len == 0) return cdr_fail(in, prefix, field, "string length 0 (at least the NUL)");
    size_t at = in->pos + 4;
    const uint8_t *p = take(in, prefix, field, 1, len);
    if (!p) return -1;
    if (p[len - 1] != 0)
        return cdr_fail(in, prefix, field, "string of %u bytes at offset %zu lacks its NUL", len,
                        at);
    size_t n = len - 1;
    if (n + 1 > cap) {
        if (!cut || cap < 4)
            return cdr_fail(in, prefix, field, "string of %zu bytes is longer than %zu", n,
                            cap - 1);
        memcpy(out, p, cap - 4);
        memcpy(out + cap - 4, "...", 4);
        return 0;
    }
    memcpy(out, p, n);
    out[n] = 0;
    return 0;
}

int cdr_count(cdr_in *in, const char *prefix, const char *field, size_t min_elem, size_t *n)
{
    uint32_t c;
    if (cdr_u32(in, prefix, field, &c)) return -1;
    size_t left = in->size - in->pos;
    if (min_elem && c > left / min_elem)
        return cdr_fail(in, prefix, field,
                        "sequence of %u elements (at least %zu bytes each) but only %zu bytes "
                        "follow", c, min_elem, left);
    *n = c;
    return 0;
}

static int cdr_sec_nsec(cdr_in *in, const char *prefix, double *seconds)
{
    int32_t sec;
    uint32_t nsec;
    if (cdr_i32(in, prefix, "sec", &sec) || cdr_u32(in, prefix, "nanosec", &nsec)) return -1;
    if (nsec >= 1000000000u)
        return cdr_fail(in, prefix, "nanosec", "%u is not below 1e9", nsec);
    *seconds = (double)sec + nsec * 1e-9;
    return 0;
}

int cdr_time(cdr_in *in, const char *prefix, double *seconds)
{
    return cdr_sec_nsec(in, prefix, seconds);
}

int cdr_duration(cdr_in *in, const char *prefix, double *seconds)
{
    return cdr_sec_nsec(in, prefix, seconds);
}

int cdr_header(cdr_in *in, const char *prefix, double *stamp_s, char *frame, size_t cap)
{
    char p[160];
    snprintf(p, sizeof p, "%s%sstamp", prefix ? prefix : "", prefix ? "." : "");
    if (cdr_time(in, p, stamp_s)) return -1;
    return cdr_string(in, prefix, "frame_id", frame, cap, 0);
}

int cdr_pose(cdr_in *in, const char *prefix, sp_ros_pose *pose, double q[4])
{
    static const char *names[7] = {"position.x",    "position.y",    "position.z",
                                   "orientation.x", "orientation.y", "orientation.z",
                                   "orientation.w"};
    double v[7];
    for (int i = 0; i < 7; i++) {
        if (cdr_f64(in, prefix, names[i], &v[i])) return -1;
        if (!isfinite(v[i])) {
            cdr_fail(in, prefix, names[i], "%g is not finite", v[i]);
            in->failed = SP_E_NUMERIC;
            if (in->err) in->err->code = SP_E_NUMERIC;
            return -1;
        }
    }
    pose->x = v[0];
    pose->y = v[1];
    pose->z = v[2];
    pose->yaw = sp_ros_quat_yaw(v[3], v[4], v[5], v[6]);
    if (q) memcpy(q, v + 3, 4 * sizeof(double));
    return 0;
}

int cdr_pose_stamped(cdr_in *in, const char *prefix, sp_ros_pose *pose, char *frame, size_t cap)
{
    char p[160];
    double stamp;
    snprintf(p, sizeof p, "%s%sheader", prefix ? prefix : "", prefix ? "." : "");
    if (cdr_header(in, p, &stamp, frame, cap)) return -1;
    snprintf(p, sizeof p, "%s%spose", prefix ? prefix : "", prefix ? "." : "");
    return cdr_pose(in, p, pose, NULL);
}

int cdr_rpc_header(cdr_in *in, sp_ros_rpc_header *h)
{
    if (cdr_u64(in, "request_header", "guid", &h->guid)) return -1;
    return cdr_i64(in, "request_header", "seq", &h->seq);
}

int cdr_end(cdr_in *in)
{
    return in->failed ? in->failed : 0;
}

double sp_ros_quat_yaw(double qx, double qy, double qz, double qw)
{
    /* Scaled by the largest component first: any finite quaternion, however far from unit length
     * (a malformed sample), then gives a finite yaw instead of inf - inf = NaN. */
    double m = fmax(fmax(fabs(qx), fabs(qy)), fmax(fabs(qz), fabs(qw)));
    if (!(m > 0) || !isfinite(m)) return 0.0;
    qx /= m;
    qy /= m;
    qz /= m;
    qw /= m;
    double n2 = qx * qx + qy * qy + qz * qz + qw * qw;
    return atan2(2.0 * (qw * qz + qx * qy), n2 - 2.0 * (qy * qy + qz * qz));
}

void sp_ros_yaw_quat(double yaw, double *qx, double *qy, double *qz, double *qw)
{
    *qx = 0;
    *qy = 0;
    *qz = sin(yaw * 0.5);
    *qw = cos(yaw * 0.5);
}
