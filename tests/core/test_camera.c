/* Cameras from a pose (sp_camera_intrinsics_fov, sp_camera_from_pose, sp_camera_set_world_from_cam):
 * where known world points land in the image, orthonormal rotations, and the round trip through
 * a camera-to-world matrix. */
#include "semsplat/core.h"
#include "test.h"

/* Pixel coordinates and depth of world point p. */
static void project(const sp_camera *c, sp_vec3 p, float *u, float *v, float *z)
{
    sp_vec3 x = sp_mat3_apply(c->R, p);
    x = sp_v3_add(x, sp_v3(c->t[0], c->t[1], c->t[2]));
    *z = x.z;
    *u = c->fx * x.x / x.z + c->cx;
    *v = c->fy * x.y / x.z + c->cy;
}

static void check_rotation(const sp_camera *c)
{
    float Rt[9], I[9];
    sp_mat3_transpose(c->R, Rt);
    sp_mat3_mul(c->R, Rt, I);
    for (int i = 0; i < 9; i++) CHECK_NEAR(I[i], (i % 4 == 0) ? 1.0 : 0.0, 1e-6);
    float det = c->R[0] * (c->R[4] * c->R[8] - c->R[5] * c->R[7]) -
                c->R[1] * (c->R[3] * c->R[8] - c->R[5] * c->R[6]) +
                c->R[2] * (c->R[3] * c->R[7] - c->R[4] * c->R[6]);
    CHECK_NEAR(det, 1.0, 1e-6);
}

static void test_intrinsics(void)
{
    sp_camera c;
    memset(&c, 0, sizeof c);
    c.distortion = SP_DIST_RADIAL;
    c.dist[0] = 0.1f;
    sp_camera_intrinsics_fov(&c, 640, 480, (float)(M_PI / 2));
    CHECK(c.width == 640 && c.height == 480);
    CHECK_NEAR(c.fx, 320.0, 1e-3);
    CHECK(c.fx == c.fy);
    CHECK(c.cx == 320.f && c.cy == 240.f);
    CHECK(c.distortion == SP_DIST_NONE && c.dist[0] == 0.f);
    sp_camera_intrinsics_fov(&c, 100, 50, 1.0f);
    CHECK_NEAR(c.fx, 50.0 / tan(0.5), 1e-3);
}

static void test_pose(void)
{
    sp_camera c;
    memset(&c, 0, sizeof c);
    sp_camera_intrinsics_fov(&c, 640, 480, (float)(M_PI / 2));
    const float pos[3] = {1, 2, 3};
    float u, v, z;
    /* yaw 0 looks along +x; +x world ahead, -y world is image right, -z is image down */
    sp_camera_from_pose(&c, pos, 0.f, 0.f);
    check_rotation(&c);
    project(&c, sp_v3(3, 2, 3), &u, &v, &z);
    CHECK_NEAR(u, 320, 1e-3); CHECK_NEAR(v, 240, 1e-3); CHECK_NEAR(z, 2, 1e-5);
    project(&c, sp_v3(3, 1, 3), &u, &v, &z);
    CHECK(u > 320 + 100 && fabsf(v - 240) < 1e-3f);
    project(&c, sp_v3(3, 2, 2), &u, &v, &z);
    CHECK(v > 240 + 100 && fabsf(u - 320) < 1e-3f);
    sp_vec3 ctr = sp_camera_center(&c);
    CHECK_NEAR(ctr.x, 1, 1e-5); CHECK_NEAR(ctr.y, 2, 1e-5); CHECK_NEAR(ctr.z, 3, 1e-5);
    /* yaw pi/2 looks along +y */
    sp_camera_from_pose(&c, pos, (float)(M_PI / 2), 0.f);
    project(&c, sp_v3(1, 5, 3), &u, &v, &z);
    CHECK_NEAR(u, 320, 1e-3); CHECK_NEAR(v, 240, 1e-3); CHECK_NEAR(z, 3, 1e-5);
    project(&c, sp_v3(2, 5, 3), &u, &v, &z); /* +x is to the right when looking along +y */
    CHECK(u > 320 + 50);
    /* pitch up positive */
    sp_camera_from_pose(&c, pos, 0.f, (float)(M_PI / 4));
    check_rotation(&c);
    project(&c, sp_v3(2, 2, 4), &u, &v, &z);
    CHECK_NEAR(u, 320, 1e-3); CHECK_NEAR(v, 240, 1e-3);
    /* straight up stays well defined: image right is still -y for yaw 0 */
    sp_camera_from_pose(&c, pos, 0.f, (float)(M_PI / 2));
    check_rotation(&c);
    project(&c, sp_v3(1, 2, 5), &u, &v, &z);
    CHECK_NEAR(u, 320, 1e-3); CHECK_NEAR(v, 240, 1e-3); CHECK_NEAR(z, 2, 1e-5);
    project(&c, sp_v3(1, 1, 5), &u, &v, &z);
    CHECK(u > 320 + 50);
}

static void test_world_from_cam(void)
{
    sp_camera a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    const float pos[3] = {-0.5f, 4.f, 1.2f};
    sp_camera_from_pose(&a, pos, 2.1f, -0.3f);
    float W2C[16], C2W[16];
    sp_camera_world_to_cam(&a, W2C);
    sp_mat4_rigid_inverse(W2C, C2W);
    sp_camera_set_world_from_cam(&b, C2W);
    for (int i = 0; i < 9; i++) CHECK_NEAR(b.R[i], a.R[i], 1e-6);
    for (int i = 0; i < 3; i++) CHECK_NEAR(b.t[i], a.t[i], 1e-5);
    /* the matrix's translation is the camera centre */
    sp_vec3 ctr = sp_camera_center(&b);
    CHECK_NEAR(ctr.x, pos[0], 1e-5); CHECK_NEAR(ctr.y, pos[1], 1e-5); CHECK_NEAR(ctr.z, pos[2], 1e-5);
}

int main(void)
{
    RUN(test_intrinsics);
    RUN(test_pose);
    RUN(test_world_from_cam);
    return TEST_EXIT();
}
