/* Resolving an object phrase to instances: the world's query, a relation to an anchor applied
 * in C ("the mug on the counter": head and anchor queried apart, the head's instances filtered
 * by footprint), fragments dropped, nearest first, and the ambiguity rule with its question. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tools_internal.h"

/* Whether `head` stands in `relation` to `anchor` (footprints where known, else centres). */
static int relation_holds(const char *rel, const agent_instance *h, const agent_instance *an)
{
    double d = agent_dist_to_footprint(an, h->position[0], h->position[1]);
    int known_z = isfinite(an->extent_max[2]) && isfinite(an->extent_min[2]);
    if (!strcmp(rel, "on") || !strcmp(rel, "on top of"))
        return d <= 0.1 && (!known_z || h->position[2] >= an->extent_max[2] - 0.15);
    if (!strcmp(rel, "under") || !strcmp(rel, "underneath") || !strcmp(rel, "below"))
        return d <= 0.1 && (!known_z || h->position[2] <= an->extent_max[2]);
    if (!strcmp(rel, "in") || !strcmp(rel, "inside")) return d <= 0.1;
    return d <= 1.0; /* near, next to, by, beside, around, at, behind, in front of ... */
}

/* A region name ("dining room") matches words of an anchor ("the dining area"). */
static int region_matches(const char *region, const char *anchor)
{
    if (!region[0]) return 0;
    char a[64];
    snprintf(a, sizeof a, "%s", anchor);
    char *save = NULL;
    for (char *w = strtok_r(a, " ", &save); w; w = strtok_r(NULL, " ", &save)) {
        if (!strcmp(w, "room") || !strcmp(w, "area") || strlen(w) < 3) continue;
        if (strstr(region, w)) return 1;
    }
    return 0;
}

static int query(sp_agent_session *s, const char *text, agent_found *f, sp_error *err)
{
    memset(f, 0, sizeof *f);
    for (int i = 0; i < AGENT_MAX_INSTANCES; i++)
        for (int k = 0; k < 3; k++) f->inst[i].extent_min[k] = f->inst[i].extent_max[k] = NAN;
    int rc = s->world.ops->query(s->world.ctx, text, f, err);
    if (f->n > AGENT_MAX_INSTANCES) f->n = AGENT_MAX_INSTANCES;
    if (f->n < 0) f->n = 0;
    for (int i = 0; i < f->n; i++)
        if (!f->inst[i].region[0])
            s->world.ops->region_of(s->world.ctx, f->inst[i].position[0], f->inst[i].position[1],
                                    f->inst[i].region, sizeof f->inst[i].region);
    return rc;
}

/* Keeps the head instances that satisfy the relation; notes what was done. */
static int apply_relation(sp_agent_session *s, const sp_agent_intent *in, agent_found *head,
                          char *note, size_t cap, sp_error *err)
{
    agent_instance keep[AGENT_MAX_INSTANCES];
    int n = 0, by_region = !strcmp(in->relation, "in") || !strcmp(in->relation, "inside");
    if (by_region) {
        for (int i = 0; i < head->n; i++)
            if (region_matches(head->inst[i].region, in->anchor)) keep[n++] = head->inst[i];
    }
    if (n == 0) {
        agent_found *an = malloc(sizeof *an);
        if (!an) return sp_error_set(err, SP_E_NOMEM, "out of memory");
        int rc = query(s, in->anchor, an, err);
        if (rc || !an->found) {
            free(an);
            if (rc) return rc;
            snprintf(note, cap, "could not find '%s' to check '%s %s' against", in->anchor,
                     in->relation, in->anchor);
            return 1; /* caller falls back to the whole phrase */
        }
        for (int i = 0; i < head->n; i++)
            for (int j = 0; j < an->n; j++)
                if (relation_holds(in->relation, &head->inst[i], &an->inst[j])) {
                    keep[n++] = head->inst[i];
                    break;
                }
        free(an);
    }
    snprintf(note, cap, "kept %d of %d '%s' %s the %s", n, head->n, in->head, in->relation, in->anchor);
    memcpy(head->inst, keep, (size_t)n * sizeof keep[0]);
    head->n = n;
    if (n == 0) head->found = 0;
    return SP_OK;
}

static int by_distance(const void *a, const void *b)
{
    double da = ((const agent_instance *)a)->distance_m, db = ((const agent_instance *)b)->distance_m;
    return da < db ? -1 : da > db;
}

int agent_resolve(sp_agent_session *s, const char *phrase, const sp_agent_pose *robot,
                  agent_resolved *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    sp_agent_intent in;
    agent_parse_phrase(phrase, &in);
    const char *text = in.target[0] ? in.target : phrase;
    int rc;
    if (in.relation[0] && in.anchor[0]) {
        char head[SP_AGENT_MAX_PHRASE + 1];
        snprintf(head, sizeof head, "%s", in.target);
        char *cut = strstr(head, in.relation);
        while (cut && !(cut > head && cut[-1] == ' ')) cut = strstr(cut + 1, in.relation);
        if (cut) cut[-1] = 0;
        rc = query(s, head, &out->found, err);
        if (!rc && out->found.found) {
            rc = apply_relation(s, &in, &out->found, out->note, sizeof out->note, err);
            if (rc == 1) rc = query(s, text, &out->found, err); /* anchor unknown: whole phrase */
        } else if (!rc) {
            rc = query(s, text, &out->found, err);
        }
    } else {
        rc = query(s, text, &out->found, err);
    }
    if (rc) return rc;
    agent_found *f = &out->found;
    /* Fragments (weight under a share of the best) are not alternatives. */
    double best = 0;
    for (int i = 0; i < f->n; i++) best = fmax(best, isfinite(f->inst[i].score) ? f->inst[i].score : 0);
    int n = 0;
    for (int i = 0; i < f->n; i++)
        if (!(best > 0) || !isfinite(f->inst[i].score) || f->inst[i].score >= AGENT_AMBIGUOUS_SCORE_FRACTION * best)
            f->inst[n++] = f->inst[i];
    if (n < f->n) {
        size_t l = strlen(out->note);
        snprintf(out->note + l, sizeof out->note - l, "%s%d small fragment(s) dropped", l ? "; " : "", f->n - n);
    }
    f->n = n;
    for (int i = 0; i < f->n; i++)
        f->inst[i].distance_m = agent_dist2d(robot->x, robot->y, f->inst[i].position[0], f->inst[i].position[1]);
    qsort(f->inst, (size_t)f->n, sizeof f->inst[0], by_distance);
    out->n_real = f->n;
    if (f->n == 0) f->found = 0;
    out->ambiguous = f->found && f->n >= 2;
    if (!f->found && s->world.ops->suggest)
        out->n_suggestions = s->world.ops->suggest(s->world.ctx, text, out->suggestions, 5);
    if (out->n_suggestions < 0) out->n_suggestions = 0;
    return SP_OK;
}

cJSON *agent_instances_json(const agent_found *f)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < f->n; i++) {
        const agent_instance *in = &f->inst[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddNumberToObject(o, "instance", i + 1);
        cJSON_AddItemToObject(o, "position", agent_json_numbers(in->position, 3));
        cJSON_AddNumberToObject(o, "confidence", agent_round4(in->confidence));
        cJSON_AddNumberToObject(o, "distance_m", agent_round4(in->distance_m));
        cJSON_AddStringToObject(o, "region", in->region[0] ? in->region : "unknown");
        if (isfinite(in->extent_min[0])) {
            cJSON_AddItemToObject(o, "extent_min", agent_json_numbers(in->extent_min, 3));
            cJSON_AddItemToObject(o, "extent_max", agent_json_numbers(in->extent_max, 3));
        }
        cJSON_AddItemToArray(a, o);
    }
    return a;
}

static void plural(const char *noun, char *out, size_t cap)
{
    size_t n = strlen(noun);
    const char *es = n && (noun[n - 1] == 's' || noun[n - 1] == 'x' || (n > 1 && noun[n - 1] == 'h'))
                         ? "es" : "s";
    if (n > 1 && noun[n - 1] == 'y' && !strchr("aeiou", noun[n - 2]))
        snprintf(out, cap, "%.*sies", (int)(n - 1), noun);
    else
        snprintf(out, cap, "%s%s", noun, es);
}

void agent_ambiguity_question(const char *phrase, const agent_resolved *r, char *out, size_t cap)
{
    sp_agent_intent in;
    agent_parse_phrase(phrase, &in);
    char many[80];
    plural(in.head[0] ? in.head : phrase, many, sizeof many);
    size_t j = (size_t)snprintf(out, cap, "I see %d %s:", r->found.n, many);
    for (int i = 0; i < r->found.n && j < cap; i++)
        j += (size_t)snprintf(out + j, cap - j, " %d) %.1f m away, in the %s%s", i + 1,
                              r->found.inst[i].distance_m,
                              r->found.inst[i].region[0] ? r->found.inst[i].region : "unknown area",
                              i + 1 < r->found.n ? ";" : ".");
    if (j < cap)
        snprintf(out + j, cap - j, " Which one do you mean (say \"the nearest\" or its number)?");
}

static char *not_found(int tool, const char *phrase, const agent_resolved *r)
{
    char msg[512];
    size_t j = (size_t)snprintf(msg, sizeof msg, "I could not find '%s' in this map (best confidence %.2f, "
                                "a match needs %.2f)", phrase, r->found.confidence, r->found.min_confidence);
    if (r->note[0] && j < sizeof msg) j += (size_t)snprintf(msg + j, sizeof msg - j, "; %s", r->note);
    cJSON *d = cJSON_CreateObject(), *m = cJSON_CreateArray();
    for (int i = 0; i < r->n_suggestions; i++) cJSON_AddItemToArray(m, cJSON_CreateString(r->suggestions[i]));
    cJSON_AddItemToObject(d, "nearest_matches", m);
    return agent_result_error(tool, "NOT_FOUND", msg,
                              r->n_suggestions ? "tell the user and offer the nearest matches" : "tell the user", d);
}

const agent_instance *agent_pick_instance(int tool, const char *phrase, int instance,
                                          const agent_resolved *r, char **result)
{
    *result = NULL;
    if (!r->found.found || r->found.n == 0) {
        *result = not_found(tool, phrase, r);
        return NULL;
    }
    if (instance > 0) {
        if (instance <= r->found.n) return &r->found.inst[instance - 1];
        char msg[200];
        snprintf(msg, sizeof msg, "instance %d: only %d match '%s'", instance, r->found.n, phrase);
        *result = agent_result_error(tool, "INVALID_ARGUMENTS", msg, "use a number from the list", NULL);
        return NULL;
    }
    if (r->ambiguous) {
        char q[1024];
        agent_ambiguity_question(phrase, r, q, sizeof q);
        cJSON *d = cJSON_CreateObject();
        cJSON_AddItemToObject(d, "candidates", agent_instances_json(&r->found));
        cJSON_AddStringToObject(d, "ask_user", q);
        *result = agent_result_error(tool, "AMBIGUOUS", q,
                                     "ask the user which one, then call again with instance=N", d);
        return NULL;
    }
    return &r->found.inst[0];
}

