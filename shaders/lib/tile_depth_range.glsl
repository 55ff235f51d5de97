// The view-depth range of the surfaces a compute workgroup's pixels see, for shaders with
// one workgroup per screen tile (tiled.comp, in_range.comp), and the tile's frustum cut to
// it (lib/culling.glsl). Include after lib/culling.glsl and the local_size layout.
shared uint tileDepthMinBits;  // float bits: positive floats order like their bits
shared uint tileDepthMaxBits;

// By one invocation, before the barrier that precedes addToTileDepthRange.
void clearTileDepthRange()
{
    tileDepthMinBits = floatBitsToUint(3.0e38);
    tileDepthMaxBits = 0u;
}

void addToTileDepthRange(float depth)
{
    uint depthBits = floatBitsToUint(max(depth, 0.0));
    atomicMin(tileDepthMinBits, depthBits);
    atomicMax(tileDepthMaxBits, depthBits);
}

// After the barrier that follows every addToTileDepthRange.
bool tileHasSurface()
{
    return tileDepthMaxBits != 0u;
}

TileFrustum workgroupTileFrustum()
{
    uvec2 pixelLo = gl_WorkGroupID.xy * gl_WorkGroupSize.xy;
    return makeTileFrustum(vec2(pixelLo), min(vec2(pixelLo + gl_WorkGroupSize.xy), frame.viewport.xy),
                           uintBitsToFloat(tileDepthMinBits), uintBitsToFloat(tileDepthMaxBits));
}
