// Camera rays (docs/RENDERING.md §1).
#ifndef VKRT_CAMERA_GLSL
#define VKRT_CAMERA_GLSL

struct CameraRay {
    vec3 origin;
    vec3 dir;  // unit length
};

// Pixel (i, j), j = 0 the top row, with the sub-pixel sample (sx, sy) in [0,1)^2; with a thin lens
// (HAS_THIN_LENS), from the lens point `lensSample` towards where the pinhole ray meets the focus
// plane: the float operations of host/cpu/camera.cpp, in the same order.
CameraRay cameraRay(uint i, uint j, vec2 subPixel, vec2 lensSample) {
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
        if (HAS_THIN_LENS && frameLensRadius() > 0.0) {  // the general kernel also renders pinholes
            vec2 disk = concentricDisk(lensSample) * frameLensRadius();
            vec3 offset = disk.x * u + disk.y * v;
            r.origin = r.origin + offset;
            float d = frameFocusDistance();
            r.dir = d >= 1.0 ? normalize(-w - offset / d) : normalize(-d * w - offset);
        }
    } else {
        vec3 q = -frameFocalLength() * w + a * u + b * v;
        r.origin = frame.cameraPosition.xyz;
        r.dir = normalize(q);
        if (HAS_THIN_LENS && frameLensRadius() > 0.0) {  // the general kernel also renders pinholes
            vec2 disk = concentricDisk(lensSample) * frameLensRadius();
            vec3 offset = disk.x * u + disk.y * v;
            r.origin = frame.cameraPosition.xyz + offset;
            float k = frameFocusDistance() / frameFocalLength();  // scaled as host/cpu/camera.cpp says why
            r.dir = k >= 1.0 ? normalize(q - offset / k) : normalize(q * k - offset);
        }
    }
    return r;
}

// Pixel sample `index` of pixel (x, y): key gets its sequence position and seed, sampleTime its
// time (motion blur), and the camera ray is returned. The megakernel (render.comp) and the
// wavefront's GENERATE stage both start a sample here.
CameraRay cameraSample(uint x, uint y, uint index, inout SampleKey key) {
    key.index = sampleIndex(samplerKind(), index);
    key.seed = sampleSeed(samplerKind(), frameSeed(), index);
    vec2 subPixel = sample2D(samplerKind(), frame.pixelGrid, key.pixel, key.index, DIM_CAMERA, key.seed);
    vec2 lens = HAS_THIN_LENS ? sample2D(samplerKind(), frame.pixelGrid, key.pixel, key.index, DIM_LENS, key.seed) : vec2(0.5);
    if (HAS_MOTION) {
        float u = sample1D(samplerKind(), frame.pixelGrid, key.pixel, key.index, DIM_TIME, key.seed);
        sampleTime = frameShutterOpen() + (frameShutterClose() - frameShutterOpen()) * u;
    }
    return cameraRay(x, y, subPixel, lens);
}

#endif
