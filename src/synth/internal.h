/* Private to src/synth: the world builder shared by the SDF reader (sdf.c), the primitive and
 * mesh tessellators (build.c, mesh.c), and the small double-precision pose algebra they use. */
#ifndef SP_SYNTH_INTERNAL_H
#define SP_SYNTH_INTERNAL_H

#include "semsplat/synth.h"

#include <limits.h>

/* Row-major 4x4 rigid (or scaled) transform in double: x_parent = M x_child. */
typedef struct { double m[16]; } xform;

xform xf_identity(void);
xform xf_mul(xform a, xform b);
/* SDF pose "x y z roll pitch yaw": R = Rz(yaw) Ry(pitch) Rx(roll). */
xform xf_from_pose(const double p[6]);
void xf_apply(const xform *a, const double in[3], double out[3]);
void xf_apply_dir(const xform *a, const double in[3], double out[3]);

/* A mesh file as assimp reads it, flattened: triangles in the file's root frame, one part per
 * assimp mesh, with its material's diffuse colour and texture name. Imported in a child process
 * (mesh_import.c): an assimp crash or hang on a malformed file becomes an error naming it. */
typedef struct mesh_material {
    int has_diffuse;
    float diffuse[3];
    char texture[1024]; /* "" = none; "*N" = embedded (not used) */
} mesh_material;

typedef struct mesh_part {
    uint32_t n_vertices, n_faces;
    uint32_t material; /* index into materials; out of range = none */
    float *pos;        /* [n_vertices][3] */
    float *nrm;        /* [n_vertices][3] or NULL */
    float *uv;         /* [n_vertices][2] or NULL */
    uint32_t *tris;    /* [n_faces][3], each < n_vertices (checked) */
} mesh_part;

typedef struct mesh_data {
    uint32_t n_materials, n_parts;
    mesh_material *materials;
    mesh_part *parts;
} mesh_data;

int mesh_import(const char *path, mesh_data *m, sp_error *err);
void mesh_data_free(mesh_data *m);

/* Meshes imported so far, by path: a model included many times is imported once. */
typedef struct mesh_cache_entry {
    char path[PATH_MAX];
    mesh_data data;
} mesh_cache_entry;

typedef struct wbuild {
    sp_world *w;
    size_t cap_v, cap_t, cap_m, cap_tex, cap_o, cap_l, cap_c;
    const sp_log *log;
    int skip_missing;
    mesh_cache_entry *meshes;
    size_t n_meshes, cap_meshes;
} wbuild;

int wb_init(wbuild *b, sp_world *w, sp_error *err);
/* Frees what the builder holds besides the world (the mesh cache); the world stays. */
void wb_release(wbuild *b);
/* Appends a vertex; returns its index or -1 when out of memory. pattern = object-local point. */
long wb_vertex(wbuild *b, const double pos[3], const double nrm[3], const double uv[2],
               const double pattern[3]);
int wb_triangle(wbuild *b, long a, long c, long d, int material, int object);
int wb_material(wbuild *b, const sp_synth_material *m);
/* Texture by path, loaded once (cached by path). Returns index, or negative SP_E_*. */
int wb_texture(wbuild *b, const char *path, sp_error *err);
int wb_object(wbuild *b, const sp_synth_object *o);
int wb_light(wbuild *b, const sp_synth_light *l);
/* Starts / ends a chunk around the triangles added in between. */
void wb_chunk_begin(wbuild *b, size_t *mark);
int wb_chunk_end(wbuild *b, size_t mark);
/* Finishes: tri_axis, object AABBs, default light. */
int wb_finish(wbuild *b, sp_error *err);

/* Geometry emitters: `to_world` maps the visual frame to world; material and object indices. */
int geom_box(wbuild *b, const xform *to_world, const double size[3], int mat, int obj);
int geom_cylinder(wbuild *b, const xform *to_world, double radius, double length, int mat, int obj);
int geom_sphere(wbuild *b, const xform *to_world, double radius, int mat, int obj);
int geom_plane(wbuild *b, const xform *to_world, const double normal[3], const double size[2],
               int mat, int obj);
/* Loads a mesh file through assimp; `fallback` is the SDF material (used where the mesh has no
 * texture and sdf_material_set). A missing texture is a warning (the material colour is used). */
int geom_mesh(wbuild *b, const xform *to_world, const char *path, const double scale[3],
              const sp_synth_material *fallback, int sdf_material_set, int obj, sp_error *err);

/* The model path: folders searched for model://NAME, in order. */
#define SYNTH_MAX_DIRS 32
typedef struct model_path {
    char dirs[SYNTH_MAX_DIRS][PATH_MAX];
    int n;
    const sp_log *log;
} model_path;

int path_is_dir(const char *p);
int path_is_file(const char *p);
void path_dir_of(const char *path, char *out, size_t cap); /* "." when there is no slash */
/* Appends the folders of a ':'-separated list (duplicates dropped). */
void mp_add(model_path *mp, const char *list);
/* The folders as "a, b, c" for messages. */
void mp_list(const model_path *mp, char *out, size_t cap);
/* model://NAME[/rest] (or package://) -> NAME's folder + rest; 0 or SP_E_NOTFOUND. */
int mp_resolve_model(const model_path *mp, const char *uri, char *out, size_t cap);
/* A mesh or texture URI -> an existing file; 0 or SP_E_NOTFOUND (out: the main candidate). */
int mp_resolve_file(const model_path *mp, const char *uri, const char *sdf_dir, char *out, size_t cap);

/* Picks a procedural pattern from a Gazebo script name or visual/model names. */
int pattern_from_names(const char *script, const char *visual, const char *link,
                       const char *model);

/* Planners (plan.c, drive.c): the free floor's clearance (metres to the nearest obstacle or
 * floor edge, robot height band) on a grid; SP_E_NOTFOUND when there is no floor. */
int synth_floor_clearance(const sp_world *w, sp_grid2 *clear, sp_error *err);
/* Farthest-point sampling on a clearance grid (plan.c's walk, drive_route.c): k cells into out,
 * the first at `first`, each next the candidate (mind >= 0 on entry: INFINITY = a candidate, -1
 * = excluded) farthest from those picked, its distance weighted by its clearance capped at
 * 0.8 m (plain FPS would pick the corners; a hard clearance cut would skip furnished rooms whose
 * free floor is narrow). mind is scratch [cells]. */
void synth_farthest_points(const sp_grid2 *g, float *mind, size_t first, int k, size_t *out);
/* A drive's route (drive_route.c): points in order, each a waypoint where the robot spins
 * (stop) or a corner between straight legs; jump marks the start of a new segment (a part of
 * the floor no path reaches from the previous one). */
typedef struct drive_route {
    size_t n;
    float *xy;     /* [n][2] world metres */
    uint8_t *stop; /* [n] */
    uint8_t *jump; /* [n] */
    int n_waypoints, n_segments;
    double reachable_fraction; /* free cells in the largest part / all free cells */
} drive_route;
/* Plans the route over the cells with clearance >= need, at most max_waypoints waypoints. */
int drive_plan_route(const sp_grid2 *clear, float need, int max_waypoints, drive_route *r,
                     sp_error *err);
void drive_route_free(drive_route *r);
/* capture.json: the plan (sp_synth_plan_info) and the capture's settings (capture_info.c). */
int synth_write_capture_json(const char *out_dir, const sp_world *w,
                             const sp_synth_capture_opts *o, const sp_synth_plan_info *info,
                             sp_error *err);
/* A capture camera (opts' size, fov_deg horizontal) at (x, y, z) looking along yaw, pitch up. */
void synth_view(sp_camera *c, const sp_synth_capture_opts *o, float fov_deg, float x, float y,
                float z, float yaw, float pitch);

#endif
