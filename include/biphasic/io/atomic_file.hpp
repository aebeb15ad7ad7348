// Checked file writes: whole-file replacement that never leaves half a file, and appends that
// report a full disk instead of losing rows silently.
#pragma once

#include <fstream>
#include <string>

namespace biphasic {

/// Replaces `path` with `content` so that a reader sees either the old file or the whole new
/// one: the bytes go to `<path>.tmp`, every write(2), fsync(2) and close(2) is checked, and only
/// then is the temporary renamed over `path`. On failure the temporary is removed, `path` is
/// left as it was, and std::runtime_error names the file and the cause (e.g. "No space left on
/// device").
void write_file_atomically(const std::string& path, const std::string& content);

/// Flushes `out` and throws std::runtime_error naming `path` and the system's cause if the
/// stream has failed (a full disk shows up here, at the latest on flush).
void flush_checked(std::ofstream& out, const std::string& path);

}  // namespace biphasic
