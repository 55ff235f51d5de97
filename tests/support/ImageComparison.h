// Comparing images in tests: one rule for "near" (|got − want| ≤ relative · |want| + absolute
// per channel), the tolerances the tests share with their reasons (docs/testing.md), and a
// failure message that names the first failing pixels and the largest difference.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "render/output/Image.h"

namespace manylights::test {

struct Tolerance {
    double relative = 0.0;
    double absolute = 0.0;
    double allowed(double want) const { return relative * std::abs(want) + absolute; }
};

// Two techniques' images of one scene (TechniqueAgreementTest): bit-identical on llvmpipe; the
// margin is for a GPU compiler's fused multiply-adds and reordered sums.
inline constexpr Tolerance kAgreementTolerance{1e-5, 1e-6};
// An image against the lighting equations evaluated by hand in double precision (AnalyticTest,
// ShadowTest): float rounding through a handful of operations, positions of about 10 units
// carrying ~1e-6 absolute error, a few ulps from pow() and normalize(); a wrong term is off by
// orders of magnitude more.
inline constexpr Tolerance kAnalyticTolerance{1e-4, 2e-5};
// An 8-bit normalized value written by the GL against 255 times the exact value. The GL 4.6
// core specification (§2.3.5.2, conversion from floating-point to normalized fixed-point)
// lets convert_float_uint return either of the two integers closest to the scaled value,
// preferring but not requiring the nearer: so the bound is under 1 level, not half a level
// (llvmpipe rounds to nearest; an NVIDIA H100 gave 134 for 134.51). The 1e-3 is the float
// arithmetic before the conversion: a few ulps of values up to 255.
inline constexpr double kEightBitConversionTolerance = 1.0 + 1e-3;

// Whether every channel of `image` is within the allowed difference of `reference`'s;
// allowedAt(value index, reference value) gives it per value (a tolerance that depends on the
// material, TechniqueAgreementTest's compact layout). The message names up to five failing
// pixels and the largest difference relative to what was allowed.
inline ::testing::AssertionResult imagesNear(const Image& reference, const Image& image,
                                             const std::function<double(std::size_t, double)>& allowedAt)
{
    if (reference.width != image.width || reference.height != image.height)
        return ::testing::AssertionFailure() << "sizes differ: " << reference.width << "x" << reference.height
                                             << " against " << image.width << "x" << image.height;
    std::ostringstream firstFailures;
    std::size_t failures = 0;
    double worstRatio = 0.0;
    for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
        const double want = reference.rgb[i];
        const double got = image.rgb[i];
        const double allowed = allowedAt(i, want);
        const double difference = std::abs(got - want);
        worstRatio = std::max(worstRatio, allowed > 0.0 ? difference / allowed : difference);
        if (!(difference <= allowed) && ++failures <= 5) {
            const std::size_t pixel = i / 3;
            firstFailures << "\n  pixel (" << pixel % static_cast<std::size_t>(reference.width) << ", "
                          << pixel / static_cast<std::size_t>(reference.width) << ") channel " << i % 3 << ": expected "
                          << want << ", got " << got << ", allowed " << allowed;
        }
    }
    if (failures == 0)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << failures << " of " << reference.rgb.size()
                                         << " values differ (largest difference / allowed " << worstRatio
                                         << "):" << firstFailures.str();
}

inline ::testing::AssertionResult imagesNear(const Image& reference, const Image& image, Tolerance tolerance)
{
    return imagesNear(reference, image, [&](std::size_t, double want) { return tolerance.allowed(want); });
}

// EXPECT_TRUE(imagesNear(...)) << what.
inline void expectImagesNear(const Image& reference, const Image& image, Tolerance tolerance,
                             const std::string& what = {})
{
    EXPECT_TRUE(imagesNear(reference, image, tolerance)) << what;
}

}  // namespace manylights::test
