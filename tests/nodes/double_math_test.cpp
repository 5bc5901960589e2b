// The double math of precision "double" (nodes/double_math.glsl) agrees with <cmath> to about
// 1e-15 relative: compiled here as C++ from the same text, and run on the GPU (lavapipe's
// shaderFloat64) as fgc lowers it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "codegen/double_lowering.h"
#include "gpu_node_evaluator.h"
#include "graph/node_library.h"

namespace fg::dmath {
// The few GLSL built-ins the file uses, spelled for C++.
using glm::clamp;
using std::abs;
using std::floor;
using std::sqrt;
inline double frexp(double x, int& e) { return std::frexp(x, &e); }
inline double ldexp(double x, int e) { return std::ldexp(x, e); }
#define OUT(T) T&
#define precise
#include "double_math.glsl"
#undef precise
#undef OUT
}  // namespace fg::dmath

namespace {

struct Case {
    const char* name;
    int id;                                   // which function the GPU shader calls
    double (*mine)(double, double);
    double (*reference)(double, double);
    double (*draw)(std::mt19937&);            // an argument (x); y is drawn by draw_y where used
    double (*draw_y)(std::mt19937&);
};

double uniform(std::mt19937& r, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(r); }
double log_uniform(std::mt19937& r, double lo, double hi) { return std::exp(uniform(r, std::log(lo), std::log(hi))); }
double signed_log(std::mt19937& r, double lo, double hi) { return (uniform(r, 0, 1) < 0.5 ? -1 : 1) * log_uniform(r, lo, hi); }
double zero(std::mt19937&) { return 0.0; }

const Case kCases[] = {
    {"sin", 0, [](double x, double) { return fg::dmath::fg_d_sin(x); }, [](double x, double) { return std::sin(x); },
     [](std::mt19937& r) { return signed_log(r, 1e-8, 1e5); }, zero},
    {"cos", 1, [](double x, double) { return fg::dmath::fg_d_cos(x); }, [](double x, double) { return std::cos(x); },
     [](std::mt19937& r) { return signed_log(r, 1e-8, 1e5); }, zero},
    {"tan", 2, [](double x, double) { return fg::dmath::fg_d_tan(x); }, [](double x, double) { return std::tan(x); },
     [](std::mt19937& r) { return uniform(r, -100.0, 100.0); }, zero},
    {"asin", 3, [](double x, double) { return fg::dmath::fg_d_asin(x); }, [](double x, double) { return std::asin(x); },
     [](std::mt19937& r) { return uniform(r, -1.0, 1.0); }, zero},
    {"acos", 4, [](double x, double) { return fg::dmath::fg_d_acos(x); }, [](double x, double) { return std::acos(x); },
     [](std::mt19937& r) { return uniform(r, -1.0, 1.0); }, zero},
    {"atan", 5, [](double x, double) { return fg::dmath::fg_d_atan(x); }, [](double x, double) { return std::atan(x); },
     [](std::mt19937& r) { return signed_log(r, 1e-8, 1e8); }, zero},
    {"atan2", 6, [](double x, double y) { return fg::dmath::fg_d_atan2(y, x); },
     [](double x, double y) { return std::atan2(y, x); }, [](std::mt19937& r) { return signed_log(r, 1e-6, 1e6); },
     [](std::mt19937& r) { return signed_log(r, 1e-6, 1e6); }},
    {"exp", 7, [](double x, double) { return fg::dmath::fg_d_exp(x); }, [](double x, double) { return std::exp(x); },
     [](std::mt19937& r) { return uniform(r, -700.0, 700.0); }, zero},
    {"log", 8, [](double x, double) { return fg::dmath::fg_d_log(x); }, [](double x, double) { return std::log(x); },
     [](std::mt19937& r) { return log_uniform(r, 1e-300, 1e300); }, zero},
    {"exp2", 9, [](double x, double) { return fg::dmath::fg_d_exp2(x); }, [](double x, double) { return std::exp2(x); },
     [](std::mt19937& r) { return uniform(r, -1000.0, 1000.0); }, zero},
    {"log2", 10, [](double x, double) { return fg::dmath::fg_d_log2(x); }, [](double x, double) { return std::log2(x); },
     [](std::mt19937& r) { return log_uniform(r, 1e-300, 1e300); }, zero},
    {"pow", 11, [](double x, double y) { return fg::dmath::fg_d_pow(x, y); },
     [](double x, double y) { return std::pow(x, y); }, [](std::mt19937& r) { return log_uniform(r, 1e-3, 1e3); },
     [](std::mt19937& r) { return uniform(r, -16.0, 16.0); }},
};

// Relative error; near a zero of the function (log near 1, sin near k pi) the reference's own
// magnitude is the scale, floored at 1e-300.
double relative_error(double got, double want) { return std::abs(got - want) / std::max(std::abs(want), 1e-300); }

constexpr int kPoints = 4000;
constexpr double kTolerance = 1e-14;

std::vector<std::pair<double, double>> arguments(const Case& c) {
    std::mt19937 rng(static_cast<unsigned>(1234 + c.id));
    std::vector<std::pair<double, double>> v;
    for (int i = 0; i < kPoints; ++i) {
        double x = c.draw(rng);
        v.emplace_back(x, c.draw_y(rng));
    }
    // Edges: exact zeros, +-1, powers of two, multiples of pi/2 as doubles.
    for (double x : {0.0, 1.0, -1.0, 0.5, 2.0, 1.5707963267948966, 3.141592653589793, 1e-300}) {
        bool positive_only = c.id == 8 || c.id == 10 || c.id == 11, unit_only = c.id == 3 || c.id == 4;
        if ((positive_only && x <= 0.0) || (unit_only && std::abs(x) > 1.0) || (c.id == 11 && x < 1e-100)) continue;
        v.emplace_back(x, c.id == 11 ? 3.0 : (c.id == 6 ? 1.0 : 0.0));
    }
    return v;
}

TEST(DoubleMath, every_function_agrees_with_cmath_on_the_cpu) {
    for (const auto& c : kCases) {
        double worst = 0.0, at = 0.0;
        for (auto [x, y] : arguments(c)) {
            double e = relative_error(c.mine(x, y), c.reference(x, y));
            if (e > worst) worst = e, at = x;
        }
        std::printf("%-6s CPU worst relative error %.2e (x = %.17g)\n", c.name, worst, at);
        EXPECT_LE(worst, kTolerance) << c.name << " at x = " << at;
    }
}

TEST(DoubleMath, every_function_agrees_with_cmath_on_the_gpu) {
    auto& gpu = fg::test::GpuNodeEvaluator::shared();
    if (!gpu.context().shader_float64_enabled()) GTEST_SKIP() << "no shaderFloat64 on " << gpu.context().device_name();
    std::string calls;
    for (const auto& c : kCases) {
        std::string call = c.id == 6    ? "fg_d_atan2(y, x)"
                           : c.id == 11 ? "fg_d_pow(x, y)"
                                        : fmt::format("fg_d_{}(x)", c.name);
        calls += fmt::format("    if (which == {}) r = {};\n", c.id, call);
    }
    std::string glsl = "#version 460\nlayout(local_size_x = 64) in;\n"
                       "layout(std430, set = 0, binding = 0) readonly buffer FgIn { dvec4 v[]; } fg_in;\n"
                       "layout(std430, set = 0, binding = 1) writeonly buffer FgOut { dvec4 v[]; } fg_out;\n"
                       "layout(push_constant) uniform FgPush { uint count; } pc;\n#define OUT(T) out T\n" +
                       fg::lower_to_double(fg::NodeLibrary::builtin().double_math()) +
                       "\nvoid main()\n{\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= pc.count) return;\n"
                       "    double x = fg_in.v[i].x;\n    double y = fg_in.v[i].y;\n    int which = int(fg_in.v[i].z);\n"
                       "    double r = 0.0lf;\n" +
                       calls + "    fg_out.v[i] = dvec4(r, 0.0, 0.0, 0.0);\n}\n";
    std::vector<fg::CpuValue> inputs;
    std::vector<const Case*> owner;
    for (const auto& c : kCases)
        for (auto [x, y] : arguments(c)) {
            fg::CpuValue v;
            v.v = glm::dvec4(x, y, c.id, 0.0);
            inputs.push_back(v);
            owner.push_back(&c);
        }
    fg::Diagnostics diag;
    auto out = gpu.run("double math", glsl, inputs, inputs.size(), 1, true, diag);
    ASSERT_TRUE(out) << diag.format();
    for (const auto& c : kCases) {
        double worst = 0.0, at = 0.0;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            if (owner[i] != &c) continue;
            double x = inputs[i].v.x, y = inputs[i].v.y;
            double e = relative_error((*out)[i].v.x, c.reference(x, y));
            if (e > worst) worst = e, at = x;
        }
        std::printf("%-6s GPU worst relative error %.2e (x = %.17g)\n", c.name, worst, at);
        EXPECT_LE(worst, kTolerance) << c.name << " at x = " << at;
    }
}

}  // namespace
