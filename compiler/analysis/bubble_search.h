#pragma once
// Stochastic bubble search (the calibration behind `fgc calibrate`): a distance estimate d at p
// promises that the ball of radius d around p holds no surface. Sample points over the scene
// bounds (half uniform, half walked towards the surface) and the graph's parameter ranges,
// search each point's ball for interior points on the CPU
// twin (double precision) and count the points whose promise is broken: the overshoots. The
// search runs once per sample; the rate for any bias and step scale then costs one evaluation per
// sample, because the guard only rescales a fractal's estimate and never moves its zero set
// (dr > 0 keeps the sign of d). A smooth blend of a much-shrunken estimate can still dig a false
// interior; surface_growth() reports that, and calibration keeps the bias where it does not.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/cpu_evaluator.h"
#include "ir/ir_graph.h"

namespace fg {

struct BubbleSearchSettings {
    int samples = 3000;              // exterior points searched
    std::uint64_t seed = 1;
    int directions = 48;             // rays searched inside each ball
    int radial_steps = 16;           // points tested along each ray before bisection
    double reach_bias = 0.0;         // the search covers the balls of every bias >= this one
    double reach_step = 1.0;         // ... and every step multiplier <= this one
    double walk_bias = 4.0;          // bias of the safe walk that carries samples to the surface
    int threads = 2;
};

// One exterior point of the search, with the parameter values it was drawn with.
struct BubbleSample {
    glm::dvec3 p{0.0};
    std::vector<Constant> params;    // one per graph parameter
    double reach = 0.0;              // radius searched
    double interior = std::numeric_limits<double>::infinity();   // nearest interior point found
    bool walked = false;             // carried close to the surface (where the march decides hits)
};

struct OvershootCount {
    std::size_t overshoots = 0;
    std::size_t samples = 0;
    double worst = 0.0;              // largest step / distance-to-interior ratio among overshoots
    double rate() const { return samples ? static_cast<double>(overshoots) / static_cast<double>(samples) : 0.0; }
};

// How far a bias moves the surface the march sees. The guard never moves the zero set (dr > 0),
// but the march stops where the estimate falls below its hit threshold, and where the bias shrinks
// the estimate by g = d(bias 0) / d(bias) that happens g thresholds out: a large g melts the
// detail into a blob. Measured where the march decides hits: at the samples walked close to the
// surface where a fractal decides the distance, and at the surface the scene's start camera sees
// (the walked samples can all but miss a small fractal beside a floor); the larger figure counts.
struct SurfaceGrowth {
    double median = 1.0;
    double p90 = 1.0;
    std::size_t samples = 0;
};

class BubbleSearch {
public:
    // The bias knobs of every node with a running derivative ("bias.<node>"), in node order.
    static std::vector<std::string> bias_knobs(const IrGraph& ir);

    BubbleSearch(const CpuEvaluator& scene, BubbleSearchSettings settings);

    // Draws the samples and searches their balls. progress(done, total) is called from the
    // calling thread now and then.
    void run(const std::function<void(std::size_t, std::size_t)>& progress = {});

    // Overshoots when every bias knob is `bias` and every step is multiplied by `step_scale`.
    OvershootCount count(double bias, double step_scale) const;
    // The smallest bias in [lo, hi] without overshoot at this step scale, to `resolution`
    // (rounded up to it); nullopt when even hi overshoots. The estimate shrinks as the bias grows,
    // so the overshoot count falls monotonically and bisection finds the edge.
    std::optional<double> smallest_safe_bias(double step_scale, double lo, double hi, double resolution = 0.01) const;
    SurfaceGrowth surface_growth(double bias) const;
    // The largest bias in [lo, hi] whose 90th-percentile surface growth stays within `max_growth` (growth
    // rises with the bias), to `resolution` (rounded down to it).
    double largest_bias_within_growth(double max_growth, double lo, double hi, double resolution = 0.01) const;

    const std::vector<BubbleSample>& samples() const { return samples_; }
    // Where the start camera's rays (a grid of 24 x 24) first come within a hit threshold (1e-3
    // of the distance travelled) of the surface, marched with the plain estimate.
    const std::vector<glm::dvec3>& visible_surface() const { return visible_; }
    std::uint64_t evaluations() const { return evaluations_; }
    std::size_t rejected_interior() const { return rejected_interior_; }

private:
    double distance_at(CpuEvaluator& ev, const BubbleSample& s, double bias) const;
    void search_ball(CpuEvaluator& ev, BubbleSample& s, std::uint64_t stream) const;

    CpuEvaluator scene_;
    BubbleSearchSettings settings_;
    std::vector<std::string> knobs_;
    std::vector<BubbleSample> samples_;
    std::vector<glm::dvec3> visible_;
    std::uint64_t evaluations_ = 0;
    std::size_t rejected_interior_ = 0;
};

}  // namespace fg
