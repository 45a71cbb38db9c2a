/* Surface shading for the synth rasterizer: deterministic hash noise, the procedural patterns
 * (wood, planks, tiles, fabric, carpet, bricks, metal, glass, plaster), bilinear repeat texture
 * lookup, and Lambert + ambient lighting from the world's lights. Private to src/synth. */
#ifndef SP_SYNTH_SHADE_H
#define SP_SYNTH_SHADE_H

#include "semsplat/synth.h"

/* Integer hash (a Murmur-style finaliser) -> [0, 1). Same bytes on every machine. */
static inline float hash3f(int x, int y, int z)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u ^ (uint32_t)z * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return (float)(h >> 8) * (1.0f / 16777216.0f);
}

static inline float smooth01(float t) { return t * t * (3.0f - 2.0f * t); }

/* Trilinear value noise in [0, 1). */
static inline float vnoise(float x, float y, float z)
{
    float fx = floorf(x), fy = floorf(y), fz = floorf(z);
    int ix = (int)fx, iy = (int)fy, iz = (int)fz;
    float tx = smooth01(x - fx), ty = smooth01(y - fy), tz = smooth01(z - fz);
    float c[8];
    for (int i = 0; i < 8; i++) c[i] = hash3f(ix + (i & 1), iy + ((i >> 1) & 1), iz + ((i >> 2) & 1));
    float x0 = c[0] + (c[1] - c[0]) * tx, x1 = c[2] + (c[3] - c[2]) * tx;
    float x2 = c[4] + (c[5] - c[4]) * tx, x3 = c[6] + (c[7] - c[6]) * tx;
    float y0 = x0 + (x1 - x0) * ty, y1 = x2 + (x3 - x2) * ty;
    return y0 + (y1 - y0) * tz;
}

static inline float fbm3(float x, float y, float z)
{
    return 0.5f * vnoise(x, y, z) + 0.3f * vnoise(2.03f * x + 17.1f, 2.03f * y, 2.03f * z) +
           0.2f * vnoise(4.1f * x, 4.1f * y + 31.7f, 4.1f * z);
}

/* Band limit for a pattern term of spatial frequency k (cycles per metre) seen with footprint fw
 * (metres per pixel): 1 while a cycle spans 4+ pixels, fading to 0 at 2 pixels (Nyquist). Real
 * cameras integrate detail finer than a pixel into its mean; point-sampling it instead gives
 * aliasing noise that differs from view to view, which no 3D model can (or should) reproduce.
 * The procedural counterpart of the image textures' mipmaps ("frequency clamping"). */
static inline float band_weight(float k, float fw)
{
    float c = k * fw;
    return c <= 0.25f ? 1.0f : (c >= 0.5f ? 0.0f : 1.0f - smooth01((c - 0.25f) / 0.25f));
}

/* Noise value n in [0, 1) of frequency k, faded toward its mean 0.5 as it gets too fine. */
static inline float band(float n, float k, float fw) { return 0.5f + (n - 0.5f) * band_weight(k, fw); }

/* Multiplies albedo by the pattern at pattern-space point p; axis = dominant normal axis; fw is
 * the pattern-space size of a pixel there (0 = no band limit). */
static inline void pattern_apply(int pattern, const float p[3], int axis, float fw, float c[3])
{
    float u = axis == 0 ? p[1] : p[0], v = axis == 2 ? p[1] : p[2];
    float f = 1.0f, tint[3] = {1, 1, 1};
    switch (pattern) {
    case SP_PATTERN_WOOD: {
        /* growth rings around the board's long axis (p[0]), wobbled by noise, plus fine grain */
        float r = sqrtf(p[1] * p[1] + p[2] * p[2]) * 18.0f + 2.2f * vnoise(p[0] * 0.7f, p[1] * 5, p[2] * 5);
        float ring = r - floorf(r);
        f = 0.8f + 0.22f * smooth01(ring) + 0.1f * (band(vnoise(p[0] * 3, p[1] * 140, p[2] * 140), 140, fw) - 0.5f);
        tint[2] = 0.92f + 0.08f * ring;
        break;
    }
    case SP_PATTERN_PLANKS: {
        const float w = 0.16f, len = 1.2f;
        float row = floorf(v / w);
        float off = hash3f((int)row, 7, 3) * len;
        float along = u + off, idx = floorf(along / len);
        float fv = v / w - row, fu = along / len - idx;
        f = 0.82f + 0.3f * hash3f((int)row, (int)idx, 11);
        f *= 0.9f + 0.12f * band(vnoise(along * 2.5f, v * 60, row), 60, fw) +
             0.06f * (band(vnoise(along * 30, v * 300, 1), 300, fw) - 0.5f);
        if (fv < 0.035f || fu < 0.006f) f *= 0.55f;
        break;
    }
    case SP_PATTERN_TILES: {
        const float s = 0.3f, g = 0.007f;
        float iu = floorf(u / s), iv = floorf(v / s);
        float fu = u - iu * s, fv = v - iv * s;
        if (fu < g || fv < g) {
            f = 0.62f;
        } else {
            f = 0.9f + 0.12f * hash3f((int)iu, (int)iv, 5) + 0.07f * (fbm3(u * 12, v * 12, 3) - 0.5f);
        }
        break;
    }
    case SP_PATTERN_FABRIC: {
        float weave = band(0.5f + 0.5f * sinf(u * 700.0f) * sinf(v * 700.0f), 111, fw);
        f = 0.86f + 0.1f * weave * 0.5f + 0.16f * (fbm3(p[0] * 9, p[1] * 9, p[2] * 9) - 0.5f) +
            0.08f * (band(vnoise(p[0] * 60, p[1] * 60, p[2] * 60), 60, fw) - 0.5f);
        break;
    }
    case SP_PATTERN_CARPET:
        f = 0.85f + 0.22f * (band(vnoise(p[0] * 90, p[1] * 90, p[2] * 90), 90, fw) - 0.5f) + 0.14f * (fbm3(p[0] * 3, p[1] * 3, p[2] * 3) - 0.5f);
        break;
    case SP_PATTERN_BRICKS: {
        const float bw = 0.22f, bh = 0.075f, g = 0.011f;
        float row = floorf(v / bh);
        float uu = u + (((int)row & 1) ? bw * 0.5f : 0);
        float col = floorf(uu / bw);
        float fu = uu - col * bw, fv = v - row * bh;
        if (fu < g || fv < g) {
            for (int k = 0; k < 3; k++) tint[k] = 1.35f;
            f = 0.62f;
        } else
            f = 0.85f + 0.25f * hash3f((int)col, (int)row, 9) + 0.1f * (band(vnoise(u * 40, v * 40, 2), 40, fw) - 0.5f);
        break;
    }
    case SP_PATTERN_METAL:
        f = 0.93f + 0.06f * (band(vnoise(p[0] * 4, p[1] * 160, p[2] * 160), 160, fw) - 0.5f) + 0.06f * (vnoise(p[0] * 2, p[1] * 2, p[2] * 2) - 0.5f);
        break;
    case SP_PATTERN_GLASS:
        f = 0.9f + 0.12f * vnoise(p[0] * 1.5f + p[2], p[1] * 1.5f, p[2] * 0.5f);
        break;
    default: /* plaster / paint: gentle mottling so flat walls still have something to match */
        f = 0.93f + 0.1f * (fbm3(p[0] * 5, p[1] * 5, p[2] * 5) - 0.5f) + 0.05f * (band(vnoise(p[0] * 45, p[1] * 45, p[2] * 45), 45, fw) - 0.5f);
        break;
    }
    for (int k = 0; k < 3; k++) c[k] *= f * tint[k];
}

/* Bilinear lookup in mip level l with repeat wrapping; v = 0 is the image bottom. */
static inline void texture_level(const sp_synth_texture *t, int l, float u, float v, float out[3])
{
    long W = t->level_w[l], H = t->level_h[l];
    const uint8_t *px = t->level[l];
    float x = u * (float)W - 0.5f, y = (1.0f - v) * (float)H - 0.5f;
    float fx = floorf(x), fy = floorf(y);
    float ax = x - fx, ay = y - fy;
    /* fmodf keeps huge coordinates (tiled UVs) in range before the integer conversion */
    long x0 = (long)fmodf(fx, (float)W), y0 = (long)fmodf(fy, (float)H);
    if (x0 < 0) x0 += W;
    if (y0 < 0) y0 += H;
    if (x0 >= W) x0 = 0;
    if (y0 >= H) y0 = 0;
    long x1 = x0 + 1 == W ? 0 : x0 + 1, y1 = y0 + 1 == H ? 0 : y0 + 1;
    const uint8_t *a = px + (y0 * W + x0) * 3, *b = px + (y0 * W + x1) * 3;
    const uint8_t *c = px + (y1 * W + x0) * 3, *d = px + (y1 * W + x1) * 3;
    for (int k = 0; k < 3; k++) {
        float top = a[k] + (b[k] - a[k]) * ax, bot = c[k] + (d[k] - c[k]) * ax;
        out[k] = (top + (bot - top) * ay) * (1.0f / 255.0f);
    }
}

/* Trilinear lookup: lod = log2 of the footprint in level-0 texels (<= 0: plain bilinear). */
static inline void texture_sample(const sp_synth_texture *t, float u, float v, float lod, float out[3])
{
    if (!(lod > 0) || t->n_levels <= 1) {
        texture_level(t, 0, u, v, out);
        return;
    }
    float maxl = (float)(t->n_levels - 1);
    if (lod >= maxl) {
        texture_level(t, t->n_levels - 1, u, v, out);
        return;
    }
    int l0 = (int)lod;
    float f = lod - (float)l0, a[3], b[3];
    texture_level(t, l0, u, v, a);
    texture_level(t, l0 + 1, u, v, b);
    for (int k = 0; k < 3; k++) out[k] = a[k] + (b[k] - a[k]) * f;
}

#endif
