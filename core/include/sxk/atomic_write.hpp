// Atomic file output: the one way simplexkit writes a file (meshes in every format, TetGen sets,
// PNG pictures), so that a failed write never destroys what the user had.
//
// The data go to a temporary file in the target's folder (".NAME.sxk-PID-N.tmp", created with
// O_EXCL, so with the permissions a new file gets under the umask, or the old target's mode);
// it is written completely, flushed to disk (fsync) and closed, and only then renamed over the
// target. rename() within one folder is atomic: a reader of the target sees the old bytes or
// the new ones, never a mixture, and a full disk, a file-size limit, a permission problem or a
// directory in the way leave no temporary file behind and the old target byte-for-byte as it
// was.
//
// A symbolic link as the target is followed (the file it names is replaced, the link stays).
// An existing target that is not a regular file (a directory, a FIFO, a device) is refused:
// renaming over it would replace the special file itself.
//
// The temporary's name keeps within the folder's NAME_MAX: of a long target name only the
// copied part is shortened, the pid and the counter stay. A process killed between creating and
// renaming its temporary files (kill -9, a crash) leaves them behind, and nothing can remove
// them then; the next successful write of the same target removes those whose pid is no
// running process (their names say which process made them).
//
// A file-size limit (RLIMIT_FSIZE, `ulimit -f`) raises SIGXFSZ when a write() would pass it, and
// the default action of that signal kills the process before write() can fail: no message, the
// temporary left behind. Only with SIGXFSZ ignored does write() fail with EFBIG, which these
// functions report as "cannot write PATH: File too large" after removing the temporary. The
// library leaves signal dispositions to the application: a program that writes files should
// ignore SIGXFSZ at start-up (`signal(SIGXFSZ, SIG_IGN)`), as `sxk` does.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>

#include "sxk/config.hpp"
#include "sxk/io.hpp"

namespace sxk {

// Writes `data` to `path` atomically (see above). Throws OutputError("cannot write PATH: why").
SXK_API void write_file_atomically(const std::filesystem::path& path, std::string_view data);

struct FileContent {
    std::filesystem::path path;
    std::string_view data;
};

// Several files as one (a TetGen .node/.ele/.face set): every file is written to its temporary
// first; then they replace their targets one after another, and should a later rename fail,
// the targets already replaced get their old content back (kept meanwhile as a hard link
// ".NAME.sxk-PID-N.old", or a copy where the file system has no hard links). Throws OutputError
// naming the file that failed; after a returned call all files are the new ones, after a thrown
// one all are as they were. Several renames cannot be one atomic step, though: a process killed
// between them leaves some targets new and some old (each file whole, never a mixture within
// one), with the temporaries and backups beside them. Readers of such a set must be able to
// tell: the TetGen writer stamps its three files with one set id and the reader refuses files
// of different writes (docs/formats.md "Writers").
SXK_API void write_files_atomically(std::span<const FileContent> files);

}  // namespace sxk
