/* Mesh files through assimp and our mesh reader (geom_mesh, as an SDF <mesh> visual loads them):
 * the first byte picks the format ('o' OBJ, 's' STL, 'd' COLLADA .dae; others byte % 3), the
 * rest is the file. Never a crash, a clear error, and what loads is consistent (triangles index
 * existing vertices, finite positions). Assimp runs in a child process (src/synth/mesh_import.c)
 * since it crashes on some malformed files; it is not instrumented, so libFuzzer sees coverage of
 * our side only (the flattened scene's checks and the world builder). The scratch folder has m.mtl (map_Kd tex.png) and tex.png, so
 * meshes that name them load a texture. */
#include "fuzz_util.h"
#include "semsplat/io.h"
#include "synth/internal.h"

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    char p[1024];
    static const char mtl[] = "newmtl m\nKd 0.8 0.6 0.4\nmap_Kd tex.png\n";
    fz_write("m.mtl", mtl, sizeof mtl - 1, p);
    uint8_t px[4 * 4 * 3];
    for (int i = 0; i < 48; i++) px[i] = (uint8_t)(i * 5);
    sp_image img = {4, 4, 3, 8, px};
    sp_error err = {0};
    if (sp_image_write_png(fz_path("tex.png", p), &img, &err)) {
        fprintf(stderr, "fuzz: %s\n", err.msg);
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    const char *ext = data[0] == 'o' ? "obj" : data[0] == 's' ? "stl" : data[0] == 'd' ? "dae"
                    : data[0] % 3 == 0 ? "obj" : data[0] % 3 == 1 ? "stl" : "dae";
    char name[16], path[1024];
    snprintf(name, sizeof name, "mesh.%s", ext);
    fz_write(name, data + 1, size - 1, path);
    sp_world w;
    wbuild b;
    sp_error err = {0};
    memset(&w, 0, sizeof w);
    wb_init(&b, &w, &err);
    b.skip_missing = 1;
    sp_synth_object o = {.name = "m", .source = "m", .class_name = "m"};
    FZ_ASSERT(wb_object(&b, &o) == 0, "wb_object");
    sp_synth_material fallback = {.diffuse = {0.5f, 0.5f, 0.5f}, .ambient = {0.5f, 0.5f, 0.5f}, .texture = -1};
    xform T = xf_identity();
    double scale[3] = {1, 1, 1};
    int rc = geom_mesh(&b, &T, path, scale, &fallback, 0, 0, &err);
    if (rc) {
        fz_check_error(rc, &err, "geom_mesh");
    } else {
        rc = wb_finish(&b, &err);
        FZ_ASSERT(rc == 0, "wb_finish: %s", err.msg);
        for (size_t t = 0; t < w.n_triangles * 3; t++)
            FZ_ASSERT(w.tris[t] < w.n_vertices, "triangle %zu indexes vertex %u of %zu", t / 3, w.tris[t], w.n_vertices);
        for (size_t v = 0; v < w.n_vertices * 3; v++) FZ_ASSERT(isfinite(w.positions[v]), "vertex %zu", v / 3);
    }
    wb_release(&b);
    sp_world_free(&w);
    return 0;
}
