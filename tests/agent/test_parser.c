/* The built-in intent parser on a table of phrasings across the four kinds of request (and
 * locate / cancel / a bare choice): intent and target must be right on at least 95% of them, and
 * nonsense and empty targets must ask back. The table was written from how people phrase these
 * requests, before tuning; every miss is printed. */
/* The rows leave trailing fields zero (= not checked). */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include "semsplat/agent.h"
#include "test.h"

typedef struct {
    const char *text;
    int kind;
    const char *target;
    int selector, index, k;
    double radius;
} row;

#define G SP_AGENT_INTENT_GOTO
#define T SP_AGENT_INTENT_TRAJECTORIES
#define D SP_AGENT_INTENT_DESCRIBE
#define E SP_AGENT_INTENT_EXPLORE
#define L SP_AGENT_INTENT_LOCATE
#define C SP_AGENT_INTENT_CANCEL
#define S SP_AGENT_INTENT_SELECT
#define NEAR SP_AGENT_SELECT_NEAREST
#define ANY SP_AGENT_SELECT_ANY
#define IDX SP_AGENT_SELECT_INDEX

static const row table[] = {
    /* go to an object */
    {"go to the refrigerator", G, "refrigerator"},
    {"Go to the fridge.", G, "fridge"},
    {"navigate to the couch", G, "couch"},
    {"drive over to the dining table", G, "dining table"},
    {"please move to the bed", G, "bed"},
    {"head to the kitchen", G, "kitchen"},
    {"take me to the sofa", G, "sofa"},
    {"can you go to the stove?", G, "stove"},
    {"I want you to go to the sink", G, "sink"},
    {"go to the red mug on the counter", G, "red mug on the counter"},
    {"could you please navigate to the wooden bookshelf", G, "wooden bookshelf"},
    {"go near the tv", G, "tv"},
    {"move next to the wardrobe", G, "wardrobe"},
    {"approach the armchair", G, "armchair"},
    {"head over to the kitchen counter please", G, "kitchen counter"},
    {"go to the nearest chair", G, "chair", NEAR},
    {"go to any chair", G, "chair", ANY},
    {"drive to the second chair", G, "chair", IDX, 2},
    {"go to chair 3", G, "chair", IDX, 3},
    {"robot, go stand by the front door", G, "front door"},
    /* -ing forms of the go verbs (polite and progressive phrasing) */
    {"would you mind going to the kitchen?", G, "kitchen"},
    {"do you mind heading to the sofa", G, "sofa"},
    {"how about driving over to the front door", G, "front door"},
    {"start moving towards the bookshelf", G, "bookshelf"},
    {"return to the couch", G, "couch"},
    {"get me to the refrigerator", G, "refrigerator"},
    {"make your way to the bedroom", G, "bedroom"},
    {"go back to the dining table", G, "dining table"},
    {"find the fridge and go there", G, "fridge"},
    {"go in front of the tv stand", G, "tv stand"},
    {"travel to the bookshelf now", G, "bookshelf"},
    {"hey robot, head towards the window", G, "window"},
    {"go to the chair closest to you", G, "chair", NEAR},
    {"go to something to sit on", G, "something to sit on"},
    {"take the shortest path to the refrigerator", G, "refrigerator"},
    {"I'd like you to drive up to the kitchen sink", G, "kitchen sink"},
    /* show trajectories */
    {"show me all the top trajectories that reach the refrigerator location", T, "refrigerator", 0, 0, 3},
    {"show me the top trajectories to the refrigerator", T, "refrigerator", 0, 0, 3},
    {"show me the top 3 trajectories to the fridge", T, "fridge", 0, 0, 3},
    {"what are the best routes to the couch?", T, "couch", 0, 0, 3},
    {"give me five paths to the bed", T, "bed", 0, 0, 5},
    {"show two alternative routes to the stove", T, "stove", 0, 0, 2},
    {"how can I get to the dining table?", T, "dining table"},
    {"compare routes to the sink", T, "sink"},
    {"preview the way to the wardrobe", T, "wardrobe"},
    {"plan 4 different paths to the tv", T, "tv", 0, 0, 4},
    {"what's the best way to get to the kitchen counter", T, "kitchen counter"},
    {"list candidate trajectories toward the armchair", T, "armchair"},
    {"show me ranked paths to the nearest chair", T, "chair", NEAR},
    {"find routes to the bookshelf", T, "bookshelf"},
    {"display the top 2 routes for reaching the refrigerator", T, "refrigerator", 0, 0, 2},
    {"which trajectories lead to the bed?", T, "bed"},
    {"visualize paths to the front door", T, "front door"},
    {"top 3 paths to the couch", T, "couch", 0, 0, 3},
    {"show me how to get to the fridge", T, "fridge"},
    {"are there several ways to reach the stove?", T, "stove", 0, 0, 3},
    {"I'd like to see trajectories to the sink", T, "sink"},
    {"show me the paths to the red mug on the counter", T, "red mug on the counter"},
    {"show 3 routes to chair 2", T, "chair", IDX, 2, 3},
    {"what routes could the robot take to the wardrobe", T, "wardrobe"},
    /* describe surroundings */
    {"what objects are near the dining table?", D, "dining table"},
    {"what is near the couch", D, "couch"},
    {"what's around the bed?", D, "bed"},
    {"describe the surroundings of the refrigerator", D, "refrigerator"},
    {"describe the area around the stove", D, "stove"},
    {"which things are next to the tv", D, "tv"},
    {"list the objects close to the sink", D, "sink"},
    {"tell me what is near the wardrobe", D, "wardrobe"},
    {"what can you see near the armchair?", D, "armchair"},
    {"is there anything near the bookshelf?", D, "bookshelf"},
    {"what furniture is by the window", D, "window"},
    {"what objects are within 2 meters of the dining table", D, "dining table", 0, 0, 0, 2.0},
    {"what's next to the kitchen counter?", D, "kitchen counter"},
    {"what items are around the red couch", D, "red couch"},
    {"describe what is beside the bed", D, "bed"},
    {"what is on the kitchen counter?", D, "kitchen counter"},
    {"what objects are close to the fridge within 1 meter", D, "fridge", 0, 0, 0, 1.0},
    {"name the things near the stove", D, "stove"},
    {"anything interesting near the tv?", D, "tv"},
    {"what is in the kitchen", D, "kitchen"},
    {"what surrounds the dining table?", D, "dining table"},
    {"what objects are in the vicinity of the couch", D, "couch"},
    {"show me what is near the couch within 50 cm", D, "couch", 0, 0, 0, 0.5},
    /* explore a region */
    {"explore the area around the kitchen", E, "kitchen"},
    {"explore the kitchen", E, "kitchen"},
    {"explore the kitchen area", E, "kitchen"},
    {"survey the living room", E, "living room"},
    {"scan the bedroom", E, "bedroom"},
    {"look around the dining room", E, "dining room"},
    {"please explore around the couch", E, "couch"},
    {"map out the hallway", E, "hallway"},
    {"patrol the living room", E, "living room"},
    {"inspect the area near the fridge", E, "fridge"},
    {"can you explore the bedroom for me", E, "bedroom"},
    {"explore the whole kitchen please", E, "kitchen"},
    {"do a sweep of the dining area", E, "dining"},
    {"check out the area around the tv", E, "tv"},
    {"search the kitchen", E, "kitchen"},
    {"go explore the living room", E, "living room"},
    {"take a look around the bedroom", E, "bedroom"},
    {"scan the region around the stove", E, "stove"},
    {"explore near the bookshelf", E, "bookshelf"},
    {"give me a tour of the kitchen", E, "kitchen"},
    /* locate, cancel, a bare choice */
    {"where is the couch?", L, "couch"},
    {"where's the refrigerator", L, "refrigerator"},
    {"locate the dining table", L, "dining table"},
    {"find the red mug", L, "red mug"},
    {"where can I find a chair", L, "chair"},
    {"do you see a tv?", L, "tv"},
    {"stop", C, ""},
    {"cancel the goal", C, ""},
    {"Stop moving!", C, ""},
    {"please abort the navigation", C, ""},
    {"never mind", C, ""},
    {"the second one", S, "", IDX, 2},
    {"number 3", S, "", IDX, 3},
    {"the nearest one", S, "", NEAR},
    {"2", S, "", IDX, 2},
};

/* Written after the parser passed the table above and never tuned on: its score is reported as
 * the honest figure for phrasings the parser has not seen (asserted only loosely). First run:
 * 38/40; the two misses ("... to the sink from here", "my options for getting to ...") were
 * then fixed, so today's 40/40 overstates it. */
static const row held_out[] = {
    {"could you head to the fridge", G, "fridge"},
    {"I need you to drive to the couch right now", G, "couch"},
    {"go over there to the bed", G, "bed"},
    {"move toward the big bookshelf", G, "big bookshelf"},
    {"navigate over to the kitchen sink please", G, "kitchen sink"},
    {"go and park next to the tv", G, "tv"},
    {"bring me to the wardrobe", G, "wardrobe"},
    {"go to the lamp in the living room", G, "lamp in the living room"},
    {"please drive me to the closest armchair", G, "armchair", NEAR},
    {"head to the third chair", G, "chair", IDX, 3},
    {"what would be the top routes to the bed", T, "bed"},
    {"show me a few ways to get to the couch", T, "couch", 0, 0, 3},
    {"rank the paths to the stove", T, "stove"},
    {"could you show me trajectories towards the window", T, "window"},
    {"give me the 2 best paths to the refrigerator", T, "refrigerator", 0, 0, 2},
    {"how would you get to the sink from here", T, "sink"},
    {"what are my options for getting to the dining table", T, "dining table"},
    {"plot routes to the kitchen counter", T, "kitchen counter"},
    {"show possible trajectories reaching the armchair", T, "armchair"},
    {"suggest some paths to the tv stand", T, "tv stand"},
    {"what is next to the fridge", D, "fridge"},
    {"what else is around the dining table", D, "dining table"},
    {"describe everything near the sofa", D, "sofa"},
    {"which objects can be found near the stove", D, "stove"},
    {"what sits beside the couch", D, "couch"},
    {"are there any objects near the window", D, "window"},
    {"tell me about the things around the bed", D, "bed"},
    {"list everything within 3 m of the tv", D, "tv", 0, 0, 0, 3.0},
    {"what do you see around the armchair", D, "armchair"},
    {"what lies near the wardrobe", D, "wardrobe"},
    {"explore the living room area", E, "living room"},
    {"please survey the area around the dining table", E, "dining table"},
    {"scan around the kitchen counter", E, "kitchen counter"},
    {"have a look around the kitchen", E, "kitchen"},
    {"explore the space near the bed", E, "bed"},
    {"inspect the bedroom", E, "bedroom"},
    {"could you map the kitchen", E, "kitchen"},
    {"go and explore the hallway", E, "hallway"},
    {"explore the region of the couch", E, "couch"},
    {"do an exploration of the dining room", E, "dining room"},
};

/* Round 2 (a2-agent): forty phrasings written by someone who did not write the parser, without
 * reading its word lists, and run once before any change. First run: 36/40 (90.0 %; go 8/10,
 * trajectories 10/10, describe 10/10, explore 8/10). The misses ("drive the robot to the
 * wardrobe", "go find the microwave and stop next to it", "scout the hallway", "wander around
 * the bathroom ...") were then fixed by general rules (a self-reference between the verb and
 * its particle, "find"/"locate" after a go verb, four exploring verbs), so today's 40/40
 * overstates the parser on unseen phrasings: 90 % is the honest figure. */
static const row fresh[] = {
    {"could you please drive the robot to the wardrobe", G, "wardrobe"},
    {"I'd like you to roll over to the armchair", G, "armchair"},
    {"get yourself to the bookshelf", G, "bookshelf"},
    {"proceed to the tv stand", G, "tv stand"},
    {"go find the microwave and stop next to it", G, "microwave"},
    {"make your way to the front door", G, "front door"},
    {"robot, travel to the nearest chair", G, "chair", NEAR},
    {"go to chair number 2", G, "chair", IDX, 2},
    {"walk up to the kitchen sink please", G, "kitchen sink"},
    {"return to the couch", G, "couch"},
    {"what are the best routes to the bed?", T, "bed"},
    {"give me three different paths to the stove", T, "stove", 0, 0, 3},
    {"plot a few candidate trajectories to the front door", T, "front door"},
    {"list the 2 best ways to get to the wardrobe", T, "wardrobe", 0, 0, 2},
    {"show all possible paths that lead to the bookshelf", T, "bookshelf"},
    {"I'd like to see the top 4 trajectories reaching the sink", T, "sink", 0, 0, 4},
    {"compare routes to the armchair", T, "armchair"},
    {"which paths could the robot take to the dining table?", T, "dining table"},
    {"visualize the ranked trajectories toward the tv", T, "tv"},
    {"display 5 alternative routes to the refrigerator", T, "refrigerator", 0, 0, 5},
    {"what's around the couch?", D, "couch"},
    {"which objects are close to the bed?", D, "bed"},
    {"tell me what is next to the stove", D, "stove"},
    {"describe the surroundings of the tv stand", D, "tv stand"},
    {"what can you see near the front door?", D, "front door"},
    {"list everything within 2 meters of the dining table", D, "dining table", 0, 0, 0, 2.0},
    {"what furniture is beside the wardrobe?", D, "wardrobe"},
    {"is there anything near the sink?", D, "sink"},
    {"what things are in the vicinity of the armchair?", D, "armchair"},
    {"what objects are within 1.5 m of the bookshelf", D, "bookshelf", 0, 0, 0, 1.5},
    {"explore the bedroom", E, "bedroom"},
    {"go explore around the dining table", E, "dining table"},
    {"take a look around the living room", E, "living room"},
    {"scout the hallway", E, "hallway"},
    {"survey the area near the front door", E, "front door"},
    {"can you explore the kitchen for me?", E, "kitchen"},
    {"wander around the bathroom and look at everything", E, "bathroom"},
    {"inspect the region around the couch", E, "couch"},
    {"do a sweep of the office", E, "office"},
    {"map out the space around the bed", E, "bed"},
};

static const char *const ask_back[] = {
    /* nonsense */
    "asdfgh qwerty", "purple monkey dishwasher", "hello", "the quick brown fox jumps over the lazy dog",
    "banana", "what is love", "blorp zzz", "", "???", "tell me a joke", "sing a song", "how are you",
    "colorless green ideas sleep furiously", "xkcd", "help",
    /* nothing named */
    "go to the", "navigate to", "show me the trajectories", "explore", "what is near", "go",
    "describe", "take me to", "what objects are near?", "what is near me", "explore the area",
    "show me the top 3 routes",
};

static int same(const char *a, const char *b) { return strcmp(a ? a : "", b ? b : "") == 0; }

/* Scores rows; returns how many were right and prints the misses. */
static int score(const row *rows, int n, int *per_kind, int *kinds)
{
    int right = 0;
    for (int i = 0; i < n; i++) {
        const row *r = &rows[i];
        sp_agent_intent in;
        sp_agent_parse(r->text, &in);
        int ok = in.kind == r->kind && same(in.target, r->target);
        if (r->selector) ok = ok && in.selector == r->selector && (!r->index || in.index == r->index);
        if (r->k) ok = ok && in.k == r->k;
        if (r->radius > 0) ok = ok && fabs(in.radius_m - r->radius) < 1e-9;
        kinds[r->kind]++;
        if (ok) right++, per_kind[r->kind]++;
        else
            fprintf(stderr, "  miss: \"%s\" -> %s \"%s\" sel %d/%d k %d r %.2f (want %s \"%s\")%s%s\n",
                    r->text, sp_agent_intent_name(in.kind), in.target, in.selector, in.index, in.k,
                    in.radius_m, sp_agent_intent_name(r->kind), r->target,
                    in.question[0] ? " q: " : "", in.question);
    }
    return right;
}

static void test_table(void)
{
    int n = (int)(sizeof table / sizeof table[0]), per_kind[8] = {0}, kinds[8] = {0};
    int right = score(table, n, per_kind, kinds);
    int four = kinds[G] + kinds[T] + kinds[D] + kinds[E];
    fprintf(stderr, "parser: %d/%d right (%.1f%%); go %d/%d, trajectories %d/%d, describe %d/%d, "
                    "explore %d/%d; %d phrasings of the four kinds\n",
            right, n, 100.0 * right / n, per_kind[G], kinds[G], per_kind[T], kinds[T], per_kind[D],
            kinds[D], per_kind[E], kinds[E], four);
    CHECK(four >= 80);
    CHECK_MSG(right >= 0.95 * n, "%d of %d", right, n);
}

static void test_held_out(void)
{
    int n = (int)(sizeof held_out / sizeof held_out[0]), per_kind[8] = {0}, kinds[8] = {0};
    int right = score(held_out, n, per_kind, kinds);
    fprintf(stderr, "parser, held-out phrasings: %d/%d right (%.1f%%)\n", right, n, 100.0 * right / n);
    CHECK_MSG(right >= 0.8 * n, "%d of %d", right, n);
}

static void test_fresh(void)
{
    int n = (int)(sizeof fresh / sizeof fresh[0]), per_kind[8] = {0}, kinds[8] = {0};
    int right = score(fresh, n, per_kind, kinds);
    fprintf(stderr, "parser, round-2 phrasings: %d/%d right (%.1f%%); go %d/%d, trajectories %d/%d, "
                    "describe %d/%d, explore %d/%d\n",
            right, n, 100.0 * right / n, per_kind[G], kinds[G], per_kind[T], kinds[T], per_kind[D],
            kinds[D], per_kind[E], kinds[E]);
    CHECK_MSG(right >= 0.95 * n, "%d of %d", right, n);
}

static void test_ask_back(void)
{
    int n = (int)(sizeof ask_back / sizeof ask_back[0]);
    for (int i = 0; i < n; i++) {
        sp_agent_intent in;
        sp_agent_parse(ask_back[i], &in);
        CHECK_MSG(in.kind == SP_AGENT_INTENT_ASK && in.question[0], "\"%s\" -> %s \"%s\"", ask_back[i],
                  sp_agent_intent_name(in.kind), in.target);
    }
}

static void test_structure(void)
{
    sp_agent_intent in;
    sp_agent_parse("go to the red mug on the counter", &in);
    CHECK(same(in.head, "mug"));
    CHECK(same(in.relation, "on"));
    CHECK(same(in.anchor, "counter"));
    sp_agent_parse("go there", &in);
    CHECK(in.kind == SP_AGENT_INTENT_GOTO && in.pronoun && !in.target[0]);
    sp_agent_parse("show me 9 routes to the bed", &in);
    CHECK(in.kind == SP_AGENT_INTENT_TRAJECTORIES && in.k == SP_AGENT_MAX_K);
    sp_agent_parse("the one in the kitchen", &in);
    CHECK(in.kind == SP_AGENT_INTENT_SELECT && same(in.relation, "in") && same(in.anchor, "kitchen"));
}

/* Arbitrary bytes: never a crash, always a kind. */
static void test_garbage(void)
{
    test_rng rng = {12345};
    char buf[1400];
    for (int it = 0; it < 2000; it++) {
        int n = (int)test_range(&rng, 0, sizeof buf - 1);
        for (int i = 0; i < n; i++) buf[i] = (char)(1 + (int)test_range(&rng, 0, 255));
        buf[n] = 0;
        sp_agent_intent in;
        sp_agent_parse(buf, &in);
        CHECK(in.kind >= SP_AGENT_INTENT_ASK && in.kind <= SP_AGENT_INTENT_SELECT);
    }
    sp_agent_intent in;
    sp_agent_parse(NULL, &in);
    CHECK(in.kind == SP_AGENT_INTENT_ASK);
}

int main(void)
{
    RUN(test_table);
    RUN(test_held_out);
    RUN(test_fresh);
    RUN(test_ask_back);
    RUN(test_structure);
    RUN(test_garbage);
    return TEST_EXIT();
}
