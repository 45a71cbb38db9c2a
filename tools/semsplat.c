/* semsplat: the command-line entry point. Dispatches `semsplat <command> [flags]` to
 * tools/cmd_<command>.c (a command whose library part is not built answers so itself). */
#include <stdio.h>
#include <string.h>

#include "cli.h"

typedef struct {
    const char *name;
    sp_cmd_fn fn;
    const char *help;
} command;

static const command commands[] = {
    {"info", cmd_info, "describe a COLMAP model, splat PLY, image or .npy file"},
    {"render", cmd_render, "render a splat from COLMAP cameras to PNG"},
    {"synth", cmd_synth, "render a Gazebo/SDF world into a capture with ground truth"},
    {"train", cmd_train, "train a Gaussian splat from a COLMAP capture"},
    {"features", cmd_features, "extract dense per-pixel features (CLIP, .npy, labels) + PCA"},
    {"embed-text", cmd_embed_text, "print the CLIP embedding of a text"},
    {"lift", cmd_lift, "lift 2D feature maps into the splat in one pass"},
    {"distill", cmd_distill, "learn per-Gaussian features by distillation"},
    {"query", cmd_query, "find a text query in the language-embedded splat"},
    {"lexical", cmd_lexical, "match text to a scene's class names with WordNet (offline, --explain)"},
    {"align", cmd_align, "put a splat into the world frame (similarity / floor plane)"},
    {"demo", cmd_demo, "synth -> train -> features -> lift -> queries on the bundled house"},
    {"agent", cmd_agent, "talk to the robot: go to, show trajectories, describe, explore"},
    {"sim-robot", cmd_sim_robot, "a simulated robot serving Nav2 actions and /odom over ROS 2 DDS"},
    {"ros-goal", cmd_ros_goal, "send a Nav2 goal / ask for a path / read the pose of a ROS 2 robot"},
    {"plan", cmd_plan, "k distinct ranked trajectories to an object, with previews and a map"},
    {"explore", cmd_explore, "views covering a region in words, ordered into a short tour"},
    {"describe", cmd_describe, "the objects near an anchor, with distances and relations"},
};

static void usage(FILE *f)
{
    fprintf(f, "usage: semsplat <command> [flags]   (semsplat <command> --help for flags)\n\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-12s %s\n", commands[i].name, commands[i].help);
}

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (strcmp(argv[1], commands[i].name) != 0) continue;
        return commands[i].fn(argc - 1, argv + 1);
    }
    fprintf(stderr, "semsplat: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return 2;
}
