// The p-quantile of a distribution of measured times, as the latency benchmarks report them
// (median: 0.5, p99: 0.99): the smallest value with at least a fraction p of the values at or below it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

inline double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    const auto index = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size()))) - 1;
    return values[std::min(index, values.size() - 1)];
}
