#version 450 core
// Screen-space ambient occlusion (render/effects/Ssao.cpp; docs/shadows.md): for each visible
// surface, how much of the hemisphere around its normal, within `radius`, lies behind other
// visible surfaces. Samples are taken in view space from a fixed kernel, rotated per pixel
// by a 4x4 tiled noise (shaders/ssao_blur.comp averages the 4x4 pattern away).
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#define LIGHTING_IN_COMPUTE 1
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = OCCLUSION_IMAGE_UNIT, r32f) uniform writeonly image2D rawOcclusion;
layout(location = SSAO_PARAMS_LOCATION) uniform vec4 ssaoParams;  // x: radius, y: strength, z: depth bias (world units)

const int KERNEL_SIZE = 16;
layout(std430, binding = SSAO_SAMPLES_BUFFER_BINDING) readonly buffer SsaoSamples {
    vec4 kernel[KERNEL_SIZE];  // xyz: offsets in the unit hemisphere around +z (tangent space)
    vec4 noise[16];            // xy: unit rotation vectors of the 4x4 noise tile
};

vec3 toView(vec3 world)
{
    return (frame.view * vec4(world, 1.0)).xyz;
}

// The pixel a view-space point projects to (the camera looks along −z).
vec2 projectToPixel(vec3 viewPoint)
{
    vec2 ndc = viewPoint.xy / (-viewPoint.z * frame.projection.xy);
    return (ndc * 0.5 + 0.5) * frame.viewport.xy;
}

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(rawOcclusion))))
        return;
    if (texelFetch(sceneDepth, pixel, 0).r == 1.0) {
        imageStore(rawOcclusion, pixel, vec4(1.0));
        return;
    }
    float radius = ssaoParams.x;
    Surface s = gbufferSurface(pixel);
    vec3 P = toView(s.position);
    vec3 N = normalize(mat3(frame.view) * s.normal);
    // Tangent basis rotated by this pixel's noise vector (Gram–Schmidt against N).
    vec3 randomVector = vec3(noise[(pixel.y % 4) * 4 + pixel.x % 4].xy, 0.0);
    vec3 T = randomVector - N * dot(randomVector, N);
    T = dot(T, T) > 1e-8 ? normalize(T) : normalize(abs(N.x) < 0.9 ? cross(N, vec3(1, 0, 0)) : cross(N, vec3(0, 1, 0)));
    mat3 TBN = mat3(T, cross(N, T), N);

    float occluded = 0.0;
    for (int i = 0; i < KERNEL_SIZE; ++i) {
        vec3 samplePoint = P + TBN * kernel[i].xyz * radius;
        if (samplePoint.z >= 0.0)
            continue;  // behind the camera: nothing visible can hide it
        ivec2 samplePixel = ivec2(floor(projectToPixel(samplePoint)));
        if (any(lessThan(samplePixel, ivec2(0))) || any(greaterThanEqual(samplePixel, ivec2(frame.viewport.xy))))
            continue;  // off screen: unknown, counted as open
        if (texelFetch(sceneDepth, samplePixel, 0).r == 1.0)
            continue;  // background
        Surface occluder = gbufferSurface(samplePixel);
        vec3 Q = toView(occluder.position);
        vec3 M = mat3(frame.view) * occluder.normal;
        // The visible surface's depth along the sample's own view ray, from its tangent plane
        // at that pixel: exact for flat surfaces, so an open plane never occludes itself
        // through the pixel grid's rounding (comparing with the pixel centre's depth would).
        float along = dot(samplePoint, M);
        float occluderZ = abs(along) > 1e-6 * length(samplePoint) ? samplePoint.z * dot(Q, M) / along : Q.z;
        // Occluded when the visible surface is in front of the sample point; occluders far in
        // front of P (beyond the radius) fade out rather than darken a distant background.
        if (occluderZ >= samplePoint.z + ssaoParams.z)
            occluded += smoothstep(0.0, 1.0, radius / abs(P.z - Q.z));
    }
    float ao = clamp(1.0 - ssaoParams.y * occluded / float(KERNEL_SIZE), 0.0, 1.0);
    imageStore(rawOcclusion, pixel, vec4(ao));
}
