/* Small linear algebra that is not worth inlining: quaternion extraction, 4x4 products,
 * camera helpers. */
#include "semsplat/core.h"

#include <string.h>

void sp_mat3_to_quat(const float R[9], float q[4])
{
    double m00 = R[0], m01 = R[1], m02 = R[2], m10 = R[3], m11 = R[4], m12 = R[5], m20 = R[6],
           m21 = R[7], m22 = R[8];
    double tr = m00 + m11 + m22, w, x, y, z;
    if (tr > 0) {
        double s = sqrt(tr + 1.0) * 2;
        w = 0.25 * s; x = (m21 - m12) / s; y = (m02 - m20) / s; z = (m10 - m01) / s;
    } else if (m00 > m11 && m00 > m22) {
        double s = sqrt(1.0 + m00 - m11 - m22) * 2;
        w = (m21 - m12) / s; x = 0.25 * s; y = (m01 + m10) / s; z = (m02 + m20) / s;
    } else if (m11 > m22) {
        double s = sqrt(1.0 + m11 - m00 - m22) * 2;
        w = (m02 - m20) / s; x = (m01 + m10) / s; y = 0.25 * s; z = (m12 + m21) / s;
    } else {
        double s = sqrt(1.0 + m22 - m00 - m11) * 2;
        w = (m10 - m01) / s; x = (m02 + m20) / s; y = (m12 + m21) / s; z = 0.25 * s;
    }
    double n = sqrt(w * w + x * x + y * y + z * z);
    if (w < 0) n = -n;
    q[0] = (float)(w / n); q[1] = (float)(x / n); q[2] = (float)(y / n); q[3] = (float)(z / n);
}

void sp_mat4_mul(const float A[16], const float B[16], float C[16])
{
    float T[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float s = 0;
            for (int k = 0; k < 4; k++) s += A[i * 4 + k] * B[k * 4 + j];
            T[i * 4 + j] = s;
        }
    memcpy(C, T, sizeof T);
}

void sp_mat4_rigid_inverse(const float A[16], float Ainv[16])
{
    float R[9] = {A[0], A[1], A[2], A[4], A[5], A[6], A[8], A[9], A[10]}, Rt[9];
    sp_mat3_transpose(R, Rt);
    sp_vec3 t = sp_v3(A[3], A[7], A[11]);
    sp_vec3 ti = sp_v3_scale(sp_mat3_apply(Rt, t), -1.0f);
    float M[16] = {Rt[0], Rt[1], Rt[2], ti.x, Rt[3], Rt[4], Rt[5], ti.y,
                   Rt[6], Rt[7], Rt[8], ti.z, 0,     0,     0,     1};
    memcpy(Ainv, M, sizeof M);
}

sp_vec3 sp_camera_center(const sp_camera *cam)
{
    float Rt[9];
    sp_mat3_transpose(cam->R, Rt);
    return sp_v3_scale(sp_mat3_apply(Rt, sp_v3(cam->t[0], cam->t[1], cam->t[2])), -1.0f);
}

void sp_camera_world_to_cam(const sp_camera *cam, float M[16])
{
    const float *R = cam->R;
    float T[16] = {R[0], R[1], R[2], cam->t[0], R[3], R[4], R[5], cam->t[1],
                   R[6], R[7], R[8], cam->t[2], 0,    0,    0,    1};
    memcpy(M, T, sizeof T);
}

void sp_camera_look_at(sp_camera *cam, sp_vec3 eye, sp_vec3 target, sp_vec3 up)
{
    /* Camera axes in world: z forward, x right, y down (OpenCV). */
    sp_vec3 z = sp_v3_normalize(sp_v3_sub(target, eye));
    sp_vec3 x = sp_v3_cross(z, up);
    if (sp_v3_norm(x) < 1e-6f) x = sp_v3_cross(z, sp_v3(0, 1, 0));
    if (sp_v3_norm(x) < 1e-6f) x = sp_v3_cross(z, sp_v3(1, 0, 0));
    x = sp_v3_normalize(x);
    sp_vec3 y = sp_v3_cross(z, x);
    float R[9] = {x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z};
    memcpy(cam->R, R, sizeof R);
    sp_vec3 t = sp_v3_scale(sp_mat3_apply(R, eye), -1.0f);
    cam->t[0] = t.x; cam->t[1] = t.y; cam->t[2] = t.z;
}

void sp_camera_downscale(sp_camera *cam, int factor)
{
    if (factor <= 1) return;
    float f = (float)factor;
    int w = cam->width / factor, h = cam->height / factor;
    /* Keep the pixel-centre convention: cx' = cx * w'/w. */
    float sx = (float)w / (float)cam->width, sy = (float)h / (float)cam->height;
    cam->fx *= sx; cam->fy *= sy; cam->cx *= sx; cam->cy *= sy;
    cam->width = w; cam->height = h;
    (void)f;
}

void sp_camera_intrinsics_fov(sp_camera *cam, int width, int height, float hfov_rad)
{
    cam->width = width;
    cam->height = height;
    cam->fx = cam->fy = 0.5f * (float)width / tanf(0.5f * hfov_rad);
    cam->cx = 0.5f * (float)width;
    cam->cy = 0.5f * (float)height;
    cam->distortion = SP_DIST_NONE;
    memset(cam->dist, 0, sizeof cam->dist);
}

void sp_camera_from_pose(sp_camera *cam, const float pos[3], float yaw, float pitch)
{
    float cy = cosf(yaw), sy = sinf(yaw), cp = cosf(pitch), sp = sinf(pitch);
    /* forward f = (cp cy, cp sy, sp); right = f x up normalised = (sy, -cy, 0), which stays
     * defined looking straight up or down; down = forward x right */
    sp_vec3 z = sp_v3(cp * cy, cp * sy, sp), x = sp_v3(sy, -cy, 0.f);
    sp_vec3 y = sp_v3_cross(z, x);
    float R[9] = {x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z};
    memcpy(cam->R, R, sizeof R);
    sp_vec3 t = sp_v3_scale(sp_mat3_apply(R, sp_v3(pos[0], pos[1], pos[2])), -1.0f);
    cam->t[0] = t.x; cam->t[1] = t.y; cam->t[2] = t.z;
}

void sp_camera_set_world_from_cam(sp_camera *cam, const float M[16])
{
    float Rwc[9] = {M[0], M[1], M[2], M[4], M[5], M[6], M[8], M[9], M[10]};
    sp_mat3_transpose(Rwc, cam->R);
    sp_vec3 t = sp_v3_scale(sp_mat3_apply(cam->R, sp_v3(M[3], M[7], M[11])), -1.0f);
    cam->t[0] = t.x; cam->t[1] = t.y; cam->t[2] = t.z;
}
