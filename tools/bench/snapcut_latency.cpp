// The snap cutter's step latency on real meshes (issue 15): a 20-sample curved cut through the
// femur's shaft, the same path relative to the bounding box on each mesh, every step one
// SnapCutSession::cut (select, snap, dissect, remove degeneracies, loose pieces). Not a Google
// Benchmark: the figures are the distribution of the steps (median, p99, per phase) over
// several runs of the cut on fresh copies, and their ratio between the meshes - the peer is the
// small femur, as a step must cost the same on a mesh 6 times larger.
//
//   snapcut_latency NAME=MESH.ele [NAME=MESH.ele ...]     the first is the peer of the others
//
// stdout: JSON lines (CONTRIBUTING.md "Benchmarks"); stderr: a table per mesh.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "degeneracy_plugin.hpp"
#include "snap_cut.hpp"
#include "sxk/io.hpp"
#include "sxk/plugin_host.hpp"

namespace {

using sxk::Mesh;
using sxk::Point;
using sxk::snapcut::Scalpel;

constexpr int runs = 5;

const sxk::degeneracy::DegeneracyService* degeneracy() {
    static sxk::PluginHost host = [] {
        sxk::PluginHost h;
        h.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy");
        return h;
    }();
    return host.service<sxk::degeneracy::DegeneracyService>().value();
}

struct Box {
    Point low{}, high{};
};

Box box_of(const Mesh& mesh) {
    Box box{mesh.reference(0), mesh.reference(0)};
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (std::size_t k = 0; k < 3; ++k) {
            box.low[k] = std::min(box.low[k], mesh.reference(v)[k]);
            box.high[k] = std::max(box.high[k], mesh.reference(v)[k]);
        }
    return box;
}

// The femur stands along z. The blade lies across the shaft (along y, longer than the bone is
// wide) a little above mid-height, and sweeps through it along x in 19 movements, rising and
// turning a little as it goes: a curved cut through the whole shaft.
std::vector<Scalpel> shaft_cut(const Box& box) {
    const Point size{box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2]};
    const Point centre{(box.low[0] + box.high[0]) / 2, (box.low[1] + box.high[1]) / 2,
                       (box.low[2] + box.high[2]) / 2};
    std::vector<Scalpel> path;
    for (int i = 0; i < 20; ++i) {
        const double s = i / 19.0;
        const double x = centre[0] + (s - 0.5) * 1.4 * size[0];
        const double z = centre[2] + 0.02 * size[2] + 0.03 * size[2] * std::sin(3.0 * s);
        const double turn = 0.2 * (s - 0.5);  // radians, about z
        const double half = 0.8 * size[1];
        Scalpel scalpel;
        scalpel.tip = {x - half * std::sin(turn), centre[1] - half * std::cos(turn), z - 0.01 * size[2]};
        scalpel.handle = {x + half * std::sin(turn), centre[1] + half * std::cos(turn), z + 0.01 * size[2]};
        path.push_back(scalpel);
    }
    return path;
}

double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    const auto index = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size()))) - 1;
    return values[std::min(index, values.size() - 1)];
}

struct Figures {
    std::string name;
    std::size_t elements = 0;
    double median = 0, p99 = 0, max = 0;
    double select = 0, snap = 0, dissect = 0, degeneracy = 0, pieces = 0;  // medians, ms
    double index_build = 0;  // s
    std::size_t dissected = 0;
    long long new_elements = 0;
};

Figures measure(const std::string& name, const Mesh& original) {
    Figures f;
    f.name = name;
    f.elements = original.element_count();
    const std::vector<Scalpel> path = shaft_cut(box_of(original));
    std::vector<double> step, select, snap, dissect, degeneracy_ms, pieces;
    for (int run = 0; run < runs; ++run) {
        Mesh mesh = original;
        const auto start = std::chrono::steady_clock::now();
        auto session = sxk::snapcut::SnapCutSession::make(mesh, {}, {degeneracy(), nullptr}).value();
        f.index_build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::size_t dissected = 0;
        for (const Scalpel& scalpel : path) {
            if (auto stepped = session->cut(scalpel); !stepped) throw std::runtime_error(stepped.reason());
            const auto& r = session->last_step();
            dissected += r.faces_dissected;
            if (r.sweeps == 0) continue;  // the first pose only places the scalpel
            step.push_back(r.seconds * 1e3);
            select.push_back(r.seconds_select * 1e3);
            snap.push_back(r.seconds_snap * 1e3);
            dissect.push_back(r.seconds_dissect * 1e3);
            degeneracy_ms.push_back(r.seconds_degeneracy * 1e3);
            pieces.push_back(r.seconds_pieces * 1e3);
        }
        f.dissected = dissected;
        f.new_elements = static_cast<long long>(mesh.element_count()) - static_cast<long long>(original.element_count());
        if (auto valid = mesh.validate({.orientation = true}); !valid) throw std::runtime_error(valid.reason());
    }
    f.median = percentile(step, 0.5);
    f.p99 = percentile(step, 0.99);
    f.max = percentile(step, 1.0);
    f.select = percentile(select, 0.5);
    f.snap = percentile(snap, 0.5);
    f.dissect = percentile(dissect, 0.5);
    f.degeneracy = percentile(degeneracy_ms, 0.5);
    f.pieces = percentile(pieces, 0.5);
    std::fprintf(stderr,
                 "%s (%zu tets): step median %.3f ms, p99 %.3f, max %.3f; phases (medians) select %.3f, snap %.3f, "
                 "dissect %.3f, degeneracy %.3f, pieces %.3f; %zu faces dissected, %+lld elements; index %.2f s\n",
                 name.c_str(), f.elements, f.median, f.p99, f.max, f.select, f.snap, f.dissect, f.degeneracy,
                 f.pieces, f.dissected, f.new_elements, f.index_build);
    return f;
}

void line(const std::string& name, const char* unit, double ours, double peer, const std::string& peer_name) {
    std::printf("{\"name\":\"%s\",\"unit\":\"%s\",\"ours\":%.6g,\"peer\":%.6g,\"peer_name\":\"%s\",\"ratio\":%.4g,"
                "\"better\":\"lower\"}\n",
                name.c_str(), unit, ours, peer, peer_name.c_str(), peer != 0 ? ours / peer : 0.0);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: snapcut_latency NAME=MESH.ele [NAME=MESH.ele ...]\n");
        return 2;
    }
    try {
        std::vector<Figures> all;
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            const auto equals = arg.find('=');
            const std::string name = arg.substr(0, equals), file = arg.substr(equals + 1);
            std::fprintf(stderr, "snapcut_latency: reading %s\n", file.c_str());
            const Mesh mesh = sxk::read_mesh(file);
            all.push_back(measure(name, mesh));
        }
        const Figures& peer = all.front();
        for (const Figures& f : all) {
            const std::string what = "snap cut step on " + f.name;
            line(what + ": median", "ms", f.median, peer.median, peer.name);
            line(what + ": p99", "ms", f.p99, peer.p99, peer.name);
            line(what + ": select (median)", "ms", f.select, peer.select, peer.name);
            line(what + ": snap (median)", "ms", f.snap, peer.snap, peer.name);
            line(what + ": dissect (median)", "ms", f.dissect, peer.dissect, peer.name);
            line(what + ": degeneracy removal (median)", "ms", f.degeneracy, peer.degeneracy, peer.name);
            line(what + ": loose pieces (median)", "ms", f.pieces, peer.pieces, peer.name);
            line("snap cut on " + f.name + ": new elements per dissected face", "elements",
                 f.dissected ? double(f.new_elements) / double(f.dissected) : 0, 17, "state-machine subdivision (up to)");
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "snapcut_latency: %s\n", error.what());
        return 1;
    }
    return 0;
}
