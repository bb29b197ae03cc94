// The snap cutter's step latency on real meshes (issue 15): the 20-sample curved cut through the
// femur's shaft of tests/data/paths/femur-shaft.path, on each mesh (the femur at several
// resolutions: the same shape), every step one SnapCutSession::cut (select, snap, dissect, remove
// degeneracies, loose pieces). Not a Google
// Benchmark: the figures are the distribution of the steps (median, p99, per phase) over
// several runs of the cut on fresh copies, and their ratio between the meshes - the peer is the
// small femur, as a step must cost the same on a mesh 6 times larger.
//
//   snapcut_latency PATH [--substeps N | --rate HZ] NAME=[deformed:|local:][index:][reordered:]MESH.ele [NAME=...]
//
// The first mesh is the peer of the others. `reordered:` renumbers a mesh as `sxk convert
// --reorder` does (Cuthill-McKee vertices, elements by their lowest vertex) before it is cut:
// TetGen's numbering against a cache-friendly one (docs/performance.md "snapcut"). `index:` cuts
// it asking the spatial index along the whole blade every sweep (Options::follow_blade false)
// instead of following the blade through the elements. `deformed:` cuts the femur deformed by
// the load of tests/real/snapcut_femur.cpp (the lower end held, the upper end pushed sideways by
// 4 N; 500 CG iterations before the cut, not timed) and relaxes the whole body 20 CG iterations
// after every step; `local:` the same, relaxing only around what each step changed
// (Options::local_vertices 300, up to 200 iterations). The loads name the femur's coordinates:
// femur meshes only.
// --substeps N replays each movement of the path as N movements (handle and tip interpolated
// linearly); --rate HZ as many as a device sampling at HZ takes over the movement's time in the
// path (--rate 1000: a haptic loop's steps). A step then moves the blade a fraction of an
// element; its work follows the faces it crosses, and "per dissected face" compares the meshes
// at equal work.
//
// stdout: JSON lines (CONTRIBUTING.md "Benchmarks"); stderr: a table per mesh.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "figure_line.hpp"
#include "percentile.hpp"
#include "degeneracy_plugin.hpp"
#include "simulation.hpp"
#include "snap_cut.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/reorder_vertices.hpp"
#include "sxk/tool_path.hpp"

namespace {

using sxk::Mesh;
using sxk::Point;
using sxk::snapcut::Scalpel;

constexpr int runs = 5;

struct Figures {
    std::string name;
    std::size_t elements = 0;
    double median = 0, p99 = 0, max = 0;
    double select = 0, snap = 0, dissect = 0, degeneracy = 0, pieces = 0;  // medians, ms
    double select99 = 0, snap99 = 0, dissect99 = 0, degeneracy99 = 0, pieces99 = 0;  // p99, ms
    std::size_t cutting_steps = 0;
    double index_build = 0;  // s
    std::size_t dissected = 0;
    long long new_elements = 0;
    double searched = 0, hit = 0;  // elements searched, edges hit: means over the cutting steps
    double rounds = 0;  // selection rounds (sweeps and their repeats): mean over the cutting steps
    double per_face = 0;  // ms of cutting steps per dissected face
    double relax = 0, relax99 = 0;  // with a simulation: the relaxation's median and p99, ms
    double relax_iterations = 0;    // and its CG iterations: mean over the cutting steps
};

// The femur deformed as tests/real/snapcut_femur.cpp deforms it, relaxed 500 CG iterations.
std::unique_ptr<sxk::Simulation> deform_femur(Mesh& mesh) {
    const std::vector<std::string> loads{"--fix", "z<-0.45", "--force", "z>0.45:4,0,0", "--E", "1e6", "--nu", "0.3",
                                         "--tol", "1e-3"};
    auto made = sxk::elasticity::simulate(mesh, sxk::cli::body_options(loads).value());
    if (!made) throw std::runtime_error(made.reason());
    std::unique_ptr<sxk::Simulation> simulation = std::move(*made);
    if (auto settled = simulation->relax(500); !settled) throw std::runtime_error(settled.reason());
    return simulation;
}

Figures measure(const std::string& name, const Mesh& original, const std::vector<Scalpel>& path,
                const sxk::snapcut::Options& options, bool deformed) {
    Figures f;
    f.name = name;
    f.elements = original.element_count();
    std::vector<double> step, select, snap, dissect, degeneracy_ms, pieces, per_face, relax;
    for (int run = 0; run < runs; ++run) {
        Mesh mesh = original;
        std::unique_ptr<sxk::Simulation> simulation;
        if (deformed) simulation = deform_femur(mesh);
        const auto start = std::chrono::steady_clock::now();
        auto session = sxk::snapcut::SnapCutSession::make(mesh, options,
                                                          {sxk::degeneracy::linked_in_service(), simulation.get()})
                           .value();
        f.index_build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::size_t dissected = 0;
        const std::size_t first = step.size();
        for (const Scalpel& scalpel : path) {
            if (auto stepped = session->cut(scalpel); !stepped) throw std::runtime_error(stepped.reason());
            const auto& r = session->last_step();
            dissected += r.faces_dissected;
            if (r.edges_hit == 0) continue;  // steps that cut: the others only move the scalpel
            f.searched += double(r.elements_searched);
            f.hit += double(r.edges_hit);
            f.rounds += double(r.sweeps + r.repeats);
            step.push_back(r.seconds * 1e3);
            select.push_back(r.seconds_select * 1e3);
            snap.push_back(r.seconds_snap * 1e3);
            dissect.push_back(r.seconds_dissect * 1e3);
            degeneracy_ms.push_back(r.seconds_degeneracy * 1e3);
            pieces.push_back(r.seconds_pieces * 1e3);
            relax.push_back(r.seconds_relax * 1e3);
            f.relax_iterations += double(r.relax_iterations);
        }
        f.dissected = dissected;
        double total = 0;
        for (std::size_t i = first; i < step.size(); ++i) total += step[i];
        per_face.push_back(dissected ? total / double(dissected) : 0);
        f.new_elements = static_cast<long long>(mesh.element_count()) - static_cast<long long>(original.element_count());
        if (auto valid = mesh.validate({.orientation = true}); !valid) throw std::runtime_error(valid.reason());
    }
    f.per_face = percentile(per_face, 0.5);
    f.median = percentile(step, 0.5);
    f.p99 = percentile(step, 0.99);
    f.max = percentile(step, 1.0);
    f.select = percentile(select, 0.5);
    f.snap = percentile(snap, 0.5);
    f.dissect = percentile(dissect, 0.5);
    f.degeneracy = percentile(degeneracy_ms, 0.5);
    f.pieces = percentile(pieces, 0.5);
    f.select99 = percentile(select, 0.99);
    f.snap99 = percentile(snap, 0.99);
    f.dissect99 = percentile(dissect, 0.99);
    f.degeneracy99 = percentile(degeneracy_ms, 0.99);
    f.pieces99 = percentile(pieces, 0.99);
    f.relax = percentile(relax, 0.5);
    f.relax99 = percentile(relax, 0.99);
    f.cutting_steps = step.size() / runs;
    f.searched /= double(step.size());
    f.hit /= double(step.size());
    f.rounds /= double(step.size());
    f.relax_iterations /= double(step.size());
    std::fprintf(stderr,
                 "%s (%zu tets): %zu cutting steps, median %.3f ms, p99 %.3f, max %.3f; phases median/p99: select "
                 "%.3f/%.3f, snap %.3f/%.3f, dissect %.3f/%.3f, degeneracy %.3f/%.3f, pieces %.3f/%.3f; %zu faces "
                 "dissected, %+lld elements, %.3f ms per dissected face; per step %.0f elements searched, %.0f edges hit, "
                 "%.1f selection rounds; index %.2f s; relaxation median/p99 %.3f/%.3f ms, %.1f CG iterations\n",
                 name.c_str(), f.elements, f.cutting_steps, f.median, f.p99, f.max, f.select, f.select99, f.snap,
                 f.snap99, f.dissect, f.dissect99, f.degeneracy, f.degeneracy99, f.pieces, f.pieces99, f.dissected,
                 f.new_elements, f.per_face, f.searched, f.hit, f.rounds, f.index_build, f.relax, f.relax99,
                 f.relax_iterations);
    return f;
}

void line(const std::string& name, const char* unit, double ours, double peer, const std::string& peer_name) {
    print_figure(name, unit, ours, peer, peer_name, "lower");
}

}  // namespace

int main(int argc, char** argv) {
    const char* usage =
        "usage: snapcut_latency PATH [--substeps N | --rate HZ] NAME=[deformed:|local:][index:][reordered:]MESH.ele "
        "[NAME=...]\n";
    int first_mesh = 2;
    int substeps = 1;  // per movement
    double rate = 0;   // samples per second of the path's time column (0: by substeps)
    if (argc > 3 && std::string(argv[2]) == "--substeps") {
        substeps = std::atoi(argv[3]);
        first_mesh = 4;
    } else if (argc > 3 && std::string(argv[2]) == "--rate") {
        rate = std::atof(argv[3]);
        first_mesh = 4;
        if (!(rate > 0)) substeps = 0;
    }
    if (argc <= first_mesh || substeps < 1) {
        std::fprintf(stderr, "%s", usage);
        return 2;
    }
    try {
        const std::array<int, 1> columns{6};
        std::vector<Scalpel> samples;
        std::vector<double> times;
        for (const sxk::ToolSample& sample : sxk::read_tool_path(argv[1], columns).samples) {
            const auto& v = sample.values;
            samples.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
            times.push_back(sample.time);
        }
        std::vector<Scalpel> path{samples.front()};
        for (std::size_t i = 1; i < samples.size(); ++i) {
            const int parts = rate > 0 ? std::max(1, int(std::lround((times[i] - times[i - 1]) * rate))) : substeps;
            for (int j = 1; j <= parts; ++j)
                path.push_back(sxk::snapcut::between(samples[i - 1], samples[i], double(j) / parts));
        }
        const std::string how = rate > 0         ? " (at " + std::to_string(std::lround(rate)) + " Hz)"
                                : substeps == 1 ? ""
                                                : " (" + std::to_string(substeps) + " substeps)";
        std::vector<Figures> all;
        for (int i = first_mesh; i < argc; ++i) {
            const std::string arg = argv[i];
            const auto equals = arg.find('=');
            const std::string name = arg.substr(0, equals);
            std::string file = arg.substr(equals + 1);
            const auto prefixed = [&file](const std::string& prefix) {
                if (!file.starts_with(prefix)) return false;
                file = file.substr(prefix.size());
                return true;
            };
            sxk::snapcut::Options options;
            const bool local = prefixed("local:");
            const bool deformed = local || prefixed("deformed:");
            options.relax_iterations = local ? 200 : 20;
            options.local_vertices = local ? 300 : 0;
            options.follow_blade = !prefixed("index:");
            const bool reorder = prefixed("reordered:");
            std::fprintf(stderr, "snapcut_latency: reading %s%s%s%s\n", file.c_str(), reorder ? " (reordered)" : "",
                         options.follow_blade ? "" : " (the index every sweep)",
                         local      ? " (deformed, relaxed around each step)"
                         : deformed ? " (deformed, relaxed whole)"
                                    : "");
            Mesh mesh = sxk::read_mesh(file);
            if (reorder) mesh = sxk::renumbered(mesh, sxk::cuthill_mckee_order(mesh));
            all.push_back(measure(name, mesh, path, options, deformed));
        }
        const Figures& peer = all.front();
        for (const Figures& f : all) {
            const std::string what = "snap cut step on " + f.name + how;
            line(what + ": median", "ms", f.median, peer.median, peer.name);
            line(what + ": p99", "ms", f.p99, peer.p99, peer.name);
            line(what + ": select (median)", "ms", f.select, peer.select, peer.name);
            line(what + ": snap (median)", "ms", f.snap, peer.snap, peer.name);
            line(what + ": dissect (median)", "ms", f.dissect, peer.dissect, peer.name);
            line(what + ": degeneracy removal (median)", "ms", f.degeneracy, peer.degeneracy, peer.name);
            line(what + ": loose pieces (median)", "ms", f.pieces, peer.pieces, peer.name);
            line(what + ": loose pieces (p99)", "ms", f.pieces99, peer.pieces99, peer.name);
            line(what + ": degeneracy removal (p99)", "ms", f.degeneracy99, peer.degeneracy99, peer.name);
            if (f.relax > 0 || peer.relax > 0) {
                line(what + ": relaxation (median)", "ms", f.relax, peer.relax, peer.name);
                line(what + ": relaxation (p99)", "ms", f.relax99, peer.relax99, peer.name);
            }
            line("snap cut on " + f.name + how + ": cutting time per dissected face", "ms", f.per_face, peer.per_face,
                 peer.name);
            line("snap cut on " + f.name + how + ": new elements per dissected face", "elements",
                 f.dissected ? double(f.new_elements) / double(f.dissected) : 0, 17, "state-machine subdivision (up to)");
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "snapcut_latency: %s\n", error.what());
        return 1;
    }
    return 0;
}
