/* Glare (render.bloom) against a CPU model of its definition: the scene's
 * colour plane (which never carries glare) is box-filtered into mip levels
 * 1..6 (each texel the mean of the 2x2 under it), each level read through a cubic B-spline of its
 * texels; the GPU evaluates that at 1 / TL_GLARE_DIVISOR of the output's resolution and the
 * display pass reads it bilinearly, then mixes it in and tonemaps. The frame's display plane must
 * match the model of that within a few 8-bit levels, and the model of the smaller image must stay
 * close to the definition evaluated at every output pixel (what glare was before it moved to its
 * own pass). */
#include <stdlib.h>
#include <string.h>

#include "core/tl_math.h"
#include "tl_gl_test.h"

/* Not powers of two, as frames are: the levels halve 176x90 down to 2x1,
 * and three of them (45 -> 22, 11 -> 5 rows, 11 -> 5 columns) leave out an
 * odd last row or column (shaders/mip.frag). The driver's own mipmaps
 * filter odd sizes as they like: llvmpipe's lost most of the coarsest
 * level's light. */
#define W      176
#define H      90
#define LEVELS 7

typedef struct image {
    int w, h;
    double *rgb; /* w*h*3 */
} image;

static image mips[LEVELS];

static void build_mips(const float *color)
{
    for (int l = 0; l < LEVELS; l++) {
        mips[l].w = W >> l;
        mips[l].h = H >> l;
        mips[l].rgb = calloc((size_t)mips[l].w * mips[l].h * 3, sizeof(double));
    }
    /* In GL's order, bottom row first: a level drops its odd last row at
     * the top of the image. */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int c = 0; c < 3; c++)
                mips[0].rgb[(y * W + x) * 3 + c] = color[((H - 1 - y) * W + x) * 4 + c];
    for (int l = 1; l < LEVELS; l++) {
        const image *a = &mips[l - 1];
        image *b = &mips[l];
        for (int y = 0; y < b->h; y++)
            for (int x = 0; x < b->w; x++)
                for (int c = 0; c < 3; c++) {
                    double s = 0.0;
                    for (int k = 0; k < 4; k++)
                        s += a->rgb[((2 * y + k / 2) * a->w + 2 * x + k % 2) * 3 + c];
                    b->rgb[(y * b->w + x) * 3 + c] = s / 4.0;
                }
    }
}

/* Bilinear, clamped to the edge, at uv (0..1): GL_LINEAR's footprint. */
static void bilinear(const image *m, double u, double v, double out[3])
{
    double x = u * m->w - 0.5, y = v * m->h - 0.5;
    double fx = floor(x), fy = floor(y);
    double tx = x - fx, ty = y - fy;
    for (int c = 0; c < 3; c++)
        out[c] = 0.0;
    for (int k = 0; k < 4; k++) {
        int xi = (int)fx + k % 2, yi = (int)fy + k / 2;
        xi = xi < 0 ? 0 : xi >= m->w ? m->w - 1 : xi;
        yi = yi < 0 ? 0 : yi >= m->h ? m->h - 1 : yi;
        double wgt = (k % 2 ? tx : 1.0 - tx) * (k / 2 ? ty : 1.0 - ty);
        for (int c = 0; c < 3; c++)
            out[c] += wgt * m->rgb[(yi * m->w + xi) * 3 + c];
    }
}

/* The cubic B-spline's weights of the four texels around a sample at
 * fraction f between the middle two. */
static void bspline(double f, double w[4])
{
    w[0] = (1.0 - f) * (1.0 - f) * (1.0 - f) / 6.0;
    w[1] = (3.0 * f * f * f - 6.0 * f * f + 4.0) / 6.0;
    w[2] = (-3.0 * f * f * f + 3.0 * f * f + 3.0 * f + 1.0) / 6.0;
    w[3] = f * f * f / 6.0;
}

/* The glare's definition at uv: each level's B-spline, clamped to the edge. */
static void glare_at(double u, double v, double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = 0.0;
    for (int l = 1; l <= 6; l++) {
        const image *m = &mips[l];
        double x = u * m->w - 0.5, y = v * m->h - 0.5;
        double fx = floor(x), fy = floor(y), wx[4], wy[4];
        bspline(x - fx, wx);
        bspline(y - fy, wy);
        for (int j = 0; j < 4; j++)
            for (int i = 0; i < 4; i++) {
                int xi = (int)fx - 1 + i, yi = (int)fy - 1 + j;
                xi = xi < 0 ? 0 : xi >= m->w ? m->w - 1 : xi;
                yi = yi < 0 ? 0 : yi >= m->h ? m->h - 1 : yi;
                for (int c = 0; c < 3; c++)
                    out[c] += wx[i] * wy[j] * m->rgb[(yi * m->w + xi) * 3 + c] / 6.0;
            }
    }
}

/* shaders/tonemap.glsl: the ACES fit, then the sRGB transfer. */
static void display_of(const double hdr[3], double exposure, double out[3])
{
    static const double m1[3][3] = {
        {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
    static const double m2[3][3] = {{1.60475, -0.53108, -0.07367},
                                    {-0.10208, 1.10813, -0.00605},
                                    {-0.00327, -0.07276, 1.07602}};
    double v[3], t[3];
    for (int r = 0; r < 3; r++)
        v[r] = exposure * (m1[r][0] * hdr[0] + m1[r][1] * hdr[1] + m1[r][2] * hdr[2]);
    for (int r = 0; r < 3; r++) {
        double a = v[r] * (v[r] + 0.0245786) - 0.000090537;
        double b = v[r] * (0.983729 * v[r] + 0.4329510) + 0.238081;
        t[r] = a / b;
    }
    for (int r = 0; r < 3; r++) {
        double c = m2[r][0] * t[0] + m2[r][1] * t[1] + m2[r][2] * t[2];
        c = c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
        out[r] = c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    }
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    /* The sun low in a narrow frame: a small, very bright disc and its
     * glitter, where glare matters. */
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = W;
    s.height = H;
    s.sun.elevation = 4.0 * TL_DEG;
    s.sun.azimuth = 0.0;
    s.camera.yaw = 0.0;
    s.camera.pitch = 0.0;
    s.camera.vfov = 12.0 * TL_DEG;
    s.bloom = 0.5;
    s.quality.pixel_filter = 0.0; /* the model is per pixel (test_render checks the filter) */
    tl_frame f;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    if (render(r, &s, &f))
        return 1;
    build_mips(f.color);

    /* The glare image at its pixel centres, as the GPU makes it (bottom
     * row first; the renderer's size, rounded up). */
    const int gw = (W + TL_GLARE_DIVISOR - 1) / TL_GLARE_DIVISOR;
    const int gh = (H + TL_GLARE_DIVISOR - 1) / TL_GLARE_DIVISOR;
    image small = {gw, gh, calloc((size_t)gw * gh * 3, sizeof(double))};
    for (int y = 0; y < gh; y++)
        for (int x = 0; x < gw; x++)
            glare_at((x + 0.5) / gw, (y + 0.5) / gh, small.rgb + (y * gw + x) * 3);

    double worst = 0.0, sum = 0.0, approx_sq = 0.0, spread = 0.0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            /* The frame's planes run top first, the model (as GL) bottom
             * first. */
            double u_ = (x + 0.5) / W, v_ = 1.0 - (y + 0.5) / H;
            const float *hdr_px = f.color + ((size_t)y * W + x) * 4;
            double g[3], exact[3], mixed[3], mixed_exact[3], want[3], want_exact[3];
            bilinear(&small, u_, v_, g);
            glare_at(u_, v_, exact);
            for (int k = 0; k < 3; k++) {
                mixed[k] = hdr_px[k] + s.bloom * (g[k] - hdr_px[k]);
                mixed_exact[k] = hdr_px[k] + s.bloom * (exact[k] - hdr_px[k]);
            }
            display_of(mixed, u.exposure, want);
            display_of(mixed_exact, u.exposure, want_exact);
            const float *got = f.display + ((size_t)y * W + x) * 4;
            for (int k = 0; k < 3; k++) {
                double e = fabs(got[k] - want[k]) * 255.0;
                worst = fmax(worst, e);
                sum += e;
                double a = (want[k] - want_exact[k]) * 255.0;
                approx_sq += a * a;
            }
            /* How far the glare reaches: its light in the top rows, away
             * from the horizon and the sun. */
            if (y < H / 8)
                spread += g[0] + g[1] + g[2];
        }
    double mean = sum / (3.0 * W * H);
    double approx_psnr = 10.0 * log10(255.0 * 255.0 / fmax(approx_sq / (3.0 * W * H), 1e-12));
    printf("display against the model: worst %.2f levels, mean %.3f levels\n", worst, mean);
    printf("glare at 1/%d resolution against the full-resolution definition: %.1f dB\n",
           TL_GLARE_DIVISOR, approx_psnr);
    printf("glare light in the top rows: %.4g\n", spread);
    CHECK(worst <= 3.0);
    CHECK(mean <= 0.3);
    CHECK(approx_psnr >= 45.0);
    CHECK(spread > 0.0);
    tl_frame_free(&f);
    free(small.rgb);

    /* The same frame rendered at half the output's size (draft's
     * render_scale) glares as far: the glare reads the half-size scene's
     * levels one lower, whose texels are as wide in output pixels. Exposed
     * low, so that nothing clips, the glare's light in the top rows (away
     * from the horizon and the sun) is the frame with glare less the frame
     * without, at each scale. */
    double reach[2];
    const double exposure = s.exposure, bloom = s.bloom;
    s.exposure = 0.02 * exposure;
    for (int k = 0; k < 2; k++) {
        s.quality.render_scale = k ? 0.5 : 1.0;
        reach[k] = 0.0;
        for (int g = 0; g < 2; g++) {
            tl_frame f2;
            s.bloom = g ? bloom : 0.0;
            if (render(r, &s, &f2))
                return 1;
            for (int y = 0; y < H / 8; y++)
                for (int x = 0; x < W; x++)
                    reach[k] +=
                        (g ? 1.0 : -1.0) * luminance(f2.display + ((size_t)y * W + x) * 4) * 255.0;
            tl_frame_free(&f2);
        }
        reach[k] /= W * (H / 8);
    }
    s.exposure = exposure;
    s.bloom = bloom;
    s.quality.render_scale = 1.0;
    printf("glare in the top rows, exposed low: %.2f levels at render scale 1, %.2f at 0.5\n",
           reach[0], reach[1]);
    CHECK(reach[0] > 1.0);
    CHECK(fabs(reach[1] - reach[0]) <= 0.15 * reach[0]);

    /* A frame smaller than the glare's coarsest level (the preview's
     * smallest scale): finite, in range, and the sun still glares. */
    s.width = 12;
    s.height = 7;
    if (render(r, &s, &f))
        return 1;
    int in_range = 1;
    double darkest = 1.0;
    for (int i = 0; i < 12 * 7 * 4; i++)
        in_range &= f.display[i] >= 0.0f && f.display[i] <= 1.0f;
    for (int i = 0; i < 12 * 7; i++)
        darkest = fmin(darkest, luminance(f.display + i * 4));
    printf("12x7 frame with glare: display in [0, 1]: %s, darkest pixel %.3f\n",
           in_range ? "yes" : "no", darkest);
    CHECK(in_range);
    CHECK(darkest > 0.0);
    tl_frame_free(&f);
    for (int l = 0; l < LEVELS; l++)
        free(mips[l].rgb);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
