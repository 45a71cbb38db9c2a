/* The navigation scene: opens a model folder (splat, cameras, query engine when there is a
 * semantic field), builds its costmap and the per-Gaussian coverage the ranking renders, keeps
 * the plans it issued under their ids, and renders views from robot poses. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_scene.h"
#include "semsplat/io.h"

sp_rank_weights sp_rank_weights_default(void)
{
    sp_rank_weights w = {0.35f, 0.20f, 0.10f, 0.20f, 0.15f};
    return w;
}

sp_nav_opts sp_nav_opts_default(void)
{
    sp_nav_opts o;
    memset(&o, 0, sizeof o);
    o.costmap = sp_costmap_opts_default();
    o.planner = sp_planner_opts_default();
    o.weights = sp_rank_weights_default();
    o.k = 3;
    o.approach_m = 0.55f;
    o.camera_height_m = 0.8f;
    o.camera_pitch_deg = 10.0f;
    o.preview_hfov_deg = 70.0f;
    o.preview_width = 320, o.preview_height = 240;
    o.n_previews = 4;
    o.loc_spacing_m = 0.5f;
    o.loc_width = 64, o.loc_height = 48;
    o.loc_views_full = 3;
    o.clearance_ref_m = 0.5f;
    o.min_confidence = 0.25f;
    o.near_m = 1.5f;
    o.region_margin_m = 1.0f;
    o.max_tour_poses = 12;
    o.tour_coverage = 0.9f;
    return o;
}

sp_nav_request sp_nav_request_default(void)
{
    sp_nav_request r;
    memset(&r, 0, sizeof r);
    r.instance = -1;
    r.previews = 1;
    r.goal = sp_nav_goal_point(0, 0);
    return r;
}

void nav_pose_camera(sp_camera *cam, int width, int height, float hfov_rad, const float pos[3],
                     float yaw, float pitch)
{
    memset(cam, 0, sizeof *cam);
    sp_camera_intrinsics_fov(cam, width, height, hfov_rad);
    sp_camera_from_pose(cam, pos, yaw, pitch);
}

static int check_nav_opts(const sp_nav_opts *o, sp_error *err)
{
    if (o->k < 1 || o->k > 64 || o->n_previews < 0 || o->n_previews > 16 || o->preview_width < 8 ||
        o->preview_height < 8 || o->loc_width < 4 || o->loc_height < 4 || !(o->loc_spacing_m > 0) ||
        !(o->approach_m >= 0) || !(o->camera_height_m > 0) || !(o->preview_hfov_deg > 1 && o->preview_hfov_deg < 179) ||
        o->loc_views_full < 1 || !(o->clearance_ref_m > 0) || o->max_tour_poses < 1)
        return sp_error_set(err, SP_E_ARG,
                            "nav: options k %d (1..64), previews %d (0..16) at %dx%d, localizability "
                            "views %dx%d every %g m, approach %g m, camera height %g m, fov %g deg, "
                            "views for full coverage %d, clearance reference %g m, tour poses %d",
                            o->k, o->n_previews, o->preview_width, o->preview_height, o->loc_width,
                            o->loc_height, o->loc_spacing_m, o->approach_m, o->camera_height_m,
                            o->preview_hfov_deg, o->loc_views_full, o->clearance_ref_m, o->max_tour_poses);
    /* upper bounds too: a robot radius of 1e30 m inflated every map into "no free floor", an
     * approach of 1e30 m made every cell a goal */
    const sp_costmap_opts *c = &o->costmap;
    if (!(c->robot_radius_m >= 0 && c->robot_radius_m <= 10) || !(c->inflation_radius_m <= 50))
        return sp_error_set(err, SP_E_ARG, "nav: robot radius %g m, inflation radius %g m: expected 0..10 and at most 50",
                            c->robot_radius_m, c->inflation_radius_m);
    if (!(o->approach_m <= 100) || !(o->near_m >= 0 && o->near_m <= 100))
        return sp_error_set(err, SP_E_ARG, "nav: approach %g m, describe radius %g m: expected 0..100",
                            o->approach_m, o->near_m);
    return SP_OK;
}

static void split_vocabulary(sp_nav *nav)
{
    nav->n_vocab = 0;
    if (!nav->opts.vocabulary || !nav->opts.vocabulary[0]) {
        int n;
        const char *const *v = sp_nav_vocabulary(&n);
        for (int i = 0; i < n && i < 512; i++) nav->vocab[nav->n_vocab++] = v[i];
        return;
    }
    snprintf(nav->vocab_buf, sizeof nav->vocab_buf, "%s", nav->opts.vocabulary);
    for (char *tok = strtok(nav->vocab_buf, ","); tok && nav->n_vocab < 512; tok = strtok(NULL, ",")) {
        while (*tok == ' ') tok++;
        char *e = tok + strlen(tok);
        while (e > tok && e[-1] == ' ') *--e = 0;
        if (*tok) nav->vocab[nav->n_vocab++] = tok;
    }
    nav->opts.vocabulary = NULL; /* the caller's string is not kept */
}

/* Everything after the splat and cameras are in place. */
static int finish(sp_nav *nav, sp_error *err)
{
    const sp_splat *s = nav->splat;
    int rc = sp_raster_create(&nav->raster, nav->dev, err);
    if (rc) return rc;
    nav->view_counts = calloc(s->n ? s->n : 1, sizeof(uint16_t));
    if (!nav->view_counts) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    if ((rc = nav_costmap_build(&nav->cm, s, nav->cams, nav->n_cams, &nav->opts.costmap, nav->raster,
                                nav->view_counts, nav_log(nav), err)))
        return rc;
    if ((rc = sp_splat_alloc(&nav->aux, s->n, 0, 2, err))) return rc;
    memcpy(nav->aux.means, s->means, sizeof(float) * 3 * s->n);
    memcpy(nav->aux.quats, s->quats, sizeof(float) * 4 * s->n);
    memcpy(nav->aux.log_scales, s->log_scales, sizeof(float) * 3 * s->n);
    memcpy(nav->aux.opacity_logits, s->opacity_logits, sizeof(float) * s->n);
    for (size_t i = 0; i < s->n; i++) {
        float c = (float)nav->view_counts[i] / (float)nav->opts.loc_views_full;
        nav->aux.features[2 * i] = c > 1 ? 1 : c;
        nav->aux.features[2 * i + 1] = 0;
    }
    if ((rc = sp_scene_create(&nav->scene_rgb, nav->dev, s, SP_SCENE_RGB, err)) ||
        (rc = sp_scene_create(&nav->scene_aux, nav->dev, &nav->aux, SP_SCENE_FEATURES, err)))
        return sp_error_prefix(err, "nav: ");
    split_vocabulary(nav);
    return SP_OK;
}

static sp_nav *nav_alloc(const sp_nav_opts *opts, sp_device *dev, const sp_log *log)
{
    sp_nav *nav = calloc(1, sizeof *nav);
    if (!nav) return NULL;
    nav->opts = opts ? *opts : sp_nav_opts_default();
    nav->dev = dev;
    if (log) nav->log = *log, nav->has_log = 1;
    return nav;
}

static int copy_cams(sp_nav *nav, const sp_camera *cams, size_t n, sp_error *err)
{
    nav->cams = malloc(sizeof(sp_camera) * (n ? n : 1));
    if (!nav->cams) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    for (size_t i = 0; i < n; i++) {
        nav->cams[i] = cams[i];
        nav->cams[i].distortion = SP_DIST_NONE;
    }
    nav->n_cams = n;
    return SP_OK;
}

int sp_nav_create(sp_nav **out, struct sp_query_engine *engine, const sp_splat *splat,
                  const sp_camera *cams, size_t n_cams, const sp_nav_opts *opts, sp_device *dev,
                  const sp_log *log, sp_error *err)
{
    *out = NULL;
    if (!dev || (!engine && (!splat || !cams)))
        return sp_error_set(err, SP_E_ARG, "nav: needs a device and an engine or a splat with cameras");
    int rc = opts ? check_nav_opts(opts, err) : 0;
    if (rc) return rc;
    sp_nav *nav = nav_alloc(opts, dev, log);
    if (!nav) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    if (engine) {
        nav->engine = engine;
        nav->splat = sp_query_engine_splat(engine);
        size_t n = sp_query_engine_n_cameras(engine);
        nav->cams = malloc(sizeof(sp_camera) * (n ? n : 1));
        if (!nav->cams) rc = sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
        for (size_t i = 0; i < n && !rc; i++) nav->cams[i] = *sp_query_engine_camera(engine, i);
        nav->n_cams = n;
    } else {
        rc = sp_splat_copy(&nav->own_splat, splat, err);
        nav->splat = &nav->own_splat;
        if (!rc) rc = copy_cams(nav, cams, n_cams, err);
    }
    if (!rc && nav->n_cams == 0)
        rc = sp_error_set(err, SP_E_NOTFOUND, "nav: no training cameras: the costmap carves free "
                          "space along them (the model folder must name its capture)");
    if (!rc) rc = finish(nav, err);
    if (rc) {
        sp_nav_free(nav);
        return rc;
    }
    *out = nav;
    return SP_OK;
}

/* Splat and cameras into the model folder's frame (frame.json, else its capture's), as the
 * query engine puts them: the costmap is then in the same world frame as the engine's answers
 * whether or not the folder has semantics. Identity frames cost nothing. */
static int to_world_frame(const char *model_dir, const char *capture, sp_splat *splat,
                          sp_camera *cams, size_t n_cams, sp_error *err)
{
    static const double I[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    sp_frame f;
    int rc = sp_frame_of_model(model_dir, capture, &f, err);
    if (!rc) rc = sp_frame_check(&f, "nav: frame", err);
    if (rc || !memcmp(f.world_from_model, I, sizeof I)) return rc;
    if ((rc = sp_splat_transform(splat, f.world_from_model, err))) return rc;
    for (size_t i = 0; i < n_cams; i++) sp_frame_apply_camera(&f, &cams[i]);
    return SP_OK;
}

/* splat.ply and the pinhole cameras of the capture train.json names, in the world frame. */
static int load_geometry(const char *model_dir, sp_splat *splat, sp_camera **cams, size_t *n_cams, sp_error *err)
{
    char path[2048];
    *cams = NULL, *n_cams = 0;
    sp_path_join(path, sizeof path, model_dir, "splat.ply");
    int rc = sp_ply_read_splat(path, splat, err);
    if (rc) return rc;
    sp_path_join(path, sizeof path, model_dir, "train.json");
    cJSON *tj = NULL;
    if ((rc = sp_json_read_file(path, &tj, err))) return sp_error_prefix(err, "nav: the capture: ");
    cJSON *st = cJSON_GetObjectItemCaseSensitive(tj, "settings");
    cJSON *c = st ? cJSON_GetObjectItemCaseSensitive(st, "colmap") : NULL;
    if (!cJSON_IsString(c)) {
        cJSON_Delete(tj);
        return sp_error_set(err, SP_E_FORMAT, "%s: settings.colmap (the capture) is missing", path);
    }
    char capture[2048];
    if (c->valuestring[0] == '/') snprintf(capture, sizeof capture, "%s", c->valuestring);
    else sp_path_join(capture, sizeof capture, model_dir, c->valuestring);
    cJSON_Delete(tj);
    sp_colmap_model m;
    if ((rc = sp_colmap_read(capture, &m, err))) return rc;
    *cams = calloc(m.n_images ? m.n_images : 1, sizeof(sp_camera));
    if (!*cams) rc = sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    for (size_t i = 0; i < m.n_images && !rc; i++) {
        rc = sp_colmap_image_camera(&m, i, &(*cams)[i], err);
        (*cams)[i].distortion = SP_DIST_NONE;
        *n_cams = i + 1;
    }
    sp_colmap_free(&m);
    return rc ? rc : to_world_frame(model_dir, capture, splat, *cams, *n_cams, err);
}

int sp_costmap_build_model(sp_costmap *cm, const char *model_dir, const sp_costmap_opts *opts,
                           sp_device *dev, const sp_log *log, sp_error *err)
{
    memset(cm, 0, sizeof *cm);
    if (!model_dir || !dev) return sp_error_set(err, SP_E_ARG, "costmap: missing model folder or device");
    sp_splat s;
    memset(&s, 0, sizeof s);
    sp_camera *cams = NULL;
    size_t n = 0;
    sp_raster *r = NULL;
    int rc = load_geometry(model_dir, &s, &cams, &n, err);
    if (!rc && !n) rc = sp_error_set(err, SP_E_NOTFOUND, "%s: the capture has no cameras", model_dir);
    if (!rc) rc = sp_raster_create(&r, dev, err);
    if (!rc) rc = sp_costmap_build(cm, &s, cams, n, opts, r, log, err);
    if (rc) sp_error_prefix(err, "%s: ", model_dir);
    sp_raster_free(r);
    sp_splat_free(&s);
    free(cams);
    return rc;
}

int sp_nav_open(sp_nav **out, const char *model_dir, const sp_nav_opts *opts, sp_device *dev,
                const sp_log *log, sp_error *err)
{
    *out = NULL;
    if (!model_dir || !dev) return sp_error_set(err, SP_E_ARG, "nav: missing model folder or device");
    if (opts) {
        int rc = check_nav_opts(opts, err);
        if (rc) return rc;
    }
    sp_nav *nav = nav_alloc(opts, dev, log);
    if (!nav) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    char path[2048];
    sp_path_join(path, sizeof path, model_dir, "semantic.json");
    int rc;
    if (sp_file_exists(path)) {
        rc = sp_query_engine_open(&nav->engine, model_dir, NULL, dev, log, err);
        nav->own_engine = 1;
        if (!rc) {
            nav->splat = sp_query_engine_splat(nav->engine);
            size_t n = sp_query_engine_n_cameras(nav->engine);
            nav->cams = malloc(sizeof(sp_camera) * (n ? n : 1));
            if (!nav->cams) rc = sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
            for (size_t i = 0; i < n && !rc; i++) nav->cams[i] = *sp_query_engine_camera(nav->engine, i);
            nav->n_cams = n;
        }
    } else {
        rc = load_geometry(model_dir, &nav->own_splat, &nav->cams, &nav->n_cams, err);
        nav->splat = &nav->own_splat;
    }
    if (!rc && nav->n_cams == 0)
        rc = sp_error_set(err, SP_E_NOTFOUND, "%s: no training cameras (the capture the model names "
                          "is missing): the costmap carves free space along them", model_dir);
    if (!rc) rc = finish(nav, err);
    if (rc) {
        sp_error_prefix(err, "%s: ", model_dir);
        sp_nav_free(nav);
        return rc;
    }
    *out = nav;
    return SP_OK;
}

void sp_nav_free(sp_nav *nav)
{
    if (!nav) return;
    if (nav->own_engine) sp_query_engine_free(nav->engine);
    sp_splat_free(&nav->own_splat);
    sp_splat_free(&nav->aux);
    free(nav->cams);
    sp_costmap_free(&nav->cm);
    free(nav->view_counts);
    free(nav->region_label);
    sp_scene_free(nav->scene_rgb);
    sp_scene_free(nav->scene_aux);
    sp_raster_free(nav->raster);
    for (int i = 0; i < nav->n_issued; i++) sp_path_free(&nav->issued[i].path);
    free(nav->issued);
    free(nav);
}

const sp_costmap *sp_nav_costmap(const sp_nav *nav) { return &nav->cm; }
const sp_nav_opts *sp_nav_options(const sp_nav *nav) { return &nav->opts; }

/* The traversable cell nearest to (x, y) within radius_m, or -1. */
static long nearest_traversable(const sp_costmap *cm, float x, float y, float radius_m)
{
    int r = (int)ceilf(radius_m / cm->res), cx, cy;
    sp_costmap_cell(cm, x, y, &cx, &cy);
    float best = INFINITY;
    long at = -1;
    for (int iy = cy - r; iy <= cy + r; iy++)
        for (int ix = cx - r; ix <= cx + r; ix++) {
            if (!sp_costmap_traversable(cm, ix, iy)) continue;
            float c[2];
            sp_costmap_cell_center(cm, ix, iy, c);
            float d = hypotf(c[0] - x, c[1] - y);
            if (d < best && d <= radius_m) best = d, at = nav_idx(cm, ix, iy);
        }
    return at;
}

/* Labels the 4-connected traversable component of seed with label (comp [cells], 0 = none yet);
 * returns its size. */
static long flood_component(const sp_costmap *cm, long seed, int32_t label, int32_t *comp, int32_t *queue)
{
    long head = 0, tail = 0;
    queue[tail++] = (int32_t)seed;
    comp[seed] = label;
    while (head < tail) {
        long c = queue[head++];
        int x0 = (int)(c % cm->nx), y0 = (int)(c / cm->nx);
        for (int k = 0; k < 4; k++) {
            int x = x0 + (k == 0) - (k == 1), y = y0 + (k == 2) - (k == 3);
            if (!sp_costmap_traversable(cm, x, y) || comp[nav_idx(cm, x, y)]) continue;
            comp[nav_idx(cm, x, y)] = label;
            queue[tail++] = (int32_t)nav_idx(cm, x, y);
        }
    }
    return tail;
}

int nav_pick_start(const sp_costmap *cm, const sp_camera *cams, size_t n_cams, float start[3], sp_error *err)
{
    size_t n = (size_t)cm->nx * cm->ny;
    int32_t *comp = calloc(n, sizeof(int32_t)), *queue = malloc(sizeof(int32_t) * n);
    long *size = calloc(n_cams + 1, sizeof(long));
    if (!comp || !queue || !size) {
        free(comp), free(queue), free(size);
        return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    }
    long best_size = 0, best_cell = -1;
    size_t best_cam = 0;
    int32_t labels = 0;
    for (size_t i = 0; i < n_cams; i++) {
        sp_vec3 p = sp_camera_center(&cams[i]);
        long cell = nearest_traversable(cm, p.x, p.y, NAV_START_SNAP_M);
        if (cell < 0) continue;
        if (!comp[cell]) size[labels] = flood_component(cm, cell, labels + 1, comp, queue), labels++;
        if (size[comp[cell] - 1] > best_size) best_size = size[comp[cell] - 1], best_cell = cell, best_cam = i;
    }
    free(comp), free(queue), free(size);
    if (best_cell < 0)
        return sp_error_set(err, SP_E_NOTFOUND, "nav: no free floor within %.0f m of any of the %zu training "
                            "cameras: give a start", NAV_START_SNAP_M, n_cams);
    sp_vec3 p = sp_camera_center(&cams[best_cam]);
    float c[2];
    sp_costmap_cell_center(cm, (int)(best_cell % cm->nx), (int)(best_cell / cm->nx), c);
    int ix, iy;
    int on = sp_costmap_cell(cm, p.x, p.y, &ix, &iy) == 0 && nav_idx(cm, ix, iy) == best_cell;
    start[0] = on ? p.x : c[0];
    start[1] = on ? p.y : c[1];
    /* heading: the optical axis (third row of world-to-camera R) on the floor */
    start[2] = atan2f(cams[best_cam].R[7], cams[best_cam].R[6]);
    return SP_OK;
}

int sp_nav_default_start(const sp_nav *nav, float start[3], sp_error *err)
{
    return nav_pick_start(&nav->cm, nav->cams, nav->n_cams, start, err);
}

int nav_issue(sp_nav *nav, const char *id, const sp_path *path, sp_error *err)
{
    if (nav->n_issued == nav->cap_issued) {
        int cap = nav->cap_issued ? 2 * nav->cap_issued : 16;
        nav_issued *a = realloc(nav->issued, sizeof *a * cap);
        if (!a) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
        nav->issued = a, nav->cap_issued = cap;
    }
    nav_issued *e = &nav->issued[nav->n_issued];
    snprintf(e->id, sizeof e->id, "%s", id);
    int rc = sp_path_copy(&e->path, path, err);
    if (!rc) nav->n_issued++;
    return rc;
}

const sp_path *sp_nav_lookup(const sp_nav *nav, const char *trajectory_id)
{
    for (int i = 0; trajectory_id && i < nav->n_issued; i++)
        if (!strcmp(nav->issued[i].id, trajectory_id)) return &nav->issued[i].path;
    return NULL;
}

/* ---- views from poses -------------------------------------------------------------------------- */

int nav_view_scores(sp_nav *nav, const float pos[3], float yaw, float pitch, float *loc,
                    float *relevance, sp_error *err)
{
    const sp_nav_opts *o = &nav->opts;
    sp_camera cam;
    nav_pose_camera(&cam, o->loc_width, o->loc_height, o->preview_hfov_deg * (float)M_PI / 180.0f, pos, yaw, pitch);
    size_t np = (size_t)o->loc_width * o->loc_height;
    float *img = malloc(sizeof(float) * 2 * np);
    if (!img) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    sp_render_request req;
    memset(&req, 0, sizeof req);
    req.features = img;
    int rc = sp_render_views(nav->raster, nav->scene_aux, &cam, 1, &req, err);
    if (!rc) {
        double a = 0, b = 0;
        for (size_t i = 0; i < np; i++) a += img[2 * i], b += img[2 * i + 1];
        *loc = (float)(a / np);
        if (relevance) *relevance = (float)(b / np);
    }
    free(img);
    return rc;
}

int nav_render_preview(sp_nav *nav, const float pos[3], float yaw, float pitch, sp_nav_preview *pv,
                       sp_error *err)
{
    const sp_nav_opts *o = &nav->opts;
    sp_camera cam;
    nav_pose_camera(&cam, o->preview_width, o->preview_height, o->preview_hfov_deg * (float)M_PI / 180.0f,
                    pos, yaw, pitch);
    size_t np = (size_t)cam.width * cam.height;
    float *rgb = malloc(sizeof(float) * 3 * np);
    pv->rgb = malloc(3 * np);
    if (!rgb || !pv->rgb) {
        free(rgb), free(pv->rgb);
        pv->rgb = NULL;
        return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    }
    static const float background[3] = {0.12f, 0.12f, 0.14f}; /* unreconstructed space: dark */
    sp_render_request req;
    memset(&req, 0, sizeof req);
    req.rgb = rgb;
    req.background = background;
    int rc = sp_render_views(nav->raster, nav->scene_rgb, &cam, 1, &req, err);
    for (size_t i = 0; !rc && i < 3 * np; i++) {
        float v = rgb[i] < 0 ? 0 : rgb[i] > 1 ? 1 : rgb[i];
        pv->rgb[i] = (uint8_t)(v * 255.0f + 0.5f);
    }
    free(rgb);
    if (rc) {
        free(pv->rgb);
        pv->rgb = NULL;
        return rc;
    }
    pv->width = cam.width, pv->height = cam.height;
    pv->pose[0] = pos[0], pv->pose[1] = pos[1], pv->pose[2] = pos[2], pv->pose[3] = yaw, pv->pose[4] = pitch;
    return SP_OK;
}

/* Relevance of Gaussian at m to the found targets from their instances' boxes (the bare splat:
 * no field to score): the most confident instance containing it. */
static float box_relevance(const float *m, const sp_nav_target *targets, int n)
{
    float r = 0;
    for (int t = 0; t < n; t++)
        for (int k = 0; targets[t].found && k < targets[t].n; k++) {
            const sp_nav_instance *in = &targets[t].inst[k];
            if (m[0] >= in->box.min[0] && m[0] <= in->box.max[0] && m[1] >= in->box.min[1] &&
                m[1] <= in->box.max[1] && m[2] >= in->z_min && m[2] <= in->z_max)
                r = fmaxf(r, fminf(1.0f, in->confidence));
        }
    return r;
}

/* Per Gaussian the most relevant of the found targets: with an engine its calibrated per-Gaussian
 * relevancy of each target's text (0.5 = no preference .. 1, stretched to 0 .. 1), the field's own
 * answer in the engine's frame; without one the instances' boxes. */
int nav_set_relevance(sp_nav *nav, const sp_nav_target *targets, int n, sp_error *err)
{
    const sp_splat *s = &nav->aux;
    float *rel = nav->engine && n > 0 ? malloc(sizeof(float) * s->n) : NULL;
    if (nav->engine && n > 0 && !rel) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    for (size_t i = 0; i < s->n; i++)
        nav->aux.features[2 * i + 1] = rel ? 0.0f : box_relevance(s->means + 3 * i, targets, n);
    for (int t = 0; rel && t < n; t++) {
        if (!targets[t].found) continue;
        int rc = sp_query_engine_relevancy(nav->engine, targets[t].text, rel, NULL, err);
        if (rc) {
            free(rel);
            return sp_error_prefix(err, "nav: relevance of '%s': ", targets[t].text);
        }
        for (size_t i = 0; i < s->n; i++) {
            float v = 2.0f * (rel[i] - 0.5f);
            v = v < 0 ? 0 : v > 1 ? 1 : v;
            if (v > nav->aux.features[2 * i + 1]) nav->aux.features[2 * i + 1] = v;
        }
    }
    free(rel);
    return sp_scene_update(nav->scene_aux, &nav->aux, SP_SCENE_CHANGED_FEATURES, err);
}
