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
// renaming over it would replace the special file itself. A process killed between creating
// and renaming the temporary file leaves that file behind (nothing can remove it then); its
// name says where it came from.
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
// the targets already replaced get their old content back (kept meanwhile as a hard link, or a
// copy where the file system has no hard links). Either all files are the new ones or all are
// as they were. Throws OutputError naming the file that failed.
SXK_API void write_files_atomically(std::span<const FileContent> files);

}  // namespace sxk
