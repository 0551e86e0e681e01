#version 450 core
// Caustics, virtual screen (iwasaki2006 5.2): one quad per surfel over the
// bounding box of its disk as the screen sees it. The screen lies at height
// u_top over the rectangle u_rect_min + [0, u_rect_size] of the horizontal axes
// (u_ea, u_eb) and looks along -u_light: an oblique orthographic projection,
// world X -> X + t(X) u_light with t(X) = (u_top - X.up) / light.up, the
// distance from X to the screen along the light (the depth).
layout(std430, binding = 0) readonly buffer FsSurfels { vec4 surf[]; }; // (pos, R), (normal, 0)
uniform vec3 u_light;            // unit, towards the light
uniform vec3 u_ea, u_eb, u_eu;   // horizontal axes a, b and up
uniform vec2 u_rect_min, u_rect_size;
uniform float u_top;
out flat vec3 v_center;
out flat vec3 v_normal;
out flat float v_radius;

void main()
{
    uint i = 2u * uint(gl_InstanceID);
    vec4 pr = surf[i], nn = surf[i + 1u];
    vec3 n = nn.xyz;
    v_center = pr.xyz;
    v_normal = n;
    v_radius = pr.w;
    // Only surfels facing the light: the light enters the water through them.
    if (!(dot(n, u_light) > 1e-4 && pr.w > 0.0)) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }
    float lu = dot(u_light, u_eu);
    // Linear part of the projection onto screen axes a and b.
    vec3 ma = u_ea - (dot(u_light, u_ea) / lu) * u_eu;
    vec3 mb = u_eb - (dot(u_light, u_eb) / lu) * u_eu;
    float t = (u_top - dot(pr.xyz, u_eu)) / lu;
    vec3 p = pr.xyz + t * u_light;
    vec2 c = vec2(dot(p, u_ea), dot(p, u_eb));
    // Half extents of the projected disk (an ellipse): R sqrt(|m|^2 - (m.n)^2) per axis.
    vec2 e = pr.w * sqrt(max(vec2(dot(ma, ma) - dot(ma, n) * dot(ma, n), dot(mb, mb) - dot(mb, n) * dot(mb, n)), 0.0));
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    vec2 w = c + corner * e;
    // Depth is written per fragment (gl_FragDepth): the quad's own z is irrelevant.
    gl_Position = vec4(2.0 * (w - u_rect_min) / u_rect_size - 1.0, 0.0, 1.0);
}
