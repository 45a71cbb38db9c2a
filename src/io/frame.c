/* frame.json: which coordinate frame a model or capture folder's positions are in, and the
 * similarity that takes the model's own coordinates (the splat as stored, the COLMAP poses) into
 * the world frame. Written by synth (its captures are in the SDF world frame), by train (copied
 * from the capture) and by align; read by the query engine, which applies it to the splat and the
 * cameras alike. */
#include "io_internal.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>

#define FRAME_FORMAT "semsplat-frame-1"

static void set_str(char *dst, size_t cap, const char *s) { snprintf(dst, cap, "%s", s); }

void sp_frame_init(sp_frame *f, const char *source)
{
    memset(f, 0, sizeof *f);
    for (int i = 0; i < 4; i++) f->world_from_model[i * 5] = 1.0;
    int world = source && (!strcmp(source, "synth") || !strcmp(source, "align"));
    set_str(f->source, sizeof f->source, source && source[0] ? source : "colmap");
    /* synth worlds are SDF worlds: metres, z up. A plain reconstruction has neither. */
    set_str(f->up, sizeof f->up, world ? "+z" : "unknown");
    set_str(f->units, sizeof f->units, world ? "m" : "unknown");
    f->residual_m = -1;
}

int sp_frame_is_world(const sp_frame *f) { return f && strcmp(f->source, "colmap") != 0; }

const char *sp_frame_name(const sp_frame *f) { return sp_frame_is_world(f) ? "world" : "colmap"; }

double sp_frame_scale(const sp_frame *f)
{
    const double *M = f->world_from_model;
    return cbrt(M[0] * (M[5] * M[10] - M[6] * M[9]) - M[1] * (M[4] * M[10] - M[6] * M[8]) +
                M[2] * (M[4] * M[9] - M[5] * M[8]));
}

int sp_frame_check(const sp_frame *f, const char *what, sp_error *err)
{
    const double *M = f->world_from_model;
    for (int i = 0; i < 16; i++)
        if (!isfinite(M[i]))
            return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model[%d][%d] is not finite", what,
                                i / 4, i % 4);
    if (M[12] != 0 || M[13] != 0 || M[14] != 0 || M[15] != 1)
        return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model's last row is not 0 0 0 1", what);
    /* Scenes are kept in single precision: a translation or scale a float cannot carry (or that
     * is no indoor scene: 1000 km away) would turn positions into inf later, silently. */
    for (int r = 0; r < 3; r++)
        if (fabs(M[4 * r + 3]) > 1e6)
            return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model's translation %g (row %d) is more "
                                "than 1000 km", what, M[4 * r + 3], r);
    double s = sp_frame_scale(f);
    if (s > 0 && (s < 1e-6 || s > 1e6))
        return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model's scale %g is outside 1e-6..1e6", what, s);
    if (!(s > 0))
        return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model has determinant <= 0 (a "
                            "reflection or a collapse, not a similarity)", what);
    /* columns orthogonal and of length s: A^T A = s^2 I */
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            double d = M[a] * M[b] + M[4 + a] * M[4 + b] + M[8 + a] * M[8 + b];
            double want = a == b ? s * s : 0;
            if (fabs(d - want) > 1e-4 * s * s)
                return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model is not a similarity "
                                    "(columns %d and %d: dot %.6g, expected %.6g)", what, a, b, d, want);
        }
    if (strcmp(f->source, "synth") && strcmp(f->source, "align") && strcmp(f->source, "colmap"))
        return sp_error_set(err, SP_E_FORMAT, "%s: source '%s' is not synth, align or colmap", what,
                            f->source);
    return 0;
}

static int read_string(const cJSON *o, const char *key, char *dst, size_t cap, const char *path,
                       int required, sp_error *err)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v && !required) return 0;
    if (!cJSON_IsString(v) || !v->valuestring[0] || strlen(v->valuestring) >= cap)
        return sp_error_set(err, SP_E_FORMAT, "%s: \"%s\" must be a string of 1..%zu characters",
                            path, key, cap - 1);
    set_str(dst, cap, v->valuestring);
    return 0;
}

static int read_matrix(const cJSON *o, double M[16], const char *path, sp_error *err)
{
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(o, "world_from_model");
    if (!cJSON_IsArray(m) || cJSON_GetArraySize(m) != 4)
        return sp_error_set(err, SP_E_FORMAT, "%s: \"world_from_model\" must be 4 rows of 4 numbers", path);
    for (int r = 0; r < 4; r++) {
        const cJSON *row = cJSON_GetArrayItem(m, r);
        if (!cJSON_IsArray(row) || cJSON_GetArraySize(row) != 4)
            return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model row %d is not 4 numbers", path, r);
        for (int c = 0; c < 4; c++) {
            const cJSON *v = cJSON_GetArrayItem(row, c);
            if (!cJSON_IsNumber(v))
                return sp_error_set(err, SP_E_FORMAT, "%s: world_from_model[%d][%d] is not a number",
                                    path, r, c);
            M[r * 4 + c] = v->valuedouble;
        }
    }
    return 0;
}

int sp_frame_read(const char *path, sp_frame *out, sp_error *err)
{
    cJSON *js = NULL;
    int rc = sp_json_read_file(path, &js, err);
    if (rc) return rc;
    sp_frame f;
    sp_frame_init(&f, "colmap");
    if (!cJSON_IsObject(js)) rc = sp_error_set(err, SP_E_FORMAT, "%s: not a JSON object", path);
    if (!rc) rc = read_string(js, "source", f.source, sizeof f.source, path, 1, err);
    if (!rc) rc = read_matrix(js, f.world_from_model, path, err);
    if (!rc) rc = read_string(js, "up", f.up, sizeof f.up, path, 1, err);
    if (!rc) rc = read_string(js, "units", f.units, sizeof f.units, path, 1, err);
    if (!rc) rc = read_string(js, "note", f.note, sizeof f.note, path, 0, err);
    const cJSON *res = cJSON_GetObjectItemCaseSensitive(js, "residual_m");
    if (!rc && res && !cJSON_IsNull(res)) {
        if (!cJSON_IsNumber(res) || !(res->valuedouble >= 0))
            rc = sp_error_set(err, SP_E_FORMAT, "%s: \"residual_m\" must be a number >= 0 or null", path);
        else f.residual_m = res->valuedouble;
    }
    if (!rc) rc = sp_frame_check(&f, path, err);
    cJSON_Delete(js);
    if (!rc) *out = f;
    return rc;
}

int sp_frame_write(const char *path, const sp_frame *f, sp_error *err)
{
    return sp_frame_write_fit(path, f, NULL, err);
}

int sp_frame_write_fit(const char *path, const sp_frame *f, const char *fit_json, sp_error *err)
{
    int rc = sp_frame_check(f, path, err);
    if (rc) return rc;
    cJSON *fit = NULL;
    if (fit_json && !(fit = cJSON_Parse(fit_json)))
        return sp_error_set(err, SP_E_ARG, "%s: the fit to record is not JSON", path);
    cJSON *o = cJSON_CreateObject();
    if (!o) {
        cJSON_Delete(fit);
        return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    }
    cJSON_AddStringToObject(o, "format", FRAME_FORMAT);
    cJSON_AddStringToObject(o, "source", f->source);
    cJSON_AddStringToObject(o, "frame", sp_frame_name(f));
    cJSON *m = cJSON_AddArrayToObject(o, "world_from_model");
    for (int r = 0; r < 4; r++) { /* exact numbers: a frame read and written again is the same frame */
        cJSON *row = cJSON_CreateArray();
        for (int c = 0; c < 4; c++) cJSON_AddItemToArray(row, sp_json_number_exact(f->world_from_model[4 * r + c]));
        cJSON_AddItemToArray(m, row);
    }
    cJSON_AddStringToObject(o, "up", f->up);
    cJSON_AddStringToObject(o, "units", f->units);
    if (f->residual_m >= 0) cJSON_AddNumberToObject(o, "residual_m", f->residual_m);
    else cJSON_AddNullToObject(o, "residual_m");
    if (f->note[0]) cJSON_AddStringToObject(o, "note", f->note);
    if (fit) cJSON_AddItemToObject(o, "fit", fit);
    rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
    return rc;
}

/* 1 when `dir` names a COLMAP model folder inside a capture (…/sparse or …/sparse/<n>), so the
 * capture root two (or one) levels up holds the capture's files. */
static int capture_root(const char *dir, char *root, size_t cap)
{
    char buf[2048];
    set_str(buf, sizeof buf, dir);
    size_t n = strlen(buf);
    while (n > 1 && buf[n - 1] == '/') buf[--n] = 0;
    char *slash = strrchr(buf, '/');
    const char *last = slash ? slash + 1 : buf;
    int numeric = last[0] != 0;
    for (const char *p = last; *p; p++) numeric &= *p >= '0' && *p <= '9';
    if (numeric && slash) { /* …/sparse/0 */
        *slash = 0;
        slash = strrchr(buf, '/');
        last = slash ? slash + 1 : buf;
    }
    if (strcmp(last, "sparse") != 0) return 0;
    if (slash) *slash = 0;
    else set_str(buf, sizeof buf, ".");
    set_str(root, cap, buf[0] ? buf : "/");
    return 1;
}

int sp_frame_of_capture(const char *colmap_dir, sp_frame *f, sp_error *err)
{
    char root[2048], path[2100];
    const char *dirs[2] = {colmap_dir, NULL};
    if (capture_root(colmap_dir, root, sizeof root)) dirs[1] = root;
    for (int k = 0; k < 2 && dirs[k]; k++) {
        sp_path_join(path, sizeof path, dirs[k], "frame.json");
        if (sp_file_exists(path)) return sp_frame_read(path, f, err);
    }
    /* Captures synth wrote before it wrote frame.json: their ground truth is in the SDF world
     * frame, and so are their poses. */
    for (int k = 0; k < 2 && dirs[k]; k++) {
        sp_path_join(path, sizeof path, dirs[k], "ground_truth.json");
        if (sp_file_exists(path)) {
            sp_frame_init(f, "synth");
            set_str(f->note, sizeof f->note, "a synth capture (ground_truth.json, no frame.json)");
            return 0;
        }
    }
    sp_frame_init(f, "colmap");
    return 0;
}

int sp_frame_of_model(const char *model_dir, const char *colmap_dir, sp_frame *f, sp_error *err)
{
    char path[2100];
    sp_path_join(path, sizeof path, model_dir, "frame.json");
    if (sp_file_exists(path)) return sp_frame_read(path, f, err);
    if (colmap_dir && colmap_dir[0]) return sp_frame_of_capture(colmap_dir, f, err);
    sp_frame_init(f, "colmap");
    return 0;
}

void sp_frame_apply_point(const sp_frame *f, const float in[3], float out[3])
{
    const double *M = f->world_from_model;
    double p[3] = {in[0], in[1], in[2]};
    for (int r = 0; r < 3; r++)
        out[r] = (float)(M[r * 4] * p[0] + M[r * 4 + 1] * p[1] + M[r * 4 + 2] * p[2] + M[r * 4 + 3]);
}

void sp_frame_apply_camera(const sp_frame *f, sp_camera *cam)
{
    /* x_cam = Rc x_model + tc and x_model = R^T (x_world - t) / s give, in world units,
     * s x_cam = (Rc R^T) x_world + (s tc - Rc R^T t): the same pixels, depth in world units. */
    const double *M = f->world_from_model;
    double s = sp_frame_scale(f), R[9], Rn[9], tn[3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) R[r * 3 + c] = M[r * 4 + c] / s;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0;
            for (int k = 0; k < 3; k++) v += (double)cam->R[r * 3 + k] * R[c * 3 + k];
            Rn[r * 3 + c] = v;
        }
    for (int r = 0; r < 3; r++) {
        double v = s * cam->t[r];
        for (int k = 0; k < 3; k++) v -= Rn[r * 3 + k] * M[k * 4 + 3];
        tn[r] = v;
    }
    for (int i = 0; i < 9; i++) cam->R[i] = (float)Rn[i];
    for (int r = 0; r < 3; r++) cam->t[r] = (float)tn[r];
}
