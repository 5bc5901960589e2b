#pragma once
// The studio's preview of a graph with formula nodes: every numeric literal of a formula body
// (a stage's fold limit, scale, angle) made a graph parameter of its own, so the passes' code holds
// a uniform where the graph holds a number. Editing such a number then changes a parameter's
// default, which compiles no pass; only a change of the body's wiring or stages compiles. Literals
// the compiler would refuse (out of the port's range, the wrong shape) stay as they are, so its
// message still points at them.
#include <string>

#include "node_library.h"

namespace fg {

// The graph text with its bodies' literals as parameters named fgbody_N (N counting from 0, past
// any the graph declares); text that is not a graph object comes back unchanged.
std::string with_body_literals_as_params(const std::string& graph_text, const NodeLibrary& library);

}  // namespace fg
