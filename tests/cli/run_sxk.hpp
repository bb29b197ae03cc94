// Runs the sxk binary as a child process (posix_spawn) and captures its exit code, stdout and
// stderr separately, with control over the environment (SXK_PLUGIN_PATH). Also: a scratch
// folder per test, and small hand-drawn mesh files.
#pragma once

#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

extern char** environ;

namespace sxk::test {

namespace fs = std::filesystem;

struct ProcessResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

inline std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write_file(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// `text` with regex special characters escaped, for matching messages that contain paths.
inline std::string regex_escape(const std::string& text) {
    std::string escaped;
    for (char c : text) {
        if (std::string_view("\\^$.|?*+()[]{}").find(c) != std::string_view::npos) escaped += '\\';
        escaped += c;
    }
    return escaped;
}

// A fresh folder removed at the end of the test.
class ScratchFolder {
public:
    ScratchFolder() {
        std::string pattern = (fs::temp_directory_path() / "sxk-test-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        m_path = fs::canonical(pattern);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        fs::remove_all(m_path, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const fs::path& path() const { return m_path; }
    fs::path operator/(const std::string& name) const { return m_path / name; }

private:
    fs::path m_path;
};

// Runs `program args...`. The child gets this process's environment without SXK_PLUGIN_PATH,
// plus `environment` (a value of std::nullopt removes the variable), and `input` as its standard
// input.
inline ProcessResult run_program(const std::string& program, const std::vector<std::string>& args,
                       const std::map<std::string, std::optional<std::string>>& environment = {},
                       const fs::path& input = "/dev/null") {
    ScratchFolder capture;
    const fs::path out_file = capture / "stdout", err_file = capture / "stderr";

    std::map<std::string, std::optional<std::string>> overrides = environment;
    overrides.try_emplace("SXK_PLUGIN_PATH", std::nullopt);
    std::vector<std::string> env_strings;
    for (char** entry = environ; *entry; ++entry) {
        const std::string text = *entry;
        if (!overrides.contains(text.substr(0, text.find('=')))) env_strings.push_back(text);
    }
    for (const auto& [name, value] : overrides)
        if (value) env_strings.push_back(name + "=" + *value);

    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    std::vector<char*> envp;
    for (std::string& text : env_strings) envp.push_back(text.data());
    envp.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, input.c_str(), O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ProcessResult run;
    if (spawned != 0) {
        run.err = "posix_spawn failed: " + std::string(strerror(spawned));
        return run;
    }
    int status = 0;
    waitpid(pid, &status, 0);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.out = slurp(out_file);
    run.err = slurp(err_file);
    return run;
}

inline ProcessResult sxk(const std::vector<std::string>& args,
               const std::map<std::string, std::optional<std::string>>& environment = {},
               const fs::path& input = "/dev/null") {
    return run_program(SXK_EXE, args, environment, input);
}

// ---- hand-drawn meshes (Medit .mesh) ----------------------------------------------------------

//            4 (0,0,1)
//            |`.
//            |  `.          5 (1,1,1) lies on the far side of the slanted face 2-3-4
//            |    `.
//            1------3       <1,2,3,4> and <2,3,4,5> (file numbering), both positive, glued
//           /  ` . '        along 2-3-4: one component, 6 boundary triangles; the boundary
//          2                triangle 1-2-3 carries face label 7, the elements labels 1 and 2
inline const char* two_tetrahedra_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
1 1 1 0
Tetrahedra
2
1 2 3 4 1
2 3 4 5 2
Triangles
1
1 2 3 7
End
)";

// Two unit tetrahedra far apart: two components, 8 boundary triangles.
inline const char* separate_tetrahedra_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
8
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
5 0 0 0
6 0 0 0
5 1 0 0
5 0 1 0
Tetrahedra
2
1 2 3 4 0
5 6 7 8 0
End
)";

//          4              two tetrahedra sharing only vertex 1 (the origin), mirrored through
//          |  3           it: every element is fine, but the star of vertex 1 is not
//          | /            face-connected (thesis §7.3), so validate() refuses the mesh
//          1----2
//    6  /  |
//     /    7   5----1 (same 1)
inline const char* vertex_star_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
7
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
-1 0 0 0
0 -1 0 0
0 0 -1 0
Tetrahedra
2
1 2 3 4 0
1 6 5 7 0
End
)";

// The same tetrahedron twice (invariant 7.4).
inline const char* duplicated_tetrahedron_mesh = R"(MeshVersionFormatted 2
Dimension 3
Vertices
4
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
Tetrahedra
2
1 2 3 4 0
1 2 3 4 0
End
)";

//   4 ---- 3
//   |    / |     planar unit square, two counter-clockwise triangles
//   |  /   |
//   1 ---- 2
inline const char* unit_square_mesh = R"(MeshVersionFormatted 2
Dimension 2
Vertices
4
0 0 0
1 0 0
1 1 0
0 1 0
Triangles
2
1 2 3 0
1 3 4 0
End
)";

}  // namespace sxk::test
