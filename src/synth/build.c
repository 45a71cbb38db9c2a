/* The world builder: growable triangle-soup buffers, primitive tessellation (box, cylinder,
 * sphere, plane), and the finishing pass (object boxes, default light). Used by sdf.c. */
#include "internal.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

/* ---- poses ----------------------------------------------------------------------------------- */

xform xf_identity(void)
{
    xform a = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
    return a;
}

xform xf_mul(xform a, xform b)
{
    xform c;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += a.m[i * 4 + k] * b.m[k * 4 + j];
            c.m[i * 4 + j] = s;
        }
    return c;
}

xform xf_from_pose(const double p[6])
{
    double cr = cos(p[3]), sr = sin(p[3]), cp = cos(p[4]), sp = sin(p[4]);
    double cy = cos(p[5]), sy = sin(p[5]);
    xform a = {{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr, p[0],
                sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr, p[1],
                -sp, cp * sr, cp * cr, p[2],
                0, 0, 0, 1}};
    return a;
}

void xf_apply(const xform *a, const double in[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = a->m[i * 4] * in[0] + a->m[i * 4 + 1] * in[1] + a->m[i * 4 + 2] * in[2] + a->m[i * 4 + 3];
    memcpy(out, r, sizeof r);
}

void xf_apply_dir(const xform *a, const double in[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = a->m[i * 4] * in[0] + a->m[i * 4 + 1] * in[1] + a->m[i * 4 + 2] * in[2];
    memcpy(out, r, sizeof r);
}

/* ---- growable buffers ------------------------------------------------------------------------ */

static int grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap) return 0;
    size_t nc = *cap ? *cap * 2 : 64;
    while (nc < need) nc *= 2;
    void *q = realloc(*p, nc * elem);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

int wb_init(wbuild *b, sp_world *w, sp_error *err)
{
    memset(b, 0, sizeof *b);
    b->w = w;
    for (int i = 0; i < 3; i++) {
        w->ambient[i] = 0.4f;
        w->background[i] = 0.7f;
    }
    (void)err;
    return 0;
}

void wb_release(wbuild *b)
{
    for (size_t i = 0; i < b->n_meshes; i++) mesh_data_free(&b->meshes[i].data);
    free(b->meshes);
    b->meshes = NULL;
    b->n_meshes = b->cap_meshes = 0;
}

long wb_vertex(wbuild *b, const double pos[3], const double nrm[3], const double uv[2],
               const double pattern[3])
{
    sp_world *w = b->w;
    size_t n = w->n_vertices, cap = b->cap_v;
    if (n + 1 > cap) {
        size_t c1 = cap, c2 = cap, c3 = cap, c4 = cap;
        if (grow((void **)&w->positions, &c1, n + 1, 3 * sizeof(float)) ||
            grow((void **)&w->normals, &c2, n + 1, 3 * sizeof(float)) ||
            grow((void **)&w->uvs, &c3, n + 1, 2 * sizeof(float)) ||
            grow((void **)&w->pattern, &c4, n + 1, 3 * sizeof(float)))
            return -1;
        b->cap_v = c1;
    }
    double nn = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(nn > 0)) nn = 1;
    for (int i = 0; i < 3; i++) {
        w->positions[n * 3 + i] = (float)pos[i];
        w->normals[n * 3 + i] = (float)(nrm[i] / nn);
        w->pattern[n * 3 + i] = (float)pattern[i];
    }
    w->uvs[n * 2] = uv ? (float)uv[0] : 0.0f;
    w->uvs[n * 2 + 1] = uv ? (float)uv[1] : 0.0f;
    w->n_vertices = n + 1;
    return (long)n;
}

int wb_triangle(wbuild *b, long a, long c, long d, int material, int object)
{
    sp_world *w = b->w;
    size_t n = w->n_triangles, cap = b->cap_t;
    if (a < 0 || c < 0 || d < 0) return SP_E_NOMEM;
    if (n + 1 > cap) {
        size_t c1 = cap, c2 = cap, c3 = cap;
        if (grow((void **)&w->tris, &c1, n + 1, 3 * sizeof(uint32_t)) ||
            grow((void **)&w->tri_material, &c2, n + 1, sizeof(uint16_t)) ||
            grow((void **)&w->tri_object, &c3, n + 1, sizeof(uint16_t)))
            return SP_E_NOMEM;
        b->cap_t = c1;
    }
    w->tris[n * 3] = (uint32_t)a;
    w->tris[n * 3 + 1] = (uint32_t)c;
    w->tris[n * 3 + 2] = (uint32_t)d;
    w->tri_material[n] = (uint16_t)material;
    w->tri_object[n] = (uint16_t)object;
    w->n_triangles = n + 1;
    return 0;
}

int wb_material(wbuild *b, const sp_synth_material *m)
{
    sp_world *w = b->w;
    /* Identical materials are shared so the table stays small for worlds of many instances. */
    for (size_t i = 0; i < w->n_materials; i++)
        if (!memcmp(&w->materials[i], m, sizeof *m)) return (int)i;
    if (w->n_materials >= 65535) return SP_E_UNSUPPORTED;
    if (grow((void **)&w->materials, &b->cap_m, w->n_materials + 1, sizeof *m)) return SP_E_NOMEM;
    w->materials[w->n_materials] = *m;
    return (int)w->n_materials++;
}

int wb_object(wbuild *b, const sp_synth_object *o)
{
    sp_world *w = b->w;
    if (w->n_objects >= 65534) return SP_E_UNSUPPORTED; /* labels are 16-bit, 0 = background */
    if (grow((void **)&w->objects, &b->cap_o, w->n_objects + 1, sizeof *o)) return SP_E_NOMEM;
    w->objects[w->n_objects] = *o;
    return (int)w->n_objects++;
}

int wb_light(wbuild *b, const sp_synth_light *l)
{
    sp_world *w = b->w;
    if (grow((void **)&w->lights, &b->cap_l, w->n_lights + 1, sizeof *l)) return SP_E_NOMEM;
    w->lights[w->n_lights] = *l;
    return (int)w->n_lights++;
}

void wb_chunk_begin(wbuild *b, size_t *mark) { *mark = b->w->n_triangles; }

int wb_chunk_end(wbuild *b, size_t mark)
{
    sp_world *w = b->w;
    if (w->n_triangles == mark) return 0;
    if (grow((void **)&w->chunks, &b->cap_c, w->n_chunks + 1, sizeof(sp_synth_chunk)))
        return SP_E_NOMEM;
    sp_synth_chunk *c = &w->chunks[w->n_chunks++];
    c->tri_begin = mark;
    c->tri_end = w->n_triangles;
    for (int k = 0; k < 3; k++) {
        c->aabb_min[k] = INFINITY;
        c->aabb_max[k] = -INFINITY;
    }
    for (size_t t = mark; t < w->n_triangles; t++)
        for (int v = 0; v < 3; v++) {
            const float *p = &w->positions[w->tris[t * 3 + v] * 3];
            for (int k = 0; k < 3; k++) {
                if (p[k] < c->aabb_min[k]) c->aabb_min[k] = p[k];
                if (p[k] > c->aabb_max[k]) c->aabb_max[k] = p[k];
            }
        }
    return 0;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Worlds are lit for a GPU renderer with its own tone curve; we take the median irradiance of
 * the surfaces (sampled triangles, both sides) and scale it to a fixed level, once per world so
 * every view of a capture has the same exposure. */
static void set_exposure(sp_world *w)
{
    enum { N = 2048 };
    float irr[N];
    int n = 0;
    size_t stride = w->n_triangles / N + 1;
    for (size_t t = 0; t < w->n_triangles && n < N; t += stride) {
        const uint32_t *v = &w->tris[t * 3];
        float p[3], nr[3];
        for (int k = 0; k < 3; k++) {
            p[k] = (w->positions[v[0] * 3 + k] + w->positions[v[1] * 3 + k] + w->positions[v[2] * 3 + k]) / 3;
            nr[k] = w->normals[v[0] * 3 + k] + w->normals[v[1] * 3 + k] + w->normals[v[2] * 3 + k];
        }
        float nl = sqrtf(nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2]);
        if (!(nl > 0)) continue;
        float e = (w->ambient[0] + w->ambient[1] + w->ambient[2]) / 3;
        for (size_t i = 0; i < w->n_lights; i++) {
            const sp_synth_light *L = &w->lights[i];
            float d[3], att = 1;
            if (L->type == SP_LIGHT_DIRECTIONAL) {
                for (int k = 0; k < 3; k++) d[k] = -L->direction[k];
            } else {
                for (int k = 0; k < 3; k++) d[k] = L->position[k] - p[k];
                float dist = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (dist > L->range || dist <= 0) continue;
                for (int k = 0; k < 3; k++) d[k] /= dist;
                float den = L->att_constant + L->att_linear * dist + L->att_quadratic * dist * dist;
                att = den > 1e-3f ? 1 / den : 1000;
            }
            float ndl = fabsf(nr[0] * d[0] + nr[1] * d[1] + nr[2] * d[2]) / nl;
            e += (L->diffuse[0] + L->diffuse[1] + L->diffuse[2]) / 3 * ndl * att;
        }
        irr[n++] = e;
    }
    w->exposure = 1.0f;
    if (n == 0) return;
    qsort(irr, (size_t)n, sizeof(float), cmp_float);
    float med = irr[n / 2];
    if (med > 0) w->exposure = fminf(fmaxf(0.95f / med, 0.25f), 1.3f);
}

int wb_finish(wbuild *b, sp_error *err)
{
    sp_world *w = b->w;
    w->tri_axis = malloc(w->n_triangles ? w->n_triangles : 1);
    if (!w->tri_axis) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", w->path);
    for (size_t o = 0; o < w->n_objects; o++) {
        for (int k = 0; k < 3; k++) {
            w->objects[o].aabb_min[k] = INFINITY;
            w->objects[o].aabb_max[k] = -INFINITY;
        }
        w->objects[o].n_triangles = 0;
    }
    for (size_t t = 0; t < w->n_triangles; t++) {
        const uint32_t *v = &w->tris[t * 3];
        /* finite inputs can still overflow: a size of 1e300 scaled, or posed far away */
        for (int j = 0; j < 3; j++) {
            const float *p = &w->positions[v[j] * 3], *n = &w->normals[v[j] * 3];
            if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || !isfinite(n[0]) || !isfinite(n[1]) ||
                !isfinite(n[2])) {
                const sp_synth_object *o = &w->objects[w->tri_object[t]];
                return sp_error_set(err, SP_E_NUMERIC,
                                    "%s:%d: model '%s' has geometry beyond float range (a size, scale or pose too large?)",
                                    w->path, o->sdf_line, o->name);
            }
        }
        const float *p0 = &w->pattern[v[0] * 3], *p1 = &w->pattern[v[1] * 3], *p2 = &w->pattern[v[2] * 3];
        float e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        float e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        float n[3] = {fabsf(e1[1] * e2[2] - e1[2] * e2[1]), fabsf(e1[2] * e2[0] - e1[0] * e2[2]),
                      fabsf(e1[0] * e2[1] - e1[1] * e2[0])};
        w->tri_axis[t] = (uint8_t)(n[0] >= n[1] && n[0] >= n[2] ? 0 : n[1] >= n[2] ? 1 : 2);
        sp_synth_object *o = &w->objects[w->tri_object[t]];
        o->n_triangles++;
        for (int j = 0; j < 3; j++) {
            const float *p = &w->positions[v[j] * 3];
            for (int k = 0; k < 3; k++) {
                if (p[k] < o->aabb_min[k]) o->aabb_min[k] = p[k];
                if (p[k] > o->aabb_max[k]) o->aabb_max[k] = p[k];
            }
        }
    }
    for (size_t o = 0; o < w->n_objects; o++)
        if (!w->objects[o].n_triangles)
            for (int k = 0; k < 3; k++)
                w->objects[o].aabb_min[k] = w->objects[o].aabb_max[k] = w->objects[o].pose[k * 4 + 3];
    if (w->n_lights == 0) {
        /* Gazebo's default world has a sun; ours comes from above and a little to the side so
         * that walls facing different ways get different shades. */
        sp_synth_light sun = {.name = "default_sun", .type = SP_LIGHT_DIRECTIONAL,
                              .direction = {-0.35f, 0.2f, -0.915f}, .diffuse = {0.75f, 0.75f, 0.72f},
                              .att_constant = 1, .range = 1000};
        if (wb_light(b, &sun) < 0) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    set_exposure(w);
    return 0;
}

/* ---- primitives ------------------------------------------------------------------------------ */

/* Emits a quad (a,b,c,d counter-clockwise seen from the normal side) in local coordinates. */
static int quad(wbuild *b, const xform *T, const double *pa, const double *pb, const double *pc,
                const double *pd, const double nl[3], int perm, int mat, int obj)
{
    const double *p[4] = {pa, pb, pc, pd};
    static const double uvq[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    long id[4];
    double nw[3];
    xf_apply_dir(T, nl, nw);
    for (int i = 0; i < 4; i++) {
        double pw[3], pat[3] = {p[i][perm], p[i][(perm + 1) % 3], p[i][(perm + 2) % 3]};
        xf_apply(T, p[i], pw);
        id[i] = wb_vertex(b, pw, nw, uvq[i], pat);
    }
    int rc = wb_triangle(b, id[0], id[1], id[2], mat, obj);
    if (!rc) rc = wb_triangle(b, id[0], id[2], id[3], mat, obj);
    return rc;
}

int geom_box(wbuild *b, const xform *T, const double size[3], int mat, int obj)
{
    double h[3] = {size[0] / 2, size[1] / 2, size[2] / 2};
    /* Pattern coordinates put the longest side first, so wood grain runs along a board. */
    int perm = size[0] >= size[1] && size[0] >= size[2] ? 0 : size[1] >= size[2] ? 1 : 2;
    double c[8][3];
    for (int i = 0; i < 8; i++) {
        c[i][0] = (i & 1) ? h[0] : -h[0];
        c[i][1] = (i & 2) ? h[1] : -h[1];
        c[i][2] = (i & 4) ? h[2] : -h[2];
    }
    static const int f[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    static const double n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 6; i++) {
        int rc = quad(b, T, c[f[i][0]], c[f[i][1]], c[f[i][2]], c[f[i][3]], n[i], perm, mat, obj);
        if (rc) return rc;
    }
    return 0;
}

int geom_cylinder(wbuild *b, const xform *T, double r, double len, int mat, int obj)
{
    const int seg = r > 0.15 ? 40 : 24;
    double hz = len / 2;
    int perm = len >= 2 * r ? 2 : 0;
    for (int i = 0; i < seg; i++) {
        double a0 = 2 * M_PI * i / seg, a1 = 2 * M_PI * (i + 1) / seg;
        double p0[3] = {r * cos(a0), r * sin(a0), -hz}, p1[3] = {r * cos(a1), r * sin(a1), -hz};
        double p2[3] = {p1[0], p1[1], hz}, p3[3] = {p0[0], p0[1], hz};
        double n0[3] = {cos(a0), sin(a0), 0}, n1[3] = {cos(a1), sin(a1), 0};
        const double *pp[4] = {p0, p1, p2, p3};
        const double *nn[4] = {n0, n1, n1, n0};
        double uvs[4][2] = {{(double)i / seg, 0}, {(double)(i + 1) / seg, 0},
                            {(double)(i + 1) / seg, 1}, {(double)i / seg, 1}};
        long id[4];
        for (int k = 0; k < 4; k++) {
            double pw[3], nw[3], pat[3] = {pp[k][perm], pp[k][(perm + 1) % 3], pp[k][(perm + 2) % 3]};
            xf_apply(T, pp[k], pw);
            xf_apply_dir(T, nn[k], nw);
            id[k] = wb_vertex(b, pw, nw, uvs[k], pat);
        }
        int rc = wb_triangle(b, id[0], id[1], id[2], mat, obj);
        if (!rc) rc = wb_triangle(b, id[0], id[2], id[3], mat, obj);
        /* caps */
        for (int s = -1; s <= 1 && !rc; s += 2) {
            double c[3] = {0, 0, s * hz}, q0[3] = {p0[0], p0[1], s * hz}, q1[3] = {p1[0], p1[1], s * hz};
            double nl[3] = {0, 0, (double)s}, nw[3];
            xf_apply_dir(T, nl, nw);
            const double *cp[3] = {c, s > 0 ? q0 : q1, s > 0 ? q1 : q0};
            long ci[3];
            for (int k = 0; k < 3; k++) {
                double pw[3], pat[3] = {cp[k][perm], cp[k][(perm + 1) % 3], cp[k][(perm + 2) % 3]};
                double uv[2] = {0.5 + cp[k][0] / (2 * r), 0.5 + cp[k][1] / (2 * r)};
                xf_apply(T, cp[k], pw);
                ci[k] = wb_vertex(b, pw, nw, uv, pat);
            }
            rc = wb_triangle(b, ci[0], ci[1], ci[2], mat, obj);
        }
        if (rc) return rc;
    }
    return 0;
}

int geom_sphere(wbuild *b, const xform *T, double r, int mat, int obj)
{
    const int nu = 32, nv = 16;
    size_t base = b->w->n_vertices;
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i <= nu; i++) {
            double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
            double n[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
            double p[3] = {r * n[0], r * n[1], r * n[2]}, pw[3], nw[3];
            double uv[2] = {(double)i / nu, 1.0 - (double)j / nv};
            xf_apply(T, p, pw);
            xf_apply_dir(T, n, nw);
            if (wb_vertex(b, pw, nw, uv, p) < 0) return SP_E_NOMEM;
        }
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            long a = (long)(base + j * (nu + 1) + i), c = a + 1, d = a + nu + 1, e = d + 1;
            int rc = 0;
            if (j > 0) rc = wb_triangle(b, a, d, c, mat, obj);
            if (!rc && j < nv - 1) rc = wb_triangle(b, c, d, e, mat, obj);
            if (rc) return rc;
        }
    return 0;
}

int geom_plane(wbuild *b, const xform *T, const double normal[3], const double size[2], int mat,
               int obj)
{
    /* Build a frame (u, v, n) with n the plane normal, as Gazebo does for <plane>. */
    double n[3] = {normal[0], normal[1], normal[2]};
    double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(nn > 0)) { n[0] = 0; n[1] = 0; n[2] = 1; nn = 1; }
    for (int i = 0; i < 3; i++) n[i] /= nn;
    /* u: the world x axis projected onto the plane (Gazebo's size[0] runs along x), v = n x u */
    double a[3] = {1, 0, 0};
    if (fabs(n[0]) > 0.9) { a[0] = 0; a[1] = 1; }
    double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    double u[3] = {a[0] - an * n[0], a[1] - an * n[1], a[2] - an * n[2]};
    double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; i++) u[i] /= un;
    double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    double hx = size[0] / 2, hy = size[1] / 2, c[4][3];
    static const double s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < 3; i++) c[k][i] = s[k][0] * hx * u[i] + s[k][1] * hy * v[i];
    return quad(b, T, c[0], c[1], c[2], c[3], n, 0, mat, obj);
}

/* ---- procedural pattern choice --------------------------------------------------------------- */

static int has_word(const char *s, const char *w)
{
    if (!s) return 0;
    size_t n = strlen(w);
    for (const char *p = s; *p; p++)
        if (!strncasecmp(p, w, n)) return 1;
    return 0;
}

int pattern_from_names(const char *script, const char *visual, const char *link, const char *model)
{
    const char *names[4] = {script, visual, link, model};
    for (int i = 0; i < 4; i++) {
        const char *s = names[i];
        if (!s || !*s) continue;
        if (has_word(s, "woodfloor") || has_word(s, "parquet") || has_word(s, "plank"))
            return SP_PATTERN_PLANKS;
        if (has_word(s, "tile")) return SP_PATTERN_TILES;
        if (has_word(s, "carpet") || has_word(s, "rug")) return SP_PATTERN_CARPET;
        if (has_word(s, "fabric") || has_word(s, "cloth") || has_word(s, "cushion") ||
            has_word(s, "sofa") || has_word(s, "couch") || has_word(s, "mattress") ||
            has_word(s, "pillow") || has_word(s, "blanket") || has_word(s, "duvet") ||
            has_word(s, "curtain"))
            return SP_PATTERN_FABRIC;
        if (has_word(s, "brick")) return SP_PATTERN_BRICKS;
        if (has_word(s, "metal") || has_word(s, "steel") || has_word(s, "chrome") ||
            has_word(s, "alumin"))
            return SP_PATTERN_METAL;
        if (has_word(s, "glass") || has_word(s, "screen") || has_word(s, "mirror"))
            return SP_PATTERN_GLASS;
        if (has_word(s, "wood") || has_word(s, "oak") || has_word(s, "walnut") ||
            has_word(s, "pine"))
            return SP_PATTERN_WOOD;
    }
    return SP_PATTERN_PLASTER;
}

void sp_world_free(sp_world *w)
{
    if (!w) return;
    free(w->positions);
    free(w->normals);
    free(w->uvs);
    free(w->pattern);
    free(w->tris);
    free(w->tri_material);
    free(w->tri_object);
    free(w->tri_axis);
    free(w->materials);
    for (size_t i = 0; i < w->n_textures; i++) {
        for (int l = 1; l < w->textures[i].n_levels; l++) free(w->textures[i].level[l]);
        free(w->textures[i].rgb);
    }
    free(w->textures);
    free(w->objects);
    free(w->lights);
    free(w->chunks);
    memset(w, 0, sizeof *w);
}
