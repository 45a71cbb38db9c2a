/* Text output of `semsplat query` (tools/cli_query.c). */
#ifndef SEMSPLAT_CLI_QUERY_H
#define SEMSPLAT_CLI_QUERY_H

#include "semsplat/io.h"
#include "semsplat/semantic.h"

/* Once, above the results: what produced them and which frame the positions are in. */
void cli_query_provenance(const sp_query_source *s, const sp_frame *f);
/* One answer; heatmap the PNG written (or NULL); explain: what the encoder understood. */
void cli_query_print(const sp_query_result *res, const char *heatmap, int explain);

#endif
