// How inputs are brought into memory (core/src/io/load_file.cpp), through read_text_file, which
// side inputs use, and read_mesh: regular files and FIFOs up to a bound, everything else refused
// with its reason; the text check and the byte order mark of the mesh readers.
#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "fifo_writer.hpp"
#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

namespace fs = std::filesystem;

// The message of the InputError `read` throws, or "no error".
template <class Read>
std::string error_of(Read read) {
    try {
        read();
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

const std::string bom = "\xEF\xBB\xBF";

TEST(LoadFile, DevicesDirectoriesAndSocketsAreRefusedBeforeReading) {
    EXPECT_EQ(error_of([] { read_text_file("/dev/zero"); }), "/dev/zero:0: is a character device, not a file");
    EXPECT_EQ(error_of([] { (void)read_text_file("/dev/null"); }),
              "/dev/null:0: is a character device, not a file");
    const fs::path dir = test::scratch_dir();
    // a mesh name does not make a device a mesh file
    fs::create_symlink("/dev/zero", dir / "zero.mesh");
    EXPECT_EQ(error_of([&] { (void)read_mesh(dir / "zero.mesh"); }),
              (dir / "zero.mesh").string() + ":0: is a character device, not a file");
    fs::create_directory(dir / "faces");
    EXPECT_EQ(error_of([&] { (void)read_text_file(dir / "faces"); }), (dir / "faces").string() + ":0: is a directory");
    EXPECT_EQ(error_of([&] { (void)read_text_file(dir / "none"); }), (dir / "none").string() + ":0: no such file");

    // sun_path holds 108 bytes and a build tree can lie deeper than that, so the socket is bound
    // by its name relative to the scratch folder and then read by its full path.
    const fs::path socket_path = dir / "s.sock";
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strcpy(address.sun_path, "s.sock");
    const fs::path here = fs::current_path();
    fs::current_path(dir);
    const int bound = ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
    fs::current_path(here);
    ASSERT_EQ(bound, 0) << std::strerror(errno);
    EXPECT_EQ(error_of([&] { read_text_file(socket_path); }), socket_path.string() + ":0: is a socket, not a file");
    ::close(fd);
}

TEST(LoadFile, AReadErrorIsReportedNotAnEmptyFile) {
    // /proc/self/mem is a regular file of size 0 whose first page cannot be read: EIO
    EXPECT_EQ(error_of([] { (void)read_text_file("/proc/self/mem"); }),
              "/proc/self/mem:0: cannot read: Input/output error");
}

TEST(LoadFile, AnUnreadableFileSaysWhy) {
    if (::geteuid() == 0)
        GTEST_SKIP() << "root reads files whatever their permissions";
    const fs::path file = test::scratch_dir() / "locked.txt";
    write(file, "0 1 2\n");
    fs::permissions(file, fs::perms::none);
    EXPECT_EQ(error_of([&] { (void)read_text_file(file); }), file.string() + ":0: cannot open: Permission denied");
}

TEST(LoadFile, RegularFilesAreReadUpToTheBound) {
    const fs::path file = test::scratch_dir() / "ten.txt";
    write(file, "0123456789");
    EXPECT_EQ(read_text_file(file, 10), "0123456789");
    EXPECT_EQ(error_of([&] { read_text_file(file, 9); }),
              file.string() + ":0: larger than 9 bytes, the most one input is read to");
    EXPECT_EQ(max_input_bytes, std::size_t{1} << 30);
}

TEST(LoadFile, FifosAreReadUpToTheBound) {
    const fs::path dir = test::scratch_dir();
    {
        test::FifoWriter writer(dir / "a.fifo", "0123456789");
        EXPECT_EQ(read_text_file(dir / "a.fifo", 10), "0123456789");
    }
    {
        test::FifoWriter writer(dir / "b.fifo", "0123456789");
        EXPECT_EQ(error_of([&] { read_text_file(dir / "b.fifo", 9); }),
                  (dir / "b.fifo").string() + ":0: larger than 9 bytes, the most one input is read to");
    }
    // a mesh through a named pipe
    std::ostringstream mesh;
    mesh << std::ifstream(test::data_file("io/tetra.off")).rdbuf();
    test::FifoWriter writer(dir / "pipe.off", mesh.str());
    EXPECT_EQ(read_mesh(dir / "pipe.off").element_count(), 4u);
}

TEST(LoadFile, StreamsAreReadUpToTheBound) {
    std::istringstream ten("0123456789");
    EXPECT_EQ(read_text_stream(ten, "<stdin>", 10), "0123456789");
    std::istringstream eleven("0123456789a");
    EXPECT_EQ(error_of([&] { read_text_stream(eleven, "<stdin>", 10); }),
              "<stdin>:0: larger than 10 bytes, the most one input is read to");
}

TEST(ReadTextFile, DropsTheByteOrderMarkAndRefusesBinaryData) {
    const fs::path dir = test::scratch_dir();
    write(dir / "bom.txt", bom + "0 1 2\n");
    EXPECT_EQ(read_text_file(dir / "bom.txt"), "0 1 2\n");
    std::istringstream stream(bom + "3 4 5\n");
    EXPECT_EQ(read_text_stream(stream, "s.txt"), "3 4 5\n");
    write(dir / "empty.txt", "");
    EXPECT_EQ(read_text_file(dir / "empty.txt"), "");
    write(dir / "binary.txt", std::string("0 1 2\n3 4\0 5\n", 12));
    EXPECT_EQ(error_of([&] { (void)read_text_file(dir / "binary.txt"); }),
              (dir / "binary.txt").string() + ":2: binary data (byte 0x00)");
}

// A UTF-8 byte order mark in front of any mesh file (every reader's file, TetGen's three) reads
// as the file without it.
TEST(ReadTextFile, EveryMeshReaderTakesAByteOrderMark) {
    const fs::path dir = test::scratch_dir();
    for (const char* name : {"two_tets.mesh", "two_tets22.msh", "two_tets41.msh", "tetra.off", "square.obj",
                             "two_tets.node", "two_tets.ele", "two_tets.face"}) {
        std::ostringstream text;
        text << std::ifstream(test::data_file(std::string("io/") + name), std::ios::binary).rdbuf();
        write(dir / name, bom + text.str());
    }
    for (const char* name : {"two_tets.mesh", "two_tets22.msh", "two_tets41.msh", "tetra.off", "square.obj",
                             "two_tets.ele"}) {
        SCOPED_TRACE(name);
        const Mesh with_mark = read_mesh(dir / name);
        const Mesh without = read_mesh(test::data_file(std::string("io/") + name));
        test::expect_same_mesh(without, with_mark);
    }
}

}  // namespace
}  // namespace sxk
