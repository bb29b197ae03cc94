// The one JSON line per figure that every benchmark prints on stdout (CONTRIBUTING.md
// "Benchmarks"): {"name", "unit", "ours", "peer", "peer_name", "ratio" (ours / peer), "better"}.
#pragma once

#include <cstdio>
#include <string>

inline void print_figure(const std::string& name, const std::string& unit, double ours, double peer,
                         const std::string& peer_name, const std::string& better) {
    std::printf("{\"name\":\"%s\",\"unit\":\"%s\",\"ours\":%.6g,\"peer\":%.6g,\"peer_name\":\"%s\",\"ratio\":%.4g,"
                "\"better\":\"%s\"}\n",
                name.c_str(), unit.c_str(), ours, peer, peer_name.c_str(), peer != 0 ? ours / peer : 0.0,
                better.c_str());
    std::fflush(stdout);
}
