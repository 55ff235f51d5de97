#include "render/frame/FramePasses.h"

#include "gl/CallTally.h"
#include "render/programs/Bindings.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

// The barrier bits each kind of access needs after incoherent writes.
constexpr GLbitfield kAllAccess = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                  GL_SHADER_STORAGE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                                  GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT;

template <typename Visit>
void forEachResource(Resource set, Visit&& visit)
{
    for (int bit = 0; bit < kResourceKinds; ++bit)
        if (contains(set, static_cast<Resource>(1 << bit)))
            visit(bit);
}

}  // namespace

FramePasses::FramePasses(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
    : scene_(scene), targets_(targets), profiler_(profiler)
{
    state(0).usedByQueuedDraws = true;  // LitImage: cleared to the background (bit 0)
    static_assert(static_cast<int>(Resource::LitImage) == 1);
}

FramePasses::~FramePasses() { finish(); }

GLbitfield FramePasses::barrierFor(const Pass& pass) const
{
    const bool compute = !draws(pass);
    GLbitfield bits = 0;
    // `access`: the bits of this kind of access; `afterDraws`: what a compute pass waits on
    // where draws used the resource.
    const auto need = [&](Resource set, GLbitfield access, GLbitfield afterDraws) {
        forEachResource(set, [&](int bit) {
            const ResourceState& resource = states_[static_cast<std::size_t>(bit)];
            bits |= resource.unmadeVisible & access;
            if (compute && resource.usedByQueuedDraws)
                bits |= afterDraws;
        });
    };
    need(pass.sampled, GL_TEXTURE_FETCH_BARRIER_BIT, GL_TEXTURE_FETCH_BARRIER_BIT);
    need(pass.images, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // A compute pass on storage buffers may start by clearing them.
    need(pass.storage, GL_SHADER_STORAGE_BARRIER_BIT, GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    need(pass.target, GL_FRAMEBUFFER_BARRIER_BIT, GL_FRAMEBUFFER_BARRIER_BIT);
    need(pass.transfers, GL_BUFFER_UPDATE_BARRIER_BIT, GL_BUFFER_UPDATE_BARRIER_BIT);
    need(pass.indirect, GL_COMMAND_BARRIER_BIT, GL_COMMAND_BARRIER_BIT);
    return bits;
}

void FramePasses::begin(const Pass& pass)
{
    if (!scope_ || scopeName_ != pass.name) {
        scope_.reset();
        scope_.emplace(profiler_, pass.name);
        scopeName_ = pass.name;
    }
    if (const GLbitfield bits = barrierFor(pass)) {
        gl::counted(glMemoryBarrier, bits);
        for (ResourceState& resource : states_) {
            resource.unmadeVisible &= ~bits;
            // On llvmpipe any barrier finishes the queued draws.
            resource.usedByQueuedDraws = false;
        }
    }
    if (draws(pass)) {
        if (pass.framebuffer)
            pass.framebuffer->bind();
        else if (pass.target == Resource::GBuffer)
            targets_.gbuffer.framebuffer().bind();
        else
            targets_.litFramebuffer.bind();
        PipelineState state = pass.state;
        if (pass.target == Resource::LitImage && !pass.framebuffer && litImagePolygonMode_ != PolygonMode::Fill)
            state.polygonMode = litImagePolygonMode_;
        applyPipelineState(state, targets_.width, targets_.height);
    }
    scene_.bind();
    if (contains(pass.sampled, Resource::GBuffer)) {
        targets_.gbuffer.bindForReading();
        targets_.depthStencil.bindUnit(bindings::SCENE_DEPTH_UNIT);
    }
    if (contains(pass.images, Resource::LitImage))
        targets_.lit.bindImage(bindings::LIT_IMAGE_UNIT, GL_READ_WRITE);
}

void FramePasses::end(const Pass& pass)
{
    forEachResource(pass.writes, [&](int bit) { state(bit).unmadeVisible = kAllAccess; });
    if (!draws(pass))
        return;
    forEachResource(pass.target | pass.sampled | pass.images | pass.storage,
                    [&](int bit) { state(bit).usedByQueuedDraws = true; });
    // Draws leave GL's default state behind them for code outside the passes.
    applyPipelineState({}, targets_.width, targets_.height);
}

void FramePasses::finish()
{
    scope_.reset();
    GLbitfield bits = 0;
    for (const ResourceState& resource : states_)
        bits |= resource.unmadeVisible;
    if (bits)
        gl::counted(glMemoryBarrier, bits);
    states_ = {};
}

}  // namespace manylights
