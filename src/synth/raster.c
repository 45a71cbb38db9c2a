/* The synth CPU rasterizer: per view, cull visuals by their boxes, clip triangles at the near
 * plane, bin them into bands of rows, and z-buffer each band on the pool (supersampled). Each
 * pixel then takes its depth and label from the surface covering most of its samples (the
 * plane's 1/z evaluated at the pixel centre, so depth is exact), and its colour from the
 * shaded samples. Bands own their rows, so the bytes do not depend on the thread count. */
#include "shade.h"

#include <stdlib.h>
#include <string.h>

#define NEAR_M 0.02f
#define BAND_PX 8 /* pixel rows per band */

typedef struct stri {
    float x[3], y[3], iz[3]; /* pixel coords, 1/z */
    float bary[3][3];        /* each vertex as barycentrics of the source triangle */
    double A[3], B[3], C[3]; /* screen barycentric l_i = A x + B y + C */
    uint32_t tri;
    int band0, band1;
} stri;

typedef struct tri_list {
    stri *t;
    size_t n, cap;
} tri_list;

static int push(tri_list *l, const stri *s)
{
    if (l->n == l->cap) {
        size_t nc = l->cap ? l->cap * 2 : 1024;
        stri *q = realloc(l->t, nc * sizeof *q);
        if (!q) return -1;
        l->t = q;
        l->cap = nc;
    }
    l->t[l->n++] = *s;
    return 0;
}

typedef struct view {
    const sp_world *w;
    const sp_camera *cam;
    int S, W, H, no_detail;
    int n_bands;
    sp_vec3 eye;
    tri_list tl;
    size_t *band_start, *band_idx;
    float *zbuf[64];
    int32_t *ibuf[64];
    sp_synth_frame *out;
} view;

static void to_cam(const sp_camera *c, const float *p, float o[3])
{
    for (int i = 0; i < 3; i++) o[i] = c->R[i * 3] * p[0] + c->R[i * 3 + 1] * p[1] + c->R[i * 3 + 2] * p[2] + c->t[i];
}

static int chunk_visible(const view *v, const sp_synth_chunk *ch)
{
    /* Conservative: culled only when all 8 corners lie beyond one frustum plane. */
    const sp_camera *c = v->cam;
    int out_near = 1, out_l = 1, out_r = 1, out_t = 1, out_b = 1;
    float xl = -c->cx / c->fx, xr = (c->width - c->cx) / c->fx;
    float yt = -c->cy / c->fy, yb = (c->height - c->cy) / c->fy;
    for (int i = 0; i < 8; i++) {
        float p[3] = {(i & 1) ? ch->aabb_max[0] : ch->aabb_min[0], (i & 2) ? ch->aabb_max[1] : ch->aabb_min[1],
                      (i & 4) ? ch->aabb_max[2] : ch->aabb_min[2]}, q[3];
        to_cam(c, p, q);
        if (q[2] >= NEAR_M) out_near = 0;
        if (q[0] >= xl * q[2]) out_l = 0;
        if (q[0] <= xr * q[2]) out_r = 0;
        if (q[1] >= yt * q[2]) out_t = 0;
        if (q[1] <= yb * q[2]) out_b = 0;
    }
    return !(out_near || out_l || out_r || out_t || out_b);
}

/* Sets up and appends one screen triangle from camera-space vertices q with source barycentrics. */
static int emit(view *v, uint32_t tri, float q[3][3], float bary[3][3])
{
    const sp_camera *c = v->cam;
    stri s;
    for (int i = 0; i < 3; i++) {
        s.iz[i] = 1.0f / q[i][2];
        s.x[i] = c->fx * q[i][0] * s.iz[i] + c->cx;
        s.y[i] = c->fy * q[i][1] * s.iz[i] + c->cy;
        memcpy(s.bary[i], bary[i], sizeof s.bary[i]);
    }
    float xmin = fminf(s.x[0], fminf(s.x[1], s.x[2])), xmax = fmaxf(s.x[0], fmaxf(s.x[1], s.x[2]));
    float ymin = fminf(s.y[0], fminf(s.y[1], s.y[2])), ymax = fmaxf(s.y[0], fmaxf(s.y[1], s.y[2]));
    if (xmax < 0 || ymax < 0 || xmin > v->W || ymin > v->H) return 0;
    double area = ((double)s.x[1] - s.x[0]) * ((double)s.y[2] - s.y[0]) -
                  ((double)s.x[2] - s.x[0]) * ((double)s.y[1] - s.y[0]);
    if (fabs(area) < 1e-12) return 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        s.A[i] = ((double)s.y[j] - s.y[k]) / area;
        s.B[i] = ((double)s.x[k] - s.x[j]) / area;
        s.C[i] = ((double)s.x[j] * s.y[k] - (double)s.x[k] * s.y[j]) / area;
    }
    s.tri = tri;
    /* clamp in float before converting: far-away vertices project to huge coordinates */
    float fb0 = floorf(ymin / BAND_PX), fb1 = floorf(ymax / BAND_PX);
    s.band0 = fb0 < 0 ? 0 : (int)fb0;
    s.band1 = fb1 >= (float)v->n_bands ? v->n_bands - 1 : (int)fb1;
    return push(&v->tl, &s);
}

/* Clips the triangle against z = NEAR (Sutherland-Hodgman) and emits the fan. */
static int clip_emit(view *v, uint32_t tri, float q[3][3])
{
    float in[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int inside = (q[0][2] >= NEAR_M) + (q[1][2] >= NEAR_M) + (q[2][2] >= NEAR_M);
    if (inside == 0) return 0;
    if (inside == 3) return emit(v, tri, q, in);
    float pq[4][3], pb[4][3];
    int n = 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        int ii = q[i][2] >= NEAR_M, jj = q[j][2] >= NEAR_M;
        if (ii) {
            memcpy(pq[n], q[i], sizeof pq[n]);
            memcpy(pb[n], in[i], sizeof pb[n]);
            n++;
        }
        if (ii != jj) {
            float t = (NEAR_M - q[i][2]) / (q[j][2] - q[i][2]);
            for (int k = 0; k < 3; k++) {
                pq[n][k] = q[i][k] + t * (q[j][k] - q[i][k]);
                pb[n][k] = in[i][k] + t * (in[j][k] - in[i][k]);
            }
            pq[n][2] = NEAR_M;
            n++;
        }
    }
    for (int k = 1; k + 1 < n; k++) {
        float tq[3][3], tb[3][3];
        memcpy(tq[0], pq[0], sizeof tq[0]); memcpy(tb[0], pb[0], sizeof tb[0]);
        memcpy(tq[1], pq[k], sizeof tq[1]); memcpy(tb[1], pb[k], sizeof tb[1]);
        memcpy(tq[2], pq[k + 1], sizeof tq[2]); memcpy(tb[2], pb[k + 1], sizeof tb[2]);
        if (emit(v, tri, tq, tb)) return -1;
    }
    return 0;
}

/* Source barycentrics at screen point (x, y) of screen triangle s (perspective-correct). */
static void source_bary(const stri *s, double x, double y, float b[3])
{
    double wsum = 0, wl[3];
    for (int i = 0; i < 3; i++) {
        double l = s->A[i] * x + s->B[i] * y + s->C[i];
        wl[i] = l * s->iz[i];
        wsum += wl[i];
    }
    if (!(wsum > 0)) wsum = 1;
    for (int k = 0; k < 3; k++)
        b[k] = (float)((wl[0] * s->bary[0][k] + wl[1] * s->bary[1][k] + wl[2] * s->bary[2][k]) / wsum);
}

/* Per-vertex attribute attr[vertex][3] of triangle tri at barycentrics b. */
static void interp3(const sp_world *w, const float *attr, uint32_t tri, const float b[3], float out[3])
{
    const uint32_t *vi = &w->tris[tri * 3];
    for (int k = 0; k < 3; k++)
        out[k] = b[0] * attr[vi[0] * 3 + k] + b[1] * attr[vi[1] * 3 + k] + b[2] * attr[vi[2] * 3 + k];
}

static void interp_uv(const sp_world *w, uint32_t tri, const float b[3], float uv[2])
{
    const uint32_t *vi = &w->tris[tri * 3];
    for (int k = 0; k < 2; k++)
        uv[k] = b[0] * w->uvs[vi[0] * 2 + k] + b[1] * w->uvs[vi[1] * 2 + k] + b[2] * w->uvs[vi[2] * 2 + k];
}

/* Colour of screen triangle s at screen point (x, y); fp is the sample spacing in pixels, the
 * footprint that picks the texture's mip level. */
static void shade(const view *v, const stri *s, double x, double y, double fp, float rgb[3])
{
    const sp_world *w = v->w;
    uint32_t tri = s->tri;
    float b[3];
    source_bary(s, x, y, b);
    const sp_synth_material *m = &w->materials[w->tri_material[tri]];
    float pos[3], nrm[3], pat[3], uv[2];
    interp3(w, w->positions, tri, b, pos);
    interp3(w, w->normals, tri, b, nrm);
    interp3(w, w->pattern, tri, b, pat);
    interp_uv(w, tri, b, uv);
    float alb[3] = {m->diffuse[0], m->diffuse[1], m->diffuse[2]};
    if (!v->no_detail) {
        if (m->texture >= 0) {
            const sp_synth_texture *tx = &w->textures[m->texture];
            float bx[3], by[3], ux[2], uy[2], t[3];
            source_bary(s, x + fp, y, bx);
            source_bary(s, x, y + fp, by);
            interp_uv(w, tri, bx, ux);
            interp_uv(w, tri, by, uy);
            float dxu = (ux[0] - uv[0]) * tx->width, dxv = (ux[1] - uv[1]) * tx->height;
            float dyu = (uy[0] - uv[0]) * tx->width, dyv = (uy[1] - uv[1]) * tx->height;
            float foot = fmaxf(dxu * dxu + dxv * dxv, dyu * dyu + dyv * dyv);
            texture_sample(tx, uv[0], uv[1], foot > 1.0f ? 0.5f * log2f(foot) : 0.0f, t);
            for (int k = 0; k < 3; k++) alb[k] *= t[k];
        } else {
            /* pattern-space size of a pixel (fp is a sample, 1/ss of a pixel): the larger of the
             * steps one sample right and one down, so oblique surfaces band-limit along their
             * stretched direction */
            float bx[3], by[3], px[3], py[3], d2x = 0, d2y = 0;
            source_bary(s, x + fp, y, bx);
            source_bary(s, x, y + fp, by);
            interp3(w, w->pattern, tri, bx, px);
            interp3(w, w->pattern, tri, by, py);
            for (int k = 0; k < 3; k++) {
                d2x += (px[k] - pat[k]) * (px[k] - pat[k]);
                d2y += (py[k] - pat[k]) * (py[k] - pat[k]);
            }
            float fw = sqrtf(fmaxf(d2x, d2y)) / (float)fp; /* per pixel */
            pattern_apply(m->pattern, pat, w->tri_axis[tri], fw, alb);
        }
    }
    /* Two-sided: the normal faces the camera. */
    float nl = sqrtf(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (nl > 0) for (int k = 0; k < 3; k++) nrm[k] /= nl;
    float tc[3] = {v->eye.x - pos[0], v->eye.y - pos[1], v->eye.z - pos[2]};
    if (nrm[0] * tc[0] + nrm[1] * tc[1] + nrm[2] * tc[2] < 0)
        for (int k = 0; k < 3; k++) nrm[k] = -nrm[k];
    float light[3] = {w->ambient[0], w->ambient[1], w->ambient[2]};
    for (size_t i = 0; i < w->n_lights; i++) {
        const sp_synth_light *L = &w->lights[i];
        float d[3], att = 1.0f;
        if (L->type == SP_LIGHT_DIRECTIONAL) {
            for (int k = 0; k < 3; k++) d[k] = -L->direction[k];
        } else {
            for (int k = 0; k < 3; k++) d[k] = L->position[k] - pos[k];
            float dist = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (dist > L->range || dist <= 0) continue;
            for (int k = 0; k < 3; k++) d[k] /= dist;
            float den = L->att_constant + L->att_linear * dist + L->att_quadratic * dist * dist;
            att = den > 1e-3f ? 1.0f / den : 1000.0f;
            if (L->type == SP_LIGHT_SPOT) {
                /* OGRE's spot: full inside the inner cone, none outside the outer, falloff between */
                float cosa = -(d[0] * L->direction[0] + d[1] * L->direction[1] + d[2] * L->direction[2]);
                if (cosa <= L->spot_cos_outer) continue;
                if (cosa < L->spot_cos_inner)
                    att *= powf((cosa - L->spot_cos_outer) / (L->spot_cos_inner - L->spot_cos_outer), L->spot_falloff);
            }
        }
        float ndl = nrm[0] * d[0] + nrm[1] * d[1] + nrm[2] * d[2];
        if (ndl <= 0) continue;
        for (int k = 0; k < 3; k++) light[k] += L->diffuse[k] * ndl * att;
    }
    for (int k = 0; k < 3; k++) {
        float c = alb[k] * light[k] * w->exposure + m->emissive[k];
        /* a soft shoulder instead of a hard clip keeps texture in bright surfaces */
        if (c > 0.8f) c = 0.8f + 0.2f * (1.0f - expf((0.8f - c) * 5.0f));
        rgb[k] = c < 0 ? 0 : c;
    }
}

static void band_fn(void *ctx, long band, int tid)
{
    view *v = ctx;
    const int S = v->S, W = v->W, SW = W * S;
    int py0 = (int)band * BAND_PX, py1 = py0 + BAND_PX > v->H ? v->H : py0 + BAND_PX;
    int sy0 = py0 * S, sy1 = py1 * S;
    float *zb = v->zbuf[tid];
    int32_t *ib = v->ibuf[tid];
    size_t ns = (size_t)(sy1 - sy0) * SW;
    for (size_t i = 0; i < ns; i++) {
        zb[i] = 0;
        ib[i] = -1;
    }
    const double inv = 1.0 / S;
    for (size_t k = v->band_start[band]; k < v->band_start[band + 1]; k++) {
        const stri *s = &v->tl.t[v->band_idx[k]];
        float xmin = fminf(s->x[0], fminf(s->x[1], s->x[2])), xmax = fmaxf(s->x[0], fmaxf(s->x[1], s->x[2]));
        float ymin = fminf(s->y[0], fminf(s->y[1], s->y[2])), ymax = fmaxf(s->y[0], fmaxf(s->y[1], s->y[2]));
        float fax = fmaxf(ceilf(xmin * S - 0.5f), 0.0f), fbx = fminf(floorf(xmax * S - 0.5f), (float)(SW - 1));
        float fay = fmaxf(ceilf(ymin * S - 0.5f), (float)sy0), fby = fminf(floorf(ymax * S - 0.5f), (float)(sy1 - 1));
        if (!(fax <= fbx) || !(fay <= fby)) continue;
        int ax = (int)fax, bx = (int)fbx, ay = (int)fay, by = (int)fby;
        if (ax > bx || ay > by) continue;
        double stepz = (s->A[0] * s->iz[0] + s->A[1] * s->iz[1] + s->A[2] * s->iz[2]) * inv;
        for (int sy = ay; sy <= by; sy++) {
            double y = (sy + 0.5) * inv, x = (ax + 0.5) * inv;
            double l0 = s->A[0] * x + s->B[0] * y + s->C[0];
            double l1 = s->A[1] * x + s->B[1] * y + s->C[1];
            double l2 = s->A[2] * x + s->B[2] * y + s->C[2];
            double iz = l0 * s->iz[0] + l1 * s->iz[1] + l2 * s->iz[2];
            double d0 = s->A[0] * inv, d1 = s->A[1] * inv, d2 = s->A[2] * inv;
            size_t row = (size_t)(sy - sy0) * SW;
            for (int sx = ax; sx <= bx; sx++, l0 += d0, l1 += d1, l2 += d2, iz += stepz) {
                if (l0 < 0 || l1 < 0 || l2 < 0) continue;
                size_t at = row + sx;
                if ((float)iz > zb[at]) {
                    zb[at] = (float)iz;
                    ib[at] = (int32_t)v->band_idx[k];
                }
            }
        }
    }
    /* Resolve each pixel of the band. */
    sp_synth_frame *o = v->out;
    for (int py = py0; py < py1; py++)
        for (int px = 0; px < W; px++) {
            int32_t ids[16];
            float zs[16];
            int n = 0;
            for (int j = 0; j < S; j++)
                for (int i = 0; i < S; i++) {
                    size_t at = (size_t)((py - py0) * S + j) * SW + (size_t)px * S + i;
                    ids[n] = ib[at];
                    zs[n++] = zb[at];
                }
            /* majority surface (background counts as one), ties to the nearer */
            int best = -1, best_cnt = 0;
            float best_z = -1;
            for (int a = 0; a < n; a++) {
                int cnt = 0;
                float zmax = 0;
                for (int b2 = 0; b2 < n; b2++)
                    if (ids[b2] == ids[a]) {
                        cnt++;
                        if (zs[b2] > zmax) zmax = zs[b2];
                    }
                if (cnt > best_cnt || (cnt == best_cnt && zmax > best_z)) {
                    best = ids[a];
                    best_cnt = cnt;
                    best_z = zmax;
                }
            }
            size_t pix = (size_t)py * W + px;
            double cxp = px + 0.5, cyp = py + 0.5;
            /* Depth and label: the nearest sampled surface that covers the pixel centre (exact
             * there, also at creases between faces), else the majority surface. */
            int at_centre = -1;
            double cz = 0;
            for (int a = 0; a < n; a++) {
                if (ids[a] < 0 || ids[a] == at_centre) continue;
                const stri *s = &v->tl.t[ids[a]];
                double l[3], iz = 0;
                for (int i = 0; i < 3; i++) {
                    l[i] = s->A[i] * cxp + s->B[i] * cyp + s->C[i];
                    iz += l[i] * s->iz[i];
                }
                if (l[0] >= -1e-9 && l[1] >= -1e-9 && l[2] >= -1e-9 && iz > cz) {
                    cz = iz;
                    at_centre = ids[a];
                }
            }
            if (at_centre >= 0) {
                o->depth[pix] = (float)(1.0 / cz);
                o->labels[pix] = (uint16_t)(v->w->tri_object[v->tl.t[at_centre].tri] + 1);
            } else if (best < 0) {
                o->depth[pix] = 0;
                o->labels[pix] = 0;
            } else {
                const stri *s = &v->tl.t[best];
                double iz = 0;
                for (int i = 0; i < 3; i++) iz += (s->A[i] * cxp + s->B[i] * cyp + s->C[i]) * s->iz[i];
                if (!(iz > 0)) iz = best_z;
                o->depth[pix] = (float)(1.0 / iz);
                o->labels[pix] = (uint16_t)(v->w->tri_object[s->tri] + 1);
            }
            float rgb[3] = {0, 0, 0}, c[3];
            if (best_cnt == n && best >= 0) {
                shade(v, &v->tl.t[best], cxp, cyp, 1.0, rgb);
            } else {
                for (int a = 0; a < n; a++) {
                    if (ids[a] < 0) {
                        for (int k = 0; k < 3; k++) rgb[k] += v->w->background[k];
                        continue;
                    }
                    int i = a % S, j = a / S;
                    shade(v, &v->tl.t[ids[a]], px + (i + 0.5) * inv, py + (j + 0.5) * inv, inv, c);
                    for (int k = 0; k < 3; k++) rgb[k] += c[k];
                }
                for (int k = 0; k < 3; k++) rgb[k] /= (float)n;
            }
            memcpy(&o->rgb[pix * 3], rgb, sizeof rgb);
        }
}

/* One 1-D pass of camera_blur: n lines of len pixels, pixel i of line l at
 * (l * line_step + i * px_step) * 3, edges clamped. */
static void blur_pass(const float *src, float *dst, int n, int len, size_t line_step,
                      size_t px_step, const float *k, int R)
{
    for (int l = 0; l < n; l++)
        for (int i = 0; i < len; i++)
            for (int c = 0; c < 3; c++) {
                float acc = 0;
                for (int j = -R; j <= R; j++) {
                    int ii = i + j < 0 ? 0 : (i + j >= len ? len - 1 : i + j);
                    acc += k[j + R] * src[((size_t)l * line_step + (size_t)ii * px_step) * 3 + c];
                }
                dst[((size_t)l * line_step + (size_t)i * px_step) * 3 + c] = acc;
            }
}

/* The camera's blur: a separable Gaussian of sigma px (radius 3 sigma, weights renormalised,
 * edges clamped) over the box-integrated colours. A real camera's lens and sensor soften
 * edges beyond the pixel box; with sigma 0.5 a pixel's response has variance 1/12 + 1/4 = 0.33
 * px^2, about the 0.3 px^2 low-pass 3DGS rasterizers assume for a pixel, and what physically
 * based renderers use by default (pbrt-v4: Gaussian pixel filter, sigma 0.5). Depth and labels
 * stay per pixel. Returns nonzero when out of memory. */
static int camera_blur(float *rgb, int W, int H, float sigma)
{
    int R = (int)ceilf(3.f * sigma);
    if (R < 1) return 0;
    if (R > 12) R = 12;
    float k[25], ksum = 0;
    for (int i = -R; i <= R; i++) ksum += k[i + R] = expf(-0.5f * (float)(i * i) / (sigma * sigma));
    for (int i = 0; i <= 2 * R; i++) k[i] /= ksum;
    float *tmp = malloc((size_t)W * H * 3 * sizeof(float));
    if (!tmp) return 1;
    blur_pass(rgb, tmp, H, W, (size_t)W, 1, k, R); /* rows into tmp */
    blur_pass(tmp, rgb, W, H, 1, (size_t)W, k, R); /* columns back */
    free(tmp);
    return 0;
}

int sp_synth_render(const sp_world *w, const sp_camera *cam, const sp_synth_render_opts *opts,
                    sp_pool *pool, sp_synth_frame *out, sp_error *err)
{
    sp_synth_render_opts def = {0};
    if (!opts) opts = &def;
    if (!w || !cam || !out) return sp_error_set(err, SP_E_ARG, "sp_synth_render: NULL argument");
    int S = opts->supersample ? opts->supersample : 4;
    if (S < 1 || S > 4) return sp_error_set(err, SP_E_ARG, "supersample %d: expected 1..4", S);
    float psf = opts->psf_px == 0.f ? 0.5f : opts->psf_px;
    if (!(psf <= 4.f)) return sp_error_set(err, SP_E_ARG, "camera blur %g px: expected at most 4", psf);
    if (cam->width <= 0 || cam->height <= 0 || cam->width > 16384 || cam->height > 16384 ||
        !(cam->fx > 0) || !(cam->fy > 0))
        return sp_error_set(err, SP_E_ARG, "camera %dx%d fx %g fy %g: expected a positive size and focal length",
                            cam->width, cam->height, cam->fx, cam->fy);
    if (out->rgb && (out->width != cam->width || out->height != cam->height))
        return sp_error_set(err, SP_E_ARG, "frame is %dx%d, camera is %dx%d", out->width, out->height,
                            cam->width, cam->height);
    size_t npx = (size_t)cam->width * cam->height;
    if (!out->rgb) {
        out->width = cam->width;
        out->height = cam->height;
        out->rgb = malloc(npx * 3 * sizeof(float));
        out->depth = malloc(npx * sizeof(float));
        out->labels = malloc(npx * sizeof(uint16_t));
        if (!out->rgb || !out->depth || !out->labels) {
            sp_synth_frame_free(out);
            return sp_error_set(err, SP_E_NOMEM, "render %dx%d: out of memory", cam->width, cam->height);
        }
    }
    view v;
    memset(&v, 0, sizeof v);
    v.w = w;
    v.cam = cam;
    v.S = S;
    v.W = cam->width;
    v.H = cam->height;
    v.no_detail = opts->no_detail;
    v.eye = sp_camera_center(cam);
    v.out = out;
    v.n_bands = (cam->height + BAND_PX - 1) / BAND_PX;
    int rc = 0;
    for (size_t c = 0; c < w->n_chunks && !rc; c++) {
        const sp_synth_chunk *ch = &w->chunks[c];
        if (!chunk_visible(&v, ch)) continue;
        for (size_t t = ch->tri_begin; t < ch->tri_end; t++) {
            float q[3][3];
            for (int i = 0; i < 3; i++) to_cam(cam, &w->positions[w->tris[t * 3 + i] * 3], q[i]);
            if (clip_emit(&v, (uint32_t)t, q)) {
                rc = sp_error_set(err, SP_E_NOMEM, "render: out of memory");
                break;
            }
        }
    }
    int nthreads = sp_pool_size(pool);
    if (nthreads > 64) { /* scratch is per thread id; a huge pool runs serially */
        nthreads = 1;
        pool = NULL;
    }
    v.band_start = calloc((size_t)v.n_bands + 1, sizeof(size_t));
    size_t total = 0;
    if (!rc && v.band_start) {
        for (size_t i = 0; i < v.tl.n; i++)
            for (int b = v.tl.t[i].band0; b <= v.tl.t[i].band1; b++) v.band_start[b + 1]++;
        for (int b = 0; b < v.n_bands; b++) v.band_start[b + 1] += v.band_start[b];
        total = v.band_start[v.n_bands];
        v.band_idx = malloc((total ? total : 1) * sizeof(size_t));
        size_t *fill = calloc((size_t)v.n_bands, sizeof(size_t));
        if (v.band_idx && fill)
            for (size_t i = 0; i < v.tl.n; i++)
                for (int b = v.tl.t[i].band0; b <= v.tl.t[i].band1; b++)
                    v.band_idx[v.band_start[b] + fill[b]++] = i;
        else
            rc = sp_error_set(err, SP_E_NOMEM, "render: out of memory");
        free(fill);
        size_t scratch = (size_t)BAND_PX * S * cam->width * S;
        for (int t = 0; t < nthreads && !rc; t++) {
            v.zbuf[t] = malloc(scratch * sizeof(float));
            v.ibuf[t] = malloc(scratch * sizeof(int32_t));
            if (!v.zbuf[t] || !v.ibuf[t]) rc = sp_error_set(err, SP_E_NOMEM, "render: out of memory");
        }
    } else if (!rc)
        rc = sp_error_set(err, SP_E_NOMEM, "render: out of memory");
    if (!rc) sp_pool_for(nthreads > 1 ? pool : NULL, v.n_bands, band_fn, &v);
    if (!rc && psf > 0.f && camera_blur(out->rgb, cam->width, cam->height, psf))
        rc = sp_error_set(err, SP_E_NOMEM, "render: out of memory");
    for (int t = 0; t < nthreads; t++) {
        free(v.zbuf[t]);
        free(v.ibuf[t]);
    }
    free(v.band_start);
    free(v.band_idx);
    free(v.tl.t);
    return rc;
}

void sp_synth_frame_free(sp_synth_frame *f)
{
    if (!f) return;
    free(f->rgb);
    free(f->depth);
    free(f->labels);
    memset(f, 0, sizeof *f);
}
