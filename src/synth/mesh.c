/* Mesh visuals (.dae, .obj, .stl, ... through libassimp, imported by mesh_import.c) with their
 * own materials and diffuse textures, and the texture cache. COLLADA files keep their <unit> scale but not their up axis,
 * as Gazebo renders them. */
#include "internal.h"

#include "semsplat/io.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int file_ok(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

int wb_texture(wbuild *b, const char *path, sp_error *err)
{
    sp_world *w = b->w;
    for (size_t i = 0; i < w->n_textures; i++)
        if (!strcmp(w->textures[i].path, path)) return (int)i;
    sp_image img = {0};
    int rc = sp_image_read(path, &img, err);
    if (rc) return rc;
    sp_synth_texture t;
    memset(&t, 0, sizeof t);
    snprintf(t.path, sizeof t.path, "%s", path);
    t.width = img.width;
    t.height = img.height;
    t.rgb = malloc((size_t)img.width * img.height * 3);
    if (!t.rgb) {
        sp_image_free(&img);
        return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    }
    size_t n = (size_t)img.width * img.height;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            int ch = img.channels >= 3 ? k : 0;
            size_t at = i * img.channels + ch;
            t.rgb[i * 3 + k] = img.bit_depth == 16 ? (uint8_t)(((const uint16_t *)img.data)[at] >> 8)
                                                   : ((const uint8_t *)img.data)[at];
        }
    sp_image_free(&img);
    /* mip levels: 2x2 box filter (the last row/column repeats on odd sizes) */
    t.n_levels = 1;
    t.level[0] = t.rgb;
    t.level_w[0] = t.width;
    t.level_h[0] = t.height;
    while (t.n_levels < SP_SYNTH_MAX_MIP) {
        int pw = t.level_w[t.n_levels - 1], ph = t.level_h[t.n_levels - 1];
        if (pw == 1 && ph == 1) break;
        int nw = pw > 1 ? pw / 2 : 1, nh = ph > 1 ? ph / 2 : 1;
        uint8_t *src = t.level[t.n_levels - 1], *dst = malloc((size_t)nw * nh * 3);
        if (!dst) break; /* fewer levels: still correct, only more aliasing */
        for (int y = 0; y < nh; y++)
            for (int x = 0; x < nw; x++) {
                int x0 = 2 * x < pw ? 2 * x : pw - 1, x1 = 2 * x + 1 < pw ? 2 * x + 1 : pw - 1;
                int y0 = 2 * y < ph ? 2 * y : ph - 1, y1 = 2 * y + 1 < ph ? 2 * y + 1 : ph - 1;
                for (int k = 0; k < 3; k++) {
                    int sum = src[((size_t)y0 * pw + x0) * 3 + k] + src[((size_t)y0 * pw + x1) * 3 + k] +
                              src[((size_t)y1 * pw + x0) * 3 + k] + src[((size_t)y1 * pw + x1) * 3 + k];
                    dst[((size_t)y * nw + x) * 3 + k] = (uint8_t)((sum + 2) / 4);
                }
            }
        t.level[t.n_levels] = dst;
        t.level_w[t.n_levels] = nw;
        t.level_h[t.n_levels] = nh;
        t.n_levels++;
    }
    sp_synth_texture *nt = realloc(w->textures, (w->n_textures + 1) * sizeof *nt);
    if (!nt) {
        for (int l = 1; l < t.n_levels; l++) free(t.level[l]);
        free(t.rgb);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    w->textures = nt;
    w->textures[w->n_textures] = t;
    return (int)w->n_textures++;
}

/* A texture path from a mesh's material: relative to the mesh file, else the usual Gazebo
 * layouts (../materials/textures, ../textures, beside the mesh). */
static int find_texture(const char *mesh_path, const char *tex, char *out, size_t cap)
{
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%s", mesh_path);
    char *s = strrchr(dir, '/');
    if (s) *s = 0;
    else snprintf(dir, sizeof dir, ".");
    const char *t = !strncmp(tex, "file://", 7) ? tex + 7 : tex;
    if (t[0] == '/') {
        snprintf(out, cap, "%s", t);
        if (file_ok(out)) return 0;
    } else {
        snprintf(out, cap, "%s/%s", dir, t);
        if (file_ok(out)) return 0;
    }
    const char *bs = strrchr(t, '/');
    const char *bn = strrchr(t, '\\');
    const char *base = bs ? bs + 1 : t;
    if (bn && bn + 1 > base) base = bn + 1;
    static const char *const sub[] = {"", "/../materials/textures", "/../textures", "/textures", NULL};
    for (int i = 0; sub[i]; i++) {
        snprintf(out, cap, "%s%s/%s", dir, sub[i], base);
        if (file_ok(out)) return 0;
    }
    /* Report the path the mesh asked for. */
    if (t[0] == '/') snprintf(out, cap, "%s", t);
    else snprintf(out, cap, "%s/%s", dir, t);
    return SP_E_NOTFOUND;
}

/* The world material of one mesh material: its colour unless the SDF set one, its texture. */
static int mesh_material_index(wbuild *b, const char *path, const mesh_material *mm, const sp_synth_material *fallback,
                               int sdf_material_set, int *out, sp_error *err)
{
    sp_synth_material m = *fallback;
    if (!sdf_material_set && mm->has_diffuse) {
        memcpy(m.diffuse, mm->diffuse, sizeof m.diffuse);
        memcpy(m.ambient, m.diffuse, sizeof m.ambient);
    }
    if (mm->texture[0] && mm->texture[0] != '*') {
        char tpath[PATH_MAX * 2];
        if (find_texture(path, mm->texture, tpath, sizeof tpath)) {
            /* As Gazebo: the mesh is drawn in its material colour, with a warning (a texture
             * changes how a thing looks, not where it is; missing meshes stay errors). */
            sp_logf(b->log, SP_LOG_WARN, "missing texture %s (used by mesh %s): drawn in its material colour", tpath,
                    path);
            b->w->n_missing_textures++;
        } else {
            int ti = wb_texture(b, tpath, err);
            if (ti < 0) return sp_error_prefix(err, "texture of mesh %s: ", path);
            m.texture = ti;
            for (int k = 0; k < 3; k++) m.diffuse[k] = m.ambient[k] = 1.0f;
        }
    }
    int idx = wb_material(b, &m);
    if (idx < 0) return sp_error_set(err, idx, "%s: too many materials", path);
    *out = idx;
    return 0;
}

/* The mesh at path, imported on first use and kept in the builder's cache. */
static int cached_mesh(wbuild *b, const char *path, const mesh_data **out, sp_error *err)
{
    for (size_t i = 0; i < b->n_meshes; i++)
        if (!strcmp(b->meshes[i].path, path)) {
            *out = &b->meshes[i].data;
            return 0;
        }
    if (b->n_meshes == b->cap_meshes) {
        size_t cap = b->cap_meshes ? b->cap_meshes * 2 : 16;
        mesh_cache_entry *nm = realloc(b->meshes, cap * sizeof *nm);
        if (!nm) return sp_error_set(err, SP_E_NOMEM, "out of memory");
        b->meshes = nm, b->cap_meshes = cap;
    }
    mesh_cache_entry *e = &b->meshes[b->n_meshes];
    snprintf(e->path, sizeof e->path, "%s", path);
    int rc = mesh_import(path, &e->data, err);
    if (rc) return rc;
    *out = &b->meshes[b->n_meshes++].data;
    return 0;
}

int geom_mesh(wbuild *b, const xform *T, const char *path, const double scale[3],
              const sp_synth_material *fallback, int sdf_material_set, int obj, sp_error *err)
{
    const mesh_data *cached = NULL;
    int rc = cached_mesh(b, path, &cached, err);
    if (rc) return rc;
    const mesh_data md = *cached;
    /* Material per mesh material, resolved once; the last slot is the fallback. */
    int *mat_of = malloc((md.n_materials + 1) * sizeof(int));
    if (!mat_of) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (uint32_t mi = 0; mi < md.n_materials && !rc; mi++)
        rc = mesh_material_index(b, path, &md.materials[mi], fallback, sdf_material_set, &mat_of[mi], err);
    if (!rc && (mat_of[md.n_materials] = wb_material(b, fallback)) < 0)
        rc = sp_error_set(err, mat_of[md.n_materials], "%s: too many materials", path);
    /* Normals go through the inverse-transpose of the scale. */
    double inv_s[3];
    for (int k = 0; k < 3; k++) inv_s[k] = scale[k] != 0 ? 1.0 / scale[k] : 0;
    for (uint32_t i = 0; i < md.n_parts && !rc; i++) {
        const mesh_part *me = &md.parts[i];
        size_t base = b->w->n_vertices;
        for (uint32_t v = 0; v < me->n_vertices && !rc; v++) {
            const float *q = me->pos + 3 * (size_t)v;
            double p[3] = {q[0] * scale[0], q[1] * scale[1], q[2] * scale[2]};
            double n[3] = {0, 0, 1}, uv[2] = {0, 0}, pw[3], nw[3];
            if (me->nrm)
                for (int k = 0; k < 3; k++) n[k] = me->nrm[3 * (size_t)v + k] * inv_s[k];
            if (me->uv) uv[0] = me->uv[2 * (size_t)v], uv[1] = me->uv[2 * (size_t)v + 1];
            xf_apply(T, p, pw);
            xf_apply_dir(T, n, nw);
            /* normals too: assimp derives them from the positions, and huge ones overflow */
            if (!isfinite(pw[0]) || !isfinite(pw[1]) || !isfinite(pw[2]) || !isfinite(nw[0]) || !isfinite(nw[1]) ||
                !isfinite(nw[2]))
                rc = sp_error_set(err, SP_E_NUMERIC, "mesh %s: vertex %u of mesh %u is not finite or too large (%g %g %g)",
                                  path, v, i, q[0], q[1], q[2]);
            else if (wb_vertex(b, pw, nw, uv, p) < 0)
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
        }
        int mat = mat_of[me->material < md.n_materials ? me->material : md.n_materials];
        for (uint32_t f = 0; f < me->n_faces && !rc; f++) {
            const uint32_t *t = me->tris + 3 * (size_t)f;
            if (wb_triangle(b, (long)(base + t[0]), (long)(base + t[1]), (long)(base + t[2]), mat, obj))
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
        }
    }
    free(mat_of);
    return rc;
}
