#include "render/environment/PrefilterSource.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "core/Error.h"

namespace manylights {

float environmentLuminance(const glm::vec3& radiance)
{
    return 0.2126f * radiance.r + 0.7152f * radiance.g + 0.0722f * radiance.b;
}

EnvironmentImage downsampledEnvironment(const EnvironmentImage& map, int maxWidth)
{
    ML_ASSERT(maxWidth >= 2 && maxWidth % 2 == 0);
    if (map.width <= maxWidth)
        return map;
    // The smallest whole factor that fits, so that most maps (powers of two) fall into equal blocks.
    const int factor = (map.width + maxWidth - 1) / maxWidth;
    const int width = std::max(2, map.width / factor / 2 * 2);
    EnvironmentImage result{.width = width, .height = width / 2, .radiance = {}};
    std::vector<glm::dvec3> sum(static_cast<std::size_t>(result.width) * result.height, glm::dvec3(0.0));
    std::vector<double> weight(sum.size(), 0.0);
    for (int j = 0; j < map.height; ++j) {
        const double solidAngle = environmentTexelSolidAngle(j, map.height);
        const int row = static_cast<int>(static_cast<long long>(j) * result.height / map.height);
        for (int i = 0; i < map.width; ++i) {
            const int column = static_cast<int>(static_cast<long long>(i) * result.width / map.width);
            const std::size_t at = static_cast<std::size_t>(row) * result.width + column;
            sum[at] += glm::dvec3(map.at(i, j)) * solidAngle;
            weight[at] += solidAngle;
        }
    }
    result.radiance.resize(sum.size());
    for (std::size_t t = 0; t < sum.size(); ++t)
        result.radiance[t] = glm::vec3(sum[t] / weight[t]);
    return result;
}

PrefilterSource splitForPrefiltering(const EnvironmentImage& map, int maxWidth, std::size_t maxBright)
{
    PrefilterSource source{.remainder = downsampledEnvironment(map, maxWidth), .bright = {}, .threshold = 0.0f};
    EnvironmentImage& remainder = source.remainder;
    double power = 0.0;
    for (int j = 0; j < remainder.height; ++j) {
        const double solidAngle = environmentTexelSolidAngle(j, remainder.height);
        for (int i = 0; i < remainder.width; ++i)
            power += environmentLuminance(remainder.at(i, j)) * solidAngle;
    }
    const double meanLuminance = power / (4.0 * std::numbers::pi);
    float threshold = static_cast<float>(kBrightFactor * meanLuminance);
    std::vector<float> above;
    for (const glm::vec3& texel : remainder.radiance)
        if (environmentLuminance(texel) > threshold)
            above.push_back(environmentLuminance(texel));
    if (above.size() > maxBright) {
        // The brightest maxBright stay above; the threshold is the next one's luminance (ties
        // with it stay in the remainder, so there may be fewer).
        std::nth_element(above.begin(), above.begin() + static_cast<std::ptrdiff_t>(maxBright), above.end(),
                         std::greater<>());
        threshold = above[maxBright];
    }
    source.threshold = threshold;
    for (int j = 0; j < remainder.height; ++j) {
        const double solidAngle = environmentTexelSolidAngle(j, remainder.height);
        for (int i = 0; i < remainder.width; ++i) {
            glm::vec3& texel = remainder.at(i, j);
            const float luminance = environmentLuminance(texel);
            if (luminance <= threshold)
                continue;
            const glm::vec3 kept = texel * (threshold / luminance);
            const glm::dvec3 direction =
                environmentDirection({(i + 0.5) / remainder.width, (j + 0.5) / remainder.height});
            source.bright.push_back({.direction = glm::vec4(glm::vec3(direction), 0.0f),
                                     .power = glm::vec4(glm::vec3(glm::dvec3(texel - kept) * solidAngle), 0.0f)});
            texel = kept;
        }
    }
    return source;
}

double ggxLobeIntegral(double roughness)
{
    // With c = N·ω: (N·h)² = (1 + c) / 2, dω = 2π dc over the ring, so
    // W = 2α² ∫₀¹ c / (A + k c)² dc with k = (α² − 1) / 2, A = 1 + k; its antiderivative is
    // (ln(A + k c) + A / (A + k c)) / k².
    const double alpha = roughness * roughness;
    const double a2 = alpha * alpha;
    const double k = (a2 - 1.0) / 2.0;
    const double a = 1.0 + k;
    double integral = 0.0;
    if (std::abs(k) < 1e-2) {
        // Near α = 1 the closed form cancels: its series in y = k c / A instead (the next term
        // is below 1e-8 of the sum).
        const double x = k / a;
        integral = (0.5 - 2.0 * x / 3.0 + 3.0 * x * x / 4.0 - 4.0 * x * x * x / 5.0) / (a * a);
    } else {
        integral = (std::log(a2 / a) + a / a2 - 1.0) / (k * k);
    }
    return 2.0 * a2 * integral;
}

}  // namespace manylights
