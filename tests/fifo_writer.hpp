// A FIFO fed from a thread, as a shell's <(...) feeds one: for the tests of reading inputs that
// are not regular files (core/src/io/load_file.cpp). Header-only, shared by test_io and test_cli.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

namespace sxk::test {

class FifoWriter {
public:
    // Makes the FIFO at `path` and writes `text` (at most a pipe buffer, 4 KiB, so one write()
    // never waits for the reader) once a reader opens it.
    FifoWriter(const std::filesystem::path& path, std::string text) : m_path(path) {
        if (text.size() > 4096 || ::mkfifo(path.c_str(), 0600) != 0)
            throw std::runtime_error("cannot make the FIFO " + path.string());
        m_thread = std::thread([path, text = std::move(text)] {
            const int fd = ::open(path.c_str(), O_WRONLY);
            if (fd < 0)
                return;
            [[maybe_unused]] const ssize_t written = ::write(fd, text.data(), text.size());
            ::close(fd);
        });
    }
    // A reader that never came is stood in for, so that the writer's open() returns.
    ~FifoWriter() {
        const int fd = ::open(m_path.c_str(), O_RDONLY | O_NONBLOCK);
        m_thread.join();
        if (fd >= 0)
            ::close(fd);
    }
    FifoWriter(const FifoWriter&) = delete;
    FifoWriter& operator=(const FifoWriter&) = delete;

private:
    std::filesystem::path m_path;
    std::thread m_thread;
};

}  // namespace sxk::test
