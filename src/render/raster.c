/* sp_raster: argument checks and dispatch to the CPU pipeline (project -> tiles -> rasterize)
 * or the CUDA backend (cuda_api.h), plus sp_render_splat, the host-splat convenience used by the
 * CLI and previews (uploads are cached per splat pointer and count). */
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"
#ifdef SP_HAVE_CUDA
#include "render/cuda_api.h"
#endif

struct sp_raster {
    sp_device *dev;
    cpu_raster cpu;
#ifdef SP_HAVE_CUDA
    sp_cuda_raster *cuda;
#endif
    /* sp_render_splat: device copies of the last splat and its output buffers */
    const sp_splat *cached;
    size_t cached_n;
    float *d_means, *d_quats, *d_log_scales, *d_opacity, *d_sh, *d_features;
    float *d_rgb;        /* [n][3] colours from SH */
    float *d_image;      /* [H][W][max(3, feat_dim)] */
    float *d_depth, *d_alpha;
    size_t image_floats; /* capacity of d_image */
    size_t pix_cap;      /* capacity of d_depth / d_alpha */
};

sp_raster_cfg sp_raster_cfg_default(void)
{
    sp_raster_cfg c;
    c.near_plane = 0.01f;
    c.far_plane = 1e10f;
    c.eps2d = SP_EPS2D;
    c.antialiased = 0;
    return c;
}

int sp_raster_create(sp_raster **out, sp_device *dev, sp_error *err)
{
    *out = NULL;
    if (!dev) return sp_error_set(err, SP_E_ARG, "sp_raster_create: NULL device");
    sp_raster *r = calloc(1, sizeof *r);
    if (!r) return sp_error_set(err, SP_E_NOMEM, "sp_raster_create: out of memory");
    r->dev = dev;
    r->cpu.dev = dev;
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) {
        int rc = sp_cuda_raster_create(&r->cuda, err);
        if (rc) {
            free(r);
            return rc;
        }
    }
#endif
    *out = r;
    return 0;
}

static void cpu_raster_release(cpu_raster *c)
{
    sp_device *d = c->dev;
    sp_scratch_release(d, &c->proj_buf, &c->proj_cap);
    sp_scratch_release(d, &c->tile_buf, &c->tile_cap);
    sp_scratch_release(d, &c->sort_buf, &c->sort_cap);
    sp_scratch_release(d, &c->pix_buf, &c->pix_cap);
    sp_scratch_release(d, &c->slot_buf, &c->slot_cap);
    for (int i = 0; i < c->n_scratch; i++) sp_scratch_release(d, &c->scratch[i].buf, &c->scratch[i].cap);
    free(c->scratch);
    free(c->background);
    memset(c, 0, sizeof *c);
    c->dev = d;
}

void sp_raster_free(sp_raster *r)
{
    if (!r) return;
    sp_raster_forget(r);
    cpu_raster_release(&r->cpu);
#ifdef SP_HAVE_CUDA
    sp_cuda_raster_free(r->cuda);
#endif
    free(r);
}

sp_device *sp_raster_device(sp_raster *r) { return r->dev; }

static int check_forward(const sp_camera *cam, const sp_raster_cfg *cfg, const sp_raster_in *in,
                         const sp_raster_out *out, sp_error *err)
{
    if (!cam || !cfg || !in || !out)
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: NULL camera, cfg, input or output");
    if (cam->width <= 0 || cam->height <= 0 || cam->width > 65536 || cam->height > 65536)
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: image size %dx%d is invalid",
                            cam->width, cam->height);
    if (!(cam->fx > 0.f) || !(cam->fy > 0.f) || !isfinite(cam->cx) || !isfinite(cam->cy))
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: intrinsics fx=%g fy=%g cx=%g cy=%g "
                            "are invalid", cam->fx, cam->fy, cam->cx, cam->cy);
    if (!(cfg->near_plane > 0.f) || !(cfg->far_plane > cfg->near_plane))
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: near %g / far %g planes are invalid "
                            "(need 0 < near < far)", cfg->near_plane, cfg->far_plane);
    if (!(cfg->eps2d >= 0.f))
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: eps2d %g < 0", cfg->eps2d);
    if (in->D < 1 || in->D > 4096)
        return sp_error_set(err, SP_E_ARG, "sp_raster_forward: channel count D=%d outside 1..4096", in->D);
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
    int rc = check_forward(cam, cfg, in, out, err);
    if (rc) return rc;
#ifdef SP_HAVE_CUDA
    if (r->dev->kind == SP_DEVICE_CUDA) return sp_cuda_raster_forward(r->cuda, cam, cfg, in, out, err);
#endif
    cpu_raster *c = &r->cpu;
    c->valid = 0;
    c->cam = *cam;
    c->cfg = *cfg;
    c->in = *in;
    c->W = cam->width;
    c->H = cam->height;
    c->D = in->D;
    c->n = in->n;
    if (c->bg_cap < (size_t)in->D) {
        float *bg = realloc(c->background, (size_t)in->D * sizeof(float));
        if (!bg) return sp_error_set(err, SP_E_NOMEM, "sp_raster_forward: out of memory");
        c->background = bg;
        c->bg_cap = (size_t)in->D;
    }
    for (int k = 0; k < in->D; k++) c->background[k] = in->background ? in->background[k] : 0.f;
    c->in.background = c->background;
    if ((rc = cpu_project(c, err)) || (rc = cpu_bin_tiles(c, err)) ||
        (rc = cpu_rasterize_forward(c, out, err)))
        return sp_error_prefix(err, "sp_raster_forward (CPU): ");
    c->valid = 1;
    return 0;
}

int sp_raster_backward(sp_raster *r, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                       sp_error *err)
{
    if (!gin || !grads || !gin->v_image)
        return sp_error_set(err, SP_E_ARG, "sp_raster_backward: NULL gradient input or v_image");
#ifdef SP_HAVE_CUDA
    if (r->dev->kind == SP_DEVICE_CUDA) return sp_cuda_raster_backward(r->cuda, gin, grads, err);
#endif
    cpu_raster *c = &r->cpu;
    if (!c->valid)
        return sp_error_set(err, SP_E_ARG, "sp_raster_backward: no successful forward to differentiate");
    int rc = cpu_rasterize_backward(c, gin, err);
    if (rc) return sp_error_prefix(err, "sp_raster_backward (CPU): ");
    cpu_project_backward(c, grads);
    return 0;
}

const int32_t *sp_raster_radii(const sp_raster *r)
{
#ifdef SP_HAVE_CUDA
    if (r->dev->kind == SP_DEVICE_CUDA) return sp_cuda_raster_radii(r->cuda);
#endif
    return r->cpu.valid ? r->cpu.radii : NULL;
}

size_t sp_raster_last_pairs(const sp_raster *r)
{
#ifdef SP_HAVE_CUDA
    if (r->dev->kind == SP_DEVICE_CUDA) return sp_cuda_raster_last_pairs(r->cuda);
#endif
    return r->cpu.valid ? r->cpu.pairs : 0;
}

/* ---- sp_render_splat --------------------------------------------------------------------------- */

static void release_ptr(sp_device *dev, float **p)
{
    sp_device_release(dev, *p);
    *p = NULL;
}

void sp_raster_forget(sp_raster *r)
{
    if (!r) return;
    sp_device *d = r->dev;
    release_ptr(d, &r->d_means);
    release_ptr(d, &r->d_quats);
    release_ptr(d, &r->d_log_scales);
    release_ptr(d, &r->d_opacity);
    release_ptr(d, &r->d_sh);
    release_ptr(d, &r->d_features);
    release_ptr(d, &r->d_rgb);
    release_ptr(d, &r->d_image);
    release_ptr(d, &r->d_depth);
    release_ptr(d, &r->d_alpha);
    r->image_floats = 0;
    r->pix_cap = 0;
    r->cached = NULL;
    r->cached_n = 0;
}

static int upload_floats(sp_raster *r, float **dst, const float *src, size_t count, sp_error *err)
{
    if (!src || count == 0) return 0;
    *dst = sp_device_alloc(r->dev, count * sizeof(float), err);
    if (!*dst) return err ? err->code : SP_E_NOMEM;
    return sp_device_upload(r->dev, *dst, src, count * sizeof(float), err);
}

static int upload_splat(sp_raster *r, const sp_splat *s, sp_error *err)
{
    if (r->cached == s && r->cached_n == s->n && r->d_means) return 0;
    sp_raster_forget(r);
    size_t n = s->n;
    int rc;
    if ((rc = upload_floats(r, &r->d_means, s->means, n * 3, err)) ||
        (rc = upload_floats(r, &r->d_quats, s->quats, n * 4, err)) ||
        (rc = upload_floats(r, &r->d_log_scales, s->log_scales, n * 3, err)) ||
        (rc = upload_floats(r, &r->d_opacity, s->opacity_logits, n, err)) ||
        (rc = upload_floats(r, &r->d_sh, s->sh, n * (size_t)sp_sh_coeffs(s->sh_degree) * 3, err)) ||
        (rc = upload_floats(r, &r->d_features, s->features, n * (size_t)s->feat_dim, err))) {
        sp_raster_forget(r);
        return rc;
    }
    r->d_rgb = sp_device_alloc(r->dev, (n ? n : 1) * 3 * sizeof(float), err);
    if (!r->d_rgb) {
        sp_raster_forget(r);
        return err ? err->code : SP_E_NOMEM;
    }
    r->cached = s;
    r->cached_n = n;
    return 0;
}

static int reserve_outputs(sp_raster *r, size_t npix, int Dmax, sp_error *err)
{
    size_t want = npix * (size_t)Dmax;
    if (want > r->image_floats) {
        release_ptr(r->dev, &r->d_image);
        r->image_floats = 0;
        if (!(r->d_image = sp_device_alloc(r->dev, want * sizeof(float), err))) return err ? err->code : SP_E_NOMEM;
        r->image_floats = want;
    }
    if (npix > r->pix_cap) {
        release_ptr(r->dev, &r->d_depth);
        release_ptr(r->dev, &r->d_alpha);
        r->pix_cap = 0;
        if (!(r->d_depth = sp_device_alloc(r->dev, npix * sizeof(float), err)) ||
            !(r->d_alpha = sp_device_alloc(r->dev, npix * sizeof(float), err)))
            return err ? err->code : SP_E_NOMEM;
        r->pix_cap = npix;
    }
    return 0;
}

int sp_render_splat(sp_raster *r, const sp_splat *s, const sp_camera *cam,
                    const sp_render_request *req, sp_error *err)
{
    if (!r || !s || !cam || !req) return sp_error_set(err, SP_E_ARG, "sp_render_splat: NULL argument");
    if (req->features && (s->feat_dim <= 0 || !s->features))
        return sp_error_set(err, SP_E_ARG, "sp_render_splat: features requested but the splat has none");
    if (s->n > 0 && (!s->sh || s->sh_degree < 0 || s->sh_degree > 3))
        return sp_error_set(err, SP_E_ARG, "sp_render_splat: splat SH degree %d or SH buffer invalid",
                            s->sh_degree);
    if (cam->width <= 0 || cam->height <= 0)
        return sp_error_set(err, SP_E_ARG, "sp_render_splat: image size %dx%d is invalid", cam->width,
                            cam->height);
    int rc = upload_splat(r, s, err);
    if (rc) return sp_error_prefix(err, "sp_render_splat: ");
    size_t npix = (size_t)cam->width * cam->height;
    int Dmax = s->feat_dim > 3 ? s->feat_dim : 3;
    if ((rc = reserve_outputs(r, npix, Dmax, err))) return sp_error_prefix(err, "sp_render_splat: ");

    sp_raster_cfg cfg = sp_raster_cfg_default();
    sp_raster_in in = {s->n, r->d_means, r->d_quats, r->d_log_scales, r->d_opacity, r->d_rgb, 3,
                       req->background};
    sp_raster_out out = {r->d_image, r->d_depth, r->d_alpha};
    int need_rgb_pass = req->rgb || !req->features; /* depth/alpha alone: use the rgb pass */
    if (need_rgb_pass) {
        rc = sp_sh_to_rgb(r->dev, s->n, s->sh_degree, s->sh_degree, r->d_sh, r->d_means,
                          sp_camera_center(cam), r->d_rgb, 3, err);
        if (!rc) rc = sp_raster_forward(r, cam, &cfg, &in, &out, err);
        if (!rc && req->rgb) rc = sp_device_download(r->dev, req->rgb, r->d_image, npix * 3 * sizeof(float), err);
        if (rc) return rc;
    }
    if (req->features) {
        in.colors = r->d_features;
        in.D = s->feat_dim;
        in.background = NULL;
        rc = sp_raster_forward(r, cam, &cfg, &in, &out, err);
        if (!rc)
            rc = sp_device_download(r->dev, req->features, r->d_image,
                                    npix * (size_t)s->feat_dim * sizeof(float), err);
        if (rc) return rc;
    }
    if (req->alpha || req->depth) {
        float *alpha = req->alpha ? req->alpha : malloc(npix * sizeof(float));
        if (!alpha) return sp_error_set(err, SP_E_NOMEM, "sp_render_splat: out of memory");
        rc = sp_device_download(r->dev, alpha, r->d_alpha, npix * sizeof(float), err);
        if (!rc && req->depth) {
            rc = sp_device_download(r->dev, req->depth, r->d_depth, npix * sizeof(float), err);
            /* expected depth = sum w z / sum w, 0 where (almost) nothing was drawn */
            for (size_t i = 0; !rc && i < npix; i++)
                req->depth[i] = alpha[i] >= 1e-6f ? req->depth[i] / alpha[i] : 0.f;
        }
        if (alpha != req->alpha) free(alpha);
        if (rc) return rc;
    }
    return 0;
}
