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
