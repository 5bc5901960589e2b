#include "lipschitz_rule.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace fg {

struct LipschitzRule::Node {
    enum class Op { Number, Radius, L, AbsMax, AbsMin, Add, Sub, Mul, Div, Pow, Neg, Max, Min, Sqrt, Abs } op;
    double number = 0;
    std::string port;
    std::vector<std::shared_ptr<const Node>> args;
};

namespace {

using RuleNode = LipschitzRule::Node;
using Op = RuleNode::Op;
constexpr double kInf = std::numeric_limits<double>::infinity();

// 0 * inf = 0: the product rule's vanishing terms must not turn into NaN.
double mul(double a, double b) {
    if (a == 0.0 || b == 0.0) return 0.0;
    return a * b;
}

class Parser {
public:
    Parser(const std::string& text, std::vector<std::string>& ports) : s_(text), ports_(ports) {}

    std::shared_ptr<const RuleNode> parse(std::string& error) {
        try {
            auto n = expression();
            skip();
            if (i_ != s_.size()) throw std::runtime_error(fmt::format("unexpected '{}'", s_[i_]));
            return n;
        } catch (const std::exception& e) {
            error = fmt::format("{} at column {}", e.what(), i_ + 1);
            return nullptr;
        }
    }

private:
    const std::string& s_;
    std::vector<std::string>& ports_;
    std::size_t i_ = 0;

    void skip() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    bool accept(char c) {
        skip();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!accept(c)) throw std::runtime_error(fmt::format("expected '{}'", c));
    }
    static std::shared_ptr<RuleNode> make(Op op, std::vector<std::shared_ptr<const RuleNode>> args = {}) {
        auto n = std::make_shared<RuleNode>();
        n->op = op;
        n->args = std::move(args);
        return n;
    }
    std::shared_ptr<const RuleNode> expression() {
        auto left = term();
        for (;;) {
            if (accept('+')) left = make(Op::Add, {left, term()});
            else if (accept('-')) left = make(Op::Sub, {left, term()});
            else return left;
        }
    }
    std::shared_ptr<const RuleNode> term() {
        auto left = power();
        for (;;) {
            if (accept('*')) left = make(Op::Mul, {left, power()});
            else if (accept('/')) left = make(Op::Div, {left, power()});
            else return left;
        }
    }
    std::shared_ptr<const RuleNode> power() {
        auto base = unary();
        if (accept('^')) return make(Op::Pow, {base, unary()});
        return base;
    }
    std::shared_ptr<const RuleNode> unary() {
        if (accept('-')) return make(Op::Neg, {unary()});
        return primary();
    }
    std::string identifier() {
        skip();
        std::size_t start = i_;
        while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
        return s_.substr(start, i_ - start);
    }
    std::shared_ptr<const RuleNode> primary() {
        skip();
        if (i_ >= s_.size()) throw std::runtime_error("unexpected end of rule");
        if (accept('(')) {
            auto e = expression();
            expect(')');
            return e;
        }
        if (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.') {
            std::size_t used = 0;
            double v = std::stod(s_.substr(i_), &used);
            i_ += used;
            auto n = make(Op::Number);
            n->number = v;
            return n;
        }
        std::string id = identifier();
        if (id.empty()) throw std::runtime_error(fmt::format("unexpected '{}'", s_[i_]));
        if (id == "inf") {
            auto n = make(Op::Number);
            n->number = kInf;
            return n;
        }
        if (id == "R") return make(Op::Radius);
        if (id == "L" || id == "absmax" || id == "absmin") {
            expect('(');
            std::string port = identifier();
            if (port.empty()) throw std::runtime_error(fmt::format("{}( needs a port name", id));
            expect(')');
            auto n = make(id == "L" ? Op::L : id == "absmax" ? Op::AbsMax : Op::AbsMin);
            n->port = port;
            if (std::find(ports_.begin(), ports_.end(), port) == ports_.end()) ports_.push_back(port);
            return n;
        }
        Op op;
        if (id == "max") op = Op::Max;
        else if (id == "min") op = Op::Min;
        else if (id == "sqrt") op = Op::Sqrt;
        else if (id == "abs") op = Op::Abs;
        else throw std::runtime_error(fmt::format("unknown name '{}'", id));
        expect('(');
        std::vector<std::shared_ptr<const RuleNode>> args{expression()};
        while (accept(',')) args.push_back(expression());
        expect(')');
        if ((op == Op::Sqrt || op == Op::Abs) && args.size() != 1)
            throw std::runtime_error(fmt::format("{}() takes one argument", id));
        return make(op, std::move(args));
    }
};

double eval(const RuleNode& n, const LipschitzEnv& env) {
    auto arg = [&](std::size_t k) { return eval(*n.args[k], env); };
    switch (n.op) {
        case Op::Number: return n.number;
        case Op::Radius: return env.bounds_radius;
        case Op::L: return env.lipschitz(n.port);
        case Op::AbsMax: return env.absmax(n.port);
        case Op::AbsMin: return env.absmin(n.port);
        case Op::Add: return arg(0) + arg(1);
        case Op::Sub: return arg(0) - arg(1);
        case Op::Mul: return mul(arg(0), arg(1));
        case Op::Div: {
            double a = arg(0), b = arg(1);
            if (a == 0.0) return 0.0;
            return b == 0.0 ? kInf : a / b;
        }
        case Op::Pow: return std::pow(arg(0), arg(1));
        case Op::Neg: return -arg(0);
        case Op::Max: {
            double m = -kInf;
            for (std::size_t k = 0; k < n.args.size(); ++k) m = std::max(m, arg(k));
            return m;
        }
        case Op::Min: {
            double m = kInf;
            for (std::size_t k = 0; k < n.args.size(); ++k) m = std::min(m, arg(k));
            return m;
        }
        case Op::Sqrt: return std::sqrt(arg(0));
        case Op::Abs: return std::abs(arg(0));
    }
    return kInf;
}

}  // namespace

std::shared_ptr<const LipschitzRule> LipschitzRule::parse(const std::string& text, std::string& error) {
    auto rule = std::make_shared<LipschitzRule>();
    Parser p(text, rule->ports_);
    rule->root_ = p.parse(error);
    if (!rule->root_) return nullptr;
    return rule;
}

double LipschitzRule::evaluate(const LipschitzEnv& env) const { return eval(*root_, env); }

}  // namespace fg
