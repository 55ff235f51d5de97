// The two stages a lighting pass runs in (--lighting-stage, render/frame/ScreenPasses.h
// runLightingPass): each technique's lighting is one function of a pixel (shadeDeferredPixel,
// shadeListPixel) that a thin main of either stage calls, so that the stages share their
// shading code and give the same image, bit for bit.
// - Fragment: the full-screen pass over the covered pixels writes the pixel's light, which the
//   blend unit stores (the first batch or part) or adds to what is stored (later ones).
// - Compute (LIGHTING_IN_COMPUTE, defined before lib/lighting.glsl): an invocation per pixel
//   loads and stores the lit image itself, adding as the blend unit would.
#ifdef LIGHTING_IN_COMPUTE
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = LIT_IMAGE_UNIT, rgba32f) uniform image2D litImage;

// Whether the pass lights `pixel`: inside the image and holding a surface (the fragment
// stage's covered pixels).
bool isLitPixel(ivec2 pixel)
{
    return all(lessThan(pixel, imageSize(litImage))) && texelFetch(sceneDepth, pixel, 0).r < 1.0;
}

// Stores `color` as the pixel's light, or with `addToStored` adds it to what an earlier batch
// or part stored, as the blend unit adds the fragment stage's colour to the stored one.
void storeLitPixel(ivec2 pixel, vec3 color, bool addToStored)
{
#ifdef SHADOW_PAGE_MARKING  // the shadow pool's marking pass (lib/shadow_pages.glsl) lights nothing
    return;
#endif
    if (addToStored)
        color = color + imageLoad(litImage, pixel).rgb;
    imageStore(litImage, pixel, vec4(color, 1.0));
}
#else
layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;
#endif
