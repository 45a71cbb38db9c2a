/* Private to the model-folder world (world_model.c: opening, queries, map look-ups;
 * world_nav.c: planning, rendering, descriptions, exploration): the query engine, the nav scene
 * on it, an optional lexical vocabulary for label-feature scenes, and the instances the queries
 * handed out, so that a goal point the tools send back is planned to as the object it came from. */
#ifndef SEMSPLAT_AGENT_WORLD_MODEL_H
#define SEMSPLAT_AGENT_WORLD_MODEL_H

#include "agent_internal.h"
#include "semsplat/nav.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

#define MW_KNOWN 64          /* instances remembered (a ring) */
#define MW_MATCH_M 0.05      /* a goal point this close to a handed-out position is that instance */

/* An instance a query handed out: what nav resolves to find it again, and its footprints. */
typedef struct mw_known {
    double position[3];
    char phrase[64];         /* the class (or region word) nav resolves */
    int index;               /* its index in nav's target for the phrase; -1 = a region: any of
                              * its objects */
    int n_boxes;
    sp_nav_box boxes[SP_NAV_MAX_BOXES];
} mw_known;

typedef struct model_world {
    sp_device *dev;
    int own_dev;
    sp_query_engine *engine;
    int own_engine;
    sp_nav *nav;
    sp_lexicon *lexicon;     /* label-feature scenes: phrases matched to class names (WordNet) */
    sp_lex_vocab *vocab;
    sp_raster *raster;       /* render_view_from_splat */
    sp_scene *scene;
    char out_dir[AGENT_PATH_CAP];
    int n_outputs;           /* numbered output folders and images */
    mw_known known[MW_KNOWN];
    int n_known;             /* handed out so far (the ring holds the last MW_KNOWN) */
    char source[320];        /* the engine's encoder and features, with the caveat */
    char vocabulary[4096];   /* what describe asks for: nav's household terms + the scene's classes */
    sp_log log;
    int has_log;
} model_world;

static inline const sp_log *mw_log(const model_world *w) { return w->has_log ? &w->log : NULL; }

/* The remembered instance at (x, y) (within MW_MATCH_M), or NULL. */
const mw_known *mw_find_known(const model_world *w, double x, double y);
/* A fresh numbered folder out_dir/<stem>_NNN (created), or -1 with err. */
int mw_output_dir(model_world *w, const char *out_dir, const char *stem, char *dir, size_t cap,
                  sp_error *err);
/* Nav's planner status in the tools' vocabulary ("GOAL_OCCUPIED", ...). */
const char *mw_status_code(int status);

/* world_nav.c: the ops that plan and render. */
int mw_plan(void *ctx, const sp_agent_pose *start, const agent_goalspec *goal, int k,
            const char *target, const char *out_dir, agent_plans *out, sp_error *err);
int mw_render(void *ctx, const sp_agent_pose *pose, const char *png_path, sp_error *err);
int mw_describe(void *ctx, const agent_instance *anchor, const char *anchor_name, double radius_m,
                const sp_agent_pose *robot, agent_scene *out, sp_error *err);
int mw_explore(void *ctx, const char *region, const sp_agent_pose *robot, int max_waypoints,
               const char *out_dir, agent_tour *out, sp_error *err);
/* The phrase nav should resolve for a user's words: the words themselves when nav finds them
 * (an object the engine knows, a room), else on a label-feature scene the best class WordNet
 * matches. out gets "" when nothing matches. */
int mw_nav_phrase(model_world *w, const char *text, char *out, size_t cap, sp_error *err);

#endif
