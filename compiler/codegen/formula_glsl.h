#pragma once
// The GLSL statements of a fractal.formula node's function: the schedule's loops calling the
// stages, the running derivative composed from their declared rules, the bias guard and the
// estimate. The CPU twin runs the same program (cpu/cpu_formula.h); keep the two in step.
#include <string>

#include "ir/formula_program.h"

namespace fg {

// Statements for a function whose parameters are named as the formula node's inputs (p, c, w,
// iterations, bailout, bias, then u_<param> for each graph parameter) and outputs (distance, trap).
std::string formula_glsl(const FormulaProgram& program);

// The name of the function input carrying graph parameter `param`.
std::string formula_param_input(const std::string& param);

}  // namespace fg
