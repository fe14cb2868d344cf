#pragma once
// Writes output files so that nothing is lost: a regular file is written
// through a temporary name beside it and renamed into place (a failed or
// killed run never leaves a truncated file); a symbolic link is followed, so
// the link stays and the file it names receives the content; an existing
// character device or FIFO (/dev/null, /dev/stdout, a named pipe) is written
// in place, never replaced.
#include <functional>
#include <ostream>
#include <string>

namespace akvf {

// Where an output path really leads: the path with every symbolic link of its
// last component followed (a dangling link leads to the file it would name).
// OutputError for a link loop.
std::string resolve_output_path(const std::string& path);

// OutputError naming `path` unless it can be written: its folder exists and
// is writable, the path is not a folder, a block device or a socket, and its
// file name and whole length are within the file system's limits. Writes
// nothing. "" is no output and passes.
void check_output_writable(const std::string& path);

// A file beside `path` named by its file name and `suffix` ("x.obj" ->
// "x.obj.partial"), the name shortened from its end where the file system's
// name limit asks for it.
std::string sibling_path(const std::string& path, const std::string& suffix);

// True when `path` exists and is not a regular file (after following links):
// such an output is written in place and may be named more than once.
bool is_special_output(const std::string& path);

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Deletes the temporary files of writes in progress. Async-signal-safe: the
// interrupt handler calls it before a second signal ends the process.
void remove_pending_temporary_files() noexcept;

// Creates `folder` and its parents if needed; OutputError naming it if that
// fails or it is not a folder.
void create_output_folder(const std::string& folder);

}  // namespace akvf
