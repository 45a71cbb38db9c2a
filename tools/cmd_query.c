/* semsplat query: finds text queries in a language-embedded model folder and prints the world
 * position, instances and confidence (text or JSON), optionally with heatmap PNGs. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_query.h"
#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

static void help(void)
{
    printf("usage: semsplat query --model DIR [flags] \"text\" [\"text\" ...]\n\n"
           "  --json                print one JSON object per query (an array for several), with\n"
           "                        the encoder's matches (class, score, kind, path, definitions)\n"
           "  --explain             print which classes the text matched and why (synonym, hypernym\n"
           "                        path, definition words); in --json always\n"
           "  --encoder NAME        text encoder: clip, lexical or exact (default: the model\n"
           "                        folder's, semantic.json \"encoder\"; lexical for label scenes)\n"
           "  --wordnet DIR         lexical: WordNet 3.0 database files (default %s)\n"
           "  --regions FILE        lexical: region table (default data/semantic/regions.json);\n"
           "                        an aliases.json and a uses.json beside it add their entries\n"
           "  --heatmap FILE.png    relevancy overlay of the best view (one query)\n"
           "  --heatmap-dir DIR     one PNG per query, named after the text\n"
           "  --method 3d|multiview localization (default 3d)\n"
           "  --view N              heatmap from camera N instead of the best view\n"
           "  --views N             multi-view: at least N views rendered and back-projected\n"
           "                        (default 4; up to 3N while under 97%% of the relevant set is seen)\n"
           "  --negatives a,b,c     canonical negatives (default %s)\n"
           "  --min-confidence C    clip, exact: raw cosine below which nothing is found (default\n"
           "                        0.2); lexical answers at its calibrated score >= %.2f\n"
           "  --device cpu|cuda|auto, --threads N, --quiet\n\n"
           "Positions are in the model folder's frame (frame.json: world for synth captures and\n"
           "aligned models, else COLMAP's); the output names the frame, the text encoder and the\n"
           "feature source. The lexical encoder matches text against the scene's known class names\n"
           "(WordNet): it cannot find what the world file does not name.\n",
           SP_LEX_DEFAULT_WORDNET, SP_SEM_DEFAULT_NEGATIVES, (double)SP_LEX_THRESHOLD);
}

static void slug(const char *text, char *out, size_t cap)
{
    size_t j = 0;
    for (const char *p = text; *p && j + 1 < cap; p++)
        out[j++] = isalnum((unsigned char)*p) ? (char)tolower((unsigned char)*p) : '_';
    out[j] = 0;
}

int cmd_query(int argc, char **argv)
{
    const char *model = NULL, *heatmap = NULL, *heatmap_dir = NULL, *v;
    const char *texts[256];
    int n_texts = 0, json = 0, explain = 0, bad = 0, r;
    sp_encoder_opts enc = {0};
    long view = -1;
    cli_common c = cli_common_default();
    sp_query_opts opts = sp_query_opts_default();
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((r = cli_common_flag("query", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--heatmap-dir", &bad))) heatmap_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--heatmap", &bad))) heatmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--encoder", &bad))) enc.encoder = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--wordnet", &bad))) enc.wordnet_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--regions", &bad))) enc.regions_path = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--negatives", &bad)))
            snprintf(opts.negatives, sizeof opts.negatives, "%s", v);
        else if ((v = cli_flag_value(argc, argv, &i, "--method", &bad))) {
            if (!strcmp(v, "3d")) opts.method = SP_QUERY_3D;
            else if (!strcmp(v, "multiview") || !strcmp(v, "multi-view")) opts.method = SP_QUERY_MULTIVIEW;
            else return cli_usage_error("query", "--method: '%s' is not 3d or multiview", v);
        } else if ((v = cli_flag_value(argc, argv, &i, "--views", &bad))) {
            long nv;
            if (cli_parse_int("query", "--views", v, &nv)) return 2;
            if (nv < 1 || nv > 64) return cli_usage_error("query", "--views: %ld not in 1..64", nv);
            opts.n_views = (int)nv;
        } else if ((v = cli_flag_value(argc, argv, &i, "--view", &bad))) {
            if (cli_parse_int("query", "--view", v, &view)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--min-confidence", &bad))) {
            double c;
            if (cli_parse_float("query", "--min-confidence", v, &c)) return 2;
            opts.min_confidence = (float)c;
        } else if (!strcmp(argv[i], "--json")) json = 1;
        else if (!strcmp(argv[i], "--explain")) explain = 1;
        else if (argv[i][0] == '-' && argv[i][1] == '-' && !bad)
            return cli_usage_error("query", "unknown flag '%s'", argv[i]);
        else if (!bad) {
            if (n_texts == 256) return cli_usage_error("query", "at most 256 queries at once");
            texts[n_texts++] = argv[i];
        }
        if (bad) return 2;
    }
    if (!model) return cli_usage_error("query", "--model DIR is required");
    if (n_texts == 0) return cli_usage_error("query", "give the text to find, e.g. \"refrigerator\"");
    if (heatmap && n_texts > 1) return cli_usage_error("query", "--heatmap takes one query; use --heatmap-dir");
    if (heatmap && heatmap_dir) return cli_usage_error("query", "--heatmap and --heatmap-dir exclude each other");
    if (enc.encoder && strcmp(enc.encoder, SP_ENCODER_CLIP) && strcmp(enc.encoder, SP_ENCODER_LEXICAL) &&
        strcmp(enc.encoder, SP_ENCODER_EXACT))
        return cli_usage_error("query", "--encoder: '%s' is not clip, lexical or exact", enc.encoder);
    opts.heatmap = heatmap || heatmap_dir;
    opts.heatmap_view = (int)view;
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_WARN);
    sp_device *dev = NULL;
    sp_query_engine *e = NULL;
    if (cli_device_open("query", &c, &dev)) return 1;
    if (sp_query_engine_open_with(&e, model, &enc, &opts, dev, &log, &err)) {
        sp_device_free(dev);
        return cli_fail("query", &err);
    }
    int rc = 0;
    if (json && n_texts > 1) printf("[\n");
    if (!json) cli_query_provenance(sp_query_engine_source(e), sp_query_engine_frame(e));
    for (int q = 0; q < n_texts && !rc; q++) {
        sp_query_result res;
        if (sp_query_engine_query(e, texts[q], &opts, &res, &err)) {
            rc = cli_fail("query", &err);
            break;
        }
        char path[2048];
        const char *hm = NULL;
        if (heatmap) hm = heatmap;
        else if (heatmap_dir) {
            char s[200];
            slug(texts[q], s, sizeof s);
            if (sp_mkdirs(heatmap_dir, &err)) rc = cli_fail("query", &err);
            snprintf(path, sizeof path, "%s/%s.png", heatmap_dir, s);
            hm = path;
        }
        if (!rc && hm && res.relevancy_image) {
            sp_image img = {res.width, res.height, 3, 8, res.relevancy_image};
            if (sp_image_write_png(hm, &img, &err)) rc = cli_fail("query", &err);
        } else if (hm) {
            hm = NULL; /* no cameras: no heatmap */
        }
        if (json) {
            char *s = sp_query_result_json(&res, hm);
            printf("%s%s\n", s ? s : "null", json && n_texts > 1 && q + 1 < n_texts ? "," : "");
            free(s);
        } else {
            cli_query_print(&res, hm, explain);
        }
        sp_query_result_free(&res);
    }
    if (json && n_texts > 1) printf("]\n");
    sp_query_engine_free(e);
    sp_device_free(dev);
    return rc;
}
