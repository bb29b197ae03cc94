// The range checks of the plug-ins' option structs (their check(), sxk/plugins/NAME.hpp): one
// message for one kind of mistake, with the struct's field name, so that an application's
// options and a command's words fail alike ("snapcut: aspect_ratio 2 is not in (0, 1)").
#pragma once

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "sxk/outcome.hpp"

namespace sxk::option_checks {

// An interval of the reals; `open_low` / `open_high`: the end is excluded.
struct Interval {
    double low = 0, high = 0;
    bool open_low = false, open_high = false;

    bool contains(double x) const {
        return (open_low ? x > low : x >= low) && (open_high ? x < high : x <= high);
    }
};

inline std::string number_text(double x) {
    std::ostringstream text;
    text << x;
    return text.str();
}

// "(0, 1)", "[0, 1e+300]": `low_text` / `high_text` replace the numbers where a name reads
// better ("pi/2").
inline std::string interval_text(const Interval& interval, std::string_view low_text = {},
                                 std::string_view high_text = {}) {
    return std::string(interval.open_low ? "(" : "[") +
           (low_text.empty() ? number_text(interval.low) : std::string(low_text)) + ", " +
           (high_text.empty() ? number_text(interval.high) : std::string(high_text)) +
           (interval.open_high ? ")" : "]");
}

// bad_argument "TOOL: FIELD X is not in I" unless x is in `interval` (NaN never is).
inline std::optional<Refusal> in(std::string_view tool, std::string_view field, double x, const Interval& interval,
                                 std::string_view low_text = {}, std::string_view high_text = {}) {
    if (interval.contains(x)) return std::nullopt;
    return Refusal{RefusalCode::bad_argument, std::string(tool) + ": " + std::string(field) + " " + number_text(x) +
                                                  " is not in " + interval_text(interval, low_text, high_text)};
}

// The same for a count.
inline std::optional<Refusal> in(std::string_view tool, std::string_view field, std::size_t n, std::size_t low,
                                 std::size_t high) {
    if (n >= low && n <= high) return std::nullopt;
    return Refusal{RefusalCode::bad_argument, std::string(tool) + ": " + std::string(field) + " " + std::to_string(n) +
                                                  " is not in [" + std::to_string(low) + ", " + std::to_string(high) +
                                                  "]"};
}

// The first refusal of a list of checks, as check() returns it: Done when every check passed.
inline Outcome<Done> first_refusal(std::initializer_list<std::optional<Refusal>> checks) {
    for (const std::optional<Refusal>& refused : checks)
        if (refused) return *refused;
    return Done{};
}

}  // namespace sxk::option_checks
