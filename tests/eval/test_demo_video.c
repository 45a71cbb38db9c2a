/* The demo video on a tiny setting: the ideal house model (label features on the house's ground
 * truth, tests/agent/house_model.h), one "go to" command through the agent and the simulated
 * robot (over loopback DDS when this build has Cyclone, else offline), written at 320x180 with a
 * handful of rendered drive frames. ffprobe must read H.264 and the duration the writer counted;
 * the robot must have arrived. Then 5.3 on two commands with the offline robot. */
#include <unistd.h>

#include "agent/house_model.h"
#include "semsplat/eval.h"
#include "semsplat/io.h"
#include "test.h"
#include "tools.h"

int main(void)
{
    sp_error err = {0};
    char dir[1100], model[1200], world[1100];
    snprintf(dir, sizeof dir, "%s", test_tmpdir("demo_video"));
    snprintf(world, sizeof world, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    sp_device *dev = NULL;
    ws_scene sc;
    float start[3];
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(ws_build(&sc, world, NULL, 120, 128, 96, 0.07f, &err), &err);
    CHECK_OK(hm_write(&sc, dir, dev, model, sizeof model, start, &err), &err);
    ws_free(&sc);
    sp_demo_video_opts o = sp_demo_video_opts_default();
    static const char *const cmds[] = {"go to the refrigerator"};
    o.commands = cmds, o.n_commands = 1;
    o.width = 320, o.height = 180, o.fps = 5, o.drive_frames = 6, o.view_width = 96, o.view_height = 72;
    o.drive.model_dir = model, o.drive.out_dir = dir, o.drive.dev = dev, o.drive.time_scale = 4;
    o.drive.max_speed_mps = 1.0;
    sp_demo_video_result r;
    int rc = sp_demo_video(&o, &r, &err);
    CHECK_OK(rc, &err);
    fprintf(stderr, "video %s: %ld frames, %.1f s, robot: %s, arrived %d/%d, %.1f s wall\n", r.path, r.frames,
            r.seconds, r.robot, r.n_arrived, r.n_commands, r.t_wall);
    CHECK(r.n_arrived == 1);
    CHECK(r.seconds >= 20);
    if (!rc && have_tool("ffprobe")) {
        char cmd[1400], out[4096];
        snprintf(cmd, sizeof cmd, "ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,width,height:"
                 "format=duration -of default=nw=1 '%s'", r.path);
        CHECK(capture(cmd, out, sizeof out) == 0);
        CHECK_MSG(strstr(out, "codec_name=h264") && strstr(out, "width=320"), "%s", out);
        const char *d = strstr(out, "duration=");
        CHECK(d != NULL);
        if (d) CHECK_NEAR(atof(d + 9), r.seconds, 0.3);
    }
    /* 5.3 on two commands with the offline robot (no waiting in wall time): every stage passes on the
     * ideal house, the graded views are on disk, and the robot is named as the offline one. */
    sp_ground_truth gt = {0};
    int have_gt = sp_ground_truth_from_world(world, NULL, 0, NULL, &gt, &err) == 0;
    static const char *const nav_cmds[] = {"go to the refrigerator|refrigerator", "take me to the sofa|couch"};
    sp_drive_opts d = {.model_dir = model, .out_dir = dir, .robot = SP_DEMO_ROBOT_OFFLINE, .dev = dev};
    sp_nav_success ns;
    CHECK_OK(sp_eval_nav_success(&d, have_gt ? &gt : NULL, nav_cmds, 2, 0.5f, &ns, &err), &err);
    CHECK(ns.n == 2 && strstr(ns.robot, "OFFLINE"));
    for (int k = 0; k < 4; k++) CHECK_MSG(ns.count[k] == 2, "stage %d: %d of 2", k, ns.count[k]);
    CHECK(sp_file_exists(ns.rows[0].views) && sp_file_exists(ns.plot));
    if (have_gt) CHECK(ns.rows[1].error_m < 0.5);
    sp_ground_truth_free(&gt);
    sp_device_free(dev);
    return TEST_EXIT();
}
