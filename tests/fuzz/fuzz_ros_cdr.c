/* ROS 2 samples as DDS carries them (the sp_ros_decode_* CDR readers, any bytes): the first byte
 * picks the message type (byte % 16; the result responses read as Humble or Jazzy by the next
 * bit), the rest is the serialized sample. Never a crash, a clear error, finite decoded poses.
 * Seeds: the library's own encoders (the bridge's and the robot's writers), written into the
 * corpus folder named by FZ_WRITE_SEEDS when set (tests/fuzz/make_seeds.py does), in builds that
 * have them (Cyclone DDS). */
#include "fuzz_util.h"
#include "ros/ros_internal.h"
#include "semsplat/ros.h"

static int decode(int which, const uint8_t *b, size_t n, sp_error *err)
{
    sp_ros_distro distro = which & 16 ? SP_ROS_DISTRO_JAZZY : SP_ROS_DISTRO_HUMBLE;
    int rc;
    switch (which % 16) {
    case 0: { sp_ros_odom o; rc = sp_ros_decode_odometry(b, n, &o, err);
              if (!rc) FZ_ASSERT(isfinite(o.pose.x) && isfinite(o.pose.y) && isfinite(o.pose.yaw), "odom pose");
              return rc; }
    case 1: { sp_ros_path p; rc = sp_ros_decode_path(b, n, &p, err); sp_ros_path_free(&p); return rc; }
    case 2: { sp_ros_grid g; memset(&g, 0, sizeof g); rc = sp_ros_decode_occupancy_grid(b, n, &g, err);
              sp_ros_grid_free(&g); return rc; }
    case 3: { sp_ros_transform t; return sp_ros_decode_tf_message(b, n, &t, err); }
    case 4: { sp_ros_transform t; rc = sp_ros_decode_tf_find(b, n, "odom", "base_link", &t, err);
              return rc; }
    case 5: { sp_ros_goal_request r; return sp_ros_decode_nav_goal_request(b, n, &r, err); }
    case 6: { sp_ros_goal_request r; return sp_ros_decode_path_goal_request(b, n, &r, err); }
    case 7: { sp_ros_goal_response r; return sp_ros_decode_goal_response(b, n, &r, err); }
    case 8: { sp_ros_goal_id_request r; return sp_ros_decode_goal_id_request(b, n, &r, err); }
    case 9: { sp_ros_result_response r; memset(&r, 0, sizeof r); rc = sp_ros_decode_nav_result_response(b, n, distro, &r, err);
              sp_ros_result_response_free(&r); return rc; }
    case 10: { sp_ros_result_response r; memset(&r, 0, sizeof r); rc = sp_ros_decode_path_result_response(b, n, distro, &r, err);
               sp_ros_result_response_free(&r); return rc; }
    case 11: { sp_ros_feedback_message m; return sp_ros_decode_nav_feedback_message(b, n, &m, err); }
    case 12: { sp_ros_status_array a; memset(&a, 0, sizeof a); rc = sp_ros_decode_goal_status_array(b, n, &a, err);
               sp_ros_status_array_free(&a); return rc; }
    case 13: { sp_ros_cancel_request r; return sp_ros_decode_cancel_request(b, n, &r, err); }
    default: { sp_ros_cancel_response r; return sp_ros_decode_cancel_response(b, n, &r, err); }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    sp_error err = {0};
    int rc = decode(data[0], data + 1, size - 1, &err);
    if (rc) fz_check_error(rc, &err, "sp_ros_decode_*");
    return 0;
}

/* ---- seeds from the encoders (absent without Cyclone DDS: weak) ------------------------------- */

/* declared in ros_internal.h; weak here so a build without them still links (they are then NULL) */
#pragma weak ros_encode_odometry
#pragma weak ros_encode_occupancy_grid
#pragma weak ros_encode_path
#pragma weak ros_encode_nav_goal_request
#pragma weak ros_encode_nav_feedback_message
#pragma weak ros_encode_nav_result_response
#pragma weak ros_encode_goal_status_array
#pragma weak ros_encode_tf

static void seed(const char *dir, const char *name, int which, uint8_t *b, size_t n, int rc)
{
    if (rc || !b) return;
    char p[1200];
    snprintf(p, sizeof p, "%s/seed_%s", dir, name);
    FILE *f = fopen(p, "wb");
    if (f) {
        fputc(which, f);
        fwrite(b, 1, n, f);
        fclose(f);
    }
    free(b);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    const char *dir = getenv("FZ_WRITE_SEEDS");
    if (!dir || !ros_encode_odometry) return 0;
    uint8_t *b = NULL;
    size_t n = 0;
    sp_error err = {0};
    sp_ros_odom o = {.pose = {1, 2, 0, 0.5}, .qw = 1, .vx = 0.2, .stamp_s = 12.5, .frame_id = "odom",
                     .child_frame_id = "base_link"};
    double cov[36] = {0};
    seed(dir, "odometry", 0, b, n, ros_encode_odometry(&o, cov, cov, &b, &n, &err));
    sp_ros_pose poses[3] = {{0, 0, 0, 0}, {1, 0.5, 0, 0.3}, {2, 1, 0, 0.6}};
    sp_ros_path path = {.n = 3, .poses = poses, .frame_id = "map"};
    seed(dir, "path", 1, b, n, ros_encode_path(&path, 3.0, &b, &n, &err));
    int8_t cells[12] = {0, 0, 100, -1, 0, 50, 0, 0, 100, 100, -1, 0};
    sp_ros_grid g = {.width = 4, .height = 3, .resolution_m = 0.05, .origin_x = -1, .cells = cells, .frame_id = "map"};
    seed(dir, "occupancy_grid", 2, b, n, ros_encode_occupancy_grid(&g, 1.0, &b, &n, &err));
    sp_ros_transform t = {.n_transforms = 1, .frame_id = "odom", .child_frame_id = "base_link", .x = 1, .qw = 1};
    seed(dir, "tf", 3, b, n, ros_encode_tf(&t, 2.0, &b, &n, &err));
    seed(dir, "tf_find", 4, b, n, ros_encode_tf(&t, 2.0, &b, &n, &err));
    sp_ros_goal_request gr = {.header = {7, 1}, .goal_id = {1, 2, 3}, .pose = {3, 4, 0, 1.5}, .frame_id = "map"};
    seed(dir, "nav_goal_request", 5, b, n, ros_encode_nav_goal_request(&gr, 4.0, &b, &n, &err));
    sp_ros_feedback_message fm = {.goal_id = {9}};
    seed(dir, "nav_feedback", 11, b, n, ros_encode_nav_feedback_message(&fm, 5.0, &b, &n, &err));
    sp_ros_result_response rr = {.header = {7, 2}, .status = 4, .error_code = 0, .error_msg = "ok"};
    seed(dir, "nav_result_humble", 9, b, n, ros_encode_nav_result_response(&rr, SP_ROS_DISTRO_HUMBLE, &b, &n, &err));
    seed(dir, "nav_result_jazzy", 9 | 16, b, n, ros_encode_nav_result_response(&rr, SP_ROS_DISTRO_JAZZY, &b, &n, &err));
    sp_ros_goal_status_entry e[2] = {{.goal_id = {1}, .stamp_s = 1, .status = 2}, {.goal_id = {2}, .status = 4}};
    sp_ros_status_array sa = {.n = 2, .entries = e};
    seed(dir, "goal_status_array", 12, b, n, ros_encode_goal_status_array(&sa, &b, &n, &err));
    return 0;
}
