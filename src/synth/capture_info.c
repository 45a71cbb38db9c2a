/* capture.json: which plan made a capture's views and with what settings, so reports can say
 * whether the views leaned on the world's objects (walk+objects), did not (walk), or came from a
 * continuous drive (with its rate, speed, the frames kept and each frame's time). */
#include "internal.h"

#include "semsplat/io.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <string.h>

static const char *plan_note(const sp_synth_plan_info *in)
{
    if (!in->name) return "";
    if (!strcmp(in->name, "walk+objects"))
        return "spins over the free floor and arcs of views aimed at the world's objects "
               "(uses the ground truth to choose views)";
    if (!strcmp(in->name, "walk"))
        return "spins over the free floor only: no view is aimed at a ground-truth object";
    if (!strcmp(in->name, "drive"))
        return "one continuous drive at a camera's frame rate through the reachable floor, the "
               "camera looking ahead: no view is aimed at a ground-truth object";
    return "an orbit around the scene (the world has no floor to walk or drive on)";
}

int synth_write_capture_json(const char *out, const sp_world *w, const sp_synth_capture_opts *o,
                             const sp_synth_plan_info *in, sp_error *err)
{
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "format", "semsplat-capture-1");
    cJSON_AddStringToObject(j, "world", w->path);
    cJSON_AddStringToObject(j, "plan", in->name ? in->name : "unknown");
    cJSON_AddStringToObject(j, "plan_note", plan_note(in));
    cJSON_AddNumberToObject(j, "views", (double)in->n_views);
    cJSON_AddNumberToObject(j, "width", o->width);
    cJSON_AddNumberToObject(j, "height", o->height);
    cJSON_AddNumberToObject(j, "fov_deg", o->fov_deg > 0 ? o->fov_deg : 70);
    cJSON_AddNumberToObject(j, "seed", o->seed);
    cJSON_AddStringToObject(j, "poses", "exact (rendered from the world)");
    if (in->name && !strcmp(in->name, "drive")) {
        cJSON *d = cJSON_AddObjectToObject(j, "drive");
        cJSON_AddNumberToObject(d, "speed_mps", in->speed_mps);
        cJSON_AddNumberToObject(d, "turn_rad_s", in->turn_rad_s);
        cJSON_AddNumberToObject(d, "camera_rate_hz", in->rate_hz * in->keep_every);
        cJSON_AddNumberToObject(d, "frames_driven", (double)in->n_frames_driven);
        cJSON_AddNumberToObject(d, "keep_every", in->keep_every);
        cJSON_AddNumberToObject(d, "kept_rate_hz", in->rate_hz);
        cJSON_AddNumberToObject(d, "camera_height_m", in->camera_height_m);
        cJSON_AddNumberToObject(d, "path_length_m", in->path_length_m);
        cJSON_AddNumberToObject(d, "duration_s", in->duration_s);
        cJSON_AddNumberToObject(d, "waypoints", in->n_waypoints);
        cJSON_AddNumberToObject(d, "segments", in->n_segments);
        cJSON_AddNumberToObject(d, "reachable_fraction", in->reachable_fraction);
        cJSON_AddNumberToObject(d, "max_step_m", in->max_step_m);
        cJSON_AddNumberToObject(d, "max_turn_rad", in->max_turn_rad);
        if (in->t_s) cJSON_AddItemToObject(d, "frame_time_s", cJSON_CreateDoubleArray(in->t_s, (int)in->n_views));
    }
    char path[2048];
    snprintf(path, sizeof path, "%s/capture.json", out);
    int rc = sp_json_write_file(path, j, err);
    cJSON_Delete(j);
    return rc;
}
