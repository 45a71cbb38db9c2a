/* semsplat lexical: the offline text encoder (WordNet 3.0). Matches text against a scene's class
 * names (--labels, --classes) and, with a label-feature model folder (--model), answers it in
 * the scene: positions, regions with their extent, relations. --explain says why. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

static void help(void)
{
    printf("usage: semsplat lexical (--model DIR | --labels FILE | --classes a,b,c) [flags] \"text\" ...\n\n"
           "  --model DIR      a label-feature model folder: answer in the scene (positions, regions,\n"
           "                   relations); its classes come from the capture's labels.json\n"
           "  --labels FILE    class names from a capture's labels.json (matching only)\n"
           "  --classes LIST   comma-separated class names (matching only)\n"
           "  --explain        which classes matched and why (synonym, hypernym path, definitions)\n"
           "  --json           one JSON object per query\n"
           "  --wordnet DIR    WordNet 3.0 database files (default %s)\n"
           "  --regions FILE   region table (default data/semantic/regions.json); an aliases.json\n"
           "                   and a uses.json (activities) beside it add their entries\n"
           "  --device cpu|cuda|auto, --threads N, --quiet\n\n"
           "Matching against the scene's known class names, not recognition: what the world file\n"
           "does not name cannot be found. Confidence >= %.2f is a match. `semsplat query` answers\n"
           "label-feature model folders through this encoder by default (--explain, --json).\n",
           SP_LEX_DEFAULT_WORDNET, (double)SP_LEX_THRESHOLD);
}

/* Splits "a,b,c" into names (pointers into buf). */
static int split_classes(char *buf, const char **names, int cap)
{
    int n = 0;
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t && n < cap; t = strtok_r(NULL, ",", &save)) {
        while (*t == ' ') t++;
        if (*t) names[n++] = t;
    }
    return n;
}

static void print_answer(const sp_lex_answer *a, const sp_lex_vocab *v)
{
    const sp_query_result *r = &a->result;
    if (!r->valid) {
        printf("%-28s not found  confidence %.2f\n", a->lex.text, (double)r->confidence);
        return;
    }
    printf("%-28s found  (%.3f, %.3f, %.3f)  confidence %.2f  %d instance%s%s%s\n", a->lex.text,
           (double)r->position[0], (double)r->position[1], (double)r->position[2], (double)r->confidence,
           r->n_instances, r->n_instances == 1 ? "" : "s", a->is_region ? "  region " : "",
           a->is_region ? a->lex.target.region : "");
    for (int k = 0; k < r->n_instances; k++) {
        printf("    instance %d  %-16s (%.3f, %.3f, %.3f)", k, sp_lex_vocab_class(v, a->instance_class[k]),
               (double)r->instances[k].position[0], (double)r->instances[k].position[1],
               (double)r->instances[k].position[2]);
        if (a->relation_m) printf("  %.2f m %s the anchor", (double)a->relation_m[k], a->lex.relation);
        printf("\n");
    }
    if (a->is_region)
        printf("    extent (%.2f, %.2f, %.2f) .. (%.2f, %.2f, %.2f)\n", (double)a->region.extent_min[0],
               (double)a->region.extent_min[1], (double)a->region.extent_min[2], (double)a->region.extent_max[0],
               (double)a->region.extent_max[1], (double)a->region.extent_max[2]);
}

int cmd_lexical(int argc, char **argv)
{
    const char *model = NULL, *labels = NULL, *classes = NULL, *wordnet = NULL, *regions = NULL;
    const char *v, *texts[256];
    int n_texts = 0, json = 0, explain = 0, bad = 0, r;
    cli_common c = cli_common_default();
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((r = cli_common_flag("lexical", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--labels", &bad))) labels = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--classes", &bad))) classes = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--wordnet", &bad))) wordnet = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--regions", &bad))) regions = v;
        else if (!strcmp(argv[i], "--json")) json = 1;
        else if (!strcmp(argv[i], "--explain")) explain = 1;
        else if (argv[i][0] == '-' && argv[i][1] == '-' && !bad)
            return cli_usage_error("lexical", "unknown flag '%s'", argv[i]);
        else if (!bad) {
            if (n_texts == 256) return cli_usage_error("lexical", "at most 256 queries at once");
            texts[n_texts++] = argv[i];
        }
        if (bad) return 2;
    }
    if (!!model + !!labels + !!classes != 1)
        return cli_usage_error("lexical", "give exactly one of --model DIR, --labels FILE, --classes LIST");
    if (n_texts == 0) return cli_usage_error("lexical", "give the text to match, e.g. \"something to sit on\"");
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_WARN);
    sp_lexicon *lx = NULL;
    sp_lex_vocab *voc = NULL;
    sp_device *dev = NULL;
    sp_query_engine *e = NULL;
    static char text[32768];
    char buf[8192];
    const char *names[SP_LEX_MAX_CLASSES];
    sp_lex_answer *a = calloc(1, sizeof *a);
    if (!a) return fprintf(stderr, "semsplat lexical: out of memory\n"), 1;
    int rc = sp_lexicon_open(&lx, wordnet, &err);
    if (!rc && classes) {
        snprintf(buf, sizeof buf, "%s", classes);
        rc = sp_lex_vocab_create(&voc, lx, names, split_classes(buf, names, SP_LEX_MAX_CLASSES), regions, &err);
    } else if (!rc && labels) {
        rc = sp_lex_vocab_from_labels(&voc, lx, labels, regions, &err);
    } else if (!rc) {
        rc = sp_lex_vocab_for_model(&voc, lx, model, regions, &err);
        if (!rc) rc = sp_device_create(&dev, c.device, (int)c.threads, &err);
        if (!rc) rc = sp_query_engine_open(&e, model, NULL, dev, &log, &err);
    }
    if (!rc && json && n_texts > 1) printf("[\n");
    for (int q = 0; q < n_texts && !rc; q++) {
        if ((rc = e ? sp_lex_query(e, voc, texts[q], a, &err) : sp_lex_match(voc, texts[q], &a->lex, &err))) break;
        if (json) {
            char *s = e ? sp_lex_answer_json(a, voc, NULL) : sp_lex_result_json(&a->lex, voc, SP_LEX_THRESHOLD);
            printf("%s%s\n", s ? s : "null", n_texts > 1 && q + 1 < n_texts ? "," : "");
            free(s);
        } else if (e) {
            print_answer(a, voc);
        } else {
            printf("%-28s %s  confidence %.2f  %s\n", texts[q], a->lex.found ? "matches" : "no match",
                   (double)a->lex.confidence,
                   a->lex.found ? sp_lex_vocab_class(voc, a->lex.target.matches[0].class_index) : "");
        }
        if (explain && !json) {
            sp_lex_explain(&a->lex, voc, text, sizeof text);
            printf("%s\n", text);
        }
        if (e) sp_lex_answer_free(a);
    }
    if (!rc && json && n_texts > 1) printf("]\n");
    if (rc) cli_fail("lexical", &err);
    free(a);
    sp_query_engine_free(e);
    sp_device_free(dev);
    sp_lex_vocab_free(voc);
    sp_lexicon_free(lx);
    return rc ? 1 : 0;
}
