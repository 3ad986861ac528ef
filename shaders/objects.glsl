// The floating objects in view (the boat and those a timeline declares),
// one slot each, u_object_count of them: src/prepare/tl_prepare.h's
// tl_object_uniforms, member for member (std140: every member a vec4 or a
// mat4, so the C struct's layout is the block's; the renderer checks the
// sizes). Camera-relative, column-major; the outline's tables are packed
// four stations to a vec4.

struct Floating {
    mat4 to_model;   // camera-relative world -> model
    mat4 shadow;     // -> its shadow map's s, t and depth
    vec4 hull;       // model y of the top, the water plane's camera-relative y, speed (m/s), shadow layer (-1: none)
    vec4 outline_z;  // the waterline's model z from x to y, the widest plan's from z to w
    vec4 shadow_map; // a texel's width (m), the share of the layer in use; the keel's model y
    vec4 waterline[TL_MESH_WATERLINE_STATIONS / 4];
    vec4 plan[TL_MESH_WATERLINE_STATIONS / 4];
    vec4 plan_y[TL_MESH_WATERLINE_STATIONS / 4];
    vec4 wake[TL_WAKE_POINTS];         // camera-relative x z, age (s), distance behind (m)
    vec4 wake_along[TL_WAKE_POINTS / 4]; // metres along the path, wrapped every 65536 m
    vec4 wake_groups[TL_WAKE_GROUPS];  // per TL_WAKE_GROUP segments: circle x z, radius (0: none)
    vec4 wake_params;                  // half beam, fade time, strength (0: no wake), hull length
    vec4 bow_spray;                    // camera-relative centre (y absolute), amount (0: none)
    vec4 bow_spray_shape;              // heading, unit (x, z), and radius
    vec4 lamp[TL_MESH_LAMPS];          // its lamps: camera-relative centre, radius (m)
    vec4 lamp_light[TL_MESH_LAMPS];    // their radiance times boat.lights (0: dark); w its side
    vec4 wash_water[TL_WASH_STATIONS / 2]; // the water's height along its sides: port, starboard
    vec4 wash_z;                       // the stations' model z from x to y
};

layout(std140) uniform tl_objects
{
    Floating u_objects[TL_OBJECT_MAX];
};

// Station i of object o's outline tables, and its wake's distance along
// the path at point k (packed four to a vec4).
float object_waterline(int o, int i)
{
    return u_objects[o].waterline[i >> 2][i & 3];
}

float object_plan(int o, int i)
{
    return u_objects[o].plan[i >> 2][i & 3];
}

float object_plan_y(int o, int i)
{
    return u_objects[o].plan_y[i >> 2][i & 3];
}

float object_wake_along(int o, int k)
{
    return u_objects[o].wake_along[k >> 2][k & 3];
}

// Object o's water height (camera-relative y) beside its hull at model z
// on its port (model x < 0) or starboard side, between the CPU's stations
// (tl_prepare_wash_water).
float object_wash_water(int o, float z, float x)
{
    vec2 span = u_objects[o].wash_z.xy;
    float f = clamp((z - span.x) / max(span.y - span.x, 1.0e-6), 0.0, 1.0) *
              float(TL_WASH_STATIONS - 1);
    int i = min(int(f), TL_WASH_STATIONS - 2);
    float t = f - float(i);
    i += x < 0.0 ? 0 : TL_WASH_STATIONS;
    float a = u_objects[o].wash_water[i >> 2][i & 3];
    float b = u_objects[o].wash_water[(i + 1) >> 2][(i + 1) & 3];
    return mix(a, b, t);
}
