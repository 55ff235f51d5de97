// The specular power max(N·H, 0)^s of lib/lighting.glsl's blinnPhong(). Depends on nothing
// else, so that tests can run it alone (tests/gl/SpecularPowerTest.cpp).

// x^n for x in [0, 1] and a constant integer n in [1, 4095] by multiplications: x, x², x⁴, ...
// and the product of the powers n's bits select. The loop's bounds and n are constants, so the
// compiler unrolls it and keeps only the multiplications n needs (render/programs/LightingPrograms.h
// integerPowerMultiplications). Each squaring doubles the relative error it is given and adds
// half an ulp, so the result is within about n/2 ulps (n · 2^-25 relative) of x^n: the same order
// as pow()'s exp2(n · log2(x)), whose log2 is rounded before the product with n, and as x^n's
// own sensitivity to the rounding of x, n ulps. A power below 2^-126 (a subnormal float,
// 1.2e-38) is 0: x is flushed where x^n would be, so that every value in the chain, all at least
// x^n, stays normal. A multiplication that reads or makes a subnormal takes a microcode assist of
// about a hundred cycles on x86, and llvmpipe does not set flush-to-zero: without the flush,
// shininess 255 cost more than pow() (docs/performance.md).
float integerPower(float x, uint n)
{
    float power = 1.0;
    float square = x < exp2(-126.0 / float(n)) ? 0.0 : x;  // x^(2^bit)
    for (uint bit = 0u; bit < 12u; ++bit) {
        if ((n & (1u << bit)) != 0u)
            power *= square;
        square *= square;
    }
    return power;
}

// x^shininess for x in [0, 1]. pow() is exp2(shininess · log2(x)), whose two polynomials cost
// a quarter of a lighting pass on llvmpipe (docs/performance.md). A program built with
// SPECULAR_EXPONENT_COUNT k and SPECULAR_EXPONENTS, k ascending integers (render/programs/LightingPrograms.h:
// the shininesses of every surface of the scene with a specular term, where their
// multiplications are few), multiplies instead: each power is computed, and the surface's
// shininess picks its own by the midpoints between them, which a compact G-buffer's decoded
// shininess (within 8.5e-5 relative, 0.18 at 2048, of the material's) never crosses. The loop's
// bounds are constants: it unrolls, and the exponents become constants of each integerPower.
#ifdef SPECULAR_EXPONENT_COUNT
const uint kSpecularExponents[SPECULAR_EXPONENT_COUNT] = uint[](SPECULAR_EXPONENTS);
#endif
float specularPower(float x, float shininess)
{
#ifdef SPECULAR_EXPONENT_COUNT
    float power = integerPower(x, kSpecularExponents[0]);
    for (int i = 1; i < SPECULAR_EXPONENT_COUNT; ++i) {
        float next = integerPower(x, kSpecularExponents[i]);
        power = shininess > 0.5 * float(kSpecularExponents[i - 1] + kSpecularExponents[i]) ? next : power;
    }
    return power;
#else
    return pow(x, shininess);
#endif
}
