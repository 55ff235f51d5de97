#include "render/culling/GpuScan.h"
#include "render/programs/Bindings.h"

#include "core/Error.h"
#include "render/culling/CullingVariant.h"
#include "render/programs/Locations.h"

namespace manylights {

namespace {

constexpr GLuint kScanGroupSize = 64;  // local_size_x of scan.comp

gl::Program scanProgram(std::string_view label, ScanStep step)
{
    return gl::Program(label, {{GL_COMPUTE_SHADER, "scan.comp"}}, CullingVariant{.scanStep = step}.toDefines());
}

std::uint32_t blocksOf(std::uint32_t count) { return (count + kScanBlock - 1) / kScanBlock; }

}  // namespace

GpuScan::GpuScan()
    : reduce_(scanProgram("scan reduce", ScanStep::Reduce)),
      top_(scanProgram("scan top", ScanStep::Top)),
      spread_(scanProgram("scan spread", ScanStep::Spread))
{
}

void GpuScan::run(FramePasses& passes, std::string_view name, const gl::Buffer& data, std::uint32_t count,
                  std::optional<std::pair<const gl::Buffer*, std::uint32_t>> total)
{
    ML_ASSERT(data.size() >= std::size_t{count} * sizeof(std::uint32_t));
    // Every level's partials before the first step: runLevel holds a reference to its own.
    std::size_t levels = 0;
    for (std::uint32_t n = count; n > kScanBlock; n = blocksOf(n))
        ++levels;
    if (partials_.size() < levels)
        partials_.resize(levels);
    runLevel(passes, name, data, count, 0, total);
}

void GpuScan::runLevel(FramePasses& passes, std::string_view name, const gl::Buffer& data, std::uint32_t count,
                       std::size_t level, std::optional<std::pair<const gl::Buffer*, std::uint32_t>> total)
{
    const Pass pass{.name = name, .storage = Resource::LightGrid, .writes = Resource::LightGrid};
    const auto bindData = [&] { data.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SCAN_DATA_BUFFER_BINDING); };
    if (count <= kScanBlock) {
        passes.run(pass, [&] {
            bindData();
            if (total)
                total->first->bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_STATUS_BUFFER_BINDING);
            top_.set(locations::SCAN_COUNT_LOCATION, count);
            top_.set(locations::SCAN_TOTAL_INDEX_LOCATION, total ? total->second : ~0u);
            top_.use();
            glDispatchCompute(1, 1, 1);
        });
        return;
    }
    const std::uint32_t blocks = blocksOf(count);
    gl::Buffer& partials = partials_[level];
    if (!partials || partials.size() < std::size_t{blocks} * sizeof(std::uint32_t))
        partials = gl::Buffer("scan partials", std::size_t{blocks} * sizeof(std::uint32_t), nullptr, 0);
    const GLuint groups = (blocks + kScanGroupSize - 1) / kScanGroupSize;
    const auto step = [&](const gl::Program& program) {
        passes.run(pass, [&] {
            bindData();
            partials.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::SCAN_PARTIALS_BUFFER_BINDING);
            program.set(locations::SCAN_COUNT_LOCATION, count);
            program.use();
            glDispatchCompute(groups, 1, 1);
        });
    };
    step(reduce_);
    runLevel(passes, name, partials, blocks, level + 1, total);
    step(spread_);
}

std::size_t GpuScan::memoryBytes() const
{
    std::size_t bytes = 0;
    for (const gl::Buffer& partials : partials_)
        bytes += partials.size();
    return bytes;
}

}  // namespace manylights
