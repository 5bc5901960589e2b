#pragma once
// The parameter of the per-node tests: every node type of the built-in library, named so that
// ctest lists one test per node ("prim.sphere" becomes "prim_sphere").
#include <gtest/gtest.h>

#include <string>

#include "node_harness.h"

namespace fg::test {

inline std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string s = info.param;
    for (auto& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return s;
}

}  // namespace fg::test

#define FG_FOR_EVERY_NODE(Suite) \
    INSTANTIATE_TEST_SUITE_P(Library, Suite, ::testing::ValuesIn(::fg::test::library_node_types()), ::fg::test::test_name)
#define FG_FOR_EVERY_DISTANCE_NODE(Suite)                                                                  \
    INSTANTIATE_TEST_SUITE_P(Library, Suite, ::testing::ValuesIn(::fg::test::library_distance_node_types()), \
                             ::fg::test::test_name)
