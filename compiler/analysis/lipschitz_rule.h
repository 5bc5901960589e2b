#pragma once
// The small expression language of Lipschitz rules in node definitions, e.g.
//   "L(p) / absmin(s) + L(s) * absmax(p) / absmin(s)^2"
// L(port)       Lipschitz bound of the input with respect to the sample point (0 for constants)
// absmax(port)  upper bound of |input| (Euclidean norm for vectors; infinite if unknown)
// absmin(port)  lower bound of |input| (0 if unknown)
// R             radius of the scene bounds
// numbers, inf, + - * / ^, unary -, max(a, b, ...), min(a, b, ...), sqrt(x), abs(x)
// Arithmetic follows 0 * inf = 0: a term whose derivative factor is zero vanishes even when the
// value it multiplies is unbounded.
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fg {

struct LipschitzEnv {
    std::function<double(const std::string& port)> lipschitz;
    std::function<double(const std::string& port)> absmax;
    std::function<double(const std::string& port)> absmin;
    double bounds_radius = 1.0;
};

class LipschitzRule {
public:
    // Parses `text`; on failure returns nullptr and sets `error` (with the column).
    static std::shared_ptr<const LipschitzRule> parse(const std::string& text, std::string& error);
    double evaluate(const LipschitzEnv& env) const;
    // Ports the rule mentions, to check them against the node definition.
    const std::vector<std::string>& ports() const { return ports_; }

    struct Node;

private:
    std::shared_ptr<const Node> root_;
    std::vector<std::string> ports_;
};

}  // namespace fg
