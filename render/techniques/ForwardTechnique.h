// forward: the reference every technique is checked against (docs/techniques.md).
#pragma once

#include "gl/Program.h"
#include "render/programs/LightingPrograms.h"
#include "render/techniques/Technique.h"

namespace manylights {

class ForwardTechnique : public Technique {
public:
    explicit ForwardTechnique(const TechniqueOptions& options);
    bool isReference() const override { return true; }
    std::string_view name() const override { return "forward"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

private:
    LightingProgram program_;  // the lighting and, as a variant, the depth pre-pass
};

}  // namespace manylights
