/* SDF world reader (libxml2): walks <world>, <model> (nested), <include> (model:// through the
 * model path), <link>, <visual>, <light> and <scene>, composes poses (with relative_to), and
 * hands geometry to the world builder. Every top-level model becomes one labelled object. */
#include "internal.h"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAX_INCLUDE_DEPTH 16

typedef struct ctx {
    wbuild b;
    sp_error *err;
    const sp_log *log;
    int skip_missing;
    model_path mp;
    int depth;
} ctx;

/* A model being read: its element, world pose, and the file it came from (for messages and
 * relative mesh paths). */
typedef struct scope {
    xmlNodePtr node;
    xform to_world;
    const char *file;
    const char *dir;
    int obj;
} scope;

static int is_elem(xmlNodePtr n, const char *name)
{
    return n && n->type == XML_ELEMENT_NODE && !strcmp((const char *)n->name, name);
}

static xmlNodePtr child(xmlNodePtr n, const char *name)
{
    for (xmlNodePtr c = n ? n->children : NULL; c; c = c->next)
        if (is_elem(c, name)) return c;
    return NULL;
}

/* Attribute value copied into buf ("" when absent). */
static const char *attr(xmlNodePtr n, const char *name, char *buf, size_t cap)
{
    buf[0] = 0;
    xmlChar *v = n ? xmlGetProp(n, (const xmlChar *)name) : NULL;
    if (v) {
        snprintf(buf, cap, "%s", (const char *)v);
        xmlFree(v);
    }
    return buf;
}

/* Trimmed text content of an element into buf. */
static const char *text(xmlNodePtr n, char *buf, size_t cap)
{
    buf[0] = 0;
    if (!n) return buf;
    xmlChar *v = xmlNodeGetContent(n);
    if (!v) return buf;
    const char *s = (const char *)v;
    while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') s++;
    snprintf(buf, cap, "%s", s);
    size_t L = strlen(buf);
    while (L && (buf[L - 1] == ' ' || buf[L - 1] == '\t' || buf[L - 1] == '\n' || buf[L - 1] == '\r'))
        buf[--L] = 0;
    xmlFree(v);
    return buf;
}

/* Parses between min_n and max_n numbers from an element's text; returns how many, or fails
 * naming the file, line and element. */
static int numbers(ctx *c, const char *file, xmlNodePtr n, int min_n, int max_n, double *out)
{
    char buf[1024];
    text(n, buf, sizeof buf);
    const char *s = buf;
    int k = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') s++;
        if (!*s) break;
        char *end;
        double v = strtod(s, &end);
        /* "1-2" is not two numbers: each ends at a blank or the end */
        int glued = *end && *end != ' ' && *end != '\t' && *end != '\n' && *end != '\r';
        if (end == s || glued || k >= max_n || !isfinite(v))
            return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: <%s>: expected %d%s numbers, got '%s'",
                                file, xmlGetLineNo(n), (const char *)n->name, min_n,
                                max_n > min_n ? "+" : "", buf);
        out[k++] = v;
        s = end;
    }
    if (k < min_n)
        return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: <%s>: expected %d numbers, got '%s'", file,
                            xmlGetLineNo(n), (const char *)n->name, min_n, buf);
    return k;
}

/* ---- files, model path, URIs ----------------------------------------------------------------- */

/* libxml2 reports every error; the first one is where the file went wrong. */
typedef struct first_error {
    int set, line;
    char msg[512];
} first_error;

static void keep_first(void *user, const xmlError *e)
{
    first_error *fe = user;
    if (fe->set || !e || e->level < XML_ERR_ERROR) return;
    fe->set = 1;
    fe->line = e->line;
    snprintf(fe->msg, sizeof fe->msg, "%s", e->message ? e->message : "error");
    size_t L = strlen(fe->msg);
    while (L && fe->msg[L - 1] == '\n') fe->msg[--L] = 0;
}

static xmlDocPtr read_xml(ctx *c, const char *path)
{
    if (!path_is_file(path)) {
        sp_error_set(c->err, SP_E_IO, "%s: cannot open the file", path);
        return NULL;
    }
    xmlParserCtxtPtr pc = xmlNewParserCtxt();
    if (!pc) {
        sp_error_set(c->err, SP_E_NOMEM, "%s: cannot create an XML parser", path);
        return NULL;
    }
    first_error fe = {0};
    xmlSetStructuredErrorFunc(&fe, (xmlStructuredErrorFunc)keep_first);
    xmlDocPtr doc = xmlCtxtReadFile(pc, path, NULL, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    xmlSetStructuredErrorFunc(NULL, NULL);
    if (!doc) {
        if (fe.set)
            sp_error_set(c->err, SP_E_FORMAT, "%s:%d: malformed XML: %s", path, fe.line, fe.msg);
        else
            sp_error_set(c->err, SP_E_FORMAT, "%s: malformed XML", path);
    }
    xmlFreeParserCtxt(pc);
    return doc;
}

/* ---- poses ----------------------------------------------------------------------------------- */

static int pose_of(ctx *c, const char *file, xmlNodePtr el, xform *local, char *rel, size_t rcap)
{
    *local = xf_identity();
    rel[0] = 0;
    xmlNodePtr p = child(el, "pose");
    if (!p) return 0;
    double v[7] = {0};
    int k = numbers(c, file, p, 6, 7, v);
    if (k < 0) return k;
    if (k == 7) { /* SDF 1.9 rotation_format="quat_xyz_w": x y z qx qy qz qw */
        double qn = v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6];
        if (!(qn > 1e-12) || !isfinite(qn))
            return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: <pose>: the quaternion (%g %g %g %g) is not a rotation",
                                file, xmlGetLineNo(p), v[3], v[4], v[5], v[6]);
        float q[4] = {(float)v[6], (float)v[3], (float)v[4], (float)v[5]}, R[9];
        sp_quat_to_mat3(q, R);
        xform a = xf_identity();
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) a.m[i * 4 + j] = R[i * 3 + j];
            a.m[i * 4 + 3] = v[i];
        }
        *local = a;
    } else {
        char deg[16];
        attr(p, "degrees", deg, sizeof deg);
        if (!strcmp(deg, "true") || !strcmp(deg, "1"))
            for (int i = 3; i < 6; i++) v[i] *= M_PI / 180.0;
        *local = xf_from_pose(v);
    }
    attr(p, "relative_to", rel, rcap);
    if (!rel[0]) attr(p, "frame", rel, rcap); /* SDF 1.5 spelling */
    return 0;
}

static int frame_world(ctx *c, const scope *s, const char *name, xform *out, int depth);

/* World pose of a named child (link, model, frame, include) of the scope's model. */
static int element_world(ctx *c, const scope *s, xmlNodePtr el, xform *out, int depth)
{
    xform local;
    char rel[256], buf[256];
    int rc = pose_of(c, s->file, el, &local, rel, sizeof rel);
    if (rc) return rc;
    if (!rel[0] && is_elem(el, "frame")) attr(el, "attached_to", rel, sizeof rel);
    xform base = s->to_world;
    if (rel[0] && strcmp(rel, "__model__") && strcmp(rel, attr(s->node, "name", buf, sizeof buf))) {
        rc = frame_world(c, s, rel, &base, depth + 1);
        if (rc) return rc;
    }
    *out = xf_mul(base, local);
    return 0;
}

static int frame_world(ctx *c, const scope *s, const char *name, xform *out, int depth)
{
    if (!strcmp(name, "world")) {
        *out = xf_identity();
        return 0;
    }
    if (depth > 16)
        return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: relative_to '%s': frames refer to each other in a cycle",
                            s->file, xmlGetLineNo(s->node), name);
    char buf[256];
    for (xmlNodePtr e = s->node->children; e; e = e->next) {
        if (e->type != XML_ELEMENT_NODE) continue;
        const char *nm = attr(e, "name", buf, sizeof buf);
        if (is_elem(e, "include")) text(child(e, "name"), buf, sizeof buf);
        if (strcmp(nm, name)) continue;
        if (is_elem(e, "link") || is_elem(e, "model") || is_elem(e, "frame") || is_elem(e, "include"))
            return element_world(c, s, e, out, depth);
    }
    return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: relative_to '%s' names no frame, link or model here",
                        s->file, xmlGetLineNo(s->node), name);
}

/* ---- materials and geometry ------------------------------------------------------------------ */

static const struct { const char *name; float rgb[3]; } gazebo_colours[] = {
    {"Gazebo/White", {0.95f, 0.95f, 0.95f}}, {"Gazebo/Grey", {0.6f, 0.6f, 0.6f}},
    {"Gazebo/Gray", {0.6f, 0.6f, 0.6f}},     {"Gazebo/DarkGrey", {0.3f, 0.3f, 0.3f}},
    {"Gazebo/Black", {0.06f, 0.06f, 0.06f}}, {"Gazebo/Red", {0.85f, 0.1f, 0.1f}},
    {"Gazebo/Green", {0.1f, 0.7f, 0.1f}},    {"Gazebo/Blue", {0.1f, 0.2f, 0.85f}},
    {"Gazebo/Yellow", {0.9f, 0.85f, 0.1f}},  {"Gazebo/Orange", {0.95f, 0.5f, 0.1f}},
    {"Gazebo/Purple", {0.5f, 0.1f, 0.6f}},   {"Gazebo/Turquoise", {0.1f, 0.7f, 0.7f}},
    {"Gazebo/Wood", {0.55f, 0.36f, 0.2f}},   {"Gazebo/WoodFloor", {0.6f, 0.42f, 0.25f}},
    {"Gazebo/Bricks", {0.6f, 0.3f, 0.22f}},  {"Gazebo/CeilingTiled", {0.9f, 0.9f, 0.88f}},
    {"Gazebo/Carpet", {0.45f, 0.4f, 0.35f}}, {"Gazebo/Grass", {0.3f, 0.6f, 0.2f}},
    {NULL, {0, 0, 0}}};

/* Reads <material>; returns 1 if it set a colour, 0 if absent, negative on a bad value. */
static int read_material(ctx *c, const char *file, xmlNodePtr vis, const char *names[3],
                         sp_synth_material *m)
{
    memset(m, 0, sizeof *m);
    m->texture = -1;
    for (int i = 0; i < 3; i++) m->diffuse[i] = m->ambient[i] = 0.75f;
    xmlNodePtr mat = child(vis, "material");
    char script[256] = "";
    int set = 0;
    if (mat) {
        xmlNodePtr sc = child(mat, "script");
        if (sc) text(child(sc, "name"), script, sizeof script);
        for (int i = 0; script[0] && gazebo_colours[i].name; i++)
            if (!strcasecmp(script, gazebo_colours[i].name)) {
                memcpy(m->diffuse, gazebo_colours[i].rgb, sizeof m->diffuse);
                memcpy(m->ambient, gazebo_colours[i].rgb, sizeof m->ambient);
                set = 1;
            }
        const char *keys[3] = {"diffuse", "ambient", "emissive"};
        float *dst[3] = {m->diffuse, m->ambient, m->emissive};
        for (int k = 0; k < 3; k++) {
            xmlNodePtr e = child(mat, keys[k]);
            if (!e) continue;
            double v[4];
            int n = numbers(c, file, e, 3, 4, v);
            if (n < 0) return n;
            for (int i = 0; i < 3; i++) dst[k][i] = (float)(v[i] < 0 ? 0 : v[i] > 1 ? 1 : v[i]);
            if (k == 0) {
                set = 1;
                if (!child(mat, "ambient")) memcpy(m->ambient, m->diffuse, sizeof m->ambient);
            }
        }
        if (!child(mat, "diffuse") && child(mat, "ambient")) {
            memcpy(m->diffuse, m->ambient, sizeof m->diffuse);
            set = 1;
        }
    }
    m->pattern = pattern_from_names(script, names[0], names[1], names[2]);
    return set;
}

static int read_visual(ctx *c, const scope *s, xmlNodePtr link, const xform *link_world,
                       xmlNodePtr vis)
{
    char vname[128], lname[128], mname[128], rel[256];
    attr(vis, "name", vname, sizeof vname);
    attr(link, "name", lname, sizeof lname);
    attr(s->node, "name", mname, sizeof mname);
    xform local, base = *link_world;
    int rc = pose_of(c, s->file, vis, &local, rel, sizeof rel);
    if (rc) return rc;
    if (rel[0] && strcmp(rel, lname) && (rc = frame_world(c, s, rel, &base, 0))) return rc;
    xform T = xf_mul(base, local);
    xmlNodePtr geo = child(vis, "geometry");
    if (!geo) return 0;
    xmlNodePtr tr = child(vis, "transparency");
    if (tr) {
        double t;
        if ((rc = numbers(c, s->file, tr, 1, 1, &t)) < 0) return rc;
        if (t >= 0.99) return 0; /* invisible helper geometry */
    }
    const char *names[3] = {vname, lname, mname};
    sp_synth_material m;
    int mset = read_material(c, s->file, vis, names, &m);
    if (mset < 0) return mset;
    int mat = wb_material(&c->b, &m);
    if (mat < 0) return sp_error_set(c->err, mat, "%s: too many materials", s->file);
    size_t mark;
    wb_chunk_begin(&c->b, &mark);
    long line = xmlGetLineNo(vis);
    for (xmlNodePtr g = geo->children; g; g = g->next) {
        if (g->type != XML_ELEMENT_NODE) continue;
        if (is_elem(g, "box")) {
            xmlNodePtr sz = child(g, "size");
            double size[3] = {1, 1, 1};
            if (sz && (rc = numbers(c, s->file, sz, 3, 3, size)) < 0) return rc;
            rc = geom_box(&c->b, &T, size, mat, s->obj);
        } else if (is_elem(g, "cylinder") || is_elem(g, "capsule")) {
            double r = 0.5, len = 1;
            if (child(g, "radius") && (rc = numbers(c, s->file, child(g, "radius"), 1, 1, &r)) < 0) return rc;
            if (child(g, "length") && (rc = numbers(c, s->file, child(g, "length"), 1, 1, &len)) < 0) return rc;
            rc = geom_cylinder(&c->b, &T, r, len, mat, s->obj);
        } else if (is_elem(g, "sphere")) {
            double r = 0.5;
            if (child(g, "radius") && (rc = numbers(c, s->file, child(g, "radius"), 1, 1, &r)) < 0) return rc;
            rc = geom_sphere(&c->b, &T, r, mat, s->obj);
        } else if (is_elem(g, "plane")) {
            double n[3] = {0, 0, 1}, size[2] = {100, 100};
            if (child(g, "normal") && (rc = numbers(c, s->file, child(g, "normal"), 3, 3, n)) < 0) return rc;
            if (child(g, "size") && (rc = numbers(c, s->file, child(g, "size"), 2, 2, size)) < 0) return rc;
            rc = geom_plane(&c->b, &T, n, size, mat, s->obj);
        } else if (is_elem(g, "mesh")) {
            char uri[PATH_MAX], path[PATH_MAX * 2];
            text(child(g, "uri"), uri, sizeof uri);
            double scale[3] = {1, 1, 1};
            if (child(g, "scale") && (rc = numbers(c, s->file, child(g, "scale"), 3, 3, scale)) < 0) return rc;
            if (!uri[0])
                return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: <mesh> without a <uri>", s->file, line);
            if (mp_resolve_file(&c->mp, uri, s->dir, path, sizeof path)) {
                if (c->skip_missing) {
                    sp_logf(c->log, SP_LOG_WARN, "%s:%ld: missing mesh %s (model '%s'), skipped", s->file,
                            line, uri, mname);
                    c->b.w->n_missing++;
                    continue;
                }
                return sp_error_set(c->err, SP_E_NOTFOUND,
                                    "%s:%ld: missing mesh %s (model '%s'; looked beside %s, its parents and the model path)",
                                    s->file, line, uri, mname, s->file);
            }
            rc = geom_mesh(&c->b, &T, path, scale, &m, mset, s->obj, c->err);
            if (rc) return sp_error_prefix(c->err, "%s:%ld: ", s->file, line);
        } else {
            sp_logf(c->log, SP_LOG_DEBUG, "%s:%ld: geometry <%s> is not rendered", s->file, line,
                    (const char *)g->name);
            continue;
        }
        if (rc) return sp_error_set(c->err, rc, "%s:%ld: out of memory building geometry", s->file, line);
    }
    if ((rc = wb_chunk_end(&c->b, mark))) return sp_error_set(c->err, rc, "out of memory");
    return 0;
}

/* ---- models and includes --------------------------------------------------------------------- */

static int read_model(ctx *c, const scope *s);
static int read_light(ctx *c, const char *file, xmlNodePtr e, const xform *base);

static int new_object(ctx *c, const char *name, const char *source, const xform *pose, long line)
{
    sp_synth_object o;
    memset(&o, 0, sizeof o);
    snprintf(o.name, sizeof o.name, "%s", name);
    snprintf(o.source, sizeof o.source, "%s", source);
    sp_synth_class_name(source, o.class_name, sizeof o.class_name);
    o.is_structure = sp_synth_is_structure(name, o.class_name);
    for (int i = 0; i < 16; i++) o.pose[i] = (float)pose->m[i];
    o.sdf_line = (int)line;
    int idx = wb_object(&c->b, &o);
    if (idx < 0) sp_error_set(c->err, idx, "too many models (labels are 16-bit)");
    return idx;
}

/* <include>: parent is the enclosing model's scope, or NULL at world level (a new object). */
static int read_include(ctx *c, const scope *parent, const char *file, xmlNodePtr inc, int obj)
{
    char uri[PATH_MAX], dir[PATH_MAX * 2], name[128], buf[256];
    long line = xmlGetLineNo(inc);
    text(child(inc, "uri"), uri, sizeof uri);
    if (!uri[0]) return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: <include> without a <uri>", file, line);
    if (c->depth >= MAX_INCLUDE_DEPTH)
        return sp_error_set(c->err, SP_E_FORMAT, "%s:%ld: includes nested deeper than %d (a cycle?) at %s",
                            file, line, MAX_INCLUDE_DEPTH, uri);
    int found;
    if (!strncmp(uri, "model://", 8) || !strncmp(uri, "package://", 10))
        found = mp_resolve_model(&c->mp, uri, dir, sizeof dir) == 0;
    else {
        const char *p = !strncmp(uri, "file://", 7) ? uri + 7 : uri;
        char fdir[PATH_MAX];
        path_dir_of(file, fdir, sizeof fdir);
        if (p[0] == '/') snprintf(dir, sizeof dir, "%s", p);
        else snprintf(dir, sizeof dir, "%s/%s", fdir, p);
        found = path_is_dir(dir) || path_is_file(dir);
    }
    if (!found) {
        char dl[2048];
        mp_list(&c->mp, dl, sizeof dl);
        if (c->skip_missing) {
            sp_logf(c->log, SP_LOG_WARN, "%s:%ld: model %s not found in the model path (%s), skipped",
                    file, line, uri, dl);
            c->b.w->n_missing++;
            return 0;
        }
        return sp_error_set(c->err, SP_E_NOTFOUND, "%s:%ld: model %s not found in the model path (%s)",
                            file, line, uri, dl);
    }
    /* The model's SDF: model.sdf, else the file model.config names. */
    char sdf[PATH_MAX * 2 + 64];
    if (path_is_file(dir)) snprintf(sdf, sizeof sdf, "%s", dir);
    else {
        snprintf(sdf, sizeof sdf, "%s/model.sdf", dir);
        if (!path_is_file(sdf)) {
            char cfg[PATH_MAX * 2 + 64];
            snprintf(cfg, sizeof cfg, "%s/model.config", dir);
            xmlDocPtr cd = path_is_file(cfg) ? read_xml(c, cfg) : NULL;
            if (cd) {
                text(child(xmlDocGetRootElement(cd), "sdf"), buf, sizeof buf);
                if (buf[0]) snprintf(sdf, sizeof sdf, "%s/%s", dir, buf);
                xmlFreeDoc(cd);
            }
        }
    }
    if (!path_is_file(sdf)) {
        if (c->skip_missing) {
            sp_logf(c->log, SP_LOG_WARN, "%s:%ld: model %s has no model.sdf (%s), skipped", file, line, uri, sdf);
            c->b.w->n_missing++;
            return 0;
        }
        return sp_error_set(c->err, SP_E_NOTFOUND, "%s:%ld: model %s: missing %s", file, line, uri, sdf);
    }
    xmlDocPtr doc = read_xml(c, sdf);
    if (!doc) return c->err ? c->err->code : SP_E_FORMAT;
    xmlNodePtr root = xmlDocGetRootElement(doc);
    xmlNodePtr model = is_elem(root, "model") ? root : child(root, "model");
    int rc = 0;
    if (!model) {
        rc = sp_error_set(c->err, SP_E_FORMAT, "%s: no <model> element (included from %s:%ld)", sdf, file, line);
        goto done;
    }
    /* The included model's name: <name> of the include, else the model's own. */
    text(child(inc, "name"), name, sizeof name);
    char mname[128];
    attr(model, "name", mname, sizeof mname);
    if (!name[0]) snprintf(name, sizeof name, "%s", mname);
    /* Pose: the include's <pose> replaces the model's own. */
    xform pose;
    char rel[256];
    scope world_scope = {.node = NULL, .to_world = xf_identity(), .file = file};
    const scope *ps = parent ? parent : &world_scope;
    if (child(inc, "pose")) {
        if (parent) rc = element_world(c, parent, inc, &pose, 0);
        else {
            xform local;
            rc = pose_of(c, file, inc, &local, rel, sizeof rel);
            pose = local;
        }
    } else {
        xform local;
        rc = pose_of(c, sdf, model, &local, rel, sizeof rel);
        pose = xf_mul(ps->to_world, local);
    }
    if (rc) goto done;
    /* Class source: the model's folder name in the URI (model://dining_chair -> dining_chair). */
    char source[256];
    {
        const char *p = strstr(uri, "://");
        p = p ? p + 3 : uri;
        snprintf(source, sizeof source, "%s", p);
        char *sl = strchr(source, '/');
        if (sl) *sl = 0;
        if (!strncmp(uri, "file://", 7) || !strstr(uri, "://")) snprintf(source, sizeof source, "%s", mname);
    }
    if (obj < 0) {
        obj = new_object(c, name, source, &pose, line);
        if (obj < 0) { rc = obj; goto done; }
    }
    char sdir[PATH_MAX];
    path_dir_of(sdf, sdir, sizeof sdir);
    scope s = {.node = model, .to_world = pose, .file = sdf, .dir = sdir, .obj = obj};
    c->depth++;
    rc = read_model(c, &s);
    c->depth--;
    /* say which include led there: "world:331: model://x: x/model.sdf:24: missing mesh ..." */
    if (rc) sp_error_prefix(c->err, "%s:%ld: %s: ", file, line, uri);
done:
    xmlFreeDoc(doc);
    return rc;
}

static int read_model(ctx *c, const scope *s)
{
    int rc;
    for (xmlNodePtr e = s->node->children; e; e = e->next) {
        if (is_elem(e, "link")) {
            xform lw;
            if ((rc = element_world(c, s, e, &lw, 0))) return rc;
            for (xmlNodePtr v = e->children; v; v = v->next) {
                if (is_elem(v, "visual") && (rc = read_visual(c, s, e, &lw, v))) return rc;
                if (is_elem(v, "light") && (rc = read_light(c, s->file, v, &lw))) return rc;
            }
        } else if (is_elem(e, "model")) {
            scope n = *s;
            n.node = e;
            if ((rc = element_world(c, s, e, &n.to_world, 0))) return rc;
            if ((rc = read_model(c, &n))) return rc;
        } else if (is_elem(e, "include")) {
            if ((rc = read_include(c, s, s->file, e, s->obj))) return rc;
        }
    }
    return 0;
}

/* Class source of a top-level <model>: a model that only wraps an <include> (the bookstore's
 * style) takes the included model's name. */
static void model_source(xmlNodePtr m, const char *name, char *out, size_t cap)
{
    snprintf(out, cap, "%s", name);
    if (child(m, "link")) return;
    xmlNodePtr inc = child(m, "include");
    if (!inc) return;
    char uri[PATH_MAX];
    text(child(inc, "uri"), uri, sizeof uri);
    const char *p = strstr(uri, "://");
    if (!p || strncmp(uri, "model://", 8)) return;
    snprintf(out, cap, "%s", p + 3);
    char *sl = strchr(out, '/');
    if (sl) *sl = 0;
}

/* <light> at world level (base = identity) or inside a link (base = the link's world pose). */
static int read_light(ctx *c, const char *file, xmlNodePtr e, const xform *base)
{
    sp_synth_light l;
    memset(&l, 0, sizeof l);
    char buf[64], rel[256];
    attr(e, "name", l.name, sizeof l.name);
    attr(e, "type", buf, sizeof buf);
    l.type = !strcmp(buf, "directional") ? SP_LIGHT_DIRECTIONAL : !strcmp(buf, "spot") ? SP_LIGHT_SPOT : SP_LIGHT_POINT;
    xform T;
    int rc = pose_of(c, file, e, &T, rel, sizeof rel);
    if (rc) return rc;
    T = xf_mul(*base, T);
    double d[4] = {0, 0, -1, 0}, dif[4] = {1, 1, 1, 1}, wd[3];
    if (child(e, "direction") && (rc = numbers(c, file, child(e, "direction"), 3, 3, d)) < 0) return rc;
    if (child(e, "diffuse") && (rc = numbers(c, file, child(e, "diffuse"), 3, 4, dif)) < 0) return rc;
    xf_apply_dir(&T, d, wd);
    double n = sqrt(wd[0] * wd[0] + wd[1] * wd[1] + wd[2] * wd[2]);
    for (int i = 0; i < 3; i++) {
        l.position[i] = (float)T.m[i * 4 + 3];
        l.direction[i] = (float)(n > 0 ? wd[i] / n : (i == 2 ? -1 : 0));
        l.diffuse[i] = (float)dif[i];
    }
    l.att_constant = 1;
    l.range = 1000;
    xmlNodePtr at = child(e, "attenuation");
    if (at) {
        const char *keys[4] = {"constant", "linear", "quadratic", "range"};
        float *dst[4] = {&l.att_constant, &l.att_linear, &l.att_quadratic, &l.range};
        for (int k = 0; k < 4; k++) {
            double v;
            if (child(at, keys[k])) {
                if ((rc = numbers(c, file, child(at, keys[k]), 1, 1, &v)) < 0) return rc;
                *dst[k] = (float)v;
            }
        }
    }
    l.spot_cos_inner = -1;
    l.spot_cos_outer = -1;
    l.spot_falloff = 1;
    xmlNodePtr sp = child(e, "spot");
    if (l.type == SP_LIGHT_SPOT && sp) {
        double inner = 0, outer = M_PI, fall = 1;
        if (child(sp, "inner_angle") && (rc = numbers(c, file, child(sp, "inner_angle"), 1, 1, &inner)) < 0) return rc;
        if (child(sp, "outer_angle") && (rc = numbers(c, file, child(sp, "outer_angle"), 1, 1, &outer)) < 0) return rc;
        if (child(sp, "falloff") && (rc = numbers(c, file, child(sp, "falloff"), 1, 1, &fall)) < 0) return rc;
        if (outer < inner) outer = inner;
        l.spot_cos_inner = (float)cos(inner);
        l.spot_cos_outer = (float)cos(outer);
        l.spot_falloff = (float)(fall > 0 ? fall : 1);
    }
    rc = wb_light(&c->b, &l);
    return rc < 0 ? sp_error_set(c->err, rc, "out of memory") : 0;
}

static int read_world(ctx *c, const char *file, xmlNodePtr world)
{
    int rc;
    char fdir[PATH_MAX];
    path_dir_of(file, fdir, sizeof fdir);
    for (xmlNodePtr e = world->children; e; e = e->next) {
        if (is_elem(e, "model")) {
            char name[128], source[256], rel[256];
            attr(e, "name", name, sizeof name);
            model_source(e, name, source, sizeof source);
            xform pose;
            if ((rc = pose_of(c, file, e, &pose, rel, sizeof rel))) return rc;
            int obj = new_object(c, name, source, &pose, xmlGetLineNo(e));
            if (obj < 0) return obj;
            scope s = {.node = e, .to_world = pose, .file = file, .dir = fdir, .obj = obj};
            if ((rc = read_model(c, &s))) return rc;
        } else if (is_elem(e, "include")) {
            if ((rc = read_include(c, NULL, file, e, -1))) return rc;
        } else if (is_elem(e, "light")) {
            xform id = xf_identity();
            if ((rc = read_light(c, file, e, &id))) return rc;
        } else if (is_elem(e, "scene")) {
            double v[4];
            if (child(e, "ambient")) {
                if ((rc = numbers(c, file, child(e, "ambient"), 3, 4, v)) < 0) return rc;
                for (int i = 0; i < 3; i++) c->b.w->ambient[i] = (float)v[i];
            }
            if (child(e, "background")) {
                if ((rc = numbers(c, file, child(e, "background"), 3, 4, v)) < 0) return rc;
                for (int i = 0; i < 3; i++) c->b.w->background[i] = (float)v[i];
            }
        }
    }
    return 0;
}

int sp_synth_load_world(const char *path, const sp_synth_load_opts *opts, sp_world *w, sp_error *err)
{
    sp_synth_load_opts def = {0};
    if (!opts) opts = &def;
    if (!path || !w) return sp_error_set(err, SP_E_ARG, "sp_synth_load_world: NULL argument");
    memset(w, 0, sizeof *w);
    ctx *c = calloc(1, sizeof *c);
    if (!c) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    c->err = err;
    c->log = opts->log;
    c->mp.log = opts->log;
    c->skip_missing = opts->skip_missing;
    wb_init(&c->b, w, err);
    c->b.log = opts->log;
    c->b.skip_missing = opts->skip_missing;
    char abs[PATH_MAX];
    if (!realpath(path, abs)) snprintf(abs, sizeof abs, "%s", path);
    snprintf(w->path, sizeof w->path, "%s", abs);

    /* A world's own model folder (<stem>_models, as the house ships) comes first so that
     * generic names ("door", "tv") are not shadowed by other models on GAZEBO_MODEL_PATH. */
    char wdir[PATH_MAX], stem[256], d[PATH_MAX + 300];
    path_dir_of(abs, wdir, sizeof wdir);
    const char *base = strrchr(abs, '/');
    snprintf(stem, sizeof stem, "%s", base ? base + 1 : abs);
    char *dot = strrchr(stem, '.');
    if (dot) *dot = 0;
    snprintf(d, sizeof d, "%s/%s_models", wdir, stem);
    if (path_is_dir(d)) mp_add(&c->mp, d);
    mp_add(&c->mp, opts->model_path);
    if (!opts->no_env) {
        mp_add(&c->mp, getenv("GAZEBO_MODEL_PATH"));
        mp_add(&c->mp, getenv("GZ_SIM_RESOURCE_PATH"));
        mp_add(&c->mp, getenv("IGN_GAZEBO_RESOURCE_PATH"));
    }
    snprintf(d, sizeof d, "%s/models", wdir);
    if (path_is_dir(d)) mp_add(&c->mp, d);
    snprintf(d, sizeof d, "%s/../models", wdir);
    if (path_is_dir(d) && realpath(d, abs)) mp_add(&c->mp, abs);

    int rc = 0;
    xmlDocPtr doc = read_xml(c, w->path);
    if (!doc) {
        rc = err ? err->code : SP_E_FORMAT;
        goto fail;
    }
    xmlNodePtr root = xmlDocGetRootElement(doc);
    if (!is_elem(root, "sdf")) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s:%ld: root element is <%s>, expected <sdf>", w->path,
                          root ? xmlGetLineNo(root) : 0L, root ? (const char *)root->name : "nothing");
        goto fail_doc;
    }
    xmlNodePtr world = child(root, "world");
    if (world) {
        attr(world, "name", w->name, sizeof w->name);
        rc = read_world(c, w->path, world);
    } else if (child(root, "model")) {
        /* A single model file: render it as a world of one model. */
        rc = read_world(c, w->path, root);
        snprintf(w->name, sizeof w->name, "%s", stem);
    } else
        rc = sp_error_set(err, SP_E_FORMAT, "%s:%ld: <sdf> holds no <world> or <model>", w->path,
                          xmlGetLineNo(root));
    if (!rc) rc = wb_finish(&c->b, err);
fail_doc:
    xmlFreeDoc(doc);
fail:
    wb_release(&c->b);
    free(c);
    if (rc) sp_world_free(w);
    return rc;
}
