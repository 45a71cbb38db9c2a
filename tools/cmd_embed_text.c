/* semsplat embed-text: the CLIP text embedding of one or more texts (or, without weights, the
 * label embedding the `labels` feature source uses). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/clip.h"

static void help(void)
{
    printf("usage: semsplat embed-text [--clip MODEL.safetensors] [--config config.json]\n"
           "                           [--full | --json] [--device cpu|cuda|auto] [--threads N] TEXT...\n\n"
           "Prints each text's L2-normalised embedding: its dimension, norm and first values\n"
           "(--full: all values, --json: one JSON object per line). Without --clip it prints the\n"
           "deterministic label embedding used for label features (512-D, not CLIP).\n");
}

int cmd_embed_text(int argc, char **argv)
{
    const char *weights = NULL, *config = NULL, *v;
    const char **texts = calloc((size_t)argc, sizeof *texts);
    cli_common c = cli_common_default();
    c.device = SP_DEVICE_CPU;
    int n = 0, full = 0, json = 0, bad = 0, r;
    if (!texts) return 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return free(texts), help(), 0;
        if ((r = cli_common_flag("embed-text", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return free(texts), 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--clip", &bad))) weights = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--config", &bad))) config = v;
        else if (!strcmp(argv[i], "--full")) full = 1;
        else if (!strcmp(argv[i], "--json")) json = 1;
        else if (!strcmp(argv[i], "--")) { while (++i < argc) texts[n++] = argv[i]; }
        else if (!strncmp(argv[i], "--", 2) && !bad) { free(texts); return cli_usage_error("embed-text", "unknown argument '%s'", argv[i]); }
        else texts[n++] = argv[i];
        if (bad) return free(texts), 2;
    }
    if (!n) return free(texts), cli_usage_error("embed-text", "no text given");
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_clip *clip = NULL;
    int dim = 512, rc = 0;
    if (weights) {
        if ((rc = sp_device_create(&dev, c.device, (int)c.threads, &err)) ||
            (rc = sp_clip_load(&clip, weights, config, dev, &err))) {
            sp_device_free(dev);
            free(texts);
            return cli_fail("embed-text", &err);
        }
        dim = sp_clip_embed_dim(clip);
    }
    float *e = malloc((size_t)n * dim * sizeof *e);
    if (!e) rc = sp_error_set(&err, SP_E_NOMEM, "out of memory");
    else if (clip) rc = sp_clip_encode_text(clip, texts, n, e, &err);
    else for (int i = 0; i < n; i++) sp_label_embedding(texts[i], dim, e + (size_t)i * dim);
    for (int i = 0; i < n && !rc; i++) {
        const float *x = e + (size_t)i * dim;
        double norm = 0;
        for (int k = 0; k < dim; k++) norm += (double)x[k] * x[k];
        int show = full || json ? dim : (dim < 8 ? dim : 8);
        if (json) printf("{\"text\": \"");
        if (json) {
            for (const char *p = texts[i]; *p; p++) {
                if (*p == '"' || *p == '\\') printf("\\%c", *p);
                else if ((unsigned char)*p < 0x20) printf("\\u%04x", *p);
                else putchar(*p);
            }
            printf("\", \"encoder\": \"%s\", \"dim\": %d, \"embedding\": [", clip ? "clip" : "exact", dim);
        } else {
            printf("\"%s\"  encoder %s  dim %d  norm %.6f  values", texts[i], clip ? "clip" : "exact (hashed name, no --clip)", dim, sqrt(norm));
        }
        for (int k = 0; k < show; k++) printf(json ? "%s%.7g" : "%s%.6f", json ? (k ? ", " : "") : " ", x[k]);
        printf(json ? "]}\n" : (show < dim ? " ...\n" : "\n"));
    }
    free(e);
    free(texts);
    sp_clip_free(clip);
    sp_device_free(dev);
    return rc ? cli_fail("embed-text", &err) : 0;
}
