// Trimmed statistics of one sensor's repeated samples (paper §6: of the 600 readings at each
// location "we discarded the smallest and largest 50 values to reduce the noise", then took
// their mean and standard deviation). A trim drops the same number of samples at each end:
// a count (50) or a fraction of the samples (50/600: round(n/12) of n). Values keep the
// samples' unit.
#pragma once

#include <string>
#include <vector>

namespace ergo {

struct SampleTrim {
  enum class Kind { kCount, kFraction };
  Kind kind = Kind::kFraction;
  long count = 0;                  // kCount: samples dropped at each end
  double fraction = 50.0 / 600.0;  // kFraction: share dropped at each end, in [0, 0.5)

  // Samples dropped at each end of n.
  long DroppedPerEnd(long n) const;
  // "50 per end" or "1/12 per end (8.33 %)"-like words for reports.
  std::string Describe() const;
};

// Reads "50" (a count per end: digits only), "0.0833" (a fraction per end, below 0.5) or
// "50/600" (50 of every 600: the fraction 1/12). false with *error saying why otherwise.
bool ParseSampleTrim(const std::string& text, SampleTrim* trim, std::string* error);

struct TrimmedStatistics {
  double mean = 0;
  double standard_deviation = 0;  // of the kept samples (n − 1 in the denominator; 0 for one)
  long kept = 0;
  long dropped_per_end = 0;
};

// The statistics of `samples` after the trim. false (and *statistics untouched) when no
// sample would remain.
bool ComputeTrimmedStatistics(std::vector<double> samples, const SampleTrim& trim,
                              TrimmedStatistics* statistics);

}  // namespace ergo
