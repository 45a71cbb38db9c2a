/* Private to eval: the demo video's panels (demo_panels.c) and scenes (demo_video.c). */
#ifndef SEMSPLAT_EVAL_DEMO_VIDEO_H
#define SEMSPLAT_EVAL_DEMO_VIDEO_H

#include "semsplat/media.h"
#include "semsplat/nav.h"

typedef struct dv_map {
    const sp_costmap *cm;
    uint8_t *rgb;     /* [ny][nx][3], +y up */
    float placed[4];  /* where the last dv_map_draw put it */
} dv_map;

int dv_image_file(sp_canvas *c, const char *path, float x, float y, float w, float h, sp_error *err);
int dv_map_init(dv_map *m, const sp_costmap *cm, sp_error *err);
void dv_map_free(dv_map *m);
int dv_map_draw(sp_canvas *c, dv_map *m, float x, float y, float w, float h, sp_error *err);
void dv_map_path(sp_canvas *c, const dv_map *m, const double *xy, int n, int stride, sp_rgba color, float line_px);
void dv_map_robot(sp_canvas *c, const dv_map *m, double x, double y, double yaw);
void dv_map_marker(sp_canvas *c, const dv_map *m, double x, double y, sp_rgba color, const char *label);
void dv_tools_panel(sp_canvas *c, const char *heading, const char *const *blocks, const char *const *labels, int n);

#endif
