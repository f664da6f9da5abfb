// Camera rays (docs/RENDERING.md §1).
#ifndef VKRT_CAMERA_GLSL
#define VKRT_CAMERA_GLSL

struct CameraRay {
    vec3 origin;
    vec3 dir;  // unit length
};

// Pixel (i, j), j = 0 the top row, with the sub-pixel sample (sx, sy) in [0,1)^2.
CameraRay cameraRay(uint i, uint j, vec2 subPixel) {
    float nx = float(frameWidth());
    float ny = float(frameHeight());
    float a = framePlaneWidth() * ((float(i) + subPixel.x) / nx - 0.5);
    float b = framePlaneHeight() * (0.5 - (float(j) + subPixel.y) / ny);
    vec3 u = frame.cameraU.xyz;
    vec3 v = frame.cameraV.xyz;
    vec3 w = frame.cameraW.xyz;
    CameraRay r;
    if (frameCameraType() == CAMERA_ORTHOGRAPHIC) {
        r.origin = frame.cameraPosition.xyz + a * u + b * v;
        r.dir = -w;
    } else {
        r.origin = frame.cameraPosition.xyz;
        r.dir = normalize(-frameFocalLength() * w + a * u + b * v);
    }
    return r;
}

#endif
