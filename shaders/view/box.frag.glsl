#version 450 core
// Container edges: bright where in front of the fluid, dim behind it.
in float eye_depth;
out vec4 color;
layout(binding = 0) uniform sampler2D depth; // G-buffer depth, rows top to bottom
uniform vec2 u_window;                        // window size in pixels
void main()
{
    vec2 uv = gl_FragCoord.xy / u_window;
    float d = texture(depth, vec2(uv.x, 1.0 - uv.y)).r;
    color = eye_depth <= d ? vec4(1.0, 0.8, 0.3, 1.0) : vec4(0.55, 0.45, 0.25, 1.0);
}
