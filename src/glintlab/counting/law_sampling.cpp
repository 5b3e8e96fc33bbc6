#include "glintlab/counting/law_sampling.h"

#include <algorithm>
#include <array>

#include "glintlab/core/error.h"
#include "glintlab/counting/laws.h"

namespace glintlab {
namespace {

// Appended laws go last: the validation seeds each (law, cell) by its index.
constexpr std::array<CountingLaw, 7> kLaws = {CountingLaw::exact,
                                              CountingLaw::gaussian,
                                              CountingLaw::zirr2016,
                                              CountingLaw::deliot2023,
                                              CountingLaw::single_gated,
                                              CountingLaw::dual_gated,
                                              CountingLaw::single_gated_conditional};

// Uniforms handed to the fp32 laws must stay below 1 after rounding to float.
float to_unit_float(double u) {
    return std::min(static_cast<float>(u), shader::ONE_MINUS_EPSILON);
}

}  // namespace

std::span<const CountingLaw> all_counting_laws() {
    return kLaws;
}

std::string_view law_name(CountingLaw law) {
    switch (law) {
        case CountingLaw::exact:
            return "exact";
        case CountingLaw::gaussian:
            return "gaussian";
        case CountingLaw::zirr2016:
            return "zirr2016";
        case CountingLaw::deliot2023:
            return "deliot2023";
        case CountingLaw::single_gated:
            return "single_gated";
        case CountingLaw::single_gated_conditional:
            return "single_gated_conditional";
        case CountingLaw::dual_gated:
            return "dual_gated";
    }
    return "unknown";
}

bool is_gated(CountingLaw law) {
    return law == CountingLaw::deliot2023 || law == CountingLaw::single_gated ||
           law == CountingLaw::single_gated_conditional || law == CountingLaw::dual_gated;
}

double sample_count(CountingLaw law, double N, double p, const LawUniforms& xi, Pcg32& rng,
                    const BinomialReference* exact) {
    const auto n = static_cast<float>(N);
    const auto q = static_cast<float>(p);
    const float u1 = to_unit_float(xi.xi1);
    const float u2 = to_unit_float(xi.xi2);
    switch (law) {
        case CountingLaw::exact:
            if (!exact) fail("sample_count: the exact law needs its reference table");
            return static_cast<double>(exact->sample(xi.xi1));
        case CountingLaw::gaussian:
            return shader::binomial_gaussian(n, q, u2);
        case CountingLaw::zirr2016: {
            glsl::mat4 trials;
            // Only the trials the law reads are drawn (cost grows with N).
            const int used = N * p > 5.0 ? 0 : static_cast<int>(std::min(std::ceil(N), 16.0));
            for (int k = 0; k < used; ++k) trials[k / 4][k % 4] = rng.next_float();
            return shader::binomial_zirr2016(n, q, u2, trials);
        }
        case CountingLaw::deliot2023:
            return shader::binomial_deliot2023(n, q, u1, u2);
        case CountingLaw::single_gated:
            return shader::binomial_single_gated(n, q, u1, u2);
        case CountingLaw::single_gated_conditional:
            return shader::binomial_single_gated_conditional(n, q, u1, u2);
        case CountingLaw::dual_gated:
            return shader::binomial_dual_gated(n, q, u1, u2, false).x;
    }
    return 0.0;
}

}  // namespace glintlab
