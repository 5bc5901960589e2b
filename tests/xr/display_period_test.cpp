// The display period learned from a runtime's predictions: Monado's placeholder first period is
// left out, stretched periods (whole multiples of the display's) lead back to the display's, and a
// little clock jitter does not turn the period into a fraction of itself.
#include <gtest/gtest.h>

#include <initializer_list>

#include "frame/display_period.h"

using fg::DisplayPeriod;

namespace {

double learned(std::initializer_list<double> predictions) {
    DisplayPeriod p;
    for (double ms : predictions) p.observe(ms);
    return p.ms().value_or(-1.0);
}

}  // namespace

TEST(DisplayPeriod, the_first_prediction_is_a_placeholder_and_stretched_periods_lead_to_the_display_period) {
    DisplayPeriod p;
    p.observe(16.0);
    EXPECT_FALSE(p.ms()) << "nothing is learned from the placeholder alone";
    EXPECT_DOUBLE_EQ(learned({16.0, 50.0, 50.0, 50.0}), 50.0);
    EXPECT_DOUBLE_EQ(learned({16.0, 100.0, 150.0, 100.0}), 50.0) << "a slow application's periods, 2 and 3 display periods";
    EXPECT_DOUBLE_EQ(learned({16.0, 150.0, 100.0, 50.0, 200.0}), 50.0);
    EXPECT_DOUBLE_EQ(learned({11.1, 11.1, 22.2, 33.3}), 11.1);
    EXPECT_DOUBLE_EQ(learned({16.0, 100.0, 100.0}), 100.0) << "only stretched periods: the runtime never showed more";
}

TEST(DisplayPeriod, jitter_of_a_percent_keeps_the_period) {
    EXPECT_NEAR(learned({16.0, 50.3, 99.6, 150.4, 49.8, 100.5}), 50.0, 0.8);
    // A fast display under a slow application: only its multiples are ever predicted.
    EXPECT_DOUBLE_EQ(learned({16.0, 740.5, 9.0, 3.0, 7.5}), 0.5);
    // Periods that share no display period at all cannot ask for less than 10 kHz.
    EXPECT_GE(learned({16.0, 50.0, 73.01}), 0.1);
}
