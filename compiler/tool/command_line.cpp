#include "command_line.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "edit_distance.h"

namespace fg::cli {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// The subcommand the user chose, the deepest one when they nest; the app itself when none.
CLI::App* chosen(CLI::App& app) {
    CLI::App* at = &app;
    for (auto subs = at->get_subcommands(); !subs.empty(); subs = at->get_subcommands()) at = subs.front();
    return at;
}

std::vector<std::string> command_names(CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    return names;
}

std::vector<std::string> option_names(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* o : command.get_options()) {
        for (const auto& n : o->get_lnames()) names.push_back("--" + n);
        for (const auto& n : o->get_snames()) names.push_back("-" + n);
    }
    return names;
}

std::string hint(const std::string& word, const std::vector<std::string>& candidates, const std::string& listing) {
    const std::string near = nearest(word, candidates);
    return near.empty() ? fmt::format(" ({})", listing) : fmt::format("; did you mean \"{}\"?", near);
}

}  // namespace

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
    for (const auto& c : candidates) {
        const std::size_t d = edit_distance(lower(word), lower(c));
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

std::optional<int> parse(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
        return std::nullopt;
    } catch (const CLI::Success& e) {   // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::string tool = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : app.get_name();
        CLI::App* command = chosen(app);
        const std::string where = command == &app ? tool : fmt::format("{} {}", tool, command->get_name());
        const std::vector<std::string> left = command->remaining();
        const auto option = std::find_if(left.begin(), left.end(), [](const std::string& w) { return w.size() > 1 && w[0] == '-'; });
        if (option != left.end()) {
            fmt::print(stderr, "{}: unknown option \"{}\"{}\n", where, *option,
                       hint(*option, option_names(*command), fmt::format("{} --help lists the options", where)));
            return e.get_exit_code();
        }
        if (command == &app && !left.empty()) {
            fmt::print(stderr, "{}: unknown command \"{}\"{}\n", tool, left.front(),
                       hint(left.front(), command_names(app), fmt::format("the commands: {}", fmt::join(command_names(app), ", "))));
            return e.get_exit_code();
        }
        return app.exit(e);
    }
}

}  // namespace fg::cli
