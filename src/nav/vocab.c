/* Words the nav module knows without a model: the household vocabulary scene descriptions query
 * (COCO's 80 classes and common household objects), the regions of a home with the objects a
 * household keeps in them (how "kitchen" is found on scenes whose features know only objects),
 * and the concepts related to a goal that the ranking's semantic term looks for on the way. */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "nav_scene.h"

/* COCO 2017's 80 detection classes (exactly 80: sp_nav_coco_classes), then household objects
 * COCO lacks. */
static const char *const vocabulary[] = {
    "person", "bicycle", "car", "motorcycle", "airplane", "bus", "train", "truck", "boat",
    "traffic light", "fire hydrant", "stop sign", "parking meter", "bench", "bird", "cat", "dog",
    "horse", "sheep", "cow", "elephant", "bear", "zebra", "giraffe", "backpack", "umbrella",
    "handbag", "tie", "suitcase", "frisbee", "skis", "snowboard", "sports ball", "kite",
    "baseball bat", "baseball glove", "skateboard", "surfboard", "tennis racket", "bottle",
    "wine glass", "cup", "fork", "knife", "spoon", "bowl", "banana", "apple", "sandwich", "orange",
    "broccoli", "carrot", "hot dog", "pizza", "donut", "cake", "chair", "couch", "potted plant",
    "bed", "dining table", "toilet", "tv", "laptop", "mouse", "remote", "keyboard", "cell phone",
    "microwave", "oven", "toaster", "sink", "refrigerator", "book", "clock", "vase", "scissors",
    "teddy bear", "hair drier", "toothbrush",
    /* household */
    "dining chair", "armchair", "sofa", "coffee table", "side table", "desk", "office chair",
    "stool", "bookshelf", "shelf", "cabinet", "kitchen counter", "kitchen cabinet", "stove",
    "dishwasher", "washing machine", "wardrobe", "dresser", "nightstand", "tv stand", "lamp",
    "floor lamp", "ceiling light", "rug", "carpet", "curtain", "window", "door", "mirror",
    "painting", "picture frame", "pillow", "blanket", "towel", "bathtub", "shower", "trash can",
    "plant", "fireplace", "radiator", "fan", "air conditioner", "shoe cabinet", "coat rack",
    "box", "basket", "piano", "guitar", "fire extinguisher", "stairs",
};

const char *const *sp_nav_vocabulary(int *n)
{
    *n = (int)(sizeof vocabulary / sizeof vocabulary[0]);
    return vocabulary;
}

const char *const *sp_nav_coco_classes(int *n)
{
    *n = 80;
    return vocabulary;
}

/* Regions of a home and the objects that make them, best anchors first. */
static const struct {
    const char *name;
    const char *aliases;
    const char *objects[8];
} regions[] = {
    {"kitchen", "kitchen area,the kitchen,kitchenette",
     {"refrigerator", "stove", "oven", "sink", "kitchen counter", "microwave", "dishwasher", "toaster"}},
    {"living room", "living area,lounge,sitting room,the living room",
     {"couch", "sofa", "tv", "tv stand", "coffee table", "armchair", "fireplace", "rug"}},
    {"dining room", "dining area,the dining room",
     {"dining table", "dining chair", NULL}},
    {"bedroom", "bed room,the bedroom,sleeping area",
     {"bed", "nightstand", "wardrobe", "dresser", NULL}},
    {"bathroom", "the bathroom,restroom,washroom",
     {"toilet", "bathtub", "shower", "towel", NULL}},
    {"entrance", "entry,hallway,hall,foyer,front door area,the entrance",
     {"shoe cabinet", "coat rack", "door", NULL}},
    {"office", "study,workspace,the office",
     {"desk", "office chair", "laptop", "keyboard", NULL}},
};
#define N_REGIONS (int)(sizeof regions / sizeof regions[0])

static int word_match(const char *list, const char *text)
{
    size_t n = strlen(text);
    for (const char *p = list; *p;) {
        const char *e = strchr(p, ',');
        size_t l = e ? (size_t)(e - p) : strlen(p);
        if (l == n && !strncasecmp(p, text, n)) return 1;
        if (!e) break;
        p = e + 1;
    }
    return 0;
}

static int contains_word(const char *text, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = text; *p; p++)
        if (!strncasecmp(p, word, n) && (p == text || !isalpha((unsigned char)p[-1])) &&
            !isalpha((unsigned char)p[n]))
            return 1;
    return 0;
}

int nav_region_index(const char *text)
{
    /* "the area around the kitchen" -> kitchen: the longest region name inside the text */
    int best = -1;
    size_t best_len = 0;
    for (int r = 0; r < N_REGIONS; r++) {
        if (!strcasecmp(regions[r].name, text) || word_match(regions[r].aliases, text)) return r;
        size_t l = strlen(regions[r].name);
        if (contains_word(text, regions[r].name) && l > best_len) best = r, best_len = l;
    }
    return best;
}

const char *nav_region_name(int r) { return r >= 0 && r < N_REGIONS ? regions[r].name : ""; }

int nav_region_objects(int r, const char *const **objects)
{
    *objects = r >= 0 && r < N_REGIONS ? regions[r].objects : NULL;
    int n = 0;
    while (*objects && n < 8 && (*objects)[n]) n++;
    return n;
}

int nav_region_of_object(const char *object)
{
    for (int r = 0; r < N_REGIONS; r++)
        for (int k = 0; k < 8 && regions[r].objects[k]; k++)
            if (!strcasecmp(regions[r].objects[k], object)) return r;
    return -1;
}

int nav_n_regions(void) { return N_REGIONS; }

int nav_related_concepts(const char *goal, char out[][64], int cap)
{
    int n = 0, r = nav_region_of_object(goal);
    if (r < 0) r = nav_region_index(goal);
    if (r < 0) return 0;
    if (n < cap) snprintf(out[n++], 64, "%s", regions[r].name);
    for (int k = 0; k < 8 && regions[r].objects[k] && n < cap; k++)
        if (strcasecmp(regions[r].objects[k], goal)) snprintf(out[n++], 64, "%s", regions[r].objects[k]);
    return n;
}
