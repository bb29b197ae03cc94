// Reading and writing mesh files (issue 12): sxk::read_mesh / write_mesh in every text format,
// against TetGen's own load of the same .node/.ele/.face.
//
//   io [google-benchmark flags] [--tetgen=PATH] DIR NAME=MESH.ele
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
// Counters: MB_per_s (bytes of the files read or written per second of wall time), tets.
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
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

void tetgen_load(benchmark::State& state, const Input* input, const std::string* program) {
    fs::path stem = input->ele;
    stem.replace_extension();  // X.1
    for (auto _ : state) {
        const pid_t child = fork();
        if (child == 0) {
            // in the mesh's folder: TetGen would write there if -NEF did not stop it
            if (chdir(stem.parent_path().c_str()) != 0)
                _exit(127);
            std::freopen("/dev/null", "w", stdout);
            const std::string base = stem.filename().string();
            execl(program->c_str(), program->c_str(), "-rNEFQ", base.c_str(),
                  static_cast<char*>(nullptr));
            _exit(127);
        }
        int status = 0;
        rusage usage{};
        if (child < 0 || wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) ||
            WEXITSTATUS(status) != 0) {
            state.SkipWithError("tetgen -rNEFQ failed");
            break;
        }
        auto seconds = [](const timeval& t) {
            return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
        };
        state.SetIterationTime(seconds(usage.ru_utime) + seconds(usage.ru_stime));
    }
    state.counters["MB_per_s"] =
        benchmark::Counter(static_cast<double>(bytes_read(input->ele)) / 1e6,
                           benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tets"] = static_cast<double>(input->tets);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::string tetgen_program;
    std::vector<std::string> arguments;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.rfind("--tetgen=", 0) == 0)
            tetgen_program = argument.substr(9);
        else
            arguments.push_back(argument);
    }
    const auto equals = arguments.size() == 2 ? arguments[1].find('=') : std::string::npos;
    if (equals == std::string::npos || equals == 0) {
        std::fprintf(stderr, "usage: io [--benchmark_...] [--tetgen=PATH] DIR NAME=MESH.ele\n");
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
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
