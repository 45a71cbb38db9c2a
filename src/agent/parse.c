/* The built-in intent parser: a deterministic reading of what a user says to the robot into one
 * of the four kinds of request (go to, show trajectories, describe surroundings, explore) plus
 * locate, cancel and a bare choice, with the target phrase, a selector among instances, k and a
 * radius. Cue words decide the kind; the target is what follows the cue with particles,
 * determiners, politeness and selectors stripped. Anything else asks back. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "agent_internal.h"
#include "parse_internal.h"

static const char *const cancel_words[] = {"stop", "cancel", "halt", "abort", "freeze", "nevermind",
                                           NULL};
static const char *const traj_words[] = {"trajectory", "trajectories", "route", "routes", "path",
                                         "paths", "alternatives", "itinerary", "itineraries",
                                         "way", "ways", "options", NULL};
static const char *const go_verbs[] = {"go", "goto", "navigate", "drive", "move", "head",
                                       "travel", "walk", "roll", "proceed", "come", "approach",
                                       "reach", "return", "visit", "park", "run", "hurry", "steer",
                                       "relocate", "get", "take", "bring", "lead", "guide",
                                       "follow", "make", "dock", "position", NULL};
static const char *const go_particles[] = {"me", "us", "yourself", "to", "towards", "toward",
                                           "over", "up", "down", "near", "next", "by", "beside",
                                           "into", "in", "at", "on", "back",
                                           "closer", "close", "right", "straight", "your", "way",
                                           "and", "stand", "wait", "stay", "stop", "park", "go",
                                           "there", "all", "the", "until", "till", "along",
                                           "across", "through", "find", "locate", NULL};
static const char *const explore_words[] = {"explore", "survey", "scan", "patrol", "inspect",
                                            "map", "sweep", "reconnoiter", "canvass", "search",
                                            "cover", "tour", "exploration", "scout", "wander", "roam",
                                            "investigate", NULL};
static const char *const explore_skip[] = {"out", "the", "area", "region", "part", "zone",
                                           "surroundings", "space", "around", "near", "of", "in",
                                           "by", "at", "inside", "whole", "entire", "all", "through",
                                           "over", "vicinity", "neighborhood", "a", "an", "for", "me",
                                           "nearby", "close", "to", "surrounding", "bit", NULL};
static const char *const region_suffixes[] = {"area", "region", "zone", "part", "section",
                                              "space", "surroundings", "vicinity", NULL};
static const char *const describe_words[] = {"what", "which", "describe", "list", "anything",
                                             "surroundings", "objects", "things", "items", "stuff",
                                             "furniture", "identify", "enumerate", "inventory",
                                             "something", "tell", NULL};
static const char *const preamble_words[] = {"please", "hey", "hi", "hello", "robot", "ok", "okay",
                                             "so", "now", "kindly", "alright", "well", "semsplat",
                                             "quickly", "just", "and", "then", NULL};
static const char *const preamble_phrases[] = {
    "would you mind", "do you mind", "how about", "can you", "could you", "would you", "will you",
    "can u", "i want you to",
    "i would like you to", "i need you to", "i want to", "i would like to", "i need to",
    "i wanna", "let us", "lets", "let me", "go ahead and", "try to", "i would love to",
    "you should", "you can", "i wish to", "be so kind as to", NULL};
static const char *const breakers[] = {"and", "then", "so", "because", "when", "while", "but",
                                       "from here", "from where", "starting",
                                       "after", "before", "if", "to see", "to check", "to look",
                                       "to find", "to get", "to grab", "to pick", "to fetch", NULL};

static void ask(sp_agent_intent *o, const char *q)
{
    o->kind = SP_AGENT_INTENT_ASK;
    o->target[0] = o->head[0] = o->anchor[0] = o->relation[0] = 0;
    snprintf(o->question, sizeof o->question, "%s", q);
}

static void strip_preamble(pw_words *t)
{
    for (int changed = 1; changed && t->n > 0;) {
        changed = 0;
        int len;
        if (pw_find_phrase(t, 0, preamble_phrases, &len) == 0) {
            pw_erase(t, 0, len);
            changed = 1;
        } else if (pw_in(t->w[0], preamble_words) && t->n > 1) {
            pw_erase(t, 0, 1);
            changed = 1;
        }
    }
}

/* k from "top 3", "three best routes", "5 paths", "k 4"; the words are removed. */
static void take_k(pw_words *t, sp_agent_intent *o)
{
    static const char *const before[] = {"top", "best", "first", "k", "shortest", "safest", NULL};
    static const char *const after[] = {"best", "different", "alternative", "distinct", "possible",
                                        "candidate", "good", "shortest", "safest", "top", "ranked",
                                        "other", "fastest", "options", NULL};
    for (int i = 0; i < t->n; i++) {
        double v;
        if (!pw_number(t->w[i], &v) || v != floor(v) || v < 1) continue;
        int ok = (i > 0 && pw_in(t->w[i - 1], before)) ||
                 (i + 1 < t->n && (pw_in(t->w[i + 1], traj_words) || pw_in(t->w[i + 1], after)));
        if (!ok) continue;
        o->k = v > SP_AGENT_MAX_K ? SP_AGENT_MAX_K : (int)v;
        pw_erase(t, i, 1);
        return;
    }
}

/* A radius from "within 2 m", "within a metre", "2 meters around", "in a 1.5 m radius". */
static void take_radius(pw_words *t, sp_agent_intent *o)
{
    for (int i = 0; i < t->n; i++) {
        double v, unit = 0;
        int span = 0;
        if (pw_number(t->w[i], &v) || !strcmp(t->w[i], "a")) {
            if (!strcmp(t->w[i], "a")) v = 1;
            const char *tail = t->w[i];
            while (*tail && ((*tail >= '0' && *tail <= '9') || *tail == '.')) tail++;
            if (*tail && tail != t->w[i]) unit = pw_unit_m(tail), span = 1; /* "2m" */
            else if (i + 1 < t->n && (unit = pw_unit_m(t->w[i + 1])) > 0) span = 2;
        }
        if (unit <= 0 || span == 0) continue;
        int from = i, to = i + span;
        if (from > 0 && (!strcmp(t->w[from - 1], "within") || !strcmp(t->w[from - 1], "of")))
            from--;
        if (from > 0 && !strcmp(t->w[from - 1], "radius")) from--;
        if (from > 0 && !strcmp(t->w[from - 1], "a")) from--;
        if (from > 0 && !strcmp(t->w[from - 1], "in")) from--;
        if (to < t->n && !strcmp(t->w[to], "radius")) to++;
        o->radius_m = v * unit;
        if (to < t->n && !strcmp(t->w[to], "of")) /* "within 2 m of the table" */
            snprintf(t->w[to], PW_WORD, "near");
        pw_erase(t, from, to - from);
        return;
    }
}

/* Selectors inside a target: "nearest", "any", "the second", "number 2", "chair 2". */
static void take_selector(pw_words *t, sp_agent_intent *o)
{
    for (int i = 0; i < t->n; i++) {
        const char *w = t->w[i];
        int ord = pw_ordinal(w), n = 1;
        if (!strcmp(w, "nearest") || !strcmp(w, "closest")) {
            o->selector = SP_AGENT_SELECT_NEAREST;
            if (i + 2 < t->n && !strcmp(t->w[i + 1], "to") && pw_in(t->w[i + 2], pw_self))
                n = 3; /* "closest to me" */
        } else if (!strcmp(w, "any") || !strcmp(w, "whichever") || !strcmp(w, "either")) {
            o->selector = SP_AGENT_SELECT_ANY;
        } else if (!strcmp(w, "farthest") || !strcmp(w, "furthest")) {
            o->selector = SP_AGENT_SELECT_FARTHEST;
        } else if (ord > 0) {
            o->selector = SP_AGENT_SELECT_INDEX;
            o->index = ord;
        } else if ((!strcmp(w, "number") || !strcmp(w, "no") || !strcmp(w, "num")) && i + 1 < t->n &&
                   pw_number(t->w[i + 1], &(double){0})) {
            double v;
            pw_number(t->w[i + 1], &v);
            o->selector = SP_AGENT_SELECT_INDEX;
            o->index = (int)v;
            n = 2;
        } else {
            continue;
        }
        pw_erase(t, i, n);
        if (i < t->n && !strcmp(t->w[i], "one")) pw_erase(t, i, 1);
        if (i > 0 && !strcmp(t->w[i - 1], "of")) pw_erase(t, i - 1, 1);
        i--;
    }
    /* A trailing small number names an instance: "chair 2". */
    double v;
    if (t->n >= 2 && o->selector == SP_AGENT_SELECT_NONE && pw_number(t->w[t->n - 1], &v) &&
        v >= 1 && v <= 16 && v == floor(v)) {
        o->selector = SP_AGENT_SELECT_INDEX;
        o->index = (int)v;
        t->n--;
    }
}

static void strip_ends(pw_words *t)
{
    for (int changed = 1; changed && t->n > 0;) {
        changed = 0;
        if (pw_in(t->w[0], pw_determiners) || !strcmp(t->w[0], "all") || !strcmp(t->w[0], "of")) {
            pw_erase(t, 0, 1);
            changed = 1;
        } else if (pw_in(t->w[t->n - 1], pw_fillers) && t->n > 0) {
            t->n--;
            changed = 1;
        }
    }
}

/* Fills target, head, relation, anchor from words [from, to) of t. */
static void finish_target(const pw_words *t, int from, int to, sp_agent_intent *o)
{
    pw_words tt = {0};
    for (int i = from; i < to && i < t->n; i++) snprintf(tt.w[tt.n++], PW_WORD, "%s", t->w[i]);
    int len, cut = pw_find_phrase(&tt, 1, breakers, &len);
    if (cut > 0) tt.n = cut;
    take_selector(&tt, o);
    strip_ends(&tt);
    if (tt.n == 0) return;
    if (tt.n <= 2 && pw_in(tt.w[tt.n - 1], pw_pronouns) &&
        (tt.n == 1 || !strcmp(tt.w[0], "over") || !strcmp(tt.w[0], "same"))) {
        o->pronoun = 1;
        return;
    }
    if (tt.n == 1 && pw_in(tt.w[0], pw_self)) return; /* "near me": an anchor we cannot name */
    pw_join(&tt, 0, tt.n, o->target, sizeof o->target);
    int rel = pw_find_phrase(&tt, 1, pw_relations, &len);
    static const char *const head_stops[] = {"of", "to", "with", "for", "from", NULL};
    int stop = pw_find(&tt, 1, head_stops);
    int h = rel > 0 && (stop < 0 || rel < stop) ? rel : stop > 0 ? stop : tt.n;
    snprintf(o->head, sizeof o->head, "%s", tt.w[h - 1]);
    if (rel > 0 && rel + len < tt.n) {
        pw_join(&tt, rel, rel + len, o->relation, sizeof o->relation);
        pw_words an = {0};
        for (int i = rel + len; i < tt.n; i++) snprintf(an.w[an.n++], PW_WORD, "%s", tt.w[i]);
        strip_ends(&an);
        pw_join(&an, 0, an.n, o->anchor, sizeof o->anchor);
    }
}

/* The index of the word after which the destination starts ("to", "reach", "for"; then
 * "get to", "getting to" are skipped), or -1. */
static int destination(const pw_words *t, int from)
{
    static const char *const to_words[] = {"to", "towards", "toward", "reach", "reaches",
                                           "reaching", "into", "for", "until", NULL};
    static const char *const skip[] = {"get", "getting", "go", "going", "drive", "driving",
                                       "reach", "reaching", "to", "towards", "toward", "arrive",
                                       "arriving", "at", "end", "ending", "up", NULL};
    int i = pw_find(t, from, to_words);
    while (i >= 0 && i + 1 < t->n && pw_in(t->w[i + 1], skip)) i++;
    return i;
}

static void parse_trajectories(pw_words *t, int cue, sp_agent_intent *o)
{
    o->kind = SP_AGENT_INTENT_TRAJECTORIES;
    int d = destination(t, cue >= 0 ? cue : 0);
    if (d >= 0) finish_target(t, d + 1, t->n, o);
    if (!o->target[0] && !o->pronoun)
        ask(o, "Trajectories to what? For example: \"show me the top 3 trajectories to the "
               "refrigerator\".");
}

static void parse_goto(pw_words *t, int verb, sp_agent_intent *o)
{
    o->kind = SP_AGENT_INTENT_GOTO;
    int i = verb + 1;
    for (;;) {
        int self = i < t->n && pw_in(t->w[i], pw_determiners) ? i + 1 : i; /* "drive the robot to" */
        if (pw_match(t, i, "in front of")) i += 3;
        else if (self + 1 < t->n && pw_in(t->w[self], pw_self) && pw_in(t->w[self + 1], go_particles))
            i = self + 1;
        else if (i < t->n && pw_in(t->w[i], go_particles) && !(!strcmp(t->w[i], "there") && i + 1 >= t->n))
            i++; /* ("go there" is a pronoun) */
        else break;
    }
    finish_target(t, i, t->n, o);
    if (!o->target[0] && !o->pronoun)
        ask(o, "Where should I go? Name an object or a place, for example: \"go to the "
               "refrigerator\".");
}

static void parse_describe(pw_words *t, int from, sp_agent_intent *o)
{
    o->kind = SP_AGENT_INTENT_DESCRIBE;
    int len, rel = pw_find_phrase(t, from, pw_relations, &len);
    static const char *const of_words[] = {"of", "around", NULL};
    if (rel >= 0) {
        finish_target(t, rel + len, t->n, o);
    } else {
        int i = pw_find(t, from, of_words); /* "describe the surroundings of the couch" */
        int start = i >= 0 ? i + 1 : from + 1;
        while (start < t->n && (pw_in(t->w[start], pw_determiners) || !strcmp(t->w[start], "area")))
            start++;
        finish_target(t, start, t->n, o);
    }
    if (!o->target[0] && !o->pronoun)
        ask(o, "Near what? For example: \"what objects are near the dining table?\".");
}

static void parse_explore(pw_words *t, int cue, sp_agent_intent *o)
{
    o->kind = SP_AGENT_INTENT_EXPLORE;
    int i = cue + 1;
    if (!strcmp(t->w[cue], "look") || !strcmp(t->w[cue], "check")) i++; /* "look around" */
    while (i < t->n && pw_in(t->w[i], explore_skip)) i++;
    finish_target(t, i, t->n, o);
    /* "kitchen area" -> "kitchen" */
    size_t n = strlen(o->target);
    for (const char *const *s = region_suffixes; *s; s++) {
        size_t k = strlen(*s);
        if (n > k + 1 && !strcmp(o->target + n - k, *s) && o->target[n - k - 1] == ' ') {
            o->target[n - k - 1] = 0;
            if (!strcmp(o->head, *s)) {
                const char *sp = strrchr(o->target, ' ');
                snprintf(o->head, sizeof o->head, "%s", sp ? sp + 1 : o->target);
            }
            break;
        }
    }
    if (!o->target[0] && !o->pronoun)
        ask(o, "Which area should I explore? For example: \"explore the area around the "
               "kitchen\".");
}

static void parse_locate(pw_words *t, int from, sp_agent_intent *o)
{
    o->kind = SP_AGENT_INTENT_LOCATE;
    static const char *const skip[] = {"where", "is", "are", "can", "could", "do", "does", "would",
                                       "i", "we", "you", "find", "locate", "see", "there", "a", "an",
                                       "any", "show", "me", "us", "tell", "the", "what", "look",
                                       "for", "search", "spot", "kept", "located", NULL};
    static const char *const tail[] = {"is", "are", "located", "kept", "placed", "situated",
                                       "stored", "at", "in", "house", "now", NULL};
    int i = from;
    while (i < t->n && pw_in(t->w[i], skip) && strcmp(t->w[i], "the") != 0) i++;
    int end = t->n;
    while (end > i + 1 && pw_in(t->w[end - 1], tail)) end--;
    finish_target(t, i, end, o);
    if (!o->target[0] && !o->pronoun)
        ask(o, "What should I look for? For example: \"where is the couch?\".");
}

static const char help_question[] =
    "I can go to an object (\"go to the refrigerator\"), show ranked trajectories to it (\"show "
    "me the top trajectories to the refrigerator\"), describe what is near something (\"what "
    "objects are near the dining table?\") or explore an area (\"explore the area around the "
    "kitchen\"). What would you like me to do?";

/* A bare reply to a question: "the second one", "number 2", "the nearest", "the one in the
 * kitchen". Returns 1 when the whole utterance is such a choice. */
static int parse_select(pw_words *t, sp_agent_intent *o)
{
    pw_words c = *t;
    sp_agent_intent s = *o;
    take_selector(&c, &s);
    strip_ends(&c);
    double v;
    if (c.n == 1 && pw_number(c.w[0], &v) && v >= 1 && v <= 16 && v == floor(v)) {
        s.selector = SP_AGENT_SELECT_INDEX;
        s.index = (int)v;
        c.n = 0;
    }
    int refine = c.n >= 2 && !strcmp(c.w[0], "one"); /* "the one in the kitchen" */
    if (s.selector == SP_AGENT_SELECT_NONE && !refine) return 0;
    if (c.n > 1 && !refine) return 0;
    *o = s;
    o->kind = SP_AGENT_INTENT_SELECT;
    if (refine) {
        pw_join(&c, 1, c.n, o->target, sizeof o->target);
        int len, rel = pw_find_phrase(&c, 1, pw_relations, &len);
        if (rel > 0) {
            pw_join(&c, rel, rel + len, o->relation, sizeof o->relation);
            pw_words an = {0};
            for (int i = rel + len; i < c.n; i++) snprintf(an.w[an.n++], PW_WORD, "%s", c.w[i]);
            strip_ends(&an);
            pw_join(&an, 0, an.n, o->anchor, sizeof o->anchor);
        }
    }
    return 1;
}

static int has_letters(const pw_words *t)
{
    for (int i = 0; i < t->n; i++)
        for (const char *p = t->w[i]; *p; p++)
            if ((*p >= 'a' && *p <= 'z') || (unsigned char)*p >= 0x80) return 1;
    return 0;
}

static void intent_init(sp_agent_intent *o, const char *text, pw_words *t)
{
    memset(o, 0, sizeof *o);
    o->k = 3;
    o->radius_m = SP_AGENT_DEFAULT_RADIUS_M;
    pw_tokenize(text, t);
}

void sp_agent_parse(const char *text, sp_agent_intent *o)
{
    pw_words t;
    intent_init(o, text, &t);
    strip_preamble(&t);
    if (t.n == 0 || !has_letters(&t)) {
        if (t.n == 0 || !parse_select(&t, o)) ask(o, help_question);
        return;
    }
    if (pw_in(t.w[0], cancel_words) || pw_match(&t, 0, "never mind")) {
        o->kind = SP_AGENT_INTENT_CANCEL;
        return;
    }
    int traj = pw_find(&t, 0, traj_words);
    int go = pw_find_verb(&t, 0, go_verbs);
    int hw = pw_find(&t, 0, (const char *const[]){"how", NULL});
    int hgo = hw >= 0 ? pw_find(&t, hw + 1, go_verbs) : -1;
    int how = hgo > hw && hgo <= hw + 4;
    if (traj >= 0) take_k(&t, o), traj = pw_find(&t, 0, traj_words), go = pw_find_verb(&t, 0, go_verbs);
    if ((traj >= 0 && go != 0) || how || (pw_in(t.w[0], (const char *const[]){"preview", "visualize", "visualise", NULL}))) {
        parse_trajectories(&t, traj >= 0 ? traj : how ? hw : 0, o);
        return;
    }
    if (traj >= 0 && go == 0) { /* "take the shortest route to the fridge" */
        int d = destination(&t, traj);
        parse_goto(&t, d >= 0 ? d : traj, o);
        return;
    }
    int len;
    int look = pw_find_phrase(&t, 0, (const char *const[]){"look around", "check out", "look over", NULL}, &len);
    int ex = pw_find(&t, 0, explore_words);
    if ((look >= 0 && look <= 3) || (ex >= 0 && ex <= 3 && !(ex + 1 < t.n && !strcmp(t.w[ex + 1], "for")))) {
        parse_explore(&t, look >= 0 && look <= 3 ? look : ex, o);
        return;
    }
    int where = pw_find(&t, 0, (const char *const[]){"where", "locate", NULL});
    int find = pw_find(&t, 0, (const char *const[]){"find", "spot", "search", NULL});
    int desc = pw_find(&t, 0, describe_words);
    take_radius(&t, o);
    desc = pw_find(&t, 0, describe_words);
    int rel = desc >= 0 ? pw_find_phrase(&t, desc + 1, pw_relations, &len) : -1;
    if (desc >= 0 && desc <= 3 && where < 0 && go != 0 && (rel > desc || !strcmp(t.w[desc], "describe"))) {
        parse_describe(&t, desc, o);
        return;
    }
    if (go >= 0 && go <= 1 && (find < 0 || find > go)) {
        parse_goto(&t, go, o);
        return;
    }
    if (find >= 0 && go > find) { /* "find the fridge and go there" */
        int cut = pw_find(&t, find + 1, (const char *const[]){"and", "then", NULL});
        finish_target(&t, find + 1, cut > find ? cut : go, o);
        o->kind = SP_AGENT_INTENT_GOTO;
        if (!o->target[0] && !o->pronoun) ask(o, help_question);
        return;
    }
    if (where >= 0 || find == 0 || pw_match(&t, 0, "do you see") || pw_match(&t, 0, "can you see") ||
        pw_match(&t, 0, "is there") || pw_match(&t, 0, "are there") || pw_match(&t, 0, "show me where")) {
        parse_locate(&t, 0, o);
        return;
    }
    if (parse_select(&t, o)) return;
    if (t.n <= 4 && has_letters(&t)) {
        char q[400], phrase[200];
        pw_join(&t, 0, t.n, phrase, sizeof phrase);
        snprintf(q, sizeof q,
                 "What should I do with \"%s\": go to it, show trajectories to it, describe "
                 "what is near it, or explore around it?",
                 phrase);
        ask(o, q);
        return;
    }
    ask(o, help_question);
}

void agent_parse_phrase(const char *phrase, sp_agent_intent *o)
{
    pw_words t;
    intent_init(o, phrase, &t);
    finish_target(&t, 0, t.n, o);
}

const char *sp_agent_intent_name(int kind)
{
    static const char *const names[] = {"ask", "goto", "trajectories", "describe", "explore",
                                        "locate", "cancel", "select"};
    return kind >= 0 && kind < (int)(sizeof names / sizeof names[0]) ? names[kind] : "unknown";
}
