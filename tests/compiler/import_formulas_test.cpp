// fgc import's formulas against Mandelbulber's definitions, written here a second time the plain
// way (one loop over the orbit in Mandelbulber's own axes, z up, rotations as its matrices): the
// imported graph's CPU twin must give the same distances at random points, which pins down the
// axis change, the Euler orders, the fold planes' sides and the estimates. Also the set filled to
// the iteration count and the primitive shapes, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "cpu/cpu_evaluator.h"
#include "import/mandelbulber_import.h"
#include "test_support.h"

using namespace fg;

namespace {

using Vec = glm::dvec3;
using Mat = glm::dmat3;

const char* kHeader = "# Mandelbulber settings file\n# version 2.20\n[main_parameters]\n";

// The imported graph's CPU twin, with the lowered graph it reads.
struct Imported {
    std::unique_ptr<IrGraph> ir;
    std::optional<CpuEvaluator> eval;
    explicit operator bool() const { return eval.has_value(); }
    CpuEvaluator* operator->() { return &*eval; }
    CpuEvaluator& operator*() { return *eval; }
};

Imported imported(const std::string& settings) {
    Diagnostics diag;
    Imported out;
    auto s = FractSettings::parse(std::string(kHeader) + settings, diag);
    auto graph = s ? import_mandelbulber(*s, "scene", diag) : std::nullopt;
    auto ir = graph ? load_and_lower(graph->dump(), NodeLibrary::builtin(), diag) : std::nullopt;
    if (ir) {
        out.ir = std::make_unique<IrGraph>(std::move(*ir));
        out.eval = CpuEvaluator::create(*out.ir, diag);
    }
    EXPECT_TRUE(out) << diag.format();
    return out;
}

// Rows to a matrix, and Mandelbulber's turns about its axes (angles in degrees).
Mat rows(Vec a, Vec b, Vec c) { return glm::transpose(Mat(a, b, c)); }
Mat rx(double d) { double r = glm::radians(d), c = std::cos(r), s = std::sin(r); return rows({1, 0, 0}, {0, c, -s}, {0, s, c}); }
Mat ry(double d) { double r = glm::radians(d), c = std::cos(r), s = std::sin(r); return rows({c, 0, s}, {0, 1, 0}, {-s, 0, c}); }
Mat rz(double d) { double r = glm::radians(d), c = std::cos(r), s = std::sin(r); return rows({c, -s, 0}, {s, c, 0}, {0, 0, 1}); }

// The graph's point (x, y, z) is Mandelbulber's (x, -z, y).
Vec mandelbulber_point(Vec g) { return {g.x, -g.z, g.y}; }

// The largest relative difference between the imported graph and the definition over `n` random
// points of the cube [-r, r]^3. Rounding alone stays under 1e-7 (the stages normalise each plane
// again, a turn goes through its axis and angle); a wrong axis, order or side is off by O(1).
double worst(CpuEvaluator& eval, const std::function<double(Vec)>& definition, double r, int n = 300) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-r, r);
    double out = 0.0;
    for (int i = 0; i < n; ++i) {
        Vec g(u(rng), u(rng), u(rng));
        double ours = eval.distance(g), theirs = definition(mandelbulber_point(g));
        out = std::max(out, std::abs(ours - theirs) / std::max(std::abs(theirs), 1e-9));
    }
    return out;
}

}  // namespace

TEST(ImportedFormulas, a_kaleidoscopic_ifs_with_turned_planes_edges_and_main_turn_is_mandelbulbers) {
    auto eval = imported(
        "formula_1 10;\nN 12;\n[fractal_1]\nIFS_abs_x true;\nIFS_abs_z true;\n"
        "IFS_enabled_0 true;\nIFS_direction_0 1 -1 0,3;\nIFS_distance_0 0,1;\nIFS_rotations_0 10 20 -5;\n"
        "IFS_enabled_1 true;\nIFS_direction_1 0,2 1 -1;\nIFS_distance_1 -0,2;\n"
        "IFS_enabled_2 true;\nIFS_direction_2 0,5 0,5 1;\nIFS_rotations_2 -30 5 12;\n"
        "IFS_rotation_enabled true;\nIFS_rotation 15 -25 40;\nIFS_offset 1 0,4 0,7;\nIFS_edge 1,2 0 0,8;\nIFS_scale 2,3;\n");
    ASSERT_TRUE(eval);
    struct Plane {
        Vec direction;
        double distance;
        Mat turn;
    };
    const Plane planes[] = {{glm::normalize(Vec(1, -1, 0.3)), 0.1, rz(10) * ry(20) * rx(-5)},
                            {glm::normalize(Vec(0.2, 1, -1)), -0.2, Mat(1.0)},
                            {glm::normalize(Vec(0.5, 0.5, 1)), 0.0, rz(-30) * ry(5) * rx(12)}};
    const Mat main = rz(15) * ry(-25) * rx(40);
    const Vec offset(1, 0.4, 0.7), edge(1.2, 0, 0.8);
    auto definition = [&](Vec z) {
        double dr = 1.0;
        for (int i = 0; i < 12 && glm::length(z) <= 100.0; ++i) {
            z.x = std::abs(z.x);
            z.z = std::abs(z.z);
            for (const auto& p : planes) {
                z = p.turn * z;
                double along = glm::dot(z, p.direction);
                if (along < p.distance) z -= p.direction * (2.0 * (along - p.distance));
            }
            z = main * (z - offset) + offset;
            for (int a = 0; a < 3; ++a)
                if (edge[a] > 0.0) z[a] = edge[a] - std::abs(edge[a] - z[a]);
            z = z * 2.3 - offset * 1.3;
            dr *= 2.3;
        }
        return (glm::length(z) - 2.0) / dr;
    };
    EXPECT_LT(worst(*eval, definition, 1.5), 1e-6);
}

TEST(ImportedFormulas, a_menger_sponge_ifs_keeps_its_edge_cubes_along_mandelbulbers_z) {
    auto eval = imported(
        "formula_1 10;\nN 10;\n[fractal_1]\nIFS_abs_x true;\nIFS_abs_y true;\nIFS_abs_z true;\n"
        "IFS_enabled_0 true;\nIFS_direction_0 1 -1 0;\nIFS_enabled_1 true;\nIFS_direction_1 1 0 -1;\n"
        "IFS_enabled_2 true;\nIFS_direction_2 0,39 1 -1;\nIFS_menger_sponge_mode true;\nIFS_offset 1 0,8 1,2;\nIFS_scale 3;\n");
    ASSERT_TRUE(eval);
    const Vec directions[] = {glm::normalize(Vec(1, -1, 0)), glm::normalize(Vec(1, 0, -1)), glm::normalize(Vec(0.39, 1, -1))};
    const Vec offset(1, 0.8, 1.2);
    auto definition = [&](Vec z) {
        double dr = 1.0;
        for (int i = 0; i < 10 && glm::length(z) <= 100.0; ++i) {
            z = glm::abs(z);
            for (const auto& d : directions)
                if (double along = glm::dot(z, d); along < 0.0) z -= d * (2.0 * along);
            z *= 3.0;
            z.x -= offset.x * 2.0;
            z.y -= offset.y * 2.0;
            if (z.z > offset.z) z.z -= offset.z * 2.0;
            dr *= 3.0;
        }
        return (glm::length(z) - 2.0) / dr;
    };
    EXPECT_LT(worst(*eval, definition, 1.5), 1e-6);
}

TEST(ImportedFormulas, a_mandelbox_with_turned_fold_planes_and_main_turn_is_mandelbulbers) {
    auto eval = imported(
        "formula_1 8;\nN 12;\n[fractal_1]\nmandelbox_scale -1,7;\nmandelbox_rotations_enabled true;\n"
        "mandelbox_main_rotation_enabled true;\nmandelbox_rotation_main 7 -13 22;\n"
        "mandelbox_rotation_neg_1 10 -20 5;\nmandelbox_rotation_pos_1 4 4 -9;\nmandelbox_rotation_neg_2 0 15 30;\n"
        "mandelbox_rotation_pos_2 20 0 0;\nmandelbox_rotation_neg_3 -12 3 0;\nmandelbox_rotation_pos_3 0 -10 25;\n");
    ASSERT_TRUE(eval);
    // Rotation settings (x, y, z) make Rz(z) Ry(y) Rx(x); the "neg" frame folds beyond +1.
    auto turn = [](Vec a) { return rz(a.z) * ry(a.y) * rx(a.x); };
    const Mat upper[] = {turn({10, -20, 5}), turn({0, 15, 30}), turn({-12, 3, 0})};
    const Mat lower[] = {turn({4, 4, -9}), turn({20, 0, 0}), turn({0, -10, 25})};
    const Mat main = turn({7, -13, 22});
    auto definition = [&](Vec c) {
        Vec z = c;
        double dr = 1.0;
        for (int i = 0; i < 12 && glm::length(z) <= 100.0; ++i) {
            for (int a = 0; a < 3; ++a) {
                Vec t = upper[a] * z;
                if (t[a] > 1.0) {
                    t[a] = 2.0 - t[a];
                    z = glm::transpose(upper[a]) * t;
                } else if (t = lower[a] * z; t[a] < -1.0) {
                    t[a] = -2.0 - t[a];
                    z = glm::transpose(lower[a]) * t;
                }
            }
            const double r2 = glm::dot(z, z), k = r2 < 0.25 ? 4.0 : r2 < 1.0 ? 1.0 / r2 : 1.0;
            z = main * (z * k) * -1.7 + c;
            dr = dr * k * 1.7 + 1.0;
        }
        return glm::length(z) / dr;
    };
    EXPECT_LT(worst(*eval, definition, 2.0), 1e-6);
}

TEST(ImportedFormulas, a_pseudo_kleinian_measures_its_seed_disc_about_mandelbulbers_z) {
    auto eval = imported(
        "formula_1 103;\nN 20;\n[fractal_1]\ntransf_addition_constant_0777 0,8 0,6 0,9;\ntransf_minimum_radius_05 0,6;\n"
        "transf_addition_constant 0,1 0 -0,05;\nanalyticDE_scale_1 1,2;\ntransf_function_enabledR_false true;\n"
        "transf_rotation 5 -3 8;\n");
    ASSERT_TRUE(eval);
    const Vec size(0.8, 0.6, 0.9), shift(0.1, 0, -0.05);
    const Mat turn = rz(8) * ry(-3) * rx(5);
    auto definition = [&](Vec z) {
        double dr = 1.0;
        for (int i = 0; i < 20 && glm::length(z) <= 100.0; ++i) {
            z = 2.0 * glm::clamp(z, -size, size) - z;
            const double k = std::max(0.6 / glm::dot(z, z), 1.0);
            z = turn * (z * k) + shift;
            dr *= k;
        }
        const double rxy = std::hypot(z.x, z.y);
        return std::max(rxy - 1.2, std::abs(rxy * z.z) / glm::length(z)) / dr;
    };
    EXPECT_LT(worst(*eval, definition, 1.5), 1e-6);
}

// The power maps' orbits are Mandelbulber's; their running derivative is the compiler's (each
// stage's factor, + 1 for c, never below the last with bias 1), with the logarithmic estimate.
struct PowerCase {
    const char* settings;
    std::function<Vec(Vec, double&)> step;   // one iteration without c; multiplies dr by the graph's factors
    double bailout;
};

TEST(ImportedFormulas, the_bulbs_and_squares_follow_mandelbulbers_orbits) {
    auto bulb2 = [](Vec z) {
        const double x2 = z.x * z.x, y2 = z.y * z.y, z2 = z.z * z.z, t = 1.0 - z2 / (x2 + y2);
        return Vec((x2 - y2) * t, 2.0 * z.x * z.y * t, -2.0 * z.z * std::sqrt(x2 + y2));
    };
    const PowerCase cases[] = {
        {"formula_1 16;\nN 9;\n[fractal_1]\nboxfold_bulbpow2_folding_factor 1,5;\nboxfold_bulbpow2_z_factor 3;\n",
         [&](Vec z, double& dr) {
             for (int a = 0; a < 3; ++a)
                 if (std::abs(z[a]) > 1.5) z[a] = (z[a] > 0 ? 3.0 : -3.0) - z[a];
             const double r2 = glm::dot(z, z), k = r2 < 0.25 ? 4.0 : r2 < 1.0 ? 1.0 / r2 : 1.0;
             z *= k * 2.0;
             dr *= k * 2.0 * 2.0 * glm::length(z) * 3.0;
             z = bulb2(z);
             z.z *= 3.0;
             return z;
         },
         10.0},
        {"formula_1 3;\nN 9;\n", [&](Vec z, double& dr) { dr *= 2.0 * glm::length(z); return bulb2(z); }, 10.0},
        {"formula_1 2;\nN 8;\n[fractal_1]\npower 7;\nalpha_angle_offset 22,5;\nbeta_angle_offset -10;\n",
         [](Vec z, double& dr) {
             const double r = glm::length(z), th = std::asin(z.z / r) + glm::radians(-10.0), ph = std::atan2(z.y, z.x) + glm::radians(22.5);
             dr *= 7.0 * std::pow(r, 6.0);
             return std::pow(r, 7.0) * Vec(std::cos(7 * th) * std::cos(7 * ph), std::cos(7 * th) * std::sin(7 * ph), std::sin(7 * th));
         },
         10.0},
        {"formula_1 11;\nN 8;\n[fractal_1]\npower 3;\nalpha_angle_offset 20;\nbeta_angle_offset -10;\n",
         [](Vec z, double& dr) {
             const double r = glm::length(z), th = std::atan2(z.y, z.x) + glm::radians(-10.0);
             double ph = std::acos(z.z / r) + glm::radians(20.0);
             if (const double pi = 3.14159265358979323846; std::abs(ph) > 0.5 * pi) ph = (ph > 0 ? pi : -pi) - ph;
             dr *= 3.0 * r * r;
             return r * r * r * Vec(std::cos(3 * th) * std::sin(3 * ph), std::sin(3 * th) * std::sin(3 * ph), std::cos(3 * ph));
         },
         10.0},
        {"formula_1 5;\nN 9;\n",
         [](Vec z, double& dr) {
             dr *= 2.0 * glm::length(z);
             return Vec(z.x * z.x - z.y * z.y - z.z * z.z, 2.0 * z.x * z.y, 2.0 * z.x * z.z);
         },
         10.0},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.settings);
        auto eval = imported(c.settings);
        ASSERT_TRUE(eval);
        const int n = std::stoi(std::string(c.settings).substr(std::string(c.settings).find("N ") + 2));
        auto definition = [&](Vec p) {
            Vec z = p;
            double dr = 1.0;
            for (int i = 0; i < n && glm::length(z) <= c.bailout; ++i) {
                double next = dr;
                z = c.step(z, next) + p;
                dr = std::max(dr, next + 1.0);
            }
            const double r = glm::length(z);
            return 0.5 * std::log(r) * r / dr;
        };
        EXPECT_LT(worst(*eval, definition, 1.3), 1e-6);
    }
}

TEST(ImportedFormulas, menger_mod1_scales_by_its_own_factor_and_shifts) {
    auto eval = imported("formula_1 61;\nN 8;\n[fractal_1]\ntransf_scale_3 2,6;\ntransf_addition_constant 0,13 -0,2 0;\n"
                         "transf_rotation_enabled true;\ntransf_rotation 0 0 30;\n");
    ASSERT_TRUE(eval);
    const Mat turn = rz(30);
    auto definition = [&](Vec z) {
        double dr = 1.0;
        for (int i = 0; i < 8 && glm::length(z) <= 10.0; ++i) {
            z = glm::abs(z);
            if (z.x < z.y) std::swap(z.x, z.y);
            if (z.x < z.z) std::swap(z.x, z.z);
            if (z.y < z.z) std::swap(z.y, z.z);
            z *= 2.6;
            z.x -= 2.0;
            z.y -= 2.0;
            if (z.z > 1.0) z.z -= 2.0;
            z = turn * z + Vec(0.13, -0.2, 0);
            dr *= 2.6;
        }
        return (glm::length(z) - 2.0) / dr;
    };
    EXPECT_LT(worst(*eval, definition, 1.5), 1e-6);
}

TEST(ImportedFormulas, the_iteration_threshold_mode_fills_what_never_escapes) {
    // A power-2 bulb at 4 iterations: inside the set filled to 4 iterations the distance is at
    // most 0, outside it is the estimate; the threshold's surface is where the orbit first stays.
    auto filled = imported("formula_1 2;\nN 4;\niteration_threshold_mode true;\n[fractal_1]\npower 2;\n");
    auto plain = imported("formula_1 2;\nN 4;\n[fractal_1]\npower 2;\n");
    ASSERT_TRUE(filled && plain);
    int inside = 0, outside = 0;
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1.6, 1.6);
    for (int i = 0; i < 400; ++i) {
        const Vec g(u(rng), u(rng), u(rng));
        Vec z = mandelbulber_point(g);
        bool escaped = false;
        for (int k = 0; k < 4 && !escaped; ++k) {
            escaped = glm::length(z) > 10.0;
            if (escaped) break;
            const double r = glm::length(z), th = std::asin(z.z / r) * 2.0, ph = std::atan2(z.y, z.x) * 2.0;
            z = r * r * Vec(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th)) + mandelbulber_point(g);
        }
        escaped = escaped || glm::length(z) > 10.0;
        if (escaped) {
            EXPECT_DOUBLE_EQ(filled->distance(g), plain->distance(g));
            ++outside;
        } else {
            EXPECT_LE(filled->distance(g), 0.0);
            EXPECT_EQ(filled->distance(g), std::min(plain->distance(g), 0.0));
            ++inside;
        }
    }
    EXPECT_GT(inside, 20);
    EXPECT_GT(outside, 20);
}

TEST(ImportedFormulas, primitives_join_the_fractal_where_mandelbulber_places_them) {
    // Primitives away from a small bulb at the origin, so their closed forms decide near them.
    auto eval = imported(
        "formula_1 2;\nN 4;\nprimitive_sphere_1_enabled true;\nprimitive_sphere_1_position 3 0 0;\nprimitive_sphere_1_radius 0,5;\n"
        "primitive_box_1_enabled true;\nprimitive_box_1_position 0 3 1;\nprimitive_box_1_size 1 2 0,4;\nprimitive_box_1_rounding 0,1;\n"
        "primitive_plane_1_enabled true;\nprimitive_plane_1_position -10 0 0;\nprimitive_plane_1_rotation 0 -90 0;\n"
        "primitive_torus_1_enabled true;\nprimitive_torus_1_position 0 -3 0;\nprimitive_torus_1_radius 0,8;\nprimitive_torus_1_tube_radius 0,1;\n");
    ASSERT_TRUE(eval);
    auto at = [&](Vec m) { return eval->distance(Vec(m.x, m.z, -m.y)); };   // Mandelbulber's point (z up)
    EXPECT_NEAR(at({3.8, 0, 0}), 0.3, 1e-9);                   // the sphere
    EXPECT_NEAR(at({0, 3, 1.5}), 0.5 - 0.2 - 0.1, 1e-9);       // the box's top: half height 0.2, rounded out by 0.1
    EXPECT_NEAR(at({0, 4.35, 1}), 0.25, 1e-9);                 // its side: half size 1, the rounding, 0.25 more
    EXPECT_NEAR(at({0.5, -3.8, 0}), std::hypot(0.5, 0.8) - 0.8 - 0.1, 1e-9);   // the torus, its ring in the xy plane
    // Rz(0) Ry(-90) Rx(0) turns the plane's z to face +x: 0.5 in front of x = -10.
    EXPECT_NEAR(at({-9.5, 0.3, 0.2}), 0.5, 1e-9);
    EXPECT_LT(at({-10.5, 0, 0}), 0.0);
}

TEST(ImportedFormulas, a_lone_bulb_far_away_is_capped_by_the_ball_its_set_lies_in) {
    // Mandelbulber's bailout of 10 leaves the logarithmic estimate too long far from the set (10.3
    // from 9.3 away, where the set's tips are 8 away): rays stepped over the whole bulb. The set
    // of z^8 + 1.1 c lies within 2 / 1.1 of the origin and reaches past 1 on every axis.
    auto eval = imported("formula_1 2;\nN 12;\nfractal_constant_factor 1,1 1,1 1,1;\n[fractal_1]\npower 8;\n");
    ASSERT_TRUE(eval);
    for (const Vec& p : {Vec(9, 0, 0), Vec(0, -7, 4), Vec(3, 5, -6)}) EXPECT_LE(eval->distance(p), glm::length(p) - 1.0) << p.x << " " << p.y << " " << p.z;
}
