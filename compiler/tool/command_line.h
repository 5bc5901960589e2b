#pragma once
// Parsing fgc's and fgplay's command lines so that a mistyped word is named, with the nearest
// command or option it could have meant:
//   fgplay: unknown command "rendr"; did you mean "render"?
//   fgplay render: unknown option "--franes"; did you mean "--frames"?
// instead of CLI11's "A subcommand is required" or "The following arguments were not expected".
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace fg::cli {

// The candidate nearest to `word` when it is near enough to be a typo (case-insensitive edit
// distance at most a third of the word, and at least 1), else empty.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

// Parses; nullopt when the command line is good. Otherwise prints the error (with the suggestion
// for an unknown command or option, or CLI11's own message and help) and returns the exit code.
std::optional<int> parse(CLI::App& app, int argc, char** argv);

}  // namespace fg::cli
