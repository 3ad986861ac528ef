#include "tl_frame.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int tl_frame_alloc(tl_frame *frame, int width, int height, tl_error *err)
{
    memset(frame, 0, sizeof *frame);
    if (width <= 0 || height <= 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "invalid frame size %dx%d", width, height);
    size_t pixels = (size_t)width * (size_t)height;
    frame->color = calloc(pixels * 4, sizeof(float));
    frame->depth = calloc(pixels, sizeof(float));
    frame->display = calloc(pixels * 4, sizeof(float));
    if (!frame->color || !frame->depth || !frame->display) {
        tl_frame_free(frame);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for a %dx%d frame", width, height);
    }
    frame->width = width;
    frame->height = height;
    return TL_OK;
}

void tl_frame_free(tl_frame *frame)
{
    free(frame->color);
    free(frame->depth);
    free(frame->display);
    free(frame->aov);
    for (int k = 0; k < TL_FRAME_LAYERS; k++)
        free(frame->layer[k]);
    memset(frame, 0, sizeof *frame);
}

int tl_frame_alloc_aov(tl_frame *frame, tl_error *err)
{
    if (frame->aov)
        return TL_OK;
    size_t pixels = (size_t)frame->width * (size_t)frame->height;
    frame->aov = calloc(pixels * TL_FRAME_AOV_FLOATS, sizeof(float));
    if (!frame->aov)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for a %dx%d frame's passes",
                            frame->width, frame->height);
    return TL_OK;
}

const char *tl_light_layer_name(int layer)
{
    static const char *const names[TL_FRAME_LAYERS] = {"sky",  "reflection", "body", "glitter",
                                                       "foam", "spray",      "boat", "glare"};
    return layer >= 0 && layer < TL_FRAME_LAYERS ? names[layer] : "";
}

int tl_frame_alloc_layers(tl_frame *frame, unsigned layers, tl_error *err)
{
    size_t pixels = (size_t)frame->width * (size_t)frame->height;
    for (int k = 0; k < TL_FRAME_LAYERS; k++) {
        if (!(layers & (1u << k)) || frame->layer[k])
            continue;
        frame->layer[k] = calloc(pixels * 3, sizeof(float));
        if (!frame->layer[k])
            return tl_error_set(err, TL_ERR_RUNTIME, "out of memory for a %dx%d frame's layers",
                                frame->width, frame->height);
    }
    return TL_OK;
}

unsigned tl_frame_layers(const tl_frame *frame)
{
    unsigned layers = 0;
    for (int k = 0; k < TL_FRAME_LAYERS; k++)
        if (frame->layer[k])
            layers |= 1u << k;
    return layers;
}

/* The dither of pixel (x, y): three uniform noises in [0, 1) codes, bytes
 * of one hash (a fixed pattern: the same frame always gives the same
 * file). */
static void dither_noise(unsigned x, unsigned y, float noise[3])
{
    uint32_t h = x * 0x9e3779b1u ^ y * 0x85ebca77u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    for (int c = 0; c < 3; c++)
        noise[c] = (float)(h >> (8 * c) & 0xffu) * (1.0f / 256.0f);
}

void tl_frame_display_row8(const tl_frame *frame, int y, int dither, unsigned char *rgb)
{
    const float *src = frame->display + (size_t)y * (size_t)frame->width * 4;
    float noise[3] = {0.5f, 0.5f, 0.5f}; /* undithered: floor(v·255 + 0.5) */
    for (int x = 0; x < frame->width; x++) {
        if (dither)
            dither_noise((unsigned)x, (unsigned)y, noise);
        for (int c = 0; c < 3; c++) {
            float v = src[(size_t)x * 4 + (size_t)c];
            int code = 0;
            if (v >= 1.0f)
                code = 255;
            else if (v > 0.0f) {
                /* floor(v·255 + noise): the code below or above v·255, the
                 * nearer the more often (positive, so truncation is floor) */
                code = (int)(v * 255.0f + noise[c]);
                code = code > 255 ? 255 : code;
            }
            *rgb++ = (unsigned char)code;
        }
    }
}
