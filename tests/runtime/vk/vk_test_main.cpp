#include <cstdlib>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    // Mesa's on-disk shader cache would make a second run behave differently from the first.
    ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
