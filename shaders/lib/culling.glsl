// Conservative light-culling tests shared by the tiled and clustered techniques, in view
// space. They may keep a light that does not reach a region, never the other way round.

bool sphereTouchesBox(vec3 centre, float radius, vec3 lo, vec3 hi)
{
    vec3 nearest = clamp(centre, lo, hi);
    vec3 d = centre - nearest;
    return dot(d, d) <= radius * radius;
}

// Whether a spot's cone (apex, unit axis, half-angle < 90°) can reach a sphere bounding the
// cluster: conservative, it only rejects clusters wholly outside the infinite cone.
bool coneTouchesSphere(vec3 apex, vec3 axis, float cosCutoff, vec3 centre, float radius)
{
    if (cosCutoff <= 0.0)
        return true;  // 90° or wider: no cone test
    vec3 v = centre - apex;
    float along = dot(v, axis);
    float across = sqrt(max(dot(v, v) - along * along, 0.0));
    float sinCutoff = sqrt(max(1.0 - cosCutoff * cosCutoff, 0.0));
    float distanceToCone = cosCutoff * across - sinCutoff * along;
    return distanceToCone <= radius * 1.001 + 1e-4 && along >= -radius;
}

// A screen tile's frustum (pixels pixelLo..pixelHi) cut to the view-depth range of the
// surfaces seen through it: four planes through the eye (normals point inwards), the cut
// frustum's bounding box (its depths widened slightly so rounding cannot cut a surface off:
// it holds the depth test), and a sphere around that box for the cone test.
struct TileFrustum {
    vec3 planes[4];
    vec3 boxLo;  // the view-space box around the cut frustum
    vec3 boxHi;
    vec3 boxCentre;
    float boxRadius;
};

// The view-space slope (x/z, y/z magnitudes) of the ray through window position `pixel`.
vec2 pixelSlope(vec2 pixel)
{
    return (pixel * frame.viewport.zw * 2.0 - 1.0) * frame.projection.xy;
}

// The view-space box around the part of the frustum through the pixels pixelLo..pixelHi
// between view depths zNear and zFar (the camera looks down -Z), grown by 0.1% in depth so
// that rounding cannot cut a surface off: a surface on the boundary between two such
// sections is inside the boxes of both.
void frustumSectionBox(vec2 pixelLo, vec2 pixelHi, float zNear, float zFar, out vec3 lo, out vec3 hi)
{
    vec2 slopeLo = pixelSlope(pixelLo);
    vec2 slopeHi = pixelSlope(pixelHi);
    zNear *= 0.999;
    zFar *= 1.001;
    lo = vec3(min(slopeLo * zNear, slopeLo * zFar), -zFar);
    hi = vec3(max(slopeHi * zNear, slopeHi * zFar), -zNear);
}

TileFrustum makeTileFrustum(vec2 pixelLo, vec2 pixelHi, float depthMin, float depthMax)
{
    TileFrustum tile;
    vec2 slopeLo = pixelSlope(pixelLo);
    vec2 slopeHi = pixelSlope(pixelHi);
    tile.planes = vec3[4](normalize(vec3(1.0, 0.0, slopeLo.x)), normalize(vec3(-1.0, 0.0, -slopeHi.x)),
                          normalize(vec3(0.0, 1.0, slopeLo.y)), normalize(vec3(0.0, -1.0, -slopeHi.y)));
    frustumSectionBox(pixelLo, pixelHi, depthMin, depthMax, tile.boxLo, tile.boxHi);
    tile.boxCentre = 0.5 * (tile.boxLo + tile.boxHi);
    tile.boxRadius = 0.5 * length(tile.boxHi - tile.boxLo);
    return tile;
}

// Whether `light` may reach a surface in the tile's frustum (conservative).
bool lightMayReachTile(GpuLight light, TileFrustum tile)
{
    float radius = light.positionRadius.w;
    if (radius <= 0.0)
        return false;
    if (radius >= UNBOUNDED_RADIUS)
        return true;
    vec3 centre = (frame.view * vec4(light.positionRadius.xyz, 1.0)).xyz;
    for (int i = 0; i < 4; ++i)
        if (dot(tile.planes[i], centre) < -radius)
            return false;
    // The box around the cut frustum as well: its depths are the tile's depth range, and the
    // planes one at a time keep a sphere near a corner of the tile, outside two planes but
    // near each (courtyard, 4096 lights: `tiled` evaluates 13.9 instead of 17.4 M pairs).
    if (!sphereTouchesBox(centre, radius, tile.boxLo, tile.boxHi))
        return false;
#ifdef NO_SPOT_LIGHTS
    return true;  // a program specialised for a scene without spots (render/programs/LightingPrograms.h)
#else
    vec3 axis = mat3(frame.view) * light.spotAxisCosCutoff.xyz;
    return coneTouchesSphere(centre, axis, light.spotAxisCosCutoff.w, tile.boxCentre, tile.boxRadius);
#endif
}

// The rectangle of tiles (first.xy, last.xy inclusive, in a grid of `grid` tiles of
// `tileSize` pixels) that a sphere in view space covers on screen. A sphere wholly beyond the
// near plane projects inside the projection of its bounding box's corners; one reaching the
// eye plane may cover any tile. False when it is off screen.
bool sphereTileRect(vec3 centre, float radius, uint tileSize, uvec2 grid, out uvec2 first, out uvec2 last)
{
    first = uvec2(0u);
    last = grid - 1u;
    if (-centre.z - radius <= frame.projection.z)
        return true;
    vec2 ndcLo = vec2(1e30);
    vec2 ndcHi = vec2(-1e30);
    for (int corner = 0; corner < 8; ++corner) {
        vec3 p = centre + radius * vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0,
                                        (corner & 4) != 0 ? 1.0 : -1.0);
        vec2 ndc = p.xy / (-p.z * frame.projection.xy);
        ndcLo = min(ndcLo, ndc);
        ndcHi = max(ndcHi, ndc);
    }
    if (any(greaterThan(ndcLo, vec2(1.0))) || any(lessThan(ndcHi, vec2(-1.0))))
        return false;
    vec2 pixelLo = (clamp(ndcLo, -1.0, 1.0) * 0.5 + 0.5) * frame.viewport.xy;
    vec2 pixelHi = (clamp(ndcHi, -1.0, 1.0) * 0.5 + 0.5) * frame.viewport.xy;
    first = min(uvec2(pixelLo) / tileSize, grid - 1u);
    last = min(uvec2(pixelHi) / tileSize, grid - 1u);
    return true;
}
