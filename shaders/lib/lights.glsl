// The local lights, all of them in one storage buffer (render/GpuScene.cpp packs it).
struct GpuLight {
    vec4 positionRadius;     // xyz: position; w: culling radius (UNBOUNDED_RADIUS when none)
    vec4 intensityExponent;  // rgb: intensity; w: spot exponent (0 for point lights)
    vec4 attenuation;        // classic: (c, b, a, 0); range falloff: (r, 0, 0, 1)
    vec4 spotAxisCosCutoff;  // xyz: unit spot axis; w: cos(cutoff). Point lights: w = -2, so
                             // every direction is inside the "cone" and S = 1.
};

layout(std430, binding = 0) readonly buffer Lights {
    GpuLight lights[];
};
