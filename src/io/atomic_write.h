#pragma once
#include <string>

namespace kinema {

// Writes `contents` to `path` without ever destroying the previous file: the data goes
// to a temporary file in the same folder, is flushed to disk, then renamed over `path`.
// On any failure the temporary file is removed and `path` is untouched.
// - A symbolic link is followed: the file it points to is replaced, the link kept. A path
//   (or link target) that exists but is not a regular file (device, FIFO, socket, folder)
//   is refused: a rename would replace the device node with a file.
// - The temporary file is "PATH.tmp-PID-XXXXXX". It is removed when the process gets
//   SIGTERM, SIGINT or SIGHUP during the write; temporaries of PATH whose writer process
//   is gone (SIGKILL, power loss) are removed by the next save of PATH.
// Returns an empty string on success, or "PATH: reason".
std::string writeFileAtomically(const std::string& path, const std::string& contents);

// The temporary-file name's pid for a name "BASE.tmp-PID-XXXXXX" of `base`, or -1 (for tests
// and the stale-file sweep).
long atomicWriteTempPid(const std::string& name, const std::string& base);

}  // namespace kinema
