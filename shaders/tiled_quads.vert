#version 450 core
// tiled-quads: one instance per tile, a quad over exactly the tile's pixels at the far plane
// (depth 1). Drawn with the depth test GL_GREATER against the scene's depth, like every
// full-screen pass, so only the tile's pixels that hold a surface run the fragment shader.

// The tiles of this draw (one light-count bucket), as tile numbers.
layout(std430, binding = 1) readonly buffer TileOrder {
    uint tileOrder[];
};
// Per tile number: (offset, count) of its lights in the index list.
layout(std430, binding = 2) readonly buffer TileRanges {
    uvec2 tileRanges[];
};

layout(location = 0) uniform uint firstTile;  // where this draw's tiles begin in tileOrder
layout(location = 1) uniform int tilesX;      // tiles per row
layout(location = 2) uniform int tileSize;    // pixels
layout(location = 3) uniform vec2 imageSize;  // pixels

layout(location = 0) flat out uvec2 lightRange;

void main()
{
    uint tile = tileOrder[firstTile + uint(gl_InstanceID)];
    lightRange = tileRanges[tile];
    ivec2 tileXY = ivec2(int(tile) % tilesX, int(tile) / tilesX);
    // Triangle strip: (0, 0), (1, 0), (0, 1), (1, 1). The last row and column of tiles are
    // cut at the image's edge. Pixel edges lie half a pixel from every pixel centre, so the
    // quad covers exactly the tile's pixels whatever the rounding.
    ivec2 corner = ivec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec2 pixel = min(vec2((tileXY + corner) * tileSize), imageSize);
    gl_Position = vec4(pixel / imageSize * 2.0 - 1.0, 1.0, 1.0);
}
