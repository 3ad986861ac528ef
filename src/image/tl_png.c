/* PNG writing and reading through libpng. */
#include "tl_image_io.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <png.h>
#include <zlib.h>

#include "tl_atomic.h"

/* Shared by the libpng callbacks of one read or write. It lives in the
 * caller of the function that calls setjmp, so its contents stay valid
 * after a longjmp. */
typedef struct png_job {
    FILE *fp;
    int err_no;         /* errno of a failed fwrite/fread, 0 if none */
    char msg[256];      /* libpng's error message */
    unsigned char *pix; /* decoded pixels (reading) */
    png_bytep *rows;    /* row pointers into pix (reading) */
    png_uint_32 width, height;
    int bits, channels;
} png_job;

/* libpng would print and abort; keep the message and unwind to setjmp. */
static void on_png_error(png_structp png, png_const_charp msg)
{
    png_job *io = png_get_error_ptr(png);
    snprintf(io->msg, sizeof io->msg, "%s", msg);
    png_longjmp(png, 1);
}

/* Warnings are not failures, and we never print. */
static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

static void write_cb(png_structp png, png_bytep data, size_t len)
{
    png_job *io = png_get_io_ptr(png);
    errno = 0;
    if (fwrite(data, 1, len, io->fp) != len) {
        /* A full disk (ENOSPC) or a file size limit (EFBIG) lands here. */
        io->err_no = errno ? errno : EIO;
        png_error(png, "write failed");
    }
}

/* tl_atomic_commit flushes and syncs once at the end. */
static void flush_cb(png_structp png)
{
    (void)png;
}

/* [0,1] to an integer code: NaN and negatives give 0, values above 1 the maximum. */
static unsigned int quantize(float v, unsigned int max)
{
    if (!(v > 0.0f))
        return 0;
    if (v >= 1.0f)
        return max;
    /* v·max + 0.5 is positive here, so truncation is floor(), without
     * floor()'s libm call per sample, a visible share of the encode (most
     * of the rest is deflate and libpng's row filter). */
    return (unsigned int)((double)v * max + 0.5);
}

/* One row of the display plane as big-endian RGB samples: 16 bits
 * rounded to nearest, 8 dithered unless asked not to be
 * (tl_frame_display_row8). */
static void pack_row(const tl_frame *frame, int y, int bits, int dither, unsigned char *row)
{
    if (bits != 16) {
        tl_frame_display_row8(frame, y, dither, row);
        return;
    }
    const float *src = frame->display + (size_t)y * (size_t)frame->width * 4;
    for (int x = 0; x < frame->width; x++) {
        for (int c = 0; c < 3; c++) {
            unsigned int q = quantize(src[(size_t)x * 4 + (size_t)c], 65535u);
            *row++ = (unsigned char)(q >> 8);
            *row++ = (unsigned char)(q & 0xffu);
        }
    }
}

/* Everything between png_create and png_destroy, in its own function so
 * that setjmp's caller has no local changed after the setjmp. */
static int encode_png(png_job *io, const tl_frame *frame, int bits, int dither, int level,
                      png_text *text, int ntext, unsigned char *row)
{
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, io, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        snprintf(io->msg, sizeof io->msg, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_set_write_fn(png, io, write_cb, flush_cb);
    png_set_compression_level(png, level);
    /* At the fast levels one filter (Sub) for every row: libpng's adaptive
     * choice tries all five per row, which cost more time than Sub and
     * gave no smaller files on the cutscenes' frames. The small-file levels
     * keep the search. */
    if (level <= 3) {
        png_set_filter(png, 0, PNG_FILTER_SUB);
        /* Run-length matches only: after Sub a frame's rows are mostly
         * small repeated differences, which RLE finds as well as deflate's
         * fast search, faster and mostly smaller. Dithered 8-bit rows
         * have no runs to find: Huffman coding alone is faster and smaller
         * there (undithered it is larger: RLE stays there). */
        png_set_compression_strategy(png, bits == 8 && dither ? Z_HUFFMAN_ONLY : Z_RLE);
    }
    png_set_IHDR(png, info, (png_uint_32)frame->width, (png_uint_32)frame->height, bits,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    /* sRGB, plus the gAMA/cHRM that the PNG spec recommends alongside it
     * for decoders that do not know sRGB. */
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (ntext > 0)
        png_set_text(png, info, text, ntext);
    png_write_info(png, info);
    for (int y = 0; y < frame->height; y++) {
        pack_row(frame, y, bits, dither, row);
        png_write_row(png, row);
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return 0;
}

/* A PNG keyword is 1-79 Latin-1 characters without leading, trailing or
 * double spaces. libpng would quietly rewrite a bad one; refuse it instead. */
static int check_keywords(const char *path, const tl_image_options *opt, tl_error *err)
{
    int n = opt && opt->meta ? opt->meta_count : 0;
    for (int i = 0; i < n; i++) {
        const unsigned char *k = (const unsigned char *)opt->meta[i].name;
        size_t len = strlen((const char *)k);
        int ok = len >= 1 && len <= 79 && k[0] != ' ' && k[len - 1] != ' ';
        for (size_t j = 0; ok && j < len; j++)
            ok = ((k[j] >= 32 && k[j] <= 126) || k[j] >= 161) && !(k[j] == ' ' && k[j + 1] == ' ');
        if (!ok)
            return tl_error_set(err, TL_ERR_RUNTIME,
                                "%s: metadata name '%s' is not a valid PNG keyword "
                                "(1-79 Latin-1 characters, single inner spaces)",
                                path, opt->meta[i].name);
    }
    return TL_OK;
}

/* tEXt chunks from the metadata; numbers become text. */
static int make_text(const tl_image_options *opt, png_text **text_out, char **numbers_out)
{
    int n = opt && opt->meta ? opt->meta_count : 0;
    *text_out = NULL;
    *numbers_out = NULL;
    if (n <= 0)
        return 0;
    enum { NUM_LEN = 16 * 26 };
    png_text *text = calloc((size_t)n, sizeof *text);
    char *numbers = calloc((size_t)n, NUM_LEN);
    if (!text || !numbers) {
        free(text);
        free(numbers);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        const tl_meta *m = &opt->meta[i];
        char *num = numbers + (size_t)i * NUM_LEN;
        if (m->type == TL_META_DOUBLE || m->type == TL_META_FLOAT)
            snprintf(num, NUM_LEN, "%.17g", m->d);
        else if (m->type == TL_META_INT)
            snprintf(num, NUM_LEN, "%d", m->i);
        for (int k = 0, at = 0; k < tl_meta_values(m->type) && at < NUM_LEN; k++)
            at += snprintf(num + at, (size_t)(NUM_LEN - at), "%s%.9g", k ? " " : "", m->v[k]);
        text[i].compression = PNG_TEXT_COMPRESSION_NONE;
        /* libpng's png_text is not const-correct; it only reads these. */
        text[i].key = (png_charp)m->name;
        text[i].text = m->type == TL_META_STRING ? (png_charp)m->s : num;
        text[i].text_length = strlen(text[i].text);
    }
    *text_out = text;
    *numbers_out = numbers;
    return n;
}

int tl_png_write(const char *path, const tl_frame *frame, const tl_image_options *opt,
                 tl_error *err)
{
    if (!frame || frame->width <= 0 || frame->height <= 0 || !frame->display)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: no frame to write", path);
    int bits = opt && opt->png_bits ? opt->png_bits : 8;
    if (bits != 8 && bits != 16)
        return tl_error_set(err, TL_ERR_USAGE, "%s: PNG bit depth must be 8 or 16, not %d", path,
                            bits);
    int level = opt && opt->png_compression ? opt->png_compression : TL_PNG_COMPRESSION_DEFAULT;
    if (level < 1 || level > 9)
        return tl_error_set(err, TL_ERR_USAGE, "%s: PNG compression must be 1..9, not %d", path,
                            level);
    int rc = tl_image_check_meta(path, opt, err);
    if (!rc)
        rc = check_keywords(path, opt, err);
    if (rc)
        return rc;

    png_text *text = NULL;
    char *numbers = NULL;
    int ntext = make_text(opt, &text, &numbers);
    unsigned char *row = malloc((size_t)frame->width * 3 * (size_t)(bits / 8));
    if (ntext < 0 || !row) {
        free(text);
        free(numbers);
        free(row);
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: out of memory", path);
    }

    tl_atomic_file file;
    rc = tl_atomic_open(&file, path, err);
    if (!rc) {
        png_job io = {.fp = file.fp};
        int dither = !(opt && opt->no_dither);
        if (encode_png(&io, frame, bits, dither, level, text, ntext, row) == 0) {
            rc = tl_atomic_commit(&file, err);
        } else {
            tl_atomic_abort(&file);
            rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot write PNG: %s", path,
                              io.err_no ? strerror(io.err_no) : io.msg);
        }
    }
    free(text);
    free(numbers);
    free(row);
    return rc;
}

static void read_cb(png_structp png, png_bytep data, size_t len)
{
    png_job *io = png_get_io_ptr(png);
    errno = 0;
    if (fread(data, 1, len, io->fp) != len) {
        io->err_no = ferror(io->fp) ? (errno ? errno : EIO) : 0;
        png_error(png, "unexpected end of file");
    }
}

/* Decodes the whole image into io->pix (freed by the caller, also on error). */
static int decode_png(png_job *io)
{
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, io, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_read_struct(&png, NULL, NULL);
        snprintf(io->msg, sizeof io->msg, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    png_set_read_fn(png, io, read_cb);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    int color = png_get_color_type(png, info);
    io->width = png_get_image_width(png, info);
    io->height = png_get_image_height(png, info);
    io->bits = png_get_bit_depth(png, info);
    io->channels = png_get_channels(png, info);
    if ((io->bits != 8 && io->bits != 16) ||
        (color != PNG_COLOR_TYPE_RGB && color != PNG_COLOR_TYPE_RGB_ALPHA))
        png_error(png, "unsupported PNG (need 8- or 16-bit RGB or RGBA)");
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    size_t rowbytes = png_get_rowbytes(png, info);
    if (io->height == 0 || rowbytes == 0 || io->height > SIZE_MAX / rowbytes)
        png_error(png, "image too large");
    io->pix = malloc(rowbytes * io->height);
    io->rows = malloc(io->height * sizeof *io->rows);
    if (!io->pix || !io->rows)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < io->height; y++)
        io->rows[y] = io->pix + (size_t)y * rowbytes;
    png_read_image(png, io->rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    return 0;
}

/* Big-endian samples to [0,1] floats in the display plane. */
static void unpack_pixels(const png_job *io, tl_frame *frame)
{
    size_t n = (size_t)io->width * io->height;
    int bytes = io->bits / 8;
    float scale = io->bits == 16 ? 65535.0f : 255.0f;
    const unsigned char *p = io->pix;
    for (size_t i = 0; i < n; i++) {
        float *dst = frame->display + i * 4;
        dst[3] = 1.0f; /* opaque when the file has no alpha */
        for (int c = 0; c < io->channels; c++) {
            unsigned int q = bytes == 2 ? (unsigned int)p[0] << 8 | p[1] : p[0];
            dst[c] = (float)q / scale;
            p += bytes;
        }
    }
}

int tl_png_read(const char *path, tl_frame *frame, int *bits_out, tl_error *err)
{
    memset(frame, 0, sizeof *frame);
    png_job io = {.fp = fopen(path, "rb")};
    if (!io.fp)
        return tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot open: %s", path, strerror(errno));
    unsigned char sig[8];
    int rc = TL_OK;
    if (fread(sig, 1, sizeof sig, io.fp) != sizeof sig || png_sig_cmp(sig, 0, sizeof sig))
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: not a PNG file", path);
    else if (decode_png(&io) != 0)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: cannot read PNG: %s", path,
                          io.err_no ? strerror(io.err_no) : io.msg);
    else if (io.width > INT32_MAX || io.height > INT32_MAX)
        rc = tl_error_set(err, TL_ERR_RUNTIME, "%s: image too large", path);
    else if ((rc = tl_frame_alloc(frame, (int)io.width, (int)io.height, err)) != 0)
        tl_error_prefix(err, "%s", path);
    if (!rc) {
        unpack_pixels(&io, frame);
        if (bits_out)
            *bits_out = io.bits;
    }
    fclose(io.fp);
    free(io.pix);
    free(io.rows);
    return rc;
}
