// The specular power by multiplication (shaders/lib/specular_power.glsl) and the compact
// G-buffer's shininess code its choice of exponent relies on (shaders/lib/gbuffer_packing.glsl),
// run alone in a compute shader over many inputs and compared with double precision. The image
// tests see only the few exponents of their scenes (docs/lighting.md, "The colour of a surface
// point", says how exact the power is).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "GlContextTest.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "render/programs/LightingPrograms.h"

namespace manylights {
namespace {

class SpecularPower : public GlContextTest {};

// Runs `body`, a statement that sets `float result` from `uint i`, for i in [0, count), in a
// compute shader that includes the two files above, and returns the results.
std::vector<float> runForEach(const std::string& body, std::uint32_t count, const gl::Defines& defines = {})
{
    const std::string source = "#version 450 core\n#include \"lib/specular_power.glsl\"\n"
                               "#include \"lib/gbuffer_packing.glsl\"\n"
                               "layout(local_size_x = 64) in;\n"
                               "layout(std430, binding = 0) writeonly buffer Results { float results[]; };\n"
                               "void main()\n{\n    uint i = gl_GlobalInvocationID.x;\n    float result;\n    " +
                               body + "\n    results[i] = result;\n}\n";
    const gl::ShaderFileReader embedded = gl::embeddedShaderReader();
    const gl::ShaderFileReader reader = [&](const std::string& name) -> std::optional<std::string> {
        return name == "test.comp" ? std::optional<std::string>(source) : embedded(name);
    };
    const gl::Program program("specular power test", {{GL_COMPUTE_SHADER, "test.comp"}}, defines, reader);
    gl::Buffer results("results", count * sizeof(float), nullptr);
    results.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    program.use();
    glDispatchCompute((count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> values(count);
    glGetNamedBufferSubData(results.id(), 0, static_cast<GLsizeiptr>(count * sizeof(float)), values.data());
    return values;
}

// x^n for every x = i / 4096 in [0, 1] (exact floats, so only the chain's own rounding is
// measured) against the power in double precision. Each squaring doubles the relative error it
// is given and adds at most half an ulp (2^-24 relative), each product adds the errors of its
// factors and half an ulp: in all at most n + 1 half-ulps, the tolerance. Below 2^-126 the
// power is 0 (the flush); within a factor 2 of that bound either answer is right, as the
// flush's threshold is itself a rounded float. A wrong bit of n (13 for 12) is off by x, far
// more than the tolerance for every x below 1 - 2^-12 · n.
TEST_F(SpecularPower, IntegerPowersAreWithinHalfAnUlpPerMultiplication)
{
    constexpr std::uint32_t kSteps = 4096;
    const double smallestNormal = std::ldexp(1.0, -126);
    for (const int n : {1, 2, 13, 16, 40, 255, 1023, 2047, int{kMaxSpecularExponent}}) {
        SCOPED_TRACE("n = " + std::to_string(n));
        const std::vector<float> powers =
            runForEach("result = integerPower(float(i) / 4096.0, " + std::to_string(n) + "u);", kSteps + 1);
        const double tolerance = (n + 1) * std::ldexp(1.0, -24);
        int failures = 0;
        for (std::uint32_t i = 0; i <= kSteps; ++i) {
            const double x = static_cast<double>(i) / kSteps;
            const double want = std::pow(x, n);
            const double got = powers[i];
            const bool ok = want < 2.0 * smallestNormal ? got == 0.0 || std::abs(got - want) <= tolerance * want
                                                        : std::abs(got - want) <= tolerance * want;
            if (!ok && ++failures <= 5)
                ADD_FAILURE() << "x = " << x << ": got " << got << ", expected " << want;
            if (want < 0.5 * smallestNormal) {
                EXPECT_EQ(got, 0.0) << "x = " << x << ": a subnormal power must be flushed";
            }
        }
    }
}

// The compact G-buffer stores the shininess as a 16-bit code of its log2; specularPower() picks
// each surface's exponent by the midpoints between the scene's integer exponents, so every
// integer shininess the multiplications take must come back within less than 0.5 of itself.
TEST_F(SpecularPower, CompactShininessCodeKeepsEveryIntegerExponentWithinHalf)
{
    const std::vector<float> decoded =
        runForEach("result = decodeShininess(encodeShininess(float(i + 1u)));", kMaxSpecularExponent);
    double worst = 0.0;
    for (std::uint32_t i = 0; i < kMaxSpecularExponent; ++i)
        worst = std::max(worst, std::abs(static_cast<double>(decoded[i]) - (i + 1)));
    EXPECT_LT(worst, 0.5);
    EXPECT_GT(worst, 0.0);  // the code does round: the midpoints are needed
}

// Where the exponents are closest together and the decoded shininess furthest from its integer
// (2046, 2047 and 2048), each surface's power is its own exponent's, bit for bit.
TEST_F(SpecularPower, EachSurfacePicksItsOwnExponent)
{
    const gl::Defines defines =
        ShaderVariant{.lighting = {.scene = {.specularExponents = {2046, 2047, 2048}}}}.toDefines({});
    const std::vector<float> picked = runForEach(
        "uint exponent = 2046u + i % 3u;\n"
        "    float x = 0.9995;\n"
        "    float shininess = i < 3u ? float(exponent) : decodeShininess(encodeShininess(float(exponent)));\n"
        "    result = specularPower(x, shininess) == integerPower(x, exponent) ? 1.0 : 0.0;",
        6, defines);
    EXPECT_EQ(picked, std::vector<float>(6, 1.0f));
    // The three powers differ, so a wrong pick would show.
    const std::vector<float> powers = runForEach("result = integerPower(0.9995, 2046u + i);", 3);
    EXPECT_NE(powers[0], powers[1]);
    EXPECT_NE(powers[1], powers[2]);
}

}  // namespace
}  // namespace manylights
