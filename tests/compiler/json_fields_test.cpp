// The one JSON field reader behind graphs, scene settings, node definitions, manifests and camera
// paths: a problem is told as the value's pointer, what was expected and what was found.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/json_fields.h"
#include "test_support.h"

namespace {

using fg::Choices;
using fg::Diagnostics;
using fg::JsonFieldReader;
using fg::NumberRange;
using fg::test::has_error;
using nlohmann::json;

const json kDoc = json::parse(R"({"name": 7, "size": 2.5, "count": 7.5, "on": "yes", "at": [1, "x", 3],
                                  "short": [1, 2], "mode": "single", "id": -3, "hue": 12, "ok": 0.5})");

TEST(JsonFields, a_value_of_the_wrong_kind_is_told_as_expected_and_found_at_its_pointer) {
    Diagnostics diag;
    JsonFieldReader r(diag);
    std::string name = "kept";
    EXPECT_FALSE(r.required(kDoc, "name", "/thing", name));
    EXPECT_EQ(name, "kept") << "a bad value leaves the default";
    std::int64_t count = 0;
    EXPECT_FALSE(r.optional(kDoc, "count", "/thing", count));
    bool on = false;
    EXPECT_FALSE(r.optional(kDoc, "on", "/thing", on));
    glm::dvec3 at{0.0};
    EXPECT_FALSE(r.optional(kDoc, "at", "/thing", at));
    EXPECT_FALSE(r.optional(kDoc, "short", "/thing", at));
    std::uint32_t id = 0;
    EXPECT_FALSE(r.optional(kDoc, "id", "/thing", id));
    EXPECT_TRUE(has_error(diag, "/thing/name", "", "expected a string, got a number"));
    EXPECT_TRUE(has_error(diag, "/thing/count", "", "expected an integer, got 7.5"));
    EXPECT_TRUE(has_error(diag, "/thing/on", "", "expected true or false, got a string"));
    EXPECT_TRUE(has_error(diag, "/thing/at/1", "", "expected a number, got a string"));
    EXPECT_TRUE(has_error(diag, "/thing/short", "", "expected an array of 3 numbers, got an array of 2"));
    EXPECT_TRUE(has_error(diag, "/thing/id", "", "expected an unsigned 32-bit integer, got -3"));
    EXPECT_EQ(r.errors(), 6u);
}

TEST(JsonFields, ranges_choices_and_missing_fields) {
    Diagnostics diag;
    JsonFieldReader r(diag);
    double hue = 0.0, ok = 0.0;
    EXPECT_FALSE(r.optional(kDoc, "hue", "", hue, NumberRange{0.0, 1.0}));
    EXPECT_TRUE(r.optional(kDoc, "ok", "", ok, NumberRange::positive(1.0)));
    EXPECT_EQ(ok, 0.5);
    std::string mode;
    EXPECT_FALSE(r.optional(kDoc, "mode", "", mode, Choices{"float", "double"}));
    EXPECT_FALSE(r.required(kDoc, "absent", "/here", mode));
    EXPECT_FALSE(r.optional(kDoc, "also_absent", "", mode)) << "left out: nothing to read, nothing wrong";
    EXPECT_TRUE(has_error(diag, "/hue", "", "12 is out of range [0, 1]"));
    EXPECT_TRUE(has_error(diag, "/mode", "", "expected \"float\" or \"double\", got \"single\""));
    EXPECT_TRUE(has_error(diag, "/here", "", "missing \"absent\""));
    EXPECT_EQ(r.errors(), 3u) << diag.format();
}

TEST(JsonFields, unknown_keys_are_reported_with_the_nearest_known_one) {
    Diagnostics diag;
    JsonFieldReader r(diag);
    r.unknown_keys(json::parse(R"({"max_sped": 1, "colour": 2, "zebra": 3, "max_speed": 4})"), "/scene/locomotion",
                   {"max_speed", "color"}, "setting");
    EXPECT_TRUE(has_error(diag, "/scene/locomotion/max_sped", "", "unknown setting \"max_sped\"; did you mean \"max_speed\"?"));
    EXPECT_TRUE(has_error(diag, "/scene/locomotion/colour", "", "did you mean \"color\"?"));
    EXPECT_TRUE(has_error(diag, "/scene/locomotion/zebra", "", "unknown setting \"zebra\""));
    EXPECT_EQ(r.errors(), 3u);
}

TEST(JsonFields, keys_are_escaped_in_pointers) {
    EXPECT_EQ(JsonFieldReader::field_pointer("/a", "b/c~d"), "/a/b~1c~0d");
}

}  // namespace
