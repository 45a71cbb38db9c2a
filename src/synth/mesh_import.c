/* Mesh files through libassimp, in a child process. Assimp crashes on some malformed files (a
 * COLLADA <float_array count="0"> with an accessor over it dereferences NULL in 5.2.5, found by
 * tests/fuzz/fuzz_mesh.c) and could hang on others; a mesh from a downloaded model must not take
 * the program with it. The child imports, flattens the scene (triangles in the file's root
 * frame, per-mesh material, diffuse colour and texture name) and writes it to a pipe; the parent
 * reads it within MESH_TIMEOUT_S and checks it like any file. A crash becomes an error naming the
 * mesh and the signal. */
#include "internal.h"

#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define MESH_TIMEOUT_S 120

void mesh_data_free(mesh_data *m)
{
    for (uint32_t i = 0; m->parts && i < m->n_parts; i++) {
        free(m->parts[i].pos);
        free(m->parts[i].nrm);
        free(m->parts[i].uv);
        free(m->parts[i].tris);
    }
    free(m->parts);
    free(m->materials);
    memset(m, 0, sizeof *m);
}

/* ---- the child: import and write ----------------------------------------------------------------- */

typedef struct {
    int fd, bad;
} out_pipe;

static void put(out_pipe *o, const void *p, size_t n)
{
    const char *c = p;
    while (n && !o->bad) {
        ssize_t w = write(o->fd, c, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            o->bad = 1;
            return;
        }
        c += w, n -= (size_t)w;
    }
}

static void put_u32(out_pipe *o, uint32_t v) { put(o, &v, 4); }

static void put_error(out_pipe *o, const char *msg)
{
    put_u32(o, 1);
    put_u32(o, (uint32_t)strlen(msg));
    put(o, msg, strlen(msg));
}

static void write_scene(out_pipe *o, const struct aiScene *sc)
{
    put_u32(o, 0);
    put_u32(o, sc->mNumMaterials);
    for (unsigned mi = 0; mi < sc->mNumMaterials; mi++) {
        const struct aiMaterial *am = sc->mMaterials[mi];
        struct aiColor4D col;
        uint32_t has = aiGetMaterialColor(am, AI_MATKEY_COLOR_DIFFUSE, &col) == aiReturn_SUCCESS;
        float rgb[3] = {has ? col.r : 0, has ? col.g : 0, has ? col.b : 0};
        struct aiString tp;
        uint32_t tl = 0;
        if (aiGetMaterialTextureCount(am, aiTextureType_DIFFUSE) > 0 &&
            aiGetMaterialTexture(am, aiTextureType_DIFFUSE, 0, &tp, NULL, NULL, NULL, NULL, NULL, NULL) ==
                aiReturn_SUCCESS)
            tl = (uint32_t)strnlen(tp.data, sizeof tp.data - 1);
        put_u32(o, has);
        put(o, rgb, sizeof rgb);
        put_u32(o, tl);
        put(o, tp.data, tl);
    }
    uint32_t n = 0;
    for (unsigned i = 0; i < sc->mNumMeshes; i++) n += (sc->mMeshes[i]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0;
    put_u32(o, n);
    for (unsigned i = 0; i < sc->mNumMeshes && !o->bad; i++) {
        const struct aiMesh *me = sc->mMeshes[i];
        if (!(me->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        uint32_t nf = 0;
        for (unsigned f = 0; f < me->mNumFaces; f++) nf += me->mFaces[f].mNumIndices == 3;
        uint32_t hdr[5] = {me->mNumVertices, nf, me->mMaterialIndex, me->mNormals != NULL,
                           me->mTextureCoords[0] != NULL};
        put(o, hdr, sizeof hdr);
        put(o, me->mVertices, sizeof(float) * 3 * me->mNumVertices);
        if (me->mNormals) put(o, me->mNormals, sizeof(float) * 3 * me->mNumVertices);
        for (unsigned v = 0; me->mTextureCoords[0] && v < me->mNumVertices; v++)
            put(o, &me->mTextureCoords[0][v], sizeof(float) * 2);
        for (unsigned f = 0; f < me->mNumFaces; f++)
            if (me->mFaces[f].mNumIndices == 3) put(o, me->mFaces[f].mIndices, sizeof(uint32_t) * 3);
    }
}

static void child(const char *path, int fd)
{
    /* A crash must end this process by its signal, for the parent to report; sanitizer and
     * libFuzzer handlers would turn it into an exit status (and a report of assimp's fault). */
    static const int fatal[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
    for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++) signal(fatal[i], SIG_DFL);
    out_pipe o = {fd, 0};
    struct aiPropertyStore *props = aiCreatePropertyStore();
    aiSetImportPropertyInteger(props, AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, 1);
    /* Points and lines are dropped; everything else becomes triangles in the file's root frame. */
    aiSetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const struct aiScene *sc = aiImportFileExWithProperties(
        path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_GenSmoothNormals |
                  aiProcess_SortByPType,
        NULL, props);
    aiReleasePropertyStore(props);
    if (!sc || !sc->mRootNode) put_error(&o, aiGetErrorString());
    else write_scene(&o, sc);
    _exit(o.bad ? 2 : 0);
}

/* ---- the parent: read and check ------------------------------------------------------------------ */

typedef struct {
    const unsigned char *p;
    size_t left;
} in_buf;

static int take(in_buf *b, void *dst, size_t n)
{
    if (b->left < n) return -1;
    memcpy(dst, b->p, n);
    b->p += n, b->left -= n;
    return 0;
}

/* n items of `size` bytes into a new buffer (NULL when n == 0). */
static int take_array(in_buf *b, void **dst, size_t n, size_t size)
{
    *dst = NULL;
    if (n > b->left / size) return -1;
    if (!n) return 0;
    if (!(*dst = malloc(n * size))) return -1;
    return take(b, *dst, n * size);
}

/* 0, an SP_E_* error, or 1 when the data is cut short or garbled. */
static int parse(in_buf *b, const char *path, mesh_data *m, sp_error *err)
{
    uint32_t status;
    if (take(b, &status, 4)) return 1;
    if (status) {
        uint32_t len;
        char msg[512] = "";
        if (take(b, &len, 4) || len > b->left) return 1;
        snprintf(msg, sizeof msg, "%.*s", (int)(len < sizeof msg ? len : sizeof msg - 1), (const char *)b->p);
        return sp_error_set(err, SP_E_FORMAT, "cannot read mesh %s: %s", path, msg[0] ? msg : "assimp failed");
    }
    if (take(b, &m->n_materials, 4) || m->n_materials > b->left / 20) return 1;
    if (!(m->materials = calloc(m->n_materials ? m->n_materials : 1, sizeof *m->materials))) return 1;
    for (uint32_t i = 0; i < m->n_materials; i++) {
        mesh_material *mm = &m->materials[i];
        uint32_t has, tl;
        if (take(b, &has, 4) || take(b, mm->diffuse, 12) || take(b, &tl, 4) || tl >= sizeof mm->texture ||
            take(b, mm->texture, tl))
            return 1;
        mm->has_diffuse = has != 0;
    }
    uint32_t np;
    if (take(b, &np, 4) || np > b->left / 20) return 1;
    if (!(m->parts = calloc(np ? np : 1, sizeof *m->parts))) return 1;
    for (uint32_t i = 0; i < np; i++) {
        mesh_part *p = &m->parts[i];
        uint32_t h[5];
        m->n_parts = i + 1;
        if (take(b, h, sizeof h)) return 1;
        p->n_vertices = h[0], p->n_faces = h[1], p->material = h[2];
        if (take_array(b, (void **)&p->pos, p->n_vertices, 12) ||
            (h[3] && take_array(b, (void **)&p->nrm, p->n_vertices, 12)) ||
            (h[4] && take_array(b, (void **)&p->uv, p->n_vertices, 8)) ||
            take_array(b, (void **)&p->tris, p->n_faces, 12))
            return 1;
        /* assimp does not check indices unless asked to validate the whole scene */
        for (uint32_t k = 0; k < 3 * p->n_faces; k++)
            if (p->tris[k] >= p->n_vertices)
                return sp_error_set(err, SP_E_FORMAT, "mesh %s: face %u of mesh %u uses vertex %u of %u", path, k / 3,
                                    i, p->tris[k], p->n_vertices);
    }
    return b->left ? 1 : 0;
}

/* Reads fd to its end or the deadline; *data is malloc'd. 0, or -1 at the deadline. */
static int read_all(int fd, unsigned char **data, size_t *size, double deadline)
{
    size_t cap = 1 << 16, n = 0;
    unsigned char *buf = malloc(cap);
    for (;;) {
        if (!buf) return -1;
        if (n == cap) {
            unsigned char *nb = realloc(buf, cap * 2);
            if (!nb) break;
            buf = nb, cap *= 2;
        }
        double left = deadline - sp_time_now();
        struct pollfd pf = {fd, POLLIN, 0};
        int r = left > 0 ? poll(&pf, 1, (int)(left * 1000) + 1) : 0;
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) {
            free(buf);
            return -1;
        }
        ssize_t got = read(fd, buf + n, cap - n);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        n += (size_t)got;
    }
    *data = buf, *size = n;
    return 0;
}

int mesh_import(const char *path, mesh_data *m, sp_error *err)
{
    memset(m, 0, sizeof *m);
    int fds[2];
    if (pipe(fds) != 0) return sp_error_set(err, SP_E_IO, "mesh %s: cannot make a pipe: %s", path, strerror(errno));
    fflush(NULL); /* nothing buffered is written twice */
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]), close(fds[1]);
        return sp_error_set(err, SP_E_IO, "mesh %s: cannot start the importer: %s", path, strerror(errno));
    }
    if (pid == 0) {
        close(fds[0]);
        child(path, fds[1]);
    }
    close(fds[1]);
    unsigned char *data = NULL;
    size_t size = 0;
    int timed_out = read_all(fds[0], &data, &size, sp_time_now() + MESH_TIMEOUT_S) != 0;
    close(fds[0]);
    if (timed_out) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    int rc;
    if (timed_out)
        rc = sp_error_set(err, SP_E_FORMAT, "mesh %s: assimp did not finish in %d s (a malformed file?)", path,
                          MESH_TIMEOUT_S);
    else if (WIFSIGNALED(status))
        rc = sp_error_set(err, SP_E_FORMAT, "mesh %s: assimp crashed reading it (signal %d: a malformed file)", path,
                          WTERMSIG(status));
    else {
        in_buf b = {data, size};
        rc = parse(&b, path, m, err);
        if (rc == 1)
            rc = sp_error_set(err, SP_E_FORMAT, "mesh %s: assimp failed reading it (importer exit status %d, output cut short)",
                              path, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    }
    free(data);
    if (rc) mesh_data_free(m);
    return rc;
}
