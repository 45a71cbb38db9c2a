/* The tool registry: names and arguments as the users' task states them, descriptions written
 * for small local models as much as hosted ones, and JSON schemas in the form both LLM APIs take
 * (OpenAI `parameters`, Anthropic `input_schema`). A read-only table. */
#include <cjson/cJSON.h>
#include <string.h>

#include "agent_internal.h"

/* A point or pose: [x, y], [x, y, z] or [x, y, z, yaw]; coordinates bounded to a building. */
#define POSE_ITEMS "{\"type\":\"number\",\"minimum\":-1000,\"maximum\":1000}"
#define PHRASE(desc) \
    "{\"type\":\"string\",\"minLength\":1,\"maxLength\":200,\"description\":\"" desc "\"}"
#define INSTANCE                                                                             \
    "\"instance\":{\"type\":\"integer\",\"minimum\":1,\"maximum\":16,\"description\":"       \
    "\"Which instance when several match: its 1-based number in query_object_location's "   \
    "list (sorted nearest first). Only when the user chose one.\"}"

static const sp_agent_tool tools[SP_AGENT_N_TOOLS] = {
    {"query_object_location",
     "Find an object in the robot's 3D semantic map by name or description (\"refrigerator\", "
     "\"the red mug on the counter\"). Returns the best position [x, y, z] in metres (world "
     "frame), a confidence (raw cosine: above about 0.25 a match, below 0.15 noise) and every "
     "instance found, nearest to the robot first, with its distance and region. If several "
     "instances match and the user did not say which, ask the user before moving.",
     "{\"type\":\"object\",\"properties\":{\"object_name\":" PHRASE(
         "What to find, in the user's words.") "},"
     "\"required\":[\"object_name\"],\"additionalProperties\":false}"},
    {"get_robot_pose",
     "The robot's current pose from odometry: {x, y, z, yaw} in metres and radians (yaw "
     "counter-clockwise from +x).",
     "{\"type\":\"object\",\"properties\":{},\"additionalProperties\":false}"},
    {"plan_path",
     "Plan a collision-free path on the map from start to goal. start: the robot's pose from "
     "get_robot_pose as [x, y, z, yaw]; goal: a point or pose [x, y], [x, y, z] or [x, y, z, "
     "yaw], e.g. an object's position from query_object_location. The path ends at a free pose "
     "within tolerance_m of the goal, facing it. Returns a plan_id and the waypoints "
     "[[x, y, z, yaw], ...]; send_nav2_goal accepts only the last waypoint of a plan issued here.",
     "{\"type\":\"object\",\"properties\":{"
     "\"start\":{\"type\":\"array\",\"items\":" POSE_ITEMS ",\"minItems\":2,\"maxItems\":4,"
     "\"description\":\"[x, y, z, yaw] of the robot (from get_robot_pose)\"},"
     "\"goal\":{\"type\":\"array\",\"items\":" POSE_ITEMS ",\"minItems\":2,\"maxItems\":4,"
     "\"description\":\"[x, y], [x, y, z] or [x, y, z, yaw]\"},"
     "\"tolerance_m\":{\"type\":\"number\",\"minimum\":0,\"maximum\":2,\"description\":"
     "\"How far from the goal point the path may end (default 1.0 m, enough to stand in front "
     "of furniture)\"}},"
     "\"required\":[\"start\",\"goal\"],\"additionalProperties\":false}"},
    {"render_view_from_splat",
     "Render what the robot's camera would see from a pose [x, y, z, yaw] (z: camera height, "
     "about 0.5 m on a small robot) from the 3D map. Returns the path of the image written.",
     "{\"type\":\"object\",\"properties\":{\"pose\":{\"type\":\"array\",\"items\":" POSE_ITEMS
     ",\"minItems\":4,\"maxItems\":4,\"description\":\"[x, y, z, yaw]\"}},"
     "\"required\":[\"pose\"],\"additionalProperties\":false}"},
    {"send_nav2_goal",
     "Send the robot to the end of a plan from plan_path (Nav2 NavigateToPose) and follow it to "
     "the end. x, y, yaw must be the plan's last waypoint; raw coordinates that no plan of this "
     "session ends at are refused. Returns the final status (succeeded, aborted, canceled, "
     "rejected) and where the robot stopped.",
     "{\"type\":\"object\",\"properties\":{"
     "\"x\":{\"type\":\"number\",\"minimum\":-1000,\"maximum\":1000},"
     "\"y\":{\"type\":\"number\",\"minimum\":-1000,\"maximum\":1000},"
     "\"yaw\":{\"type\":\"number\",\"minimum\":-7,\"maximum\":7,\"description\":\"radians\"},"
     "\"plan_id\":{\"type\":\"string\",\"minLength\":1,\"maxLength\":31,\"description\":"
     "\"The plan_id plan_path returned (recommended)\"}},"
     "\"required\":[\"x\",\"y\",\"yaw\"],\"additionalProperties\":false}"},
    {"show_trajectories",
     "Compute up to k genuinely different paths from the robot to an object, ranked with an "
     "itemized score (length, clearance, how well the map can localize the robot along it, "
     "semantic relevance), with rendered previews of the views along each and a top-down map. "
     "Does not move the robot; each trajectory has a plan_id that send_nav2_goal accepts.",
     "{\"type\":\"object\",\"properties\":{\"target\":" PHRASE(
         "The object to reach, in the user's words.") ","
     "\"k\":{\"type\":\"integer\",\"minimum\":1,\"maximum\":5,\"description\":\"How many "
     "trajectories (default 3)\"}," INSTANCE "},"
     "\"required\":[\"target\"],\"additionalProperties\":false}"},
    {"describe_surroundings",
     "List the objects within radius metres of an object (\"what is near the dining table?\"), "
     "with distances, where they are relative to it as seen from the robot, their region, and "
     "a one-sentence description.",
     "{\"type\":\"object\",\"properties\":{\"object_name\":" PHRASE(
         "The object to describe around.") ","
     "\"radius\":{\"type\":\"number\",\"minimum\":0.2,\"maximum\":5,\"description\":\"metres "
     "(default 1.5)\"}," INSTANCE "},"
     "\"required\":[\"object_name\"],\"additionalProperties\":false}"},
    {"explore_region",
     "Plan an exploration tour of a region (\"kitchen\", \"the area around the couch\"): "
     "waypoints that cover it with views, preferring places the map reconstructs poorly, in a "
     "short order. Returns the waypoints and a plan_id for the tour; does not move the robot.",
     "{\"type\":\"object\",\"properties\":{\"region\":" PHRASE(
         "A room or an object whose surroundings to explore.") ","
     "\"max_waypoints\":{\"type\":\"integer\",\"minimum\":1,\"maximum\":20,\"description\":"
     "\"default 8\"}},"
     "\"required\":[\"region\"],\"additionalProperties\":false}"},
    {"cancel_nav2_goal",
     "Stop the robot: cancel the navigation goal being followed, if any.",
     "{\"type\":\"object\",\"properties\":{},\"additionalProperties\":false}"},
};

const sp_agent_tool *sp_agent_tool_get(int id)
{
    return id >= 0 && id < SP_AGENT_N_TOOLS ? &tools[id] : NULL;
}

int sp_agent_tool_find(const char *name)
{
    for (int i = 0; name && i < SP_AGENT_N_TOOLS; i++)
        if (!strcmp(tools[i].name, name)) return i;
    return -1;
}

cJSON *agent_tool_schema_json(int tool, sp_error *err)
{
    const sp_agent_tool *t = sp_agent_tool_get(tool);
    if (!t) {
        sp_error_set(err, SP_E_ARG, "unknown tool id %d", tool);
        return NULL;
    }
    cJSON *j = cJSON_Parse(t->schema);
    if (!j) sp_error_set(err, SP_E_FORMAT, "%s: the built-in schema does not parse", t->name);
    return j;
}

static cJSON *tool_list(int anthropic)
{
    cJSON *arr = cJSON_CreateArray();
    for (int i = 0; arr && i < SP_AGENT_N_TOOLS; i++) {
        cJSON *schema = cJSON_Parse(tools[i].schema), *t = cJSON_CreateObject();
        if (!schema || !t) {
            cJSON_Delete(schema);
            cJSON_Delete(t);
            cJSON_Delete(arr);
            return NULL;
        }
        if (anthropic) {
            cJSON_AddStringToObject(t, "name", tools[i].name);
            cJSON_AddStringToObject(t, "description", tools[i].description);
            cJSON_AddItemToObject(t, "input_schema", schema);
        } else {
            cJSON *f = cJSON_CreateObject();
            cJSON_AddStringToObject(t, "type", "function");
            cJSON_AddStringToObject(f, "name", tools[i].name);
            cJSON_AddStringToObject(f, "description", tools[i].description);
            cJSON_AddItemToObject(f, "parameters", schema);
            cJSON_AddItemToObject(t, "function", f);
        }
        cJSON_AddItemToArray(arr, t);
    }
    return arr;
}

cJSON *agent_tools_openai(void) { return tool_list(0); }
cJSON *agent_tools_anthropic(void) { return tool_list(1); }
