/* media's private parts: limits and the text layout shared by the canvas (Cairo measures the
 * widths) and its tests (a fake measure). */
#ifndef SP_MEDIA_INTERNAL_H
#define SP_MEDIA_INTERNAL_H

#include <stddef.h>

#define MEDIA_MAX_SIDE 8192  /* canvas, image and video sides */
#define MEDIA_MAX_LINE 4096  /* bytes of one laid-out line (longer lines are cut) */
#define MEDIA_MAX_LINES 512  /* lines of one text call */

/* Width of the first n bytes of s (valid UTF-8, no control characters) in pixels. */
typedef double (*media_width_fn)(void *ctx, const char *s, size_t n);

typedef struct media_lines {
    int n;
    char **line; /* [n] NUL-terminated, owned */
} media_lines;

/* Replaces what Cairo would refuse: invalid UTF-8 (bad leads, missing continuations, overlong
 * forms, surrogates, above U+10FFFF) and control characters become '?', tabs a space; '\n' stays.
 * Returns a malloc'd copy (NULL when out of memory). */
char *media_sanitize(const char *text);
/* Breaks text into lines: at every '\n', and when wrap_px > 0 at spaces so that each line fits
 * wrap_px (a word wider than that is broken between characters); max_lines > 0 keeps that many
 * and ends the last with "..." when text was left out. Returns 0, or -1 when out of memory. */
int media_layout(const char *text, float wrap_px, int max_lines, media_width_fn width, void *ctx,
                 media_lines *out);
void media_lines_free(media_lines *l);

#endif
