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
    memset(frame, 0, sizeof *frame);
}
