// One particle sprite as the compute splatter sees it (common/gl/gl_splat.h),
// built from the raster's own functions so both paths compute the same bounds,
// hits and chords. The program defines one shape: SPRITE_XYZ (spheres of
// radius u_radius, packed float triples), SPRITE_XYZW (spheres, vec4 positions)
// or SPRITE_ELLIPSOID (3 vec4 per particle: common/ellipsoid_sprite.glsl). The
// buffer of the sprites being splatted is at binding 0; the includer declares
// u_view, u_proj and u_radius.
#ifdef SPRITE_ELLIPSOID
#include "common/ellipsoid_sprite.glsl"
layout(std430, binding = 0) readonly buffer FsSprites { vec4 sprite_data[]; };
struct Sprite {
    vec3 c;   // view-space centre
    mat3 inv; // view-space offset -> unit-sphere parameter space
};

// Sprite i of the bound buffer, its NDC rectangle and depth; false when culled.
bool sprite_load(uint i, out Sprite sp, out vec4 rect, out float ndc_z)
{
    mat3 M;
    ellipsoid_setup(sprite_data[3u * i], sprite_data[3u * i + 1u], sprite_data[3u * i + 2u], u_view, u_radius,
                    sp.c, M);
    sp.inv = inverse(M);
    return ellipsoid_sprite_rect(sp.c, M, u_proj, rect, ndc_z);
}

// Sprite i without its bounds (the same values as sprite_load's).
Sprite sprite_core(uint i)
{
    Sprite sp;
    mat3 M;
    ellipsoid_setup(sprite_data[3u * i], sprite_data[3u * i + 1u], sprite_data[3u * i + 2u], u_view, u_radius,
                    sp.c, M);
    sp.inv = inverse(M);
    return sp;
}

// The front hit at dir * t and the chord; false on a miss.
bool sprite_ray(Sprite sp, vec3 dir, out float t, out float chord) { return ellipsoid_ray(dir, sp.c, sp.inv, t, chord); }

vec3 sprite_normal(Sprite sp, vec3 hit) { return ellipsoid_normal(hit, sp.c, sp.inv); }
#else
#include "common/sphere_bounds.glsl"
#ifdef SPRITE_XYZ
layout(std430, binding = 0) readonly buffer FsSprites { float sprite_pos[]; };
vec3 sprite_centre(uint i) { return vec3(sprite_pos[3u * i], sprite_pos[3u * i + 1u], sprite_pos[3u * i + 2u]); }
#else
layout(std430, binding = 0) readonly buffer FsSprites { vec4 sprite_pos[]; };
vec3 sprite_centre(uint i) { return sprite_pos[i].xyz; }
#endif
struct Sprite {
    vec3 c; // view-space centre
};

bool sprite_load(uint i, out Sprite sp, out vec4 rect, out float ndc_z)
{
    sp.c = (u_view * vec4(sprite_centre(i), 1.0)).xyz;
    return sphere_sprite_rect(sp.c, u_radius, u_proj, rect, ndc_z);
}

Sprite sprite_core(uint i)
{
    Sprite sp;
    sp.c = (u_view * vec4(sprite_centre(i), 1.0)).xyz;
    return sp;
}

bool sprite_ray(Sprite sp, vec3 dir, out float t, out float chord)
{
    float b, s;
    bool hit = sphere_ray(dir, sp.c, u_radius, b, s);
    t = b - s;
    chord = 2.0 * s;
    return hit;
}

vec3 sprite_normal(Sprite sp, vec3 hit) { return (hit - sp.c) / u_radius; }
#endif
