/* A small document model for the reports: headings, paragraphs in a Markdown subset (**bold**,
 * *italic*, `code`), tables and figures, rendered as Markdown (report.md, figures linked) and as
 * one self-contained HTML page (report.html, figures inline as base64 PNG). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval/doc.h"
#include "semsplat/io.h"

void doc_free(doc *d)
{
    for (int i = 0; i < d->n; i++) {
        free(d->b[i].text);
        for (int c = 0; c < d->b[i].n_cells; c++) free(d->b[i].cells[c]);
        free(d->b[i].cells);
    }
    free(d->b);
    memset(d, 0, sizeof *d);
}

static doc_block *add(doc *d, int kind, const char *text)
{
    if (d->n == d->cap) {
        int cap = d->cap ? 2 * d->cap : 32;
        doc_block *nb = realloc(d->b, (size_t)cap * sizeof *nb);
        if (!nb) return NULL;
        d->b = nb;
        d->cap = cap;
    }
    doc_block *b = &d->b[d->n++];
    memset(b, 0, sizeof *b);
    b->kind = kind;
    b->text = strdup(text ? text : "");
    return b;
}

void doc_heading(doc *d, int level, const char *text)
{
    doc_block *b = add(d, DOC_HEADING, text);
    if (b) b->level = level;
}

void doc_para(doc *d, const char *text) { add(d, DOC_PARA, text); }

void doc_figure(doc *d, const char *path, const char *caption)
{
    doc_block *b = add(d, DOC_FIGURE, caption);
    if (b) {
        b->cells = calloc(1, sizeof *b->cells);
        if (b->cells) b->cells[b->n_cells++] = strdup(path);
    }
}

void doc_table(doc *d, int cols)
{
    doc_block *b = add(d, DOC_TABLE, "");
    if (b) b->cols = cols;
}

void doc_cell(doc *d, const char *fmt, ...)
{
    if (!d->n || d->b[d->n - 1].kind != DOC_TABLE) return;
    doc_block *b = &d->b[d->n - 1];
    if (b->n_cells == b->cap_cells) {
        int cap = b->cap_cells ? 2 * b->cap_cells : 64;
        char **nc = realloc(b->cells, (size_t)cap * sizeof *nc);
        if (!nc) return;
        b->cells = nc;
        b->cap_cells = cap;
    }
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    b->cells[b->n_cells++] = strdup(buf);
}

/* ---- Markdown --------------------------------------------------------------------------------- */

static const char *base_name(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

/* A figure's link relative to the report's folder (its path without the folder's prefix). */
static const char *relative(const char *path, const char *dir)
{
    size_t n = strlen(dir);
    if (n && !strncmp(path, dir, n) && path[n] == '/') return path + n + 1;
    return path;
}

char *doc_markdown(const doc *d, const char *out_dir)
{
    sp_strbuf s = {0};
    for (int i = 0; i < d->n; i++) {
        const doc_block *b = &d->b[i];
        switch (b->kind) {
        case DOC_HEADING:
            sp_strbuf_printf(&s, "%.*s %s\n\n", b->level, "######", b->text);
            break;
        case DOC_PARA:
            sp_strbuf_printf(&s, "%s\n\n", b->text);
            break;
        case DOC_FIGURE:
            sp_strbuf_printf(&s, "![%s](%s)\n\n", b->text, relative(b->cells[0], out_dir));
            break;
        case DOC_TABLE:
            for (int c = 0; c < b->n_cells; c++) {
                sp_strbuf_printf(&s, "| %s ", b->cells[c]);
                if ((c + 1) % b->cols == 0) {
                    sp_strbuf_printf(&s, "|\n");
                    if (c + 1 == b->cols)
                        for (int k = 0; k <= b->cols; k++) sp_strbuf_printf(&s, k < b->cols ? "|---" : "|\n");
                }
            }
            sp_strbuf_printf(&s, "\n");
            break;
        }
    }
    return sp_strbuf_take(&s);
}

/* ---- HTML ------------------------------------------------------------------------------------- */

/* Escapes text and turns the Markdown subset into tags. */
static void inline_html(sp_strbuf *s, const char *t)
{
    int bold = 0, ital = 0, code = 0;
    for (const char *p = t; *p; p++) {
        if (!code && p[0] == '*' && p[1] == '*') {
            sp_strbuf_printf(s, bold ? "</b>" : "<b>");
            bold = !bold;
            p++;
        } else if (!code && p[0] == '*' && (ital || (p[1] && p[1] != ' '))) {
            sp_strbuf_printf(s, ital ? "</i>" : "<i>");
            ital = !ital;
        } else if (p[0] == '`') {
            sp_strbuf_printf(s, code ? "</code>" : "<code>");
            code = !code;
        } else if (*p == '<') sp_strbuf_printf(s, "&lt;");
        else if (*p == '>') sp_strbuf_printf(s, "&gt;");
        else if (*p == '&') sp_strbuf_printf(s, "&amp;");
        else if (*p == '"') sp_strbuf_printf(s, "&quot;");
        else sp_strbuf_printf(s, "%c", *p);
    }
    if (code) sp_strbuf_printf(s, "</code>");
    if (ital) sp_strbuf_printf(s, "</i>");
    if (bold) sp_strbuf_printf(s, "</b>");
}

static void base64(sp_strbuf *s, const unsigned char *d, size_t n)
{
    static const char T[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char q[5] = {0};
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = (unsigned)d[i] << 16 | (i + 1 < n ? (unsigned)d[i + 1] << 8 : 0) | (i + 2 < n ? d[i + 2] : 0);
        q[0] = T[v >> 18 & 63];
        q[1] = T[v >> 12 & 63];
        q[2] = i + 1 < n ? T[v >> 6 & 63] : '=';
        q[3] = i + 2 < n ? T[v & 63] : '=';
        sp_strbuf_printf(s, "%s", q);
    }
}

char *doc_html(const doc *d, const char *title)
{
    sp_strbuf s = {0};
    sp_strbuf_printf(&s, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>");
    inline_html(&s, title);
    sp_strbuf_printf(&s, "</title><style>body{font-family:DejaVu Sans,sans-serif;max-width:1150px;margin:2em auto;"
                         "line-height:1.45;color:#222}table{border-collapse:collapse;margin:1em 0;font-size:90%%}"
                         "td,th{border:1px solid #bbb;padding:3px 8px}th{background:#eef}code{background:#f3f3f3}"
                         "img{max-width:100%%;border:1px solid #ddd}figcaption{color:#555;font-size:90%%}"
                         "</style></head><body>\n");
    for (int i = 0; i < d->n; i++) {
        const doc_block *b = &d->b[i];
        if (b->kind == DOC_HEADING) {
            sp_strbuf_printf(&s, "<h%d>", b->level);
            inline_html(&s, b->text);
            sp_strbuf_printf(&s, "</h%d>\n", b->level);
        } else if (b->kind == DOC_PARA) {
            sp_strbuf_printf(&s, "<p>");
            inline_html(&s, b->text);
            sp_strbuf_printf(&s, "</p>\n");
        } else if (b->kind == DOC_FIGURE) {
            char *png = NULL;
            size_t n = 0;
            sp_strbuf_printf(&s, "<figure>");
            if (!sp_read_file(b->cells[0], &png, &n, NULL)) {
                sp_strbuf_printf(&s, "<img alt=\"");
                inline_html(&s, b->text);
                sp_strbuf_printf(&s, "\" src=\"data:image/png;base64,");
                base64(&s, (const unsigned char *)png, n);
                sp_strbuf_printf(&s, "\">");
            } else sp_strbuf_printf(&s, "<p>(figure %s could not be read)</p>", base_name(b->cells[0]));
            free(png);
            sp_strbuf_printf(&s, "<figcaption>");
            inline_html(&s, b->text);
            sp_strbuf_printf(&s, "</figcaption></figure>\n");
        } else {
            sp_strbuf_printf(&s, "<table>\n");
            for (int c = 0; c < b->n_cells; c++) {
                const char *tag = c < b->cols ? "th" : "td";
                if (c % b->cols == 0) sp_strbuf_printf(&s, "<tr>");
                sp_strbuf_printf(&s, "<%s>", tag);
                inline_html(&s, b->cells[c]);
                sp_strbuf_printf(&s, "</%s>", tag);
                if ((c + 1) % b->cols == 0) sp_strbuf_printf(&s, "</tr>\n");
            }
            sp_strbuf_printf(&s, "</table>\n");
        }
    }
    sp_strbuf_printf(&s, "</body></html>\n");
    return sp_strbuf_take(&s);
}
