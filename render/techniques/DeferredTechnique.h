// deferred: the G-buffer, then one full-screen lighting pass per light batch (docs/techniques.md).
#pragma once

#include "gl/Program.h"
#include "gl/VertexArray.h"
#include "render/programs/LightBatches.h"
#include "render/programs/LightingPrograms.h"
#include "render/techniques/Technique.h"

namespace manylights {

// deferred: the geometry pass fills the G-buffer, then a full-screen pass per light batch
// shades every covered pixel with every light of the batch.
class DeferredTechnique : public Technique {
public:
    explicit DeferredTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "deferred"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

private:
    LightingProgram lighting_;
};

}  // namespace manylights
