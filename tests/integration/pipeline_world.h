/* A small world for the pipeline tests: one room, two crates and a table (classes "crate" and
 * "table"), written to a file. Renders in well under a second at the sizes the tests use. */
#ifndef SP_TEST_PIPELINE_WORLD_H
#define SP_TEST_PIPELINE_WORLD_H

#include <stdio.h>

#include "test.h"

static const char *pipeline_world_sdf =
    "<sdf version='1.6'><world name='room'>\n"
    "<model name='floor'><link name='l'><visual name='v'><pose>2 1.5 -0.01 0 0 0</pose><geometry><box><size>4 3 0.02</size></box></geometry>"
    "<material><script><name>Gazebo/WoodFloor</name></script></material></visual></link></model>\n"
    "<model name='walls'><link name='l'>\n"
    "<visual name='s'><pose>2 0 1.2 0 0 0</pose><geometry><box><size>4 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='n'><pose>2 3 1.2 0 0 0</pose><geometry><box><size>4 0.1 2.4</size></box></geometry></visual>\n"
    "<visual name='w'><pose>0 1.5 1.2 0 0 0</pose><geometry><box><size>0.1 3 2.4</size></box></geometry></visual>\n"
    "<visual name='e'><pose>4 1.5 1.2 0 0 0</pose><geometry><box><size>0.1 3 2.4</size></box></geometry></visual>\n"
    "</link></model>\n"
    "<model name='table_1'><pose>1.0 2.1 0 0 0 0.3</pose><link name='l'><visual name='top'><pose>0 0 0.7 0 0 0</pose>"
    "<geometry><box><size>0.9 0.6 0.06</size></box></geometry><material><diffuse>0.6 0.4 0.2 1</diffuse></material></visual>"
    "<visual name='leg'><pose>0 0 0.35 0 0 0</pose><geometry><cylinder><radius>0.06</radius><length>0.7</length></cylinder></geometry></visual>"
    "</link></model>\n"
    "<model name='crate_1'><pose>3.0 0.8 0.25 0 0 0</pose><link name='l'><visual name='v'><geometry><box><size>0.5 0.5 0.5</size></box></geometry>"
    "<material><diffuse>0.1 0.3 0.9 1</diffuse></material></visual></link></model>\n"
    "<model name='crate_2'><pose>3.1 2.2 0.25 0 0 0.5</pose><link name='l'><visual name='v'><geometry><box><size>0.5 0.5 0.5</size></box></geometry>"
    "<material><diffuse>0.8 0.2 0.2 1</diffuse></material></visual></link></model>\n"
    "</world></sdf>\n";

/* Writes the world into dir; returns its path (static buffer). */
static inline const char *pipeline_world(const char *dir)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s/room.world", dir);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(pipeline_world_sdf, f);
        fclose(f);
    }
    return path;
}

#endif
