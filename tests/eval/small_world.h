/* A second small world for evaluation tests, written as SDF text by the test itself so that no
 * heuristic can have been tuned on it: a kitchen and a living room joined by a doorway, with
 * household objects made of boxes and cylinders (a fridge, a counter, a dining table with two
 * chairs, a sofa, a television on a stand, a bookshelf, a floor lamp, a potted plant). The
 * refrigerator's position is a parameter, so a test can move it and watch the ground truth and
 * the error follow. */
#ifndef SP_TEST_SMALL_WORLD_H
#define SP_TEST_SMALL_WORLD_H

#include <stdio.h>

/* Rooms: kitchen x in [0, 4], living room x in [4, 9], y in [0, 4]; a wall at x = 4 with a
 * doorway at y in [1.5, 2.7]. */
#define SMALL_WORLD_FRIDGE_X 0.45
#define SMALL_WORLD_FRIDGE_Y 3.5

static inline void small_world_box(FILE *f, const char *name, double x, double y, double z,
                                   double yaw, double sx, double sy, double sz, const char *rgb)
{
    fprintf(f,
            "<model name='%s'><static>true</static><pose>%g %g %g 0 0 %g</pose><link name='l'>"
            "<visual name='v'><pose>0 0 %g 0 0 0</pose><geometry><box><size>%g %g %g</size></box>"
            "</geometry><material><diffuse>%s 1</diffuse></material></visual></link></model>\n",
            name, x, y, z, yaw, sz / 2, sx, sy, sz, rgb);
}

static inline void small_world_cyl(FILE *f, const char *name, double x, double y, double r, double h,
                                   const char *rgb)
{
    fprintf(f,
            "<model name='%s'><static>true</static><pose>%g %g 0 0 0 0</pose><link name='l'>"
            "<visual name='v'><pose>0 0 %g 0 0 0</pose><geometry><cylinder><radius>%g</radius>"
            "<length>%g</length></cylinder></geometry><material><diffuse>%s 1</diffuse></material>"
            "</visual></link></model>\n",
            name, x, y, h / 2, r, h, rgb);
}

/* Writes the world to path with the refrigerator's footprint centred at (fx, fy). Returns 0. */
static inline int small_world_write(const char *path, double fx, double fy)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "<?xml version='1.0'?>\n<sdf version='1.6'><world name='small_flat'>\n"
               "<light name='sun' type='directional'><direction>-0.4 0.2 -0.9</direction>"
               "<diffuse>0.9 0.9 0.85 1</diffuse></light>\n");
    fprintf(f, "<model name='floor'><static>true</static><link name='l'><visual name='v'>"
               "<pose>4.5 2 -0.01 0 0 0</pose><geometry><box><size>9 4 0.02</size></box></geometry>"
               "<material><script><name>Gazebo/WoodFloor</name></script></material></visual></link></model>\n");
    fprintf(f, "<model name='walls'><static>true</static><link name='l'>\n");
    const double w[][4] = {/* x, y, sx, sy */
                           {4.5, 0, 9, 0.1}, {4.5, 4, 9, 0.1}, {0, 2, 0.1, 4}, {9, 2, 0.1, 4},
                           {4, 0.75, 0.1, 1.5}, {4, 3.35, 0.1, 1.3}};
    for (int i = 0; i < 6; i++)
        fprintf(f, "<visual name='w%d'><pose>%g %g 1.25 0 0 0</pose><geometry><box><size>%g %g 2.5</size>"
                   "</box></geometry><material><diffuse>0.85 0.83 0.78 1</diffuse></material></visual>\n",
                i, w[i][0], w[i][1], w[i][2], w[i][3]);
    fprintf(f, "</link></model>\n");
    /* kitchen */
    small_world_box(f, "refrigerator", fx, fy, 0, 0, 0.7, 0.7, 1.8, "0.92 0.92 0.95");
    small_world_box(f, "kitchen_counter", 2.2, 3.65, 0, 0, 2.4, 0.6, 0.9, "0.55 0.42 0.30");
    small_world_box(f, "dining_table", 2.0, 1.3, 0, 0, 1.4, 0.8, 0.75, "0.45 0.30 0.18");
    small_world_box(f, "chair_1", 1.2, 1.3, 0, 0, 0.45, 0.45, 0.9, "0.30 0.25 0.20");
    small_world_box(f, "chair_2", 2.8, 1.3, 0, 3.14159, 0.45, 0.45, 0.9, "0.30 0.25 0.20");
    /* living room */
    small_world_box(f, "sofa", 6.5, 3.45, 0, 0, 2.0, 0.85, 0.8, "0.25 0.35 0.55");
    small_world_box(f, "tv_stand", 6.5, 0.35, 0, 0, 1.4, 0.45, 0.5, "0.20 0.20 0.22");
    small_world_box(f, "television", 6.5, 0.35, 0.5, 0, 1.1, 0.08, 0.65, "0.05 0.05 0.06");
    small_world_box(f, "bookshelf", 8.75, 1.8, 0, 0, 0.35, 1.2, 1.9, "0.50 0.35 0.20");
    small_world_cyl(f, "floor_lamp", 8.5, 3.5, 0.15, 1.6, "0.90 0.85 0.60");
    small_world_cyl(f, "potted_plant", 4.5, 0.4, 0.22, 0.9, "0.20 0.55 0.25");
    fprintf(f, "</world></sdf>\n");
    return fclose(f) == 0 ? 0 : -1;
}

#endif
