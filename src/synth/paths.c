/* Where SDF worlds find their files: the model path (model://NAME), and mesh/texture URIs
 * (model://, package://, file://, absolute, or relative to the SDF file and its parents, with a
 * case-insensitive fallback for worlds made on case-insensitive file systems). */
#include "internal.h"

#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

int path_is_dir(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

int path_is_file(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

void path_dir_of(const char *path, char *out, size_t cap)
{
    snprintf(out, cap, "%s", path);
    char *s = strrchr(out, '/');
    if (s == out) s[1] = 0;
    else if (s) *s = 0;
    else snprintf(out, cap, ".");
}

void mp_add(model_path *c, const char *list)
{
    if (!list) return;
    const char *s = list;
    while (*s && c->n < SYNTH_MAX_DIRS) {
        const char *e = strchr(s, ':');
        size_t L = e ? (size_t)(e - s) : strlen(s);
        if (L && L < PATH_MAX) {
            char d[PATH_MAX];
            memcpy(d, s, L);
            d[L] = 0;
            int dup = 0;
            for (int i = 0; i < c->n; i++) dup |= !strcmp(c->dirs[i], d);
            if (!dup) snprintf(c->dirs[c->n++], PATH_MAX, "%s", d);
        }
        if (!e) break;
        s = e + 1;
    }
}

void mp_list(const model_path *c, char *out, size_t cap)
{
    size_t o = 0;
    out[0] = 0;
    for (int i = 0; i < c->n && o + 2 < cap; i++)
        o += (size_t)snprintf(out + o, cap - o, "%s%s", i ? ", " : "", c->dirs[i]);
    if (!c->n) snprintf(out, cap, "(none; pass --model-path or set GAZEBO_MODEL_PATH)");
}

/* model://NAME[/rest] (or package://) -> path of NAME's folder + rest; 0 or SP_E_NOTFOUND. */
int mp_resolve_model(const model_path *c, const char *uri, char *out, size_t cap)
{
    const char *p = strstr(uri, "://");
    p = p ? p + 3 : uri;
    char name[PATH_MAX];
    snprintf(name, sizeof name, "%s", p);
    char *slash = strchr(name, '/');
    const char *rest = "";
    if (slash) {
        *slash = 0;
        rest = p + (slash - name) + 1;
    }
    for (int i = 0; i < c->n; i++) {
        char d[PATH_MAX * 2];
        snprintf(d, sizeof d, "%s/%s", c->dirs[i], name);
        if (!path_is_dir(d)) continue;
        if (*rest) snprintf(out, cap, "%s/%s", d, rest);
        else snprintf(out, cap, "%s", d);
        return 0;
    }
    return SP_E_NOTFOUND;
}

/* Worlds made on case-insensitive file systems name "Spotlight.DAE" for "spotlight.DAE": when the
 * exact name is absent, a file in the same folder whose name differs only in case is used. */
static int case_insensitive_file(char *path, size_t cap)
{
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%s", path);
    char *s = strrchr(dir, '/');
    if (!s) return 0;
    *s = 0;
    const char *base = s + 1;
    DIR *d = opendir(dir);
    if (!d) return 0;
    int found = 0;
    for (struct dirent *e; !found && (e = readdir(d));)
        if (!strcasecmp(e->d_name, base)) {
            snprintf(path, cap, "%s/%s", dir, e->d_name);
            found = path_is_file(path);
        }
    closedir(d);
    return found;
}

/* A mesh or texture URI: model://, file://, absolute, or relative to the SDF file's folder (and,
 * as Gazebo worlds assume, its parents, the model path's folders, or the working directory). */
int mp_resolve_file(const model_path *c, const char *uri, const char *sdf_dir, char *out, size_t cap)
{
    if (!strncmp(uri, "model://", 8) || !strncmp(uri, "package://", 10)) {
        if (mp_resolve_model(c, uri, out, cap)) return SP_E_NOTFOUND;
        return path_is_file(out) ? 0 : SP_E_NOTFOUND;
    }
    const char *p = !strncmp(uri, "file://", 7) ? uri + 7 : uri;
    if (p[0] == '/') {
        snprintf(out, cap, "%s", p);
        return path_is_file(out) ? 0 : SP_E_NOTFOUND;
    }
    char base[PATH_MAX];
    snprintf(base, sizeof base, "%s", sdf_dir);
    for (int up = 0; up < 4; up++) {
        snprintf(out, cap, "%s/%s", base, p);
        if (path_is_file(out)) return 0;
        if (case_insensitive_file(out, cap)) {
            sp_logf(c->log, SP_LOG_WARN, "%s: using %s (the name differs in case)", uri, out);
            return 0;
        }
        char *s = strrchr(base, '/');
        if (!s || s == base) break;
        *s = 0;
    }
    for (int i = 0; i < c->n; i++) {
        snprintf(out, cap, "%s/%s", c->dirs[i], p);
        if (path_is_file(out)) return 0;
        snprintf(out, cap, "%s/../%s", c->dirs[i], p);
        if (path_is_file(out)) return 0;
    }
    snprintf(out, cap, "%s", p);
    if (path_is_file(out)) return 0;
    snprintf(out, cap, "%s/%s", sdf_dir, p);
    return SP_E_NOTFOUND;
}
