// The surfels method's own appearance (iwasaki2006 section 5.3): reflection of
// the environment (the analytic sky of common/shading.c, looked up by direction
// as an environment map), refraction of the floor under the water with its
// caustics (the floor is sample plane 0 of the caustic maps), Fresnel weights.
// Sky and floor constants are common/shading.c's, so both appearances agree
// away from the water.
uniform vec3 u_light_dir;   // unit, towards the light (world)
uniform vec3 u_light_color;
uniform float u_ambient;
uniform float u_ior;
uniform vec3 u_extinction;  // per scene unit
uniform vec3 u_tint;
uniform int u_up;           // 0 x, 1 y, 2 z
uniform float u_floor;      // floor height along up
uniform float u_check;      // checker size
uniform int u_checker;      // 1: checker floor, 0: sky only
uniform vec3 u_eye_world;
uniform float u_pixel_angle;
uniform sampler2DArray u_caustic_maps;
uniform int u_has_caustics;
uniform vec2 u_rect_min;    // horizontal extent of the caustic maps (axes up+1, up+2)
uniform vec2 u_rect_max;
// The object under the water as sliced object images (methods/surfels/object_slices.h):
// slice k holds what of it lies between heights u_slice_h[k] and u_slice_h[k + 1].
uniform sampler2DArray u_object_slices;
uniform int u_nslices;          // 0: no object
uniform float u_slice_h[9];

const vec3 SKY_HORIZON = vec3(0.78, 0.84, 0.90);
const vec3 SKY_ZENITH = vec3(0.16, 0.34, 0.70);
const vec3 SKY_GROUND = vec3(0.30, 0.28, 0.26);
const float CHECK_LIGHT = 0.75, CHECK_DARK = 0.22, CHECK_HAZE_FADE = 120.0;
const float WATER_SPEC = 0.8, WATER_SHININESS = 256.0;

vec3 up_vec() { return vec3(u_up == 0 ? 1.0 : 0.0, u_up == 1 ? 1.0 : 0.0, u_up == 2 ? 1.0 : 0.0); }
vec2 horizontal(vec3 p) { return vec2(p[(u_up + 1) % 3], p[(u_up + 2) % 3]); }

vec3 sky(vec3 d)
{
    float t = dot(d, up_vec());
    if (t >= 0.0) return mix(SKY_HORIZON, SKY_ZENITH, 1.0 - (1.0 - t) * (1.0 - t));
    return mix(SKY_HORIZON, SKY_GROUND, min(-t * 8.0, 1.0));
}

float square_wave_integral(float x)
{
    float m = x - 2.0 * floor(0.5 * x);
    return 1.0 - abs(m - 1.0);
}
float filtered_square(float x, float w)
{
    if (w < 1e-4) return (int(floor(x)) & 1) != 0 ? -1.0 : 1.0;
    return (square_wave_integral(x + 0.5 * w) - square_wave_integral(x - 0.5 * w)) / w;
}

// Caustic irradiance at floor point q (rgb) and whether water lies above it (a).
vec4 caustic_at(vec3 q)
{
    if (u_has_caustics == 0) return vec4(0.0);
    vec2 uv = (horizontal(q) - u_rect_min) / (u_rect_max - u_rect_min);
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec4(0.0);
    return textureLod(u_caustic_maps, vec3(uv, 0.0), 0.0);
}

// Light reaching the floor at q: refracted light where water lies above it
// (the caustic map), direct sunlight elsewhere; ambient everywhere.
vec3 floor_light(vec3 q, out float caustic)
{
    vec4 c = caustic_at(q);
    caustic = dot(c.rgb, vec3(0.2126, 0.7152, 0.0722));
    vec3 direct = max(u_light_dir[u_up], 0.0) * u_light_color;
    return u_ambient + (c.a > 0.0 ? c.rgb : direct);
}

// What a ray from o along d sees below the water or in the open: the checker
// floor (lit by floor_light) or the sky. travelled: eye distance to o (footprint).
vec3 scene_behind(vec3 o, vec3 d, float travelled, out float caustic, out float path)
{
    caustic = 0.0;
    path = 1e30;
    vec3 s = sky(d);
    float height = o[u_up] - u_floor;
    if (u_checker == 0 || height <= 0.0 || d[u_up] >= 0.0) return s;
    // Refraction mapping of the sliced object images: from the top slab down,
    // the ray's point where it enters each slab (or its start, inside one).
    for (int k = u_nslices - 1; k >= 0; k--) {
        float top = min(u_slice_h[k + 1], o[u_up]);
        if (top <= u_slice_h[k]) continue;
        float t = (o[u_up] - top) / -d[u_up];
        vec2 uv = (horizontal(o + t * d) - u_rect_min) / (u_rect_max - u_rect_min);
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) continue;
        vec4 obj = textureLod(u_object_slices, vec3(uv, float(k)), 0.0);
        if (obj.a > 0.5) { path = t; return obj.rgb / obj.a; }
    }
    float t = height / -d[u_up];
    path = t;
    vec3 q = o + t * d;
    vec2 h = horizontal(q) / u_check;
    float w = (travelled + t) * u_pixel_angle / u_check / max(-d[u_up], 0.05);
    float parity = filtered_square(h.x, w) * filtered_square(h.y, w);
    float albedo = 0.5 * (CHECK_LIGHT + CHECK_DARK) + 0.5 * (CHECK_LIGHT - CHECK_DARK) * parity;
    vec3 lit = albedo * floor_light(q, caustic);
    return mix(s, lit, exp(-t / u_check / CHECK_HAZE_FADE));
}

// Exact Fresnel reflectance of unpolarised light entering the water.
float fresnel_exact(float cos_i, float ior)
{
    float sin_t2 = (1.0 - cos_i * cos_i) / (ior * ior);
    if (sin_t2 >= 1.0) return 1.0;
    float cos_t = sqrt(1.0 - sin_t2);
    float rs = (cos_i - ior * cos_t) / (cos_i + ior * cos_t);
    float rp = (ior * cos_i - cos_t) / (ior * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Colour of a surfel fragment at world point p seen along d with normal n.
vec3 surfel_appearance(vec3 p, vec3 d, vec3 n, out float caustic)
{
    float cos_i = clamp(-dot(n, d), 0.0, 1.0);
    float F = fresnel_exact(cos_i, max(u_ior, 1.0));
    vec3 refl = sky(reflect(d, n));
    vec3 t = refract(d, n, 1.0 / max(u_ior, 1.0));
    float path;
    float travelled = length(p - u_eye_world);
    vec3 trans = scene_behind(p, normalize(t), travelled, caustic, path);
    if (path > 1e29) path = 0.0; // leaves through the side or the top: no floor behind
    trans *= u_tint * exp(-u_extinction * path);
    vec3 h = normalize(u_light_dir - d);
    float spec = dot(n, h) > 0.0 && dot(n, u_light_dir) > 0.0 ? pow(dot(n, h), WATER_SHININESS) : 0.0;
    return F * refl + (1.0 - F) * trans + WATER_SPEC * spec * u_light_color;
}
