/* The shared shading pass (docs/DESIGN.md): every method's G-buffer is lit here with
 * the same light, material and background, so image differences come from the
 * surface alone. Per pixel and independent of the others: deterministic for any
 * thread count. */
#include "shading.h"
#include "vec3.h"
#include <math.h>
#include <stddef.h>
#include <string.h>

/* Sky, linear RGB. */
static const float SKY_HORIZON[3] = {0.78f, 0.84f, 0.90f};
static const float SKY_ZENITH[3] = {0.16f, 0.34f, 0.70f};
static const float SKY_GROUND[3] = {0.30f, 0.28f, 0.26f};
/* Checker floor albedos, and the distance (in check sizes) over which the floor
 * fades into the horizon haze. */
static const float CHECK_LIGHT = 0.75f, CHECK_DARK = 0.22f, CHECK_HAZE_FADE = 120.0f;
/* Opaque: Blinn-Phong; water: a sharp sun highlight. */
static const float OPAQUE_SPEC = 0.25f, OPAQUE_SHININESS = 48.0f;
static const float WATER_SPEC = 0.8f, WATER_SHININESS = 256.0f;

typedef struct shade_ctx {
    const fs_scene *s;
    float eye[3], fwd[3];
    float L[3], up[3];
    float floor_y, check;
    float pixel_angle;    /* angular size of one pixel: ray cone spread per unit distance */
    float eps;            /* rays leave a surface beyond this distance (a thousandth of r) */
    float floor_light[3]; /* ambient + direct light on the floor */
    fs_camera_rays rays;  /* the camera's basis, once per pass, not per pixel */
} shade_ctx;

static float mixf(float a, float b, float t) { return a + (b - a) * t; }

static void sky(const shade_ctx *c, const float d[3], float out[3])
{
    float t = fs_v3_dot(d, c->up);
    if (t >= 0) {
        float k = 1.0f - (1.0f - t) * (1.0f - t); /* quick departure from the horizon */
        for (int i = 0; i < 3; i++) out[i] = mixf(SKY_HORIZON[i], SKY_ZENITH[i], k);
    } else {
        float k = fminf(-t * 8.0f, 1.0f); /* short blend into the ground colour */
        for (int i = 0; i < 3; i++) out[i] = mixf(SKY_HORIZON[i], SKY_GROUND[i], k);
    }
}

/* Integral of the unit square wave (+1 on [0,1), -1 on [1,2), period 2). */
static float square_wave_integral(float x)
{
    float m = x - 2.0f * floorf(0.5f * x);
    return 1.0f - fabsf(m - 1.0f);
}

/* The square wave box-filtered over width w (check units): -1..1, fades to 0
 * where a pixel covers many checks, so distant checks do not alias. */
static float filtered_square(float x, float w)
{
    if (w < 1e-4f) return ((long)floorf(x) & 1) ? -1.0f : 1.0f;
    return (square_wave_integral(x + 0.5f * w) - square_wave_integral(x - 0.5f * w)) / w;
}

static float highlight(const shade_ctx *c, const float n[3], const float v[3], float shininess)
{
    float h[3] = {c->L[0] + v[0], c->L[1] + v[1], c->L[2] + v[2]};
    fs_v3_normalize(h);
    float nh = fs_v3_dot(n, h);
    return nh > 0 && fs_v3_dot(n, c->L) > 0 ? powf(nh, shininess) : 0.0f;
}

static void shade_opaque(const shade_ctx *c, const float n[3], const float v[3], const float albedo[3], float out[3])
{
    float nl = fmaxf(fs_v3_dot(n, c->L), 0.0f);
    float spec = OPAQUE_SPEC * highlight(c, n, v, OPAQUE_SHININESS);
    for (int i = 0; i < 3; i++)
        out[i] = albedo[i] * (c->s->ambient + nl * c->s->light_color[i]) + spec * c->s->light_color[i];
}

/* Distance along the ray o + t d to the checker floor (seen from above); INFINITY
 * when it does not reach it or there is no floor. */
static float floor_distance(const shade_ctx *c, const float o[3], const float d[3])
{
    int u = c->s->up_axis;
    float height = o[u] - c->floor_y;
    if (c->s->background != FS_BACKGROUND_CHECKER || height <= 0 || d[u] >= 0) return INFINITY;
    return height / -d[u];
}

/* An obstacle (opaque, unshadowed) hit by the ray o + t d before tmax: its colour in
 * out, and t in *hit_t; 0 when none is hit. */
static int obstacle_seen(const shade_ctx *c, const float o[3], const float d[3], float tmax, float out[3], float *hit_t)
{
    float t, n[3];
    int i = c->s->obstacles.n ? fs_obstacles_hit(&c->s->obstacles, o, d, c->eps, tmax, &t, n) : -1;
    if (i < 0) return 0;
    float v[3] = {-d[0], -d[1], -d[2]};
    shade_opaque(c, n, v, c->s->obstacles.o[i].color, out);
    *hit_t = t;
    return 1;
}

/* What a ray from origin o in direction d sees: an obstacle, the floor (checker
 * mode, from above) or the sky. travelled: distance from the eye to o, for the
 * pixel's footprint on the floor. Returns the distance to the obstacle seen,
 * INFINITY when none is. */
static float background(const shade_ctx *c, const float o[3], const float d[3], float travelled, float out[3])
{
    float t = floor_distance(c, o, d), hit_t;
    if (obstacle_seen(c, o, d, t, out, &hit_t)) return hit_t;
    sky(c, d, out);
    if (!isfinite(t)) return INFINITY;
    int u = c->s->up_axis;
    int a = (u + 1) % 3, b = (u + 2) % 3;
    float pa = (o[a] + t * d[a]) / c->check, pb = (o[b] + t * d[b]) / c->check;
    /* Pixel footprint on the floor: an ellipse stretched along the ray's
     * horizontal direction by 1/|d_up|; its extent along each floor axis. */
    float across = (travelled + t) * c->pixel_angle / c->check, along = across / -d[u];
    float hl = sqrtf(d[a] * d[a] + d[b] * d[b]);
    float ha = hl > 1e-6f ? d[a] / hl : 1.0f, hb = hl > 1e-6f ? d[b] / hl : 0.0f;
    float wa = sqrtf(along * ha * along * ha + across * hb * across * hb);
    float wb = sqrtf(along * hb * along * hb + across * ha * across * ha);
    float parity = filtered_square(pa, wa) * filtered_square(pb, wb); /* +1 light, -1 dark */
    float albedo = 0.5f * (CHECK_LIGHT + CHECK_DARK) + 0.5f * (CHECK_LIGHT - CHECK_DARK) * parity;
    float haze = expf(-t / c->check / CHECK_HAZE_FADE);
    for (int i = 0; i < 3; i++) out[i] = mixf(out[i], albedo * c->floor_light[i], haze);
    return INFINITY;
}

/* Schlick's approximation, cos_i the cosine between view and normal. */
static float fresnel(float cos_i, float ior)
{
    float f0 = (ior - 1) / (ior + 1);
    f0 *= f0;
    float m = 1 - cos_i;
    return f0 + (1 - f0) * m * m * m * m * m;
}

static void shade_water(const shade_ctx *c, const float p[3], float dist, const float n[3], const float d[3],
                        float thickness, const float tint[3], float out[3])
{
    float v[3] = {-d[0], -d[1], -d[2]};
    float cos_i = fminf(fmaxf(fs_v3_dot(n, v), 0.0f), 1.0f);
    float ior = c->s->ior > 1e-3f ? c->s->ior : 1.0f;
    float F = fresnel(cos_i, ior);

    float r[3], refl[3];
    for (int i = 0; i < 3; i++) r[i] = d[i] + 2 * cos_i * n[i];
    background(c, p, r, dist, refl);
    float spec = WATER_SPEC * highlight(c, n, v, WATER_SHININESS);

    /* Snell into the water (never total internal reflection entering it); the
     * background is looked up from where the ray leaves the fluid. */
    float eta = 1.0f / ior, k = 1 - eta * eta * (1 - cos_i * cos_i);
    float t[3], exit[3], trans[3];
    float tn = eta * cos_i - sqrtf(fmaxf(k, 0.0f));
    for (int i = 0; i < 3; i++) t[i] = eta * d[i] + tn * n[i];
    fs_v3_normalize(t);
    /* A solid inside the water is seen through the water in front of it. */
    float seen, to_floor = floor_distance(c, p, t);
    if (obstacle_seen(c, p, t, thickness, trans, &seen)) thickness = seen;
    else if (to_floor <= thickness) {
        /* The water ends at the floor: a refracted ray that reaches it within the
         * thickness sees the floor there (looked up from p: from an exit point
         * below the floor it would see the sky's ground colour, issue 35). */
        thickness = to_floor;
        background(c, p, t, dist, trans);
    } else {
        for (int i = 0; i < 3; i++) exit[i] = p[i] + t[i] * thickness;
        background(c, exit, t, dist + thickness, trans);
    }

    for (int i = 0; i < 3; i++) {
        float transmitted = trans[i] * tint[i] * expf(-c->s->absorption[i] * thickness);
        out[i] = F * refl[i] + (1 - F) * transmitted + spec * c->s->light_color[i];
    }
}

/* The light, floor and footprint every pixel of one shading pass shares. */
static void shade_setup(shade_ctx *c, const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g, float floor_y)
{
    c->s = s;
    fs_camera_rays_init(cam, &c->rays);
    memcpy(c->fwd, c->rays.fwd, sizeof c->fwd);
    for (int i = 0; i < 3; i++) {
        c->eye[i] = cam->eye[i];
        c->L[i] = s->light_dir[i];
        c->up[i] = i == s->up_axis ? 1.0f : 0.0f;
    }
    fs_v3_normalize(c->L);
    c->floor_y = floor_y;
    c->check = s->radius > 0 ? 8.0f * s->radius : 1.0f;
    c->eps = 1e-3f * (s->radius > 0 ? s->radius : 1.0f);
    c->pixel_angle = 2.0f * tanf(cam->fovy_deg * (float)M_PI / 360.0f) / g->h;
    float floor_nl = fmaxf(c->L[s->up_axis], 0.0f);
    for (int i = 0; i < 3; i++) c->floor_light[i] = s->ambient + floor_nl * s->light_color[i];
}

/* Pixel idx's surface along view ray d: its normal made to face the camera, lit
 * as the scene's material with the pixel's albedo. */
static void shade_surface(const shade_ctx *c, const fs_gbuffer *g, size_t idx, const float d[3], const float *albedo,
                          float col[3])
{
    float n[3], vn[3] = {g->normal[3 * idx], g->normal[3 * idx + 1], g->normal[3 * idx + 2]};
    if (!(fs_v3_dot(vn, vn) > 1e-12f)) {
        vn[0] = 0;
        vn[1] = 0;
        vn[2] = 1;
    }
    fs_camera_rays_from_view(&c->rays, vn, n);
    fs_v3_normalize(n);
    /* Normals bent slightly away at silhouettes: make them face the camera. */
    float nv = -fs_v3_dot(n, d);
    if (nv < 0.02f) {
        for (int i = 0; i < 3; i++) n[i] -= (0.02f - nv) * d[i];
        fs_v3_normalize(n);
    }
    float v[3] = {-d[0], -d[1], -d[2]};
    if (c->s->material == FS_MATERIAL_OPAQUE) {
        shade_opaque(c, n, v, albedo, col);
        return;
    }
    float along = fs_v3_dot(d, c->fwd), depth = g->depth[idx], p[3];
    float dist = isfinite(depth) && along > 0 ? depth / along : 0.0f;
    for (int i = 0; i < 3; i++) p[i] = c->eye[i] + d[i] * dist;
    float thick = g->thickness[idx];
    thick = isfinite(thick) && thick > 0 ? thick : 0.0f;
    shade_water(c, p, dist, n, d, thick, albedo, col);
}

/* Pixel (x, y): the background, and over it the surface by its coverage. sx, sy:
 * the camera's pixels per G-buffer pixel. */
static void shade_pixel(const shade_ctx *c, const fs_gbuffer *g, const float *color, int x, int y, float sx, float sy,
                        float *o)
{
    size_t idx = (size_t)y * g->w + x;
    float d[3], bg[3], col[3];
    fs_camera_rays_dir(&c->rays, (x + 0.5f) * sx, (y + 0.5f) * sy, d);
    float t_obstacle = background(c, c->eye, d, 0.0f, bg);
    float cov = g->coverage[idx];
    cov = cov > 0 ? (cov < 1 ? cov : 1) : 0; /* also NaN -> 0 */
    /* A solid in front of the fluid: the pixel shows the solid alone (a NaN depth hides too). */
    if (cov > 0 && isfinite(t_obstacle) && !(t_obstacle * fs_v3_dot(d, c->fwd) >= g->depth[idx])) cov = 0;
    if (cov > 0) {
        shade_surface(c, g, idx, d, color ? color + 4 * idx : c->s->material_color, col);
        for (int i = 0; i < 3; i++) bg[i] = mixf(bg[i], col[i], cov);
    }
    o[0] = bg[0];
    o[1] = bg[1];
    o[2] = bg[2];
    o[3] = 1.0f;
}

void fs_shade(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g, float floor_y, float *rgba)
{
    shade_ctx c;
    shade_setup(&c, s, cam, g, floor_y);
    /* The G-buffer may be smaller or larger than the camera's image: scale pixel positions. */
    float sx = (float)cam->width / g->w, sy = (float)cam->height / g->h;
    int w = g->w, h = g->h;
    const float *color = fs_gbuffer_aov(g, FS_AOV_COLOR); /* NULL: the material's colour */
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) shade_pixel(&c, g, color, x, y, sx, sy, rgba + 4 * ((size_t)y * w + x));
}
