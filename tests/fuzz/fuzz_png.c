/* PNG through our libpng wrapper (sp_image_decode): see fuzz_image.h. */
#include "fuzz_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fz_image_one(data, size, "fuzz.png"); }
