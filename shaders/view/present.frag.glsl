#version 450 core
// Shows the linear RGBA image (rows top to bottom) sRGB-encoded, as PNGs are.
in vec2 uv;
out vec4 color;
layout(binding = 0) uniform sampler2D image;

float srgb(float c)
{
    c = clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

void main()
{
    vec4 c = texture(image, vec2(uv.x, 1.0 - uv.y));
    color = vec4(srgb(c.r), srgb(c.g), srgb(c.b), 1.0);
}
