#include <gtest/gtest.h>

#include "compiler.h"

TEST(Placeholder, builds) { SUCCEED(); }
