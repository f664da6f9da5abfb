// Texture lookup (docs/RENDERING.md §7): bilinear between texel centres, wrapping at the edges,
// bytes used linearly.
#ifndef VKRT_TEXTURE_GLSL
#define VKRT_TEXTURE_GLSL

vec3 texelColor(uint offset, int width, int x, int y) {
    uint packed = imageLoad(textureTexels, int(offset + uint(y * width + x))).x;
    return vec3(float(packed & 0xffu), float((packed >> 8u) & 0xffu), float((packed >> 16u) & 0xffu)) * (1.0 / 255.0);
}

int wrapIndex(int i, int n) {
    int m = i % n;
    return m < 0 ? m + n : m;
}

vec3 sampleTexture(uint texture, vec2 uv) {
    TextureInfo info = loadTextureInfo(texture);
    uint first = textureFirstTexel(info);
    int w = int(textureWidth(info));
    int h = int(textureHeight(info));
    // Keep the coordinates small before scaling so huge uv cannot overflow the int conversion.
    vec2 f = uv - floor(uv);
    float x = f.x * float(w) - 0.5;
    float y = (1.0 - f.y) * float(h) - 0.5;
    float fx0 = floor(x);
    float fy0 = floor(y);
    float tx = x - fx0;
    float ty = y - fy0;
    int x0 = wrapIndex(int(fx0), w);
    int y0 = wrapIndex(int(fy0), h);
    int x1 = wrapIndex(x0 + 1, w);
    int y1 = wrapIndex(y0 + 1, h);
    vec3 top = mix(texelColor(first, w, x0, y0), texelColor(first, w, x1, y0), tx);
    vec3 bottom = mix(texelColor(first, w, x0, y1), texelColor(first, w, x1, y1), tx);
    return mix(top, bottom, ty);
}

#endif
