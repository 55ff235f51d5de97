// Distance falloff, light radius and spot factor of docs/lighting.md.
//
// This file is compiled twice: as GLSL (included by lighting.glsl) and as C++ (included by
// scene/Falloff.cpp), so the radius the CPU computes for culling and the attenuation the
// GPU evaluates come from one source and cannot drift apart. It is therefore written in the
// common subset of both languages: float literals with an f suffix, no vectors, no overloads.

// Stands for "no finite radius" (classic attenuation with a = b = 0): larger than any distance
// in a scene, and finite so that comparisons and arithmetic on it stay well defined.
const float UNBOUNDED_RADIUS = 3.0e38f;

// The distance R at which a classic light (A(d) = 1 / (c + b·d + a·d²)) with brightest
// channel imax has faded to the threshold t: A(R) · imax = t. 0 when the light never
// reaches the threshold (imax / t ≤ c), UNBOUNDED_RADIUS when a = b = 0.
float classicRadius(float c, float b, float a, float imax, float threshold)
{
    float k = imax / threshold;
    if (k <= c)
        return 0.0f;
    if (a > 0.0f)
        return (-b + sqrt(b * b - 4.0f * a * (c - k))) / (2.0f * a);
    if (b > 0.0f)
        return (k - c) / b;
    return UNBOUNDED_RADIUS;
}

// Classic attenuation, cut to zero at its radius.
float classicAttenuation(float d, float radius, float c, float b, float a)
{
    if (d >= radius)
        return 0.0f;
    return 1.0f / (c + b * d + a * d * d);
}

// Smooth windowed falloff: reaches exactly zero at r with no visible edge.
float rangeAttenuation(float d, float r)
{
    if (d >= r)
        return 0.0f;
    float clamped = max(d, r / 100.0f);
    return 1.0f / (clamped * clamped) - 1.0f / (r * r);
}

// S = (cos θ)^exponent inside the cone (cos θ ≥ cos cutoff), 0 outside. Behind a spot wider
// than 90° cos θ is negative, where a power is undefined for non-integer exponents: there
// the factor is max(cos θ, 0)^exponent, which is 0 for exponent > 0 and 1 for exponent 0.
float spotFactor(float cosTheta, float cosCutoff, float exponent)
{
    if (cosTheta < cosCutoff)
        return 0.0f;
    if (exponent == 0.0f)
        return 1.0f;
    return pow(max(cosTheta, 0.0f), exponent);
}
