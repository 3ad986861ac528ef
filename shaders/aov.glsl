// The compositing passes' data (TL_PASS_AOV): what each sample saw,
// recorded while it is traced and averaged over the pixel's samples like
// its radiance. src/image/tl_frame.h lays out the aov plane they become;
// src/passes turns it into an EXR's layers.

// What a sample's ray met first: the sky, the ocean, the giant wave (the
// water it raises above TL_GIANT_MATTE_SHARE of its height, and its lip,
// as tl_giant_in_matte), or a floating object (AOV_OBJECT + its index in
// the scene).
const int AOV_SKY = 0;
const int AOV_OCEAN = 1;
const int AOV_GIANT = 2;
const int AOV_OBJECT = 3;

vec3 g_aov_normal;  // of the surface met, facing the eye (0: the sky)
float g_aov_foam;   // the foam's cover there
int g_aov_hit;      // AOV_*
bool g_aov_under;   // the ray started under the water

// The sums over a pixel's samples.
vec4 g_aov_sum_normal, g_aov_sum_cover;
vec4 g_aov_sum_objects[TL_FRAME_AOV_OBJECTS / 4];

layout(location = 2) out vec4 out_aov_normal;                         // normal, foam
layout(location = 3) out vec4 out_aov_cover;                          // sky, ocean, giant wave, under
layout(location = 4) out vec4 out_aov_objects[TL_FRAME_AOV_OBJECTS / 4]; // per object

void aov_begin_pixel()
{
    g_aov_sum_normal = vec4(0.0);
    g_aov_sum_cover = vec4(0.0);
    for (int i = 0; i < TL_FRAME_AOV_OBJECTS / 4; i++)
        g_aov_sum_objects[i] = vec4(0.0);
}

void aov_begin_sample()
{
    g_aov_normal = vec3(0.0);
    g_aov_foam = 0.0;
    g_aov_hit = AOV_SKY;
    g_aov_under = false;
}

// The surface the ray met: its normal (facing the eye) and what it is.
void aov_surface(vec3 n, int hit)
{
    g_aov_normal = n;
    g_aov_hit = hit;
}

void aov_foam(float cover)
{
    g_aov_foam = max(g_aov_foam, clamp(cover, 0.0, 1.0));
}

void aov_add_sample()
{
    g_aov_sum_normal += vec4(g_aov_normal, g_aov_foam);
    g_aov_sum_cover += vec4(g_aov_hit == AOV_SKY ? 1.0 : 0.0, g_aov_hit == AOV_OCEAN ? 1.0 : 0.0,
                            g_aov_hit == AOV_GIANT ? 1.0 : 0.0, g_aov_under ? 1.0 : 0.0);
    int object = g_aov_hit - AOV_OBJECT;
    if (object >= 0 && object < TL_FRAME_AOV_OBJECTS)
        g_aov_sum_objects[object >> 2][object & 3] += 1.0;
}

// The pixel's means over `samples`, scaled as its radiance is.
void aov_write(float samples, float weight)
{
    float s = weight / max(samples, 1.0);
    out_aov_normal = g_aov_sum_normal * s;
    out_aov_cover = g_aov_sum_cover * s;
    for (int i = 0; i < TL_FRAME_AOV_OBJECTS / 4; i++)
        out_aov_objects[i] = g_aov_sum_objects[i] * s;
}
