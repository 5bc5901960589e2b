// fgplay: plays Fractograph shader packs. Headless to images (render), benchmarks (bench), a
// desktop window (view), OpenXR headsets (xr) and the node editor in the browser (studio). Each
// command is registered by its own layer; this executable sits above them all and only puts them
// together.
#include <CLI/CLI.hpp>

#include "bench_command.h"
#include "command_line.h"
#include "tool/render_command.h"
#ifdef FG_HAVE_XR
#include "xr/xr_command.h"
#endif
#ifdef FG_HAVE_DESKTOP
#include "desktop/view_command.h"
#endif
#ifdef FG_HAVE_STUDIO
#include "studio/studio_command.h"
#endif

int main(int argc, char** argv) {
    CLI::App app{"fgplay: plays Fractograph shader packs (.fgpack)"};
    app.require_subcommand(1);
    fg::fgplay::RenderCommand render;
    fg::fgplay::add_render_command(app, render);
    fg::bench::BenchCommand bench;
    fg::bench::add_bench_command(app, bench);
#ifdef FG_HAVE_XR
    fg::xr::XrCommand xr;
    fg::xr::add_xr_command(app, xr);
#endif
#ifdef FG_HAVE_DESKTOP
    fg::desktop::ViewCommand view;
    fg::desktop::add_view_command(app, view);
#endif
#ifdef FG_HAVE_STUDIO
    fg::studio::StudioCommand studio;
    fg::studio::add_studio_command(app, studio);
#endif

    if (auto failed = fg::cli::parse(app, argc, argv)) return *failed;
    if (render.chosen()) return render.run();
    if (bench.chosen()) return bench.run();
#ifdef FG_HAVE_XR
    if (xr.chosen()) return xr.run();
#endif
#ifdef FG_HAVE_DESKTOP
    if (view.chosen()) return view.run();
#endif
#ifdef FG_HAVE_STUDIO
    if (studio.chosen()) return studio.run();
#endif
    return 2;
}
