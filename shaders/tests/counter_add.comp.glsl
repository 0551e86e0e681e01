#version 450 core
// Adds u_n to counter u_counter from every invocation, for tests/test_counters_render.c
// to check the 64-bit carry of common/counters.glsl and its overflow bit.
#include "common/counters.glsl"
layout(local_size_x = 64) in;
uniform uint u_n, u_counter;

void main() { FS_COUNT(u_counter, u_n); }
