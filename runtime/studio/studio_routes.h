#pragma once
// The studio's JSON API, one handler per verb of the page:
//   GET  /api/nodes                 the node library (palette)
//   GET  /api/graphs                graph files in the folder, and the one opened on the command line
//   GET  /api/graph?path=P          a graph file, parsed
//   POST /api/validate {graph}      the compiler's front half: diagnostics only (wires, literals)
//   POST /api/edit {graph}          queue a compile of the preview's graph -> {revision}
//   GET  /api/state?after=R&wait_ms=N   the newest compile outcome (waits for revision R)
//   POST /api/frame {camera, params, stereo}   a preview frame (PNG; figures in X-Fg-* headers)
//   POST /api/probe {x, y}          the surface under a pixel of the last frame
//   POST /api/node-preview {graph, node, port, params}   a node's small preview (PNG)
//   POST /api/save {path, graph, based_on}   the canonical text, inside the folder
//   POST /api/export {path, graph}  a shader pack, inside the folder
//   POST /api/calibrate {graph, samples}, GET /api/calibrate   fgc calibrate and its progress
#include <httplib.h>

#include "studio/studio_session.h"

namespace fg::studio {

void add_api_routes(httplib::Server& server, StudioSession& session, const std::string& opened_graph);

}  // namespace fg::studio
