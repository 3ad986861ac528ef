/* Cryptomatte's IDs (tl_passes.h): MurmurHash3 of the names, as floats
 * that are never NaN, Inf or denormal. */
#include "passes/tl_passes.h"

#include <stdio.h>
#include <string.h>

static uint32_t rotl32(uint32_t x, int r)
{
    return (x << r) | (x >> (32 - r));
}

uint32_t tl_crypto_murmur3(const void *data, size_t len, uint32_t seed)
{
    const uint8_t *bytes = data;
    const uint32_t c1 = 0xcc9e2d51u, c2 = 0x1b873593u;
    uint32_t h = seed;
    size_t blocks = len / 4;
    for (size_t i = 0; i < blocks; i++) {
        const uint8_t *b = bytes + i * 4; /* little-endian, whatever the machine */
        uint32_t k =
            (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
        k *= c1;
        k = rotl32(k, 15);
        k *= c2;
        h ^= k;
        h = rotl32(h, 13);
        h = h * 5u + 0xe6546b64u;
    }
    const uint8_t *tail = bytes + blocks * 4;
    uint32_t k = 0;
    switch (len & 3u) {
    case 3: k ^= (uint32_t)tail[2] << 16; /* fall through */
    case 2: k ^= (uint32_t)tail[1] << 8;  /* fall through */
    case 1:
        k ^= tail[0];
        k *= c1;
        k = rotl32(k, 15);
        k *= c2;
        h ^= k;
    }
    h ^= (uint32_t)len;
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

float tl_crypto_id(const char *name, uint32_t *bits)
{
    uint32_t h = tl_crypto_murmur3(name, strlen(name), 0);
    uint32_t exponent = (h >> 23) & 0xffu;
    /* The specification's conversion: the exponent held in 1..254. */
    if (exponent == 0)
        exponent = 1;
    else if (exponent == 255)
        exponent = 254;
    uint32_t b = (h & 0x807fffffu) | exponent << 23;
    float f;
    memcpy(&f, &b, sizeof f);
    if (bits)
        *bits = b;
    return f;
}

void tl_crypto_key(const char *layer, char out[8])
{
    char hex[9];
    snprintf(hex, sizeof hex, "%08x", (unsigned)tl_crypto_murmur3(layer, strlen(layer), 0));
    memcpy(out, hex, 7);
    out[7] = '\0';
}

const char *tl_crypto_material_name(const char *model)
{
    if (!model || !model[0])
        return "builtin_boat";
    const char *slash = strrchr(model, '/');
    return slash ? slash + 1 : model;
}
