/* EXR writing and reading through OpenEXR's C API (OpenEXRCore). */
#include "tl_image_io.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenEXR/openexr.h>

#include "tl_atomic.h"

#define TL_HALF_MAX 65504.0f

/* One file's I/O state, handed to OpenEXR as its stream user data. */
typedef struct exr_stream {
    int fd;
    int err_no; /* errno of the first failed read or write, 0 if none */
} exr_stream;

/* OpenEXR prints to stderr unless given a handler; we must never print, so
 * the handler keeps the last message for our own error. The library calls it
 * on the thread that made the failing call, hence thread-local storage (and
 * not the context's user data, whose getter may take the context's lock). */
static _Thread_local char exr_last_msg[256];

static void on_exr_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    (void)code;
    snprintf(exr_last_msg, sizeof exr_last_msg, "%s", msg ? msg : "");
}

/* The most precise description of a failure: the OS error of a failed
 * read/write, else OpenEXR's message, else its generic text for the code. */
static const char *exr_reason(const exr_stream *s, exr_result_t r)
{
    if (s && s->err_no)
        return strerror(s->err_no);
    if (exr_last_msg[0])
        return exr_last_msg;
    return exr_get_default_error_message(r);
}

static int64_t exr_pwrite(exr_const_context_t ctxt, void *user, const void *buf, uint64_t size,
                          uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = user;
    const uint8_t *p = buf;
    uint64_t done = 0;
    (void)ctxt;
    (void)error_cb;
    while (done < size) {
        ssize_t n = pwrite(s->fd, p + done, (size_t)(size - done), (off_t)(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            /* A full disk (ENOSPC) or a file size limit (EFBIG) lands here. */
            if (!s->err_no)
                s->err_no = n < 0 ? errno : EIO;
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t exr_pread(exr_const_context_t ctxt, void *user, void *buf, uint64_t size,
                         uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = user;
    uint8_t *p = buf;
    uint64_t done = 0;
    (void)ctxt;
    (void)error_cb;
    while (done < size) {
        ssize_t n = pread(s->fd, p + done, (size_t)(size - done), (off_t)(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            if (!s->err_no)
                s->err_no = errno;
            return -1;
        }
        if (n == 0)
            break; /* end of file: OpenEXR decides whether a short read is fatal */
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t exr_size(exr_const_context_t ctxt, void *user)
{
    exr_stream *s = user;
    struct stat st;
    (void)ctxt;
    return fstat(s->fd, &st) == 0 ? (int64_t)st.st_size : -1;
}

/* Index of the colour component (R,G,B,A = 0..3) or 4 for Z, -1 otherwise:
 * a plain file's channels, or Blender's multilayer names for them (a frame
 * written with passes). */
static int channel_slot(const char *name)
{
    static const char *const names[] = {"R", "G", "B", "A", "Z"};
    static const char *const layered[] = {"ViewLayer.Combined.R", "ViewLayer.Combined.G",
                                          "ViewLayer.Combined.B", "ViewLayer.Combined.A",
                                          "ViewLayer.Depth.Z"};
    for (int i = 0; i < 5; i++)
        if (strcmp(name, names[i]) == 0 || strcmp(name, layered[i]) == 0)
            return i;
    return -1;
}

/* ---- writing ---------------------------------------------------------- */

/* Colour is stored as half, whose largest finite value is 65504. Non-finite
 * values must never reach a file (a NaN or Inf poisons every filter a
 * compositor runs over it), so NaN becomes 0 and +-Inf becomes +-65504;
 * finite values beyond the half range saturate to +-65504 instead of
 * overflowing to Inf. Nothing else is clamped. */
static float sanitize_half(float v)
{
    if (isnan(v))
        return 0.0f;
    if (v > TL_HALF_MAX)
        return TL_HALF_MAX;
    if (v < -TL_HALF_MAX)
        return -TL_HALF_MAX;
    return v;
}

/* IEEE float to half, rounding to nearest even. Expects |v| <= 65504 (see
 * sanitize_half); anything larger saturates. */
static uint16_t float_to_half(float v)
{
    uint32_t x;
    memcpy(&x, &v, sizeof x);
    uint16_t sign = (uint16_t)((x >> 16) & 0x8000u);
    uint32_t ax = x & 0x7fffffffu;
    if (ax > 0x477fe000u) /* above 65504 */
        return sign | 0x7bffu;
    if (ax < 0x33000000u) /* below 2^-25: rounds to zero */
        return sign;
    uint32_t h, rem, halfway;
    if (ax < 0x38800000u) { /* below 2^-14: a subnormal half */
        uint32_t shift = 126u - (ax >> 23);
        uint32_t mant = (ax & 0x7fffffu) | 0x800000u;
        h = mant >> shift;
        rem = mant & ((1u << shift) - 1u);
        halfway = 1u << (shift - 1u);
    } else { /* rebias the exponent from 127 to 15, keep 10 mantissa bits */
        h = (ax - 0x38000000u) >> 13;
        rem = ax & 0x1fffu;
        halfway = 0x1000u;
    }
    if (rem > halfway || (rem == halfway && (h & 1u)))
        h++; /* a carry into the exponent is still the right result */
    return (uint16_t)(sign | h);
}

/* The channel named `name` of the caller's, or NULL. */
static const tl_exr_channel *find_channel(const tl_exr_channel *ch, int count, const char *name)
{
    for (int i = 0; i < count; i++)
        if (strcmp(ch[i].name, name) == 0)
            return &ch[i];
    return NULL;
}

/* What one file's channels are written from: the caller's list, and per
 * half channel a buffer of one chunk's halves. */
typedef struct exr_source {
    int width, height;
    const tl_exr_channel *channels;
    int count;
    uint16_t **halves; /* per channel: a chunk's halves, or NULL for a float one */
} exr_source;

/* Converts `rows` rows from row y0 of each half channel into its buffer. */
static void pack_half_rows(const exr_source *src, int y0, int rows)
{
    size_t n = (size_t)rows * (size_t)src->width;
    for (int c = 0; c < src->count; c++) {
        if (!src->halves[c])
            continue;
        const tl_exr_channel *ch = &src->channels[c];
        const float *from = ch->data + (size_t)y0 * (size_t)src->width * (size_t)ch->stride;
        for (size_t i = 0; i < n; i++)
            src->halves[c][i] = float_to_half(sanitize_half(from[i * (size_t)ch->stride]));
    }
}

/* Points the encoder's channels at this chunk's rows. */
static void bind_encode_channels(exr_encode_pipeline_t *enc, const exr_source *src, int y0)
{
    int w = src->width;
    for (int c = 0; c < enc->channel_count; c++) {
        exr_coding_channel_info_t *ch = &enc->channels[c];
        /* Every channel of the header is one of the caller's. */
        const tl_exr_channel *from = find_channel(src->channels, src->count, ch->channel_name);
        int k = (int)(from - src->channels);
        if (src->halves[k]) {
            ch->encode_from_ptr = (const uint8_t *)src->halves[k];
            ch->user_data_type = EXR_PIXEL_HALF;
            ch->user_bytes_per_element = 2;
            ch->user_pixel_stride = 2;
            ch->user_line_stride = 2 * w;
        } else {
            ch->encode_from_ptr =
                (const uint8_t *)(from->data + (size_t)y0 * (size_t)w * (size_t)from->stride);
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4 * from->stride;
            ch->user_line_stride = 4 * from->stride * w;
        }
    }
}

/* OpenEXRCore (Debian 12's 3.1, and later ones) keeps a ZIP chunk's zlib
 * bytes when they come out exactly as long as the packed pixels; a reader
 * takes a chunk of that size for uncompressed pixels and decodes garbage
 * (values of any size, Inf). Small chunks, as in a frame one pixel wide,
 * meet it often. The format stores the packed pixels in that case; so do
 * we, around the library's compressor. */
typedef struct zip_guard {
    exr_result_t (*compress)(exr_encode_pipeline_t *enc);
} zip_guard;

static exr_result_t compress_guarded(exr_encode_pipeline_t *enc)
{
    const zip_guard *guard = enc->encoding_user_data;
    exr_result_t r = guard->compress(enc);
    if (r == EXR_ERR_SUCCESS && enc->compressed_bytes == enc->packed_bytes &&
        enc->compressed_buffer && enc->compressed_buffer != enc->packed_buffer)
        memcpy(enc->compressed_buffer, enc->packed_buffer, enc->packed_bytes);
    return r;
}

static exr_result_t write_chunks(exr_context_t ctx, const exr_source *src)
{
    zip_guard guard = {NULL};
    int32_t lines = 0;
    exr_result_t r = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    if (r != EXR_ERR_SUCCESS)
        return r;
    for (int c = 0; c < src->count && r == EXR_ERR_SUCCESS; c++)
        if (src->channels[c].half &&
            !(src->halves[c] = malloc((size_t)lines * (size_t)src->width * sizeof(uint16_t))))
            r = EXR_ERR_OUT_OF_MEMORY;

    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int started = 0;
    for (int y = 0; y < src->height && r == EXR_ERR_SUCCESS; y += lines) {
        exr_chunk_info_t chunk;
        r = exr_write_scanline_chunk_info(ctx, 0, y, &chunk);
        if (r != EXR_ERR_SUCCESS)
            break;
        r = started ? exr_encoding_update(ctx, 0, &chunk, &enc)
                    : exr_encoding_initialize(ctx, 0, &chunk, &enc);
        if (r != EXR_ERR_SUCCESS)
            break;
        pack_half_rows(src, y, chunk.height);
        bind_encode_channels(&enc, src, y);
        if (!started) {
            started = 1;
            r = exr_encoding_choose_default_routines(ctx, 0, &enc);
            if (r != EXR_ERR_SUCCESS)
                break;
            if (enc.compress_fn) {
                guard.compress = enc.compress_fn;
                enc.compress_fn = compress_guarded;
                enc.encoding_user_data = &guard;
            }
        }
        r = exr_encoding_run(ctx, 0, &enc);
    }
    if (started)
        exr_encoding_destroy(ctx, &enc);
    for (int c = 0; c < src->count; c++) {
        free(src->halves[c]);
        src->halves[c] = NULL;
    }
    return r;
}

static exr_result_t set_meta(exr_context_t ctx, const tl_image_options *opt)
{
    int n = opt && opt->meta ? opt->meta_count : 0;
    exr_result_t r = EXR_ERR_SUCCESS;
    /* Names over 31 bytes need the long-name flag (readers since OpenEXR 1.7). */
    for (int i = 0; i < n && r == EXR_ERR_SUCCESS; i++)
        if (strlen(opt->meta[i].name) > 31)
            r = exr_set_longname_support(ctx, 1);
    for (int i = 0; i < n && r == EXR_ERR_SUCCESS; i++) {
        const tl_meta *m = &opt->meta[i];
        switch (m->type) {
        case TL_META_STRING: r = exr_attr_set_string(ctx, 0, m->name, m->s); break;
        case TL_META_DOUBLE: r = exr_attr_set_double(ctx, 0, m->name, m->d); break;
        case TL_META_INT: r = exr_attr_set_int(ctx, 0, m->name, m->i); break;
        case TL_META_FLOAT: r = exr_attr_set_float(ctx, 0, m->name, (float)m->d); break;
        case TL_META_M44F: {
            exr_attr_m44f_t v;
            for (int k = 0; k < 16; k++)
                v.m[k] = (float)m->v[k];
            r = exr_attr_set_m44f(ctx, 0, m->name, &v);
            break;
        }
        case TL_META_V3D: {
            exr_attr_v3d_t v = {.arr = {m->v[0], m->v[1], m->v[2]}};
            r = exr_attr_set_v3d(ctx, 0, m->name, &v);
            break;
        }
        case TL_META_CHROMATICITIES: {
            const exr_attr_chromaticities_t v = {(float)m->v[0], (float)m->v[1], (float)m->v[2],
                                                 (float)m->v[3], (float)m->v[4], (float)m->v[5],
                                                 (float)m->v[6], (float)m->v[7]};
            r = exr_attr_set_chromaticities(ctx, 0, m->name, &v);
            break;
        }
        case TL_META_RATIONAL: {
            const exr_attr_rational_t v = {(int32_t)m->v[0], (uint32_t)m->v[1]};
            r = exr_attr_set_rational(ctx, 0, m->name, &v);
            break;
        }
        }
    }
    return r;
}

/* Colour is perceptually logarithmic, everything else linear (this only
 * guides lossy codecs): the channels whose last name is R, G or B. */
static exr_perceptual_treatment_t perceptual(const char *name)
{
    const char *dot = strrchr(name, '.');
    const char *last = dot ? dot + 1 : name;
    return strcmp(last, "R") == 0 || strcmp(last, "G") == 0 || strcmp(last, "B") == 0
               ? EXR_PERCEPTUALLY_LOGARITHMIC
               : EXR_PERCEPTUALLY_LINEAR;
}

static exr_result_t define_header(exr_context_t ctx, const exr_source *src,
                                  const tl_image_options *opt, int level)
{
    int part = 0;
    exr_result_t r = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (r == EXR_ERR_SUCCESS)
        r = exr_initialize_required_attr_simple(ctx, part, src->width, src->height,
                                                EXR_COMPRESSION_ZIP);
    /* Channel names over 31 bytes need the long-name flag too. */
    for (int c = 0; c < src->count && r == EXR_ERR_SUCCESS; c++)
        if (strlen(src->channels[c].name) > 31)
            r = exr_set_longname_support(ctx, 1);
    for (int c = 0; c < src->count && r == EXR_ERR_SUCCESS; c++) {
        const tl_exr_channel *ch = &src->channels[c];
        r = exr_add_channel(ctx, part, ch->name, ch->half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT,
                            perceptual(ch->name), 1, 1);
    }
    if (r == EXR_ERR_SUCCESS)
        r = exr_set_zip_compression_level(ctx, part, level);
    if (r == EXR_ERR_SUCCESS)
        r = set_meta(ctx, opt);
    return r;
}

int tl_exr_write_channels(const char *path, int width, int height, const tl_exr_channel *channels,
                          int count, const tl_image_options *opt, tl_error *err)
{
    if (width <= 0 || height <= 0 || !channels || count < 1 || count > TL_EXR_CHANNELS_MAX)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no frame to write", path);
    for (int c = 0; c < count; c++) {
        const tl_exr_channel *ch = &channels[c];
        if (!ch->name || !ch->name[0] || strlen(ch->name) > 255 || !ch->data || ch->stride < 1)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: channel %d has no name or no data", path,
                                c);
        if (find_channel(channels, c, ch->name))
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: two channels are named '%s'", path,
                                ch->name);
    }
    int level = opt && opt->exr_compression ? opt->exr_compression : TL_EXR_COMPRESSION_DEFAULT;
    if (level < 1 || level > 9)
        return tl_error_set(err, TL_ERR_USAGE, "%s: EXR compression must be 1..9, not %d", path,
                            level);
    int rc = tl_image_check_meta(path, opt, err);
    if (rc)
        return rc;
    uint16_t *halves[TL_EXR_CHANNELS_MAX] = {NULL};
    exr_source src = {width, height, channels, count, halves};
    tl_atomic_file file;
    rc = tl_atomic_open(&file, path, err);
    if (rc)
        return rc;

    /* Our own write function sends the bytes to the temporary file, so
     * OpenEXR never touches the final path. */
    exr_stream stream = {.fd = file.fd, .err_no = 0};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_exr_error;
    init.user_data = &stream;
    init.write_fn = exr_pwrite;
    exr_last_msg[0] = '\0';

    exr_context_t ctx = NULL;
    exr_result_t r = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (r == EXR_ERR_SUCCESS)
        r = define_header(ctx, &src, opt, level);
    if (r == EXR_ERR_SUCCESS)
        r = exr_write_header(ctx);
    if (r == EXR_ERR_SUCCESS)
        r = write_chunks(ctx, &src);
    if (ctx) {
        exr_result_t fr = exr_finish(&ctx);
        if (r == EXR_ERR_SUCCESS)
            r = fr;
    }
    if (r != EXR_ERR_SUCCESS || stream.err_no) {
        tl_atomic_abort(&file);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot write EXR: %s", path,
                            exr_reason(&stream, r));
    }
    return tl_atomic_commit(&file, err);
}

int tl_exr_write(const char *path, const tl_frame *frame, const tl_image_options *opt,
                 tl_error *err)
{
    if (!frame || frame->width <= 0 || frame->height <= 0 || !frame->color || !frame->depth)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no frame to write", path);
    const tl_exr_channel channels[5] = {
        {"R", 1, frame->color + 0, 4}, {"G", 1, frame->color + 1, 4}, {"B", 1, frame->color + 2, 4},
        {"A", 1, frame->color + 3, 4}, {"Z", 0, frame->depth, 1},
    };
    return tl_exr_write_channels(path, frame->width, frame->height, channels, 5, opt, err);
}

/* ---- reading ---------------------------------------------------------- */

typedef struct exr_reader {
    exr_stream stream;
    exr_context_t ctx;
} exr_reader;

static int exr_open_read(const char *path, exr_reader *rd, tl_error *err)
{
    rd->ctx = NULL;
    rd->stream.err_no = 0;
    rd->stream.fd = open(path, O_RDONLY | O_CLOEXEC);
    if (rd->stream.fd < 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot open: %s", path, strerror(errno));

    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_exr_error;
    init.user_data = &rd->stream;
    init.read_fn = exr_pread;
    init.size_fn = exr_size;
    exr_last_msg[0] = '\0';
    exr_result_t r = exr_start_read(&rd->ctx, path, &init);
    if (r != EXR_ERR_SUCCESS) {
        /* exr_start_read has already released the context. */
        rd->ctx = NULL;
        close(rd->stream.fd);
        rd->stream.fd = -1;
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: not a readable EXR file: %s", path,
                            exr_reason(&rd->stream, r));
    }
    return TL_OK;
}

static void exr_close_read(exr_reader *rd)
{
    if (rd->ctx)
        exr_finish(&rd->ctx);
    if (rd->stream.fd >= 0)
        close(rd->stream.fd);
    rd->stream.fd = -1;
}

static int check_channels(const char *path, exr_const_context_t ctx, int *have_alpha, tl_error *err)
{
    const exr_attr_chlist_t *list = NULL;
    exr_result_t r = exr_get_channels(ctx, 0, &list);
    if (r != EXR_ERR_SUCCESS)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read the channel list: %s", path,
                            exr_reason(NULL, r));
    int found[5] = {0};
    for (int i = 0; i < list->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &list->entries[i];
        int slot = channel_slot(e->name.str);
        if (slot < 0)
            continue;
        if (e->pixel_type != EXR_PIXEL_HALF && e->pixel_type != EXR_PIXEL_FLOAT)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: channel %s is not half or float", path,
                                e->name.str);
        if (e->x_sampling != 1 || e->y_sampling != 1)
            return tl_error_set(err, TL_ERR_RUNTIME, "%s: channel %s is subsampled", path,
                                e->name.str);
        found[slot] = 1;
    }
    if (!found[0] || !found[1] || !found[2])
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: needs R, G and B channels", path);
    *have_alpha = found[3];
    return TL_OK;
}

/* Points the decoder's channels at the frame rows of this chunk (as floats). */
static void bind_decode_channels(exr_decode_pipeline_t *dec, tl_frame *frame, int row)
{
    int w = frame->width;
    for (int c = 0; c < dec->channel_count; c++) {
        exr_coding_channel_info_t *ch = &dec->channels[c];
        int slot = channel_slot(ch->channel_name);
        if (slot < 0) {
            ch->decode_to_ptr = NULL; /* skipped */
            continue;
        }
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        if (slot == 4) {
            ch->decode_to_ptr = (uint8_t *)(frame->depth + (size_t)row * (size_t)w);
            ch->user_pixel_stride = 4;
            ch->user_line_stride = 4 * w;
        } else {
            ch->decode_to_ptr = (uint8_t *)(frame->color + (size_t)row * (size_t)w * 4 + slot);
            ch->user_pixel_stride = 4 * 4;
            ch->user_line_stride = 4 * 4 * w;
        }
    }
}

static exr_result_t read_chunks(exr_const_context_t ctx, const exr_attr_box2i_t *dw,
                                tl_frame *frame)
{
    int32_t lines = 0;
    exr_result_t r = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    if (r != EXR_ERR_SUCCESS)
        return r;
    if (lines <= 0)
        return EXR_ERR_CORRUPT_CHUNK;
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int started = 0;
    for (int64_t y = dw->min.y; y <= dw->max.y && r == EXR_ERR_SUCCESS; y += lines) {
        exr_chunk_info_t chunk;
        r = exr_read_scanline_chunk_info(ctx, 0, (int)y, &chunk);
        if (r != EXR_ERR_SUCCESS)
            break;
        r = started ? exr_decoding_update(ctx, 0, &chunk, &dec)
                    : exr_decoding_initialize(ctx, 0, &chunk, &dec);
        if (r != EXR_ERR_SUCCESS)
            break;
        int row = chunk.start_y - dw->min.y;
        if (row < 0 || row + chunk.height > frame->height) {
            r = EXR_ERR_CORRUPT_CHUNK;
            break;
        }
        bind_decode_channels(&dec, frame, row);
        if (!started) {
            started = 1;
            r = exr_decoding_choose_default_routines(ctx, 0, &dec);
            if (r != EXR_ERR_SUCCESS)
                break;
        }
        r = exr_decoding_run(ctx, 0, &dec);
    }
    if (started)
        exr_decoding_destroy(ctx, &dec);
    return r;
}

static int read_image(const char *path, exr_reader *rd, tl_frame *frame, tl_error *err)
{
    exr_storage_t storage;
    exr_result_t r = exr_get_storage(rd->ctx, 0, &storage);
    if (r != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: only scanline EXR files are supported", path);
    exr_attr_box2i_t dw;
    r = exr_get_data_window(rd->ctx, 0, &dw);
    if (r != EXR_ERR_SUCCESS)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no data window: %s", path,
                            exr_reason(NULL, r));
    int64_t w = (int64_t)dw.max.x - dw.min.x + 1, h = (int64_t)dw.max.y - dw.min.y + 1;
    if (w <= 0 || h <= 0 || w > INT32_MAX || h > INT32_MAX)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: invalid data window", path);
    int have_alpha = 0;
    int rc = check_channels(path, rd->ctx, &have_alpha, err);
    if (rc)
        return rc;
    rc = tl_frame_alloc(frame, (int)w, (int)h, err);
    if (rc) {
        tl_error_prefix(err, "%s", path);
        return rc;
    }
    if (!have_alpha) /* opaque, as a reader of an RGB file would assume */
        for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
            frame->color[i * 4 + 3] = 1.0f;
    r = read_chunks(rd->ctx, &dw, frame);
    if (r != EXR_ERR_SUCCESS) {
        tl_frame_free(frame);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read EXR pixels: %s", path,
                            exr_reason(&rd->stream, r));
    }
    return TL_OK;
}

int tl_exr_read(const char *path, tl_frame *frame, tl_error *err)
{
    memset(frame, 0, sizeof *frame);
    exr_reader rd;
    int rc = exr_open_read(path, &rd, err);
    if (rc)
        return rc;
    rc = read_image(path, &rd, frame, err);
    exr_close_read(&rd);
    return rc;
}

/* The decoder's channels pointed at the rows of `row` of channel `name`
 * alone (as floats in `out`, `w` wide); the others skipped. */
static void bind_one_channel(exr_decode_pipeline_t *dec, const char *name, float *out, int w,
                             int row)
{
    for (int c = 0; c < dec->channel_count; c++) {
        exr_coding_channel_info_t *ch = &dec->channels[c];
        if (strcmp(ch->channel_name, name) != 0) {
            ch->decode_to_ptr = NULL;
            continue;
        }
        ch->decode_to_ptr = (uint8_t *)(out + (size_t)row * (size_t)w);
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = 4;
        ch->user_line_stride = 4 * w;
    }
}

int tl_exr_read_channel(const char *path, const char *name, int *width, int *height, float **out,
                        tl_error *err)
{
    *out = NULL;
    exr_reader rd;
    int rc = exr_open_read(path, &rd, err);
    if (rc)
        return rc;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *list = NULL;
    exr_storage_t storage;
    exr_result_t r = exr_get_storage(rd.ctx, 0, &storage);
    if (r == EXR_ERR_SUCCESS && storage != EXR_STORAGE_SCANLINE)
        r = EXR_ERR_INVALID_ARGUMENT;
    if (r == EXR_ERR_SUCCESS)
        r = exr_get_data_window(rd.ctx, 0, &dw);
    if (r == EXR_ERR_SUCCESS)
        r = exr_get_channels(rd.ctx, 0, &list);
    int found = 0;
    for (int i = 0; r == EXR_ERR_SUCCESS && i < list->num_channels; i++)
        found |= strcmp(list->entries[i].name.str, name) == 0 && list->entries[i].x_sampling == 1 &&
                 list->entries[i].y_sampling == 1;
    int64_t w = r == EXR_ERR_SUCCESS ? (int64_t)dw.max.x - dw.min.x + 1 : 0,
            h = r == EXR_ERR_SUCCESS ? (int64_t)dw.max.y - dw.min.y + 1 : 0;
    if (r != EXR_ERR_SUCCESS)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read its header: %s", path,
                          exr_reason(NULL, r));
    else if (!found)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: no channel '%s'", path, name);
    else if (w <= 0 || h <= 0 || w > 65536 || h > 65536)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: invalid data window", path);
    float *data = rc ? NULL : calloc((size_t)w * (size_t)h, sizeof *data);
    if (!rc && !data)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", path);
    int32_t lines = 0;
    if (!rc && (exr_get_scanlines_per_chunk(rd.ctx, 0, &lines) != EXR_ERR_SUCCESS || lines <= 0))
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: bad chunks", path);
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int started = 0;
    for (int64_t y = dw.min.y; !rc && y <= dw.max.y; y += lines) {
        exr_chunk_info_t chunk;
        r = exr_read_scanline_chunk_info(rd.ctx, 0, (int)y, &chunk);
        if (r == EXR_ERR_SUCCESS)
            r = started ? exr_decoding_update(rd.ctx, 0, &chunk, &dec)
                        : exr_decoding_initialize(rd.ctx, 0, &chunk, &dec);
        int row = chunk.start_y - dw.min.y;
        if (r == EXR_ERR_SUCCESS && (row < 0 || row + chunk.height > h))
            r = EXR_ERR_CORRUPT_CHUNK;
        if (r == EXR_ERR_SUCCESS) {
            bind_one_channel(&dec, name, data, (int)w, row);
            if (!started) {
                started = 1;
                r = exr_decoding_choose_default_routines(rd.ctx, 0, &dec);
            }
        }
        if (r == EXR_ERR_SUCCESS)
            r = exr_decoding_run(rd.ctx, 0, &dec);
        if (r != EXR_ERR_SUCCESS)
            rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read channel '%s': %s", path, name,
                              exr_reason(&rd.stream, r));
    }
    if (started)
        exr_decoding_destroy(rd.ctx, &dec);
    exr_close_read(&rd);
    if (rc) {
        free(data);
        return rc;
    }
    *out = data;
    *width = (int)w;
    *height = (int)h;
    return TL_OK;
}

/* Finds attribute `name` in part 0 of an open file. */
static int find_attr(const char *path, exr_reader *rd, const char *name,
                     const exr_attribute_t **attr, tl_error *err)
{
    exr_result_t r = exr_get_attribute_by_name(rd->ctx, 0, name, attr);
    if (r == EXR_ERR_NO_ATTR_BY_NAME)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no attribute '%s'", path, name);
    if (r != EXR_ERR_SUCCESS)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read attribute '%s': %s", path, name,
                            exr_reason(NULL, r));
    return TL_OK;
}

int tl_exr_read_attr_string(const char *path, const char *name, char *out, int out_size,
                            tl_error *err)
{
    if (!out || out_size <= 0)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no buffer for attribute '%s'", path, name);
    out[0] = '\0';
    exr_reader rd;
    int rc = exr_open_read(path, &rd, err);
    if (rc)
        return rc;
    const exr_attribute_t *attr = NULL;
    rc = find_attr(path, &rd, name, &attr, err);
    if (!rc && attr->type != EXR_ATTR_STRING)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: attribute '%s' is a %s, not a string", path,
                          name, attr->type_name);
    if (!rc && attr->string->length >= out_size)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: attribute '%s' is longer than %d bytes", path,
                          name, out_size - 1);
    if (!rc) {
        memcpy(out, attr->string->str, (size_t)attr->string->length);
        out[attr->string->length] = '\0';
    }
    exr_close_read(&rd);
    return rc;
}

/* Accepts double, float and int attributes (tl_exr_write stores ints as int). */
int tl_exr_read_attr_double(const char *path, const char *name, double *out, tl_error *err)
{
    exr_reader rd;
    int rc = exr_open_read(path, &rd, err);
    if (rc)
        return rc;
    const exr_attribute_t *attr = NULL;
    rc = find_attr(path, &rd, name, &attr, err);
    if (!rc) {
        if (attr->type == EXR_ATTR_DOUBLE)
            *out = attr->d;
        else if (attr->type == EXR_ATTR_FLOAT)
            *out = attr->f;
        else if (attr->type == EXR_ATTR_INT)
            *out = attr->i;
        else
            rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: attribute '%s' is a %s, not a number", path,
                              name, attr->type_name);
    }
    exr_close_read(&rd);
    return rc;
}
