/* sp_raster: argument checks and dispatch through the render backend table (backend.h) to the
 * CPU pipeline or the CUDA backend. The backends trust what passes these checks. */
#include <stdlib.h>
#include <string.h>

#include "render/backend.h"
#include "render/render_internal.h"

struct sp_raster {
    sp_device *dev;
    const sp_render_backend *be;
    void *state; /* the backend's per-view state */
};

sp_raster_cfg sp_raster_cfg_default(void)
{
    sp_raster_cfg c;
    memset(&c, 0, sizeof c);
    c.near_plane = 0.01f;
    c.far_plane = 1e10f;
    c.eps2d = SP_EPS2D;
    c.antialiased = 0;
    c.surface_alpha = SP_SURFACE_ALPHA;
    c.chunk_fwd = c.chunk_bwd = 0;
    return c;
}

int sp_raster_create(sp_raster **out, sp_device *dev, sp_error *err)
{
    *out = NULL;
    if (!dev) return sp_error_set(err, SP_E_ARG, "sp_raster_create: NULL device");
    const sp_render_backend *be = sp_render_backend_of(dev);
    if (!be)
        return sp_error_set(err, SP_E_NODEVICE, "sp_raster_create: no render backend for %s",
                            sp_device_name(dev));
    sp_raster *r = calloc(1, sizeof *r);
    if (!r) return sp_error_set(err, SP_E_NOMEM, "sp_raster_create: out of memory");
    r->dev = dev;
    r->be = be;
    int rc = be->create(&r->state, dev, err);
    if (rc) {
        free(r);
        return rc;
    }
    *out = r;
    return 0;
}

void sp_raster_free(sp_raster *r)
{
    if (!r) return;
    r->be->destroy(r->state);
    free(r);
}

sp_device *sp_raster_device(sp_raster *r) { return r->dev; }

static int is_width(int w)
{
#define SP_WIDTH_IS(x) if (w == (x)) return 1;
    SP_CHANNEL_WIDTHS(SP_WIDTH_IS)
#undef SP_WIDTH_IS
    return 0;
}

/* Camera and cfg checks shared by single views and batches; `what` names the call. */
int sp_raster_check_view(const char *what, const sp_camera *cam, const sp_raster_cfg *cfg,
                         sp_error *err)
{
    if (cam->width <= 0 || cam->height <= 0 || cam->width > 65536 || cam->height > 65536)
        return sp_error_set(err, SP_E_ARG, "%s: image size %dx%d is invalid", what, cam->width,
                            cam->height);
    if (!(cam->fx > 0.f) || !(cam->fy > 0.f) || !isfinite(cam->cx) || !isfinite(cam->cy))
        return sp_error_set(err, SP_E_ARG, "%s: intrinsics fx=%g fy=%g cx=%g cy=%g are invalid",
                            what, cam->fx, cam->fy, cam->cx, cam->cy);
    if (!(cfg->near_plane > 0.f) || !(cfg->far_plane > cfg->near_plane))
        return sp_error_set(err, SP_E_ARG, "%s: near %g / far %g planes are invalid (need 0 < "
                            "near < far)", what, cfg->near_plane, cfg->far_plane);
    if (!(cfg->eps2d >= 0.f)) return sp_error_set(err, SP_E_ARG, "%s: eps2d %g < 0", what, cfg->eps2d);
    if (!(cfg->surface_alpha > 0.f && cfg->surface_alpha <= 1.f))
        return sp_error_set(err, SP_E_ARG, "%s: surface_alpha %g is outside (0, 1]", what,
                            cfg->surface_alpha);
    if (cfg->bwd_gather < -1 || cfg->bwd_gather > 2)
        return sp_error_set(err, SP_E_ARG, "%s: bwd_gather %d is not one of -1, 0, 1, 2", what,
                            cfg->bwd_gather);
    if (cfg->bwd_px < 0 || cfg->bwd_px > 4 || cfg->bwd_px == 3)
        return sp_error_set(err, SP_E_ARG, "%s: bwd_px %d is not one of 0, 1, 2, 4", what, cfg->bwd_px);
    if (cfg->fwd_px < 0 || cfg->fwd_px > 4 || cfg->fwd_px == 3)
        return sp_error_set(err, SP_E_ARG, "%s: fwd_px %d is not one of 0, 1, 2, 4", what, cfg->fwd_px);
    if (cfg->warp_cull < -1 || cfg->warp_cull > 1)
        return sp_error_set(err, SP_E_ARG, "%s: warp_cull %d is not one of -1, 0, 1", what,
                            cfg->warp_cull);
    if ((cfg->chunk_fwd && !is_width(cfg->chunk_fwd)) || (cfg->chunk_bwd && !is_width(cfg->chunk_bwd)))
        return sp_error_set(err, SP_E_ARG, "%s: chunk widths %d / %d: each must be 0 or one of the "
                            "specialised widths (SP_CHANNEL_WIDTHS)", what, cfg->chunk_fwd,
                            cfg->chunk_bwd);
    return 0;
}

static int check_forward(sp_raster *r, const sp_camera *cam, const sp_raster_cfg *cfg,
                         const sp_raster_in *in, const sp_raster_out *out, sp_error *err)
{
    if (!cam || !cfg || !in || !out)
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: NULL camera, cfg, input or output");
    int rc = sp_raster_check_view("sp_raster_forward", cam, cfg, err);
    if (rc) return rc;
    if (in->D < 1 || !sp_device_supports(r->dev, SP_STAGE_RASTER_FWD, in->D))
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: channel count D=%d outside 1..%d",
                            in->D, SP_CHANNELS_MAX);
    if (in->n > (size_t)INT32_MAX)
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: %zu Gaussians exceed 2^31", in->n);
    if (in->n > 0 && (!in->means || !in->quats || !in->log_scales || !in->opacity_logits || !in->colors))
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: a Gaussian buffer (means, quats, "
                            "log_scales, opacity_logits, colors) is NULL");
    if (!out->image) return sp_error_set(err, SP_E_ARG, "sp_raster_forward: output image is NULL");
    return 0;
}

int sp_raster_forward(sp_raster *r, const sp_camera *cam, const sp_raster_cfg *cfg,
                      const sp_raster_in *in, sp_raster_out *out, sp_error *err)
{
    int rc = check_forward(r, cam, cfg, in, out, err);
    if (rc) return rc;
    return r->be->forward(r->state, cam, cfg, in, out, err);
}

int sp_raster_backward(sp_raster *r, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                       sp_error *err)
{
    if (!gin || !grads || !gin->v_image)
        return sp_error_set(err, SP_E_ARG, "sp_raster_backward: NULL gradient input or v_image");
    return r->be->backward(r->state, gin, grads, err);
}

const int32_t *sp_raster_radii(const sp_raster *r) { return r->be->radii(r->state); }

size_t sp_raster_last_pairs(const sp_raster *r) { return r->be->last_pairs(r->state); }

int sp_raster_last_stages(sp_raster *r, sp_raster_stages *out, sp_error *err)
{
    if (!out) return sp_error_set(err, SP_E_ARG, "sp_raster_last_stages: out is NULL");
    memset(out, 0, sizeof *out);
    return r->be->stages(r->state, out, err);
}

int sp_raster_views(sp_raster *r, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                    const sp_raster_view *views, size_t n_views, sp_error *err)
{
    return r->be->views(r->state, cfg, geom, views, n_views, err);
}
