// write_file_atomically / write_files_atomically (sxk/atomic_write.hpp): temporary file, full
// write, fsync, close, rename. POSIX calls rather than stdio so that every step reports its
// own errno (a full disk may show at write(), at fsync() or only at close()).
#include "sxk/atomic_write.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

namespace sxk {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    throw OutputError("cannot write " + path.string() + ": " + why);
}

[[noreturn]] void fail_errno(const std::filesystem::path& path, int error) {
    fail(path, std::strerror(error));
}

// The longest file name the target's folder takes (NAME_MAX where the file system does not say).
std::size_t name_limit(const std::filesystem::path& target) {
    const std::filesystem::path folder =
        target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
    const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    return limit > 0 ? static_cast<std::size_t>(limit) : std::size_t{NAME_MAX};
}

// ".NAME.sxk-PID-N.KIND": the pid and the counter make it unique, and a file name that would
// not fit `limit` with them (a legal 245-byte name gets ~20 more) is shortened: only the copied
// NAME loses bytes, cut before a UTF-8 sequence rather than inside one, so that the pid and the
// counter stay readable for remove_stale_leftovers.
std::string temporary_name(const std::string& name, long pid, unsigned long counter,
                           std::string_view kind, std::size_t limit) {
    const std::string tail =
        ".sxk-" + std::to_string(pid) + "-" + std::to_string(counter) + std::string(kind);
    std::size_t keep = name.size();
    const std::size_t room = limit > tail.size() + 2 ? limit - tail.size() - 1 : 1;
    if (keep > room) {
        keep = room;
        while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80)
            --keep;
    }
    return "." + name.substr(0, keep) + tail;
}

// Names unique within this process (the counter) and across processes (the pid); O_EXCL
// settles any remaining clash, the caller simply takes the next number.
std::filesystem::path temporary_beside(const std::filesystem::path& target, const char* kind) {
    static std::atomic<unsigned long> counter{0};
    return target.parent_path() / temporary_name(target.filename().string(),
                                                 static_cast<long>(::getpid()),
                                                 counter.fetch_add(1), kind, name_limit(target));
}

// The pid and counter of `text` ("PID-N"), both plain decimal numbers, or false.
bool parse_pid_and_counter(std::string_view text, long& pid, unsigned long& counter) {
    const std::size_t dash = text.find('-');
    if (dash == std::string_view::npos)
        return false;
    const std::string_view pid_text = text.substr(0, dash), counter_text = text.substr(dash + 1);
    const auto [pid_end, pid_error] =
        std::from_chars(pid_text.data(), pid_text.data() + pid_text.size(), pid);
    const auto [counter_end, counter_error] = std::from_chars(
        counter_text.data(), counter_text.data() + counter_text.size(), counter);
    return !pid_text.empty() && pid_error == std::errc() &&
           pid_end == pid_text.data() + pid_text.size() && !counter_text.empty() &&
           counter_error == std::errc() &&
           counter_end == counter_text.data() + counter_text.size() && pid > 0;
}

// What a writer killed between creating its temporaries and renaming them (kill -9, a crash)
// left beside `target`: ".NAME.sxk-PID-N.tmp" and, of a set, the backups ".NAME.sxk-PID-N.old".
// Only names this writer would make for `target` are considered, and only those whose PID is no
// running process (kill(PID, 0) says ESRCH): a live writer's files, or a file of a process we
// cannot judge (EPERM: it runs), stay. A pid reused since keeps its leftovers until a later
// write. Called after a successful write: the target is then complete, and the backups of an
// interrupted set (its only copy of the old files) are no longer needed.
void remove_stale_leftovers(const std::filesystem::path& target) {
    const std::filesystem::path folder =
        target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
    const std::string name = target.filename().string();
    const std::size_t limit = name_limit(target);
    std::error_code error;
    std::vector<std::filesystem::path> stale;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error)) {
        const std::string found = entry->path().filename().string();
        if (found.size() < 10 || found[0] != '.')
            continue;
        const std::string_view kind = std::string_view(found).substr(found.size() - 4);
        if (kind != ".tmp" && kind != ".old")
            continue;
        const std::size_t marker = found.rfind(".sxk-");
        if (marker == std::string::npos)
            continue;
        long pid = 0;
        unsigned long counter = 0;
        if (!parse_pid_and_counter(std::string_view(found).substr(
                                       marker + 5, found.size() - 4 - (marker + 5)),
                                   pid, counter))
            continue;
        if (temporary_name(name, pid, counter, kind, limit) != found ||
            pid == static_cast<long>(::getpid()))
            continue;
        if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
            stale.push_back(entry->path());
    }
    for (const std::filesystem::path& path : stale)
        ::unlink(path.c_str());
}

// What a write aims at: the file a symbolic link names, checked to be a regular file or absent.
std::filesystem::path resolve_target(const std::filesystem::path& path, bool& existed,
                                     mode_t& mode) {
    if (path.empty() || path.filename().empty())
        fail(path, "no file name");
    std::filesystem::path target = path;
    std::error_code error;
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, error))) {
        const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
        if (!error)
            target = resolved;
    }
    struct stat info {};
    if (::stat(target.c_str(), &info) != 0) {
        if (errno != ENOENT)
            fail_errno(path, errno);
        existed = false;
        return target;
    }
    if (S_ISDIR(info.st_mode))
        fail(path, "is a directory");
    if (!S_ISREG(info.st_mode))
        fail(path, "not a regular file");
    existed = true;
    mode = info.st_mode & 07777;
    return target;
}

// One file on its way: the temporary is removed by the destructor unless it was renamed.
struct Pending {
    std::filesystem::path requested;  // as the caller named it (for messages)
    std::filesystem::path target;
    std::filesystem::path temporary;
    std::filesystem::path backup;  // the old target, kept while a set is being replaced
    bool existed = false;
    bool renamed = false;

    Pending() = default;
    Pending(const Pending&) = delete;
    Pending& operator=(const Pending&) = delete;
    ~Pending() {
        if (!temporary.empty() && !renamed)
            ::unlink(temporary.c_str());
        if (!backup.empty())
            ::unlink(backup.c_str());
    }
};

int write_all(int fd, std::string_view data) {
    while (!data.empty()) {
        // at most 1 GiB per call: Linux writes no more than about 2 GiB at once anyway
        const std::size_t chunk = std::min<std::size_t>(data.size(), std::size_t{1} << 30);
        const ssize_t written = ::write(fd, data.data(), chunk);
        if (written < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        data.remove_prefix(static_cast<std::size_t>(written));
    }
    return 0;
}

// Creates the temporary beside the target and writes, flushes and closes it.
void write_temporary(Pending& file, std::string_view data, mode_t mode) {
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        file.temporary = temporary_beside(file.target, ".tmp");
        fd = ::open(file.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) {
            const int error = errno;
            file.temporary.clear();  // nothing was created
            fail_errno(file.requested, error);
        }
    }
    if (fd < 0) {
        file.temporary.clear();
        fail(file.requested, "cannot create a temporary file beside it");
    }
    int error = 0;
    // keep the old file's permissions; a new file keeps what open() gave it under the umask
    if (file.existed && ::fchmod(fd, mode) != 0)
        error = errno;
    if (error == 0)
        error = write_all(fd, data);
    // the data must be on disk before the rename makes them the target: otherwise a crash
    // right after could leave an empty target (the rename reached the disk, the data not)
    if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL)
        error = errno;
    if (::close(fd) != 0 && error == 0 && errno != EINTR)
        error = errno;
    if (error != 0)
        fail_errno(file.requested, error);
}

// The folder's entry for the rename on disk too; not every file system can (EINVAL), which is
// no reason to fail a write that has already happened.
void sync_folder(const std::filesystem::path& target) {
    const std::filesystem::path folder =
        target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return;
    ::fsync(fd);
    ::close(fd);
}

// Keeps the old target reachable under a second name while a set is replaced: a hard link
// (no copy, no window without the target), else a copy.
void keep_backup(Pending& file) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::filesystem::path backup = temporary_beside(file.target, ".old");
        if (::link(file.target.c_str(), backup.c_str()) == 0) {
            file.backup = backup;
            return;
        }
        if (errno == EEXIST)
            continue;
        std::error_code error;
        if (std::filesystem::copy_file(file.target, backup, error)) {
            file.backup = backup;
            return;
        }
        fail(file.requested, "cannot keep the old file while replacing the set: " +
                                 error.message());
    }
    fail(file.requested, "cannot keep the old file while replacing the set");
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view data) {
    const FileContent file{path, data};
    write_files_atomically(std::span(&file, 1));
}

void write_files_atomically(std::span<const FileContent> files) {
    std::vector<Pending> pending(files.size());
    std::vector<mode_t> modes(files.size(), 0);
    for (std::size_t i = 0; i < files.size(); ++i) {
        pending[i].requested = files[i].path;
        pending[i].target = resolve_target(files[i].path, pending[i].existed, modes[i]);
    }
    for (std::size_t i = 0; i < files.size(); ++i)
        write_temporary(pending[i], files[i].data, modes[i]);
    if (files.size() > 1)
        for (Pending& file : pending)
            if (file.existed)
                keep_backup(file);
    for (std::size_t i = 0; i < pending.size(); ++i) {
        Pending& file = pending[i];
        if (::rename(file.temporary.c_str(), file.target.c_str()) == 0) {
            file.renamed = true;
            continue;
        }
        const int error = errno;
        // put back what this set has replaced so far: all files or none
        for (std::size_t j = 0; j < i; ++j) {
            Pending& done = pending[j];
            if (!done.backup.empty() && ::rename(done.backup.c_str(), done.target.c_str()) == 0)
                done.backup.clear();
            else if (!done.existed)
                ::unlink(done.target.c_str());
        }
        fail_errno(file.requested, error);
    }
    for (const Pending& file : pending)
        sync_folder(file.target);
    for (const Pending& file : pending)
        remove_stale_leftovers(file.target);
}

}  // namespace sxk
