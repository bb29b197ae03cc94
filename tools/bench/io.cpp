// Reading and writing mesh files (issue 12): sxk::read_mesh / write_mesh in every text format,
// against TetGen's own load of the same .node/.ele/.face.
//
//   io [google-benchmark flags] [--tetgen=PATH] [--sxk=PATH] [--former-sxk=PATH] DIR NAME=MESH.ele
//
// Setup (untimed): MESH.ele is read once and written into DIR as NAME.mesh (Medit),
// NAME-22.msh and NAME-41.msh (Gmsh 2.2 / 4.1), NAME.off and NAME.obj (its boundary surface:
// those formats hold triangles); files already in DIR are kept, so a second build of this
// program (tools/bench/run builds it again on the former library, see there) reads the very same
// bytes. Only the public API is used, for the same reason.
//
// Benchmarks, wall time (the reader runs parallel loops on TBB's threads, so the time a caller
// waits is the figure), with the CPU time of the whole process beside it (user + system of all
// threads; loading the file is part of both):
//   read/FORMAT/NAME    read_mesh(file): load, parse, build_mesh (every check, assign_elements)
//   write/FORMAT/NAME   write_mesh(mesh, DIR/out/...): format the text and write the file
//   tetgen/NAME         `tetgen -rNEFQ NAME` (with --tetgen): TetGen reads the .node/.ele/.face
//                       and rebuilds its mesh (-r), writes nothing (-NEF), quietly (-Q). Debian
//                       ships only the tetgen program, no library, so this is the child process'
//                       user + system time from wait4 (manual time), process start included.
//   sxk_info/NAME       `sxk info MESH.ele` (with --sxk), the command issue 12 timed ("3.5 s of
//   sxk_info_former/NAME  CPU"): read, components, labels; with --former-sxk the same command
//                       built on the former library. Wall time of the child process (manual time),
//                       its user + system time as the counter cpu_s.
// Counters: MB_per_s (bytes of the files read or written per second of wall time), tets.
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace {

namespace fs = std::filesystem;

struct Format {
    const char* name;  // in the benchmark name
    const char* file;  // NAME + this
    int gmsh_version;
};
constexpr Format formats[] = {{"tetgen", ".1.ele", 0},   {"medit", ".mesh", 0},
                              {"gmsh22", "-22.msh", 22}, {"gmsh41", "-41.msh", 41},
                              {"off", ".off", 0},        {"obj", ".obj", 0}};

struct Input {
    std::string name;
    fs::path dir;
    fs::path ele;  // the TetGen mesh
    std::optional<sxk::Mesh> mesh;
    std::size_t tets = 0;
};

// The files a read of `path` loads (TetGen: .node, .ele and .face).
std::size_t bytes_read(const fs::path& path) {
    if (path.extension() != ".ele")
        return fs::file_size(path);
    std::size_t bytes = 0;
    for (const char* extension : {".node", ".ele", ".face"}) {
        fs::path part = path;
        part.replace_extension(extension);
        if (fs::exists(part))
            bytes += fs::file_size(part);
    }
    return bytes;
}

fs::path file_of(const Input& input, const Format& format) {
    if (std::string(format.name) == "tetgen")
        return input.ele;
    return input.dir / (input.name + format.file);
}

void read_file(benchmark::State& state, const Input* input, const Format* format) {
    const fs::path path = file_of(*input, *format);
    std::size_t elements = 0;
    for (auto _ : state) {
        sxk::Mesh mesh = sxk::read_mesh(path);
        elements = mesh.element_count();
        benchmark::DoNotOptimize(mesh);
    }
    state.counters["MB_per_s"] = benchmark::Counter(static_cast<double>(bytes_read(path)) / 1e6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
    state.counters["elements"] = static_cast<double>(elements);
    state.counters["tets"] = static_cast<double>(input->tets);
}

void write_file(benchmark::State& state, const Input* input, const Format* format) {
    const fs::path out_dir = input->dir / "out";
    fs::create_directories(out_dir);
    const fs::path path = out_dir / (input->name + format->file);
    sxk::WriteOptions options;
    if (format->gmsh_version != 0)
        options.gmsh_version = format->gmsh_version;
    for (auto _ : state)
        sxk::write_mesh(*input->mesh, path, options);
    state.counters["MB_per_s"] = benchmark::Counter(static_cast<double>(bytes_read(path)) / 1e6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tets"] = static_cast<double>(input->tets);
}

// What a child process cost: its wall time and its user + system time (wait4).
struct ChildTimes {
    double wall = 0;
    double cpu = 0;
};

// Runs `arguments` (arguments[0] the program) in `dir` with stdout to /dev/null; nullopt when
// it could not start or did not exit 0.
std::optional<ChildTimes> run_child(const std::vector<std::string>& arguments, const fs::path& dir) {
    std::vector<char*> argv;
    for (const std::string& argument : arguments)
        argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = fork();
    if (child == 0) {
        if (chdir(dir.c_str()) != 0)
            _exit(127);
        std::freopen("/dev/null", "w", stdout);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    if (child < 0 || wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0)
        return std::nullopt;
    auto seconds = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
    };
    return ChildTimes{std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                      seconds(usage.ru_utime) + seconds(usage.ru_stime)};
}

void tetgen_load(benchmark::State& state, const Input* input, const std::string* program) {
    fs::path stem = input->ele;
    stem.replace_extension();  // X.1
    // in the mesh's folder: TetGen would write there if -NEF did not stop it
    const std::vector<std::string> command = {*program, "-rNEFQ", stem.filename().string()};
    for (auto _ : state) {
        const std::optional<ChildTimes> times = run_child(command, stem.parent_path());
        if (!times) {
            state.SkipWithError("tetgen -rNEFQ failed");
            break;
        }
        state.SetIterationTime(times->cpu);
    }
    state.counters["MB_per_s"] =
        benchmark::Counter(static_cast<double>(bytes_read(input->ele)) / 1e6,
                           benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tets"] = static_cast<double>(input->tets);
}

// `PROGRAM info MESH.ele`, the command the issue timed: wall time as the iteration time, the
// process' user + system time as the counter cpu_s.
void sxk_info(benchmark::State& state, const Input* input, const std::string* program) {
    const std::vector<std::string> command = {*program, "info", fs::absolute(input->ele).string()};
    double cpu = 0;
    for (auto _ : state) {
        const std::optional<ChildTimes> times = run_child(command, input->dir);
        if (!times) {
            state.SkipWithError((*program + " info failed").c_str());
            break;
        }
        state.SetIterationTime(times->wall);
        cpu += times->cpu;
    }
    state.counters["cpu_s"] = benchmark::Counter(cpu, benchmark::Counter::kAvgIterations);
    state.counters["tets"] = static_cast<double>(input->tets);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::string tetgen_program, sxk_program, former_sxk_program;
    // by hand rather than with parse_option.hpp: this file is also built on the former library
    // (tools/bench/run), whose tree has no string options there
    const std::pair<std::string, std::string*> options[] = {
        {"--tetgen=", &tetgen_program}, {"--sxk=", &sxk_program}, {"--former-sxk=", &former_sxk_program}};
    std::vector<std::string> arguments;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        bool known = false;
        for (const auto& [prefix, value] : options)
            if (!known && argument.rfind(prefix, 0) == 0) {
                *value = argument.substr(prefix.size());
                known = true;
            }
        if (!known)
            arguments.push_back(argument);
    }
    const auto equals = arguments.size() == 2 ? arguments[1].find('=') : std::string::npos;
    if (equals == std::string::npos || equals == 0) {
        std::fprintf(stderr, "usage: io [--benchmark_...] [--tetgen=PATH] [--sxk=PATH] [--former-sxk=PATH] DIR NAME=MESH.ele\n");
        return 2;
    }
    Input input;
    input.dir = arguments[0];
    input.name = arguments[1].substr(0, equals);
    input.ele = arguments[1].substr(equals + 1);
    try {
        fs::create_directories(input.dir);
        input.mesh = sxk::read_mesh(input.ele);
        input.tets = input.mesh->element_count();
        for (const Format& format : formats) {
            const fs::path path = file_of(input, format);
            if (fs::exists(path))
                continue;
            sxk::WriteOptions options;
            if (format.gmsh_version != 0)
                options.gmsh_version = format.gmsh_version;
            sxk::write_mesh(*input.mesh, path, options);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "io: %s\n", error.what());
        return 2;
    }
    for (const Format& format : formats) {
        benchmark::RegisterBenchmark(
            (std::string("read/") + format.name + "/" + input.name).c_str(), read_file, &input,
            &format)
            ->UseRealTime()
            ->MeasureProcessCPUTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(
            (std::string("write/") + format.name + "/" + input.name).c_str(), write_file, &input,
            &format)
            ->UseRealTime()
            ->MeasureProcessCPUTime()
            ->Unit(benchmark::kMillisecond);
    }
    if (!tetgen_program.empty())
        benchmark::RegisterBenchmark(("tetgen/" + input.name).c_str(), tetgen_load, &input,
                                     &tetgen_program)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    for (const auto& [prefix, program] : {std::pair{"sxk_info/", &sxk_program},
                                          std::pair{"sxk_info_former/", &former_sxk_program}})
        if (!program->empty())
            benchmark::RegisterBenchmark((prefix + input.name).c_str(), sxk_info, &input, program)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
