/* COLMAP binary model files (cameras.bin, images.bin, points3D.bin): see fuzz_colmap.h. The
 * custom mutator walks the records after a mutation and rewrites the counts (file count,
 * points2D per image, track length) to what the bytes hold, most of the time, so mutated values
 * reach the record checks instead of stopping at the first count check. */
#include "fuzz_colmap.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[3] = {"cameras.bin", "images.bin", "points3D.bin"};
    return fz_colmap_one(data, size, sp_colmap_parse_bin, sp_colmap_write_bin, names);
}

/* ---- structure-aware mutation ------------------------------------------------------------------ */

/* Walks records from offset 8 of body[0..n); returns the bytes they cover; fixes inner counts. */
static size_t walk(int part, uint8_t *b, size_t n, uint64_t *count, unsigned seed)
{
    size_t off = 8;
    *count = 0;
    for (;;) {
        size_t left = n - off;
        if (part == 0) { /* camera: id 4, model 4, width 8, height 8, params */
            if (left < 24) break;
            uint32_t model = fz_get_u32(b + off + 4);
            int np = sp_colmap_model_num_params((int)model);
            if (np < 0 && (seed & 1)) {
                model %= 12;
                fz_put_u32(b + off + 4, model);
                np = sp_colmap_model_num_params((int)model);
            }
            if (np < 0 || left < 24 + (size_t)np * 8) break;
            off += 24 + (size_t)np * 8;
        } else if (part == 1) { /* image: id 4, qvec 32, tvec 24, camera 4, name\0, n 8, n * 24 */
            if (left < 64) break;
            const uint8_t *nul = memchr(b + off + 64, 0, left - 64);
            if (!nul) break;
            size_t at = (size_t)(nul - b) + 1;
            if (n - at < 8) break;
            uint64_t np = fz_get_u64(b + at), room = (n - at - 8) / 24;
            if (np > room) fz_put_u64(b + at, np = room);
            off = at + 8 + (size_t)np * 24;
        } else { /* point: id 8, xyz 24, rgb 3, error 8, track n 8, n * 8 */
            if (left < 51) break;
            uint64_t tl = fz_get_u64(b + off + 43), room = (left - 51) / 8;
            if (tl > room) fz_put_u64(b + off + 43, tl = room);
            off += 51 + (size_t)tl * 8;
        }
        (*count)++;
    }
    return off;
}

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    size = LLVMFuzzerMutate(data, size, max_size);
    if (size < 9 || seed % 5 == 0) return size; /* sometimes leave the counts as mutated */
    int part = data[0] % 3;
    uint64_t count;
    size_t used = walk(part, data + 1, size - 1, &count, seed >> 3);
    fz_put_u64(data + 1, count);
    return (seed >> 1) % 4 ? 1 + used : size; /* mostly drop a partial trailing record */
}
