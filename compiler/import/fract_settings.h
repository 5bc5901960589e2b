#pragma once
// A Mandelbulber settings file (.fract) as written: sections ([main_parameters], [fractal_1] ...)
// of `name value;` lines. Values keep their text; numbers may use a decimal comma (the writer's
// locale), vectors are numbers separated by spaces. Every value remembers its line, so a message
// can name where it came from.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/diagnostics.h"

namespace fg {

struct FractValue {
    std::string text;
    int line = 0;
};

class FractSettings {
public:
    // nullopt, with the line named, when the text is not a settings file.
    static std::optional<FractSettings> parse(const std::string& text, Diagnostics& diag);

    using Section = std::map<std::string, FractValue>;
    const Section* section(const std::string& name) const;
    const std::map<std::string, Section>& sections() const { return sections_; }
    // The Mandelbulber version that wrote the file ("# version 2.05"); older files mean some
    // settings differently.
    double version() const { return version_; }

    // A value of [main_parameters] (or of `section`), or nullptr.
    const FractValue* find(const std::string& name, const std::string& section = "main_parameters") const;

private:
    std::map<std::string, Section> sections_;
    double version_ = 2.20;
};

// Readers of a value's text; nullopt when it is not of that kind.
std::optional<double> fract_number(const std::string& text);
std::optional<glm::dvec3> fract_vector(const std::string& text);
std::optional<bool> fract_bool(const std::string& text);

}  // namespace fg
