#version 450 core
// tiled-quads: one instance per tile over exactly the tile's pixels at the far plane (depth
// 1), drawn with the depth test GL_GREATER against the scene's depth, like every full-screen
// pass, so only the tile's pixels that hold a surface run the fragment shader. A tile is one
// point of the tile's size where the driver draws points that large, else a quad
// (render/techniques/TiledQuadsTechnique.cpp says why).
#include "lib/bindings.glsl"
#include "lib/locations.glsl"

// The quads of every draw, grouped by light-count bucket: (tile number, offset and count of
// its run of lights in the index list, unused). A tile has one quad per run of at most a
// light batch of its lights.
layout(std430, binding = TILE_QUADS_BUFFER_BINDING) readonly buffer TileQuads {
    uvec4 tileQuads[];
};

layout(location = TILE_FIRST_QUAD_LOCATION) uniform uint firstQuad;  // where this draw's quads begin in tileQuads
layout(location = TILES_X_LOCATION) uniform int tilesX;   // tiles per row
layout(location = TILE_SIZE_LOCATION) uniform int tileSize;   // pixels
// Pixels: the image for quads; the whole grid of tiles for points, since GL drops a point
// whose centre lies outside the viewport, as the centre of a tile cut at the image's edge may.
layout(location = TILE_VIEWPORT_SIZE_LOCATION) uniform vec2 viewportSize;
layout(location = TILES_AS_POINTS_LOCATION) uniform bool tilesAsPoints;

layout(location = 0) flat out uvec2 lightRange;

void main()
{
    uvec4 quad = tileQuads[firstQuad + uint(gl_InstanceID)];
    uint tile = quad.x;
    lightRange = quad.yz;
    ivec2 tileXY = ivec2(int(tile) % tilesX, int(tile) / tilesX);
    // Tile edges lie half a pixel from every pixel centre, so a point or quad covers exactly
    // the tile's pixels whatever the rounding.
    vec2 pixel;
    if (tilesAsPoints) {
        // A point covers the pixels whose centres lie in the square of its size around it.
        // The scissor cuts the last row and column of tiles at the image's edge.
        gl_PointSize = float(tileSize);
        pixel = (vec2(tileXY) + 0.5) * float(tileSize);
    } else {
        // Triangle strip: (0, 0), (1, 0), (0, 1), (1, 1), cut at the image's edge.
        ivec2 corner = ivec2(gl_VertexID & 1, gl_VertexID >> 1);
        pixel = min(vec2((tileXY + corner) * tileSize), viewportSize);
    }
    gl_Position = vec4(pixel / viewportSize * 2.0 - 1.0, 1.0, 1.0);
}
