// A spinner with the elapsed time on stderr, for work that may take more than about a second
// (reading a big mesh, a quality pass over 200k tetrahedra, removing the degeneracies of the
// femur). The built-in commands (tools/sxk/progress.hpp) and the plug-ins' commands share it, as
// they share command_line.hpp (the command-line library, cli/).
//
// It draws nothing during the first `delay`, so quick runs stay quiet, and nothing at all unless
// stderr is a terminal: pipes, logs and tests never see control characters. The line is erased
// when the object is destroyed, before any message the command prints afterwards.
//
//     {
//         ProgressLine progress("reading femur.1.ele");
//         mesh = read_mesh(path);
//     }  // spinner gone
#pragma once

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <ostream>
#include <stop_token>
#include <string>
#include <thread>

namespace sxk {

class ProgressLine {
public:
    static constexpr std::chrono::milliseconds default_delay{800};
    static constexpr std::chrono::milliseconds default_interval{100};

    explicit ProgressLine(std::string label)
        : ProgressLine(std::move(label), isatty(STDERR_FILENO) ? &std::cerr : nullptr, default_delay,
                       default_interval) {}
    // Draws on `out` whatever it is (tests); `interval` is the redraw period.
    ProgressLine(std::string label, std::ostream& out, std::chrono::milliseconds delay,
                 std::chrono::milliseconds interval)
        : ProgressLine(std::move(label), &out, delay, interval) {}
    ~ProgressLine() {
        if (m_thread.joinable()) {
            m_thread.request_stop();  // wakes the wait through the stop token
            m_thread.join();
        }
        if (m_out && m_drawn) *m_out << "\r\033[K" << std::flush;
    }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // Whether it draws at all (stderr is a terminal, or a stream was given): a caller that
    // builds labels as it goes needs to build none otherwise.
    bool drawing() const { return m_out != nullptr; }

    void set_label(std::string label) {
        std::lock_guard lock(m_mutex);
        m_label = std::move(label);
    }

private:
    ProgressLine(std::string label, std::ostream* out, std::chrono::milliseconds delay,
                 std::chrono::milliseconds interval)
        : m_out(out),
          m_delay(delay),
          m_interval(interval),
          m_start(std::chrono::steady_clock::now()),
          m_label(std::move(label)) {
        if (m_out) m_thread = std::jthread([this](std::stop_token stop) { loop(stop); });
    }

    void draw(std::chrono::steady_clock::duration elapsed) {
        static constexpr char spinner[] = {'|', '/', '-', '\\'};
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%.1f s", std::chrono::duration<double>(elapsed).count());
        *m_out << '\r' << spinner[m_frame++ % 4] << ' ' << m_label << "  " << seconds << "\033[K" << std::flush;
        m_drawn = true;
    }

    void loop(std::stop_token stop) {
        std::unique_lock lock(m_mutex);
        // wait() returns true when stop was requested
        if (m_wake.wait_for(lock, stop, m_delay, [] { return false; }) || stop.stop_requested()) return;
        while (!stop.stop_requested()) {
            draw(std::chrono::steady_clock::now() - m_start);
            m_wake.wait_for(lock, stop, m_interval, [] { return false; });
        }
    }

    std::ostream* m_out;  // nullptr: disabled
    std::chrono::milliseconds m_delay;
    std::chrono::milliseconds m_interval;
    std::chrono::steady_clock::time_point m_start;
    std::mutex m_mutex;
    std::condition_variable_any m_wake;
    std::string m_label;
    bool m_drawn = false;
    unsigned m_frame = 0;
    std::jthread m_thread;  // declared last: starts once everything above is initialised
};

}  // namespace sxk
