/* eval's document model (doc.c): blocks rendered to Markdown and to self-contained HTML. */
#ifndef SP_EVAL_DOC_H
#define SP_EVAL_DOC_H

#include <stdarg.h>

enum { DOC_HEADING, DOC_PARA, DOC_TABLE, DOC_FIGURE };

typedef struct doc_block {
    int kind, level, cols;
    char *text;          /* heading, paragraph, or figure caption */
    int n_cells, cap_cells;
    char **cells;        /* table cells row by row (the first row is the header); figure: path */
} doc_block;

typedef struct doc {
    int n, cap;
    doc_block *b;
} doc;

void doc_heading(doc *d, int level, const char *text);
void doc_para(doc *d, const char *text);           /* **bold**, *italic*, `code` */
void doc_table(doc *d, int cols);                  /* then doc_cell, row by row */
void doc_cell(doc *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void doc_figure(doc *d, const char *png_path, const char *caption);
/* Markdown with figures linked relative to out_dir (the report's folder); HTML with them inline.
 * malloc'd. */
char *doc_markdown(const doc *d, const char *out_dir);
char *doc_html(const doc *d, const char *title);
void doc_free(doc *d);

#endif
