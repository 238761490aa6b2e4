// The paper's trim (the lowest and highest 50 of 600 samples dropped) as a count and as a
// fraction, its parser, and the statistics of what remains.
#include "ergo/ergonomics/trimmed_statistics.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace ergo {
namespace {

// 500 readings of 10 ± 1 with 50 spikes at 1000 and 50 drops to −1000, shuffled: the
// paper's trim removes exactly the spikes, and the mean is that of the 500.
TEST(ErgonomicsTrim, PaperTrimRemovesFiftySpikesAtEachEnd) {
  std::vector<double> samples;
  double clean_sum = 0;
  for (int i = 0; i < 500; ++i) {
    const double value = 10 + std::sin(i);  // in [9, 11]
    samples.push_back(value);
    clean_sum += value;
  }
  for (int i = 0; i < 50; ++i) {
    samples.push_back(1000);
    samples.push_back(-1000);
  }
  std::shuffle(samples.begin(), samples.end(), std::mt19937(4));
  for (const char* text : {"50", "50/600", "0.083333333"}) {
    SCOPED_TRACE(text);
    SampleTrim trim;
    std::string error;
    ASSERT_TRUE(ParseSampleTrim(text, &trim, &error)) << error;
    TrimmedStatistics statistics;
    ASSERT_TRUE(ComputeTrimmedStatistics(samples, trim, &statistics));
    EXPECT_EQ(statistics.dropped_per_end, 50);
    EXPECT_EQ(statistics.kept, 500);
    EXPECT_NEAR(statistics.mean, clean_sum / 500, 1e-12);
    EXPECT_LT(statistics.standard_deviation, 1.0);
  }
  // The default is the paper's, as a fraction.
  TrimmedStatistics statistics;
  ASSERT_TRUE(ComputeTrimmedStatistics(samples, SampleTrim(), &statistics));
  EXPECT_EQ(statistics.dropped_per_end, 50);
}

TEST(ErgonomicsTrim, FractionScalesWithTheSampleCountAndCountDoesNot) {
  SampleTrim fraction;  // 50/600
  EXPECT_EQ(fraction.DroppedPerEnd(600), 50);
  EXPECT_EQ(fraction.DroppedPerEnd(300), 25);
  EXPECT_EQ(fraction.DroppedPerEnd(12), 1);
  EXPECT_EQ(fraction.DroppedPerEnd(5), 0);
  SampleTrim count;
  count.kind = SampleTrim::Kind::kCount;
  count.count = 50;
  EXPECT_EQ(count.DroppedPerEnd(300), 50);
  // 100 samples and 50 per end leave nothing: refused, not a mean of nothing.
  TrimmedStatistics statistics;
  EXPECT_FALSE(ComputeTrimmedStatistics(std::vector<double>(100, 1.0), count, &statistics));
  EXPECT_FALSE(ComputeTrimmedStatistics({}, fraction, &statistics));
}

TEST(ErgonomicsTrim, StandardDeviationOfTheKeptSamples) {
  SampleTrim none;
  none.kind = SampleTrim::Kind::kCount;
  none.count = 0;
  TrimmedStatistics statistics;
  ASSERT_TRUE(ComputeTrimmedStatistics({2, 4, 4, 4, 5, 5, 7, 9}, none, &statistics));
  EXPECT_DOUBLE_EQ(statistics.mean, 5);
  EXPECT_NEAR(statistics.standard_deviation, std::sqrt(32.0 / 7), 1e-12);
  ASSERT_TRUE(ComputeTrimmedStatistics({3}, none, &statistics));
  EXPECT_EQ(statistics.standard_deviation, 0);
}

TEST(ErgonomicsTrim, ParserRefusesWhatIsNotATrim) {
  for (const char* text : {"", "-1", "0.5", "0.7", "abc", "60/100", "1/0", "5/x", "1e400"}) {
    SCOPED_TRACE(text);
    SampleTrim trim;
    std::string error;
    EXPECT_FALSE(ParseSampleTrim(text, &trim, &error));
    EXPECT_NE(error.find("50/600"), std::string::npos) << error;  // the message shows the forms
  }
  SampleTrim trim;
  std::string error;
  ASSERT_TRUE(ParseSampleTrim("0", &trim, &error));
  EXPECT_EQ(trim.kind, SampleTrim::Kind::kCount);
  EXPECT_EQ(trim.DroppedPerEnd(10), 0);
  ASSERT_TRUE(ParseSampleTrim("0.1", &trim, &error));
  EXPECT_EQ(trim.kind, SampleTrim::Kind::kFraction);
  EXPECT_EQ(trim.DroppedPerEnd(600), 60);
}

}  // namespace
}  // namespace ergo
