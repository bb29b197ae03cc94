#include "progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace sxk::cli {

namespace {
constexpr std::chrono::milliseconds default_delay{800};
constexpr std::chrono::milliseconds default_interval{100};
}  // namespace

Progress::Progress(std::string label)
    : Progress(std::move(label), isatty(STDERR_FILENO) ? &std::cerr : nullptr, default_delay,
               default_interval) {}

Progress::Progress(std::string label, std::ostream& out, std::chrono::milliseconds delay,
                   std::chrono::milliseconds interval)
    : Progress(std::move(label), &out, delay, interval) {}

Progress::Progress(std::string label, std::ostream* out, std::chrono::milliseconds delay,
                   std::chrono::milliseconds interval)
    : m_out(out),
      m_delay(delay),
      m_interval(interval),
      m_start(std::chrono::steady_clock::now()),
      m_label(std::move(label)) {
    if (m_out) m_thread = std::jthread([this](std::stop_token stop) { loop(stop); });
}

Progress::~Progress() {
    if (m_thread.joinable()) {
        m_thread.request_stop();  // wakes the wait through the stop token
        m_thread.join();
    }
    if (m_out && m_drawn) *m_out << "\r\033[K" << std::flush;
}

void Progress::set_label(std::string label) {
    std::lock_guard lock(m_mutex);
    m_label = std::move(label);
}

void Progress::draw(std::chrono::steady_clock::duration elapsed) {
    static constexpr char spinner[] = {'|', '/', '-', '\\'};
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f s", std::chrono::duration<double>(elapsed).count());
    *m_out << '\r' << spinner[m_frame++ % 4] << ' ' << m_label << "  " << seconds << "\033[K" << std::flush;
    m_drawn = true;
}

void Progress::loop(std::stop_token stop) {
    std::unique_lock lock(m_mutex);
    // wait() returns true when stop was requested
    if (m_wake.wait_for(lock, stop, m_delay, [] { return false; }) || stop.stop_requested()) return;
    while (!stop.stop_requested()) {
        draw(std::chrono::steady_clock::now() - m_start);
        m_wake.wait_for(lock, stop, m_interval, [] { return false; });
    }
}

}  // namespace sxk::cli
