// Reading and writing every format and encoding (issue 47), against the peers our users open the
// same files with: meshio 5 and VTK 9 (Debian's python3-meshio and python3-vtk9), in the same run.
//
//   formats [--python=/usr/bin/python3] [--repetitions=N] DIR NAME=MESH.ele
//
// MESH.ele is read once; for each target (format and encoding) the mesh is written into DIR
// once untimed, then, each the median of N runs (default 3):
//   formats/write/TARGET/NAME   sxk::write_mesh            against meshio.write of the same mesh
//                                                          into the same format and encoding
//   formats/read/TARGET/NAME    sxk::read_mesh (load, parse, build_mesh's checks and
//                               connectivity)              against meshio.read (arrays only)
//   formats/read_vtk/TARGET/NAME  the same read            against VTK's reader of the format
//                               (vtkXMLUnstructuredGridReader, vtkUnstructuredGridReader,
//                               vtkSTLReader, vtkPLYReader: VTK's data set, no connectivity)
//   formats/size/TARGET/NAME    bytes of our file          against meshio's file
// The peers run in one Python child process per figure; it prints its median in seconds (meshio
// and VTK are Python-only here). A peer that cannot handle a target is left out with a note on
// stderr.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "figure_line.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace {

namespace fs = std::filesystem;

struct Target {
    const char* name;       // in the figure's name
    const char* extension;  // of the file
    sxk::Encoding encoding;
    int gmsh_version;
    const char* meshio_options;  // keyword arguments of meshio.write for the same encoding
    const char* vtk_reader;      // VTK's reader class, or nullptr
};

constexpr Target targets[] = {
    {"vtu-zlib", ".vtu", sxk::Encoding::standard, 41, "binary=True, compression='zlib'",
     "vtkXMLUnstructuredGridReader"},
    {"vtu-raw", ".vtu", sxk::Encoding::binary, 41, "binary=True, compression=None", "vtkXMLUnstructuredGridReader"},
    {"vtu-ascii", ".vtu", sxk::Encoding::ascii, 41, "binary=False", "vtkXMLUnstructuredGridReader"},
    {"vtk-ascii", ".vtk", sxk::Encoding::ascii, 41, "binary=False", "vtkUnstructuredGridReader"},
    {"vtk-binary", ".vtk", sxk::Encoding::binary, 41, "binary=True", "vtkUnstructuredGridReader"},
    {"msh41-ascii", ".msh", sxk::Encoding::ascii, 41, "file_format='gmsh', binary=False", nullptr},
    {"msh41-binary", ".msh", sxk::Encoding::binary, 41, "file_format='gmsh', binary=True", nullptr},
    {"msh22-ascii", ".msh", sxk::Encoding::ascii, 22, "file_format='gmsh22', binary=False", nullptr},
    {"msh22-binary", ".msh", sxk::Encoding::binary, 22, "file_format='gmsh22', binary=True", nullptr},
    {"stl-binary", ".stl", sxk::Encoding::binary, 41, "binary=True", "vtkSTLReader"},
    {"ply-binary", ".ply", sxk::Encoding::binary, 41, "binary=True", "vtkPLYReader"},
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class F>
double median_seconds(int repetitions, F&& run) {
    std::vector<double> times;
    for (int i = 0; i < repetitions; ++i) {
        const auto start = std::chrono::steady_clock::now();
        run();
        times.push_back(seconds_since(start));
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

// Runs a Python script that prints one number; nullopt when it failed.
std::optional<double> python_figure(const std::string& python, const std::string& script) {
    const fs::path file = fs::temp_directory_path() / "sxk-bench-formats.py";
    {
        std::FILE* out = std::fopen(file.c_str(), "w");
        if (!out)
            return std::nullopt;
        std::fputs(script.c_str(), out);
        std::fclose(out);
    }
    std::FILE* pipe = popen((python + " " + file.string() + " 2>&1").c_str(), "r");
    if (!pipe)
        return std::nullopt;
    std::string text;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe))
        text += buffer;
    if (pclose(pipe) != 0) {
        std::cerr << "formats: peer failed: " << text.substr(0, 400) << '\n';
        return std::nullopt;
    }
    try {
        return std::stod(text.substr(text.find_last_of('\n', text.size() - 2) + 1));
    } catch (const std::exception&) {
        std::cerr << "formats: peer printed no number: " << text.substr(0, 400) << '\n';
        return std::nullopt;
    }
}

std::string timed_python(const std::string& setup, const std::string& body, int repetitions) {
    return "import time\n" + setup + "\ntimes = []\nfor _ in range(" + std::to_string(repetitions) +
           "):\n    start = time.perf_counter()\n    " + body +
           "\n    times.append(time.perf_counter() - start)\nprint(sorted(times)[len(times) // 2])\n";
}

}  // namespace

int main(int argc, char** argv) {
    std::string python = "/usr/bin/python3";
    int repetitions = 3;
    std::vector<std::string> arguments;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.rfind("--python=", 0) == 0)
            python = argument.substr(9);
        else if (argument.rfind("--repetitions=", 0) == 0)
            repetitions = std::max(1, std::stoi(argument.substr(14)));
        else
            arguments.push_back(argument);
    }
    if (arguments.size() != 2 || arguments[1].find('=') == std::string::npos) {
        std::cerr << "usage: formats [--python=P] [--repetitions=N] DIR NAME=MESH.ele\n";
        return 2;
    }
    const fs::path dir = arguments[0];
    const std::string name = arguments[1].substr(0, arguments[1].find('='));
    const fs::path ele = arguments[1].substr(arguments[1].find('=') + 1);
    fs::create_directories(dir);
    const sxk::Mesh mesh = sxk::read_mesh(ele);
    std::cerr << "formats: " << name << ": " << mesh.vertex_count() << " vertices, " << mesh.element_count()
              << " elements\n";

    for (const Target& target : targets) {
        const std::string figure = std::string(target.name) + "/" + name;
        const fs::path ours = dir / (name + "-" + target.name + target.extension);
        const fs::path theirs = dir / (name + "-" + target.name + "-meshio" + target.extension);
        sxk::WriteOptions options;
        options.encoding = target.encoding;
        options.gmsh_version = target.gmsh_version;
        sxk::write_mesh(mesh, ours, options);

        const double write = median_seconds(repetitions, [&] { sxk::write_mesh(mesh, ours, options); });
        const std::string load_ours = "import meshio\nmesh = meshio.read('" + ours.string() + "')";
        const auto meshio_write = python_figure(
            python, timed_python(load_ours, "meshio.write('" + theirs.string() + "', mesh, " +
                                                std::string(target.meshio_options) + ")",
                                 repetitions));
        if (meshio_write)
            print_figure("formats/write/" + figure, "s", write, *meshio_write, "meshio.write", "lower");
        if (meshio_write && fs::exists(theirs))
            print_figure("formats/size/" + figure, "bytes", static_cast<double>(fs::file_size(ours)),
                         static_cast<double>(fs::file_size(theirs)), "meshio's file", "lower");

        std::size_t elements = 0;
        const double read = median_seconds(repetitions, [&] { elements = sxk::read_mesh(ours).element_count(); });
        const auto meshio_read = python_figure(
            python, timed_python("import meshio", "meshio.read('" + ours.string() + "')", repetitions));
        if (meshio_read)
            print_figure("formats/read/" + figure, "s", read, *meshio_read, "meshio.read", "lower");
        if (target.vtk_reader) {
            const std::string setup = "import vtk";
            const std::string body = "r = vtk." + std::string(target.vtk_reader) + "(); r.SetFileName('" +
                                     ours.string() + "'); r.Update()";
            if (const auto vtk_read = python_figure(python, timed_python(setup, body, repetitions)))
                print_figure("formats/read_vtk/" + figure, "s", read, *vtk_read,
                             std::string(target.vtk_reader), "lower");
        }
        std::cerr << "formats: " << figure << ": " << fs::file_size(ours) << " bytes, " << elements
                  << " elements read back\n";
    }
    return 0;
}
