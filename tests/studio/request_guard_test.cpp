#include <gtest/gtest.h>

#include "studio/request_guard.h"

namespace fg::studio {

TEST(RequestGuard, AnswersItsOwnHostOnLoopbackUnderEveryLoopbackName) {
    RequestGuard guard("127.0.0.1", 8765);
    EXPECT_FALSE(guard.refuse("127.0.0.1:8765", ""));
    EXPECT_FALSE(guard.refuse("localhost:8765", "http://localhost:8765"));
    EXPECT_FALSE(guard.refuse("[::1]:8765", ""));
    EXPECT_FALSE(guard.refuse("LOCALHOST:8765", "HTTP://127.0.0.1:8765"));
}

TEST(RequestGuard, RefusesAForeignHostAsDnsRebindingWouldSendIt) {
    RequestGuard guard("127.0.0.1", 8765);
    auto why = guard.refuse("evil.example:8765", "");
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("evil.example"), std::string::npos);
    EXPECT_TRUE(guard.refuse("127.0.0.1:9999", ""));
    EXPECT_TRUE(guard.refuse("", ""));
}

TEST(RequestGuard, RefusesAPageFromAnotherOrigin) {
    RequestGuard guard("127.0.0.1", 8765);
    auto why = guard.refuse("127.0.0.1:8765", "http://evil.example");
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("Origin"), std::string::npos);
    EXPECT_TRUE(guard.refuse("127.0.0.1:8765", "https://127.0.0.1:8765"));
    EXPECT_TRUE(guard.refuse("127.0.0.1:8765", "http://127.0.0.1:8766"));
    EXPECT_TRUE(guard.refuse("127.0.0.1:8765", "null"));
}

TEST(RequestGuard, AnotherBindAddressAcceptsOnlyThatAddress) {
    RequestGuard guard("192.168.1.20", 80);
    EXPECT_FALSE(guard.refuse("192.168.1.20:80", ""));
    EXPECT_TRUE(guard.refuse("localhost:80", ""));
}

}  // namespace fg::studio
