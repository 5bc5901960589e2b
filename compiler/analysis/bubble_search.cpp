#include "bubble_search.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace fg {

namespace {

// splitmix64: a seedable stream per sample, so results do not depend on the thread count.
struct SampleRandom {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    glm::dvec3 unit_vector() {
        double z = uniform(-1.0, 1.0), a = uniform(0.0, 2.0 * M_PI), s = std::sqrt(1.0 - z * z);
        return {s * std::cos(a), s * std::sin(a), z};
    }
};

// A random rotation (from a random unit quaternion, Shoemake), to turn the fixed direction set.
glm::dmat3 random_rotation(SampleRandom& rng) {
    double u1 = rng.uniform(), u2 = rng.uniform(0.0, 2.0 * M_PI), u3 = rng.uniform(0.0, 2.0 * M_PI);
    double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3), w = b * std::cos(u3);
    return glm::dmat3(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
                      2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                      2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y));
}

// Evenly spread directions (a Fibonacci sphere).
std::vector<glm::dvec3> fibonacci_directions(int n) {
    std::vector<glm::dvec3> dirs;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        dirs.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
    }
    return dirs;
}

}  // namespace

std::vector<std::string> BubbleSearch::bias_knobs(const IrGraph& ir) {
    std::vector<std::string> out;
    for (const auto& n : ir.nodes)
        for (std::size_t i = 0; i < n.inputs.size(); ++i)
            if (n.inputs[i].kind == IrInput::Kind::Knob && n.def->inputs[i].knob == "bias")
                out.push_back("bias." + n.id);
    return out;
}

BubbleSearch::BubbleSearch(const CpuEvaluator& scene, BubbleSearchSettings settings)
    : scene_(scene), settings_(settings), knobs_(bias_knobs(scene.ir())) {}

double BubbleSearch::distance_at(CpuEvaluator& ev, const BubbleSample& s, double bias) const {
    const auto& params = ev.ir().params;
    for (std::size_t i = 0; i < params.size(); ++i) ev.set_param(params[i].name, s.params[i]);
    for (const auto& k : knobs_) ev.set_knob(k, bias);
    return ev.distance(s.p);
}

void BubbleSearch::search_ball(CpuEvaluator& ev, BubbleSample& s, std::uint64_t stream) const {
    SampleRandom rng{stream};
    const IrGraph& ir = ev.ir();
    const glm::dvec3 centre = ir.scene.bounds_center;
    const double radius = ir.scene.bounds_radius;
    double d = 0.0;
    // Every other sample is carried towards the surface: a march spends its steps close to it,
    // where estimates overshoot, and uniform points in large bounds seldom land there.
    const bool near_surface = (stream & 1u) != 0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        // A uniform point of the bounds sphere and uniform parameter values.
        glm::dvec3 u;
        do u = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        while (glm::dot(u, u) > 1.0);
        s.p = centre + radius * u;
        s.params.clear();
        for (const auto& p : ir.params) {
            Constant c = p.value;
            if ((p.type == ValueType::Float || p.type == ValueType::Int) && p.min && p.max) {
                double x = rng.uniform(*p.min, *p.max);
                c.v[0] = p.type == ValueType::Int ? std::floor(x + 0.5) : x;
            }
            s.params.push_back(c);
        }
        d = distance_at(ev, s, settings_.reach_bias);
        if (!(d > 0.0 && std::isfinite(d))) {
            d = 0.0;
            continue;
        }
        if (near_surface) {
            // March from there roughly towards the centre of the bounds (where scenes put their
            // fractal; an infinite floor would otherwise take every walk) with short, safe steps
            // (the largest bias, a quarter step) until the distance falls below a target spread
            // log-uniformly over four decades below the bounds radius.
            const double target = radius * std::pow(10.0, -1.0 - 4.0 * rng.uniform());
            glm::dvec3 inward = centre - s.p;
            double len = glm::length(inward);
            const glm::dvec3 dir = glm::normalize((len > 0.0 ? inward / len : glm::dvec3(0.0)) + 0.7 * rng.unit_vector());
            BubbleSample walker = s;
            for (int step = 0; step < 200; ++step) {
                double safe = distance_at(ev, walker, settings_.walk_bias);
                if (!(safe > 0.0) || glm::length(walker.p - centre) > radius) break;
                if (safe < target) {
                    s.p = walker.p;
                    s.walked = true;
                    d = distance_at(ev, s, settings_.reach_bias);
                    break;
                }
                walker.p += dir * (0.25 * safe);
            }
            if (!(d > 0.0 && std::isfinite(d))) {
                d = 0.0;
                continue;
            }
        }
        break;
    }
    if (d <= 0.0) return;   // no exterior point found: the sample stays empty (reach 0)
    s.reach = std::min(d * settings_.reach_step, 4.0 * radius);
    glm::dmat3 turn = random_rotation(rng);
    static thread_local std::vector<glm::dvec3> dirs;
    if (dirs.size() != static_cast<std::size_t>(settings_.directions)) dirs = fibonacci_directions(settings_.directions);
    auto inside = [&](double r, const glm::dvec3& dir) { return ev.distance(s.p + dir * r) <= 0.0; };
    for (const auto& base : dirs) {
        glm::dvec3 dir = turn * base;
        // Only nearer interior points than the nearest one found so far matter.
        double limit = std::min(s.reach, s.interior);
        double step = s.reach / settings_.radial_steps;
        double prev = 0.0;
        for (int k = 1; k <= settings_.radial_steps && k * step < limit; ++k) {
            double r = k * step;
            if (!inside(r, dir)) {
                prev = r;
                continue;
            }
            // A sign change between prev and r: bisect to the crossing.
            double lo = prev, hi = r;
            for (int b = 0; b < 14; ++b) {
                double mid = 0.5 * (lo + hi);
                (inside(mid, dir) ? hi : lo) = mid;
            }
            s.interior = std::min(s.interior, hi);
            break;
        }
    }
}

namespace {

// The median and 90th percentile of a set of growth figures.
SurfaceGrowth growth_of(std::vector<double> g) {
    SurfaceGrowth out;
    out.samples = g.size();
    if (g.empty()) return out;
    auto at = [&](double q) {
        auto k = g.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(g.size() - 1));
        std::nth_element(g.begin(), k, g.end());
        return *k;
    };
    out.median = at(0.5);
    out.p90 = at(0.9);
    return out;
}

std::vector<glm::dvec3> march_start_view(CpuEvaluator& ev, int grid) {
    const SceneSettings& scene = ev.ir().scene;
    const glm::dvec3 eye = scene.camera.position;
    const glm::dvec3 forward = glm::normalize(scene.camera.target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, scene.camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(0.5 * scene.camera.fov_deg * M_PI / 180.0);
    const double far = glm::length(eye - scene.bounds_center) + 2.0 * scene.bounds_radius;
    std::vector<glm::dvec3> points;
    for (int y = 0; y < grid; ++y)
        for (int x = 0; x < grid; ++x) {
            glm::dvec2 uv = (glm::dvec2(x, y) + 0.5) / static_cast<double>(grid) * 2.0 - 1.0;
            glm::dvec3 dir = glm::normalize(forward + tan_half * (uv.x * right - uv.y * up));
            double t = 0.0;
            for (int step = 0; step < 400 && t < far; ++step) {
                double d = ev.distance(eye + t * dir);
                if (!std::isfinite(d) || d < 0.0) break;
                if (d < 1e-3 * std::max(t, 1e-9)) {
                    points.push_back(eye + t * dir);
                    break;
                }
                t += d;
            }
        }
    return points;
}

}  // namespace

void BubbleSearch::run(const std::function<void(std::size_t, std::size_t)>& progress) {
    const std::size_t n = static_cast<std::size_t>(std::max(settings_.samples, 0));
    samples_.assign(n, {});
    std::atomic<std::size_t> done{0};
    std::atomic<std::uint64_t> evaluations{0};
    int threads = std::max(1, settings_.threads);
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            CpuEvaluator ev = scene_;
            std::uint64_t before = ev.evaluations();
            for (std::size_t i = static_cast<std::size_t>(t); i < n; i += static_cast<std::size_t>(threads)) {
                SampleRandom mix{settings_.seed * 0xd1b54a32d192ed03ull + i};
                search_ball(ev, samples_[i], mix.next());
                ++done;
            }
            evaluations += ev.evaluations() - before;
        });
    while (progress && done.load() < n) {
        progress(done.load(), n);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    for (auto& w : workers) w.join();
    if (progress) progress(n, n);
    evaluations_ = evaluations.load();
    {
        CpuEvaluator ev = scene_;
        for (const auto& k : knobs_) ev.set_knob(k, 0.0);
        visible_ = march_start_view(ev, 24);
    }
    rejected_interior_ = static_cast<std::size_t>(
        std::count_if(samples_.begin(), samples_.end(), [](const BubbleSample& s) { return s.reach <= 0.0; }));
}

OvershootCount BubbleSearch::count(double bias, double step_scale) const {
    OvershootCount c;
    CpuEvaluator ev = scene_;
    for (const auto& s : samples_) {
        if (s.reach <= 0.0) continue;
        ++c.samples;
        double step = distance_at(ev, s, bias) * step_scale;
        // Steps beyond the searched reach cannot be judged; reach covers every setting the sweep asks for.
        if (step > s.interior) {
            ++c.overshoots;
            c.worst = std::max(c.worst, step / s.interior);
        }
    }
    return c;
}

// A bias larger than any knob allows: where even this leaves the distance alone, no fractal
// decides it.
constexpr double kAnyBias = 64.0;

SurfaceGrowth BubbleSearch::surface_growth(double bias) const {
    CpuEvaluator ev = scene_;
    std::vector<double> walked, visible;
    auto growth_at = [&](const BubbleSample& s, std::vector<double>& out) {
        double plain = distance_at(ev, s, 0.0), guarded = distance_at(ev, s, bias);
        // Only where the fractal decides the distance: a floor beside it would dilute the figure.
        if (distance_at(ev, s, kAnyBias) == plain) return;
        if (plain > 0.0 && guarded > 0.0 && std::isfinite(plain) && std::isfinite(guarded)) out.push_back(plain / guarded);
        // A guarded estimate at or below zero outside the surface (a smooth union with a shrunken
        // fractal digs a false interior) is the largest growth there is.
        else if (plain > 0.0 && std::isfinite(plain)) out.push_back(std::numeric_limits<double>::infinity());
    };
    for (const auto& s : samples_)
        // Only where the march decides hits: within a hundredth of the bounds of the surface.
        if (s.walked && s.reach > 0.0 && distance_at(ev, s, 0.0) <= 0.01 * scene_.ir().scene.bounds_radius) growth_at(s, walked);
    BubbleSample start;
    for (const auto& p : ev.ir().params) start.params.push_back(p.value);
    for (const auto& p : visible_) {
        start.p = p;
        growth_at(start, visible);
    }
    SurfaceGrowth a = growth_of(std::move(walked)), b = growth_of(std::move(visible));
    return a.p90 >= b.p90 ? a : b;
}

double BubbleSearch::largest_bias_within_growth(double max_growth, double lo, double hi, double resolution) const {
    if (surface_growth(hi).p90 <= max_growth) return hi;
    if (surface_growth(lo).p90 > max_growth) return lo;
    while (hi - lo > resolution) {
        double mid = 0.5 * (lo + hi);
        (surface_growth(mid).p90 <= max_growth ? lo : hi) = mid;
    }
    return std::floor(lo / resolution + 1e-9) * resolution;
}

std::optional<double> BubbleSearch::smallest_safe_bias(double step_scale, double lo, double hi,
                                                       double resolution) const {
    if (count(hi, step_scale).overshoots) return std::nullopt;
    if (!count(lo, step_scale).overshoots) return lo;
    while (hi - lo > resolution) {
        double mid = 0.5 * (lo + hi);
        (count(mid, step_scale).overshoots ? lo : hi) = mid;
    }
    // Round up to the resolution: the grid value at or above the edge is safe by monotonicity.
    return std::ceil(hi / resolution - 1e-9) * resolution;
}

}  // namespace fg
