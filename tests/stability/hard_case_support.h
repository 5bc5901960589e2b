#pragma once
// What the stability suite needs around the hard-case scenes of graphs/hard/: the list (every
// file there is a case, so a new one is covered without touching the tests), renders with every
// float image read back, and the overstep check by dense CPU sampling along pixel rays.
#include <map>
#include <string>
#include <vector>

#include "frame/headless_renderer.h"
#include "runtime_test_support.h"

namespace fg::test {

constexpr std::uint32_t kHardCaseSize = 64;

// File stems of graphs/hard/*.json, sorted.
std::vector<std::string> hard_case_names();
// The formula graphs of graphs/formulas/ and the gallery's as cases: "formulas/NAME", "gallery/NAME".
// The stability checks hold for a formula the compiler derived as for a hand-written fractal.
std::vector<std::string> formula_case_names();
// A case's graph: graphs/hard/NAME.json, or graphs/PATH.json for a name with a folder.
std::string hard_case_text(const std::string& name);
// A case's name as a test name (letters, digits and '_').
std::string test_name(std::string name);

struct HardRender {
    RenderedFrame frame;
    StereoViews views;
    std::vector<std::pair<std::string, std::vector<float>>> float_images;   // every float image, decoded
};
HardRender render_hard_case(const Pack& pack, StereoMode mode, std::map<std::string, double> knobs = {},
                            bool count_evaluations = false);

// Values that are NaN or infinite.
std::size_t count_not_finite(const std::vector<float>& values);

struct OverstepReport {
    std::size_t rays = 0;          // pixel rays checked
    std::size_t overstepped = 0;   // the CPU finds the inside more than the tolerance before the hit
    std::size_t holes = 0;         // a miss, but the CPU finds the inside along the ray
    std::vector<std::string> examples;
};
// Checks every `stride`-th pixel of one view: samples the CPU distance `samples` times from where
// the ray enters the bounds to the reported hit less the tolerance (or to the exit on a miss).
// Tolerance: epsilon cone radii at the hit, plus the spacing of float positions there (a float
// march cannot place a point closer than that). A camera-relative march (precision "double")
// places points to float's spacing at t from the camera, plus the 48 bits of its hi + lo anchor.
OverstepReport check_oversteps(const CpuEvaluator& cpu, const SceneSettings& s, const View& view,
                               const std::vector<float>& depth, double pixel_half_diagonal, double epsilon,
                               int stride, int samples, bool camera_relative = false);

}  // namespace fg::test
