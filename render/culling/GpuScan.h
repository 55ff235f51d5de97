// An exclusive prefix sum over a buffer of uints on the GPU (shaders/scan.comp), for the
// clustered technique's light lists (render/culling/ClusterLists.h): each light's first slot from the
// lights' pair counts, each cluster's first entry from the lists' lengths, and each digit's
// places in the radix sort. Blocks of kScanBlock elements, one invocation each, in as many
// levels as the count needs (three up to 16,777,216 elements); each step is a pass of its own
// so that the frame's passes put the barrier between them.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/frame/FramePasses.h"

namespace manylights {

inline constexpr std::uint32_t kScanBlock = 256;

class GpuScan {
public:
    GpuScan();

    // Replaces the first `count` uints of `data` by the sum of those before each, in passes
    // named `name`. With `total`, also writes the sum of all to element `total->second` of
    // the buffer `total->first` (bound at CLUSTER_LIST_STATUS_BUFFER_BINDING).
    void run(FramePasses& passes, std::string_view name, const gl::Buffer& data, std::uint32_t count,
             std::optional<std::pair<const gl::Buffer*, std::uint32_t>> total = std::nullopt);

    std::size_t memoryBytes() const;

private:
    void runLevel(FramePasses& passes, std::string_view name, const gl::Buffer& data, std::uint32_t count,
                  std::size_t level, std::optional<std::pair<const gl::Buffer*, std::uint32_t>> total);

    gl::Program reduce_;
    gl::Program top_;
    gl::Program spread_;
    std::vector<gl::Buffer> partials_;  // one per level below the first
};

}  // namespace manylights
