/* SDF worlds through libxml2 (sp_synth_load_world): never a crash or a hang, a clear error, and a
 * world that loads is consistent (triangles index existing vertices, objects and materials exist,
 * finite geometry) and renders a tiny view with finite colours. Includes resolve against
 * tests/fuzz/fixtures/models (a crate with an OBJ mesh and a texture, a ball); the environment's
 * model paths are ignored. */
#include "fuzz_util.h"
#include "semsplat/synth.h"

static char models[1024];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    fz_source("tests/fuzz/fixtures/models", models);
    return 0;
}

static void check_world(const sp_world *w)
{
    for (size_t t = 0; t < w->n_triangles; t++) {
        for (int k = 0; k < 3; k++) FZ_ASSERT(w->tris[t * 3 + k] < w->n_vertices, "triangle %zu index", t);
        FZ_ASSERT(w->tri_material[t] < w->n_materials, "triangle %zu material", t);
        FZ_ASSERT(w->tri_object[t] < w->n_objects, "triangle %zu object", t);
    }
    for (size_t v = 0; v < w->n_vertices * 3; v++)
        FZ_ASSERT(isfinite(w->positions[v]) && isfinite(w->normals[v]), "vertex %zu is not finite", v / 3);
    for (size_t m = 0; m < w->n_materials; m++)
        FZ_ASSERT(w->materials[m].texture < (int)w->n_textures, "material %zu texture", m);
    FZ_ASSERT(w->n_lights >= 1, "no light");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[1024];
    fz_write("fuzz.world", data, size, path);
    sp_synth_load_opts o = {.model_path = models, .skip_missing = (int)(size & 1), .no_env = 1};
    sp_world w;
    sp_error err = {0};
    int rc = sp_synth_load_world(path, &o, &w, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_synth_load_world");
        return 0;
    }
    check_world(&w);
    if (w.n_triangles <= 20000) {
        sp_camera cam;
        memset(&cam, 0, sizeof cam);
        cam.width = 8, cam.height = 6, cam.fx = cam.fy = 6, cam.cx = 4, cam.cy = 3;
        sp_camera_look_at(&cam, sp_v3(3, -4, 2), sp_v3(0, 0, 0.5f), sp_v3(0, 0, 1));
        sp_synth_render_opts ro = {.supersample = 1};
        sp_synth_frame f = {0};
        rc = sp_synth_render(&w, &cam, &ro, NULL, &f, &err);
        FZ_ASSERT(rc == 0, "render failed: %s", err.msg);
        for (int i = 0; i < 8 * 6 * 3; i++) FZ_ASSERT(isfinite(f.rgb[i]), "pixel %d is not finite", i / 3);
        sp_synth_frame_free(&f);
    }
    sp_world_free(&w);
    return 0;
}
