/* CPU tile binning. Visible Gaussians are sorted once by depth (a stable LSD radix sort on the
 * float bits, which order like the values for positive depths; ties keep index order), then
 * dealt into 16x16 tiles in that order with a counting sort, so every tile list is already
 * front to back, ordered by (depth, index): deterministic whatever the thread count.
 * Each (Gaussian, tile) pair also gets a backward slot; a Gaussian's slots are contiguous
 * (pair_off[g] ..), so the backward can sum them per Gaussian in a fixed order. */
#include <string.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"

static uint32_t float_key(float z)
{
    uint32_t u;
    memcpy(&u, &z, sizeof u);
    return u; /* z >= near_plane > 0 for visible Gaussians: bit order = value order */
}

/* Stable LSD radix sort of (key, value) by key, 8 bits a pass. */
static void radix_sort(uint32_t *key, uint32_t *val, uint32_t *key_tmp, uint32_t *val_tmp, size_t m)
{
    for (int shift = 0; shift < 32; shift += 8) {
        size_t count[257];
        memset(count, 0, sizeof count);
        for (size_t i = 0; i < m; i++) count[((key[i] >> shift) & 255u) + 1]++;
        if (count[1 + ((key[0] >> shift) & 255u)] == m) continue; /* all in one bucket */
        for (int b = 0; b < 256; b++) count[b + 1] += count[b];
        for (size_t i = 0; i < m; i++) {
            size_t pos = count[(key[i] >> shift) & 255u]++;
            key_tmp[pos] = key[i];
            val_tmp[pos] = val[i];
        }
        memcpy(key, key_tmp, m * sizeof *key);
        memcpy(val, val_tmp, m * sizeof *val);
    }
}

/* Whether Gaussian g's pair with tile (x, y) is kept: the part of its pixel box in the tile meets
 * its alpha >= 1/255 ellipse (sp_gm_tile_hit), or every box tile when cfg.box_tiles. The counting
 * and the dealing loops both ask this, so they agree. */
static int tile_kept(const cpu_raster *r, size_t g, float cut, int x, int y)
{
    const int32_t *b = r->pix_box + 4 * g;
    /* a box within one tile keeps it (dropping a Gaussian's only tile saves nothing) */
    if (r->cfg.box_tiles || (b[0] / SP_TILE_SIZE == b[1] / SP_TILE_SIZE &&
                             b[2] / SP_TILE_SIZE == b[3] / SP_TILE_SIZE))
        return 1;
    int x0 = x * SP_TILE_SIZE, y0 = y * SP_TILE_SIZE;
    int x1 = x0 + SP_TILE_SIZE - 1, y1 = y0 + SP_TILE_SIZE - 1;
    return sp_gm_tile_hit(r->conic + 3 * g, cut, r->mean2d[2 * g], r->mean2d[2 * g + 1],
                          x0 > b[0] ? x0 : b[0], x1 < b[1] ? x1 : b[1], y0 > b[2] ? y0 : b[2],
                          y1 < b[3] ? y1 : b[3]);
}

/* The binning in parallel over chunks of the depth-sorted list: each chunk counts its
 * Gaussians' kept tiles (per Gaussian and per tile), the counts are scanned serially into every
 * Gaussian's first slot, every tile's start and every chunk's cursor into each tile (chunk c's
 * pairs of a tile after those of the chunks before it), then each chunk deals its pairs. The
 * tile lists and slots are the serial walk's exactly, whatever the thread count. */
#define BIN_CHUNK 2048             /* Gaussians per chunk, at least */
#define BIN_MAX_CHUNKS 64
#define BIN_MAX_COUNTS (1u << 22)  /* chunk x tile counters, at most */

typedef struct bin_job {
    cpu_raster *r;
    const uint32_t *order; /* [m] visible Gaussians front to back */
    size_t m, chunk;
    size_t *pair_off;      /* [n + 1]: kept-tile counts, then first slots */
    uint64_t *kept_mask;   /* [n] the kept tiles of a box of at most 64 (bit k: the box's k-th tile, row-major) */
    uint32_t *ccount;      /* [chunks][tiles]: counts, then cursors */
} bin_job;

/* A box of at most this many tiles has its kept tiles recorded by the counting loop as a mask,
 * which the dealing loop reads instead of asking tile_kept again. */
#define BIN_MASK_TILES 64

/* One past the last entry of chunk c of the sorted list. */
static size_t chunk_end(const bin_job *b, long c)
{
    size_t e = (size_t)(c + 1) * b->chunk;
    return e < b->m ? e : b->m;
}

static void bin_count_chunk(void *ctx, long c, int thread_id)
{
    (void)thread_id;
    const bin_job *b = ctx;
    const cpu_raster *r = b->r;
    uint32_t *cnt = b->ccount + (size_t)c * r->tiles_x * r->tiles_y;
    const size_t k1 = chunk_end(b, c);
    for (size_t k = (size_t)c * b->chunk; k < k1; k++) {
        const uint32_t g = b->order[k];
        const int32_t *bx = r->pix_box + 4 * g;
        const float cut = sp_gm_sigma_cut(r->opacity[g]);
        const int tx0 = bx[0] / SP_TILE_SIZE, tx1 = bx[1] / SP_TILE_SIZE, ty0 = bx[2] / SP_TILE_SIZE, ty1 = bx[3] / SP_TILE_SIZE;
        const int masked = (tx1 - tx0 + 1) * (ty1 - ty0 + 1) <= BIN_MASK_TILES;
        uint64_t mask = 0, bit = 1;
        size_t kept = 0;
        for (int y = ty0; y <= ty1; y++)
            for (int x = tx0; x <= tx1; x++, bit <<= 1)
                if (tile_kept(r, g, cut, x, y)) kept++, cnt[(size_t)y * r->tiles_x + x]++, mask |= bit;
        b->pair_off[g] = kept;
        if (masked) b->kept_mask[g] = mask;
    }
}

static void bin_deal_chunk(void *ctx, long c, int thread_id)
{
    (void)thread_id;
    const bin_job *b = ctx;
    cpu_raster *r = b->r;
    const int tx = r->tiles_x;
    uint32_t *cursor = b->ccount + (size_t)c * r->tiles_x * r->tiles_y;
    const size_t k1 = chunk_end(b, c);
    for (size_t k = (size_t)c * b->chunk; k < k1; k++) {
        const uint32_t g = b->order[k];
        const int32_t *bx = r->pix_box + 4 * g;
        uint32_t slot = (uint32_t)b->pair_off[g];
        cpu_gauss rec;
        rec.mx = r->mean2d[2 * g];
        rec.my = r->mean2d[2 * g + 1];
        for (int i = 0; i < 3; i++) rec.con[i] = r->conic[3 * g + i];
        rec.op = r->opacity[g];
        rec.z = r->depth[g];
        rec.det_con = r->conic_det[g];
        rec.cut = sp_gm_sigma_cut(rec.op);
        rec.g = (int32_t)g;
        for (int i = 0; i < 4; i++) rec.box[i] = bx[i];
        rec.pad[0] = rec.pad[1] = 0.f;
        const int tx0 = bx[0] / SP_TILE_SIZE, tx1 = bx[1] / SP_TILE_SIZE, ty0 = bx[2] / SP_TILE_SIZE, ty1 = bx[3] / SP_TILE_SIZE;
        const int masked = (tx1 - tx0 + 1) * (ty1 - ty0 + 1) <= BIN_MASK_TILES;
        const uint64_t mask = masked ? b->kept_mask[g] : 0;
        uint64_t bit = 1;
        for (int y = ty0; y <= ty1; y++)
            for (int x = tx0; x <= tx1; x++, bit <<= 1) {
                if (masked ? !(mask & bit) : !tile_kept(r, g, rec.cut, x, y)) continue;
                uint32_t pos = cursor[(size_t)y * tx + x]++;
                r->tile_rec[pos] = rec;
                r->tile_slot[pos] = slot++;
            }
    }
}

int cpu_bin_tiles(cpu_raster *r, sp_error *err)
{
    size_t n = r->n;
    int tx = (r->W + SP_TILE_SIZE - 1) / SP_TILE_SIZE, ty = (r->H + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    size_t tiles = (size_t)tx * (size_t)ty;
    r->tiles_x = tx;
    r->tiles_y = ty;

    /* chunks: enough for the pool's threads to share, few enough to keep the counters small */
    sp_pool *pool = r->dev->pool;
    size_t max_chunks = (size_t)4 * (pool ? (size_t)sp_pool_size(pool) : 1);
    if (max_chunks > BIN_MAX_CHUNKS) max_chunks = BIN_MAX_CHUNKS;
    if (max_chunks * tiles > BIN_MAX_COUNTS) max_chunks = BIN_MAX_COUNTS / tiles ? BIN_MAX_COUNTS / tiles : 1;

    /* sort scratch: 4 x n uint32 + chunk x tile counters; pair_off ([n+1] size_t) and the kept
     * masks ([n] uint64) live here too */
    size_t sort_bytes = 4 * n * sizeof(uint32_t) + max_chunks * tiles * sizeof(uint32_t) +
                        (n + 1) * sizeof(size_t) + n * sizeof(uint64_t) + 256;
    int rc = sp_scratch_reserve(r->dev, &r->sort_buf, &r->sort_cap, sort_bytes, err);
    if (rc) return rc;
    size_t *pair_off = r->sort_buf;
    uint64_t *kept_mask = (uint64_t *)(pair_off + n + 1);
    uint32_t *key = (uint32_t *)(kept_mask + n);
    uint32_t *val = key + n, *key_tmp = val + n, *val_tmp = key_tmp + n;
    uint32_t *ccount = val_tmp + n;
    r->pair_off = pair_off;

    /* the visible list, front to back */
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        pair_off[i] = 0;
        if (r->radii[i] <= 0) continue;
        key[m] = float_key(r->depth[i]);
        val[m] = (uint32_t)i;
        m++;
    }
    if (m > 0) radix_sort(key, val, key_tmp, val_tmp, m);

    size_t chunk = (m + max_chunks - 1) / max_chunks;
    if (chunk < BIN_CHUNK) chunk = BIN_CHUNK;
    size_t n_chunks = m ? (m + chunk - 1) / chunk : 0;
    memset(ccount, 0, n_chunks * tiles * sizeof(uint32_t));
    bin_job job = {r, val, m, chunk, pair_off, kept_mask, ccount};
    sp_pool_for(pool, (long)n_chunks, bin_count_chunk, &job);

    /* first slots (index order) and the pair count */
    size_t pairs = 0;
    for (size_t i = 0; i < n; i++) {
        size_t c = pair_off[i];
        pair_off[i] = pairs;
        pairs += c;
    }
    pair_off[n] = pairs;
    if (pairs > UINT32_MAX)
        return sp_error_set(err, SP_E_ARG, "rasterizer: %zu Gaussian-tile pairs exceed 2^32", pairs);
    r->pairs = pairs;

    size_t tile_bytes = pairs * sizeof(cpu_gauss) + (tiles + 1) * sizeof(uint32_t) +
                        pairs * sizeof(uint32_t) + 64;
    rc = sp_scratch_reserve(r->dev, &r->tile_buf, &r->tile_cap, tile_bytes, err);
    if (rc) return rc;
    r->tile_rec = r->tile_buf; /* first: keeps the records 64-byte aligned */
    r->tile_start = (uint32_t *)(r->tile_rec + pairs);
    r->tile_slot = r->tile_start + tiles + 1;

    /* tile starts, and each chunk's cursor into each tile */
    uint32_t at = 0;
    for (size_t t = 0; t < tiles; t++) {
        r->tile_start[t] = at;
        for (size_t c = 0; c < n_chunks; c++) {
            uint32_t k = ccount[c * tiles + t];
            ccount[c * tiles + t] = at;
            at += k;
        }
    }
    r->tile_start[tiles] = at;
    sp_pool_for(pool, (long)n_chunks, bin_deal_chunk, &job);
    return 0;
}
