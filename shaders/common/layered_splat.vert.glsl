#version 450 core
// Single-pass layered splatting (inacio2010 IV-A): one point per particle; the
// geometry shader turns it into the particle's disks on every grid layer it reaches.
layout(std430, binding = 0) readonly buffer Positions { vec4 pos[]; };
out vec3 v_p;        // particle, world

void main()
{
    v_p = pos[gl_VertexID] /* one chunk of particles per draw */.xyz;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // unused: the geometry shader places the disks
}
