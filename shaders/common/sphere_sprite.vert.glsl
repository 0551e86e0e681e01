#version 450 core
// One screen-aligned quad per particle (instanced triangle strip), sized to the
// exact screen-space bounds of the perspective-projected sphere, so the sprite
// covers the whole silhouette at any distance (no point-size limit).
layout(std430, binding = 0) readonly buffer Positions { vec4 pos[]; };
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
out flat vec3 v_center; // view space

// Tangent slopes x/(-z) of the two lines through the eye touching a circle
// of radius r centred at (c, -u) in one axis plane.
vec2 tangent_slopes(float c, float u, float r)
{
    float disc = sqrt(max(c * c + u * u - r * r, 0.0));
    float den = u * u - r * r;
    return vec2(c * u - r * disc, c * u + r * disc) / den;
}

void main()
{
    vec3 c = (u_view * vec4(pos[gl_InstanceID].xyz, 1.0)).xyz;
    v_center = c;
    float u = -c.z;
    if (u <= u_radius * 1.001) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; } // behind or around the eye: cull
    vec2 sx = tangent_slopes(c.x, u, u_radius) * u_proj[0][0];
    vec2 sy = tangent_slopes(c.y, u, u_radius) * u_proj[1][1];
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec2 ndc = vec2(mix(sx.x, sx.y, corner.x), mix(sy.x, sy.y, corner.y));
    // Depth of the quad: the sphere's nearest point, so early depth rejection stays conservative.
    vec4 clip = u_proj * vec4(0.0, 0.0, c.z + u_radius, 1.0);
    gl_Position = vec4(ndc, clip.z / clip.w, 1.0);
}
