/* synth world loading: class names, poses (nested models, includes, relative_to), meshes (.obj
 * and .dae with <scale> and COLLADA units), and the errors for broken or incomplete worlds. */
#include "semsplat/synth.h"
#include "test.h"

static void put(const char *dir, const char *name, const char *text)
{
    char p[1400];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    char d[1400];
    snprintf(d, sizeof d, "%s", p);
    char *s = strrchr(d, '/');
    *s = 0;
    char cmd[1500];
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", d);
    if (system(cmd) != 0) fprintf(stderr, "mkdir failed\n");
    FILE *f = fopen(p, "w");
    fputs(text, f);
    fclose(f);
}

/* Loads DIR/w.world with DIR/models as the model path (no environment variables). */
static int load_dir_world(const char *d, sp_world *w, sp_error *err)
{
    char path[1200], mp[1200];
    snprintf(path, sizeof path, "%s/w.world", d);
    snprintf(mp, sizeof mp, "%s/models", d);
    sp_synth_load_opts o = {.model_path = mp, .no_env = 1};
    return sp_synth_load_world(path, &o, w, err);
}

static const sp_synth_object *find(const sp_world *w, const char *name)
{
    for (size_t i = 0; i < w->n_objects; i++)
        if (!strcmp(w->objects[i].name, name)) return &w->objects[i];
    return NULL;
}

static void check_box(const sp_synth_object *o, double x0, double y0, double z0, double x1, double y1,
                      double z1)
{
    CHECK(o != NULL);
    if (!o) return;
    CHECK_NEAR(o->aabb_min[0], x0, 1e-4);
    CHECK_NEAR(o->aabb_min[1], y0, 1e-4);
    CHECK_NEAR(o->aabb_min[2], z0, 1e-4);
    CHECK_NEAR(o->aabb_max[0], x1, 1e-4);
    CHECK_NEAR(o->aabb_max[1], y1, 1e-4);
    CHECK_NEAR(o->aabb_max[2], z1, 1e-4);
}

static void test_class_names(void)
{
    struct { const char *in, *out; } cases[] = {
        {"aws_robomaker_retail_BookshelfB_01", "bookshelf"},
        {"dining_table_2", "dining table"},
        {"dining_chair_1", "dining chair"},
        {"aws_robomaker_retail_AirConditionerC_01", "air conditioner"},
        {"aws_robomaker_residential_Refrigerator_01", "refrigerator"},
        {"aws_robomaker_retail_RetailShopWall_01", "wall"},
        {"aws_robomaker_retail_InfoDesk_01", "info desk"},
        {"TVStand", "tv stand"},
        {"kitchen_counter", "kitchen counter"},
        {"tv", "tv"},
        {"BookE_01_003", "book"},
        {"box_7", "box"},
        {"unit_box", "unit box"},
        {"aws_01", "aws"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char out[128];
        sp_synth_class_name(cases[i].in, out, sizeof out);
        CHECK_MSG(!strcmp(out, cases[i].out), "%s -> '%s', expected '%s'", cases[i].in, out, cases[i].out);
    }
    CHECK(sp_synth_is_structure("walls", "walls"));
    CHECK(sp_synth_is_structure("ground_plane", "ground plane"));
    CHECK(sp_synth_is_structure("Floor_3", "floor"));
    CHECK(sp_synth_is_structure("RetailShopWall_01_001", "wall"));
    CHECK(!sp_synth_is_structure("standing_lamp", "standing lamp"));
    CHECK(!sp_synth_is_structure("lamp_1", "floor lamp"));
    CHECK(!sp_synth_is_structure("window_1", "window"));
    /* Modifiers are not heads: the furniture named after where it stands or hangs is an object
     * (each with the class name the loader gives it, so the model name is what decides). */
    const char *objects[] = {"floor_lamp", "FloorLamp_01", "wall_clock", "ceiling_fan", "WallShelf_2",
                             "groundskeeper_cart", "ceiling_light_3", "floor_mat", "wall_art_1", "aws_robomaker_retail_Spotlight_01"};
    const char *structure[] = {"floor", "Floor_3", "walls", "Wall_12", "kitchen_floor", "ceiling", "ceilings",
                               "ground_plane", "ground", "aws_robomaker_retail_RetailShopCeiling_01",
                               "RetailShopWall_01_001", "floor_plane", "WoodFloor"};
    for (size_t i = 0; i < sizeof objects / sizeof *objects; i++) {
        char cls[128];
        sp_synth_class_name(objects[i], cls, sizeof cls);
        CHECK_MSG(!sp_synth_is_structure(objects[i], cls), "%s ('%s') classed as structure", objects[i], cls);
    }
    for (size_t i = 0; i < sizeof structure / sizeof *structure; i++) {
        char cls[128];
        sp_synth_class_name(structure[i], cls, sizeof cls);
        CHECK_MSG(sp_synth_is_structure(structure[i], cls), "%s ('%s') not classed as structure", structure[i], cls);
    }
    /* an include named after its place keeps its model's class: a lamp included as floor_lamp_2 */
    CHECK(!sp_synth_is_structure("floor_lamp_2", "lamp"));
    CHECK(sp_synth_is_structure("north_wall", "box"));
}

static const char *crate_sdf =
    "<?xml version='1.0'?>\n<sdf version='1.6'>\n<model name='crate'>\n"
    "  <pose>0 0 0.5 0 0 0</pose>\n"
    "  <link name='l'><visual name='v'><geometry><box><size>1 2 1</size></box></geometry></visual></link>\n"
    "</model>\n</sdf>\n";

static void test_poses_and_includes(void)
{
    const char *d = test_tmpdir("synth_world_poses");
    put(d, "models/crate/model.sdf", crate_sdf);
    put(d, "w.world",
        "<?xml version='1.0'?>\n<sdf version='1.6'><world name='t'>\n"
        /* include: the include's pose replaces the model's own (z 0.5 is dropped) */
        "<include><uri>model://crate</uri><name>crate_2</name><pose>3 0 0 0 0 1.5707963267948966</pose></include>\n"
        /* include without a pose keeps the model's own */
        "<include><uri>model://crate</uri><name>crate_3</name></include>\n"
        /* the bookstore style: a model wrapping an include */
        "<model name='wrapped_1'><pose>0 5 0 0 0 0</pose><include><uri>model://crate</uri></include></model>\n"
        /* nested models, link and visual poses, relative_to a frame */
        "<model name='shelf_4'><pose>10 0 0 0 0 0</pose>\n"
        "  <frame name='f'><pose>1 0 0 0 0 0</pose></frame>\n"
        "  <link name='a'><pose relative_to='f'>0 1 0 0 0 0</pose>\n"
        "    <visual name='v'><pose>0 0 0.25 0 0 0</pose><geometry><box><size>0.5 0.5 0.5</size></box></geometry></visual>\n"
        "  </link>\n"
        "  <model name='inner'><pose>0 0 2 0 0 0</pose><link name='b'><visual name='v'>"
        "<geometry><sphere><radius>0.5</radius></sphere></geometry></visual></link></model>\n"
        "</model>\n"
        "<model name='ground_plane'><link name='l'><visual name='v'><geometry><plane><normal>0 0 1</normal>"
        "<size>4 6</size></plane></geometry></visual></link></model>\n"
        "<light name='sun' type='directional'><direction>0 0 -1</direction><diffuse>0.5 0.5 0.5 1</diffuse></light>\n"
        "</world></sdf>\n");
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load_dir_world(d, &w, &err), &err);
    CHECK(w.n_objects == 5);
    CHECK(w.n_lights == 1);
    /* rotated 90 degrees about z: the 1 x 2 footprint becomes 2 x 1 */
    check_box(find(&w, "crate_2"), 2, -0.5, -0.5, 4, 0.5, 0.5);
    check_box(find(&w, "crate_3"), -0.5, -1, 0, 0.5, 1, 1);
    check_box(find(&w, "wrapped_1"), -0.5, 4, 0, 0.5, 6, 1);
    const sp_synth_object *s = find(&w, "shelf_4");
    check_box(s, 9.5, -0.5, 0, 11.25, 1.25, 2.5); /* box at (11,1,.25) and sphere at (10,0,2) */
    CHECK(s && !strcmp(s->class_name, "shelf"));
    CHECK(!strcmp(find(&w, "crate_2")->class_name, "crate"));
    CHECK(!strcmp(find(&w, "wrapped_1")->class_name, "crate"));
    CHECK(!strcmp(find(&w, "wrapped_1")->source, "crate"));
    CHECK(find(&w, "ground_plane")->is_structure);
    CHECK(!find(&w, "crate_2")->is_structure);
    check_box(find(&w, "ground_plane"), -2, -3, 0, 2, 3, 0);
    CHECK_NEAR(find(&w, "crate_2")->pose[3], 3, 1e-6);
    sp_world_free(&w);
}

/* A 1 m x 2 m quad in centimetres, Z up. */
static const char *quad_dae =
    "<?xml version='1.0' encoding='utf-8'?>\n"
    "<COLLADA xmlns='http://www.collada.org/2005/11/COLLADASchema' version='1.4.1'>\n"
    "<asset><unit meter='0.01' name='centimeter'/><up_axis>Z_UP</up_axis></asset>\n"
    "<library_geometries><geometry id='g' name='g'><mesh>\n"
    "<source id='g-pos'><float_array id='g-pos-a' count='12'>0 0 0 100 0 0 100 200 0 0 200 0</float_array>\n"
    "<technique_common><accessor source='#g-pos-a' count='4' stride='3'><param name='X' type='float'/>"
    "<param name='Y' type='float'/><param name='Z' type='float'/></accessor></technique_common></source>\n"
    "<vertices id='g-vtx'><input semantic='POSITION' source='#g-pos'/></vertices>\n"
    "<triangles count='2'><input semantic='VERTEX' source='#g-vtx' offset='0'/><p>0 1 2 0 2 3</p></triangles>\n"
    "</mesh></geometry></library_geometries>\n"
    "<library_visual_scenes><visual_scene id='s'><node id='n'><instance_geometry url='#g'/></node>"
    "</visual_scene></library_visual_scenes>\n<scene><instance_visual_scene url='#s'/></scene>\n</COLLADA>\n";

static const char *cube_obj =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

static void test_meshes(void)
{
    const char *d = test_tmpdir("synth_world_mesh");
    put(d, "models/quad/meshes/quad.dae", quad_dae);
    put(d, "models/quad/model.sdf",
        "<sdf version='1.6'><model name='quad'><link name='l'><visual name='v'><geometry><mesh>"
        "<uri>model://quad/meshes/quad.dae</uri><scale>2 1 1</scale></mesh></geometry></visual></link></model></sdf>");
    put(d, "meshes/cube.obj", cube_obj);
    put(d, "w.world",
        "<sdf version='1.6'><world name='m'>\n"
        "<include><uri>model://quad</uri><name>quad_1</name><pose>5 0 0 0 0 0</pose></include>\n"
        "<model name='cube'><pose>1 2 3 0 0 1.5707963267948966</pose><link name='l'><visual name='v'><geometry><mesh>"
        "<uri>meshes/cube.obj</uri><scale>1 2 3</scale></mesh></geometry></visual></link></model>\n"
        "</world></sdf>\n");
    sp_world w;
    sp_error err = {0};
    CHECK_OK(load_dir_world(d, &w, &err), &err);
    /* centimetres -> metres, then <scale> 2 along x, then the pose */
    check_box(find(&w, "quad_1"), 5, 0, 0, 7, 2, 0);
    CHECK(find(&w, "quad_1") && find(&w, "quad_1")->n_triangles == 2);
    /* yaw 90: the y extent (2) lies along x */
    check_box(find(&w, "cube"), 0, 1.5, 1.5, 2, 2.5, 4.5);
    CHECK(find(&w, "cube") && find(&w, "cube")->n_triangles == 12);
    sp_world_free(&w);
}

static void test_errors(void)
{
    const char *d = test_tmpdir("synth_world_errors");
    char path[1200], mp[1200];
    sp_world w;
    sp_error err = {0};
    sp_synth_load_opts o = {.no_env = 1};
    /* malformed XML: the line is named */
    put(d, "bad.world", "<?xml version='1.0'?>\n<sdf version='1.6'>\n<world name='x'>\n<model name='a'>\n</world>\n</sdf>\n");
    snprintf(path, sizeof path, "%s/bad.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_FORMAT, &err, "bad.world:5");
    /* a bad number names file, line and element */
    put(d, "num.world", "<sdf version='1.6'><world name='x'>\n<model name='a'>\n<pose>1 2 x 0 0 0</pose>\n</model></world></sdf>\n");
    snprintf(path, sizeof path, "%s/num.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_FORMAT, &err, "num.world:3: <pose>");
    /* not SDF */
    put(d, "html.world", "<html></html>\n");
    snprintf(path, sizeof path, "%s/html.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_FORMAT, &err, "expected <sdf>");
    /* missing file */
    snprintf(path, sizeof path, "%s/nope.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_IO, &err, "nope.world");
    /* a model the path does not have */
    put(d, "inc.world", "<sdf version='1.6'><world name='x'>\n\n<include><uri>model://no_such_model</uri></include>\n</world></sdf>\n");
    snprintf(path, sizeof path, "%s/inc.world", d);
    snprintf(mp, sizeof mp, "%s/models", d);
    o.model_path = mp;
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_NOTFOUND, &err, "model://no_such_model");
    CHECK(strstr(err.msg, "inc.world:3") != NULL);
    /* a missing mesh names the mesh; --skip-missing goes on */
    put(d, "mesh.world",
        "<sdf version='1.6'><world name='x'><model name='m'><link name='l'><visual name='v'><geometry>\n"
        "<mesh><uri>meshes/gone.dae</uri></mesh></geometry></visual></link></model>\n"
        "<model name='b'><link name='l'><visual name='v'><geometry><box><size>1 1 1</size></box></geometry></visual></link></model>\n"
        "</world></sdf>\n");
    snprintf(path, sizeof path, "%s/mesh.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_NOTFOUND, &err, "meshes/gone.dae");
    o.skip_missing = 1;
    CHECK_OK(sp_synth_load_world(path, &o, &w, &err), &err);
    CHECK(w.n_missing == 1 && w.n_objects == 2 && w.n_triangles == 12);
    sp_world_free(&w);
    /* a mesh file that is not a mesh */
    put(d, "junk/junk.dae", "this is not collada");
    put(d, "junk.world", "<sdf version='1.6'><world name='x'><model name='m'><link name='l'><visual name='v'><geometry>"
                         "<mesh><uri>junk/junk.dae</uri></mesh></geometry></visual></link></model></world></sdf>\n");
    snprintf(path, sizeof path, "%s/junk.world", d);
    o.skip_missing = 0;
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_FORMAT, &err, "junk.dae");
    /* a COLLADA file that crashes assimp 5.2 (float_array count 0 under an accessor; found by
     * tests/fuzz/fuzz_mesh.c): the importer's crash is an error naming the mesh */
    char crash[1200], *dae = NULL;
    size_t dae_size = 0;
    snprintf(crash, sizeof crash, "%s/tests/fuzz/corpus/mesh/crash-collada-float-array-count0", SP_SOURCE_DIR);
    CHECK_OK(sp_read_file(crash, &dae, &dae_size, &err), &err);
    if (dae) {
        put(d, "crash/crash.dae", dae + 1); /* the fuzz input's first byte picks the format */
        free(dae);
    }
    put(d, "crash.world", "<sdf version='1.6'><world name='x'><model name='m'><link name='l'><visual name='v'><geometry>"
                          "<mesh><uri>crash/crash.dae</uri></mesh></geometry></visual></link></model></world></sdf>\n");
    snprintf(path, sizeof path, "%s/crash.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_FORMAT, &err, "crash.dae");
    CHECK(strstr(err.msg, "assimp crashed") != NULL);
    /* relative_to naming nothing */
    put(d, "rel.world", "<sdf version='1.6'><world name='x'><model name='m'>\n<link name='l'><pose relative_to='nowhere'>0 0 0 0 0 0</pose></link></model></world></sdf>\n");
    snprintf(path, sizeof path, "%s/rel.world", d);
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_FORMAT, &err, "nowhere");
}

/* The bookstore (data/worlds/bookstore, MISSING.txt) lacks one texture and one mesh: the texture
 * is not an error (that mesh is drawn in its colour), the mesh is, until skip_missing. */
static void test_bookstore_missing_assets(void)
{
    char path[1200], mp[1200];
    snprintf(path, sizeof path, "%s/data/worlds/bookstore/worlds/bookstore.world", SP_SOURCE_DIR);
    snprintf(mp, sizeof mp, "%s/data/worlds/bookstore/models", SP_SOURCE_DIR);
    sp_world w;
    sp_error err = {0};
    sp_synth_load_opts o = {.model_path = mp, .no_env = 1};
    CHECK_FAILS(sp_synth_load_world(path, &o, &w, &err), SP_E_NOTFOUND, &err, "aws_BookshelfA_01_visual.DAE");
    CHECK_MSG(strstr(err.msg, "missing mesh") != NULL, "%s", err.msg);
    o.skip_missing = 1;
    sp_error_clear(&err);
    CHECK_OK(sp_synth_load_world(path, &o, &w, &err), &err);
    if (err.code) return;
    /* the one missing mesh is BookshelfA's, included four times; the texture is the clock's */
    CHECK_MSG(w.n_missing == 4 && w.n_missing_textures == 1, "%zu assets skipped, %zu textures missing",
              w.n_missing, w.n_missing_textures);
    const sp_synth_object *clock = NULL;
    for (size_t i = 0; i < w.n_objects; i++)
        if (!strcmp(w.objects[i].class_name, "horologe")) clock = &w.objects[i];
    CHECK(clock && clock->n_triangles > 0 && !clock->is_structure);
    sp_world_free(&w);
}

static void test_house_loads(void)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    sp_world w;
    sp_error err = {0};
    sp_synth_load_opts o = {.no_env = 1};
    CHECK_OK(sp_synth_load_world(path, &o, &w, &err), &err);
    const char *want[] = {"refrigerator", "kitchen counter", "stove", "sink", "couch", "armchair", "tv",
                          "coffee table", "bookshelf", "dining table", "dining chair", "bed", "wardrobe",
                          "window", "door"};
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
        int n = 0;
        for (size_t i = 0; i < w.n_objects; i++) n += !strcmp(w.objects[i].class_name, want[k]) && !w.objects[i].is_structure;
        CHECK_MSG(n >= 1, "house has no '%s'", want[k]);
        if (!strcmp(want[k], "dining chair")) CHECK(n >= 4);
    }
    /* about 10 m x 8 m */
    const sp_synth_object *fl = find(&w, "floor");
    CHECK(fl && fl->is_structure);
    if (fl) {
        CHECK_NEAR(fl->aabb_max[0] - fl->aabb_min[0], 10, 0.5);
        CHECK_NEAR(fl->aabb_max[1] - fl->aabb_min[1], 8, 0.5);
    }
    sp_world_free(&w);
}

int main(void)
{
    RUN(test_class_names);
    RUN(test_poses_and_includes);
    RUN(test_meshes);
    RUN(test_errors);
    RUN(test_house_loads);
    RUN(test_bookstore_missing_assets);
    return TEST_EXIT();
}
