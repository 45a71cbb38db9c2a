/* Mesh visuals (.dae, .obj, .stl, ... through libassimp) with their own materials and diffuse
 * textures, and the texture cache. COLLADA files keep their <unit> scale but not their up axis,
 * as Gazebo renders them. */
#include "internal.h"

#include "semsplat/io.h"

#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
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

int geom_mesh(wbuild *b, const xform *T, const char *path, const double scale[3],
              const sp_synth_material *fallback, int sdf_material_set, int obj, sp_error *err)
{
    struct aiPropertyStore *props = aiCreatePropertyStore();
    aiSetImportPropertyInteger(props, AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, 1);
    /* Points and lines are dropped; everything else becomes triangles in the file's root frame. */
    aiSetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const struct aiScene *sc = aiImportFileExWithProperties(
        path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_GenSmoothNormals |
                  aiProcess_SortByPType,
        NULL, props);
    aiReleasePropertyStore(props);
    if (!sc || !sc->mRootNode)
        return sp_error_set(err, SP_E_FORMAT, "cannot read mesh %s: %s", path, aiGetErrorString());
    int rc = 0;
    /* Material per assimp material index, resolved once. */
    int *mat_of = malloc((sc->mNumMaterials + 1) * sizeof(int));
    if (!mat_of) {
        aiReleaseImport(sc);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    for (unsigned mi = 0; mi < sc->mNumMaterials; mi++) {
        const struct aiMaterial *am = sc->mMaterials[mi];
        sp_synth_material m = *fallback;
        struct aiColor4D col;
        if (!sdf_material_set && aiGetMaterialColor(am, AI_MATKEY_COLOR_DIFFUSE, &col) == aiReturn_SUCCESS) {
            m.diffuse[0] = col.r; m.diffuse[1] = col.g; m.diffuse[2] = col.b;
            memcpy(m.ambient, m.diffuse, sizeof m.ambient);
        }
        struct aiString tp;
        if (aiGetMaterialTextureCount(am, aiTextureType_DIFFUSE) > 0 &&
            aiGetMaterialTexture(am, aiTextureType_DIFFUSE, 0, &tp, NULL, NULL, NULL, NULL, NULL, NULL) ==
                aiReturn_SUCCESS &&
            tp.data[0] != '*') {
            char tpath[PATH_MAX * 2];
            if (find_texture(path, tp.data, tpath, sizeof tpath)) {
                if (!b->skip_missing) {
                    rc = sp_error_set(err, SP_E_NOTFOUND, "missing texture %s (used by mesh %s)", tpath, path);
                    goto done;
                }
                sp_logf(b->log, SP_LOG_WARN, "missing texture %s (used by mesh %s), using its colour", tpath, path);
                b->w->n_missing++;
            } else {
                int ti = wb_texture(b, tpath, err);
                if (ti < 0) {
                    rc = sp_error_prefix(err, "texture of mesh %s: ", path);
                    goto done;
                }
                m.texture = ti;
                for (int k = 0; k < 3; k++) m.diffuse[k] = m.ambient[k] = 1.0f;
            }
        }
        int idx = wb_material(b, &m);
        if (idx < 0) {
            rc = sp_error_set(err, idx, "%s: too many materials", path);
            goto done;
        }
        mat_of[mi] = idx;
    }
    /* Normals go through the inverse-transpose of the scale. */
    double inv_s[3];
    for (int k = 0; k < 3; k++) inv_s[k] = scale[k] != 0 ? 1.0 / scale[k] : 0;
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *me = sc->mMeshes[i];
        if (!(me->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        size_t base = b->w->n_vertices;
        for (unsigned v = 0; v < me->mNumVertices; v++) {
            double p[3] = {me->mVertices[v].x * scale[0], me->mVertices[v].y * scale[1], me->mVertices[v].z * scale[2]};
            double n[3] = {0, 0, 1}, uv[2] = {0, 0}, pw[3], nw[3];
            if (me->mNormals) {
                n[0] = me->mNormals[v].x * inv_s[0];
                n[1] = me->mNormals[v].y * inv_s[1];
                n[2] = me->mNormals[v].z * inv_s[2];
            }
            if (me->mTextureCoords[0]) {
                uv[0] = me->mTextureCoords[0][v].x;
                uv[1] = me->mTextureCoords[0][v].y;
            }
            xf_apply(T, p, pw);
            xf_apply_dir(T, n, nw);
            if (!isfinite(pw[0]) || !isfinite(pw[1]) || !isfinite(pw[2])) {
                rc = sp_error_set(err, SP_E_NUMERIC, "mesh %s: vertex %u of mesh %u is not finite (%g %g %g)", path,
                                  v, i, me->mVertices[v].x, me->mVertices[v].y, me->mVertices[v].z);
                goto done;
            }
            if (wb_vertex(b, pw, nw, uv, p) < 0) {
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
                goto done;
            }
        }
        int mat = me->mMaterialIndex < sc->mNumMaterials ? mat_of[me->mMaterialIndex] : wb_material(b, fallback);
        for (unsigned f = 0; f < me->mNumFaces; f++) {
            const struct aiFace *fc = &me->mFaces[f];
            if (fc->mNumIndices != 3) continue;
            /* assimp does not check indices unless asked to validate the whole scene */
            for (int k = 0; k < 3; k++)
                if (fc->mIndices[k] >= me->mNumVertices) {
                    rc = sp_error_set(err, SP_E_FORMAT, "mesh %s: face %u of mesh %u uses vertex %u of %u", path, f,
                                      i, fc->mIndices[k], me->mNumVertices);
                    goto done;
                }
            if (wb_triangle(b, (long)(base + fc->mIndices[0]), (long)(base + fc->mIndices[1]),
                            (long)(base + fc->mIndices[2]), mat, obj)) {
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
                goto done;
            }
        }
    }
done:
    free(mat_of);
    aiReleaseImport(sc);
    return rc;
}
