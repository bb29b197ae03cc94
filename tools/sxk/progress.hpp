// A spinner with the elapsed time on stderr, for work that may take more than about a second
// (reading a big mesh, a quality pass over 200k tetrahedra).
//
// It draws nothing during the first `delay`, so quick runs stay quiet, and nothing at all unless
// stderr is a terminal: pipes, logs and tests never see control characters. The line is erased
// when the Progress object is destroyed, before any message the command prints afterwards.
//
//     {
//         Progress progress("reading femur.1.ele");
//         mesh = read_mesh(path);
//     }  // spinner gone
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <ostream>
#include <stop_token>
#include <string>
#include <thread>

namespace sxk::cli {

class Progress {
public:
    explicit Progress(std::string label);
    // Draws on `out` whatever it is (tests); `interval` is the redraw period.
    Progress(std::string label, std::ostream& out, std::chrono::milliseconds delay,
             std::chrono::milliseconds interval);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void set_label(std::string label);

private:
    Progress(std::string label, std::ostream* out, std::chrono::milliseconds delay,
             std::chrono::milliseconds interval);
    void draw(std::chrono::steady_clock::duration elapsed);
    void loop(std::stop_token stop);

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

}  // namespace sxk::cli
