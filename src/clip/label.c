/* Label embeddings: a fixed pseudo-random unit vector per class name, the stand-in for a CLIP
 * text embedding when no weights are given (synthetic scenes with label maps). Deterministic
 * across machines: FNV-1a 64 -> splitmix64 -> Box-Muller in double -> normalise. */
#include <ctype.h>
#include <math.h>
#include <string.h>

#include "semsplat/clip.h"

static uint64_t splitmix64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* Uniform in (0, 1]: never 0, so log() in Box-Muller is finite. */
static double uniform01(uint64_t *s) { return ((double)(splitmix64(s) >> 11) + 1.0) / 9007199254740992.0; }

void sp_label_embedding(const char *text, int dim, float *out)
{
    if (dim <= 0 || !out) return;
    /* normalise: lower-case, trim, collapse whitespace runs; hash as we go */
    uint64_t h = 1469598103934665603ULL;
    int pending_space = 0, any = 0;
    for (const unsigned char *p = (const unsigned char *)(text ? text : ""); *p; p++) {
        if (isspace(*p)) {
            pending_space = any;
            continue;
        }
        if (pending_space) {
            h = (h ^ (uint64_t)' ') * 1099511628211ULL;
            pending_space = 0;
        }
        h = (h ^ (uint64_t)tolower(*p)) * 1099511628211ULL;
        any = 1;
    }
    uint64_t s = h;
    double norm = 0;
    for (int i = 0; i < dim; i += 2) {
        double u1 = uniform01(&s), u2 = uniform01(&s);
        double r = sqrt(-2.0 * log(u1)), th = 2.0 * M_PI * u2;
        double g0 = r * cos(th), g1 = r * sin(th);
        out[i] = (float)g0;
        norm += g0 * g0;
        if (i + 1 < dim) {
            out[i + 1] = (float)g1;
            norm += g1 * g1;
        }
    }
    norm = sqrt(norm);
    for (int i = 0; i < dim; i++) out[i] = (float)(out[i] / norm);
}
