// The light radius solve and falloff of docs/lighting.md, against values worked out by hand. The
// functions under test are shaders/lib/falloff.glsl compiled as C++: the same source the GPU
// runs.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/Falloff.h"

namespace manylights {
namespace {

using namespace falloff;

TEST(ClassicRadius, QuadraticOnly)
{
    // a = 0.3, b = c = 0, Imax = 1, t = 1/255: 0.3 R² = 255, R = sqrt(850) = 29.1548.
    EXPECT_NEAR(classicRadius(0.0f, 0.0f, 0.3f, 1.0f, 1.0f / 255.0f), 29.1548f, 1e-3f);
}

TEST(ClassicRadius, FullQuadratic)
{
    // c = 1, b = 0.1, a = 0.05, Imax = 1, t = 1/256: 0.05 R² + 0.1 R + 1 = 256,
    // R = (−0.1 + sqrt(0.01 + 0.2 · 255)) / 0.1 = (−0.1 + 7.14213) / 0.1 = 70.4213.
    EXPECT_NEAR(classicRadius(1.0f, 0.1f, 0.05f, 1.0f, 1.0f / 256.0f), 70.4213f, 1e-2f);
}

TEST(ClassicRadius, LinearOnlyAndIntensityScales)
{
    // a = 0, b = 0.5, c = 1, Imax = 2, t = 1/256: 1 + 0.5 R = 512, R = 1022.
    EXPECT_FLOAT_EQ(classicRadius(1.0f, 0.5f, 0.0f, 2.0f, 1.0f / 256.0f), 1022.0f);
}

TEST(ClassicRadius, TooDimToReachTheThresholdContributesNothing)
{
    // Imax / t = 0.01 · 256 = 2.56 ≤ c = 3: A · Imax < t everywhere.
    EXPECT_EQ(classicRadius(3.0f, 0.0f, 1.0f, 0.01f, 1.0f / 256.0f), 0.0f);
}

TEST(ClassicRadius, ConstantOnlyIsUnbounded)
{
    EXPECT_EQ(classicRadius(1.0f, 0.0f, 0.0f, 1.0f, 1.0f / 256.0f), kUnboundedRadius);
    EXPECT_GT(kUnboundedRadius, 1e30f);
}

TEST(ClassicRadius, AttenuationAtTheRadiusIsTheThreshold)
{
    for (float imax : {0.2f, 1.0f, 5.0f}) {
        const float radius = classicRadius(1.0f, 0.2f, 0.7f, imax, 1.0f / 256.0f);
        EXPECT_NEAR(classicAttenuation(radius * 0.999999f, radius, 1.0f, 0.2f, 0.7f) * imax, 1.0f / 256.0f, 1e-5f);
    }
}

TEST(ClassicAttenuation, ValueInsideAndCutAtRadius)
{
    // 1 / (1 + 0.5 · 2 + 0.25 · 4) = 1/3.
    EXPECT_FLOAT_EQ(classicAttenuation(2.0f, 10.0f, 1.0f, 0.5f, 0.25f), 1.0f / 3.0f);
    EXPECT_EQ(classicAttenuation(10.0f, 10.0f, 1.0f, 0.5f, 0.25f), 0.0f);
    EXPECT_EQ(classicAttenuation(11.0f, 10.0f, 1.0f, 0.5f, 0.25f), 0.0f);
}

TEST(RangeAttenuation, WindowedInverseSquare)
{
    // r = 4, d = 2: 1/4 − 1/16 = 0.1875.
    EXPECT_FLOAT_EQ(rangeAttenuation(2.0f, 4.0f), 0.1875f);
    // Exactly zero at and beyond r, with no jump: just inside r it is tiny.
    EXPECT_EQ(rangeAttenuation(4.0f, 4.0f), 0.0f);
    EXPECT_EQ(rangeAttenuation(9.0f, 4.0f), 0.0f);
    EXPECT_LT(rangeAttenuation(3.999f, 4.0f), 1e-4f);
    // Near the light, d is clamped to r/100 = 0.04: 1/0.0016 − 1/16 = 624.9375.
    EXPECT_FLOAT_EQ(rangeAttenuation(0.0f, 4.0f), 624.9375f);
    EXPECT_FLOAT_EQ(rangeAttenuation(0.01f, 4.0f), 624.9375f);
}

TEST(SpotFactor, PowerInsideZeroOutside)
{
    const float cos30 = std::cos(30.0f * 3.14159265f / 180.0f);
    EXPECT_FLOAT_EQ(spotFactor(1.0f, cos30, 8.0f), 1.0f);
    EXPECT_FLOAT_EQ(spotFactor(0.9f, cos30, 2.0f), 0.81f);
    EXPECT_EQ(spotFactor(0.8f, cos30, 2.0f), 0.0f);  // 0.8 < cos 30° = 0.866: outside
    EXPECT_FLOAT_EQ(spotFactor(0.87f, cos30, 0.0f), 1.0f);
}

TEST(SpotFactor, WiderThanNinetyDegrees)
{
    // cutoff 120°: cos = −0.5. Behind the spot's plane (cos θ < 0) but inside the cone the
    // factor is max(cos θ, 0)^e: 1 for exponent 0, 0 otherwise.
    EXPECT_FLOAT_EQ(spotFactor(-0.3f, -0.5f, 0.0f), 1.0f);
    EXPECT_EQ(spotFactor(-0.3f, -0.5f, 2.0f), 0.0f);
    EXPECT_EQ(spotFactor(-0.7f, -0.5f, 0.0f), 0.0f);
}

TEST(LightRadius, UsesTheLightsFalloff)
{
    Light ranged;
    ranged.falloff = Falloff::Range;
    ranged.range = 3.5f;
    EXPECT_EQ(lightRadius(ranged, 1.0f / 256.0f), 3.5f);

    Light classic;
    classic.falloff = Falloff::Classic;
    classic.intensity = {0.2f, 1.0f, 0.5f};  // Imax is the brightest channel
    classic.attenuation = {0.0f, 0.0f, 0.3f};
    EXPECT_NEAR(lightRadius(classic, 1.0f / 255.0f), 29.1548f, 1e-3f);
}

}  // namespace
}  // namespace manylights
