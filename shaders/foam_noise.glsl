// Foam's texture: value noise from an integer hash, a lace of four
// octaves and a footprint-faded detail. Shared by the water's foam
// (foam.glsl) and the white water on a hull (mesh.frag).

// Smooth value noise in [0, 1] from an integer hash (the same on every
// GPU, unlike sin-based hashes).
float foam_hash(ivec2 c)
{
    uint h = uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return float(h & 0xffffu) / 65535.0;
}

float foam_noise(vec2 p)
{
    vec2 i = floor(p), f = p - i;
    f = f * f * (3.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float a = foam_hash(c), b = foam_hash(c + ivec2(1, 0));
    float d = foam_hash(c + ivec2(0, 1)), e = foam_hash(c + ivec2(1, 1));
    return mix(mix(a, b, f.x), mix(d, e, f.x), f.y);
}

// Four octaves of value noise, each turned and shifted so no grid shows;
// p in metres, the coarsest cell 4 m.
float foam_lace(vec2 p)
{
    const mat2 turn = mat2(0.8, 0.6, -0.6, 0.8);
    float sum = 0.0, amp = 0.5;
    p *= 0.25;
    for (int i = 0; i < 4; i++) {
        sum += amp * foam_noise(p);
        p = turn * p * 2.03 + vec2(11.7, 3.1);
        amp *= 0.5;
    }
    return sum / 0.9375;
}

// Detail for foam seen close: five octaves of value noise, cells 50, 25,
// 12, 6 and 3 cm (three, down to 12 cm, left a close wake's patches with
// smooth, painted edges), each faded out as its cell shrinks from one
// pixel's footprint to half of one (metres; 0: all): a cell is half a
// wavelength, so none goes past the pixels' Nyquist limit and aliases.
// Centred on zero, within +-0.5.
float foam_detail(vec2 p, float footprint)
{
    const mat2 turn = mat2(0.6, -0.8, 0.8, 0.6);
    float sum = 0.0, amp = 0.5, cell = 0.5;
    p *= 2.0;
    for (int i = 0; i < 5; i++) {
        float weight = footprint > 0.0 ? clamp(2.0 * cell / footprint - 1.0, 0.0, 1.0) : 1.0;
        if (weight <= 0.0)
            break;
        sum += amp * weight * (foam_noise(p) - 0.5);
        p = turn * p * 2.07 + vec2(5.3, 9.1);
        amp *= 0.5;
        cell /= 2.07;
    }
    return sum / 0.96875;
}

// Cellular noise (tl_noise_cells): the distance from p to the border
// between the cells of its two nearest points, one point per unit cell at
// a hashed place, F2 - F1 (0 on a border, about 1 at most). Foam's
// spent lace is a net of bubbles along such borders.
float foam_cells(vec2 p)
{
    vec2 i = floor(p), f = p - i;
    float f1 = 8.0, f2 = 8.0;
    for (int y = -1; y <= 1; y++)
        for (int x = -1; x <= 1; x++) {
            ivec2 c = ivec2(i) + ivec2(x, y);
            vec2 at = vec2(x, y) + vec2(TL_NOISE_CELL_MARGIN) +
                      (1.0 - 2.0 * TL_NOISE_CELL_MARGIN) *
                          vec2(foam_hash(c), foam_hash(c + ivec2(TL_NOISE_CELL_SHIFT_X,
                                                                   TL_NOISE_CELL_SHIFT_Y)));
            float d = length(at - f);
            if (d < f1) {
                f2 = f1;
                f1 = d;
            } else if (d < f2)
                f2 = d;
        }
    return f2 - f1;
}

// A net of lines `width` (cell units) wide along the cells' borders at p,
// for a pixel `footprint` cell units across: a line narrower than the
// pixel is drawn a pixel wide and as much fainter, so it cannot flicker.
float foam_net(vec2 p, float width, float footprint)
{
    float drawn = max(width, footprint);
    return (1.0 - smoothstep(0.2 * drawn, drawn, foam_cells(p))) * width / drawn;
}
