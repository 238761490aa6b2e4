#include "ergo/ergonomics/trimmed_statistics.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

bool AllDigits(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
}

}  // namespace

long SampleTrim::DroppedPerEnd(long n) const {
  if (kind == Kind::kCount) return count;
  return std::lround(fraction * static_cast<double>(n));
}

std::string SampleTrim::Describe() const {
  std::ostringstream out;
  if (kind == Kind::kCount) {
    out << count << " per end";
  } else {
    out << fraction * 100 << " % per end";
  }
  return out.str();
}

bool ParseSampleTrim(const std::string& text, SampleTrim* trim, std::string* error) {
  const std::string usage =
      "write a count per end (50), a fraction per end below 0.5 (0.0833) or K/N (50/600)";
  const size_t slash = text.find('/');
  if (slash != std::string::npos) {
    const std::string kept = text.substr(0, slash), of = text.substr(slash + 1);
    int64_t k = 0, n = 0;
    if (!AllDigits(kept) || !AllDigits(of) || !ParseInt64(kept, &k) || !ParseInt64(of, &n) ||
        n <= 0) {
      *error = "'" + text + "' is not K/N with whole numbers K >= 0, N > 0: " + usage;
      return false;
    }
    if (2 * k >= n) {
      *error = "'" + text + "' drops every sample (2K >= N): " + usage;
      return false;
    }
    trim->kind = SampleTrim::Kind::kFraction;
    trim->fraction = static_cast<double>(k) / static_cast<double>(n);
    return true;
  }
  if (AllDigits(text)) {
    int64_t count = 0;
    if (!ParseInt64(text, &count) || count > 1000000000) {
      *error = "'" + text + "' is too large: " + usage;
      return false;
    }
    trim->kind = SampleTrim::Kind::kCount;
    trim->count = static_cast<long>(count);
    return true;
  }
  double fraction = 0;
  if (!ParseDouble(text, &fraction) || !std::isfinite(fraction)) {
    *error = "'" + text + "' is not a number: " + usage;
    return false;
  }
  if (fraction < 0 || fraction >= 0.5) {
    *error = "'" + text + "' is not a fraction in [0, 0.5): " + usage;
    return false;
  }
  trim->kind = SampleTrim::Kind::kFraction;
  trim->fraction = fraction;
  return true;
}

bool ComputeTrimmedStatistics(std::vector<double> samples, const SampleTrim& trim,
                              TrimmedStatistics* statistics) {
  const long n = static_cast<long>(samples.size());
  const long drop = trim.DroppedPerEnd(n);
  if (n == 0 || drop < 0 || 2 * drop >= n) return false;
  std::sort(samples.begin(), samples.end());
  const long kept = n - 2 * drop;
  double sum = 0;
  for (long i = drop; i < n - drop; ++i) sum += samples[static_cast<size_t>(i)];
  const double mean = sum / static_cast<double>(kept);
  double squares = 0;
  for (long i = drop; i < n - drop; ++i) {
    const double d = samples[static_cast<size_t>(i)] - mean;
    squares += d * d;
  }
  statistics->mean = mean;
  statistics->standard_deviation =
      kept > 1 ? std::sqrt(squares / static_cast<double>(kept - 1)) : 0.0;
  statistics->kept = kept;
  statistics->dropped_per_end = drop;
  return true;
}

}  // namespace ergo
