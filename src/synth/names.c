/* Class names from model names, the way people ask for things: vendor tokens, variant letters
 * and instance numbers removed, CamelCase split, lower case ("aws_robomaker_retail_BookshelfB_01"
 * -> "bookshelf", "dining_chair_2" -> "dining chair"). */
#include "semsplat/synth.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#define MAX_TOKENS 32

/* Prefixes of model vendors and world packs that say where a model came from, not what it is. */
static const char *const vendor_tokens[] = {"aws", "robomaker", "retail", "residential", "warehouse",
                                            "hospital", "gazebo", "gz", "ign", "ignition", "fuel",
                                            "osrf", "openrobotics", NULL};

static int is_vendor(const char *t)
{
    for (int i = 0; vendor_tokens[i]; i++)
        if (!strcasecmp(t, vendor_tokens[i])) return 1;
    return 0;
}

static int all_digits(const char *t)
{
    if (!*t) return 0;
    for (; *t; t++)
        if (!isdigit((unsigned char)*t)) return 0;
    return 1;
}

/* Splits s into tokens at separators, lower->Upper, letter<->digit and "ABc" -> "A","Bc". */
static int tokenize(const char *s, char tok[MAX_TOKENS][64])
{
    int n = 0, len = 0;
    char cur[64];
    size_t L = strlen(s);
    for (size_t i = 0; i <= L; i++) {
        unsigned char c = (unsigned char)s[i];
        int sep = c == 0 || c == '_' || c == '-' || c == ' ' || c == '.' || c == '/' || c == ':';
        int brk = 0;
        if (!sep && len > 0) {
            unsigned char p = (unsigned char)s[i - 1], nx = (unsigned char)s[i + 1];
            if (islower(p) && isupper(c)) brk = 1;
            else if (isalpha(p) != 0 && isdigit(c)) brk = 1;
            else if (isdigit(p) && isalpha(c)) brk = 1;
            else if (isupper(p) && isupper(c) && islower(nx)) brk = 1;
        }
        if ((sep || brk) && len > 0) {
            cur[len] = 0;
            if (n < MAX_TOKENS) snprintf(tok[n++], 64, "%s", cur);
            len = 0;
        }
        if (!sep && len < 63) cur[len++] = (char)c;
    }
    return n;
}

void sp_synth_class_name(const char *model_name, char *out, size_t cap)
{
    char tok[MAX_TOKENS][64];
    int keep[MAX_TOKENS];
    if (!cap) return;
    out[0] = 0;
    if (!model_name) return;
    int n = tokenize(model_name, tok);
    for (int i = 0; i < n; i++) keep[i] = !is_vendor(tok[i]);
    /* "RetailShopWall": the shop belongs to the retail pack, the wall is the thing. */
    for (int i = 1; i < n; i++)
        if (!strcasecmp(tok[i - 1], "retail") && !strcasecmp(tok[i], "shop")) keep[i] = 0;
    int last = n - 1, kept = 0;
    for (int i = 0; i < n; i++) kept += keep[i];
    /* Trailing instance numbers and variant letters ("_01", "B"), keeping at least one word. */
    while (last >= 0 && kept > 1) {
        if (!keep[last]) { last--; continue; }
        if (all_digits(tok[last]) || (strlen(tok[last]) == 1 && isalpha((unsigned char)tok[last][0]))) {
            keep[last--] = 0;
            kept--;
            continue;
        }
        break;
    }
    /* A single remaining number or letter is not a class; fall back to the plain name. */
    if (kept == 0 || (kept == 1 && last >= 0 && keep[last] && all_digits(tok[last]))) {
        for (int i = 0; i < n; i++) keep[i] = 1;
        last = n - 1;
        while (last > 0 && all_digits(tok[last])) keep[last--] = 0;
    }
    size_t o = 0;
    for (int i = 0; i < n; i++) {
        if (!keep[i]) continue;
        if (o && o + 1 < cap) out[o++] = ' ';
        for (const char *p = tok[i]; *p && o + 1 < cap; p++) out[o++] = (char)tolower((unsigned char)*p);
    }
    out[o] = 0;
}

/* Structure is what a building is made of: walls, floors, ceilings and the ground. In English
 * compounds the last word is the head and the words before it modify it, so "shop wall" and
 * "kitchen floor" are structure while a "floor lamp", "wall clock" or "ceiling fan" is furniture
 * named after where it stands or hangs. A plane is structure when it is the ground or a floor
 * ("ground plane", Gazebo's usual name). */
static int is_structure_class(const char *cls)
{
    static const char *const heads[] = {"wall", "walls", "floor", "floors", "flooring", "ground",
                                        "ceiling", "ceilings", NULL};
    static const char *const plane_of[] = {"ground", "floor", NULL};
    if (!cls || !*cls) return 0;
    const char *sp = strrchr(cls, ' ');
    const char *head = sp ? sp + 1 : cls;
    for (int i = 0; heads[i]; i++)
        if (!strcasecmp(head, heads[i])) return 1;
    if (sp && !strcasecmp(head, "plane")) {
        const char *b = sp; /* the word before "plane" */
        while (b > cls && b[-1] != ' ') b--;
        for (int i = 0; plane_of[i]; i++)
            if ((size_t)(sp - b) == strlen(plane_of[i]) && !strncasecmp(b, plane_of[i], (size_t)(sp - b)))
                return 1;
    }
    return 0;
}

int sp_synth_is_structure(const char *model_name, const char *class_name)
{
    /* The class comes from the model a world includes; the instance name can still say what it
     * is (a box included as "north_wall"), read the same way. */
    if (is_structure_class(class_name)) return 1;
    if (!model_name || !*model_name) return 0;
    char own[128];
    sp_synth_class_name(model_name, own, sizeof own);
    return is_structure_class(own);
}
