/* The lexical text encoder on the phrasing tables (tests/semantic/phrases_*.json, written before
 * the scorer was tuned): precision@1 on the present phrasings, rejection of the absent ones, with
 * the one threshold SP_LEX_THRESHOLD for both worlds; plus WordNet reader and morphy checks and
 * bad input. Tuned on the house; the bookstore was measured without retuning (precision@1 0.815,
 * absent 0.92), then three general rules found from its misses raised it to 0.862 / 1.0, a
 * class's derived verbs in its definitions (issue 17 phase 2) to 0.877 / 1.0, and in phase 3
 * subsumption without depth decay (laptop -> computer) and the patient reading of a definition's
 * participle under a stranded preposition ("something to write on": desk, not "a written work")
 * to 0.908 / 1.0, the house unchanged at 0.912 / 1.0 (see docs/DESIGN.md; every bookstore gain
 * was chosen knowing its misses). The floors below are the issue's bar, 0.9 / 0.9, for both.
 * The office table (phrases_office.json, written blind with data/worlds/office.world by someone
 * who had not read or run the encoder) measured 0.688 / 0.969 on first run; since phase 4 it is
 * development data (its misses were read and their general causes fixed: 0.854 / 0.969, the house
 * 0.925, the bookstore 0.908), so its floor, 0.85 / 0.9, only guards against regressions.
 * The ward table (phrases_ward.json, data/worlds/ward.world: a hospital ward, written blind by
 * someone who had not read or run the encoder, and first run by the lead on the phase-4 encoder)
 * is the blind measurement now: 81/121 = 0.669 present, 27/32 = 0.844 absent; printed, no bar.
 * The garage (phrases_garage.json, data/worlds/garage.world, written blind, first run by the lead on
 * the phase-4 and phase-5 encoders: 94/139 = 0.676, 29/30, both times) is development data since
 * phase 6 (the alias table, data/semantic/aliases.json, and l8's regions: its region and relation
 * misses were read), like all five tables: every floor below guards against regressions. Each
 * table also prints precision@1 on its region and relation phrasings, and test_region_rules
 * checks the region rules on a vocabulary of general classes. The blind tables now are the cafe
 * (phrases_cafe.json, data/worlds/cafe.world: a coffee shop) and the basement
 * (phrases_basement.json, data/worlds/basement.world: a laundry room, a utility and storage corner
 * and a home gym), written by helpers who had not read or run the encoder, never read by those
 * who wrote phase 6 (first runs: docs/DESIGN.md); since phase 7 (l9-lexical) they are
 * development data too, with regression floors. So are, since phase 8 and phase 9, the classroom
 * (phrases_classroom.json, data/worlds/classroom.world: a primary-school classroom with a
 * reading corner and the teacher's area, by w6-blind), the hotel (phrases_hotel.json,
 * data/worlds/hotel.world: a hotel room with its en-suite bathroom and entrance hall, by
 * w7-blind), the grocery (phrases_grocery.json, data/worlds/grocery.world: a corner shop with
 * its till, aisles, chilled section and stock room, by w8-blind) and the chemistry lab
 * (phrases_chemlab.json, data/worlds/chemlab.world: a university teaching laboratory with its
 * prep room, by w9-blind), and since phase 10 (l12-lexical) the pharmacy (phrases_pharmacy.json,
 * data/worlds/pharmacy.world: a neighbourhood pharmacy with its dispensary, by w10-blind) and the
 * hair salon (phrases_salon.json, data/worlds/salon.world, by w11-blind), and since phase 11
 * (l13-lexical) the warehouse (phrases_warehouse.json, data/worlds/warehouse.world, by w12-blind)
 * and the apartment (phrases_apartment.json, data/worlds/apartment.world, by w13-blind). The
 * tables after the floors are printed with their misses and no bar: the hospital
 * (phrases_hospital.json, data/worlds/hospital.world: reception, waiting area, corridor, nurses'
 * station, patient rooms, an examination room and a supply room, by w14-blind) and the small
 * house (phrases_smallhouse.json, data/worlds/smallhouse.world: a single-storey family house, by
 * w15-blind), the gym (phrases_gym.json, data/worlds/gym.world: lobby, cardio and weights areas,
 * a stretching corner and changing rooms, by w16-blind) and the museum (phrases_museum.json,
 * data/worlds/museum.world: entrance hall, galleries, gift shop, cafe, by w17-blind), written by
 * helpers who had not read or run the encoder; their first runs (on phases 10 to 12, none of
 * which saw them) are in docs/DESIGN.md and phrases_*_first_run.txt; since phase 13 (l15-lexical)
 * they are development data too, with floors. The library (phrases_library.json,
 * data/worlds/library.world: a public library with its children's corner and workroom, by
 * w18-blind) and the restaurant (phrases_restaurant.json, data/worlds/restaurant.world: dining
 * room, bar, kitchen, store and office, by w19-blind) were first run on phase 13, which never
 * saw them (phrases_*_first_run.txt); since phase 14 (l16-lexical) they are development data too,
 * with floors. The veterinary clinic (phrases_vetclinic.json, data/worlds/vetclinic.world, by
 * w20-blind) and the railway station (phrases_station.json, data/worlds/station.world, by
 * w21-blind) were first run on phase 14, which never saw them (phrases_*_first_run.txt); since
 * phase 15 (l17-lexical) they are development data too, with floors. The cinema
 * (phrases_cinema.json, by w22-blind) and the fire station (phrases_firestation.json, by
 * w23-blind) were first run on main a1be5f5's encoder, the bowling centre (phrases_bowling.json,
 * by w24-blind) and the airport terminal (phrases_airport.json, by w25-blind) on main f5d5db6
 * (that encoder with a17-lexicon's general aliases and regions); since phase 16 (l18-lexical)
 * they are development data too, with floors. The open-plan office (phrases_openoffice.json, by
 * w27-blind) and the family home (phrases_familyhome.json, by w26-blind) were first run on main
 * 682ca96's encoder (with the activity table), which never saw them; they are printed after the
 * floors with no bar. Run with an argument
 * (house | bookstore | office | ward | garage | cafe | basement | classroom | hotel | grocery |
 * chemlab | pharmacy | salon | warehouse | apartment | hospital | smallhouse | gym | museum | library | restaurant |
 * vetclinic | station | cinema | firestation | bowling | airport | openoffice | familyhome) to
 * print every phrase of one table, and a query after it to print its explanation. */
#include <cjson/cJSON.h>
#include <unistd.h>

#include "semantic/lexical.h"
#include "semantic/wordnet.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "test.h"

static const char *wordnet_dir(void)
{
    return SP_LEX_DEFAULT_WORDNET;
}

static int have_wordnet(void)
{
    char p[512];
    snprintf(p, sizeof p, "%s/index.noun", wordnet_dir());
    return access(p, R_OK) == 0;
}

static void test_reader(void)
{
    sp_error err = {0};
    wn_db *db = NULL;
    CHECK_OK(wn_open(&db, wordnet_dir(), &err), &err);
    if (!db) return;
    uint32_t offs[WN_MAX_SENSES];
    /* index.noun: "tv n 2 6 @ ~ #p %p ; - 2 2 06277280 04405907" */
    int n = wn_lookup(db, WN_NOUN, "tv", offs, WN_MAX_SENSES, NULL, &err);
    CHECK(n == 2);
    CHECK(n == 2 && offs[0] == 6277280u && offs[1] == 4405907u);
    CHECK(wn_lookup(db, WN_NOUN, "coffee table", offs, WN_MAX_SENSES, NULL, &err) == 1);
    CHECK(wn_lookup(db, WN_NOUN, "zzzz-no-such-word", offs, WN_MAX_SENSES, NULL, &err) == 0);
    CHECK(wn_lookup(db, WN_NOUN, "a", offs, WN_MAX_SENSES, NULL, &err) >= 1); /* first lemma */
    CHECK(wn_lookup(db, WN_NOUN, "zymurgy", offs, WN_MAX_SENSES, NULL, &err) == 1); /* last */
    wn_synset s;
    wn_id id = {4405907u, WN_NOUN};
    CHECK_OK(wn_read(db, id, &s, &err), &err);
    CHECK(s.n_words == 9 && !strcmp(s.words[0], "television_receiver") && !strcmp(s.words[3], "tv"));
    CHECK(s.n_pointers == 4 && !strcmp(s.pointers[0].symbol, "@") && s.pointers[0].target.offset == 4060647u);
    CHECK(strstr(s.gloss, "receives television signals") != NULL);
    wn_synset_free(&s);
    wn_id bad = {4405908u, WN_NOUN}; /* inside a line, not a synset */
    CHECK_FAILS(wn_read(db, bad, &s, &err), SP_E_FORMAT, &err, "data.noun");
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    struct { wn_pos pos; const char *word, *base; } morph[] = {
        {WN_NOUN, "chairs", "chair"},        {WN_NOUN, "shelves", "shelf"},
        {WN_NOUN, "geese", "goose"},         {WN_NOUN, "boxes", "box"},
        {WN_NOUN, "benches", "bench"},       {WN_NOUN, "women", "woman"},
        {WN_NOUN, "libraries", "library"},   {WN_NOUN, "coffee_tables", "coffee_table"},
        {WN_NOUN, "glass", "glass"},         {WN_VERB, "sitting", "sit"},
        {WN_VERB, "placed", "place"},        {WN_VERB, "ran", "run"},
        {WN_VERB, "stores", "store"},        {WN_ADJ, "bigger", "big"},
    };
    for (size_t i = 0; i < sizeof morph / sizeof morph[0]; i++) {
        int nb = wn_morphy(db, morph[i].pos, morph[i].word, b, &err);
        int hit = 0;
        for (int k = 0; k < nb; k++) hit |= !strcmp(b[k], morph[i].base);
        CHECK_MSG(hit, "morphy %s -> %s (got %d forms, first '%s')", morph[i].word, morph[i].base, nb,
                  nb > 0 ? b[0] : "");
    }
    CHECK(wn_morphy(db, WN_NOUN, "glass", b, &err) == 1); /* "-ss" is not a plural */
    wn_close(db);
    /* A missing database names the file and the package. */
    CHECK_FAILS(wn_open(&db, "/nonexistent/wordnet", &err), SP_E_NOTFOUND, &err, "wordnet-base");
}

/* A WordNet folder of links to the real files but for one file written here. */
static const char *fake_wordnet(const char *name, const char *file, const char *text)
{
    const char *dir = test_tmpdir(name);
    const char *files[] = {"index.noun", "index.verb", "index.adj", "index.adv", "data.noun", "data.verb",
                           "data.adj", "data.adv", "noun.exc", "verb.exc", "adj.exc", "adv.exc"};
    char a[1200], b[1200];
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(b, sizeof b, "%s/%s", dir, files[i]);
        if (!strcmp(files[i], file)) {
            FILE *f = fopen(b, "w");
            if (f) fputs(text, f), fclose(f);
            continue;
        }
        snprintf(a, sizeof a, "%s/%s", wordnet_dir(), files[i]);
        if (symlink(a, b) != 0) fprintf(stderr, "cannot link %s\n", b);
    }
    return dir;
}

static void test_bad_input(void)
{
    sp_error err = {0};
    sp_lexicon *lx = NULL;
    CHECK_FAILS(sp_lexicon_open(&lx, fake_wordnet("wn_empty", "data.noun", ""), &err), SP_E_FORMAT, &err,
                "data.noun: empty file");
    CHECK_FAILS(sp_lexicon_open(&lx, fake_wordnet("wn_trunc", "data.noun", "  1 license\n00001740 03 n 01 entity"),
                                &err), SP_E_FORMAT, &err, "data.noun");
    char other[2100]; /* a synset line where WordNet 3.0 has 'entity', naming something else */
    memset(other, ' ', 1739);
    other[1739] = '\n';
    snprintf(other + 1740, sizeof other - 1740, "00001740 03 n 01 thing 0 000 | x\n");
    CHECK_FAILS(sp_lexicon_open(&lx, fake_wordnet("wn_other", "data.noun", other), &err), SP_E_FORMAT, &err,
                "not 'entity'");
    CHECK(lx == NULL);
    CHECK_OK(sp_lexicon_open(&lx, NULL, &err), &err);
    if (!lx) return;
    sp_lex_vocab *v = NULL;
    const char *empty[] = {"chair", ""};
    CHECK_FAILS(sp_lex_vocab_create(&v, lx, empty, 2, "", &err), SP_E_ARG, &err, "class 1");
    const char *names[] = {"chair", "sofa", "lamp"};
    const char *dir = test_tmpdir("lex_regions");
    char path[1200];
    snprintf(path, sizeof path, "%s/regions.json", dir);
    FILE *f = fopen(path, "w");
    if (f) fputs("{\"kitchen\": \"stove\"}", f), fclose(f);
    CHECK_FAILS(sp_lex_vocab_create(&v, lx, names, 3, path, &err), SP_E_FORMAT, &err, "kitchen");
    CHECK(sp_lex_vocab_create(&v, lx, names, 3, "/nonexistent/regions.json", &err) != 0);
    CHECK_MSG(strstr(err.msg, "regions.json") != NULL, "%s", err.msg);
    CHECK_OK(sp_lex_vocab_create(&v, lx, names, 3, "", &err), &err);
    sp_lex_result *res = malloc(sizeof *res);
    if (v && res) {
        CHECK_FAILS(sp_lex_match(v, "", res, &err), SP_E_ARG, &err, "no words");
        CHECK_FAILS(sp_lex_match(v, "?! ...", res, &err), SP_E_ARG, &err, "no words");
        CHECK_OK(sp_lex_match(v, "zxqvw blorft", res, &err), &err);
        CHECK(!res->found && res->confidence < SP_LEX_THRESHOLD);
        char longtext[8192] = "";
        for (int i = 0; i < 600; i++) strcat(longtext, i % 7 ? "very " : "the big red ");
        strcat(longtext, "sofa");
        CHECK_OK(sp_lex_match(v, longtext, res, &err), &err); /* 32 words kept, no crash */
        CHECK_OK(sp_lex_match(v, "caf\xc3\xa9 \xff\xfe sofa", res, &err), &err);
        CHECK(res->found && !strcmp(sp_lex_vocab_class(v, res->target.matches[0].class_index), "sofa"));
        /* As an embedding: "sofa" is the sofa's label vector, "giraffe" nothing. */
        float e[512], ref[512], conf = 0;
        CHECK_OK(sp_lex_embed(v, "sofas", 512, e, &conf, &err), &err);
        sp_label_embedding("sofa", 512, ref);
        double dot = 0;
        for (int j = 0; j < 512; j++) dot += (double)e[j] * ref[j];
        CHECK_NEAR(dot, 1.0, 1e-5);
        CHECK_NEAR(conf, 1.0, 1e-6);
        CHECK_OK(sp_lex_embed(v, "giraffe", 512, e, &conf, &err), &err);
        CHECK(conf < SP_LEX_THRESHOLD && e[0] == 0.0f && e[511] == 0.0f);
        char *js = sp_lex_result_json(res, v, 0.0f);
        CHECK(js && strstr(js, "\"encoder\":\t\"lexical\""));
        free(js);
    }
    free(res);
    sp_lex_vocab_free(v);
    sp_lexicon_free(lx);
}

/* The top class of text in v, "" when nothing is found. */
static const char *found_class(const sp_lex_vocab *v, const char *text, sp_lex_result *res)
{
    sp_error err = {0};
    if (sp_lex_match(v, text, res, &err) || !res->found) return "";
    return sp_lex_vocab_class(v, res->target.matches[0].class_index);
}

/* A vocabulary of names and a result to match into; 1 (both freed) when either failed. */
static int rules_vocab(const sp_lexicon *lx, const char **names, int n, sp_lex_vocab **v, sp_lex_result **res)
{
    sp_error err = {0};
    CHECK_OK(sp_lex_vocab_create(v, lx, names, n, NULL, &err), &err);
    *res = malloc(sizeof **res);
    if (*v && *res) return 0;
    free(*res), sp_lex_vocab_free(*v);
    *res = NULL, *v = NULL;
    return 1;
}

/* The activity table (data/semantic/uses.json): every entry has a verb first and 1-4 names; a
 * query asking to do a thing finds what affords it, one weak step below a named thing; the verb
 * only counts used as a verb ("cash machine" is no "get cash"); kinds with another modifier do not
 * take the reading; a thing the scene lacks finds nothing through it. */
static void test_uses(const sp_lexicon *lx)
{
    char path[2048];
    sp_path_join(path, sizeof path, sp_data_dir(), "semantic/uses.json");
    cJSON *js = NULL;
    sp_error err = {0};
    CHECK_OK(sp_json_read_file(path, &js, &err), &err);
    const cJSON *uses = cJSON_GetObjectItemCaseSensitive(js, "uses"), *it;
    int n = 0;
    cJSON_ArrayForEach(it, uses) {
        n++;
        char first[64];
        sscanf(it->string, "%63s", first);
        CHECK_MSG(lex_is_pos((const lex_db *)lx, WN_VERB, first, &err) > 0, "use '%s': '%s' is no WordNet verb",
                  it->string, first);
        CHECK_MSG(cJSON_GetArraySize(it) >= 1 && cJSON_GetArraySize(it) <= 4, "use '%s': 1 to 4 names", it->string);
    }
    cJSON_Delete(js);
    CHECK_MSG(n >= 100, "%d activities", n);
    const char *classes[] = {"sink", "toilet", "ticket machine", "kiosk counter", "cash machine", "bed"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, classes, 6, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "where can I wash my hands", res), "sink"));
    CHECK(strstr(res->target.matches[0].path, "activity 'wash hand' is done with") != NULL);
    CHECK(res->confidence <= LEX_USE + 1e-6f);
    CHECK(!strcmp(found_class(v, "where do I buy a ticket", res), "ticket machine"));
    for (int i = 0; i < res->target.n_matches; i++) /* no reading through "counter" alone */
        if (!strcmp(sp_lex_vocab_class(v, res->target.matches[i].class_index), "kiosk counter"))
            CHECK(!strstr(res->target.matches[i].path, "activity"));
    CHECK(!strcmp(found_class(v, "cash machine", res), "cash machine"));
    CHECK(!strstr(res->target.matches[0].path, "activity"));
    sp_lex_vocab_free(v);
    free(res);
    const char *none[] = {"bed", "wardrobe"};
    if (rules_vocab(lx, none, 2, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "where can I wash my hands", res), ""));
    sp_lex_vocab_free(v);
    /* a user's uses.json beside the region table they pass adds its activities; a bad one fails */
    const char *dir = test_tmpdir("lex_uses");
    char rp[1200], up[1200];
    snprintf(rp, sizeof rp, "%s/regions.json", dir);
    snprintf(up, sizeof up, "%s/uses.json", dir);
    FILE *f = fopen(rp, "w");
    if (f) fputs("{\"lounge\": [\"sofa\"]}", f), fclose(f);
    f = fopen(up, "w");
    if (f) fputs("{\"uses\": {\"juggle ball\": [\"toy box\"]}}", f), fclose(f);
    const char *mine[] = {"toy box", "sink"};
    v = NULL;
    CHECK_OK(sp_lex_vocab_create(&v, lx, mine, 2, rp, &err), &err);
    if (v && res) {
        CHECK_OK(sp_lex_match(v, "where can I juggle some balls", res, &err), &err);
        CHECK(res->found && !strcmp(sp_lex_vocab_class(v, res->target.matches[0].class_index), "toy box"));
        CHECK(strstr(res->target.matches[0].path, "activity 'juggle ball'") != NULL);
    }
    sp_lex_vocab_free(v);
    f = fopen(up, "w");
    if (f) fputs("{\"uses\": {\"juggle ball\": \"toy box\"}}", f), fclose(f);
    v = NULL;
    CHECK_FAILS(sp_lex_vocab_create(&v, lx, mine, 2, rp, &err), SP_E_FORMAT, &err, "juggle ball");
    free(res);
}

/* The alias table (data/semantic/aliases.json, issue 17 phase 6): every target is a WordNet noun
 * (no scene's class strings), no name is a class of the five development tables, and names are
 * another reading: whole words, plurals, never inside a WordNet collocation, whole class names. */
static void test_aliases(const sp_lexicon *lx)
{
    char path[2048];
    sp_path_join(path, sizeof path, sp_data_dir(), "semantic/aliases.json");
    cJSON *js = NULL;
    sp_error err = {0};
    CHECK_OK(sp_json_read_file(path, &js, &err), &err);
    const cJSON *names = cJSON_GetObjectItemCaseSensitive(js, "names"), *it, *t;
    int n = 0;
    const char *worlds[] = {"house", "bookstore", "office", "ward", "garage"};
    cJSON *tables[5] = {0};
    for (int w = 0; w < 5; w++) {
        char tp[2048];
        snprintf(tp, sizeof tp, "%s/tests/semantic/phrases_%s.json", SP_SOURCE_DIR, worlds[w]);
        CHECK_OK(sp_json_read_file(tp, &tables[w], &err), &err);
    }
    cJSON_ArrayForEach(it, names) {
        n++;
        for (int w = 0; w < 5; w++) {
            const cJSON *c;
            cJSON_ArrayForEach(c, cJSON_GetObjectItem(tables[w], "classes"))
                CHECK_MSG(strcmp(c->valuestring, it->string), "alias '%s' names a class of %s", it->string, worlds[w]);
        }
        cJSON_ArrayForEach(t, it) {
            uint32_t off;
            char lemma[WN_LEMMA_MAX];
            snprintf(lemma, sizeof lemma, "%s", t->valuestring);
            int k = wn_lookup(((const lex_db *)lx)->db, WN_NOUN, lemma, &off, 1, NULL, &err);
            CHECK_MSG(k == 1, "alias '%s': target '%s' is no WordNet noun", it->string, lemma);
        }
    }
    for (int w = 0; w < 5; w++) cJSON_Delete(tables[w]);
    cJSON_Delete(js);
    CHECK_MSG(n >= 400, "%d aliases", n);
    const char *classes[] = {"vacuum cleaner", "wheelie bin", "laundry cart", "garbage can", "television"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, classes, 5, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "shop vac", res), "vacuum cleaner"));
    CHECK(!strcmp(found_class(v, "the shop vacs", res), "vacuum cleaner")); /* a plural */
    CHECK(strstr(res->target.matches[0].path, "alias 'vac' = vacuum cleaner") != NULL); /* 'shop' + vac */
    CHECK(!strcmp(found_class(v, "hoover", res), "vacuum cleaner")); /* WordNet: a person, a verb */
    CHECK(!strcmp(found_class(v, "telly", res), "television"));
    /* a class that is wholly an alias is read through it: the wheelie bin is a garbage can */
    CHECK(!strcmp(found_class(v, "ashcan", res), "garbage can") || !strcmp(found_class(v, "ashcan", res), "wheelie bin"));
    int both = 0;
    for (int i = 0; i < res->target.n_matches; i++)
        both += res->target.matches[i].score >= SP_LEX_THRESHOLD;
    CHECK(both == 2);
    /* "trolley" is an alias (a handcart), but no alias is read inside WordNet's "laundry cart" */
    lex_tokens in = {1, {"laundry_cart"}}, out;
    CHECK(lex_alias_rewrite(v, &in, 0, &out, NULL, 0) == 0 && out.n == 1 && !strcmp(out.w[0], "laundry_cart"));
    lex_tokens two = {2, {"a", "trolley"}};
    char used[160];
    CHECK(lex_alias_rewrite(v, &two, 0, &out, used, sizeof used) == 1 && out.n == 2 && !strcmp(out.w[1], "handcart"));
    CHECK_MSG(!strcmp(used, "'trolley' = handcart"), "%s", used);
    sp_lex_vocab_free(v);
    /* a scene's own class name shadows the alias of the same words: "card terminal" is an alias
     * of the cash register, but where a class is called that, it is that class */
    const char *shop[] = {"cash register", "card terminal", "trolley"};
    free(res);
    if (rules_vocab(lx, shop, 3, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "card terminal", res), "card terminal"));
    CHECK(!strcmp(found_class(v, "a trolley", res), "trolley"));
    CHECK(!strcmp(found_class(v, "the till", res), "cash register"));
    sp_lex_vocab_free(v);
    /* a class's full name is that class, also when WordNet joins words of its modifiers ("blood
     * pressure" is a WordNet collocation) */
    const char *clinic[] = {"computer monitor", "blood pressure monitor"};
    free(res);
    if (rules_vocab(lx, clinic, 2, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "blood pressure monitor", res), "blood pressure monitor"));
    CHECK(res->target.matches[0].kind == SP_LEX_EXACT);
    CHECK(!strcmp(found_class(v, "the computer monitor", res), "computer monitor"));
    sp_lex_vocab_free(v);
    /* a user's aliases.json beside the region table they pass adds its names; a bad one fails */
    const char *dir = test_tmpdir("lex_aliases");
    char rp[1200], ap[1200];
    snprintf(rp, sizeof rp, "%s/regions.json", dir);
    snprintf(ap, sizeof ap, "%s/aliases.json", dir);
    FILE *f = fopen(rp, "w");
    if (f) fputs("{\"lounge\": [\"sofa\"]}", f), fclose(f);
    f = fopen(ap, "w");
    if (f) fputs("{\"names\": {\"zorbo\": [\"sofa\"]}}", f), fclose(f);
    const char *mine[] = {"sofa", "lamp"};
    v = NULL;
    CHECK_OK(sp_lex_vocab_create(&v, lx, mine, 2, rp, &err), &err);
    if (v && res) {
        CHECK_OK(sp_lex_match(v, "the zorbo", res, &err), &err);
        CHECK(res->found && !strcmp(sp_lex_vocab_class(v, res->target.matches[0].class_index), "sofa"));
    }
    sp_lex_vocab_free(v);
    f = fopen(ap, "w");
    if (f) fputs("{\"names\": {\"zorbo\": 3}}", f), fclose(f);
    v = NULL;
    CHECK_FAILS(sp_lex_vocab_create(&v, lx, mine, 2, rp, &err), SP_E_FORMAT, &err, "zorbo");
    free(res);
}

/* The phase-4 rules one by one (docs/DESIGN.md, changes 6-13), on a vocabulary of their own. */
static void test_phase4_rules(const sp_lexicon *lx)
{
    const char *names[] = {"trash can", "monitor", "printer", "water cooler", "plant",
                           "projector screen", "conference table", "whiteboard", "stove", "desk"};
    sp_error err = {0};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, names, 10, &v, &res)) return;
    /* 6: "trash can" is WordNet's trash_can ("can" is not dropped as an auxiliary) */
    CHECK(!strcmp(found_class(v, "dustbin", res), "trash can"));
    CHECK(!strcmp(found_class(v, "garbage cans", res), "trash can"));
    /* 7: a table region WordNet does not join, read whole */
    const char *top = found_class(v, "the meeting room", res);
    CHECK_MSG(!strcmp(top, "conference table") || !strcmp(top, "projector screen") || !strcmp(top, "whiteboard"),
              "the meeting room -> '%s'", top);
    CHECK(res->target.is_region && !strcmp(res->target.region, "meeting room"));
    /* 8: a class is no person: "monitor" the display, not the supervisor */
    CHECK(!strcmp(found_class(v, "a display", res), "monitor"));
    CHECK(!strcmp(found_class(v, "laser printer", res), "printer"));
    /* 11: agent nouns; a past participle ("can be projected") and a person ("writer") are not */
    CHECK(!strcmp(found_class(v, "water dispenser", res), "water cooler"));
    CHECK(!strcmp(found_class(v, "cooker", res), "stove"));
    CHECK(!strcmp(found_class(v, "projector", res), ""));
    CHECK(!strcmp(found_class(v, "a writer", res), ""));
    /* 13: a genus stands for its members */
    CHECK(!strcmp(found_class(v, "ficus", res), "plant"));
    sp_lex_vocab_free(v);
    /* ... but a name that names no artifact keeps its persons */
    const char *people[] = {"person", "sofa"};
    v = NULL;
    CHECK_OK(sp_lex_vocab_create(&v, lx, people, 2, NULL, &err), &err);
    if (v) CHECK(!strcmp(found_class(v, "someone", res), "person"));
    free(res);
    sp_lex_vocab_free(v);
}

/* Phase-5 rules (issue 17, the ward as development data). */
static void test_phase5_rules(const sp_lexicon *lx)
{
    const char *names[] = {"overbed table", "iv stand", "patient bed", "whiteboard", "privacy curtain"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, names, 5, &v, &res)) return;
    /* a modifier WordNet lacks ("overbed") specializes: another kind of table is a sibling, the
     * bare head still matches, and the modifier's parts agree ("bed table") */
    CHECK(!strcmp(found_class(v, "operating table", res), ""));
    CHECK(!strcmp(found_class(v, "dining table", res), ""));
    CHECK(!strcmp(found_class(v, "a table", res), "overbed table"));
    CHECK(!strcmp(found_class(v, "bed table", res), "overbed table"));
    /* a split query names its own kind ("nightstand" is no IV stand); the same split agrees */
    CHECK(!strcmp(found_class(v, "nightstand", res), ""));
    CHECK(!strcmp(found_class(v, "whiteboards", res), "whiteboard"));
    /* "between" is a relation */
    CHECK(!strcmp(found_class(v, "the curtain between the beds", res), "privacy curtain"));
    CHECK(!strcmp(res->relation, "between"));
    sp_lex_vocab_free(v);
    free(res);
}

/* Region and relation rules of l8 (issue 17): names the region table lacks, read through WordNet
 * and the table's own names; a vocabulary of general classes, not one of the tables' worlds. */
/* Phase 7 (l9-lexical): accents and typographic apostrophes fold to ASCII; a joined class name
 * is a kind of its last word; a holder is found by what its modifier names; a class name that
 * names an artifact is no physical process. */
static void test_phase7_rules(const sp_lexicon *lx)
{
    lex_tokens t;
    lex_tokenize("Caf\xc3\xa9 cr\xc3\xa8me the fridge\xe2\x80\x99s door", &t);
    CHECK(t.n == 5);
    if (t.n == 5) {
        CHECK(!strcmp(t.w[0], "cafe"));
        CHECK(!strcmp(t.w[1], "creme"));
        CHECK(!strcmp(t.w[3], "fridge"));
    }
    const char *names[] = {"washing machine", "dumbbell rack", "projector screen", "microwave", "chair"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, names, 5, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "machine", res), "washing machine"));
    CHECK(!strcmp(found_class(v, "dumbbells", res), "dumbbell rack"));
    CHECK(!strcmp(found_class(v, "microwave oven", res), "microwave"));
    CHECK(!strcmp(found_class(v, "projector", res), "")); /* a screen holds no projector */
    CHECK(!strcmp(found_class(v, "kettlebell", res), ""));
    free(res);
    sp_lex_vocab_free(v);
}

static void test_region_rules(const sp_lexicon *lx)
{
    const char *names[] = {"stove", "bed", "sofa", "printer", "car", "bicycle", "water heater", "chest freezer",
                           "shelving unit", "storage bin", "rug", "door", "window", "crib", "toilet", "bathtub",
                           "charging station"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, names, 17, &v, &res)) return;
    /* an area named by an activity: the classes that do it ("something to cook") */
    CHECK(!strcmp(found_class(v, "the cooking area", res), "stove") && res->target.is_region);
    CHECK(!strcmp(found_class(v, "the sleeping corner", res), "bed") && res->target.is_region);
    CHECK(!strcmp(found_class(v, "the printing area", res), "printer") && res->target.is_region);
    /* the generic word is style: "utility corner" is the table's "utility room"; a WordNet
     * collocation of an area ("parking area") that is no room reads the same way (a table region
     * needs two of its kinds here: car and bicycle) */
    const char *top = found_class(v, "the utility corner", res);
    CHECK_MSG(res->target.is_region && !strcmp(res->target.region, "utility room") &&
                  (!strcmp(top, "water heater") || !strcmp(top, "chest freezer")), "utility corner -> '%s' [%s]", top,
              res->target.region);
    CHECK(!strcmp(found_class(v, "the parking area", res), "car") && res->target.is_region);
    /* a WordNet room the table lacks is the table's nearest kind of room it is ("washroom": a
     * bathroom, one step up) */
    top = found_class(v, "the washroom", res);
    CHECK_MSG(res->target.is_region && !strcmp(res->target.region, "bathroom") &&
                  (!strcmp(top, "toilet") || !strcmp(top, "bathtub")), "washroom -> '%s' [%s]", top, res->target.region);
    /* a "where" clause about things is their place; a question or a person's doing is not */
    CHECK(!strcmp(found_class(v, "where the car is parked", res), "car") && res->target.is_region);
    found_class(v, "where I can cook", res);
    CHECK(!res->target.is_region);
    found_class(v, "where is the car", res);
    CHECK(!res->target.is_region);
    /* a part of a place: the anchor is the place */
    CHECK(!strcmp(found_class(v, "the rug in the middle of the storage area", res), "rug"));
    CHECK(!strcmp(res->relation, "in") && res->anchor.is_region && !strcmp(res->anchor.region, "storage area"));
    top = found_class(v, "the far end of the storage room", res); /* either member: they tie at 1.00 */
    CHECK_MSG(res->target.is_region && (!strcmp(top, "shelving unit") || !strcmp(top, "storage bin")),
              "the far end of the storage room -> '%s'", top);
    /* a reduced relative clause's participle is dropped from the target; "nearest to" is near */
    CHECK(!strcmp(found_class(v, "the rug lying in front of the sofa", res), "rug") &&
          !strcmp(res->relation, "in front of"));
    CHECK(!strcmp(found_class(v, "the bicycle nearest to the door", res), "bicycle") && !strcmp(res->relation, "near"));
    /* "between X and Y": both phrases anchor it */
    found_class(v, "the rug between the sofa and the bed", res);
    int has_sofa = 0, has_bed = 0;
    for (int i = 0; i < res->anchor.n_matches; i++) {
        const char *c = sp_lex_vocab_class(v, res->anchor.matches[i].class_index);
        if (res->anchor.matches[i].score < SP_LEX_THRESHOLD) continue;
        has_sofa |= !strcmp(c, "sofa"), has_bed |= !strcmp(c, "bed");
    }
    CHECK_MSG(!strcmp(res->relation, "between") && has_sofa && has_bed, "between: relation '%s', sofa %d, bed %d",
              res->relation, has_sofa, has_bed);
    /* a class named with a generic area word ("station") is still split off its relation */
    CHECK(!strcmp(found_class(v, "the charging station next to the door", res), "charging station") &&
          !strcmp(res->relation, "next to"));
    /* ... but a lone "nearest" is an adjective, not a preposition: "the nearest bed" keeps its head */
    CHECK(!strcmp(found_class(v, "the nearest bed", res), "bed") && res->target.matches[0].kind != SP_LEX_GLOSS);
    /* classes named after an area's words are its members ("the freezer corner": the chest freezer) */
    CHECK(!strcmp(found_class(v, "the freezer corner", res), "chest freezer") && res->target.is_region);
    /* else whom it is for: "something for a baby" */
    CHECK(!strcmp(found_class(v, "the baby corner", res), "crib") && res->target.is_region);
    /* a generic word with a modifier naming an object of the scene stays that object's area */
    CHECK(!strcmp(found_class(v, "the sofa corner", res), "sofa") && res->target.is_region);
    /* a room of the table whose objects are not here matches nothing ("kitchenette": no fridge,
     * no sink, only the stove, one kind) */
    CHECK(!strcmp(found_class(v, "the kitchenette", res), ""));
    sp_lex_vocab_free(v);
    free(res);
}

/* Phase 8 (issue 17, l10-lexical; docs/DESIGN.md changes 41-60), rule by rule on general
 * vocabularies. */
static void test_phase8_rules(const sp_lexicon *lx)
{
    const char *names[] = {"bookshelf", "teacher chair", "student chair", "teacher desk", "table lamp",
                           "sink", "toilet", "bathtub", "radiator", "luggage rack", "nightstand",
                           "desk lamp", "bed", "walls", "floor", "armchair", "sofa", "coffee table"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, names, 18, &v, &res)) return;
    /* a "where" clause with a subject: a description when its place names nothing */
    CHECK(!strcmp(found_class(v, "where the books are kept", res), "bookshelf"));
    CHECK(!strcmp(found_class(v, "where the teacher sits", res), "teacher chair"));
    /* what the thing does ("a lamp that sits on a table") is no place to sit */
    CHECK(strcmp(found_class(v, "something to sit on", res), "table lamp") && res->found);
    CHECK(!strcmp(found_class(v, "where can I lie down", res), "bed")); /* not walls: a layer "lying over" */
    /* a class that is an artifact drops its room senses: "bathroom" is the region, not the toilet */
    found_class(v, "the bathroom", res);
    CHECK(res->found && res->target.is_region);
    CHECK(!strcmp(found_class(v, "the en-suite", res), "toilet") && res->target.is_region); /* an alias */
    /* WordNet's sitting room is a living room */
    found_class(v, "the sitting area", res);
    CHECK(res->found && res->target.is_region && !strcmp(res->target.region, "living room"));
    /* kinds' definitions: the washbasin is "where you can wash your hands" */
    CHECK(!strcmp(found_class(v, "where can I wash my hands", res), "sink"));
    /* ties: a target named with the anchor's word; a class whose name says the query's word */
    CHECK(!strcmp(found_class(v, "the chair at the teacher's desk", res), "teacher chair"));
    CHECK(!strcmp(found_class(v, "rack", res), "luggage rack"));
    /* the radiator is an artifact (the heater), not "any object that radiates energy" */
    CHECK(!strcmp(found_class(v, "heater", res), "radiator"));
    /* "light: any device serving as a source of illumination" finds the lamps */
    const char *top = found_class(v, "a light", res);
    CHECK(!strcmp(top, "desk lamp") || !strcmp(top, "table lamp"));
    /* a person's "where" clause names the table area of the activity: the reading area */
    found_class(v, "where the kids read", res);
    CHECK(res->found && res->target.is_region && !strcmp(res->target.region, "reading area"));
    free(res);
    sp_lex_vocab_free(v);
    /* "storage", an act: what one stores things in ("a cabinet ... for storage or display") */
    const char *home[] = {"cabinet", "bed", "walls", "floor", "armchair", "sofa", "sink", "door"};
    if (rules_vocab(lx, home, 8, &v, &res)) return;
    CHECK(!strcmp(found_class(v, "storage", res), "cabinet"));
    /* a way in a direction is the passage that goes there (the exit is an alias of the door) */
    CHECK(!strcmp(found_class(v, "the way out", res), "door"));
    CHECK(!strcmp(found_class(v, "how do I get outside", res), "door"));
    lex_tokens way;
    lex_tokenize("go up the stairs", &way);
    lex_way_direction(&way); /* a preposition with its object: left alone */
    CHECK(way.n == 4 && !strcmp(way.w[1], "up"));
    lex_tokenize("how do I get back up to the kitchen", &way);
    lex_way_direction(&way);
    CHECK(way.n == 7 && !strcmp(way.w[3], "stairs") && !strcmp(way.w[4], "to"));
    free(res);
    sp_lex_vocab_free(v);
}

typedef struct {
    int present, present_ok, absent, absent_ok, ignored_ok, ignored_total;
    int bin_n[4], bin_ok[4]; /* found results by confidence: [0.5,0.7) [0.7,0.9) [0.9,1] */
    int kind_n[2], kind_ok[2]; /* present phrasings of kind region, relation */
} tally;

static int bin_of(float c) { return c < 0.7f ? 0 : c < 0.9f ? 1 : 2; }

static int in_array(const cJSON *arr, const char *s)
{
    const cJSON *it;
    cJSON_ArrayForEach(it, arr)
        if (cJSON_IsString(it) && !strcmp(it->valuestring, s)) return 1;
    return 0;
}

/* The table names a relation by the word its writer used ("over"); the encoder reports the
 * canonical name of that spelling ("above"): compare through the encoder's own spelling table. */
static int same_relation(const char *got, const char *table)
{
    lex_tokens t;
    lex_tokenize(table, &t);
    const char *canon = NULL;
    int n = lex_relation_at(&t, 0, &canon);
    return !strcmp(got, table) || (n == t.n && canon && !strcmp(got, canon));
}

/* Phase 9 (issue 17, l11-lexical; docs/DESIGN.md change 62): a query modifier naming another
 * kind of thing than the class's modifier makes the query the class's sibling, on a general
 * vocabulary. */
static void test_phase9_rules(const sp_lexicon *lx)
{
    const char *names[] = {"magazine rack", "fruit stand", "storage shelf", "privacy curtain", "bed", "chair",
                           "bread rack", "espresso machine", "walls", "floor"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, names, 10, &v, &res)) return;
    /* 'M H' against 'M2 H' with M and M2 unrelated kinds of things: a sibling, not the class */
    CHECK_MSG(!strcmp(found_class(v, "wine rack", res), ""), "wine rack -> '%s'", found_class(v, "wine rack", res));
    CHECK(!strcmp(found_class(v, "shoe rack", res), ""));
    CHECK(!strcmp(found_class(v, "flower stand", res), ""));
    /* the bare head, a class without a modifier, an attribute, the class's own modifier */
    CHECK(!strcmp(found_class(v, "rack", res), "magazine rack") || !strcmp(found_class(v, "rack", res), "bread rack"));
    CHECK(!strcmp(found_class(v, "double bed", res), "bed"));
    CHECK(!strcmp(found_class(v, "office chair", res), "chair"));
    CHECK(!strcmp(found_class(v, "wooden magazine rack", res), "magazine rack"));
    /* a class modifier naming a purpose or a quality, not a kind ("storage", "privacy") */
    CHECK(!strcmp(found_class(v, "wire shelf", res), "storage shelf"));
    CHECK(!strcmp(found_class(v, "cubicle curtain", res), "privacy curtain"));
    /* related modifiers: one a kind of the other (espresso is a coffee) */
    CHECK(!strcmp(found_class(v, "coffee machine", res), "espresso machine"));
    /* a modifier with no attested sense ("bakery": WordNet's order says nothing) stays an
     * attribute, ignored and reported */
    CHECK(strcmp(found_class(v, "bakery rack", res), "") && res->n_ignored == 1);
    sp_lex_vocab_free(v);
    free(res);
}

/* Phase 10 (issue 17, l12-lexical; docs/DESIGN.md changes 63-68), on general vocabularies. */
static void test_phase10_rules(const sp_lexicon *lx)
{
    const char *salon[] = {"styling chair", "drying rack", "barber chair", "mop bucket", "ironing board",
                           "weighing scale", "luggage rack", "coat rack", "walls", "floor"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, salon, 10, &v, &res)) return;
    /* a gerund modifier names a kind: another kind of chair is a sibling, the head finds it */
    CHECK_MSG(!strcmp(found_class(v, "armchair", res), ""), "armchair -> '%s'", found_class(v, "armchair", res));
    CHECK(!strcmp(found_class(v, "rack", res), "drying rack") || !strcmp(found_class(v, "rack", res), "luggage rack") ||
          !strcmp(found_class(v, "rack", res), "coat rack"));
    /* a name's modifier by its commonest sense: barber, "who cuts hair and shaves beards" */
    CHECK_MSG(!strcmp(found_class(v, "where do I get a shave", res), "barber chair"), "shave -> '%s'",
              found_class(v, "where do I get a shave", res));
    /* the purpose verb weighs as much as its object (a shirt; the board is "for ironing clothes") */
    CHECK(!strcmp(found_class(v, "something to iron a shirt on", res), "ironing board"));
    /* the modifier chooses the head's sense: the scale for weighing, a measuring instrument */
    CHECK(!strcmp(found_class(v, "a measuring instrument", res), "weighing scale"));
    /* a description naming what a holder holds: a suitcase is luggage, a jacket a coat */
    CHECK(!strcmp(found_class(v, "where do I put my suitcase", res), "luggage rack"));
    CHECK(!strcmp(found_class(v, "somewhere to hang my jacket", res), "coat rack"));
    /* a support and what it holds name the holder of the same things ("luggage stand") */
    CHECK_MSG(!strcmp(found_class(v, "a luggage stand", res), "luggage rack"), "luggage stand -> '%s'",
              found_class(v, "a luggage stand", res));
    free(res);
    sp_lex_vocab_free(v);
    /* a category word with a modifier: what the modifier's area holds, furniture apart */
    const char *flat[] = {"microwave", "dishwasher", "kitchen counter", "sofa", "desk", "printer", "toilet",
                          "bathtub", "walls", "floor"};
    if (rules_vocab(lx, flat, 10, &v, &res)) return;
    const char *k = found_class(v, "kitchen equipment", res);
    CHECK_MSG(!strcmp(k, "microwave") || !strcmp(k, "dishwasher"), "kitchen equipment -> '%s'", k);
    k = found_class(v, "bathroom fittings", res);
    CHECK_MSG(!strcmp(k, "toilet") || !strcmp(k, "bathtub"), "bathroom fittings -> '%s'", k);
    CHECK(!strcmp(found_class(v, "office equipment", res), "printer"));
    CHECK(!strcmp(found_class(v, "office furniture", res), "desk"));
    free(res);
    sp_lex_vocab_free(v);
    /* a place's definition names what it is by its genus ("shower stall: a BOOTH for taking a
     * shower"), no member; a class named after the place is of it, alone too */
    const char *bath[] = {"shower", "nightstand", "bed", "walls", "floor", "door"};
    if (rules_vocab(lx, bath, 6, &v, &res)) return;
    CHECK_MSG(!strcmp(found_class(v, "the shower stall", res), "shower"), "shower stall -> '%s'",
              found_class(v, "the shower stall", res));
    free(res);
    sp_lex_vocab_free(v);
    /* a name that names an artifact has no animal sense (jack, the fish); a category's members
     * are of the category ("camping gear" is no floor) */
    const char *store[] = {"pallet jack", "forklift", "first aid kit", "walls", "floor", "door", "atm", "computer"};
    if (rules_vocab(lx, store, 8, &v, &res)) return;
    /* a kind WordNet names with its own word is no other kind of its hypernym: a coffee machine
     * is no atm (a machine), a cash machine is */
    CHECK_MSG(!strcmp(found_class(v, "a coffee machine", res), ""), "coffee machine -> '%s'",
              found_class(v, "a coffee machine", res));
    CHECK(!strcmp(found_class(v, "a cash machine", res), "atm"));
    for (int s = 0; s < v->classes[0].np.n_senses; s++) CHECK(!lex_sense_animal(&v->classes[0].np.senses[s]));
    CHECK(!strcmp(found_class(v, "fishing gear", res), ""));
    CHECK(!strcmp(found_class(v, "camping gear", res), "") || strcmp(found_class(v, "camping gear", res), "floor"));
    free(res);
    sp_lex_vocab_free(v);
}

/* phase 11 (l13-lexical), on a general depot and a general flat (no table's class list) */
static void test_phase11_rules(const sp_lexicon *lx)
{
    const char *depot[] = {"door", "roll up door", "table", "coffee table", "pallet jack", "hand truck",
                           "vending machine", "safety cone", "walls", "floor", "cardboard box"};
    sp_lex_vocab *v = NULL;
    sp_lex_result *res = NULL;
    if (rules_vocab(lx, depot, 11, &v, &res)) return;
    /* a hyphenated modifier is its words */
    CHECK(!strcmp(found_class(v, "roll-up door", res), "roll up door"));
    /* a noun modifier puts the query one level below its head: beside the bare door, a door
     * WordNet lacks named by a modifier may be it; an adjective describes ("the red door") */
    CHECK_MSG(!strcmp(found_class(v, "shutter door", res), "roll up door"), "shutter door -> '%s'",
              found_class(v, "shutter door", res));
    CHECK(!strcmp(found_class(v, "the red door", res), "door"));
    /* a pallet jack is no hand truck (alias removed), a pallet truck is the pallet jack */
    CHECK(!strcmp(found_class(v, "pallet truck", res), "pallet jack"));
    CHECK(!strcmp(found_class(v, "hand truck", res), "hand truck"));
    /* a WordNet collocation names a kind: a coffee machine is no vending machine */
    CHECK_MSG(!strcmp(found_class(v, "coffee machine", res), ""), "coffee machine -> '%s'",
              found_class(v, "coffee machine", res));
    /* cousins: another kind of the head the modifier says nothing of, a scene word too */
    CHECK_MSG(strcmp(found_class(v, "massage table", res), "coffee table"), "massage table -> coffee table");
    CHECK_MSG(!strcmp(found_class(v, "a safety barrier", res), ""), "safety barrier -> '%s'",
              found_class(v, "a safety barrier", res));
    /* a bare category the taxonomy misses names its members */
    const char *e = found_class(v, "equipment", res);
    CHECK_MSG(!strcmp(e, "pallet jack") || !strcmp(e, "hand truck") || !strcmp(e, "vending machine") ||
                  !strcmp(e, "safety cone"),
              "equipment -> '%s'", e);
    free(res);
    sp_lex_vocab_free(v);
    const char *flat[] = {"bar stool", "toilet", "toy chest", "dresser", "washing machine", "nightstand", "desk",
                          "walls", "floor"};
    if (rules_vocab(lx, flat, 9, &v, &res)) return;
    /* the scene's names choose the head's senses: the stool of "bar stool", not the toilet */
    CHECK_MSG(!strcmp(found_class(v, "stool", res), "bar stool"), "stool -> '%s'", found_class(v, "stool", res));
    CHECK(!strcmp(found_class(v, "a chest", res), "toy chest"));
    /* two activities, two kinds */
    CHECK_MSG(!strcmp(found_class(v, "rowing machine", res), ""), "rowing machine -> '%s'",
              found_class(v, "rowing machine", res));
    /* a split compound's first part is a word of its name */
    CHECK(!strcmp(found_class(v, "night table", res), "nightstand"));
    free(res);
    sp_lex_vocab_free(v);
}

static const char *top_class(const sp_lex_vocab *v, const sp_lex_phrase *ph)
{
    return ph->n_matches ? sp_lex_vocab_class(v, ph->matches[0].class_index) : "";
}

/* Runs one table; verbose prints every phrase; explain: only that query, with --explain text. */
static tally run_table(const sp_lexicon *lx, const char *name, int verbose, const char *explain)
{
    tally t = {0};
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/semantic/phrases_%s.json", SP_SOURCE_DIR, name);
    sp_error err = {0};
    cJSON *js = NULL;
    CHECK_OK(sp_json_read_file(path, &js, &err), &err);
    if (!js) return t;
    const cJSON *classes = cJSON_GetObjectItem(js, "classes"), *phrases = cJSON_GetObjectItem(js, "phrases");
    const char *names[SP_LEX_MAX_CLASSES];
    int n = 0;
    const cJSON *it;
    cJSON_ArrayForEach(it, classes) names[n++] = it->valuestring;
    sp_lex_vocab *v = NULL;
    CHECK_OK(sp_lex_vocab_create(&v, lx, names, n, NULL, &err), &err);
    sp_lex_result *res = malloc(sizeof *res);
    if (explain && v && res) {
        static char text[16384];
        if (!sp_lex_match(v, explain, res, &err)) sp_lex_explain(res, v, text, sizeof text), printf("%s", text);
        else printf("error: %s\n", err.msg);
        phrases = NULL;
    }
    cJSON_ArrayForEach(it, phrases) {
        if (!v || !res) break;
        const char *text = cJSON_GetObjectItem(it, "text")->valuestring;
        const char *kind = cJSON_GetObjectItem(it, "kind")->valuestring;
        const cJSON *expect = cJSON_GetObjectItem(it, "expect"), *anchor = cJSON_GetObjectItem(it, "anchor");
        const cJSON *ignored = cJSON_GetObjectItem(it, "ignored"), *rel = cJSON_GetObjectItem(it, "relation");
        double t0 = sp_time_now();
        int mrc = sp_lex_match(v, text, res, &err);
        double ms = (sp_time_now() - t0) * 1e3;
        if (mrc) {
            CHECK_MSG(0, "%s: '%s': %s", name, text, err.msg);
            continue;
        }
        int absent = cJSON_GetArraySize(expect) == 0, ok;
        const char *top = top_class(v, &res->target);
        if (absent) ok = !res->found;
        else {
            ok = res->found && in_array(expect, top);
            if (ok && rel) /* a relation must also be read as one, with the right anchor (a table that
                            * names the anchor by its room only, "anchor_region": a region) */
                ok = same_relation(res->relation, rel->valuestring) &&
                     (anchor || !cJSON_GetObjectItem(it, "anchor_region") ? in_array(anchor, top_class(v, &res->anchor))
                                                                          : res->anchor.is_region);
            if (ok && !strcmp(kind, "region")) ok = res->target.is_region;
        }
        if (absent) t.absent++, t.absent_ok += ok;
        else t.present++, t.present_ok += ok;
        int rk = !strcmp(kind, "region") ? 0 : !strcmp(kind, "relation") ? 1 : -1;
        if (!absent && rk >= 0) t.kind_n[rk]++, t.kind_ok[rk] += ok;
        if (res->found) t.bin_n[bin_of(res->confidence)]++, t.bin_ok[bin_of(res->confidence)] += ok;
        const cJSON *ig;
        cJSON_ArrayForEach(ig, ignored) {
            int got = 0;
            for (int k = 0; k < res->n_ignored; k++) got |= !strcmp(res->ignored[k], ig->valuestring);
            t.ignored_total++, t.ignored_ok += got;
        }
        if (verbose || !ok) {
            printf("%-5s %-9s %-36s -> %-16s %.2f %-8s", ok ? "ok" : "MISS", kind, text,
                   res->found || absent ? top : "(none)", (double)res->confidence,
                   res->target.n_matches ? sp_lex_kind_name(res->target.matches[0].kind) : "");
            if (res->relation[0]) printf(" [%s %s]", res->relation, top_class(v, &res->anchor));
            if (res->target.is_region) printf(" [region %s]", res->target.region);
            for (int k = 0; k < res->n_ignored; k++) printf(" ignored:%s", res->ignored[k]);
            if (verbose) printf(" (%.1f ms)", ms);
            printf("\n");
        }
    }
    free(res);
    sp_lex_vocab_free(v);
    cJSON_Delete(js);
    printf("%s: precision@1 %d/%d = %.3f on present phrasings, absent rejected %d/%d = %.3f, "
           "ignored attributes reported %d/%d (threshold %.2f)\n",
           name, t.present_ok, t.present, t.present ? (double)t.present_ok / t.present : 0.0, t.absent_ok,
           t.absent, t.absent ? (double)t.absent_ok / t.absent : 0.0, t.ignored_ok, t.ignored_total,
           (double)SP_LEX_THRESHOLD);
    printf("%s: found results correct by confidence: [0.5,0.7) %d/%d, [0.7,0.9) %d/%d, [0.9,1] %d/%d\n", name,
           t.bin_ok[0], t.bin_n[0], t.bin_ok[1], t.bin_n[1], t.bin_ok[2], t.bin_n[2]);
    printf("%s: kind region %d/%d, relation %d/%d\n", name, t.kind_ok[0], t.kind_n[0], t.kind_ok[1], t.kind_n[1]);
    return t;
}

int main(int argc, char **argv)
{
    if (!have_wordnet()) {
        fprintf(stderr, "skipped: no WordNet at %s (Debian wordnet-base)\n", wordnet_dir());
        return 77;
    }
    sp_lexicon *lx = NULL;
    sp_error err = {0};
    if (argc > 1) {
        CHECK_OK(sp_lexicon_open(&lx, NULL, &err), &err);
        if (lx) run_table(lx, argv[1], 1, argc > 2 ? argv[2] : NULL);
        sp_lexicon_free(lx);
        return TEST_EXIT();
    }
    RUN(test_reader);
    RUN(test_bad_input);
    CHECK_OK(sp_lexicon_open(&lx, NULL, &err), &err);
    if (!lx) return TEST_EXIT();
    test_phase4_rules(lx);
    test_phase5_rules(lx);
    test_aliases(lx);
    test_region_rules(lx);
    test_phase7_rules(lx);
    test_phase8_rules(lx);
    test_phase9_rules(lx);
    test_phase10_rules(lx);
    test_phase11_rules(lx);
    test_uses(lx);
    const char *worlds[] = {"house", "bookstore", "office", "ward", "garage", "cafe", "basement", "classroom", "hotel",
                            "grocery", "chemlab", "pharmacy", "salon", "warehouse", "apartment", "hospital", "smallhouse", "gym", "museum",
                            "library", "restaurant", "vetclinic", "station", "cinema", "firestation", "bowling", "airport", "openoffice", "familyhome"};
    const int n_worlds = (int)(sizeof worlds / sizeof worlds[0]);
    /* house and bookstore: the issue's bar; office: development data since phase 4 (its misses
     * were read), so its floor only guards against regressions (82/96 when it was set); the ward:
     * development data since phase 5, a regression floor too (93/121 = 0.769 and 30/32 when set) */
    /* phase 6 (aliases, docs/DESIGN.md changes 24-29) read all five tables' misses: the ward's
     * floor rises to 0.8 (100/121 = 0.826, 29/32 when set) and the garage gets one (113/139 =
     * 0.813, 28/30 when set); regression floors, not bars */
    /* phase 7 (l9-lexical) read the cafe's and the basement's misses too: they get regression
     * floors (cafe 144/187 = 0.770 and 32/35, basement 164/195 = 0.841 and 27/34 when set) */
    /* phase 8 (l10-lexical) read all nine tables' misses: the classroom and the hotel are
     * development data too and get floors; floors rise to just under the figures when set
     * (office 87/96, ward 102/121, garage 123/139, cafe 152/187 and 33/35, basement 170/195,
     * classroom 152/178 and 33/33, hotel 136/170 and 34/40); regression floors, not bars */
    /* phase 9 (l11-lexical): the grocery and the chemlab are development data too and get
     * regression floors (163/200 and 32/36, 138/197 and 32/34 when set); a table added after
     * them is printed without a bar */
    /* phase 10 (l12-lexical) read all thirteen tables' misses: the pharmacy and the salon are
     * development data too and get floors (147/190 and 32/35, 155/188 and 36/40 when set); the
     * others rise to just under their figures (garage 123/139, cafe 154/187, basement 172/195
     * and 27/34, classroom 154/178, hotel 144/170, grocery 169/200 and 34/36, chemlab 146/197) */
    /* phase 11 (l13-lexical) read all fifteen tables' misses: the warehouse and the apartment are
     * development data too and get floors (211/265 and 40/47, 236/290 and 40/44 when set); the
     * others rise to just under their figures (garage 124/139, basement 29/34 absent, hotel
     * 145/170 and 35/40, grocery 172/200 and 35/36, pharmacy 149/190 and 34/35, salon 37/40) */
    /* phase 13 (l15-lexical) read the hospital's, small house's, gym's and museum's misses: they
     * are development data too and get floors just under their figures (hospital 229/302 and
     * 47/53, small house 288/349 and 40/55, gym 178/229 and 24/32, museum 180/232 and 39/41 when
     * set); the grocery's 0.85 holds at 171/200 */
    /* phase 14 (l16-lexical) read the library's and the restaurant's misses: they are development
     * data too and get floors just under their figures (library 287/394 and 51/58, restaurant
     * 305/393 and 45/50 when set); the other floors stand */
    /* phase 15 (l17-lexical) read the vet clinic's and the station's misses: they are development
     * data too and get floors just under their figures (vetclinic 288/399 and 41/50, station
     * 305/398 and 45/52 when set); the other floors stand */
    /* phase 16 (l18-lexical) read the cinema's, fire station's, bowling centre's and airport's
     * misses: they are development data too and get floors just under their figures (cinema
     * 354/434 and 42/52, fire station 334/442 and 40/51, bowling 353/456 and 40/56, airport
     * 336/435 and 39/50 when set); the other floors stand */
    const double floor_p1[] = {0.9, 0.9, 0.9, 0.83, 0.89, 0.82, 0.88, 0.86, 0.85, 0.85, 0.74, 0.78, 0.82, 0.79, 0.81,
                               0.75, 0.82, 0.77, 0.77, 0.72, 0.77, 0.72, 0.76, 0.81, 0.75, 0.77, 0.77},
                 floor_absent[] = {0.9, 0.9, 0.9, 0.9, 0.9, 0.94, 0.85, 0.96, 0.87, 0.97, 0.94, 0.97, 0.92, 0.85, 0.9,
                                   0.88, 0.72, 0.75, 0.95, 0.87, 0.89, 0.82, 0.86, 0.80, 0.78, 0.71, 0.77};
    const int n_floors = (int)(sizeof floor_p1 / sizeof floor_p1[0]);
    for (int w = 0; w < n_worlds; w++) {
        tally t = run_table(lx, worlds[w], 0, NULL);
        if (w >= n_floors) continue; /* a table added later: printed, no bar (openoffice, familyhome) */
        CHECK_MSG(t.present_ok >= floor_p1[w] * t.present, "%s: precision@1 below %.2f", worlds[w], floor_p1[w]);
        CHECK_MSG(t.absent_ok >= floor_absent[w] * t.absent, "%s: fewer than %.0f%% of absent phrasings rejected",
                  worlds[w], 100 * floor_absent[w]);
        if (w >= 5) continue; /* the cafe's and basement's attribute misses (14/16) were not studied */
        /* the ward's "tall IV stand": "tall" occurs in a definition the class's head reaches, so
         * it counts as described, not ignored (7/8 when this was written) */
        /* and the garage's "white freezer": a refrigerator is "white goods" (10/11) */
        CHECK_MSG(t.ignored_ok + (w >= 3) >= t.ignored_total, "%s: attribute words not reported as ignored", worlds[w]);
    }
    sp_lexicon_free(lx);
    return TEST_EXIT();
}
