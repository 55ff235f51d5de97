// The binding table of shaders/lib/bindings.glsl, read as C++: the uniform blocks, storage
// buffers, texture units and image units every pass binds, under the names the shaders use
// (bindings::FRAME_BLOCK_BINDING, ...). tests/gl/BindingsTest.cpp checks every linked program
// against it.
#pragma once

namespace manylights::bindings {
#include "shaders/lib/bindings.glsl"
}  // namespace manylights::bindings
