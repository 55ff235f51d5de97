#version 450 core
// tiled-quads: one instance per tile, a quad over exactly the tile's pixels at the far plane
// (depth 1). Drawn with the depth test GL_GREATER against the scene's depth, like every
// full-screen pass, so only the tile's pixels that hold a surface run the fragment shader.
#include "lib/bindings.glsl"

// The quads of every draw, grouped by light-count bucket: (tile number, offset and count of
// its run of lights in the index list, unused). A tile has one quad per run of at most a
// light batch of its lights.
layout(std430, binding = TILE_QUADS_BUFFER_BINDING) readonly buffer TileQuads {
    uvec4 tileQuads[];
};

layout(location = 0) uniform uint firstQuad;  // where this draw's quads begin in tileQuads
layout(location = 1) uniform int tilesX;      // tiles per row
layout(location = 2) uniform int tileSize;    // pixels
layout(location = 3) uniform vec2 imageSize;  // pixels

layout(location = 0) flat out uvec2 lightRange;

void main()
{
    uvec4 quad = tileQuads[firstQuad + uint(gl_InstanceID)];
    uint tile = quad.x;
    lightRange = quad.yz;
    ivec2 tileXY = ivec2(int(tile) % tilesX, int(tile) / tilesX);
    // Triangle strip: (0, 0), (1, 0), (0, 1), (1, 1). The last row and column of tiles are
    // cut at the image's edge. Pixel edges lie half a pixel from every pixel centre, so the
    // quad covers exactly the tile's pixels whatever the rounding.
    ivec2 corner = ivec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec2 pixel = min(vec2((tileXY + corner) * tileSize), imageSize);
    gl_Position = vec4(pixel / imageSize * 2.0 - 1.0, 1.0, 1.0);
}
