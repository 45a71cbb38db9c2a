/* What an evaluated model was made from, for the report's head and its analysis: the capture it
 * was trained on (semantic.json's "colmap"), that capture's plan and poses (capture.json: synth's
 * plan, or sfm's COLMAP figures), and training's held-out PSNR and Gaussian count (train.json). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <string.h>

#include "eval/eval_internal.h"
#include "semsplat/io.h"

static cJSON *read_json(const char *dir, const char *name)
{
    char p[2200];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    cJSON *j = NULL;
    if (!sp_file_exists(p) || sp_json_read_file(p, &j, NULL)) return NULL;
    return j;
}

const char *ev_json_str(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsString(v) ? v->valuestring : NULL;
}

double ev_json_num(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

void ev_model_info(const char *model_dir, sp_eval_run *r)
{
    snprintf(r->plan, sizeof r->plan, "unknown");
    snprintf(r->poses, sizeof r->poses, "unknown (no capture.json)");
    r->sfm_ate_rms_m = r->train_psnr = NAN;
    cJSON *sem = read_json(model_dir, "semantic.json"), *tr = read_json(model_dir, "train.json");
    const char *cap = ev_json_str(sem, "colmap");
    if (cap) {
        /* semantic.json names the model folder (sparse/0) or the capture root */
        snprintf(r->capture_dir, sizeof r->capture_dir, "%s", cap);
        size_t n = strlen(r->capture_dir);
        if (n > 9 && !strcmp(r->capture_dir + n - 9, "/sparse/0")) r->capture_dir[n - 9] = 0;
    }
    cJSON *cj = r->capture_dir[0] ? read_json(r->capture_dir, "capture.json") : NULL;
    if (cj) {
        const char *plan = ev_json_str(cj, "plan"), *poses = ev_json_str(cj, "poses");
        if (plan) snprintf(r->plan, sizeof r->plan, "%s", plan);
        if (poses) snprintf(r->poses, sizeof r->poses, "%s", poses);
        const cJSON *sfm = cJSON_GetObjectItemCaseSensitive(cj, "sfm");
        if (sfm) {
            r->sfm_ate_rms_m = ev_json_num(cJSON_GetObjectItemCaseSensitive(sfm, "alignment"), "ate_rms_m");
            r->sfm_registered = (int)ev_json_num(sfm, "registered");
            r->sfm_images = (int)ev_json_num(sfm, "images");
        }
    }
    r->train_psnr = ev_json_num(tr, "psnr");
    double g = ev_json_num(tr, "gaussians");
    r->n_gaussians = isfinite(g) ? (long)g : -1;
    cJSON_Delete(sem);
    cJSON_Delete(tr);
    cJSON_Delete(cj);
}
