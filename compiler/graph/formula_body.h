#pragma once
// The body of a fractal.formula node as the author wrote it: groups of stage nodes acting on the
// orbit point z, and the schedule that says which group each iteration runs. The compiler derives
// the running derivative, the distance estimate and the bias guard from it (ir/formula_program.h).
#include <string>
#include <vector>

namespace fg {

struct GraphNode;
struct Binding;

// Stages whose z inputs chain from the point entering the group to `z`, the point it leaves with,
// and maths nodes between them (they read the entering point from a stage.orbit node).
struct FormulaGroup {
    std::string name;
    std::vector<GraphNode> nodes;
    std::string z_node;        // the node whose first output leaves the group as z
    std::string pointer;       // /nodes/2/formula/groups/0
};

// Run `group` for `count` iterations (0: every iteration left).
struct FormulaSegment {
    std::string group;
    int count = 0;
    std::string pointer;
};

struct FormulaBody {
    std::vector<FormulaGroup> groups;
    std::vector<FormulaSegment> schedule;   // in order; empty: the only group, every iteration
    bool repeat = false;                    // after the last segment, start the schedule again
    bool julia = false;                     // c is the node's input c, not the sample point
    std::string estimate;                   // "linear", "log", "box", "sheet", or "" (the compiler infers it)
    std::string derivative;                 // "scalar", "jacobian", or "" (Jacobian when maths nodes are in it)
    double sheet_radius = 100.0;            // "sheet": the radius of the seed disc
    double linear_radius = 0.0;             // "linear": (|z| - this) / dr
    bool filled = false;                    // a point whose orbit never escapes is inside (distance <= 0)
    double bound_radius = 0.0;              // the set lies in |p| <= this (0: unknown)
    std::string pointer;                    // /nodes/2/formula
};

}  // namespace fg
