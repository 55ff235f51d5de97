// The one cache of render/'s shader variants (issue 46): the programs of one set of shader
// files, each compiled the first time its key is asked for and kept. A key is a typed struct
// (render/programs/LightingPrograms.h ShaderVariant, render/culling/CullingVariant.h) that
// orders itself and gives the program's #defines by its one toDefines(), so that what a
// program is cached by and what it is compiled with cannot drift apart.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gl/Program.h"

namespace manylights {

template <typename Key>
class ProgramVariants {
public:
    // Programs of `stages`, each with `defines` (what every variant shares) and its key's.
    ProgramVariants(std::string label, std::vector<gl::ShaderStage> stages, gl::Defines defines = {})
        : label_(std::move(label)), stages_(std::move(stages)), defines_(std::move(defines))
    {
    }

    // The program of `key`, compiled the first time it is asked for (throws manylights::Error
    // as gl::Program does).
    const gl::Program& variant(const Key& key) const
    {
        auto found = variants_.find(key);
        if (found == variants_.end())
            found = variants_.emplace(key, gl::Program(label_, stages_, key.toDefines(defines_))).first;
        return found->second;
    }

private:
    std::string label_;
    std::vector<gl::ShaderStage> stages_;
    gl::Defines defines_;
    mutable std::map<Key, gl::Program> variants_;
};

}  // namespace manylights
