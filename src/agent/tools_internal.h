/* Shared by the tool implementations (tools_exec.c, tools_scene.c): result envelopes, the robot's
 * pose, and resolving an object phrase to one instance with the ambiguity rules. */
#ifndef SEMSPLAT_AGENT_TOOLS_INTERNAL_H
#define SEMSPLAT_AGENT_TOOLS_INTERNAL_H

#include "agent_internal.h"

struct cJSON;

/* A second instance counts as a real alternative when its weight is at least this share of the
 * best one's (smaller clusters are fragments of the same object or noise). */
#define AGENT_AMBIGUOUS_SCORE_FRACTION 0.25
/* Waypoints written into a tool result at most (the plan itself keeps all of them). */
#define AGENT_MAX_WAYPOINTS_OUT 40

/* {"tool", "ok": true, "data"} (takes data). */
char *agent_result_ok(int tool, struct cJSON *data);
/* {"tool", "ok": false, "error": {code, message, hint}, "data"?} (takes data, may be NULL). */
char *agent_result_error(int tool, const char *code, const char *message, const char *hint,
                         struct cJSON *data);

int agent_robot_pose(sp_agent_session *s, sp_agent_pose *pose, sp_error *err);
struct cJSON *agent_pose_json(const sp_agent_pose *p);

/* A phrase resolved on the world: instances sorted nearest first with distances and regions,
 * the relation to an anchor applied ("mug on the counter"), and whether it is ambiguous. */
typedef struct agent_resolved {
    agent_found found;
    int n_real;            /* instances that count for ambiguity */
    int ambiguous;
    char note[256];        /* how the relation was applied, or why it was not */
    char suggestions[5][64];
    int n_suggestions;
} agent_resolved;

int agent_resolve(sp_agent_session *s, const char *phrase, const sp_agent_pose *robot,
                  agent_resolved *out, sp_error *err);
/* The instances as JSON [{instance, position, confidence, distance_m, region}]. */
struct cJSON *agent_instances_json(const agent_found *f);
/* "I see 4 chairs: 1) 1.2 m away in the dining room, ... Which one?" */
void agent_ambiguity_question(const char *phrase, const agent_resolved *r, char *out, size_t cap);
/* Picks the instance for a tool that takes an object phrase: the 1-based `instance` if given,
 * else the only one; otherwise writes the AMBIGUOUS / NOT_FOUND error result into *result. */
const agent_instance *agent_pick_instance(int tool, const char *phrase, int instance,
                                          const agent_resolved *r, char **result);

char *agent_tool_show_trajectories(sp_agent_session *s, const sp_agent_args *a);
char *agent_tool_describe(sp_agent_session *s, const sp_agent_args *a);
char *agent_tool_explore(sp_agent_session *s, const sp_agent_args *a);
struct cJSON *agent_waypoints_json(const double *wp, int n, int max_out);

#endif
