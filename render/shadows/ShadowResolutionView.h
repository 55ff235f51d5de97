// --view shadow-resolution (docs/shadows.md, "The shadow-resolution view"; issue 47): for each
// visible pixel, the shadow texels per screen pixel of the pages its shadowed lights' lookups
// read there. It is drawn by the light lists' walk the shadow pool's marking uses (clustered's,
// over the G-buffer, render/techniques/ListLighting.h), built with
// TechniqueVariant::showShadowResolution: each (pixel, light) pair the lighting would shade
// (A · S > 0) whose light has a page there adds the log2 of the figure and a count of 1 to the
// lit image, instead of its light. Every technique reads the same pages at the same shaded
// point, so one walk shows them all, whichever technique the view is asked of.
#pragma once

#include <cmath>
#include <memory>

#include "render/frame/FramePasses.h"
#include "render/frame/FrameTargets.h"
#include "render/frame/TechniqueOptions.h"
#include "render/scene/GpuScene.h"
#include "render/shadows/SurfaceListWalk.h"

namespace manylights {

class ShadowResolutionView {
public:
    ShadowResolutionView();
    ~ShadowResolutionView();
    ShadowResolutionView(const ShadowResolutionView&) = delete;
    ShadowResolutionView& operator=(const ShadowResolutionView&) = delete;

    // Writes the view's sums into the lit image's covered pixels (red: the sum of the pairs'
    // log2 texels per pixel; green: the pairs), after the shadow pool's update of the frame
    // has bound its tables (ShadowPool::bind, the Shadowing block's lookup parameters).
    // `options`: the renderer's technique options, whose G-buffer layout and culling tuning the
    // walk is made for. The lit image's uncovered pixels are left as they are.
    void draw(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, const TechniqueOptions& options);

    // The view's value of a pixel from its sums: their geometric mean, 2^(sum / pairs); 0 where
    // no pair counted (no shadowed light with a page reaches the pixel).
    static float texelsPerPixel(float logSum, float pairs) { return pairs > 0.0f ? std::exp2(logSum / pairs) : 0.0f; }

private:
    std::unique_ptr<SurfaceListWalk> walk_;  // made for the last options drawn with
};

}  // namespace manylights
