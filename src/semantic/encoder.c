/* The query engine's text encoders behind one table of operations (sem_encoder): clip (CLIP's
 * text tower), exact (the text's hashed embedding) and lexical (WordNet against the scene's class
 * names, grounded by lex_engine.c). Each names itself in every result and says what it
 * understood: the threshold it reports matches at, the classes it matched and an explanation. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"
#include "semsplat/clip.h"

/* Class names compared as sp_label_embedding hashes them: case, surrounding and repeated
 * whitespace aside. */
static void normalise(const char *s, char *out, size_t cap)
{
    size_t j = 0;
    int space = 0;
    for (; *s && j + 1 < cap; s++) {
        if (isspace((unsigned char)*s)) {
            space = j > 0;
            continue;
        }
        if (space && j + 2 < cap) out[j++] = ' ';
        space = 0;
        out[j++] = (char)tolower((unsigned char)*s);
    }
    out[j] = 0;
}

static int embed_base_one(sp_query_engine *e, const char *text, float *out, sp_error *err)
{
    return sem_embed_base(e, &text, 1, out, err);
}

static int set_explanation(sp_query_result *res, const char *text, sp_error *err)
{
    free(res->explanation);
    res->explanation = strdup(text);
    return res->explanation ? 0 : sp_error_set(err, SP_E_NOMEM, "query: out of memory");
}

static int explain_clip(sp_query_engine *e, const sp_query_opts *o, sp_query_result *res, sp_error *err)
{
    char buf[2048];
    res->threshold = o->min_confidence;
    snprintf(buf, sizeof buf,
             "clip encoder (CLIP's text tower, %s): '%s' embedded as it is, open vocabulary with no list "
             "of classes; confidence %.3f is the robust largest cosine to the scene's features (found at "
             ">= %.2f)\n", e->clip_path[0] ? e->clip_path : "no weights", res->text,
             (double)res->confidence, (double)o->min_confidence);
    return set_explanation(res, buf, err);
}

/* exact: the class whose name the text is, when the engine knows the classes. */
static int explain_exact(sp_query_engine *e, const sp_query_opts *o, sp_query_result *res, sp_error *err)
{
    char want[256], name[256], buf[2048];
    res->threshold = o->min_confidence;
    normalise(res->text, want, sizeof want);
    int hit = -1;
    for (int i = 0; i < e->n_classes && hit < 0; i++) {
        normalise(e->classes[i], name, sizeof name);
        if (!strcmp(want, name)) hit = i;
    }
    if (hit >= 0) {
        res->matches = calloc(1, sizeof *res->matches);
        if (!res->matches) return sp_error_set(err, SP_E_NOMEM, "query: out of memory");
        sp_query_match *m = &res->matches[0];
        res->n_matches = 1;
        snprintf(m->label, sizeof m->label, "%s", e->classes[hit]);
        snprintf(m->role, sizeof m->role, "target");
        snprintf(m->kind, sizeof m->kind, "exact");
        m->score = 1;
        for (int k = 0; res->valid && k < res->n_instances; k++)
            snprintf(res->instances[k].label, sizeof res->instances[k].label, "%s", e->classes[hit]);
    }
    snprintf(buf, sizeof buf,
             "exact encoder (hashed class names): '%s' is %s; only a class named exactly so can match "
             "(confidence %.3f, the robust largest cosine; found at >= %.2f)\n", res->text,
             hit >= 0 ? "the name of a class of this scene" : e->n_classes ? "no class name of this scene"
                                                                       : "hashed as it is",
             (double)res->confidence, (double)o->min_confidence);
    return set_explanation(res, buf, err);
}

/* lexical: the score-weighted label embeddings of the classes the text matches; when it matches
 * none, its own hash (near-orthogonal to every class: it finds nothing). */
static int embed_lexical(sp_query_engine *e, const char *text, float *out, sp_error *err)
{
    float conf = 0;
    int rc = sp_lex_embed(e->vocab, text, e->pca.full_dim, out, &conf, err);
    if (!rc && conf < SP_LEX_THRESHOLD) rc = embed_base_one(e, text, out, err);
    return rc;
}

static const sem_encoder encoders[] = {
    {SP_ENCODER_CLIP, 0, embed_base_one, NULL, explain_clip},
    {SP_ENCODER_EXACT, 1, embed_base_one, NULL, explain_exact},
    {SP_ENCODER_LEXICAL, 1, embed_lexical, sem_lex_engine_query, NULL},
};

const sem_encoder *sem_encoder_find(const char *name)
{
    for (size_t i = 0; name && i < sizeof encoders / sizeof encoders[0]; i++)
        if (!strcmp(encoders[i].name, name)) return &encoders[i];
    return NULL;
}

int sem_encoder_prepare(sp_query_engine *e, const char *name, const char *wordnet_dir,
                        const char *regions_path, sp_error *err)
{
    const sem_encoder *enc = sem_encoder_find(name);
    if (!enc)
        return sp_error_set(err, SP_E_ARG, "query engine: text encoder '%s' is not clip, lexical or exact",
                            name ? name : "(none)");
    if (!strcmp(name, SP_ENCODER_LEXICAL) && !e->vocab) {
        if (e->n_classes == 0)
            return sp_error_set(err, SP_E_NOTFOUND, "query engine: the lexical encoder needs the scene's class "
                                "names (semantic.json \"classes\", or the capture's labels.json)");
        const char **names = malloc(sizeof *names * (size_t)e->n_classes);
        if (!names) return sp_error_set(err, SP_E_NOMEM, "query engine: out of memory");
        for (int i = 0; i < e->n_classes; i++) names[i] = e->classes[i];
        int rc = sp_lexicon_open(&e->lx, wordnet_dir, err);
        if (!rc) rc = sp_lex_vocab_create(&e->vocab, e->lx, names, e->n_classes, regions_path, err);
        free(names);
        if (rc) {
            sp_lex_vocab_free(e->vocab), sp_lexicon_free(e->lx);
            e->vocab = NULL, e->lx = NULL;
            return sp_error_prefix(err, "query engine: lexical encoder: ");
        }
    }
    e->enc = enc;
    snprintf(e->source.encoder, sizeof e->source.encoder, "%s", enc->name); /* name may be this field */
    return 0;
}
