// What `sxk needle` prints: the replay's steps as a table or one JSON object (docs/cli.md).
#pragma once

#include <cstddef>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "needle.hpp"

namespace sxk::needle {

struct ReplayStep {
    double time = 0;
    std::size_t line = 0;
    NeedleStepReport report;
};

struct Replay {
    std::size_t start_bisections = 0;  // --h-start
    bool geometry_only = false;
    std::vector<ReplayStep> steps;
    std::size_t undone = 0;
    std::size_t elements_before = 0, vertices_before = 0, elements_after = 0, vertices_after = 0;
};

nlohmann::ordered_json to_json(const Options& options);
nlohmann::ordered_json to_json(const Replay& replay);
void print_replay(std::ostream& out, const Replay& replay);

}  // namespace sxk::needle
