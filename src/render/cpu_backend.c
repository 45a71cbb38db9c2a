/* The CPU render backend: the per-view pipeline project -> tiles -> composite (project.c,
 * tiles.c, rasterize_fwd.c, rasterize_bwd.c, rasterize_surface.c) on the device's pool, behind
 * the render backend table (backend.h). Host scratch is grow-only and accounted to the device. */
#include <stdlib.h>
#include <string.h>

#include "render/backend.h"
#include "render/render_internal.h"

int sp_scratch_reserve(sp_device *dev, void **buf, size_t *cap, size_t bytes, sp_error *err)
{
    if (bytes <= *cap && *buf) return 0;
    size_t want = bytes + bytes / 4 + 256; /* headroom: views of similar size reuse the block */
    void *p = sp_alloc(want);
    if (!p) return sp_error_set(err, SP_E_NOMEM, "rasterizer scratch: cannot allocate %zu bytes", want);
    sp_free(*buf);
    sp_device_account(dev, (long long)want - (long long)*cap);
    *buf = p;
    *cap = want;
    return 0;
}

void sp_scratch_release(sp_device *dev, void **buf, size_t *cap)
{
    sp_free(*buf);
    sp_device_account(dev, -(long long)*cap);
    *buf = NULL;
    *cap = 0;
}

static int cpu_create(void **state, sp_device *dev, sp_error *err)
{
    cpu_raster *c = calloc(1, sizeof *c);
    if (!c) return sp_error_set(err, SP_E_NOMEM, "sp_raster_create: out of memory");
    c->dev = dev;
    *state = c;
    return 0;
}

static void cpu_destroy(void *state)
{
    cpu_raster *c = state;
    if (!c) return;
    sp_device *d = c->dev;
    sp_scratch_release(d, &c->proj_buf, &c->proj_cap);
    sp_scratch_release(d, &c->tile_buf, &c->tile_cap);
    sp_scratch_release(d, &c->sort_buf, &c->sort_cap);
    sp_scratch_release(d, &c->pix_buf, &c->pix_cap);
    sp_scratch_release(d, &c->slot_buf, &c->slot_cap);
    for (int i = 0; i < c->n_scratch; i++) sp_scratch_release(d, &c->scratch[i].buf, &c->scratch[i].cap);
    free(c->scratch);
    free(c->background);
    free(c);
}

/* Copies the background (HOST, may be NULL) into the state, D floats. */
static int set_background(cpu_raster *c, const float *bg, int D, sp_error *err)
{
    if (c->bg_cap < (size_t)D) {
        float *b = realloc(c->background, (size_t)D * sizeof(float));
        if (!b) return sp_error_set(err, SP_E_NOMEM, "sp_raster_forward: out of memory");
        c->background = b;
        c->bg_cap = (size_t)D;
    }
    for (int k = 0; k < D; k++) c->background[k] = bg ? bg[k] : 0.f;
    return 0;
}

/* Projects and bins one view of `in`'s Gaussians (colours and D set by the caller later). */
static int begin_view(cpu_raster *c, const sp_camera *cam, const sp_raster_cfg *cfg,
                      const sp_raster_in *in, sp_error *err)
{
    c->valid = 0;
    c->cam = *cam;
    c->cfg = *cfg;
    c->in = *in;
    c->W = cam->width;
    c->H = cam->height;
    c->D = in->D;
    c->n = in->n;
    int rc = cpu_project(c, err);
    if (!rc) rc = cpu_bin_tiles(c, err);
    return rc;
}

/* Composites one set of channels over the current view's lists. */
static int composite(cpu_raster *c, const float *colors, int D, const float *bg, sp_raster_out *out,
                     sp_error *err)
{
    int rc = set_background(c, bg, D, err);
    if (rc) return rc;
    c->in.colors = colors;
    c->in.D = D;
    c->D = D;
    c->in.background = c->background;
    return cpu_rasterize_forward(c, out, err);
}

static int cpu_forward(void *state, const sp_camera *cam, const sp_raster_cfg *cfg,
                       const sp_raster_in *in, sp_raster_out *out, sp_error *err)
{
    cpu_raster *c = state;
    int rc = begin_view(c, cam, cfg, in, err);
    if (!rc) rc = composite(c, in->colors, in->D, in->background, out, err);
    if (!rc && out->surface_depth) rc = cpu_rasterize_surface(c, cfg->surface_alpha, out->surface_depth, err);
    if (rc) return sp_error_prefix(err, "sp_raster_forward (CPU): ");
    c->valid = 1;
    return 0;
}

static int cpu_backward(void *state, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                        sp_error *err)
{
    cpu_raster *c = state;
    if (!c->valid)
        return sp_error_set(err, SP_E_ARG, "sp_raster_backward: no successful forward to differentiate");
    int rc = cpu_rasterize_backward(c, gin, err);
    if (rc) return sp_error_prefix(err, "sp_raster_backward (CPU): ");
    cpu_project_backward(c, grads);
    return 0;
}

static const int32_t *cpu_radii(const void *state)
{
    const cpu_raster *c = state;
    return c->valid ? c->radii : NULL;
}

static size_t cpu_last_pairs(const void *state)
{
    const cpu_raster *c = state;
    return c->valid ? c->pairs : 0;
}

/* Views one after another; each view's projection and lists serve all its passes. */
static int cpu_views(void *state, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                     const sp_raster_view *views, size_t n_views, sp_error *err)
{
    cpu_raster *c = state;
    int rc = 0;
    for (size_t v = 0; v < n_views && !rc; v++) {
        const sp_raster_view *vw = &views[v];
        rc = begin_view(c, &vw->cam, cfg, geom, err);
        for (int k = 0; k < vw->n_pass && !rc; k++) {
            const sp_raster_pass *p = &vw->pass[k];
            /* depth and alpha are the same for every pass: written by the first */
            sp_raster_out out = {p->image, k ? NULL : vw->depth, k ? NULL : vw->alpha, NULL};
            rc = composite(c, p->colors, p->D, p->background, &out, err);
        }
        if (!rc && vw->surface_depth) rc = cpu_rasterize_surface(c, vw->surface_alpha, vw->surface_depth, err);
        if (rc) sp_error_prefix(err, "view %zu (CPU): ", v);
    }
    c->valid = 0;
    return rc;
}

static int cpu_depth_normalize(sp_device *dev, float *depth, const float *alpha, size_t npix,
                               sp_error *err)
{
    (void)dev, (void)err;
    for (size_t i = 0; i < npix; i++) depth[i] = alpha[i] >= 1e-6f ? depth[i] / alpha[i] : 0.f;
    return 0;
}

/* The CPU backend does not time its stages (sp_raster_last_stages gives zeros). */
static int cpu_stages(void *state, sp_raster_stages *out, sp_error *err)
{
    (void)state, (void)out, (void)err;
    return 0;
}

const sp_render_backend sp_render_cpu_backend = {
    "cpu", cpu_create, cpu_destroy, cpu_forward, cpu_backward, cpu_radii, cpu_last_pairs,
    cpu_views, cpu_depth_normalize, cpu_sh_to_rgb, cpu_sh_to_rgb_backward, cpu_stages};

const sp_render_backend *sp_render_backend_of(const sp_device *dev)
{
    return sp_device_kind_of(dev) == SP_DEVICE_CUDA ? sp_render_cuda_backend() : &sp_render_cpu_backend;
}
