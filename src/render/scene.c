/* Uploaded scenes and rendering for callers other than training: sp_scene (a host splat's
 * geometry, SH and/or features on a device, updated by the caller's say-so), sp_render_views
 * (many views of one scene: colours from SH per view, one projection and sort per view shared by
 * the RGB and feature passes, outputs downloaded after the batch) and sp_render_splat (a scene
 * for one call). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/backend.h"
#include "render/render_internal.h"

/* Device memory one batch of views may take for its colours and outputs (the CUDA backend adds
 * its per-view projections, about 44 bytes per Gaussian and view); views beyond it go in the next
 * batch. A batch costs one wait for the GPU, so a few per call is noise. */
#define BATCH_BYTES ((size_t)256 << 20)

struct sp_scene {
    sp_device *dev;
    unsigned what;    /* SP_SCENE_RGB | SP_SCENE_FEATURES */
    int valid;        /* 0 after a failed update */
    size_t n;
    int sh_degree, feat_dim;
    float *means, *quats, *log_scales, *opacity, *sh, *features; /* device */
    sp_device_scratch out; /* per-view colours and outputs of sp_render_views, grow-only */
};

/* ---- scenes ------------------------------------------------------------------------------------ */

static void release_buffers(sp_scene *sc)
{
    float **all[] = {&sc->means, &sc->quats, &sc->log_scales, &sc->opacity, &sc->sh, &sc->features};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        sp_device_release(sc->dev, *all[i]);
        *all[i] = NULL;
    }
}

/* The first non-finite value of field `name` ([n][w] floats), or 0. */
static int check_field(const char *name, const float *v, size_t n, size_t w, sp_error *err)
{
    for (size_t i = 0; i < n * w; i++)
        if (!isfinite(v[i]))
            return sp_error_set(err, SP_E_NUMERIC, "scene: Gaussian %zu has a non-finite %s (%g)",
                                i / w, name, v[i]);
    return 0;
}

static int check_splat(const sp_splat *s, unsigned what, sp_error *err)
{
    if (!s) return sp_error_set(err, SP_E_ARG, "scene: NULL splat");
    if (what & ~(unsigned)(SP_SCENE_RGB | SP_SCENE_FEATURES))
        return sp_error_set(err, SP_E_ARG, "scene: unknown content flags 0x%x", what);
    if (s->n > (size_t)INT32_MAX)
        return sp_error_set(err, SP_E_ARG, "scene: %zu Gaussians exceed 2^31", s->n);
    if (s->n > 0 && (!s->means || !s->quats || !s->log_scales || !s->opacity_logits))
        return sp_error_set(err, SP_E_ARG, "scene: the splat lacks means, quats, log_scales or "
                            "opacity_logits");
    if ((what & SP_SCENE_RGB) && (s->sh_degree < 0 || s->sh_degree > 3 || (s->n > 0 && !s->sh)))
        return sp_error_set(err, SP_E_ARG, "scene: RGB asked for, but the splat's SH degree %d or "
                            "SH buffer is invalid", s->sh_degree);
    if ((what & SP_SCENE_FEATURES) && (s->feat_dim < 1 || (s->n > 0 && !s->features)))
        return sp_error_set(err, SP_E_ARG, "scene: features asked for, but the splat has none "
                            "(feat_dim %d)", s->feat_dim);
    if ((what & SP_SCENE_FEATURES) && s->feat_dim > SP_CHANNELS_MAX)
        return sp_error_set(err, SP_E_ARG, "scene: feat_dim %d exceeds %d", s->feat_dim,
                            SP_CHANNELS_MAX);
    return 0;
}

static int check_values(const sp_splat *s, unsigned what, unsigned changed, sp_error *err)
{
    int rc = 0;
    size_t n = s->n;
    if (changed & SP_SCENE_CHANGED_GEOMETRY)
        if ((rc = check_field("mean", s->means, n, 3, err)) ||
            (rc = check_field("quaternion", s->quats, n, 4, err)) ||
            (rc = check_field("log scale", s->log_scales, n, 3, err)) ||
            (rc = check_field("opacity logit", s->opacity_logits, n, 1, err)))
            return rc;
    if ((changed & SP_SCENE_CHANGED_SH) && (what & SP_SCENE_RGB) &&
        (rc = check_field("SH coefficient", s->sh, n, (size_t)sp_sh_coeffs(s->sh_degree) * 3, err)))
        return rc;
    if ((changed & SP_SCENE_CHANGED_FEATURES) && (what & SP_SCENE_FEATURES) &&
        (rc = check_field("feature", s->features, n, (size_t)s->feat_dim, err)))
        return rc;
    return 0;
}

/* Uploads count floats into *dst, allocating it first when NULL. */
static int put(sp_scene *sc, float **dst, const float *src, size_t count, sp_error *err)
{
    if (count == 0) return 0;
    if (!*dst && !(*dst = sp_device_alloc_scratch(sc->dev, count * sizeof(float), err)))
        return err && err->code ? err->code : SP_E_NOMEM;
    return sp_device_upload(sc->dev, *dst, src, count * sizeof(float), err);
}

static int upload(sp_scene *sc, const sp_splat *s, unsigned changed, sp_error *err)
{
    size_t n = s->n;
    int rc = 0;
    if (changed & SP_SCENE_CHANGED_GEOMETRY)
        if ((rc = put(sc, &sc->means, s->means, n * 3, err)) ||
            (rc = put(sc, &sc->quats, s->quats, n * 4, err)) ||
            (rc = put(sc, &sc->log_scales, s->log_scales, n * 3, err)) ||
            (rc = put(sc, &sc->opacity, s->opacity_logits, n, err)))
            return rc;
    if ((changed & SP_SCENE_CHANGED_SH) && (sc->what & SP_SCENE_RGB) &&
        (rc = put(sc, &sc->sh, s->sh, n * (size_t)sp_sh_coeffs(s->sh_degree) * 3, err)))
        return rc;
    if ((changed & SP_SCENE_CHANGED_FEATURES) && (sc->what & SP_SCENE_FEATURES) &&
        (rc = put(sc, &sc->features, s->features, n * (size_t)s->feat_dim, err)))
        return rc;
    return 0;
}

int sp_scene_create(sp_scene **out, sp_device *dev, const sp_splat *s, unsigned what,
                    sp_error *err)
{
    *out = NULL;
    if (!dev) return sp_error_set(err, SP_E_ARG, "scene: NULL device");
    int rc = check_splat(s, what, err);
    if (!rc) rc = check_values(s, what, SP_SCENE_CHANGED_ALL, err);
    if (rc) return rc;
    sp_scene *sc = calloc(1, sizeof *sc);
    if (!sc) return sp_error_set(err, SP_E_NOMEM, "scene: out of memory");
    sc->dev = dev;
    sc->what = what;
    sc->n = s->n;
    sc->sh_degree = (what & SP_SCENE_RGB) ? s->sh_degree : 0;
    sc->feat_dim = (what & SP_SCENE_FEATURES) ? s->feat_dim : 0;
    if ((rc = upload(sc, s, SP_SCENE_CHANGED_ALL, err))) {
        sp_scene_free(sc);
        return sp_error_prefix(err, "scene upload: ");
    }
    sc->valid = 1;
    *out = sc;
    return 0;
}

int sp_scene_update(sp_scene *sc, const sp_splat *s, unsigned changed, sp_error *err)
{
    if (!sc) return sp_error_set(err, SP_E_ARG, "sp_scene_update: NULL scene");
    int rc = check_splat(s, sc->what, err);
    if (rc) return rc;
    int reshaped = s->n != sc->n || ((sc->what & SP_SCENE_RGB) && s->sh_degree != sc->sh_degree) ||
                   ((sc->what & SP_SCENE_FEATURES) && s->feat_dim != sc->feat_dim);
    if (reshaped) changed = SP_SCENE_CHANGED_ALL;
    changed &= SP_SCENE_CHANGED_ALL;
    if ((rc = check_values(s, sc->what, changed, err))) return rc;
    sc->valid = 0;
    if (reshaped) {
        release_buffers(sc);
        sc->n = s->n;
        sc->sh_degree = (sc->what & SP_SCENE_RGB) ? s->sh_degree : 0;
        sc->feat_dim = (sc->what & SP_SCENE_FEATURES) ? s->feat_dim : 0;
    }
    if ((rc = upload(sc, s, changed, err))) return sp_error_prefix(err, "sp_scene_update: ");
    sc->valid = 1;
    return 0;
}

void sp_scene_free(sp_scene *sc)
{
    if (!sc) return;
    release_buffers(sc);
    sp_device_scratch_release(sc->dev, &sc->out);
    free(sc);
}

size_t sp_scene_count(const sp_scene *sc) { return sc->n; }
int sp_scene_feat_dim(const sp_scene *sc) { return sc->feat_dim; }
sp_device *sp_scene_device(const sp_scene *sc) { return sc->dev; }
const float *sp_scene_device_features(const sp_scene *sc) { return sc->valid ? sc->features : NULL; }

int sp_scene_copy_features(sp_scene *sc, const float *d_features, sp_error *err)
{
    if (!sc || !d_features) return sp_error_set(err, SP_E_ARG, "sp_scene_copy_features: NULL argument");
    if (!sc->valid) return sp_error_set(err, SP_E_ARG, "sp_scene_copy_features: the scene's last update failed");
    if (!(sc->what & SP_SCENE_FEATURES))
        return sp_error_set(err, SP_E_ARG, "sp_scene_copy_features: the scene was made without "
                            "SP_SCENE_FEATURES");
    size_t bytes = sc->n * (size_t)sc->feat_dim * sizeof(float);
    return bytes ? sp_device_copy(sc->dev, sc->features, d_features, bytes, err) : 0;
}

int sp_scene_raster_in(const sp_scene *sc, sp_raster_in *in, sp_error *err)
{
    if (!sc || !in) return sp_error_set(err, SP_E_ARG, "sp_scene_raster_in: NULL argument");
    if (!sc->valid) return sp_error_set(err, SP_E_ARG, "scene: its last update failed");
    memset(in, 0, sizeof *in);
    in->n = sc->n;
    in->means = sc->means;
    in->quats = sc->quats;
    in->log_scales = sc->log_scales;
    in->opacity_logits = sc->opacity;
    return 0;
}

/* ---- views --------------------------------------------------------------------------------------- */

/* What one request needs on the device, in floats, laid out in the scene's output scratch. */
typedef struct {
    int skip;       /* nothing asked */
    int rgb_pass;   /* composite SH colours (rgb asked) */
    int feat_pass;  /* composite features */
    int want_alpha; /* alpha buffer (asked, or to normalise expected depth) */
    int want_depth; /* expected-depth numerator */
    int want_surface;
    int direct;     /* on_device: the request's own buffers take the outputs */
    size_t colors, image_rgb, image_feat, depth, alpha, surface, total; /* offsets, in floats */
} view_plan;

static int check_request(const sp_scene *sc, size_t v, const sp_render_request *q, sp_error *err)
{
    if ((q->rgb) && !(sc->what & SP_SCENE_RGB))
        return sp_error_set(err, SP_E_ARG, "view %zu: rgb asked for, but the scene was made without "
                            "SP_SCENE_RGB", v);
    if (q->features && !(sc->what & SP_SCENE_FEATURES))
        return sp_error_set(err, SP_E_ARG, "view %zu: features asked for, but the scene has none "
                            "(made without SP_SCENE_FEATURES)", v);
    if (q->depth_mode != SP_DEPTH_EXPECTED && q->depth_mode != SP_DEPTH_SURFACE)
        return sp_error_set(err, SP_E_ARG, "view %zu: unknown depth mode %d", v, (int)q->depth_mode);
    if (!(q->depth_alpha >= 0.f && q->depth_alpha <= 1.f))
        return sp_error_set(err, SP_E_ARG, "view %zu: depth_alpha %g is outside (0, 1] (0 = %g)", v,
                            q->depth_alpha, SP_SURFACE_ALPHA);
    return 0;
}

static view_plan plan_view(const sp_scene *sc, const sp_camera *cam, const sp_render_request *q)
{
    view_plan p;
    memset(&p, 0, sizeof p);
    size_t npix = (size_t)cam->width * cam->height, at = 0;
    int expected = q->depth && q->depth_mode == SP_DEPTH_EXPECTED;
    p.rgb_pass = q->rgb != NULL;
    p.feat_pass = q->features != NULL;
    p.want_alpha = q->alpha || expected;
    p.want_depth = expected;
    p.want_surface = q->depth && q->depth_mode == SP_DEPTH_SURFACE;
    p.skip = !p.rgb_pass && !p.feat_pass && !p.want_alpha && !p.want_surface;
    if (p.skip) return p;
    /* colours: RGB from SH per view; a depth/alpha-only view composites the opacity logits as
     * one dummy channel (any [n] buffer serves: only the weights matter). Outputs left on the
     * device take no scratch but the dummy image and an alpha nobody asked for. */
    int d = p.direct = q->on_device != 0, dummy = !p.rgb_pass && !p.feat_pass && (p.want_alpha || p.want_depth);
    p.colors = at, at += p.rgb_pass ? sc->n * 3 : 0;
    p.image_rgb = at, at += npix * ((p.rgb_pass && !d) || dummy ? 3 : 0);
    p.image_feat = at, at += p.feat_pass && !d ? npix * (size_t)sc->feat_dim : 0;
    p.depth = at, at += p.want_depth && !d ? npix : 0;
    p.alpha = at, at += p.want_alpha && !(d && q->alpha) ? npix : 0;
    p.surface = at, at += p.want_surface && !d ? npix : 0;
    p.total = (at + 63) & ~(size_t)63; /* keeps each view's block 256-byte aligned */
    return p;
}

/* Fills the backend's view description from a plan over the scratch block at base. */
static int setup_view(sp_scene *sc, const sp_camera *cam, const sp_render_request *q,
                      const view_plan *p, float *base, sp_raster_view *vw, sp_error *err)
{
    memset(vw, 0, sizeof *vw);
    vw->cam = *cam;
    int d = p->direct;
    if (p->rgb_pass) {
        int rc = sp_sh_to_rgb(sc->dev, sc->n, sc->sh_degree, sc->sh_degree, sc->sh, sc->means,
                              sp_camera_center(cam), base + p->colors, 3, err);
        if (rc) return rc;
        vw->pass[vw->n_pass++] = (sp_raster_pass){base + p->colors, 3, q->background,
                                                  d ? q->rgb : base + p->image_rgb};
    }
    if (p->feat_pass)
        vw->pass[vw->n_pass++] = (sp_raster_pass){sc->features, sc->feat_dim, NULL,
                                                  d ? q->features : base + p->image_feat};
    /* depth or alpha without colours: composite the opacities as one dummy channel for the
     * weights; first-surface depth alone is its own pass and needs no compositing */
    if (vw->n_pass == 0 && (p->want_alpha || p->want_depth))
        vw->pass[vw->n_pass++] = (sp_raster_pass){sc->opacity, 1, NULL, base + p->image_rgb};
    vw->depth = p->want_depth ? (d ? q->depth : base + p->depth) : NULL;
    vw->alpha = p->want_alpha ? (d && q->alpha ? q->alpha : base + p->alpha) : NULL;
    vw->surface_depth = p->want_surface ? (d ? q->depth : base + p->surface) : NULL;
    vw->surface_alpha = q->depth_alpha > 0.f ? q->depth_alpha : SP_SURFACE_ALPHA;
    return 0;
}

static int download_view(sp_scene *sc, const sp_camera *cam, const sp_render_request *q,
                         const view_plan *p, const float *base, sp_error *err)
{
    sp_device *d = sc->dev;
    size_t npix = (size_t)cam->width * cam->height, fb = sizeof(float);
    int rc = 0;
    if (p->direct) /* outputs are in place: only expected depth still needs dividing */
        return p->want_depth ? sp_render_backend_of(d)->depth_normalize(
                                   d, q->depth, q->alpha ? q->alpha : base + p->alpha, npix, err)
                             : 0;
    if (q->rgb) rc = sp_device_download(d, q->rgb, base + p->image_rgb, npix * 3 * fb, err);
    if (!rc && q->features)
        rc = sp_device_download(d, q->features, base + p->image_feat, npix * (size_t)sc->feat_dim * fb, err);
    if (!rc && q->alpha) rc = sp_device_download(d, q->alpha, base + p->alpha, npix * fb, err);
    if (!rc && p->want_surface) rc = sp_device_download(d, q->depth, base + p->surface, npix * fb, err);
    if (rc || !p->want_depth) return rc;
    /* expected depth = sum w z / sum w, 0 where (almost) nothing was drawn */
    float *alpha = q->alpha ? q->alpha : malloc(npix * fb);
    if (!alpha) return sp_error_set(err, SP_E_NOMEM, "render: out of memory");
    rc = q->alpha ? 0 : sp_device_download(d, alpha, base + p->alpha, npix * fb, err);
    if (!rc) rc = sp_device_download(d, q->depth, base + p->depth, npix * fb, err);
    for (size_t i = 0; !rc && i < npix; i++) q->depth[i] = alpha[i] >= 1e-6f ? q->depth[i] / alpha[i] : 0.f;
    if (alpha != q->alpha) free(alpha);
    return rc;
}

/* Renders views [v0, v1) as one batch through the scene's output scratch. */
static int render_batch(sp_raster *r, sp_scene *sc, const sp_camera *cams,
                        const sp_render_request *reqs, size_t v0, size_t v1, const view_plan *plans,
                        sp_raster_view *views, sp_error *err)
{
    size_t total = 0, nv = 0;
    for (size_t v = v0; v < v1; v++) total += plans[v].total;
    int rc = sp_device_scratch_reserve(sc->dev, &sc->out, total * sizeof(float), err);
    if (rc) return rc;
    float *base = sc->out.ptr, *at = base;
    for (size_t v = v0; v < v1 && !rc; at += plans[v].total, v++)
        if (!plans[v].skip) rc = setup_view(sc, &cams[v], &reqs[v], &plans[v], at, &views[nv++], err);
    sp_raster_in geom;
    if (!rc) rc = sp_scene_raster_in(sc, &geom, err);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    if (!rc && nv) rc = sp_raster_views(r, &cfg, &geom, views, nv, err);
    at = base;
    for (size_t v = v0; v < v1 && !rc; at += plans[v].total, v++)
        if (!plans[v].skip) rc = download_view(sc, &cams[v], &reqs[v], &plans[v], at, err);
    return rc;
}

int sp_render_views(sp_raster *r, sp_scene *sc, const sp_camera *cams, size_t n,
                    const sp_render_request *reqs, sp_error *err)
{
    if (!r || !sc || (n > 0 && (!cams || !reqs)))
        return sp_error_set(err, SP_E_ARG, "sp_render_views: NULL argument");
    if (sp_raster_device(r) != sc->dev)
        return sp_error_set(err, SP_E_ARG, "sp_render_views: the raster and the scene are on "
                            "different devices");
    if (!sc->valid) return sp_error_set(err, SP_E_ARG, "sp_render_views: the scene's last update failed");
    if (n == 0) return 0;
    sp_raster_cfg cfg = sp_raster_cfg_default();
    view_plan *plans = malloc(n * sizeof *plans);
    sp_raster_view *views = malloc(n * sizeof *views);
    int rc = plans && views ? 0 : sp_error_set(err, SP_E_NOMEM, "sp_render_views: out of memory");
    for (size_t v = 0; v < n && !rc; v++) {
        char what[48];
        snprintf(what, sizeof what, "sp_render_views: view %zu", v);
        if (!(rc = sp_raster_check_view(what, &cams[v], &cfg, err)) &&
            !(rc = check_request(sc, v, &reqs[v], err)))
            plans[v] = plan_view(sc, &cams[v], &reqs[v]);
    }
    /* batches of views whose colours and outputs fit BATCH_BYTES (at least one view each) */
    size_t per_gauss = sc->n * 44; /* the CUDA backend's projection of one view */
    for (size_t v0 = 0, v1; v0 < n && !rc; v0 = v1) {
        size_t bytes = 0;
        for (v1 = v0; v1 < n; v1++) {
            size_t b = plans[v1].total * sizeof(float) + per_gauss;
            if (v1 > v0 && bytes + b > BATCH_BYTES) break;
            bytes += b;
        }
        rc = render_batch(r, sc, cams, reqs, v0, v1, plans, views, err);
    }
    free(plans);
    free(views);
    return rc;
}

int sp_render_splat(sp_raster *r, const sp_splat *s, const sp_camera *cam,
                    const sp_render_request *req, sp_error *err)
{
    if (!r || !s || !cam || !req) return sp_error_set(err, SP_E_ARG, "sp_render_splat: NULL argument");
    unsigned what = (req->rgb ? SP_SCENE_RGB : 0) | (req->features ? SP_SCENE_FEATURES : 0);
    sp_scene *sc = NULL;
    int rc = sp_scene_create(&sc, sp_raster_device(r), s, what, err);
    if (!rc) rc = sp_render_views(r, sc, cam, 1, req, err);
    sp_scene_free(sc);
    return rc ? sp_error_prefix(err, "sp_render_splat: ") : 0;
}
