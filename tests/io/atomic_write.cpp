// Atomic writes (sxk/atomic_write.hpp and every mesh writer through it): a failed write leaves
// no partial file and an existing target byte for byte as it was; a TetGen set is all files or
// none. The failures are real: a file-size limit (RLIMIT_FSIZE) and a full file system (a
// 16 KiB tmpfs in a private mount namespace), each in a child process so that the limit or the
// mount never touches the test program.
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "io_fixtures.hpp"
#include "sxk/atomic_write.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"

namespace sxk::test {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void put(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// The names in a folder, sorted: what a failed write must not have added to.
std::vector<std::string> listing(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class AtomicWrite : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_folder = fs::temp_directory_path() /
                   ("sxk-atomic-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(m_folder);
        fs::create_directories(m_folder);
    }
    void TearDown() override { fs::remove_all(m_folder); }
    const fs::path& folder() const { return m_folder; }

private:
    fs::path m_folder;
};

// Runs `body` in a child process and returns what it returned (through a pipe), or
// "child died" when it did not exit normally.
std::string in_child(const std::function<std::string()>& body) {
    int channel[2];
    if (::pipe(channel) != 0)
        return "pipe failed";
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(channel[0]);
        std::string answer;
        try {
            answer = body();
        } catch (const std::exception& error) {
            answer = std::string("exception: ") + error.what();
        }
        const ssize_t written = ::write(channel[1], answer.data(), answer.size());
        ::_exit(written == static_cast<ssize_t>(answer.size()) ? 0 : 1);
    }
    ::close(channel[1]);
    std::string answer;
    char buffer[4096];
    ssize_t got;
    while ((got = ::read(channel[0], buffer, sizeof buffer)) > 0)
        answer.append(buffer, static_cast<std::size_t>(got));
    ::close(channel[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return "child died";
    return answer;
}

// A mesh whose files are far above the limits below (about 100 KB in every format).
Mesh big_mesh() {
    Outcome<Mesh> cube = make_kuhn_cube(6);
    EXPECT_TRUE(cube.ok());
    return std::move(cube).value();
}

TEST_F(AtomicWrite, WritesANewFileWithTheUmasksPermissions) {
    const fs::path target = folder() / "new.txt";
    write_file_atomically(target, "hello\n");
    EXPECT_EQ(contents(target), "hello\n");
    EXPECT_EQ(listing(folder()), std::vector<std::string>{"new.txt"});
    const mode_t mask = ::umask(0);
    ::umask(mask);
    struct stat info {};
    ASSERT_EQ(::stat(target.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
}

TEST_F(AtomicWrite, ReplacesAnExistingFileKeepingItsMode) {
    const fs::path target = folder() / "old.txt";
    put(target, "old contents that are longer than the new ones\n");
    ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
    write_file_atomically(target, "new\n");
    EXPECT_EQ(contents(target), "new\n");
    struct stat info {};
    ASSERT_EQ(::stat(target.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0640);
    EXPECT_EQ(listing(folder()), std::vector<std::string>{"old.txt"});
}

TEST_F(AtomicWrite, FollowsASymbolicLink) {
    const fs::path file = folder() / "real.mesh", link = folder() / "link.mesh";
    put(file, "old");
    fs::create_symlink(file.filename(), link);
    write_file_atomically(link, "new");
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
    EXPECT_EQ(contents(file), "new");
}

TEST_F(AtomicWrite, RefusesADirectoryInTheWay) {
    const fs::path target = folder() / "out.mesh";
    fs::create_directory(target);
    try {
        write_mesh(two_tetrahedra(), target);
        FAIL() << "a directory was overwritten";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()), "cannot write " + target.string() + ": is a directory");
    }
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(listing(folder()), std::vector<std::string>{"out.mesh"});
}

TEST_F(AtomicWrite, RefusesAFifoInTheWay) {
    const fs::path target = folder() / "out.mesh";
    ASSERT_EQ(::mkfifo(target.c_str(), 0600), 0);
    try {
        write_mesh(two_tetrahedra(), target);
        FAIL() << "a FIFO was replaced";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()), "cannot write " + target.string() + ": not a regular file");
    }
    EXPECT_TRUE(fs::is_fifo(target));
}

TEST_F(AtomicWrite, AMissingFolderIsReported) {
    const fs::path target = folder() / "no" / "such" / "out.mesh";
    try {
        write_mesh(two_tetrahedra(), target);
        FAIL() << "wrote into a missing folder";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "cannot write " + target.string() + ": No such file or directory");
    }
}

// The file-size limit makes write() fail with EFBIG part-way through the file: the classic way
// a plain fopen("w") loses the old file.
TEST_F(AtomicWrite, AFileSizeLimitLeavesTheOldTargetAsItWas) {
    for (const char* name : {"out.mesh", "out.msh", "out.off", "out.obj", "out.vtu"}) {
        const fs::path target = folder() / name;
        const std::string old = std::string("the user's precious file ") + name + "\n";
        put(target, old);
        const std::vector<std::string> before = listing(folder());
        const std::string answer = in_child([&] {
            ::signal(SIGXFSZ, SIG_IGN);
            const rlimit limit{4096, 4096};
            ::setrlimit(RLIMIT_FSIZE, &limit);
            write_mesh(big_mesh(), target);
            return std::string("written");
        });
        EXPECT_EQ(answer, "exception: cannot write " + target.string() + ": File too large") << name;
        EXPECT_EQ(contents(target), old) << name;
        EXPECT_EQ(listing(folder()), before) << name << ": a temporary file was left behind";
    }
}

TEST_F(AtomicWrite, ATetgenSetIsAllFilesOrNone) {
    const fs::path stem = folder() / "set";
    const std::array<std::string, 3> extensions{".node", ".ele", ".face"};
    for (const std::string& extension : extensions)
        put(fs::path(stem).replace_extension(extension), "old " + extension + "\n");
    const std::vector<std::string> before = listing(folder());
    // the .node file of the cube (about 10 KB) fits, its .ele (about 40 KB) does not: the set
    // must not end up with a new .node beside the old .ele
    const std::string answer = in_child([&] {
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{20000, 20000};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        write_mesh(big_mesh(), fs::path(stem).replace_extension(".ele"));
        return std::string("written");
    });
    EXPECT_EQ(answer, "exception: cannot write " + fs::path(stem).replace_extension(".ele").string() +
                          ": File too large");
    for (const std::string& extension : extensions)
        EXPECT_EQ(contents(fs::path(stem).replace_extension(extension)), "old " + extension + "\n") << extension;
    EXPECT_EQ(listing(folder()), before);
    // and without the limit the whole set is replaced and reads back
    write_mesh(big_mesh(), fs::path(stem).replace_extension(".ele"));
    EXPECT_EQ(read_mesh(fs::path(stem).replace_extension(".node")).element_count(), big_mesh().element_count());
    EXPECT_EQ(listing(folder()), before);
}

// The id a TetGen file's stamp line (its last line) gives, or "" without one.
std::string stamp_of(const fs::path& file) {
    std::string text = contents(file);
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    const std::string line = text.substr(text.rfind('\n') + 1);
    const std::string prefix = "# written by simplexkit, set ";
    return line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : std::string();
}

// A pid that belonged to a process and no longer does: a child that has exited and been reaped.
pid_t dead_pid() {
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

// kill -9 between the renames of a set cannot be prevented (several renames are no one atomic
// step): simulated by putting an old .ele back beside a new .node. The reader must refuse the
// mixture, naming both files, instead of reading the new nodes with the old elements (the
// hostile trial's "element 193 is inverted"), and the next write of the set clears what the
// killed writer left (its temporaries and backups; their names carry its pid).
TEST_F(AtomicWrite, AMixedTetgenSetIsRefusedNamingBothFiles) {
    const fs::path node = folder() / "set.node", ele = folder() / "set.ele", face = folder() / "set.face";
    Outcome<Mesh> small = make_kuhn_cube(2);
    ASSERT_TRUE(small.ok());
    write_mesh(*small, ele);
    const std::string old_ele = contents(ele);
    const std::string old_stamp = stamp_of(ele);
    EXPECT_EQ(old_stamp.size(), 16u);
    EXPECT_EQ(stamp_of(node), old_stamp);
    EXPECT_EQ(stamp_of(face), old_stamp);
    write_mesh(big_mesh(), ele);
    const std::string new_stamp = stamp_of(node);
    EXPECT_NE(new_stamp, old_stamp);
    EXPECT_EQ(stamp_of(face), new_stamp);
    EXPECT_EQ(read_mesh(node).element_count(), big_mesh().element_count());
    put(ele, old_ele);  // killed after renaming .node, before .ele
    // the killed writer's leftovers, and a live process's temporary that must stay
    const std::string dead = std::to_string(dead_pid());
    const std::vector<std::string> leftovers{".set.ele.sxk-" + dead + "-7.tmp", ".set.node.sxk-" + dead + "-8.old",
                                             ".set.face.sxk-" + dead + "-9.tmp"};
    for (const std::string& name : leftovers)
        put(folder() / name, "left behind\n");
    const std::string live = ".set.ele.sxk-" + std::to_string(::getppid()) + "-1.tmp";
    put(folder() / live, "being written\n");
    put(folder() / (".other.ele.sxk-" + dead + "-1.tmp"), "another target's\n");
    // 48 elements after the header: the stamp is line 50
    try {
        read_mesh(node);
        FAIL() << "a mixed set was read";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  ele.string() + ":50: set " + old_stamp + ", but " + node.string() + " is of set " + new_stamp +
                      ": the files come from two writes (one was interrupted between replacing them); write the "
                      "set again");
    }
    // given as its .ele the set says the same
    EXPECT_THROW(read_mesh(ele), InputError);
    write_mesh(big_mesh(), ele);
    EXPECT_EQ(read_mesh(node).element_count(), big_mesh().element_count());
    EXPECT_EQ(listing(folder()),
              (std::vector<std::string>{".other.ele.sxk-" + dead + "-1.tmp", live, "set.ele", "set.face", "set.node"}));
}

// TetGen's own files carry no stamp and are read as they are.
TEST_F(AtomicWrite, AnUnstampedTetgenSetIsRead) {
    put(folder() / "plain.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n# Generated by tetgen\n");
    put(folder() / "plain.ele", "1 4 0\n1 1 2 3 4\n# Generated by tetgen\n");
    EXPECT_EQ(read_mesh(folder() / "plain.node").element_count(), 1u);
}

// A file name of 245 bytes is legal (NAME_MAX is 255); its temporary, ".NAME.sxk-PID-N.tmp",
// would not be: the copied name is shortened, the pid and counter kept. Also a name of two-byte
// UTF-8 characters, which must not be cut inside a character.
TEST_F(AtomicWrite, ALongLegalNameIsWritten) {
    std::string utf8;
    for (int i = 0; i < 120; ++i)
        utf8 += "\xc3\xa9";  // U+00E9
    for (const std::string& name : {std::string(240, 'n') + ".mesh", utf8 + ".mesh"}) {
        ASSERT_EQ(name.size(), 245u);
        const fs::path target = folder() / name;
        write_mesh(two_tetrahedra(), target);
        EXPECT_EQ(read_mesh(target).element_count(), 2u);
        write_file_atomically(target, "replaced\n");
        EXPECT_EQ(contents(target), "replaced\n");
        EXPECT_EQ(listing(folder()), std::vector<std::string>{name});
        fs::remove(target);
    }
    // and as a TetGen set (its backups get the same shortening)
    const fs::path stem = folder() / std::string(240, 's');
    write_mesh(two_tetrahedra(), fs::path(stem).replace_extension(".node"));
    write_mesh(two_tetrahedra(), fs::path(stem).replace_extension(".node"));
    EXPECT_EQ(read_mesh(fs::path(stem).replace_extension(".ele")).element_count(), 2u);
    EXPECT_EQ(listing(folder()).size(), 3u);
}

// A set whose third file cannot be written because a directory stands where it goes: nothing
// is written at all (the targets are checked before any temporary is made).
TEST_F(AtomicWrite, ATetgenSetWithADirectoryInTheWayWritesNothing) {
    const fs::path stem = folder() / "set";
    put(fs::path(stem).replace_extension(".node"), "old node\n");
    fs::create_directory(fs::path(stem).replace_extension(".face"));
    const std::vector<std::string> before = listing(folder());
    try {
        write_mesh(two_tetrahedra(), fs::path(stem).replace_extension(".node"));
        FAIL() << "written over a directory";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "cannot write " + fs::path(stem).replace_extension(".face").string() + ": is a directory");
    }
    EXPECT_EQ(contents(fs::path(stem).replace_extension(".node")), "old node\n");
    EXPECT_EQ(listing(folder()), before);
}

// A full disk: a 16 KiB tmpfs mounted in a mount namespace of the child's own (as root a plain
// one, else inside a user namespace), so nothing outside the child sees it.
TEST_F(AtomicWrite, AFullFileSystemLeavesTheOldTargetAsItWas) {
    const fs::path mount_point = folder() / "small";
    fs::create_directory(mount_point);
    const std::string answer = in_child([&]() -> std::string {
        const int flags = ::geteuid() == 0 ? CLONE_NEWNS : CLONE_NEWUSER | CLONE_NEWNS;
        if (::unshare(flags) != 0)
            return std::string("skip: unshare: ") + std::strerror(errno);
        // keep the mount private to this namespace
        ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr);
        if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=16k") != 0)
            return std::string("skip: mount: ") + std::strerror(errno);
        const fs::path target = mount_point / "femur.mesh";
        const std::string old = "the user's only copy\n";
        put(target, old);
        std::string outcome;
        try {
            write_mesh(big_mesh(), target);
            outcome = "written";
        } catch (const OutputError& error) {
            outcome = error.what();
        }
        std::string names;
        for (const std::string& name : listing(mount_point))
            names += name + ";";
        return outcome + "|" + (contents(target) == old ? "kept" : "changed") + "|" + names;
    });
    if (answer.rfind("skip: ", 0) == 0)
        GTEST_SKIP() << "no private tmpfs here (" << answer << "); the file-size limit test covers the same path";
    EXPECT_EQ(answer, "cannot write " + (mount_point / "femur.mesh").string() +
                          ": No space left on device|kept|femur.mesh;");
}

TEST_F(AtomicWrite, AMeshWithoutElementsIsRefused) {
    Mesh empty(3, 3);
    empty.add_vertex({0, 0, 0});
    const fs::path target = folder() / "empty.mesh";
    try {
        write_mesh(empty, target);
        FAIL() << "an empty mesh was written";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()), "cannot write " + target.string() + ": the mesh has no elements");
    }
    EXPECT_FALSE(fs::exists(target));
}

TEST_F(AtomicWrite, RefuseInvalidRefusesAnInvertedElement) {
    Mesh mesh = two_tetrahedra();
    // move vertex 3 below the plane z = 0: element 0 (0 1 2 3) turns inside out
    mesh.set_reference(3, {0.2, 1.0 / 3.0, -0.5});
    mesh.set_deformed(3, {0.2, 1.0 / 3.0, -0.5});
    ASSERT_TRUE(mesh.validate().ok());  // the connectivity is fine
    const fs::path target = folder() / "inverted.mesh";
    WriteOptions options;
    options.refuse_invalid = true;
    try {
        write_mesh(mesh, target, options);
        FAIL() << "an inverted mesh was written";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()), "cannot write " + target.string() +
                                                 ": the mesh is invalid: element 0 is inverted in the reference positions");
    }
    EXPECT_FALSE(fs::exists(target));
    // without the option the writer writes what it is given
    write_mesh(mesh, target);
    EXPECT_TRUE(fs::exists(target));
}

}  // namespace
}  // namespace sxk::test
