#pragma once
// Summaries of measured values (benchmarks, figures in docs).
#include <vector>

namespace impasto::util {

// The middle value; with an even count the mean of the two middle values. Throws
// std::invalid_argument for no values.
double median(std::vector<double> values);

}  // namespace impasto::util
